//! The CRG files a map's records lay on its roads: each file loaded once, in its own
//! coordinates (its options and its own modifiers, not the reference library's default
//! ones), and the value a record gives at a point of the road, in every mode and
//! orientation (`../shared/spec/opendrive-crg.md`).

use crate::map::{CrgMode, CrgOrientation, CrgRecord, Map, Road};
use opencrg_core::draft::Draft;
use opencrg_core::math;
use opencrg_core::{ContactPoint, Error, Location, Result};
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::Arc;

/// One CRG file as the records use it: whole, and as its grid alone (the `attached` mode
/// disregards its reference line's height and banking).
pub(crate) struct CrgFile {
    /// The file as read, its own modifiers applied.
    pub whole: Arc<opencrg_core::Road>,
    /// Its grid on a level reference line at height `base`.
    pub grid: Arc<opencrg_core::Road>,
    /// The level reference line's height.
    pub base: f64,
}

/// The CRG files of a map, each loaded once.
#[derive(Default)]
pub(crate) struct CrgFiles {
    pub files: Vec<CrgFile>,
    /// Each file's index by path (a B-tree: see `Map`'s index of roads).
    by_path: BTreeMap<PathBuf, usize>,
}

/// A CRG file for a map, read: its modifiers only if it gives some.
fn prepared(mut road: opencrg_core::Road) -> Result<CrgFile> {
    if !road.header().modifiers_given {
        road.modifiers_mut().clear();
    }
    let line = road.reference_line();
    let climbs = line.slope.is_some() || line.z.is_some() || line.z_first != 0.0;
    let mut flat = road.clone();
    if climbs || line.has_bank {
        // The grid alone: the line's slope, start height and banking dropped.
        let mut d = Draft::of(&road);
        if climbs {
            d.slope = None;
            d.z_start = 0.0;
        }
        d.bank = None;
        flat = d.into_road("the grid alone, as attached records lay it")?;
    }
    road.apply_modifiers();
    flat.apply_modifiers();
    let base = flat.reference_line().z_first;
    Ok(CrgFile { whole: Arc::new(road), grid: Arc::new(flat), base })
}

/// Where a map's CRG files come from.
pub(crate) enum Source<'a> {
    /// The files the records name, resolved against the map's folder.
    Disk,
    /// Files held in memory, by name: a record takes the one named as its `file` is
    /// written, else the one whose last path component is its file's.
    Memory(&'a [(String, Vec<u8>)]),
}

impl Source<'_> {
    /// The road a record's file holds.
    pub(crate) fn read(&self, record: &CrgRecord) -> Result<opencrg_core::Road> {
        match self {
            Source::Disk => opencrg_core::Road::load(&record.path),
            Source::Memory(files) => {
                let last = |name: &str| name.rsplit(['/', '\\']).next().unwrap_or(name).to_string();
                let found = files
                    .iter()
                    .find(|(name, _)| *name == record.file)
                    .or_else(|| files.iter().find(|(name, _)| last(name) == last(&record.file)))
                    .ok_or_else(|| Error::out_of_range(format!("no file named '{}' was given", record.file)))?;
                opencrg_core::Road::from_bytes(found.1.clone(), &found.0)
            }
        }
    }
}

impl CrgFiles {
    /// Loads every file the records of `map` name from `source`; refused: a file that
    /// cannot be read, named with the map's line of the record.
    pub fn load(map: &Map, source: &Source<'_>) -> Result<CrgFiles> {
        let mut files = CrgFiles::default();
        let records = map.roads.iter().flat_map(|r| &r.crg).chain(map.junctions.iter().flat_map(|j| &j.crg));
        for record in records {
            if files.by_path.contains_key(&record.path) {
                continue;
            }
            let file = source.read(record).and_then(prepared).map_err(|e| Error::Format {
                path: map.path.clone(),
                location: Location::Line(record.line),
                field: format!("<CRG> file '{}'", record.file),
                message: e.to_string(),
            })?;
            files.by_path.insert(record.path.clone(), files.files.len());
            files.files.push(file);
        }
        Ok(files)
    }

    /// The index of the file a record names.
    pub fn index(&self, record: &CrgRecord) -> Option<usize> {
        self.by_path.get(&record.path).copied()
    }
}

/// A contact point on each CRG file, kept by whoever evaluates (one per wheel or thread):
/// their x/y search histories follow the wheel. All are made with the probe, so that its
/// queries allocate nothing.
pub(crate) struct CrgPoints {
    whole: Vec<ContactPoint>,
    grid: Vec<ContactPoint>,
}

impl CrgPoints {
    pub fn new(files: &CrgFiles) -> CrgPoints {
        CrgPoints {
            whole: files.files.iter().map(|f| ContactPoint::new(f.whole.clone())).collect(),
            grid: files.files.iter().map(|f| ContactPoint::new(f.grid.clone())).collect(),
        }
    }

    fn whole(&mut self, k: usize) -> &mut ContactPoint {
        &mut self.whole[k]
    }

    fn grid(&mut self, k: usize) -> &mut ContactPoint {
        &mut self.grid[k]
    }
}

/// A CRG record laid on one road: the record, and what evaluating it needs.
#[derive(Debug, Clone)]
pub(crate) struct Layer {
    pub record: CrgRecord,
    pub laid: Laid,
    /// Whether the record is the road's junction's rather than the road's own.
    pub of_junction: bool,
}

/// What evaluating a CRG record laid on a road needs, worked out once for every query:
/// its file's index, where its u/v or x/y come from, what is done with its values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Laid {
    /// The index of its file in [`CrgFiles::files`].
    pub file: usize,
    lay: Lay,
    /// `zScale` and `zOffset`.
    scale: f64,
    offset: f64,
    /// Whether its heights lie on the road's own (mode `attached`).
    on_road: bool,
}

/// How a world point or a road's s/t becomes a place in a CRG file.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Lay {
    /// The attached modes: u = sign (s - s0), v = sign (t - t0), on the file's grid alone
    /// (less its level line's height `base`) or on the whole file.
    Along { s0: f64, t0: f64, sign: f64, grid: bool, base: f64 },
    /// Genuine and global: the file's x/y = R(a) (world - origin) + first, with the sine
    /// and cosine of a.
    Placed { origin: (f64, f64), sin_cos: (f64, f64), first: (f64, f64) },
}

impl Layer {
    /// `record`, whose file is `files`' `file`, laid on `road` (by its junction where
    /// `of_junction`).
    pub fn new(record: &CrgRecord, file: usize, files: &CrgFiles, road: &Road, of_junction: bool) -> Layer {
        let sign = if record.orientation == CrgOrientation::Opposite { -1.0 } else { 1.0 };
        let (s0, t0) = (record.s_offset, record.t_offset);
        let lay = match record.mode {
            CrgMode::Attached => Lay::Along { s0, t0, sign, grid: true, base: files.files[file].base },
            CrgMode::Attached0 => Lay::Along { s0, t0, sign, grid: false, base: 0.0 },
            CrgMode::Genuine => {
                let at = road.reference(record.s_offset);
                let (sin, cos) = math::sin_cos(at.hdg);
                let line = files.files[file].whole.reference_line();
                Lay::Placed {
                    origin: (at.x - record.t_offset * sin, at.y + record.t_offset * cos),
                    sin_cos: math::sin_cos(at.hdg + record.h_offset - line.phi_first),
                    first: (line.x_first, line.y_first),
                }
            }
            CrgMode::Global => Lay::Placed {
                origin: (record.x_offset, record.y_offset),
                sin_cos: math::sin_cos(record.h_offset),
                first: (0.0, 0.0),
            },
        };
        let on_road = record.mode == CrgMode::Attached;
        let laid = Laid { file, lay, scale: record.z_scale, offset: record.z_offset, on_road };
        Layer { record: record.clone(), laid, of_junction }
    }
}

impl Laid {
    /// The CRG value at the world point (x, y), which lies at (s, t) of the road: the
    /// height or friction as the file gives it; NaN where the CRG has none (a hole in its
    /// grid, border mode none).
    #[inline(always)]
    pub fn value(&self, points: &mut CrgPoints, (x, y, s, t): (f64, f64, f64, f64)) -> f64 {
        let found = match self.lay {
            Lay::Along { s0, t0, sign, grid, base } => {
                let (u, v) = (sign * (s - s0), sign * (t - t0));
                let point = if grid { points.grid(self.file) } else { points.whole(self.file) };
                point.uv_to_z(u, v).map(|z| z - base)
            }
            Lay::Placed { origin, sin_cos: (sin, cos), first } => {
                let (dx, dy) = (x - origin.0, y - origin.1);
                points.whole(self.file).xy_to_z(cos * dx + sin * dy + first.0, -sin * dx + cos * dy + first.1)
            }
        };
        found.unwrap_or(f64::NAN)
    }

    /// The surface's height where the record's elevation holds, `road` the road's own
    /// height there: the value scaled and shifted, on the road's height in mode `attached`.
    #[inline(always)]
    pub fn height(&self, points: &mut CrgPoints, at: (f64, f64, f64, f64), road: f64) -> f64 {
        let own = if self.on_road { road } else { 0.0 };
        self.value(points, at) * self.scale + self.offset + own
    }

    /// [`Laid::value`], called rather than inlined (for the layers queried less often).
    #[inline(never)]
    pub fn value_called(&self, points: &mut CrgPoints, at: (f64, f64, f64, f64)) -> f64 {
        self.value(points, at)
    }
}

/// The outline of the area a record lays its file on, in world x/y: along the road between
/// the CRG's v borders (attached modes) or around the CRG's own grid placed as the record
/// says (genuine, global); about a point a metre, closed.
pub(crate) fn outline(layer: &Layer, file: &CrgFile, road: &Road) -> Vec<[f64; 2]> {
    let record = &layer.record;
    let crg = &file.whole;
    let ((u0, u1), (v0, v1)) = (crg.u_range(), crg.v_range());
    let mut points = Vec::new();
    match layer.laid.lay {
        Lay::Along { .. } => {
            let (s_lo, s_hi, t_lo, t_hi) = match record.orientation {
                CrgOrientation::Same => {
                    (record.s_offset + u0, record.s_offset + u1, record.t_offset + v0, record.t_offset + v1)
                }
                CrgOrientation::Opposite => {
                    (record.s_offset - u1, record.s_offset - u0, record.t_offset - v1, record.t_offset - v0)
                }
            };
            let (a, b) = (s_lo.max(record.s_start).max(0.0), s_hi.min(record.s_end).min(road.length));
            if !(b > a) {
                return points;
            }
            let n = ((b - a).ceil() as usize).clamp(1, 100_000);
            let along = |k: usize| a + (b - a) * k as f64 / n as f64;
            for k in 0..=n {
                let [x, y, _] = road.surface_point(along(k), t_lo);
                points.push([x, y]);
            }
            for k in (0..=n).rev() {
                let [x, y, _] = road.surface_point(along(k), t_hi);
                points.push([x, y]);
            }
        }
        Lay::Placed { origin, sin_cos: (sin, cos), first } => {
            let cp = ContactPoint::new(crg.clone());
            let n = ((u1 - u0).ceil() as usize).clamp(1, 100_000);
            let along = |k: usize| u0 + (u1 - u0) * k as f64 / n as f64;
            let edge = (0..=n).map(|k| (along(k), v0)).chain((0..=n).rev().map(|k| (along(k), v1)));
            // The CRG's own x/y back to the world: the inverse of the layer's turn.
            for (u, v) in edge {
                if let Ok((x, y)) = cp.uv_to_xy(u, v) {
                    let (dx, dy) = (x - first.0, y - first.1);
                    points.push([origin.0 + cos * dx - sin * dy, origin.1 + sin * dx + cos * dy]);
                }
            }
        }
    }
    if let Some(&p) = points.first() {
        points.push(p);
    }
    points
}
