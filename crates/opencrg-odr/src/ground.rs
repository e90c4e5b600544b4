//! The ground of a map as a vehicle meets it: at a world x/y, which road, lane, s and t,
//! how high the surface is, which way is up and how grippy it is, with the CRG records
//! laid on the roads (`../shared/spec/opendrive-crg.md`). [`Surface`] holds the map, its
//! index and its CRG files, shared by every wheel; a [`Probe`] per wheel (or thread) keeps
//! where its wheel was, so that a wheel moving along a road is found again without the
//! index, and its own contact points on the CRG files.

use crate::crg::{self, CrgFiles, CrgPoints};
use crate::geometry::Station;
use crate::lanes::LaneSpan;
use crate::locate::{Anchor, RoadIndex, RoadPos};
use crate::map::{CrgPurpose, CrgRecord, Map, Road};
use crate::surface::span_height;
use crate::trig;
use opencrg::Result;
use std::path::Path;
use std::sync::Arc;

/// A map ready to answer: the map, the index of its roads, its CRG files loaded.
pub struct Surface {
    map: Map,
    index: RoadIndex,
    files: CrgFiles,
    /// Per road: the CRG records that apply to it (its own, then its junction's), with
    /// the index of their file.
    layers: Vec<Vec<(CrgRecord, usize)>>,
}

/// What the ground is at a world point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ground {
    /// The road's index in [`Map::roads`].
    pub road: usize,
    /// The lane's id (0 on the centre line of a section without lanes there).
    pub lane: i32,
    /// s along the road.
    pub s: f64,
    /// t across it.
    pub t: f64,
    /// The surface's height, CRG records laid on (NaN in a hole of a CRG's grid).
    pub z: f64,
    /// The friction coefficient: a friction record's, else the lane material's; NaN
    /// where neither gives one.
    pub friction: f64,
}

impl Surface {
    /// Reads the map in `path`, indexes its roads and loads the CRG files its records
    /// name (each once).
    pub fn load(path: impl AsRef<Path>) -> Result<Surface> {
        Surface::new(Map::load(path)?)
    }

    /// `map` ready to answer.
    pub fn new(map: Map) -> Result<Surface> {
        let files = CrgFiles::load(&map)?;
        let index = RoadIndex::new(&map);
        let layers = map
            .roads
            .iter()
            .map(|road| {
                let junction = road.junction.as_ref().and_then(|j| map.junctions.iter().find(|x| &x.id == j));
                let records = road.crg.iter().chain(junction.into_iter().flat_map(|j| &j.crg));
                records.filter_map(|r| files.index(r).map(|k| (r.clone(), k))).collect()
            })
            .collect();
        Ok(Surface { map, index, files, layers })
    }

    /// The map.
    pub fn map(&self) -> &Map {
        &self.map
    }

    /// Where on road `road` (index) the elevation records start and end (s).
    pub(crate) fn crg_bounds(&self, road: usize) -> impl Iterator<Item = f64> + '_ {
        self.layers[road]
            .iter()
            .filter(|(r, _)| r.purpose == CrgPurpose::Elevation)
            .flat_map(|(r, _)| [r.s_start, r.s_end])
    }

    /// The grid increments (du, dv) of the CRG file whose elevation record holds at s of
    /// road `road` (index), if one does.
    pub(crate) fn elevation_detail(&self, road: usize, s: f64) -> Option<(f64, f64)> {
        let (_, k) = self.layers[road]
            .iter()
            .rev()
            .find(|(r, _)| r.purpose == CrgPurpose::Elevation && r.s_start <= s && s <= r.s_end)?;
        Some(self.files.files[*k].whole.increments())
    }

    /// The outline of every CRG record's area in world x/y/z (heights from the ground,
    /// NaN off every road), closed polylines, with the road (index) it is drawn on and
    /// the record's purpose.
    pub fn crg_outlines(self: &Arc<Self>) -> Vec<(usize, CrgPurpose, Vec<[f64; 3]>)> {
        let mut probe = self.probe();
        let mut out = Vec::new();
        for (i, road) in self.map.roads.iter().enumerate() {
            // A junction's records are drawn once, on the first of its roads.
            let first_of_junction = road
                .junction
                .as_ref()
                .is_none_or(|j| self.map.roads.iter().position(|r| r.junction.as_ref() == Some(j)) == Some(i));
            for (record, k) in &self.layers[i] {
                let own = road.crg.contains(record);
                if !own && !first_of_junction {
                    continue;
                }
                let line = crg::outline(record, &self.files.files[*k], road);
                let with_z = line.iter().map(|&[x, y]| [x, y, probe.ground(x, y).map_or(f64::NAN, |g| g.z)]).collect();
                out.push((i, record.purpose, with_z));
            }
        }
        out
    }

    /// A probe for one wheel (or thread).
    pub fn probe(self: &Arc<Self>) -> Probe {
        Probe { surface: self.clone(), track: Track::default(), points: CrgPoints::new(&self.files) }
    }

    /// Where (x, y) lies on the map, searched through the index: the road whose lane
    /// holds it (a driving lane's before a lane of type `none`, then the first road in
    /// the file), with the anchor its search ended on.
    fn locate(&self, x: f64, y: f64) -> Option<(Spot<'_>, Station, Option<Anchor>)> {
        let mut best: Option<(bool, Spot<'_>, Station, Option<Anchor>)> = None;
        for (i, s0, s1) in self.index.candidates(x, y) {
            let road = &self.map.roads[i];
            let mut anchor = None;
            let Some(p) = road.project_from(x, y, &mut anchor, None, 0.5 * (s0 + s1), (s0 - 1.0, s1 + 1.0)) else {
                continue;
            };
            let Some(lane) = road.lane_place(p.s, p.t) else { continue };
            let real = lane.0.lane.kind != "none";
            let better = match &best {
                None => true,
                Some((was_real, was, ..)) => (real && !was_real) || (real == *was_real && i < was.pos.road),
            };
            if better {
                let spot = Spot { pos: RoadPos { road: i, s: p.s, t: p.t }, roll: p.roll, lane: Some(lane) };
                best = Some((real, spot, p.station, anchor));
            }
        }
        best.map(|(_, spot, station, anchor)| (spot, station, anchor))
    }

    /// Where (x, y) lies on the map: first on the road the wheel of `track` was on, near
    /// where it was, else through the index; `None` off every road.
    fn find(&self, x: f64, y: f64, track: &mut Track) -> Option<Spot<'_>> {
        if let Some((last, station)) = track.last {
            let road = &self.map.roads[last.road];
            let (lo, hi) = (last.s - 10.0, last.s + 10.0);
            if let Some(p) = road.project_from(x, y, &mut track.anchor, Some((last.s, station)), last.s, (lo, hi)) {
                if let Some(lane) = road.lane_place(p.s, p.t).filter(|(l, _)| l.lane.kind != "none") {
                    let pos = RoadPos { road: last.road, s: p.s, t: p.t };
                    track.last = Some((pos, p.station));
                    return Some(Spot { pos, roll: p.roll, lane: Some(lane) });
                }
            }
        }
        match self.locate(x, y) {
            Some((spot, station, anchor)) => {
                *track = Track { last: Some((spot.pos, station)), anchor };
                Some(spot)
            }
            None => {
                *track = Track::default();
                None
            }
        }
    }

    /// The ground at a place of the map, (x, y) its world point.
    fn ground_at(&self, spot: Spot<'_>, points: &mut CrgPoints, x: f64, y: f64) -> Ground {
        let Spot { pos, roll: (sr, cr), lane } = spot;
        let road = &self.map.roads[pos.road];
        let (s, t) = (pos.s, pos.t);
        let lane_height = lane.map_or(0.0, |(l, ds)| span_height(&l, ds, t));
        let height = road.shape_height(s, t) + lane_height;
        let mut ground = Ground {
            road: pos.road,
            lane: lane.map_or(0, |(l, _)| l.lane.id),
            s,
            t,
            z: road.elevation.at(s) + t * sr + height * cr,
            friction: lane.and_then(|(l, ds)| l.lane.friction_at(ds)).unwrap_or(f64::NAN),
        };
        let layers = &self.layers[pos.road];
        for purpose in [CrgPurpose::Elevation, CrgPurpose::Friction] {
            let last = layers.iter().rev().find(|(r, _)| r.purpose == purpose && r.s_start <= s && s <= r.s_end);
            let Some((record, k)) = last else { continue };
            let value = crg::value(record, *k, &self.files, points, road, (x, y, s, t));
            match purpose {
                CrgPurpose::Friction => ground.friction = value,
                CrgPurpose::Elevation => {
                    let own = if record.mode == crate::map::CrgMode::Attached { ground.z } else { 0.0 };
                    ground.z = value * record.z_scale + record.z_offset + own;
                }
            }
        }
        ground
    }
}

/// A world point's place on a road, with what its ground needs: the superelevation's sine
/// and cosine, the lane and the distance into its section.
#[derive(Clone, Copy)]
struct Spot<'a> {
    pos: RoadPos,
    roll: (f64, f64),
    lane: Option<(LaneSpan<'a>, f64)>,
}

/// Where a wheel was: its place and the reference line's station there, and the anchor
/// its searches start from.
#[derive(Default)]
struct Track {
    last: Option<(RoadPos, Station)>,
    anchor: Option<Anchor>,
}

/// One wheel's view of a [`Surface`]: where it was last, its contact points on the CRG
/// files. Cheap to make; not shared between threads.
pub struct Probe {
    surface: Arc<Surface>,
    track: Track,
    points: CrgPoints,
}

impl Probe {
    /// The surface probed.
    pub fn surface(&self) -> &Arc<Surface> {
        &self.surface
    }

    /// Where (x, y) lies on the map: first on the road the wheel was on, near where it
    /// was, else through the index; `None` off every road.
    pub fn locate(&mut self, x: f64, y: f64) -> Option<RoadPos> {
        self.surface.find(x, y, &mut self.track).map(|spot| spot.pos)
    }

    /// The ground at (x, y); `None` off every road.
    pub fn ground(&mut self, x: f64, y: f64) -> Option<Ground> {
        let surface = &*self.surface;
        let spot = surface.find(x, y, &mut self.track)?;
        Some(surface.ground_at(spot, &mut self.points, x, y))
    }

    /// The ground at (s, t) of road `road` (index in [`Map::roads`]), with the world point
    /// of the road's surface there: `(x, y, ground)`.
    pub fn ground_st(&mut self, road: usize, s: f64, t: f64) -> Option<(f64, f64, Ground)> {
        let surface = &*self.surface;
        let r: &Road = surface.map.roads.get(road)?;
        let [x, y, _] = r.surface_point(s, t);
        if !(x.is_finite() && y.is_finite()) {
            return None;
        }
        let spot =
            Spot { pos: RoadPos { road, s, t }, roll: trig::sin_cos(r.superelevation.at(s)), lane: r.lane_place(s, t) };
        Some((x, y, surface.ground_at(spot, &mut self.points, x, y)))
    }

    /// The upward unit normal of the surface at (x, y), CRG records laid on, from the
    /// heights 5 mm around it; `None` where any of them is off the road or NaN.
    pub fn normal(&mut self, x: f64, y: f64) -> Option<[f64; 3]> {
        const E: f64 = 0.005;
        let mut z = |dx: f64, dy: f64| self.ground(x + dx, y + dy).map(|g| g.z).filter(|z| z.is_finite());
        let (east, west, north, south) = (z(E, 0.0)?, z(-E, 0.0)?, z(0.0, E)?, z(0.0, -E)?);
        let (gx, gy) = ((east - west) / (2.0 * E), (north - south) / (2.0 * E));
        let n = (gx * gx + gy * gy + 1.0).sqrt();
        Some([-gx / n, -gy / n, 1.0 / n])
    }
}
