//! The ground of a map as a vehicle meets it: at a world x/y, which road, lane, s and t,
//! how high the surface is, which way is up and how grippy it is, with the CRG records
//! laid on the roads (`../shared/spec/opendrive-crg.md`). [`Surface`] holds the map, its
//! index and its CRG files, shared by every wheel; a [`Probe`] per wheel (or thread) keeps
//! where its wheel was, so that a wheel moving along a road is found again without the
//! index, and its own contact points on the CRG files.

use crate::crg::{self, CrgFiles, CrgPoints, Laid, Layer, Source};
use crate::last_wins::{layer_at, visible};
use crate::locate::{Anchor, Footing, RoadIndex, RoadPos};
use crate::map::{CrgPurpose, Junction, Map, Road};
use crate::patch::{Patch, Patches};
use crate::surface::{height_across, span_height};
use crate::trig;
use opencrg_core::Result;
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Arc;

/// A map ready to answer: the map, the index of its roads, its CRG files loaded.
pub struct Surface {
    map: Map,
    index: RoadIndex,
    files: CrgFiles,
    /// Per road: the CRG records that apply to it (its own, then its junction's), laid on it.
    layers: Vec<Vec<Layer>>,
    /// Per road: its patches, the records holding between its cuts.
    patches: Vec<Patches>,
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

    /// `map` ready to answer, its CRG files read from where its records name them.
    pub fn new(map: Map) -> Result<Surface> {
        Surface::with_files(map, &Source::Disk)
    }

    /// `map` ready to answer, its CRG files from `files` (name and content): a record
    /// takes the file named as its `file` attribute is written, else the one of the same
    /// last path component. For maps read from bytes, where there is no folder.
    pub fn from_files(map: Map, files: &[(String, Vec<u8>)]) -> Result<Surface> {
        Surface::with_files(map, &Source::Memory(files))
    }

    fn with_files(map: Map, source: &Source<'_>) -> Result<Surface> {
        let files = CrgFiles::load(&map, source)?;
        let index = RoadIndex::new(&map);
        let junctions: BTreeMap<&str, &Junction> = map.junctions.iter().map(|j| (j.id.as_str(), j)).collect();
        let layers = map
            .roads
            .iter()
            .map(|road| {
                let junction = road.junction.as_deref().and_then(|j| junctions.get(j));
                let own = road.crg.iter().map(|r| (r, false));
                let records = own.chain(junction.into_iter().flat_map(|j| &j.crg).map(|r| (r, true))).collect();
                let records = visible(records, |&(r, _)| r).into_iter();
                let layer = |(r, of_junction)| files.index(r).map(|k| Layer::new(r, k, &files, road, of_junction));
                records.filter_map(layer).collect::<Vec<_>>()
            })
            .collect::<Vec<_>>();
        let patches = map.roads.iter().zip(&layers).map(|(road, layers)| Patches::new(road, layers)).collect();
        Ok(Surface { map, index, files, layers, patches })
    }

    /// The map.
    pub fn map(&self) -> &Map {
        &self.map
    }

    /// What [`check`](crate::check) finds wrong with the map (its CRG files, read
    /// already, are usable).
    pub fn check(&self) -> Vec<crate::check::Finding> {
        crate::check::check_from(&self.map, None)
    }

    /// Where on road `road` (index) the elevation records start and end (s).
    pub fn crg_bounds(&self, road: usize) -> impl Iterator<Item = f64> + '_ {
        self.layers[road]
            .iter()
            .filter(|l| l.record.purpose == CrgPurpose::Elevation)
            .flat_map(|l| [l.record.s_start, l.record.s_end])
    }

    /// The grid increments (du, dv) of the CRG file whose elevation record holds at s of
    /// road `road` (index), if one does.
    pub fn elevation_detail(&self, road: usize, s: f64) -> Option<(f64, f64)> {
        let layer = self.layers[road]
            .iter()
            .rev()
            .find(|l| l.record.purpose == CrgPurpose::Elevation && l.record.s_start <= s && s <= l.record.s_end)?;
        Some(self.files.files[layer.laid.file].whole.increments())
    }

    /// The outline of every CRG record's area in world x/y/z (heights from the ground,
    /// NaN off every road), closed polylines, with the road (index) it is drawn on and
    /// the record's purpose.
    pub fn crg_outlines(self: &Arc<Self>) -> Vec<(usize, CrgPurpose, Vec<[f64; 3]>)> {
        let mut probe = self.probe();
        let mut out = Vec::new();
        // A junction's records are drawn once, on the first of its roads.
        let mut first_roads = BTreeMap::new();
        for (i, road) in self.map.roads.iter().enumerate() {
            if let Some(j) = &road.junction {
                first_roads.entry(j.as_str()).or_insert(i);
            }
        }
        for (i, road) in self.map.roads.iter().enumerate() {
            let first_of_junction = road.junction.as_deref().is_none_or(|j| first_roads.get(j) == Some(&i));
            for layer in &self.layers[i] {
                let record = &layer.record;
                if layer.of_junction && !first_of_junction {
                    continue;
                }
                let line = crg::outline(layer, &self.files.files[layer.laid.file], road);
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
    /// the file), with the station and the anchor its search ended on.
    #[inline(never)]
    fn locate(&self, x: f64, y: f64) -> Option<(Spot<'_>, Footing, Option<Anchor>)> {
        let mut best: Option<(Spot<'_>, Footing, Option<Anchor>)> = None;
        for (i, s0, s1) in self.index.candidates(x, y) {
            let road = &self.map.roads[i];
            let mut anchor = None;
            let Some(mut at) = road.footing(0.5 * (s0 + s1), &mut anchor) else { continue };
            let Some((s, ground)) = road.foot(x, y, &mut anchor, &mut at, (s0 - 1.0, s1 + 1.0)) else { continue };
            let mut patch = usize::MAX;
            let Some(spot) = self.place(i, s, ground, &mut patch) else { continue };
            let better = match &best {
                None => true,
                Some((was, ..)) => (spot.real && !was.real) || (spot.real == was.real && i < was.pos.road),
            };
            if better {
                best = Some((spot, at, anchor));
            }
        }
        best
    }

    /// Where (x, y) lies on the road the wheel of `track` was on, near where it was;
    /// `None` off that road's lanes of a type other than `none`, or where the wheel was on
    /// no road.
    fn find_on_track(&self, x: f64, y: f64, track: &mut Track) -> Option<Spot<'_>> {
        let (road, s, ground) = self.foot_on_track(x, y, track)?;
        self.place(road, s, ground, &mut track.patch).filter(|spot| spot.real)
    }

    /// The foot of (x, y) on the road the wheel of `track` was on, near where it was:
    /// the road (index), s and how far the point lies from the line on the ground.
    #[inline(always)]
    fn foot_on_track(&self, x: f64, y: f64, track: &mut Track) -> Option<(usize, f64, f64)> {
        let (i, at) = track.last.as_mut()?;
        let range = (at.s - 10.0, at.s + 10.0);
        let (s, ground) = self.map.roads[*i].foot(x, y, &mut track.anchor, at, range)?;
        Some((*i, s, ground))
    }

    /// Where (x, y) lies on the map, searched through the index, which `track` then
    /// follows; `None` off every road.
    #[inline(never)]
    fn find_searched(&self, x: f64, y: f64, track: &mut Track) -> Option<Spot<'_>> {
        match self.locate(x, y) {
            Some((spot, at, anchor)) => {
                *track = Track { last: Some((spot.pos.road, at)), anchor, patch: usize::MAX };
                Some(spot)
            }
            None => {
                *track = Track::default();
                None
            }
        }
    }

    /// The place on road `road` (index) at s whose surface lies over the point `ground`
    /// from the reference line (on the ground, across it); `None` outside its lanes.
    /// `patch` is the index of the road's patch tried first, and becomes the one used.
    fn place(&self, road: usize, s: f64, ground: f64, patch: &mut usize) -> Option<Spot<'_>> {
        let spot = match self.patched_place(road, s, ground, patch) {
            Some(spot) => spot,
            None => self.place_from_road(road, s, ground),
        };
        spot.lane.is_some().then_some(spot)
    }

    /// [`Surface::place`] from the patch serving s, lane or not; `None` where no patch
    /// serves s.
    #[inline(always)]
    fn patched_place(&self, road: usize, s: f64, ground: f64, patch: &mut usize) -> Option<Spot<'_>> {
        let patches = &self.patches[road];
        let (i, p) = patches.find(s, *patch)?;
        *patch = i;
        let (roll, sin_cos) = p.tilt.unwrap_or_else(|| {
            let roll = p.superelevation.value(s - p.superelevation.s);
            (roll, trig::sin_cos(roll))
        });
        let t = self.map.roads[road].across(s, ground, roll, sin_cos, p.level);
        Some(self.patched_spot(road, patches, p, s, t, sin_cos))
    }

    /// [`Surface::place`] from the road's own records, where no patch serves s.
    #[cold]
    #[inline(never)]
    fn place_from_road(&self, road: usize, s: f64, ground: f64) -> Spot<'_> {
        let r = &self.map.roads[road];
        let roll = r.superelevation.at(s);
        let sin_cos = trig::sin_cos(roll);
        let t = r.across(s, ground, roll, sin_cos, r.level_at(s));
        self.spot_from_road(road, s, t, sin_cos)
    }

    /// The spot at (s, t) of road `road` (index) with the records of `p`, one of its
    /// `patches` (which serves s), the superelevation's sine and cosine `roll`.
    #[inline(always)]
    fn patched_spot<'a>(
        &self,
        road: usize,
        patches: &'a Patches,
        p: &'a Patch,
        s: f64,
        t: f64,
        roll: (f64, f64),
    ) -> Spot<'a> {
        let lane = patches.lane_at(p, s, t);
        let shape = if p.level { 0.0 } else { self.map.roads[road].shape_height(s, t) };
        Spot {
            pos: RoadPos { road, s, t },
            roll,
            lane: lane.map(|(l, ..)| l.id),
            real: lane.is_some_and(|(l, ..)| l.real),
            elevation: p.elevation.value(s - p.elevation.s),
            above: shape + lane.map_or(0.0, |(l, inner, outer)| height_across(l.heights, inner, outer, t)),
            friction: lane.map_or(f64::NAN, |(l, ..)| l.friction),
            crg: [p.crg[0].as_ref(), p.crg[1].as_ref()],
        }
    }

    /// The spot at (s, t) of road `road` (index), from the road's records (where no patch
    /// serves s), the superelevation's sine and cosine `roll`.
    fn spot_from_road(&self, road: usize, s: f64, t: f64, roll: (f64, f64)) -> Spot<'_> {
        let r = &self.map.roads[road];
        let lane = r.lane_place(s, t);
        let layers = &self.layers[road];
        Spot {
            pos: RoadPos { road, s, t },
            roll,
            lane: lane.map(|(l, _)| l.lane.id),
            real: lane.is_some_and(|(l, _)| l.lane.kind != "none"),
            elevation: r.elevation.at(s),
            above: r.shape_height(s, t) + lane.map_or(0.0, |(l, ds)| span_height(&l, ds, t)),
            friction: lane.and_then(|(l, ds)| l.lane.friction_at(ds)).unwrap_or(f64::NAN),
            crg: [CrgPurpose::Elevation, CrgPurpose::Friction].map(|p| layer_at(layers, p, s).map(|i| &layers[i].laid)),
        }
    }

    /// The spot at (s, t) of road `road` (index), lane or not.
    fn spot_st(&self, road: usize, s: f64, t: f64) -> Spot<'_> {
        let roll = trig::sin_cos(self.map.roads[road].superelevation.at(s));
        let patches = &self.patches[road];
        match patches.find(s, usize::MAX) {
            Some((_, p)) => self.patched_spot(road, patches, p, s, t, roll),
            None => self.spot_from_road(road, s, t, roll),
        }
    }

    /// The ground at a place of the map, (x, y) its world point.
    #[inline(always)]
    fn ground_at(&self, spot: Spot, points: &mut CrgPoints, x: f64, y: f64) -> Ground {
        let Spot { pos, roll: (sr, cr), .. } = spot;
        let (s, t) = (pos.s, pos.t);
        let mut ground = Ground {
            road: pos.road,
            lane: spot.lane.unwrap_or(0),
            s,
            t,
            z: spot.elevation + t * sr + spot.above * cr,
            friction: spot.friction,
        };
        if let [Some(elevation), _] = spot.crg {
            ground.z = elevation.height(points, (x, y, s, t), ground.z);
        }
        if let [_, Some(friction)] = spot.crg {
            ground.friction = friction.value_called(points, (x, y, s, t));
        }
        ground
    }
}

/// A world point's place on a road and what its ground needs there: the superelevation's
/// sine and cosine, the lane, the reference line's height, the surface's height above the
/// cross section, the lane material's friction and the CRG layers that hold.
#[derive(Clone, Copy)]
struct Spot<'a> {
    pos: RoadPos,
    roll: (f64, f64),
    /// The lane's id; `None` outside the lanes.
    lane: Option<i32>,
    /// Whether the lane is of a type other than `none`.
    real: bool,
    elevation: f64,
    above: f64,
    friction: f64,
    /// The CRG records that hold: elevation, friction.
    crg: [Option<&'a Laid>; 2],
}

/// Where a wheel was: its road (index) and footing there, the anchor its searches start
/// from and the patch of its road it was on.
struct Track {
    last: Option<(usize, Footing)>,
    anchor: Option<Anchor>,
    patch: usize,
}

impl Default for Track {
    fn default() -> Track {
        Track { last: None, anchor: None, patch: usize::MAX }
    }
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
        let surface = &*self.surface;
        let spot = surface.find_on_track(x, y, &mut self.track);
        spot.or_else(|| surface.find_searched(x, y, &mut self.track)).map(|spot| spot.pos)
    }

    /// The ground at (x, y); `None` off every road.
    pub fn ground(&mut self, x: f64, y: f64) -> Option<Ground> {
        let surface = &*self.surface;
        if let Some((road, s, ground)) = surface.foot_on_track(x, y, &mut self.track) {
            match surface.patched_place(road, s, ground, &mut self.track.patch) {
                Some(spot) if spot.real => return Some(surface.ground_at(spot, &mut self.points, x, y)),
                Some(_) => {}
                None => {
                    if let Some(ground) = self.ground_near_cut(road, s, ground, x, y) {
                        return Some(ground);
                    }
                }
            }
        }
        self.ground_searched(x, y)
    }

    /// [`Probe::ground`] on the wheel's road where no patch serves s (within rounding of
    /// a cut): from the road's own records.
    #[cold]
    #[inline(never)]
    fn ground_near_cut(&mut self, road: usize, s: f64, ground: f64, x: f64, y: f64) -> Option<Ground> {
        let surface = &*self.surface;
        let spot = surface.place_from_road(road, s, ground);
        spot.real.then(|| surface.ground_at(spot, &mut self.points, x, y))
    }

    /// [`Probe::ground`] where the wheel has left the road it was on (or was on none).
    #[inline(never)]
    fn ground_searched(&mut self, x: f64, y: f64) -> Option<Ground> {
        let surface = &*self.surface;
        let spot = surface.find_searched(x, y, &mut self.track)?;
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
        let spot = surface.spot_st(road, s, t);
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Every shared map, every road: at s all along it (cuts included) and t across its
    /// lanes, the spot a patch gives is the spot the road's own records give, to the bit.
    #[test]
    #[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
    fn shared_maps_patches_give_what_the_roads_records_give() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/opendrive");
        let (mut patched, mut near_cuts) = (0usize, 0usize);
        for group in ["carla", "esmini"] {
            for entry in std::fs::read_dir(dir.join(group)).unwrap() {
                let path = entry.unwrap().path();
                if path.extension().is_none_or(|e| e != "xodr") {
                    continue;
                }
                let surface = Surface::load(&path).unwrap();
                for (i, road) in surface.map.roads.iter().enumerate() {
                    let cuts = road.lanes.sections.iter().map(|l| l.s).chain(road.elevation.starts());
                    let mut stations: Vec<(f64, bool)> =
                        (1..40).map(|k| (road.length * k as f64 / 40.0, true)).collect();
                    stations.extend(cuts.flat_map(|c| [c - 1e-6, c + 1e-6, c + 0.01]).map(|s| (s, false)));
                    for (s, even) in stations {
                        let patches = &surface.patches[i];
                        let Some((_, p)) = patches.find(s, usize::MAX) else {
                            near_cuts += usize::from(even);
                            continue;
                        };
                        let roll = trig::sin_cos(road.superelevation.at(s));
                        for k in -24..=24 {
                            let t = k as f64 * 0.75 + 0.013;
                            let (a, b) = (
                                surface.patched_spot(i, patches, p, s, t, roll),
                                surface.spot_from_road(i, s, t, roll),
                            );
                            let same = a.lane == b.lane
                                && a.real == b.real
                                && a.elevation.to_bits() == b.elevation.to_bits()
                                && a.above.to_bits() == b.above.to_bits()
                                && a.friction.to_bits() == b.friction.to_bits()
                                && a.crg == b.crg;
                            assert!(same, "{} road {} s {s} t {t}", path.display(), road.id);
                            patched += 1;
                        }
                    }
                }
            }
        }
        // Points within the margin of a cut are the road's own to answer: hardly any of the
        // evenly spaced stations.
        assert!(patched > 1_000_000 && near_cuts * 49 * 1000 < patched, "{patched} compared, {near_cuts} near cuts");
    }
}
