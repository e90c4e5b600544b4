//! A road cut where any of its records along s starts or ends (elevation, superelevation,
//! lane offset, lane sections, the lanes' widths, borders, heights and materials, the CRG
//! records laid on it): between two cuts the same records hold, so a wheel moving along
//! the road evaluates them without searching. Each patch keeps those records, found once
//! when the map is made ready; the answers are the same as the road's own lookups give
//! (tested below), which serve the points within rounding of a cut.

use crate::crg::{Laid, Layer};
use crate::lanes::{find_lane, Edge, Lane, LaneSection};
use crate::last_wins::last_holding;
use crate::map::{CrgPurpose, CrgRecord, Road};
use crate::profile::Cubic;
use crate::trig;
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
        let sections: Vec<_> = spans.iter().map(|&(.., at)| lanes.section_at(at)).collect();
        // Each patch keeps its section's lanes: many lanes times many cuts (a file made to
        // blow up) would take memory out of all proportion to the file, so beyond a bound
        // proportional to the road's own records it answers from those records instead.
        let count = |sec: &LaneSection| sec.left.len() + sec.right.len();
        let lanes_kept: usize = sections.iter().flatten().map(|&(sec, _)| count(sec)).sum();
        let own = cuts.len() + lanes.sections.iter().map(count).sum::<usize>();
        let mut out = Patches::default();
        if lanes_kept > MAX_LANES_PER_RECORD * own + 1000 {
            return out;
        }
        let records: Vec<&CrgRecord> = layers.iter().map(|l| &l.record).collect();
        let [elevation, friction] = [CrgPurpose::Elevation, CrgPurpose::Friction]
            .map(|p| last_holding(&records, p, spans.iter().map(|&(.., at)| at)));
        for (k, ((lo, hi, at), section)) in spans.into_iter().zip(sections).enumerate() {
            let crg = [elevation[k], friction[k]].map(|i| i.map(|i| layers[i].laid));
            out.push(road, (lo, hi, at), section, crg);
        }
        out
    }

    /// Adds the patch between `lo` and `hi`, its records those holding at `at`: the lane
    /// section `section` (with `at` less its start) and the CRG layers `crg` (elevation,
    /// friction).
    fn push(
        &mut self,
        road: &Road,
        (lo, hi, at): (f64, f64, f64),
        section: Option<(&LaneSection, f64)>,
        crg: [Option<Laid>; 2],
    ) {
        let mut side = |lanes: &[Lane], ds: f64| {
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
    use crate::map::Map;

    /// Every road of the shared maps keeps its patches.
    #[test]
    #[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
    fn shared_maps_keep_their_roads_patched() {
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
    }

    /// A road of many lanes, one of them with a width record every millimetre, keeps no
    /// patches (its product would be 900,000 lanes kept) and is answered from its own
    /// records.
    #[test]
    fn the_bound_stops_a_blow_up() {
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
