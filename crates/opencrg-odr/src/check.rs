//! The checker: the rules of the CRG records (`../shared/spec/opendrive-crg.md`) and of
//! the roads they lie on, each finding naming the road or junction and the line.

use crate::crg::Source;
use crate::map::{CrgMode, CrgOrientation, CrgPurpose, CrgRecord, Map, Road};
use opencrg_core::math;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// One thing wrong with a map.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    /// The map file's line of the element concerned.
    pub line: usize,
    /// `road ID` or `junction ID`, and the record where one is concerned.
    pub place: String,
    /// What is wrong.
    pub message: String,
}

impl std::fmt::Display for Finding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "line {}: {}: {}", self.line, self.place, self.message)
    }
}

/// The largest gap between a reference line record's end and the next one's start that
/// is not reported (m).
const GAP: f64 = 0.01;

/// Why each CRG file the records name cannot be used (`None`: it can), each read once.
type Files = BTreeMap<PathBuf, Option<String>>;

/// The findings of the rules of one record (`length`: of its road; `None` for a
/// junction's, `old` when the map is older than OpenDRIVE 1.8), `files` the files read so
/// far.
fn record_findings(
    record: &CrgRecord,
    place: &str,
    length: Option<f64>,
    old: bool,
    source: Option<&Source<'_>>,
    files: &mut Files,
    out: &mut Vec<Finding>,
) {
    let mut find = |message: String| {
        out.push(Finding { line: record.line, place: format!("{place}, CRG record '{}'", record.file), message })
    };
    let given = |name: &str| record.given.iter().any(|g| g == name);
    let attached = matches!(record.mode, CrgMode::Attached | CrgMode::Attached0);
    if record.purpose == CrgPurpose::Friction {
        if record.mode == CrgMode::Attached {
            find("mode attached is not allowed for friction".into());
        }
        for name in ["zOffset", "zScale"] {
            if given(name) {
                find(format!("a friction record sets no {name}"));
            }
        }
    }
    if !attached && record.orientation == CrgOrientation::Opposite {
        find("orientation opposite only in the modes attached and attached0".into());
    }
    if attached && given("hOffset") {
        find("hOffset only in the modes genuine and global".into());
    }
    if record.mode != CrgMode::Global {
        for name in ["xOffset", "yOffset"] {
            if given(name) {
                find(format!("{name} only in the mode global"));
            }
        }
    }
    if let Some(length) = length {
        if !(0.0 <= record.s_start && record.s_start < record.s_end && record.s_end <= length + 1e-9) {
            find(format!(
                "sStart {} and sEnd {} must satisfy 0 <= sStart < sEnd <= {length} (the road's length)",
                record.s_start, record.s_end
            ));
        }
    } else if record.mode != CrgMode::Global && old {
        find("a junction's records are of mode global before OpenDRIVE 1.8".into());
    }
    let Some(source) = source else { return };
    let unusable = files.entry(record.path.clone()).or_insert_with(|| source.read(record).err().map(|e| e.to_string()));
    if let Some(e) = unusable {
        find(format!("the CRG file cannot be used: {e}"));
    }
}

/// The findings of a road's geometry.
fn road_findings(road: &Road, out: &mut Vec<Finding>) {
    let place = format!("road {}", road.id);
    let mut find = |message: String| out.push(Finding { line: road.line, place: place.clone(), message });
    if road.plan.is_empty() {
        find("no reference line (no <planView> geometry)".into());
        return;
    }
    if !(road.length > 0.0) {
        find(format!("length {} is not positive", road.length));
    }
    let planned: f64 = road.plan.iter().map(|g| g.length).sum();
    if (planned - road.length).abs() > GAP {
        find(format!("its geometries are {planned:.4} m long, the road {:.4} m", road.length));
    }
    for pair in road.plan.windows(2) {
        let end = pair[0].pose(pair[0].length);
        let gap = math::hypot(end.x - pair[1].x, end.y - pair[1].y);
        if gap > GAP {
            find(format!("the reference line jumps {gap:.3} m at s = {}", pair[1].s));
        }
    }
    if road.lanes.sections.is_empty() {
        find("no lane section".into());
    }
}

/// Everything wrong with `map`, in the file's order: the roads' geometry, the CRG records'
/// rules and files, junctions whose connecting roads carry records of their own.
pub fn check(map: &Map) -> Vec<Finding> {
    check_from(map, Some(&Source::Disk))
}

/// [`check`]'s findings with the CRG files read from `source` (none: the files are read
/// already, as a [`Surface`](crate::Surface)'s are).
pub(crate) fn check_from(map: &Map, source: Option<&Source<'_>>) -> Vec<Finding> {
    let (mut out, mut files) = (Vec::new(), Files::new());
    let old = map.header.rev_major == 1 && map.header.rev_minor < 8;
    for road in &map.roads {
        road_findings(road, &mut out);
        for record in &road.crg {
            record_findings(
                record,
                &format!("road {}", road.id),
                Some(road.length),
                false,
                source,
                &mut files,
                &mut out,
            );
        }
    }
    for junction in &map.junctions {
        let place = format!("junction {}", junction.id);
        for record in &junction.crg {
            record_findings(record, &place, None, old, source, &mut files, &mut out);
        }
        if !junction.crg.is_empty() {
            for id in &junction.connecting_roads {
                if map.road(id).is_some_and(|r| !r.crg.is_empty()) {
                    out.push(Finding {
                        line: junction.line,
                        place: place.clone(),
                        message: format!("has CRG records, and so does its connecting road {id}"),
                    });
                }
            }
        }
    }
    out.sort_by_key(|f| f.line);
    out
}
