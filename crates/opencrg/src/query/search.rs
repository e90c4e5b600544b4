//! x/y to u/v: finding the reference line segment next to a point.
//!
//! The search starts from a nearby earlier result (the contact point's history) or,
//! without one, from the nearest of every tenth reference line point; from there it
//! walks along the line to the segment whose normal passes through the point. The
//! nearest sample comes from a k-d tree, so random access costs O(log n) instead of
//! a scan, and gives exactly the sample a linear scan would (ties go to the lowest
//! index).

use crate::refline::RefLine;
use crate::sample_index::SampleIndex;

/// Default number of history entries of a contact point.
pub(crate) const DEFAULT_HISTORY: usize = 50;

#[derive(Debug, Clone, Copy, Default)]
struct Entry {
    x: f64,
    y: f64,
    index: usize,
}

/// The recent results of a contact point, newest first, used to start the search.
#[derive(Debug, Clone)]
pub(crate) struct History {
    ring: Vec<Entry>,
    head: usize,
    used: usize,
    close2: f64,
    far2: f64,
}

/// The index of the first entry closer than `limit` (squared) to (x, y). Entries are
/// tested four at a time, so that their distances are computed side by side.
#[inline]
fn first_within(entries: &[Entry], x: f64, y: f64, limit: f64) -> Option<usize> {
    let d2 = |e: &Entry| {
        let (dx, dy) = (x - e.x, y - e.y);
        dx * dx + dy * dy
    };
    let mut chunks = entries.chunks_exact(4);
    for chunk in chunks.by_ref() {
        let near = [d2(&chunk[0]) < limit, d2(&chunk[1]) < limit, d2(&chunk[2]) < limit, d2(&chunk[3]) < limit];
        if near.iter().any(|&n| n) {
            return near.iter().position(|&n| n).map(|k| chunk[k].index);
        }
    }
    chunks.remainder().iter().find(|e| d2(e) < limit).map(|e| e.index)
}

impl History {
    /// A history of `size` entries with squared close and far distances.
    pub(crate) fn new(size: usize, close2: f64, far2: f64) -> Self {
        History { ring: vec![Entry::default(); size], head: 0, used: 0, close2, far2 }
    }

    /// Empties the history and gives it `size` entries.
    pub(crate) fn resize(&mut self, size: usize) {
        self.ring = vec![Entry::default(); size];
        self.head = 0;
        self.used = 0;
    }

    /// Sets the distance under which an entry is a close hit.
    pub(crate) fn set_close(&mut self, distance: f64) {
        self.close2 = distance * distance;
    }

    /// Sets the distance under which an entry is a far hit.
    pub(crate) fn set_far(&mut self, distance: f64) {
        self.far2 = distance * distance;
    }

    /// Entry `j` (0 is the newest). `j` is below the length, so one conditional
    /// subtraction replaces a division in this hot path.
    #[inline]
    fn get(&self, j: usize) -> &Entry {
        let mut k = self.head + j;
        if k >= self.ring.len() {
            k -= self.ring.len();
        }
        &self.ring[k]
    }

    #[inline]
    fn push_front(&mut self, e: Entry) {
        self.head = if self.head == 0 { self.ring.len() - 1 } else { self.head - 1 };
        self.ring[self.head] = e;
    }

    /// Starts the history afresh with the reference line point at `u`.
    pub(crate) fn preload(&mut self, line: &RefLine, u: f64) {
        if self.ring.is_empty() {
            return;
        }
        let (i, frac) = line.interval(u);
        let x = line.x[i] + frac * (line.x[i + 1] - line.x[i]);
        let y = line.y[i] + frac * (line.y[i + 1] - line.y[i]);
        self.push_front(Entry { x, y, index: i });
        self.used = 1;
    }

    /// The index to start from: the newest entry within the close or the far distance.
    fn lookup(&self, x: f64, y: f64) -> Option<usize> {
        // `d2 < close2 || d2 < far2` is `d2 < max(close2, far2)`, NaN included (a NaN
        // bound never holds, and `max` ignores a NaN).
        let limit = self.close2.max(self.far2);
        // Newest first: from the head to the end of the ring, then from its start.
        let first = self.ring.len().min(self.head + self.used);
        let (newer, older) = (&self.ring[self.head..first], &self.ring[..self.used - (first - self.head)]);
        first_within(newer, x, y, limit).or_else(|| first_within(older, x, y, limit))
    }

    fn record(&mut self, x: f64, y: f64, index: usize) {
        if self.ring.len() < 2 {
            return;
        }
        if self.get(0).index != index {
            self.push_front(Entry::default());
            if self.used < self.ring.len() {
                self.used += 1;
            }
        }
        self.ring[self.head] = Entry { x, y, index };
    }
}

/// Finds (u, v) of the point (x, y), starting from the history and recording the
/// result in it; `closed_search` continues the walk around a closed track.
pub(crate) fn xy_to_uv(
    line: &RefLine,
    index: &SampleIndex,
    closed_search: bool,
    history: &mut History,
    x: f64,
    y: f64,
) -> (f64, f64) {
    let n = line.n;
    // Slices of exactly n points: with k kept in 1..n, the indexing below needs no
    // further bounds checks.
    let (xs, ys) = (&line.x[..n], &line.y[..n]);
    let closed = &line.closed;
    let start = match history.lookup(x, y) {
        Some(i) => i.min(n - 1),
        None => index.nearest(line, x, y),
    };
    let mut k = start.max(1);
    let walk_limit = 2 * n + 4;

    // Walk forward while the point lies ahead of point k.
    let mut turn = 0.0;
    for _ in 0..walk_limit {
        let p1 = (k + 1).min(n - 1);
        let ahead = (x - xs[k]) * (xs[p1] - xs[k - 1]) + (y - ys[k]) * (ys[p1] - ys[k - 1]);
        if !(ahead > 0.0) {
            break;
        }
        if k < n - 1 {
            k += 1;
        } else if closed.is_some() {
            turn = (x - xs[0]) * (xs[1] - xs[0]) + (y - ys[0]) * (ys[1] - ys[0]);
            if turn <= 0.0 {
                break;
            }
            k = 1;
        } else {
            break;
        }
    }

    // Walk backward while the point lies behind point k - 1.
    let (mut x0, mut x1, mut x2, mut y0, mut y1, mut y2);
    let mut behind;
    let mut steps = 0;
    loop {
        let m2 = k.saturating_sub(2);
        x0 = xs[m2];
        x1 = xs[k - 1];
        x2 = xs[k];
        y0 = ys[m2];
        y1 = ys[k - 1];
        y2 = ys[k];
        behind = (x - x1) * (x2 - x0) + (y - y1) * (y2 - y0);
        steps += 1;
        if !(behind < 0.0) || steps > walk_limit {
            break;
        }
        if k > 1 {
            k -= 1;
        } else if closed.is_some() {
            if turn != 0.0 {
                break;
            }
            let last = n - 1;
            turn = (x - xs[last]) * (xs[last] - xs[last - 1]) + (y - ys[last]) * (ys[last] - ys[last - 1]);
            if turn >= 0.0 {
                break;
            }
            k = last;
        } else {
            break;
        }
    }

    let (x2x1, y2y1) = (x2 - x1, y2 - y1);
    let (xxx1, yyy1) = (x - x1, y - y1);
    let mut v = (x2x1 * yyy1 - y2y1 * xxx1) / line.seg_len[k - 1];
    let p1 = (k + 1).min(n - 1);
    let (x3x1, y3y1) = (xs[p1] - x1, ys[p1] - y1);
    let (x2x0, y2y0) = (x2 - x0, y2 - y0);
    let ta = behind / (x2x0 * x2x1 + y2y0 * y2y1);
    let tb = (x3x1 * (x2 - x) + y3y1 * (y2 - y)) / (x3x1 * x2x1 + y3y1 * y2y1);
    let du = ta / (ta + tb) * line.u_inc;
    let mut u = (k - 1) as i64 as f64 * line.u_inc + du + line.u_first;

    let t = &line.trig;
    let from_start = |u: &mut f64, v: &mut f64| {
        let (dx, dy) = (x - line.x_first, y - line.y_first);
        *u = line.u_first + dx * t.first_cos + dy * t.first_sin;
        *v = dy * t.first_cos - dx * t.first_sin;
    };
    let from_end = |u: &mut f64, v: &mut f64| {
        let (dx, dy) = (x - line.x_last, y - line.y_last);
        *u = line.u_last + dx * t.last_cos + dy * t.last_sin;
        *v = dy * t.last_cos - dx * t.last_sin;
    };
    match closed {
        Some((cmin, cmax)) if closed_search => {
            let (cmin, cmax) = (*cmin, *cmax);
            if u > cmax {
                from_start(&mut u, &mut v);
            } else if u < cmin {
                from_end(&mut u, &mut v);
            }
        }
        _ => {
            if u < line.u_first {
                from_start(&mut u, &mut v);
            } else if u > line.u_last {
                from_end(&mut u, &mut v);
            }
        }
    }
    history.record(x, y, p1);
    (u, v)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The chunked lookup answers as the plain newest-first loop, across the ring's wrap.
    #[test]
    fn lookup_finds_the_newest_entry_within_reach() {
        let mut seed = 3u64;
        let mut random = move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for size in [2, 3, 5, 8, 13, 50] {
            let mut h = History::new(size, 0.5, 2.0);
            for step in 0..200 {
                let (x, y) = (10.0 * random(), 10.0 * random());
                let plain = (0..h.used).map(|j| h.get(j)).find(|e| {
                    let d2 = (x - e.x) * (x - e.x) + (y - e.y) * (y - e.y);
                    d2 < h.close2 || d2 < h.far2
                });
                assert_eq!(h.lookup(x, y), plain.map(|e| e.index), "size {size}, step {step}");
                h.record(x, y, step);
            }
        }
    }

    #[test]
    fn history_ring_keeps_newest_first() {
        let mut h = History::new(3, 1.0, 4.0);
        h.record(0.0, 0.0, 5);
        h.record(10.0, 0.0, 6);
        h.record(20.0, 0.0, 6);
        assert_eq!(h.used, 2);
        assert_eq!(h.get(0).x, 20.0);
        assert_eq!(h.lookup(0.5, 0.0), Some(5));
        assert_eq!(h.lookup(100.0, 0.0), None);
    }
}
