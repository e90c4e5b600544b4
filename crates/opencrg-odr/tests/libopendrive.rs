//! Every road of every map in `../shared/opendrive/` against libOpenDRIVE, an independent
//! implementation of the geometry: the reference line (x, y, z, heading), the
//! superelevation, the lane offset, the lane at (s, t), the height above the cross section
//! and the surface point, at every metre of s and across every lane, within 1 mm.
//!
//! Where the specification and libOpenDRIVE differ (`../shared/spec/opendrive-crg.md`),
//! the comparison follows the specification and counts the samples concerned:
//! libOpenDRIVE turns the cross section about the sloped tangent (this library about the
//! horizontal one), so where a road both climbs and is superelevated its surface point is
//! rebuilt from its own parts in this library's frame; it interpolates lane heights
//! between records, where the specification holds each record until the next; it gives
//! points of a lane to a zero-wide neighbour sharing its border; it forces a paramPoly3's
//! declared length onto the end of the curve (s is the curve's arc length here); an arc
//! of curvature 0 gives it no point.
//!
//! Needs the oracle: `OPENCRG_ODR_ORACLE=path/to/libopendrive_answers` (test.sh builds
//! libOpenDRIVE and `tests/oracle/libopendrive_answers.cpp`).

use opencrg_odr::{Map, Road};
use std::path::{Path, PathBuf};

mod common;

const TOLERANCE: f64 = 1e-3;

fn maps() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/opendrive");
    let mut found = Vec::new();
    for kind in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        for f in std::fs::read_dir(kind.unwrap().path()).unwrap() {
            let p = f.unwrap().path();
            if p.extension().is_some_and(|e| e == "xodr") {
                found.push(p);
            }
        }
    }
    found.sort();
    found
}

/// The (s, t) samples of a road: every metre and the ends of its reference line records,
/// across: the reference line, each lane's middle and 5 cm inside each of its borders.
fn samples(road: &Road) -> Vec<(f64, f64)> {
    let mut ss: Vec<f64> = (0..=road.length.floor() as usize).map(|i| i as f64).collect();
    ss.push(road.length);
    for g in &road.plan {
        ss.extend([g.s + 1e-6, g.s + g.length - 1e-6]);
    }
    ss.retain(|&s| (0.0..=road.length).contains(&s));
    let mut out = Vec::new();
    for s in ss {
        out.push((s, 0.0));
        let Some((section, ds)) = road.lanes.section_at(s) else { continue };
        let offset = road.lanes.offset.at(s);
        for left in [true, false] {
            for span in section.spans(left, ds, offset) {
                let (a, b) = (span.inner, span.outer);
                if (b - a).abs() < 0.2 {
                    continue;
                }
                let inward = 0.05 * (b - a).signum();
                out.extend([(s, 0.5 * (a + b)), (s, a + inward), (s, b - inward)]);
            }
        }
    }
    out
}

#[derive(Default)]
struct Worst {
    compared: usize,
    frame_rebuilt: usize,
    height_interpolated: usize,
    zero_width_lanes: usize,
    flat_arcs: usize,
    forced_lengths: usize,
    errors: Vec<String>,
    max: [f64; 6],
}

impl Worst {
    fn check(&mut self, what: usize, name: &str, ours: f64, theirs: f64, limit: f64, at: &str) {
        let d = (ours - theirs).abs();
        self.max[what] = self.max[what].max(d);
        if (d.is_nan() || d > limit) && self.errors.iter().filter(|e| e.contains(name)).count() < 5 {
            self.errors.push(format!("{at}: {name} {ours} here, {theirs} in libOpenDRIVE"));
        }
    }
}

/// Whether libOpenDRIVE's interpolation between lane height records changes the height at
/// (s, t): the lane there has a later record with other heights.
fn heights_interpolated(road: &Road, s: f64, t: f64) -> bool {
    let Some((section, ds)) = road.lanes.section_at(s) else { return false };
    let Some(span) = section.lane_at(ds, t, road.lanes.offset.at(s)) else { return false };
    let h = &span.lane.heights;
    let k = h.partition_point(|r| r.s_offset <= ds);
    k >= 1 && k < h.len() && (h[k].inner != h[k - 1].inner || h[k].outer != h[k - 1].outer)
}

/// Whether lane `id` is zero wide at s: libOpenDRIVE's lookup by outer border gives such a
/// lane the place of its inner neighbour, whose outer border it shares.
fn zero_width(road: &Road, s: f64, id: i32) -> bool {
    let Some((section, ds)) = road.lanes.section_at(s) else { return false };
    let offset = road.lanes.offset.at(s);
    [true, false]
        .iter()
        .flat_map(|&left| section.spans(left, ds, offset))
        .any(|span| span.lane.id == id && (span.outer - span.inner).abs() < 1e-9)
}

#[test]
#[ignore = "needs libOpenDRIVE: OPENCRG_ODR_ORACLE=path/to/libopendrive_answers (test.sh builds it)"]
fn every_road_agrees_with_libopendrive() {
    let oracle = std::env::var("OPENCRG_ODR_ORACLE").expect("OPENCRG_ODR_ORACLE names the oracle's program");
    let mut w = Worst::default();
    let (mut n_maps, mut n_roads) = (0, 0);
    for path in maps() {
        let map = Map::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let mut queries = String::new();
        let mut asked = Vec::new();
        for (ri, road) in map.roads.iter().enumerate() {
            for (s, t) in samples(road) {
                queries.push_str(&format!("{} {s:.17e} {t:.17e}\n", road.id));
                asked.push((ri, s, t));
            }
        }
        let answers = common::answers(&oracle, &[path.as_os_str()], queries);
        let lines: Vec<&str> = answers.lines().collect();
        assert_eq!(lines.len(), asked.len(), "{}: answers", path.display());
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        for (&(ri, s, t), line) in asked.iter().zip(&lines) {
            let road = &map.roads[ri];
            let at = format!("{name} road {} s {s:.3} t {t:.3}", road.id);
            assert!(!line.starts_with("error"), "{at}: libOpenDRIVE: {line}");
            let f: Vec<f64> = line.split_whitespace().map(|x| x.parse().unwrap()).collect();
            let r = road.reference(s);
            w.compared += 1;
            // libOpenDRIVE forces a paramPoly3's declared length onto the end of its curve;
            // where the two differ, its points move along the line by up to the difference.
            let g = road.geometry_at(s).unwrap();
            let forced = (g.curve_length() - g.length).abs();
            let xy_limit = if forced > 0.5 * TOLERANCE {
                w.forced_lengths += 1;
                forced + TOLERANCE
            } else {
                TOLERANCE
            };
            if !f[0].is_finite() {
                // libOpenDRIVE divides by the curvature of an arc: one of curvature 0 gives
                // it no point. This library's is the straight line it is.
                let g = road.geometry_at(s).unwrap();
                assert_eq!(g.shape, opencrg_odr::Shape::Arc { curvature: 0.0 }, "{at}: libOpenDRIVE: {line}");
                let ds = s - g.s;
                w.check(0, "reference x", r.x, g.x + ds * g.hdg.cos(), 1e-12, &at);
                w.check(0, "reference y", r.y, g.y + ds * g.hdg.sin(), 1e-12, &at);
                w.flat_arcs += 1;
                continue;
            }
            w.check(0, "reference x", r.x, f[0], xy_limit, &at);
            w.check(0, "reference y", r.y, f[1], xy_limit, &at);
            w.check(1, "reference z", r.z, f[2], TOLERANCE, &at);
            let dh = (r.hdg - f[3] + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI;
            w.check(2, "heading", dh, 0.0, 1e-5, &at);
            w.check(3, "superelevation", r.roll, f[4], 1e-9, &at);
            w.check(3, "lane offset", road.lanes.offset.at(s), f[5], TOLERANCE, &at);
            if t != 0.0 {
                let ours = road.lane_at(s, t).map_or(0, |l| l.lane.id);
                if ours != f[6] as i32 {
                    if zero_width(road, s, f[6] as i32) {
                        w.zero_width_lanes += 1;
                    } else if w.errors.len() < 40 {
                        w.errors.push(format!("{at}: lane {ours} here, {} in libOpenDRIVE", f[6]));
                    }
                }
            }
            let h = road.height_above_section(s, t);
            if (h - f[10]).abs() > TOLERANCE && heights_interpolated(road, s, t) {
                w.height_interpolated += 1;
                continue;
            }
            w.check(4, "height above the cross section", h, f[10], TOLERANCE, &at);
            let p = road.surface_point(s, t);
            let expected = if r.roll != 0.0 && r.slope != 0.0 {
                // libOpenDRIVE's frame is turned about the sloped tangent: its point rebuilt
                // from its own parts in this library's frame.
                w.frame_rebuilt += 1;
                let theirs = opencrg_odr::RefPoint { x: f[0], y: f[1], z: f[2], hdg: f[3], slope: r.slope, roll: f[4] };
                theirs.at(t, f[10])
            } else {
                [f[7], f[8], f[9]]
            };
            for (k, axis) in ["x", "y", "z"].iter().enumerate() {
                w.check(
                    5,
                    &format!("surface {axis}"),
                    p[k],
                    expected[k],
                    if k < 2 { xy_limit } else { TOLERANCE },
                    &at,
                );
            }
        }
        n_maps += 1;
        n_roads += map.roads.len();
    }
    eprintln!(
        "{n_maps} maps, {n_roads} roads, {} samples: largest differences (m, rad): reference x/y {:.2e}, z {:.2e}, \
         heading {:.2e}, superelevation/offset {:.2e}, height above the section {:.2e}, surface point {:.2e}; \
         {} samples in libOpenDRIVE's frame rebuilt, {} with lane heights it interpolates left out, {} in lanes it \
         gives to a zero-wide neighbour, {} on arcs of curvature 0 (none in libOpenDRIVE) against the straight line, {} on \
         paramPoly3 records whose declared length libOpenDRIVE forces onto the curve's end (x/y within that \
         difference more)",
        w.compared,
        w.max[0],
        w.max[1],
        w.max[2],
        w.max[3],
        w.max[4],
        w.max[5],
        w.frame_rebuilt,
        w.height_interpolated,
        w.zero_width_lanes,
        w.flat_arcs,
        w.forced_lengths
    );
    assert!(w.errors.is_empty(), "{}", w.errors.join("\n"));
    assert!(n_maps >= 20 && w.compared > 10_000);
}
