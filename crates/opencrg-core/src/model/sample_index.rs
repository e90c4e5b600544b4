//! The nearest-sample index over a reference line: every tenth point (and the last) in
//! a k-d tree, so that a search without history starts in O(log n) from exactly the
//! sample a linear scan would pick (ties go to the lowest index).

use crate::model::refline::RefLine;

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
pub(crate) struct SampleIndex {
    /// Points in k-d tree order: the median of each range splits it, along the
    /// range's longer side (reference lines are long and thin, so alternating
    /// axes would prune badly).
    nodes: Vec<Node>,
}

impl SampleIndex {
    /// The index for a reference line, built in this index's memory (a road prepared
    /// again takes no more; a new index starts from `SampleIndex::default()`).
    pub(crate) fn rebuilt(mut self, line: &RefLine) -> Self {
        let nodes = &mut self.nodes;
        nodes.clear();
        nodes.extend(sample_indices(line.n).map(|i| Node {
            x: line.x[i],
            y: line.y[i],
            index: i,
            y_split: false,
            bbox: [0.0; 4],
        }));
        if nodes.iter().any(|p| p.x.is_nan() || p.y.is_nan()) {
            nodes.clear();
            return self;
        }
        arrange(nodes);
        self
    }

    /// The sample nearest to (x, y); ties go to the lowest index.
    pub(crate) fn nearest(&self, line: &RefLine, x: f64, y: f64) -> usize {
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
    // Every point beyond the splitting line differs from (x, y) by at least `diff` along
    // the split axis (in computed values too: rounding is monotonic), so its computed
    // squared distance is at least diff²: when that exceeds the best, nothing there can
    // win or tie, and the far side is not even touched.
    if diff * diff <= best.0 {
        search(far, x, y, best);
    }
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

    /// The tree answers exactly as the linear scan, ties (to the lowest index) included,
    /// on a straight line, a spiral that passes near itself, and a line that turns back.
    #[test]
    fn the_tree_finds_the_sample_a_linear_scan_finds() {
        use crate::synth::RoadSpec;
        let roads = [
            RoadSpec::straight(100.0, 2.0, 0.1, 0.5),
            RoadSpec::straight(300.0, 2.0, 0.1, 0.5).with_heading(|u| 0.002 * u * u / 10.0),
            RoadSpec::straight(120.0, 2.0, 0.1, 0.5).with_heading(|u| if u < 60.0 { 0.0 } else { 3.1 }),
        ];
        let mut seed = 7u64;
        let mut random = move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for spec in roads {
            let road = spec.build().expect("a valid road");
            let line = road.reference_line();
            let index = SampleIndex::default().rebuilt(line);
            let (x0, x1) = line.x.iter().fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
            let (y0, y1) = line.y.iter().fold((f64::MAX, f64::MIN), |(a, b), &y| (a.min(y), b.max(y)));
            let mut points: Vec<(f64, f64)> = (0..3000)
                .map(|_| (x0 - 20.0 + (x1 - x0 + 40.0) * random(), y0 - 20.0 + (y1 - y0 + 40.0) * random()))
                .collect();
            // On samples, and halfway between two samples (a tie on the straight line).
            points.extend((0..line.n).step_by(37).map(|i| (line.x[i], line.y[i])));
            points.extend(
                (0..line.n.saturating_sub(10))
                    .step_by(90)
                    .map(|i| ((line.x[i] + line.x[i + 10]) / 2.0, (line.y[i] + line.y[i + 10]) / 2.0 + 0.75)),
            );
            for (x, y) in points {
                assert_eq!(index.nearest(line, x, y), scan_nearest(line, x, y), "at ({x}, {y})");
            }
        }
    }
}
