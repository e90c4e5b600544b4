//! World to road: which road, s and t lie under a world x/y. An R-tree (`rstar`) holds
//! the reference line in stretches of at most 5 m, each boxed with the room its lanes
//! take; a point is projected onto the reference line of each stretch whose box holds it
//! (Newton's method on the tangent), and kept where a lane lies at the (s, t) found.

use crate::geometry::{turned_path, Shape, Station, CLOSED_TURN};
use crate::map::{Map, Road};
use crate::trig;
use opencrg_core::math;
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

/// The longest stretch indexed (m), unless the map would need more than [`MAX_STRETCHES`].
const STRETCH: f64 = 5.0;
/// About the most stretches a map is cut into (5,000 km of roads in 5 m stretches; longer
/// stretches beyond, so that the index stays in proportion to the file however long its
/// roads say they are).
const MAX_STRETCHES: f64 = 1_000_000.0;

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
        let longest = STRETCH.max(map.length() / MAX_STRETCHES);
        for (i, road) in map.roads.iter().enumerate() {
            if road.plan.is_empty() || !(road.length > 0.0) {
                continue;
            }
            let mut cuts: Vec<f64> = road.plan.iter().map(|g| g.s).chain([0.0, road.length]).collect();
            cuts.retain(|s| (0.0..=road.length).contains(s));
            cuts.sort_by(f64::total_cmp);
            cuts.dedup();
            for w in cuts.windows(2) {
                let n = ((w[1] - w[0]) / longest).ceil().clamp(1.0, MAX_STRETCHES) as usize;
                // The window lies on one record: sampled from it, 4 points a stretch, each
                // stretch's last point the next one's first. Inside a cubic curve, each
                // station is reached from an earlier one as a wheel's is (by the arc length
                // nearby, not from the curve's start); the window's end is the record's
                // own (where the next record starts, its station may lie elsewhere).
                let Some(g) = road.geometry_at(0.5 * (w[0] + w[1])) else { continue };
                let frame = math::sin_cos(g.hdg);
                let cubic = matches!(g.shape, Shape::Poly3 { .. } | Shape::ParamPoly3 { .. });
                let (mut anchor, mut station) = (None, Station::default());
                let mut sample = |j: usize| {
                    let s = w[0] + (w[1] - w[0]) * j as f64 / (4 * n) as f64;
                    let point = if cubic && j < 4 * n && road.station_at(s, &mut anchor, &mut station) {
                        [station.pose.x, station.pose.y]
                    } else {
                        g.point_in(frame, s - g.s)
                    };
                    (s, point, reach(road, s))
                };
                let mut first = sample(0);
                for k in 0..n {
                    let (mut lo, mut hi) = (first.1, first.1);
                    let mut room = first.2;
                    let mut last = first;
                    for j in 1..=4 {
                        last = sample(4 * k + j);
                        for c in 0..2 {
                            lo[c] = lo[c].min(last.1[c]);
                            hi[c] = hi[c].max(last.1[c]);
                        }
                        room = room.max(last.2);
                    }
                    let (s0, s1) = (first.0, last.0);
                    first = last;
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
    /// The s range where the record holds (the first record's reaches back without end,
    /// the last one's on).
    from: f64,
    to: f64,
    /// s of the station.
    s: f64,
    station: Station,
    generation: u32,
    /// How the record bends, where the foot of a point has a closed form.
    bend: Bend,
}

/// A record whose feet have a closed form: a line, an arc of this curvature, a spiral
/// whose curvature changes at this rate (per m).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Bend {
    Line,
    Arc(f64),
    Spiral(f64),
    Other,
}

/// The foot of a point on an arc of curvature k, the point at `along` and `across` in the
/// frame of one of its stations, within [`CLOSED_TURN`] of turn from it: how far on the
/// foot lies and how far the point lies from the arc. With q = 1 - k across and
/// z = k along / q, the foot lies atan(z) / k further and the point (1 - q sqrt(1 + z^2)) / k
/// from the arc: by their series in z, exact to rounding while z stays within the bound
/// (the first terms left out are below 1e-18).
#[inline(always)]
fn arc_foot(k: f64, along: f64, across: f64) -> Option<(f64, f64)> {
    let q = 1.0 - k * across;
    if !(q > 0.1) {
        return None;
    }
    let inverse = 1.0 / q;
    let z = k * along * inverse;
    let z2 = z * z;
    if !(z2 <= CLOSED_TURN * CLOSED_TURN) {
        return None;
    }
    let ds = along * inverse * (1.0 - z2 * (1.0 / 3.0 - z2 * 0.2));
    let drop = k * along * along * inverse * (0.5 - z2 * (0.125 - z2 * 0.0625));
    Some((ds, across - drop))
}

impl Anchor {
    /// The foot of (x, y) on the anchor's record, where the record is a line, an arc or a
    /// spiral and the foot lies within [`CLOSED_TURN`] of turn from the anchor: s and how
    /// far the point lies from the line on the ground. A spiral's foot is the foot on the
    /// arc whose heading meets the spiral's where the point's tangent projection lies,
    /// then one Newton step from the spiral's station there (turned in closed form), taken
    /// without its station as [`Road::foot`]'s last step is, where it is within [`SNAP`].
    /// With them, the turn between the anchor and the foot (at most; 0 on lines).
    #[inline(always)]
    fn closed_foot(&self, x: f64, y: f64) -> Option<(f64, f64, f64)> {
        let p = &self.station;
        let (ex, ey) = (x - p.pose.x, y - p.pose.y);
        let along = ex * p.cos + ey * p.sin;
        let across = -ex * p.sin + ey * p.cos;
        let (ds, off, turn) = match self.bend {
            Bend::Line => (along, across, 0.0),
            Bend::Arc(k) => {
                let (ds, off) = arc_foot(k, along, across)?;
                (ds, off, (k * ds).abs())
            }
            Bend::Spiral(rate) => {
                let k0 = p.pose.curvature;
                let (d, _) = arc_foot(k0 + 0.5 * rate * along, along, across)?;
                let k1 = k0 + rate * d;
                let (turn0, turn1) = ((k0 * d).abs(), (k1 * d).abs());
                if !(turn0 <= CLOSED_TURN && turn1 <= CLOSED_TURN) {
                    return None;
                }
                // The spiral's station d on, in the anchor's frame, and the point from it.
                let (lx, ly) = turned_path(k0 * d, 0.5 * rate * d * d, d);
                let (st, ct) = trig::tiny_sin_cos(d * (k0 + 0.5 * rate * d));
                let (fx, fy) = (along - lx, across - ly);
                let (rest, off) = (fx * ct + fy * st, -fx * st + fy * ct);
                let q = 1.0 - k1 * off;
                if !(rest.abs() <= SNAP && q > 0.1) {
                    return None;
                }
                (d + rest / q, off, turn0.max(turn1))
            }
            Bend::Other => return None,
        };
        Some((self.s + ds, off, turn))
    }

    /// The anchor moved on to `station` at s, reached from it.
    fn reached(&mut self, s: f64, station: Station) {
        self.station = station;
        self.s = s;
        self.generation += 1;
    }

    /// Where the anchor moves once a foot at s, `turn` from it, lies more than
    /// [`MOVE_TURN`] from it: as far again ahead as it is, short of the closed turn from the
    /// anchor, so that the wheel passes the new anchor before the next move; the foot
    /// itself where that would leave the record.
    fn next_s(&self, s: f64, turn: f64) -> f64 {
        let ahead = self.s + 1.8 * (s - self.s);
        if turn <= 0.5 * CLOSED_TURN && self.from <= ahead && ahead < self.to {
            ahead
        } else {
            s
        }
    }
}

/// The turn between an anchor and a foot found in closed form beyond which the anchor
/// moves on (see [`Anchor::next_s`]).
const MOVE_TURN: f64 = 0.4 * CLOSED_TURN;

/// Where a search stands on a road's reference line: s and the station there (`fresh`:
/// whether the station is there; a foot found in closed form moves s alone).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Footing {
    pub s: f64,
    pub station: Station,
    pub fresh: bool,
}

/// How close (m) the foot of a point is searched for: the distance along the tangent left.
const FOOT: f64 = 1e-10;

/// How close (m) to the foot the search takes its last step without its station.
const SNAP: f64 = 1e-6;

/// How many anchors in a row may be reached from the one before.
const GENERATIONS: u32 = 32;

impl Road {
    /// (s, t) of the world point (x, y) near s = `guess`, searched within `lo..=hi`:
    /// the reference line point whose normal passes through it, and how far along the
    /// cross section the surface point over it lies; `None` where the search leaves the
    /// range or the road.
    pub fn project(&self, x: f64, y: f64, guess: f64, lo: f64, hi: f64) -> Option<(f64, f64)> {
        let (lo, hi) = (lo.max(0.0), hi.min(self.length));
        if !(lo <= hi) {
            return None;
        }
        let mut anchor = None;
        let mut at = self.footing(guess.clamp(lo, hi), &mut anchor)?;
        let (s, ground) = self.foot(x, y, &mut anchor, &mut at, (lo, hi))?;
        let roll = self.superelevation.at(s);
        Some((s, self.across(s, ground, roll, trig::sin_cos(roll), self.level_at(s))))
    }

    /// The reference line's station at `s`, written to `out`: reached from `anchor` where
    /// that lies on the same record near enough, else computed from the record, which then
    /// becomes the anchor; `false` on a road without records.
    #[inline(always)]
    pub(crate) fn station_at(&self, s: f64, anchor: &mut Option<Anchor>, out: &mut Station) -> bool {
        if let Some(a) = anchor {
            if a.from <= s && s < a.to {
                let g = &self.plan[a.geometry];
                match g.station_from(&a.station, s - g.s, out) {
                    Some(true) => return true,
                    Some(false) if a.generation < GENERATIONS => {
                        a.reached(s, *out);
                        return true;
                    }
                    _ => {}
                }
            }
        }
        self.anchor_at(s, anchor, out)
    }

    /// Moves `anchor` on to `s` on its record, the station there reached from it (or, after
    /// [`GENERATIONS`] such moves, computed from the record), so that the feet of the points
    /// ahead keep their closed form.
    #[cold]
    #[inline(never)]
    fn move_anchor(&self, s: f64, anchor: &mut Option<Anchor>) {
        let mut station = Station::default();
        if let Some(a) = anchor {
            let g = &self.plan[a.geometry];
            if a.generation < GENERATIONS && g.station_from(&a.station, s - g.s, &mut station).is_some() {
                a.reached(s, station);
                return;
            }
        }
        self.anchor_at(s, anchor, &mut station);
    }

    /// The reference line's station at `s` computed from its record, which becomes the
    /// anchor.
    #[inline(never)]
    fn anchor_at(&self, s: f64, anchor: &mut Option<Anchor>, out: &mut Station) -> bool {
        if self.plan.is_empty() {
            return false;
        }
        let geometry = self.plan.partition_point(|g| g.s <= s).saturating_sub(1);
        let g = &self.plan[geometry];
        *out = g.station(s - g.s);
        let from = if geometry == 0 { f64::NEG_INFINITY } else { g.s };
        let to = self.plan.get(geometry + 1).map_or(f64::INFINITY, |n| n.s);
        let bend = match g.shape {
            Shape::Line | Shape::Arc { curvature: 0.0 } => Bend::Line,
            Shape::Arc { curvature } => Bend::Arc(curvature),
            Shape::Spiral { start, end } if g.length > 0.0 => Bend::Spiral((end - start) / g.length),
            _ => Bend::Other,
        };
        *anchor = Some(Anchor { geometry, from, to, s, station: *out, generation: 0, bend });
        true
    }

    /// The footing at `s` (clamped to the road), its station reached from `anchor`.
    pub(crate) fn footing(&self, s: f64, anchor: &mut Option<Anchor>) -> Option<Footing> {
        let s = s.clamp(0.0, self.length.max(0.0));
        let mut station = Station::default();
        self.station_at(s, anchor, &mut station).then_some(Footing { s, station, fresh: true })
    }

    /// The foot of the world point (x, y) on the reference line, searched within `lo..=hi`
    /// from `at`, which it moves (the stations reached from `anchor`): s, and how far the
    /// point lies from the line on the ground (to the left positive); `None` where the
    /// search leaves the range or the road. Within [`SNAP`] of the foot, the last Newton
    /// step is taken without its station: its error is of the order of the curvature
    /// times the square of the step, far below rounding.
    #[inline(always)]
    pub(crate) fn foot(
        &self,
        x: f64,
        y: f64,
        anchor: &mut Option<Anchor>,
        at: &mut Footing,
        (lo, hi): (f64, f64),
    ) -> Option<(f64, f64)> {
        if let Some(a) = anchor {
            if let Some((s, across, turn)) = a.closed_foot(x, y) {
                let on_road = 0.0 <= s && s <= self.length;
                if lo <= s && s <= hi && on_road && a.from <= s && s < a.to {
                    at.s = s;
                    at.fresh = false;
                    if turn > MOVE_TURN {
                        let to = a.next_s(s, turn).min(self.length);
                        self.move_anchor(to, anchor);
                    }
                    return Some((s, across));
                }
            }
            if !at.fresh {
                *at = Footing { s: a.s, station: a.station, fresh: true };
            }
        }
        self.newton_foot(x, y, anchor, at, (lo, hi))
    }

    /// [`Road::foot`] by Newton's method, where no closed form serves.
    #[inline(never)]
    fn newton_foot(
        &self,
        x: f64,
        y: f64,
        anchor: &mut Option<Anchor>,
        at: &mut Footing,
        (lo, hi): (f64, f64),
    ) -> Option<(f64, f64)> {
        let (lo, hi) = (lo.max(0.0), hi.min(self.length));
        if !(lo <= hi) {
            return None;
        }
        for _ in 0..30 {
            let p = &at.station;
            let (ex, ey) = (x - p.pose.x, y - p.pose.y);
            let along = ex * p.cos + ey * p.sin;
            let across = -ex * p.sin + ey * p.cos;
            if along.abs() <= FOOT {
                return Some((at.s, across));
            }
            // The normal turns with the curvature as s moves.
            let k = p.pose.curvature;
            let step = if k == 0.0 { along } else { along / (1.0 - k * across).max(0.1) };
            let next = (at.s + step.clamp(-STRETCH, STRETCH)).clamp(lo, hi);
            if along.abs() <= SNAP && next == at.s + step {
                return Some((next, across));
            }
            if (next - at.s).abs() < FOOT {
                return (along.abs() <= 1e-6).then_some((at.s, across));
            }
            if !self.station_at(next, anchor, &mut at.station) {
                return None;
            }
            at.s = next;
        }
        None
    }

    /// t of the surface point over the point `ground` from the reference line at s (on the
    /// ground, across it), the superelevation `roll` with its sine and cosine; `level`
    /// where the surface lies on the cross section there. The surface point at t lies
    /// t cos r - h(s, t) sin r from the line on the ground.
    #[inline(always)]
    pub(crate) fn across(&self, s: f64, ground: f64, roll: f64, (sr, cr): (f64, f64), level: bool) -> f64 {
        let t = ground / cr;
        if roll != 0.0 && !level {
            return self.across_lifted(s, ground, (sr, cr), t);
        }
        t
    }

    /// [`Road::across`] where the surface lies above the tilted cross section: the height
    /// there moves the point across, by fixed-point rounds from `t`.
    #[cold]
    #[inline(never)]
    fn across_lifted(&self, s: f64, ground: f64, (sr, cr): (f64, f64), mut t: f64) -> f64 {
        for _ in 0..4 {
            let h = self.height_above_section(s, t);
            if h == 0.0 {
                break;
            }
            t = (ground + h * sr) / cr;
        }
        t
    }

    /// Whether the surface lies on the cross section at s (no lateral shape, no lane heights).
    pub(crate) fn level_at(&self, s: f64) -> bool {
        self.shape.is_empty() && !self.lanes.section_at(s).is_some_and(|(l, _)| l.has_heights())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Geometry;

    /// A small file whose roads say they are 10,000 km long each (a typo a hundred times
    /// over) is indexed in about [`MAX_STRETCHES`] stretches, not a billion, and its points
    /// are found.
    /// A long cubic curve, sampled station from station: every point along it, and 2 m
    /// to its left, lies in a stretch of the index around its own s.
    #[test]
    fn a_long_cubic_curve_is_indexed_where_it_lies() {
        let text = "<OpenDRIVE><header revMajor=\"1\" revMinor=\"8\"/><road id=\"1\" length=\"1000\" junction=\"-1\"><planView>\
            <geometry s=\"0\" x=\"3\" y=\"-2\" hdg=\"0.3\" length=\"1000\"><paramPoly3 aU=\"0\" bU=\"960\" cU=\"60\" dU=\"-20\" \
            aV=\"0\" bV=\"0\" cV=\"180\" dV=\"-140\"/></geometry></planView>\
            <lanes><laneSection s=\"0\"><center><lane id=\"0\" type=\"none\"/></center></laneSection></lanes></road></OpenDRIVE>";
        let map = Map::from_bytes(text.as_bytes(), std::path::Path::new("cubic.xodr")).unwrap();
        let index = RoadIndex::new(&map);
        let road = &map.roads[0];
        for k in 0..=200 {
            let s = road.length * f64::from(k) / 200.0;
            let r = road.reference(s);
            for t in [0.0, 2.0] {
                let (x, y) = (r.x - t * r.hdg.sin(), r.y + t * r.hdg.cos());
                let held = index.candidates(x, y).any(|(i, s0, s1)| i == 0 && s0 <= s + 1e-9 && s <= s1 + 1e-9);
                assert!(held, "s = {s}, t = {t}: no stretch holds it");
            }
        }
    }

    #[test]
    fn the_index_stays_in_proportion_to_the_file() {
        let road = |i: usize| {
            format!(
                "<road id=\"{i}\" length=\"1e7\" junction=\"-1\"><planView><geometry s=\"0\" x=\"0\" y=\"{}\" hdg=\"0\" length=\"1e7\"><line/></geometry></planView>\
                 <lanes><laneSection s=\"0\"><left><lane id=\"1\" type=\"driving\"><width sOffset=\"0\" a=\"3\" b=\"0\" c=\"0\" d=\"0\"/></lane></left>\
                 <center><lane id=\"0\" type=\"none\"/></center></laneSection></lanes></road>",
                i * 10
            )
        };
        let roads: String = (0..100).map(road).collect();
        let text = format!("<OpenDRIVE><header revMajor=\"1\" revMinor=\"8\"/>{roads}</OpenDRIVE>");
        let map = Map::from_bytes(text.as_bytes(), std::path::Path::new("long.xodr")).unwrap();
        let index = RoadIndex::new(&map);
        let size = index.tree.size();
        assert!((100..=MAX_STRETCHES as usize + 100).contains(&size), "{size} stretches");
        let found: Vec<usize> = index.candidates(5e6, 301.0).map(|(road, ..)| road).collect();
        assert!(found.contains(&30), "{found:?}");
    }

    /// Feet found in closed form on lines, arcs and spirals of either turn are feet: the
    /// station there, computed from the record, has the point on its normal at the
    /// distance found.
    #[test]
    fn closed_form_feet_are_feet() {
        let mut checked = 0;
        let shapes = [
            Shape::Line,
            Shape::Arc { curvature: 0.004 },
            Shape::Arc { curvature: -0.1 },
            Shape::Spiral { start: 0.0, end: 0.004 },
            Shape::Spiral { start: 0.02, end: -0.05 },
            Shape::Spiral { start: -0.002, end: -0.1 },
        ];
        for shape in shapes {
            let g = Geometry { s: 5.0, x: 10.0, y: -3.0, hdg: 0.7, length: 80.0, shape };
            let station = g.station(30.0);
            let bend = match shape {
                Shape::Arc { curvature } => Bend::Arc(curvature),
                Shape::Spiral { start, end } => Bend::Spiral((end - start) / g.length),
                _ => Bend::Line,
            };
            let anchor = Anchor { geometry: 0, from: 5.0, to: 85.0, s: 35.0, station, generation: 0, bend };
            for along in [-3.0, -0.4, -0.02, 0.0, 1e-7, 0.015, 0.3, 2.0] {
                for across in [-4.0, -0.8, 0.0, 0.8, 3.5] {
                    let p = station.pose;
                    let (x, y) = (
                        p.x + along * station.cos - across * station.sin,
                        p.y + along * station.sin + across * station.cos,
                    );
                    let Some((s, off, _)) = anchor.closed_foot(x, y) else { continue };
                    let foot = g.station(s - g.s);
                    let (ex, ey) = (x - foot.pose.x, y - foot.pose.y);
                    let (a, c) = (ex * foot.cos + ey * foot.sin, -ex * foot.sin + ey * foot.cos);
                    assert!(a.abs() < 1e-12 && (c - off).abs() < 1e-12, "{shape:?} {along} {across}: {a} {c} {off}");
                    checked += 1;
                }
            }
        }
        // Lines answer everywhere; arcs and spirals within their closed turn (0.25 m at a
        // curvature of 0.004, 1 cm at 0.1).
        assert!(checked >= 40 + 20 + 10 + 30 + 20 + 20, "{checked}");
    }
}
