//! x/y to u/v: finding the reference line segment next to a point.
//!
//! The search starts from a nearby earlier result (the contact point's history) or,
//! without one, from the nearest of every tenth reference line point; from there it
//! walks along the line to the segment whose normal passes through the point. The
//! nearest sample comes from a k-d tree, so random access costs O(log n) instead of
//! a scan, and gives exactly the sample a linear scan would (ties go to the lowest
//! index).

use crate::base::pair::Pair;
use crate::model::refline::{RefLine, SearchPoint};
use crate::model::sample_index::SampleIndex;

/// Default number of history entries of a contact point.
pub(crate) const DEFAULT_HISTORY: usize = 50;

#[derive(Debug, Clone, Copy, Default, PartialEq)]
struct Entry {
    at: Pair,
    index: usize,
}

impl Entry {
    /// The squared distance from (x, y) to the entry's position.
    #[inline(always)]
    fn distance2(&self, x: f64, y: f64) -> f64 {
        let (dx, dy) = (x - self.at.0[0], y - self.at.0[1]);
        dx * dx + dy * dy
    }
}

/// The newest entry of a history without entries: no point is within reach of a NaN
/// position (the lookup of the newest entry needs no count), and no search records
/// its index.
const NO_ENTRY: Entry = Entry { at: Pair([f64::NAN; 2]), index: usize::MAX };

/// The recent results of a contact point, newest first, used to start the search.
#[derive(Debug, Clone)]
pub(crate) struct History {
    /// The newest entry, kept out of the ring: along a path it is the one every search
    /// reads and most of them overwrite. The ring's slot at `head` is its place and is
    /// written only when a newer entry pushes it back.
    newest: Entry,
    ring: Vec<Entry>,
    head: usize,
    used: usize,
    close2: f64,
    far2: f64,
    /// The squared distance under which an entry is a hit: `d2 < close2 || d2 < far2`
    /// is `d2 < max(close2, far2)`, NaN included (a NaN bound never holds, and `max`
    /// ignores a NaN).
    reach2: f64,
}

/// The index of the first entry closer than `limit` (squared) to (x, y). Entries are
/// tested four at a time, so that their distances are computed side by side.
#[inline]
fn first_within(entries: &[Entry], x: f64, y: f64, limit: f64) -> Option<usize> {
    let d2 = |e: &Entry| e.distance2(x, y);
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
        History {
            newest: NO_ENTRY,
            ring: vec![Entry::default(); size],
            head: 0,
            used: 0,
            close2,
            far2,
            reach2: close2.max(far2),
        }
    }

    /// Empties the history and gives it `size` entries; `false` (the history as it was)
    /// when the system does not give the memory.
    pub(crate) fn resize(&mut self, size: usize) -> bool {
        let mut ring = Vec::new();
        if ring.try_reserve_exact(size).is_err() {
            return false;
        }
        ring.resize(size, Entry::default());
        self.newest = NO_ENTRY;
        self.ring = ring;
        self.head = 0;
        self.used = 0;
        true
    }

    /// Sets the distance under which an entry is a close hit.
    pub(crate) fn set_close(&mut self, distance: f64) {
        self.close2 = distance * distance;
        self.reach2 = self.close2.max(self.far2);
    }

    /// Sets the distance under which an entry is a far hit.
    pub(crate) fn set_far(&mut self, distance: f64) {
        self.far2 = distance * distance;
        self.reach2 = self.close2.max(self.far2);
    }

    /// Entry `j` (0 is the newest, `j` below the ring's size; `None` beyond it). One
    /// conditional subtraction wraps the ring instead of a division.
    #[inline(always)]
    fn entry(&self, j: usize) -> Option<&Entry> {
        if j == 0 {
            return (!self.ring.is_empty()).then_some(&self.newest);
        }
        let k = self.head + j;
        self.ring.get(if k >= self.ring.len() { k - self.ring.len() } else { k })
    }

    /// Makes (x, y, index) the newest entry, the previous newest one the second (the
    /// ring holds at least one entry; never panics).
    #[inline]
    fn push_front(&mut self, x: f64, y: f64, index: usize) {
        if let Some(slot) = self.ring.get_mut(self.head) {
            *slot = self.newest;
        }
        self.head = if self.head == 0 { self.ring.len() - 1 } else { self.head - 1 };
        self.set_newest(x, y, index);
    }

    /// Overwrites the newest entry, its position with one store (the next search reads
    /// it at once; see [`Pair`]).
    #[inline(always)]
    fn set_newest(&mut self, x: f64, y: f64, index: usize) {
        self.newest.at.set(x, y);
        self.newest.index = index;
    }

    /// Starts the history afresh with the reference line point at `u`.
    pub(crate) fn preload(&mut self, line: &RefLine, u: f64) {
        if self.ring.is_empty() {
            return;
        }
        let (i, frac) = line.interval(u);
        let x = line.x[i] + frac * (line.x[i + 1] - line.x[i]);
        let y = line.y[i] + frac * (line.y[i + 1] - line.y[i]);
        self.push_front(x, y, i);
        self.used = 1;
    }

    /// The newest entry's index when it is within reach of (x, y); `None` otherwise.
    /// The newest entry is the contact point's previous query: along a path, the hit.
    #[inline(always)]
    fn newest_within(&self, x: f64, y: f64) -> Option<usize> {
        (self.newest.distance2(x, y) < self.reach2).then_some(self.newest.index)
    }

    /// [`History::lookup`] among the [`RECENT`] newest entries only: its answer when
    /// the hit lies among them, `None` otherwise. Never panics.
    #[inline(always)]
    fn recent_within(&self, x: f64, y: f64) -> Option<usize> {
        if let Some(i) = self.newest_within(x, y) {
            return Some(i);
        }
        (1..self.used.min(RECENT))
            .filter_map(|j| self.entry(j))
            .find(|e| e.distance2(x, y) < self.reach2)
            .map(|e| e.index)
    }

    /// The index to start from: the newest entry within the close or the far distance.
    fn lookup(&self, x: f64, y: f64) -> Option<usize> {
        if self.used == 0 {
            return None;
        }
        self.newest_within(x, y).or_else(|| self.lookup_older(x, y, self.reach2))
    }

    /// [`History::lookup`] among the entries after the newest, newest first: from the
    /// head to the end of the ring, then from its start.
    fn lookup_older(&self, x: f64, y: f64, limit: f64) -> Option<usize> {
        let first = self.ring.len().min(self.head + self.used);
        let (newer, older) = (&self.ring[self.head + 1..first], &self.ring[..self.used - (first - self.head)]);
        first_within(newer, x, y, limit).or_else(|| first_within(older, x, y, limit))
    }

    /// The entries as (x, y, index), newest first, and the ring's size and squared
    /// close and far distances: everything the search reads.
    pub(crate) fn state(&self) -> (usize, f64, f64, Vec<(f64, f64, usize)>) {
        let entries = (0..self.used).filter_map(|j| self.entry(j)).map(|e| (e.at.0[0], e.at.0[1], e.index)).collect();
        (self.ring.len(), self.close2, self.far2, entries)
    }

    /// A history of `size` entries with these squared distances and entries (newest
    /// first; those beyond the size are dropped).
    pub(crate) fn from_state(size: usize, close2: f64, far2: f64, entries: &[(f64, f64, usize)]) -> Self {
        let mut h = History::new(size, close2, far2);
        if size > 0 {
            for &(x, y, index) in entries.iter().take(size).rev() {
                h.push_front(x, y, index);
                h.used += 1;
            }
        }
        h
    }

    /// Records a result: a new newest entry, unless the newest one has the same index
    /// (then it is overwritten). Never panics.
    #[inline]
    fn record(&mut self, x: f64, y: f64, index: usize) {
        if self.ring.len() < 2 {
            return;
        }
        if self.newest.index == index {
            self.set_newest(x, y, index);
        } else {
            self.push_front(x, y, index);
            if self.used < self.ring.len() {
                self.used += 1;
            }
        }
    }
}

/// History entries the lean search looks at (the newest first): those of the wheels
/// sharing a contact point, the step before.
const RECENT: usize = 8;

/// Walks from point `k` to the segment `k - 1`..`k` whose normals enclose (x, y):
/// forward while the point lies ahead of point `k`, then backward while it lies behind
/// point `k - 1` (around a closed track, past its ends once). Returns `k` and how far
/// the point lies ahead of points `k - 1` and `k` (see [`SearchPoint::ahead`]). `pts`
/// holds at least two points and `1 <= k < pts.len()`; the walk never panics.
fn walk(pts: &[SearchPoint], closed: bool, mut k: usize, x: f64, y: f64) -> Option<Walked<'_>> {
    let n = pts.len();
    let ahead = |i: usize| pts.get(i).map(|p| p.ahead(x, y));
    let walk_limit = 2 * n + 4;
    let mut turn = 0.0;
    let mut steps = 0;
    let mut at_k;
    loop {
        at_k = ahead(k)?;
        if !(at_k > 0.0) {
            break;
        }
        steps += 1;
        if steps > walk_limit {
            break;
        }
        if k < n - 1 {
            k += 1;
        } else if closed {
            turn = ahead(0)?;
            if turn <= 0.0 {
                break;
            }
            k = 1;
        } else {
            break;
        }
    }
    let mut steps = 0;
    loop {
        let behind = ahead(k - 1)?;
        steps += 1;
        if !(behind < 0.0) || steps > walk_limit {
            return Walked::at(pts, k, behind, at_k);
        }
        if k > 1 {
            k -= 1;
            at_k = behind;
        } else if closed {
            if turn != 0.0 {
                return Walked::at(pts, k, behind, at_k);
            }
            turn = ahead(n - 1)?;
            if turn >= 0.0 {
                return Walked::at(pts, k, behind, at_k);
            }
            k = n - 1;
            at_k = turn;
        } else {
            return Walked::at(pts, k, behind, at_k);
        }
    }
}

/// [`walk`] where it stays between the line's ends: the same steps and result, or
/// `None` where the walk would go around a closed track's end. On an open line the
/// general walk never reaches its step limit (each direction takes fewer steps than
/// the line has points), so this one needs no count.
#[inline(always)]
fn walk_lean(pts: &[SearchPoint], closed: bool, mut k: usize, x: f64, y: f64) -> Option<Walked<'_>> {
    let mut b = pts.get(k)?;
    let mut at_k = b.ahead(x, y);
    if !(at_k > 0.0) {
        return walk_back(pts, closed, k, at_k, x, y);
    }
    loop {
        let Some(next) = pts.get(k + 1) else {
            return (!closed).then(|| walk_back(pts, closed, k, at_k, x, y)).flatten();
        };
        let (a, behind) = (b, at_k);
        (k, b, at_k) = (k + 1, next, next.ahead(x, y));
        if !(at_k > 0.0) {
            // The point lies ahead of point k - 1 (`behind` > 0): where the backward walk
            // would stop at once, with the value it would compute again.
            return Some(Walked { k, a, b, behind, at_k });
        }
    }
}

/// The backward part of [`walk_lean`], from point `k` where the point lies `at_k`
/// ahead: iterates the points before `k`, newest index first, with no index checks.
#[inline(always)]
fn walk_back(pts: &[SearchPoint], closed: bool, k: usize, mut at_k: f64, x: f64, y: f64) -> Option<Walked<'_>> {
    let mut b = pts.get(k)?;
    for (i, a) in pts.get(..k)?.iter().enumerate().rev() {
        let behind = a.ahead(x, y);
        if !(behind < 0.0) {
            return Some(Walked { k: i + 1, a, b, behind, at_k });
        }
        if i == 0 {
            return (!closed).then_some(Walked { k: 1, a, b, behind, at_k });
        }
        (b, at_k) = (a, behind);
    }
    None
}

/// Where a [`walk`] ended: on segment `k - 1`..`k` from point `a` to point `b`, with
/// how far the point lies ahead of point `k - 1` (`behind`) and of point `k` (`at_k`).
#[derive(Debug, Clone, Copy)]
struct Walked<'p> {
    k: usize,
    a: &'p SearchPoint,
    b: &'p SearchPoint,
    behind: f64,
    at_k: f64,
}

impl<'p> Walked<'p> {
    /// The walk's end on segment `k - 1`..`k` of `pts` (`None` outside them).
    fn at(pts: &'p [SearchPoint], k: usize, behind: f64, at_k: f64) -> Option<Self> {
        Some(Walked { k, a: pts.get(k.checked_sub(1)?)?, b: pts.get(k)?, behind, at_k })
    }
}

/// (u, v) of (x, y) found by a [`walk`]: v along the segment's normal, u interpolated
/// between the normals of its two points; then measured from an end point where u
/// lies before the start or beyond the end. `None` only for a line without the
/// segment's length.
#[inline(always)]
fn solve(line: &RefLine, closed_search: bool, w: Walked, x: f64, y: f64) -> Option<(f64, f64)> {
    let (k, a, b) = (w.k, w.a, w.b);
    let (x2x1, y2y1) = (b.x - a.x, b.y - a.y);
    let (xxx1, yyy1) = (x - a.x, y - a.y);
    let v = (x2x1 * yyy1 - y2y1 * xxx1) / line.seg_len.get(k - 1)?;
    let ta = w.behind / (a.dx * x2x1 + a.dy * y2y1);
    // How far the point lies behind point k: `b.dx (b.x - x) + b.dy (b.y - y)`, which
    // is `-at_k` exactly (IEEE subtraction and multiplication are symmetric under
    // negation), except for the sign of a zero, which `ta / (ta + tb)` never shows (a
    // zero `tb` leaves `ta + tb` at `ta`, and with `ta` zero too the quotient is NaN).
    let tb = -w.at_k / (b.dx * x2x1 + b.dy * y2y1);
    let du = ta / (ta + tb) * line.u_inc;
    let u = (k - 1) as i64 as f64 * line.u_inc + du + line.u_first;
    Some(beyond_ends(line, closed_search, x, y, u, v))
}

/// (u, v) of a point found before the start or beyond the end of the line (or beyond
/// the closed-track range): measured from the end point along its heading.
#[inline(always)]
fn beyond_ends(line: &RefLine, closed_search: bool, x: f64, y: f64, u: f64, v: f64) -> (f64, f64) {
    let t = &line.trig;
    let from_start = || {
        let (dx, dy) = (x - line.x_first, y - line.y_first);
        (line.u_first + dx * t.first_cos + dy * t.first_sin, dy * t.first_cos - dx * t.first_sin)
    };
    let from_end = || {
        let (dx, dy) = (x - line.x_last, y - line.y_last);
        (line.u_last + dx * t.last_cos + dy * t.last_sin, dy * t.last_cos - dx * t.last_sin)
    };
    match line.closed {
        Some((low, high)) if closed_search => {
            if u > high {
                return from_start();
            } else if u < low {
                return from_end();
            }
        }
        _ => {
            if u < line.u_first {
                return from_start();
            } else if u > line.u_last {
                return from_end();
            }
        }
    }
    (u, v)
}

/// [`xy_to_uv`] for the common case of a point near a recent one: one of the [`RECENT`]
/// newest history entries is within reach, and the walk does not go around a closed
/// track's end. The same answer and the same history change as
/// [`xy_to_uv`] then; `None`, with nothing changed, otherwise. Never panics.
#[inline(always)]
pub(crate) fn xy_to_uv_lean(
    line: &RefLine,
    closed_search: bool,
    history: &mut History,
    x: f64,
    y: f64,
) -> Option<(f64, f64)> {
    let n = line.n;
    let pts = line.search.get(..n)?;
    // Unlike the general search, no clamp of the start to 1..n-1: from an index beyond
    // the line the walk declines, and from 0 it either steps forward to where the
    // general walk starting at 1 ends or declines.
    let start = history.recent_within(x, y)?;
    let walked = walk_lean(pts, line.closed.is_some(), start, x, y)?;
    prefetch_ahead(line, start, walked.k);
    let found = solve(line, closed_search, walked, x, y)?;
    history.record(x, y, (walked.k + 1).min(n - 1));
    Some(found)
}

/// How many reference line points ahead of a walk's end, in the direction it moved,
/// the lean search asks the caches for: where the wheel will be some calls later (at
/// 50 m/s on points 1 cm apart, ten steps of 1 ms), fetched while this call computes.
const PREFETCH_AHEAD: usize = 48;

/// Asks the caches for the search record and the segment length [`PREFETCH_AHEAD`]
/// points beyond `k`, where a walk from `start` ended at segment `k - 1`..`k`, when it
/// moved on to a new point: forward (`k > start`), or back beyond the point before the
/// start (`k + 1 < start`; a start is one beyond the last search's segment). The
/// addresses are only computed, never read.
#[inline(always)]
fn prefetch_ahead(line: &RefLine, start: usize, k: usize) {
    let i = if k > start {
        k.wrapping_add(PREFETCH_AHEAD)
    } else if k + 1 < start {
        k.wrapping_sub(PREFETCH_AHEAD)
    } else {
        return;
    };
    crate::base::memory::prefetch(line.search.as_ptr().wrapping_add(i));
    crate::base::memory::prefetch(line.seg_len.as_ptr().wrapping_add(i));
}

/// Finds (u, v) of the point (x, y), starting from the history (or, without a hit
/// there, from the nearest reference line sample) and recording the result in it;
/// `closed_search` continues the walk around a closed track.
pub(crate) fn xy_to_uv(
    line: &RefLine,
    index: &SampleIndex,
    closed_search: bool,
    history: &mut History,
    x: f64,
    y: f64,
) -> (f64, f64) {
    let n = line.n;
    let start = match history.lookup(x, y) {
        Some(i) => i.min(n - 1),
        None => index.nearest(line, x, y),
    };
    let pts = &line.search[..n];
    let found = walk(pts, line.closed.is_some(), start.max(1), x, y)
        .and_then(|w| Some((w.k, solve(line, closed_search, w, x, y)?)));
    match found {
        Some((k, found)) => {
            history.record(x, y, (k + 1).min(n - 1));
            found
        }
        // Unreachable: the line has its n >= 2 points, and the walk keeps 1 <= k < n.
        None => (f64::NAN, f64::NAN),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The chunked lookup answers as the plain newest-first loop, across the ring's wrap,
    /// and the lookup among the recent entries as that loop does when its hit is recent.
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
                let hit = (0..h.used).find(|&j| {
                    let e = h.entry(j).unwrap();
                    let d2 = (x - e.at.0[0]) * (x - e.at.0[0]) + (y - e.at.0[1]) * (y - e.at.0[1]);
                    d2 < h.close2 || d2 < h.far2
                });
                assert_eq!(h.lookup(x, y), hit.map(|j| h.entry(j).unwrap().index), "size {size}, step {step}");
                let recent = hit.filter(|&j| j < RECENT).map(|j| h.entry(j).unwrap().index);
                assert_eq!(h.recent_within(x, y), recent, "size {size}, step {step}");
                h.record(x, y, step);
            }
        }
    }

    /// The lean search either gives the general search's answer and history change, bit
    /// for bit, or declines and changes nothing: on an open winding line, a closed
    /// circle (with and without the closed-track search) and lines of a few points,
    /// along paths forwards and backwards, with jumps, off the road and beyond its ends,
    /// and from history entries outside the line's indices.
    #[test]
    fn lean_search_answers_as_the_general_search() {
        use crate::synth::RoadSpec;
        let circle = 2.0 * std::f64::consts::PI * 20.0;
        let roads = [
            RoadSpec::straight(300.0, 4.0, 0.25, 1.0).with_heading(|u| 2.0 * (u / 40.0).sin()),
            RoadSpec::straight(circle - 0.5, 4.0, 0.1, 1.0).with_heading(|u| u / 20.0),
            RoadSpec::straight(0.5, 4.0, 0.25, 1.0).with_heading(|u| u),
            RoadSpec::straight(0.75, 4.0, 0.25, 1.0),
        ];
        let mut seed = 7u64;
        let mut random = move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut lean_answers, mut closed_tested) = (0, false);
        for spec in roads {
            let road = spec.build().unwrap();
            let line = &road.line;
            closed_tested |= line.closed.is_some();
            let (length, xs, ys) = (line.u_last - line.u_first, &line.x, &line.y);
            for closed_search in [false, true] {
                for size in [50, 3, 0] {
                    let mut history = History::new(size, 0.09, 4.84);
                    let mut k = 0.0;
                    for step in 0..3000 {
                        // Mostly small steps along the line, now and then a jump or a point
                        // far off it; u reaching past both ends.
                        k = if step % 400 == 0 { random() } else { k + (random() - 0.3) * 0.01 };
                        let i = ((k.rem_euclid(1.0)) * (line.n - 1) as f64) as usize;
                        let off = if step % 97 == 0 { 50.0 * (random() - 0.5) } else { 3.0 * (random() - 0.5) };
                        let along = if step % 131 == 0 { 1.2 * length * (random() - 0.1) } else { 0.0 };
                        let (x, y) = (xs[i] + off + along, ys[i] - off * 0.5);
                        if step % 250 == 125 {
                            // A history from another road: an index at either end or beyond it.
                            let index = [0, 1, line.n - 1, line.n, line.n + 7][step / 250 % 5];
                            history.record(x + 0.01, y, index);
                        }
                        let mut general = history.clone();
                        let expected = xy_to_uv(line, &road.index, closed_search, &mut general, x, y);
                        let mut lean = history.clone();
                        match xy_to_uv_lean(line, closed_search, &mut lean, x, y) {
                            Some((u, v)) => {
                                lean_answers += 1;
                                assert_eq!((u.to_bits(), v.to_bits()), (expected.0.to_bits(), expected.1.to_bits()));
                                assert_eq!(lean.state(), general.state(), "history after step {step}");
                            }
                            None => assert_eq!(lean.state(), history.state(), "a declined search changed the history"),
                        }
                        history = general;
                    }
                }
            }
        }
        assert!(closed_tested, "the circle can be closed");
        assert!(lean_answers > 20_000, "the lean search answered {lean_answers} times");
    }

    /// A history taken apart and made again answers every lookup alike and records alike.
    #[test]
    fn history_state_makes_the_same_history() {
        for size in [0, 1, 2, 3, 7, 50] {
            let mut h = History::new(size, 0.25, 4.0);
            for step in 0..(size * 3 + 2) {
                h.record(step as f64 * 0.7, (step % 5) as f64, step / 2);
            }
            let (len, close2, far2, entries) = h.state();
            let mut again = History::from_state(len, close2, far2, &entries);
            assert_eq!(again.state(), h.state(), "size {size}");
            for probe in 0..40 {
                let (x, y) = (probe as f64 * 0.31, (probe % 7) as f64 * 0.5);
                assert_eq!(again.lookup(x, y), h.lookup(x, y), "size {size}, probe {probe}");
            }
            h.record(1.0, 1.0, 999);
            again.record(1.0, 1.0, 999);
            assert_eq!(again.state(), h.state(), "size {size} after a record");
        }
    }

    #[test]
    fn history_ring_keeps_newest_first() {
        let mut h = History::new(3, 1.0, 4.0);
        h.record(0.0, 0.0, 5);
        h.record(10.0, 0.0, 6);
        h.record(20.0, 0.0, 6);
        assert_eq!(h.used, 2);
        assert_eq!(h.entry(0).unwrap().at.0[0], 20.0);
        assert_eq!(h.lookup(0.5, 0.0), Some(5));
        assert_eq!(h.lookup(100.0, 0.0), None);
    }
}
