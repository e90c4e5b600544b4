//! A road cut where any of its records along s starts or ends (elevation, superelevation,
//! lane offset, lane sections, the lanes' widths, borders, heights and materials, the CRG
//! records laid on it): between two cuts the same records hold, so a wheel moving along
//! the road evaluates them without searching. Each patch keeps those records, found once
//! when the map is made ready; the answers are the same as the road's own lookups give
//! (tested below), which serve the points within rounding of a cut.

use crate::crg::{Laid, Layer};
use crate::lanes::{find_lane, Edge};
use crate::map::{CrgPurpose, CrgRecord, Road};
use crate::profile::Cubic;
use crate::trig;
use std::collections::{BTreeMap, BinaryHeap};
use std::ops::Range;

/// A lane as one patch sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PatchLane {
    /// Its id.
    pub id: i32,
    /// Whether it is a lane of a type other than `none`.
    pub real: bool,
    /// How its outer border is given.
    pub edge: Edge,
    /// Its heights at the inner and the outer border.
    pub heights: (f64, f64),
    /// Its material's friction; NaN where none gives one.
    pub friction: f64,
}

/// The records that hold on a road between two cuts.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Patch {
    /// s beyond which the patch serves, its start with a margin for rounding.
    lo: f64,
    /// s before which the patch serves, its end with a margin for rounding.
    hi: f64,
    /// The elevation's record.
    pub elevation: Cubic,
    /// The superelevation's record.
    pub superelevation: Cubic,
    /// Where the superelevation is constant over the patch: its value, and its sine and
    /// cosine.
    pub tilt: Option<(f64, (f64, f64))>,
    /// The lane offset's record.
    pub offset: Cubic,
    /// Where the lane section starts.
    pub section_s: f64,
    /// Whether the surface lies on the cross section (no lateral shape, no lane heights).
    pub level: bool,
    /// The lanes left of the centre, outwards, in [`Patches::lanes`].
    left: Range<usize>,
    /// The lanes right of the centre, outwards.
    right: Range<usize>,
    /// The CRG records that hold: elevation, friction.
    pub crg: [Option<Laid>; 2],
}

/// A road's patches in order of s, and their lanes.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Patches {
    patches: Vec<Patch>,
    lanes: Vec<PatchLane>,
}

/// The margin kept from each cut: far above the rounding of s less a section's start, far
/// below any distance a wheel can tell.
fn margin(s: f64) -> f64 {
    if s.is_finite() {
        1e-9 * (1.0 + s.abs())
    } else {
        0.0
    }
}

/// The most lanes the patches of a road keep per record of the road (lane, or cut along
/// s), beyond a thousand: real roads keep a few.
const MAX_LANES_PER_RECORD: usize = 16;

/// The last of `layers` with `purpose` that holds at s (the last record wins).
pub(crate) fn layer_at(layers: &[Layer], purpose: CrgPurpose, s: f64) -> Option<usize> {
    layers.iter().rposition(|l| l.record.purpose == purpose && l.record.s_start <= s && s <= l.record.s_end)
}

/// Of `records`, the last with `purpose` that holds at each of `points` (s, ascending), as
/// [`layer_at`] finds it, in one sweep: the records by start, the last one started on top
/// of a heap until it ends.
fn last_holding(records: &[&CrgRecord], purpose: CrgPurpose, points: impl Iterator<Item = f64>) -> Vec<Option<usize>> {
    let mut by_start: Vec<usize> = (0..records.len()).filter(|&i| records[i].purpose == purpose).collect();
    by_start.sort_by(|&a, &b| records[a].s_start.total_cmp(&records[b].s_start));
    let (mut started, mut next) = (BinaryHeap::new(), 0);
    points
        .map(|s| {
            while next < by_start.len() && records[by_start[next]].s_start <= s {
                started.push(by_start[next]);
                next += 1;
            }
            while started.peek().is_some_and(|&i| !(s <= records[i].s_end)) {
                started.pop();
            }
            started.peek().copied()
        })
        .collect()
}

/// An f64's place in the order of all f64 (for the keys of a B-tree).
fn order(x: f64) -> u64 {
    let bits = x.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | 1 << 63
    }
}

/// `records` (in the order they apply) less those that never hold: of each purpose the
/// last record whose range holds s wins, so a record whose range later ones of its
/// purpose cover is never seen (a junction's many records on every connecting road).
pub(crate) fn visible<T>(records: Vec<T>, record: impl Fn(&T) -> &CrgRecord) -> Vec<T> {
    // Per purpose, the union of the later records' ranges: disjoint ranges by start.
    let mut covered: [BTreeMap<u64, (f64, f64)>; 2] = Default::default();
    let mut keep = vec![false; records.len()];
    for (i, r) in records.iter().map(&record).enumerate().rev() {
        let union = &mut covered[usize::from(r.purpose == CrgPurpose::Friction)];
        let (mut lo, mut hi) = (r.s_start, r.s_end);
        if union.range(..=order(lo)).next_back().is_some_and(|(_, &(_, end))| hi <= end) {
            continue;
        }
        keep[i] = true;
        if let Some((_, &(start, end))) = union.range(..=order(lo)).next_back() {
            if lo <= end {
                lo = start;
                hi = hi.max(end);
            }
        }
        let within: Vec<u64> = union.range(order(lo)..=order(hi)).map(|(&k, _)| k).collect();
        for k in within {
            if let Some((_, end)) = union.remove(&k) {
                hi = hi.max(end);
            }
        }
        union.insert(order(lo), (lo, hi));
    }
    records.into_iter().zip(keep).filter_map(|(r, keep)| keep.then_some(r)).collect()
}

impl Patches {
    /// The patches of `road`, `layers` the CRG records that apply to it.
    pub fn new(road: &Road, layers: &[Layer]) -> Patches {
        let lanes = &road.lanes;
        let mut cuts: Vec<f64> = road.elevation.starts().chain(road.superelevation.starts()).collect();
        cuts.extend(lanes.offset.starts());
        for section in &lanes.sections {
            cuts.push(section.s);
            for lane in section.left.iter().chain(&section.right) {
                let offsets = lane.width.iter().chain(&lane.border).map(|r| r.s);
                let offsets = offsets.chain(lane.heights.iter().map(|h| h.s_offset));
                cuts.extend(offsets.chain(lane.materials.iter().map(|m| m.s_offset)).map(|ds| section.s + ds));
            }
        }
        cuts.extend(layers.iter().flat_map(|l| [l.record.s_start, l.record.s_end]));
        cuts.retain(|s| s.is_finite());
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        let bounds = std::iter::once(f64::NEG_INFINITY).chain(cuts.iter().copied());
        let spans: Vec<(f64, f64, f64)> = bounds
            .zip(cuts.iter().copied().chain([f64::INFINITY]))
            .filter_map(|(start, end)| {
                let (lo, hi) = (start + margin(start), end - margin(end));
                // Where every record holds as it does all over the patch.
                let at = match (start.is_finite(), end.is_finite()) {
                    (true, true) => 0.5 * (start + end),
                    (true, false) => start + 1.0,
                    (false, true) => end - 1.0,
                    (false, false) => 0.0,
                };
                (lo < hi).then_some((lo, hi, at))
            })
            .collect();
        // Each patch keeps its section's lanes: many lanes times many cuts (a file made to
        // blow up) would take memory out of all proportion to the file, so beyond a bound
        // proportional to the road's own records it answers from those records instead.
        let lanes_kept: usize = spans
            .iter()
            .map(|&(.., at)| lanes.section_at(at).map_or(0, |(sec, _)| sec.left.len() + sec.right.len()))
            .sum();
        let records = cuts.len() + lanes.sections.iter().map(|sec| sec.left.len() + sec.right.len()).sum::<usize>();
        let mut out = Patches::default();
        if lanes_kept > MAX_LANES_PER_RECORD * records + 1000 {
            return out;
        }
        let records: Vec<&CrgRecord> = layers.iter().map(|l| &l.record).collect();
        let [elevation, friction] = [CrgPurpose::Elevation, CrgPurpose::Friction]
            .map(|p| last_holding(&records, p, spans.iter().map(|&(.., at)| at)));
        for (k, (lo, hi, at)) in spans.into_iter().enumerate() {
            let crg = [elevation[k], friction[k]].map(|i| i.map(|i| layers[i].laid));
            out.push(road, lo, hi, at, crg);
        }
        out
    }

    /// Adds the patch between `lo` and `hi`, its records those holding at `at`, its CRG
    /// layers `crg` (elevation, friction).
    fn push(&mut self, road: &Road, lo: f64, hi: f64, at: f64, crg: [Option<Laid>; 2]) {
        let section = road.lanes.section_at(at);
        let mut side = |lanes: &[crate::lanes::Lane], ds: f64| {
            let first = self.lanes.len();
            self.lanes.extend(lanes.iter().map(|lane| PatchLane {
                id: lane.id,
                real: lane.kind != "none",
                edge: lane.edge(ds),
                heights: lane.height_at(ds),
                friction: lane.friction_at(ds).unwrap_or(f64::NAN),
            }));
            first..self.lanes.len()
        };
        let (left, right, section_s) = match section {
            Some((sec, ds)) => (side(&sec.left, ds), side(&sec.right, ds), sec.s),
            None => (0..0, 0..0, 0.0),
        };
        let superelevation = road.superelevation.cubic_at(at);
        let tilt = (superelevation.b == 0.0 && superelevation.c == 0.0 && superelevation.d == 0.0).then(|| {
            let roll = superelevation.value(at - superelevation.s);
            (roll, trig::sin_cos(roll))
        });
        self.patches.push(Patch {
            lo,
            hi,
            elevation: road.elevation.cubic_at(at),
            superelevation,
            tilt,
            offset: road.lanes.offset.cubic_at(at),
            section_s,
            level: road.level_at(at),
            left,
            right,
            crg,
        });
    }

    /// The patch serving `s` and its index, trying `hint` (a patch's index) first; `None`
    /// within the margin of a cut.
    #[inline(always)]
    pub fn find(&self, s: f64, hint: usize) -> Option<(usize, &Patch)> {
        if let Some(p) = self.patches.get(hint) {
            if p.lo < s && s < p.hi {
                return Some((hint, p));
            }
        }
        let i = self.patches.partition_point(|p| p.hi <= s);
        self.patches.get(i).filter(|p| p.lo < s && s < p.hi).map(|p| (i, p))
    }

    /// The lane of patch `patch` at (s, t), with its inner and outer borders' t.
    #[inline(always)]
    pub fn lane_at(&self, patch: &Patch, s: f64, t: f64) -> Option<(&PatchLane, f64, f64)> {
        let ds = s - patch.section_s;
        let offset = patch.offset.value(s - patch.offset.s);
        let sides = (&self.lanes[patch.left.clone()], &self.lanes[patch.right.clone()]);
        find_lane(t, offset, sides, |lane, inner, sign| lane.edge.outer(ds, inner, sign))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::map::{CrgMode, CrgOrientation, Map};

    fn record(purpose: CrgPurpose, s_start: f64, s_end: f64, line: usize) -> CrgRecord {
        CrgRecord {
            file: String::new(),
            path: Default::default(),
            s_start,
            s_end,
            mode: CrgMode::Attached0,
            orientation: CrgOrientation::Same,
            purpose,
            s_offset: 0.0,
            t_offset: 0.0,
            z_offset: 0.0,
            z_scale: 1.0,
            h_offset: 0.0,
            x_offset: 0.0,
            y_offset: 0.0,
            given: Vec::new(),
            line,
        }
    }

    /// Random records (ranges over 0..100, both purposes): the sweep finds at every s the
    /// record the last-record-wins rule names, and the records left out as never holding
    /// are exactly those that hold nowhere.
    #[test]
    fn the_last_record_wins_by_sweep_and_the_hidden_ones_go() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for round in 0..200 {
            let n = 1 + round % 40;
            let records: Vec<CrgRecord> = (0..n)
                .map(|i| {
                    let purpose = if next() < 0.7 { CrgPurpose::Elevation } else { CrgPurpose::Friction };
                    let a = (next() * 100.0).round();
                    let b = if next() < 0.1 { f64::INFINITY } else { a + (next() * 40.0).round() };
                    record(purpose, a, b, i)
                })
                .collect();
            let refs: Vec<&CrgRecord> = records.iter().collect();
            let points: Vec<f64> = (-2..=300).map(|k| k as f64 * 0.5).collect();
            let rule =
                |p: CrgPurpose, s: f64| refs.iter().rposition(|r| r.purpose == p && r.s_start <= s && s <= r.s_end);
            let mut seen = vec![false; n];
            for p in [CrgPurpose::Elevation, CrgPurpose::Friction] {
                let swept = last_holding(&refs, p, points.iter().copied());
                for (&s, &found) in points.iter().zip(&swept) {
                    assert_eq!(found, rule(p, s), "round {round} s {s}");
                    if let Some(i) = found {
                        seen[i] = true;
                    }
                }
            }
            // The points are the ranges' ends and the halves between: every record that
            // holds anywhere holds at one of them.
            let kept: Vec<usize> = visible(refs.clone(), |r| r).iter().map(|r| r.line).collect();
            let holding: Vec<usize> = (0..n).filter(|&i| seen[i]).collect();
            assert_eq!(kept, holding, "round {round}");
        }
    }

    /// Every road of the shared maps keeps its patches; a road of many lanes, one of them
    /// with a width record every millimetre, keeps none (its product would be 900,000
    /// lanes kept) and is answered from its own records.
    #[test]
    fn the_bound_keeps_real_roads_patched_and_stops_a_blow_up() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/opendrive");
        let mut roads = 0;
        for group in ["carla", "esmini"] {
            for entry in std::fs::read_dir(dir.join(group)).unwrap() {
                let path = entry.unwrap().path();
                if path.extension().is_some_and(|e| e == "xodr") {
                    for road in &Map::load(&path).unwrap().roads {
                        assert!(!Patches::new(road, &[]).patches.is_empty(), "{} road {}", path.display(), road.id);
                        roads += 1;
                    }
                }
            }
        }
        assert!(roads > 1400, "{roads}");
        let lane = |id: usize, widths: &str| format!("<lane id=\"{id}\" type=\"driving\">{widths}</lane>");
        let many: String = (0..3000)
            .map(|k| format!("<width sOffset=\"{}\" a=\"3\" b=\"0\" c=\"0\" d=\"0\"/>", k as f64 * 0.001))
            .collect();
        let thin = "<width sOffset=\"0\" a=\"0.01\" b=\"0\" c=\"0\" d=\"0\"/>";
        let lanes: String = (1..=300).map(|id| lane(id, if id == 1 { &many } else { thin })).collect();
        let text = format!(
            "<OpenDRIVE><header revMajor=\"1\" revMinor=\"8\"/><road id=\"r\" length=\"100\" junction=\"-1\">\
             <planView><geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"100\"><line/></geometry></planView>\
             <lanes><laneSection s=\"0\"><left>{lanes}</left><center><lane id=\"0\" type=\"none\"/></center></laneSection></lanes>\
             </road></OpenDRIVE>"
        );
        let map = Map::from_bytes(text.as_bytes(), std::path::Path::new("blow-up.xodr")).unwrap();
        assert!(Patches::new(&map.roads[0], &[]).patches.is_empty());
        let surface = std::sync::Arc::new(crate::Surface::new(map).unwrap());
        let mut probe = surface.probe();
        for (x, y, lane) in [(1.0005, 1.0, 1), (50.0, 2.9, 1), (50.0, 3.005, 2), (99.0, 3.015, 3)] {
            assert_eq!(probe.ground(x, y).map(|g| g.lane), Some(lane), "({x}, {y})");
        }
    }
}
