//! The ground of a map as a vehicle meets it: at a world x/y, which road, lane, s and t,
//! how high the surface is, which way is up and how grippy it is, with the CRG records
//! laid on the roads (`../shared/spec/opendrive-crg.md`). [`Surface`] holds the map, its
//! index and its CRG files, shared by every wheel; a [`Probe`] per wheel (or thread) keeps
//! where its wheel was, so that a wheel moving along a road is found again without the
//! index, and its own contact points on the CRG files.

use crate::crg::{self, CrgFiles, CrgPoints};
use crate::geometry::Pose;
use crate::locate::{RoadIndex, RoadPos};
use crate::map::{CrgPurpose, CrgRecord, Map, Road};
use crate::surface::span_height;
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

    /// A probe for one wheel (or thread).
    pub fn probe(self: &Arc<Self>) -> Probe {
        Probe { surface: self.clone(), last: None, points: CrgPoints::new(&self.files) }
    }

    /// Where (x, y) lies on the map, searched through the index: the road whose lane
    /// holds it (a driving lane's before a lane of type `none`, then the first road in
    /// the file), with the reference line's pose there.
    fn locate(&self, x: f64, y: f64) -> Option<(RoadPos, Pose)> {
        let mut best: Option<(bool, RoadPos, Pose)> = None;
        for (i, s0, s1) in self.index.candidates(x, y) {
            let road = &self.map.roads[i];
            let Some((s, t, pose)) = road.project_from(x, y, None, 0.5 * (s0 + s1), s0 - 1.0, s1 + 1.0) else {
                continue;
            };
            let Some(span) = road.lane_at(s, t) else { continue };
            let real = span.lane.kind != "none";
            let better = match best {
                None => true,
                Some((was_real, was, _)) => (real && !was_real) || (real == was_real && i < was.road),
            };
            if better {
                best = Some((real, RoadPos { road: i, s, t }, pose));
            }
        }
        best.map(|(_, p, pose)| (p, pose))
    }
}

/// One wheel's view of a [`Surface`]: where it was last, its contact points on the CRG
/// files. Cheap to make; not shared between threads.
pub struct Probe {
    surface: Arc<Surface>,
    /// Where the wheel was, and the reference line's pose there.
    last: Option<(RoadPos, Pose)>,
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
        self.find(x, y).map(|(p, _)| p)
    }

    /// [`Probe::locate`] with the reference line's pose there.
    fn find(&mut self, x: f64, y: f64) -> Option<(RoadPos, Pose)> {
        let surface = &self.surface;
        if let Some((last, pose)) = self.last {
            let road = &surface.map.roads[last.road];
            let near = Some((last.s, pose));
            if let Some((s, t, pose)) = road.project_from(x, y, near, last.s, last.s - 10.0, last.s + 10.0) {
                if road.lane_at(s, t).is_some_and(|l| l.lane.kind != "none") {
                    let here = (RoadPos { road: last.road, s, t }, pose);
                    self.last = Some(here);
                    return Some(here);
                }
            }
        }
        let found = surface.locate(x, y);
        self.last = found;
        found
    }

    /// The ground at (x, y); `None` off every road.
    pub fn ground(&mut self, x: f64, y: f64) -> Option<Ground> {
        let (pos, pose) = self.find(x, y)?;
        Some(self.ground_at(pos, Some(pose), x, y))
    }

    /// The ground at a known place of the map, (x, y) its world point; `pose` the
    /// reference line's there, when known.
    fn ground_at(&mut self, pos: RoadPos, pose: Option<Pose>, x: f64, y: f64) -> Ground {
        let surface = &self.surface;
        let road = &surface.map.roads[pos.road];
        let (s, t) = (pos.s, pos.t);
        let reference = match pose {
            Some(p) => road.reference_at(s, p),
            None => road.reference(s),
        };
        let section = road.lanes.section_at(s);
        let lane = section.and_then(|(sec, ds)| sec.lane_at(ds, t, road.lanes.offset.at(s)).map(|l| (l, ds)));
        let lane_height = lane.map_or(0.0, |(l, ds)| span_height(&l, ds, t));
        let height = road.shape_height(s, t) + lane_height;
        let mut ground = Ground {
            road: pos.road,
            lane: lane.map_or(0, |(l, _)| l.lane.id),
            s,
            t,
            z: reference.at(t, height)[2],
            friction: lane.and_then(|(l, ds)| l.lane.friction_at(ds)).unwrap_or(f64::NAN),
        };
        let layers = &surface.layers[pos.road];
        for purpose in [CrgPurpose::Elevation, CrgPurpose::Friction] {
            let last = layers.iter().rev().find(|(r, _)| r.purpose == purpose && r.s_start <= s && s <= r.s_end);
            let Some((record, k)) = last else { continue };
            let value = crg::value(record, *k, &surface.files, &mut self.points, road, (x, y, s, t));
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

    /// The ground at (s, t) of road `road` (index in [`Map::roads`]), with the world point
    /// of the road's surface there: `(x, y, ground)`.
    pub fn ground_st(&mut self, road: usize, s: f64, t: f64) -> Option<(f64, f64, Ground)> {
        let r: &Road = self.surface.map.roads.get(road)?;
        let [x, y, _] = r.surface_point(s, t);
        if !(x.is_finite() && y.is_finite()) {
            return None;
        }
        Some((x, y, self.ground_at(RoadPos { road, s, t }, None, x, y)))
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
