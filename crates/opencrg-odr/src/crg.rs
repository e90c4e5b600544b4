//! The CRG files a map's records lay on its roads: each file loaded once, in its own
//! coordinates (its options and its own modifiers, not the reference library's default
//! ones), and the value a record gives at a point of the road, in every mode and
//! orientation (`../shared/spec/opendrive-crg.md`).

use crate::map::{CrgMode, CrgOrientation, CrgRecord, Map, Road};
use opencrg::tools::{change_channel, ChannelAction, LineChannel};
use opencrg::{ContactPoint, Error, Location, Result};
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::Arc;

/// One CRG file as the records use it: whole, and as its grid alone (the `attached` mode
/// disregards its reference line's height and banking).
pub(crate) struct CrgFile {
    /// The file as read, its own modifiers applied.
    pub whole: Arc<opencrg::Road>,
    /// Its grid on a level reference line at height `base`.
    pub grid: Arc<opencrg::Road>,
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

/// Reads a CRG file for a map: its modifiers only if it gives some.
fn load(path: &std::path::Path) -> Result<CrgFile> {
    let mut road = opencrg::Road::load(path)?;
    if !road.header().modifiers_given {
        road.modifiers_mut().clear();
    }
    let line = road.reference_line();
    let climbs = line.slope.is_some() || line.z.is_some() || line.z_first != 0.0;
    let mut flat =
        if climbs { change_channel(&road, LineChannel::Slope, ChannelAction::Remove)? } else { road.clone() };
    if flat.reference_line().has_bank {
        flat = change_channel(&flat, LineChannel::Banking, ChannelAction::Remove)?;
    }
    road.apply_modifiers();
    flat.apply_modifiers();
    let base = flat.reference_line().z_first;
    Ok(CrgFile { whole: Arc::new(road), grid: Arc::new(flat), base })
}

impl CrgFiles {
    /// Loads every file the records of `map` name; refused: a file that cannot be read,
    /// named with the map's line of the record.
    pub fn load(map: &Map) -> Result<CrgFiles> {
        let mut files = CrgFiles::default();
        let records = map.roads.iter().flat_map(|r| &r.crg).chain(map.junctions.iter().flat_map(|j| &j.crg));
        for record in records {
            if files.by_path.contains_key(&record.path) {
                continue;
            }
            let file = load(&record.path).map_err(|e| Error::Format {
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

/// The record's CRG value at the world point (x, y), which lies at (s, t) of `road`:
/// the height or friction before `zScale`, `zOffset` and the road's own height; NaN
/// where the CRG has none (a hole in its grid, border mode none).
pub(crate) fn value(
    record: &CrgRecord,
    k: usize,
    files: &CrgFiles,
    points: &mut CrgPoints,
    road: &Road,
    (x, y, s, t): (f64, f64, f64, f64),
) -> f64 {
    let found = match record.mode {
        CrgMode::Attached | CrgMode::Attached0 => {
            let (mut u, mut v) = (s - record.s_offset, t - record.t_offset);
            if record.orientation == CrgOrientation::Opposite {
                (u, v) = (-u, -v);
            }
            if record.mode == CrgMode::Attached {
                points.grid(k).uv_to_z(u, v).map(|z| z - files.files[k].base)
            } else {
                points.whole(k).uv_to_z(u, v)
            }
        }
        CrgMode::Genuine => {
            let at = road.reference(record.s_offset);
            let (sin, cos) = at.hdg.sin_cos();
            let (x0, y0) = (at.x - record.t_offset * sin, at.y + record.t_offset * cos);
            let line = files.files[k].whole.reference_line();
            let a = at.hdg + record.h_offset - line.phi_first;
            let (xc, yc) = turned(a, x - x0, y - y0);
            points.whole(k).xy_to_z(xc + line.x_first, yc + line.y_first)
        }
        CrgMode::Global => {
            let (xc, yc) = turned(record.h_offset, x - record.x_offset, y - record.y_offset);
            points.whole(k).xy_to_z(xc, yc)
        }
    };
    found.unwrap_or(f64::NAN)
}

/// R(a) [x, y]: a world vector in the frame turned by `a`.
fn turned(a: f64, x: f64, y: f64) -> (f64, f64) {
    let (sin, cos) = a.sin_cos();
    (cos * x + sin * y, -sin * x + cos * y)
}
