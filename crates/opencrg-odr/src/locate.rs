//! World to road: which road, s and t lie under a world x/y. An R-tree (`rstar`) holds
//! the reference line in stretches of at most 5 m, each boxed with the room its lanes
//! take; a point is projected onto the reference line of each stretch whose box holds it
//! (Newton's method on the tangent), and kept where a lane lies at the (s, t) found.

use crate::geometry::Pose;
use crate::map::{Map, Road};
use rstar::{RTree, RTreeObject, AABB};

/// Where a world point lies on the map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadPos {
    /// The road's index in [`Map::roads`].
    pub road: usize,
    /// s along its reference line.
    pub s: f64,
    /// t across it (along the cross section, which superelevation tilts).
    pub t: f64,
}

/// A stretch of a road's reference line and the box its lanes fill around it.
struct Stretch {
    road: usize,
    s0: f64,
    s1: f64,
    envelope: AABB<[f64; 2]>,
}

impl RTreeObject for Stretch {
    type Envelope = AABB<[f64; 2]>;
    fn envelope(&self) -> Self::Envelope {
        self.envelope
    }
}

/// The index of a map's roads by where they lie.
pub struct RoadIndex {
    tree: RTree<Stretch>,
}

/// The longest stretch indexed (m), unless a road would need more than [`MAX_STRETCHES`].
const STRETCH: f64 = 5.0;
/// The most stretches a road is cut into (a road of 500 km in 5 m stretches).
const MAX_STRETCHES: f64 = 100_000.0;

/// How far the lanes of `road` reach from its reference line at `s` (m, on the ground).
fn reach(road: &Road, s: f64) -> f64 {
    let Some((section, ds)) = road.lanes.section_at(s) else { return 0.0 };
    let offset = road.lanes.offset.at(s);
    let mut most = offset.abs();
    for left in [true, false] {
        for span in section.spans(left, ds, offset) {
            most = most.max(span.outer.abs()).max(span.inner.abs());
        }
    }
    most
}

impl RoadIndex {
    /// The index of `map`'s roads.
    pub fn new(map: &Map) -> RoadIndex {
        let mut stretches = Vec::new();
        for (i, road) in map.roads.iter().enumerate() {
            if road.plan.is_empty() || !(road.length > 0.0) {
                continue;
            }
            let mut cuts: Vec<f64> = road.plan.iter().map(|g| g.s).chain([0.0, road.length]).collect();
            cuts.retain(|s| (0.0..=road.length).contains(s));
            cuts.sort_by(f64::total_cmp);
            cuts.dedup();
            cuts.truncate(MAX_STRETCHES as usize);
            let longest = STRETCH.max(road.length / MAX_STRETCHES);
            for w in cuts.windows(2) {
                let n = ((w[1] - w[0]) / longest).ceil().clamp(1.0, MAX_STRETCHES) as usize;
                for k in 0..n {
                    let (s0, s1) =
                        (w[0] + (w[1] - w[0]) * k as f64 / n as f64, w[0] + (w[1] - w[0]) * (k + 1) as f64 / n as f64);
                    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
                    let mut room: f64 = 0.0;
                    for j in 0..=4 {
                        let s = s0 + (s1 - s0) * j as f64 / 4.0;
                        let r = road.reference(s);
                        for (c, v) in [r.x, r.y].into_iter().enumerate() {
                            lo[c] = lo[c].min(v);
                            hi[c] = hi[c].max(v);
                        }
                        room = room.max(reach(road, s));
                    }
                    // The lanes' reach, the line's bulge between the points sampled, a margin.
                    let grow = room + 0.25 * (s1 - s0) + 1.0;
                    if lo.iter().chain(&hi).all(|v| v.is_finite()) {
                        let envelope = AABB::from_corners([lo[0] - grow, lo[1] - grow], [hi[0] + grow, hi[1] + grow]);
                        stretches.push(Stretch { road: i, s0, s1, envelope });
                    }
                }
            }
        }
        RoadIndex { tree: RTree::bulk_load(stretches) }
    }

    /// The stretches whose box holds (x, y): (road, s0, s1).
    pub fn candidates(&self, x: f64, y: f64) -> impl Iterator<Item = (usize, f64, f64)> + '_ {
        self.tree.locate_in_envelope_intersecting(AABB::from_point([x, y])).map(|st| (st.road, st.s0, st.s1))
    }
}

impl Road {
    /// (s, t) of the world point (x, y) near s = `guess`, searched within `lo..=hi`:
    /// the reference line point whose normal passes through it, and how far along the
    /// cross section the surface point over it lies; `None` where the search leaves the
    /// range or the road.
    pub fn project(&self, x: f64, y: f64, guess: f64, lo: f64, hi: f64) -> Option<(f64, f64)> {
        self.project_from(x, y, None, guess, lo, hi).map(|(s, t, _)| (s, t))
    }

    /// [`Road::project`] starting from a known pose of the reference line (`near`: its s
    /// and pose), each pose of the search reached from the one before it (a short
    /// quadrature on a spiral); also gives the reference line's pose at the s found.
    pub(crate) fn project_from(
        &self,
        x: f64,
        y: f64,
        near: Option<(f64, Pose)>,
        guess: f64,
        lo: f64,
        hi: f64,
    ) -> Option<(f64, f64, Pose)> {
        let (lo, hi) = (lo.max(0.0), hi.min(self.length));
        let pose_at = |s: f64, known: Option<(f64, Pose)>| -> Option<Pose> {
            let g = self.geometry_at(s)?;
            match known {
                Some((ks, kp)) if self.geometry_at(ks).is_some_and(|kg| std::ptr::eq(kg, g)) => {
                    Some(g.pose_from(ks - g.s, kp, s - g.s))
                }
                _ => Some(g.pose(s - g.s)),
            }
        };
        let mut s = guess.clamp(lo, hi);
        let mut p = match near {
            Some((ns, np)) if ns == s => np,
            _ => pose_at(s, near)?,
        };
        for _ in 0..30 {
            let (sin, cos) = p.hdg.sin_cos();
            let (ex, ey) = (x - p.x, y - p.y);
            let along = ex * cos + ey * sin;
            let across = -ex * sin + ey * cos;
            // The normal turns with the curvature as s moves.
            let denominator = (1.0 - p.curvature * across).max(0.1);
            let step = (along / denominator).clamp(-STRETCH, STRETCH);
            let next = (s + step).clamp(lo, hi);
            if (next - s).abs() < 1e-10 {
                break;
            }
            p = pose_at(next, Some((s, p)))?;
            s = next;
        }
        let (sin, cos) = p.hdg.sin_cos();
        let (ex, ey) = (x - p.x, y - p.y);
        if (ex * cos + ey * sin).abs() > 1e-6 {
            return None;
        }
        let ground = -ex * sin + ey * cos;
        // The surface point at t lies t cos r - h(s, t) sin r from the line on the ground.
        let roll = self.superelevation.at(s);
        let (sr, cr) = roll.sin_cos();
        let mut t = ground / cr;
        let level = self.shape.is_empty() && !self.lanes.section_at(s).is_some_and(|(l, _)| l.has_heights());
        if roll != 0.0 && !level {
            for _ in 0..4 {
                let h = self.height_above_section(s, t);
                if h == 0.0 {
                    break;
                }
                t = (ground + h * sr) / cr;
            }
        }
        Some((s, t, p))
    }
}
