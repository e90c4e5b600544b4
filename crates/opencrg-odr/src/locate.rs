//! World to road: which road, s and t lie under a world x/y. An R-tree (`rstar`) holds
//! the reference line in stretches of at most 5 m, each boxed with the room its lanes
//! take; a point is projected onto the reference line of each stretch whose box holds it
//! (Newton's method on the tangent), and kept where a lane lies at the (s, t) found.

use crate::geometry::Station;
use crate::map::{Map, Road};
use crate::trig;
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

/// A search's footing on a road's reference line: a record and a station on it, from
/// which the stations near it are reached cheaply
/// ([`Geometry::station_from`](crate::geometry::Geometry)). A station reached that way
/// from the anchor may become the next anchor, up to [`GENERATIONS`] times before one is
/// computed from the record again, so that rounding cannot build up.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Anchor {
    geometry: usize,
    station: Station,
    generation: u32,
}

/// How many anchors in a row may be reached from the one before.
const GENERATIONS: u32 = 32;

/// A world point projected onto a road: its (s, t), the reference line's station at s and
/// the superelevation's sine and cosine there.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Projection {
    pub s: f64,
    pub t: f64,
    pub station: Station,
    pub roll: (f64, f64),
}

impl Road {
    /// (s, t) of the world point (x, y) near s = `guess`, searched within `lo..=hi`:
    /// the reference line point whose normal passes through it, and how far along the
    /// cross section the surface point over it lies; `None` where the search leaves the
    /// range or the road.
    pub fn project(&self, x: f64, y: f64, guess: f64, lo: f64, hi: f64) -> Option<(f64, f64)> {
        self.project_from(x, y, &mut None, None, guess, (lo, hi)).map(|p| (p.s, p.t))
    }

    /// The reference line's station at `s`: reached from `anchor` where that lies on the
    /// same record near enough, else computed from the record, which then becomes the
    /// anchor.
    pub(crate) fn station_at(&self, s: f64, anchor: &mut Option<Anchor>) -> Option<Station> {
        if let Some(a) = anchor {
            let g = &self.plan[a.geometry];
            let holds = (a.geometry == 0 || g.s <= s) && self.plan.get(a.geometry + 1).is_none_or(|n| n.s > s);
            if holds {
                match g.station_from(&a.station, s - g.s) {
                    Some((station, true)) => return Some(station),
                    Some((station, false)) if a.generation < GENERATIONS => {
                        *anchor = Some(Anchor { geometry: a.geometry, station, generation: a.generation + 1 });
                        return Some(station);
                    }
                    _ => {}
                }
            }
        }
        if self.plan.is_empty() {
            return None;
        }
        let geometry = self.plan.partition_point(|g| g.s <= s).saturating_sub(1);
        let g = &self.plan[geometry];
        let station = g.station(s - g.s);
        *anchor = Some(Anchor { geometry, station, generation: 0 });
        Some(station)
    }

    /// [`Road::project`] with the stations of the search reached from `anchor` (which it
    /// moves where it must), starting from `start` (s and its station) when given.
    pub(crate) fn project_from(
        &self,
        x: f64,
        y: f64,
        anchor: &mut Option<Anchor>,
        start: Option<(f64, Station)>,
        guess: f64,
        (lo, hi): (f64, f64),
    ) -> Option<Projection> {
        let (lo, hi) = (lo.max(0.0), hi.min(self.length));
        let mut s = guess.clamp(lo, hi);
        let mut p = match start {
            Some((ss, station)) if ss == s => station,
            _ => self.station_at(s, anchor)?,
        };
        let (mut along, mut across);
        let mut rounds = 0;
        loop {
            let (ex, ey) = (x - p.pose.x, y - p.pose.y);
            along = ex * p.cos + ey * p.sin;
            across = -ex * p.sin + ey * p.cos;
            rounds += 1;
            if rounds > 30 {
                break;
            }
            // The normal turns with the curvature as s moves.
            let denominator = (1.0 - p.pose.curvature * across).max(0.1);
            let step = (along / denominator).clamp(-STRETCH, STRETCH);
            let next = (s + step).clamp(lo, hi);
            if (next - s).abs() < 1e-10 {
                break;
            }
            p = self.station_at(next, anchor)?;
            s = next;
        }
        if along.abs() > 1e-6 {
            return None;
        }
        let ground = across;
        // The surface point at t lies t cos r - h(s, t) sin r from the line on the ground.
        let roll = self.superelevation.at(s);
        let (sr, cr) = trig::sin_cos(roll);
        let mut t = ground / cr;
        if roll != 0.0 && !self.level_at(s) {
            for _ in 0..4 {
                let h = self.height_above_section(s, t);
                if h == 0.0 {
                    break;
                }
                t = (ground + h * sr) / cr;
            }
        }
        Some(Projection { s, t, station: p, roll: (sr, cr) })
    }

    /// Whether the surface lies on the cross section at s (no lateral shape, no lane heights).
    fn level_at(&self, s: f64) -> bool {
        self.shape.is_empty() && !self.lanes.section_at(s).is_some_and(|(l, _)| l.has_heights())
    }
}
