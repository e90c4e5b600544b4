//! x/y to u/v: finding the reference line segment next to a point.
//!
//! The search starts from a nearby earlier result (the contact point's history) or,
//! without one, from the nearest of every tenth reference line point; from there it
//! walks along the line to the segment whose normal passes through the point. The
//! nearest sample comes from a k-d tree, so random access costs O(log n) instead of
//! a scan, and gives exactly the sample a linear scan would (ties go to the lowest
//! index).

use crate::eval::EvalOptions;
use crate::refline::RefLine;

/// Default number of history entries of a contact point.
pub const DEFAULT_HISTORY: usize = 50;

#[derive(Debug, Clone, Copy, Default)]
struct Entry {
    x: f64,
    y: f64,
    index: usize,
}

/// The recent results of a contact point, newest first, used to start the search.
#[derive(Debug, Clone)]
pub struct History {
    ring: Vec<Entry>,
    head: usize,
    used: usize,
    close2: f64,
    far2: f64,
}

impl History {
    /// A history of `size` entries with squared close and far distances.
    pub fn new(size: usize, close2: f64, far2: f64) -> Self {
        History { ring: vec![Entry::default(); size], head: 0, used: 0, close2, far2 }
    }

    /// Number of entries it can hold.
    pub fn capacity(&self) -> usize {
        self.ring.len()
    }

    /// Empties the history and gives it `size` entries.
    pub fn resize(&mut self, size: usize) {
        self.ring = vec![Entry::default(); size];
        self.head = 0;
        self.used = 0;
    }

    /// Sets the distance under which an entry is a close hit.
    pub fn set_close(&mut self, distance: f64) {
        self.close2 = distance * distance;
    }

    /// Sets the distance under which an entry is a far hit.
    pub fn set_far(&mut self, distance: f64) {
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
    pub fn preload(&mut self, line: &RefLine, u: f64) {
        if self.ring.is_empty() {
            return;
        }
        let (i, frac) = line.interval(u);
        let x = line.x[i] + frac * (line.x[i + 1] - line.x[i]);
        let y = line.y[i] + frac * (line.y[i + 1] - line.y[i]);
        self.push_front(Entry { x, y, index: i });
        self.used = 1;
    }

    /// The index to start from: the first close entry, else the first far one.
    fn lookup(&self, x: f64, y: f64) -> Option<usize> {
        for j in 0..self.used {
            let e = self.get(j);
            let (dx, dy) = (x - e.x, y - e.y);
            let d2 = dx * dx + dy * dy;
            if d2 < self.close2 || d2 < self.far2 {
                return Some(e.index);
            }
        }
        None
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

/// A sample point, with the bounding box of the subtree it heads and the axis that
/// subtree is split on.
#[derive(Debug, Clone, Copy)]
struct Node {
    x: f64,
    y: f64,
    index: usize,
    y_split: bool,
    /// x min, x max, y min, y max of the subtree.
    bbox: [f64; 4],
}

impl Node {
    /// A lower bound of the computed squared distance from (x, y) to any point of the
    /// subtree: the per-axis gaps are no larger than any point's differences, and
    /// rounding is monotonic, so no point that could win or tie is pruned.
    #[inline]
    fn box_distance2(&self, x: f64, y: f64) -> f64 {
        let [x0, x1, y0, y1] = self.bbox;
        let (dx, dy) = (gap(x, x0, x1), gap(y, y0, y1));
        dx * dx + dy * dy
    }
}

/// Distance from `p` to the interval `lo..=hi` (0 inside).
#[inline]
fn gap(p: f64, lo: f64, hi: f64) -> f64 {
    if p < lo {
        lo - p
    } else if p > hi {
        p - hi
    } else {
        0.0
    }
}

/// Nearest-sample index over every tenth reference line point (and the last one).
#[derive(Debug, Clone, Default)]
pub struct SampleIndex {
    /// Points in k-d tree order: the median of each range splits it, along the
    /// range's longer side (reference lines are long and thin, so alternating
    /// axes would prune badly).
    nodes: Vec<Node>,
}

impl SampleIndex {
    /// Builds the index for a reference line.
    pub fn build(line: &RefLine) -> Self {
        let mut nodes: Vec<Node> = sample_indices(line.n)
            .map(|i| Node { x: line.x[i], y: line.y[i], index: i, y_split: false, bbox: [0.0; 4] })
            .collect();
        if nodes.iter().any(|p| p.x.is_nan() || p.y.is_nan()) {
            return SampleIndex { nodes: Vec::new() };
        }
        arrange(&mut nodes);
        SampleIndex { nodes }
    }

    /// The sample nearest to (x, y); ties go to the lowest index.
    fn nearest(&self, line: &RefLine, x: f64, y: f64) -> usize {
        if self.nodes.is_empty() {
            return scan_nearest(line, x, y);
        }
        let mut best = (f64::INFINITY, usize::MAX);
        search(&self.nodes, x, y, &mut best);
        if best.1 == usize::MAX {
            0
        } else {
            best.1
        }
    }
}

/// The indices a linear search would look at: 0, 10, 20, ... and the last one.
fn sample_indices(n: usize) -> impl Iterator<Item = usize> {
    let mut next = Some(0usize);
    std::iter::from_fn(move || {
        let i = next?;
        next = if n < 10 {
            None
        } else if i < n - 10 {
            Some(i + 10)
        } else if i < n - 1 {
            Some(n - 1)
        } else {
            None
        };
        Some(i)
    })
}

fn scan_nearest(line: &RefLine, x: f64, y: f64) -> usize {
    let mut best = (f64::INFINITY, 0);
    for (k, i) in sample_indices(line.n).enumerate() {
        let (dx, dy) = (x - line.x[i], y - line.y[i]);
        let d2 = dx * dx + dy * dy;
        if k == 0 || d2 < best.0 {
            best = (d2, i);
        }
    }
    best.1
}

fn arrange(nodes: &mut [Node]) {
    if nodes.is_empty() {
        return;
    }
    let mut bbox = [f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY];
    for n in nodes.iter() {
        bbox = [bbox[0].min(n.x), bbox[1].max(n.x), bbox[2].min(n.y), bbox[3].max(n.y)];
    }
    let y_split = bbox[3] - bbox[2] > bbox[1] - bbox[0];
    let mid = nodes.len() / 2;
    if y_split {
        nodes.select_nth_unstable_by(mid, |a, b| a.y.total_cmp(&b.y));
    } else {
        nodes.select_nth_unstable_by(mid, |a, b| a.x.total_cmp(&b.x));
    }
    nodes[mid].y_split = y_split;
    nodes[mid].bbox = bbox;
    let (left, right) = nodes.split_at_mut(mid);
    arrange(left);
    arrange(&mut right[1..]);
}

/// Subtrees this small are scanned point by point: cheaper than their box tests.
const LEAF: usize = 12;

fn search(nodes: &[Node], x: f64, y: f64, best: &mut (f64, usize)) {
    if nodes.len() <= LEAF {
        for node in nodes {
            let (dx, dy) = (x - node.x, y - node.y);
            let d2 = dx * dx + dy * dy;
            if d2 < best.0 || (d2 == best.0 && node.index < best.1) {
                *best = (d2, node.index);
            }
        }
        return;
    }
    let mid = nodes.len() / 2;
    let node = &nodes[mid];
    if node.box_distance2(x, y) > best.0 {
        return;
    }
    let (dx, dy) = (x - node.x, y - node.y);
    let d2 = dx * dx + dy * dy;
    if d2 < best.0 || (d2 == best.0 && node.index < best.1) {
        *best = (d2, node.index);
    }
    let diff = if node.y_split { dy } else { dx };
    let (near, far) = if diff < 0.0 { (&nodes[..mid], &nodes[mid + 1..]) } else { (&nodes[mid + 1..], &nodes[..mid]) };
    search(near, x, y, best);
    search(far, x, y, best);
}

/// Finds (u, v) of the point (x, y), starting from the history and recording the
/// result in it.
pub(crate) fn xy_to_uv(
    line: &RefLine,
    index: &SampleIndex,
    options: &EvalOptions,
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
        Some((cmin, cmax)) if options.closed_search => {
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

    #[test]
    fn samples_match_a_linear_scan() {
        assert_eq!(sample_indices(5).collect::<Vec<_>>(), vec![0]);
        assert_eq!(sample_indices(10).collect::<Vec<_>>(), vec![0, 9]);
        assert_eq!(sample_indices(25).collect::<Vec<_>>(), vec![0, 10, 20, 24]);
        assert_eq!(sample_indices(21).collect::<Vec<_>>(), vec![0, 10, 20]);
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
