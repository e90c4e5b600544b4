//! The CRG records of every mode and orientation against the reference OpenCRG C
//! library: CRG files of this test's own laid on a road of a shared map (esmini's
//! `curves_elevation.xodr`, curved and climbing), each answer compared with what the
//! reference's `crgEvaluv2z` / `crgEvalxy2z` give at the CRG coordinates the
//! specification's formulas name (`../shared/spec/opendrive-crg.md`), within 1 mm.
//!
//! Needs the reference: `OPENCRG_CRG_REFERENCE=path/to/crg_reference_answers`
//! (test.sh builds the reference with `../shared/reference/build-references.sh` and
//! `tests/oracle/crg_reference_answers.c` against it).

use opencrg_core::synth::RoadSpec;
use opencrg_odr::{Map, Surface};
use std::path::Path;
use std::sync::Arc;

mod common;

/// The reference's answers for one CRG file: `queries` lines "uv U V" or "xy X Y".
fn reference(file: &Path, modifiers: &str, queries: &str) -> Vec<f64> {
    let program = std::env::var("OPENCRG_CRG_REFERENCE").expect("OPENCRG_CRG_REFERENCE names the reference's client");
    let out = common::answers(&program, &[file.as_os_str(), modifiers.as_ref()], queries.to_string());
    out.lines().map(|l| l.trim().parse().unwrap_or(f64::NAN)).collect()
}

/// The CRG files: `rough.crg`, a curved, climbing, banked road with its own modifiers
/// section (grid scaled by 1.5); `flat.crg`, straight and level, without modifiers (the
/// reference's default ones are removed, as the specification asks).
fn crg_files(dir: &Path) {
    let rough = RoadSpec::straight(60.0, 6.0, 0.1, 0.1)
        .starting_at(230.0, 150.0, 1.2)
        .with_heading(|u| 1.2 + 0.004 * u)
        .with_slope(|u| 0.02 + 0.0002 * u)
        .with_bank(|u| 0.03 * (u / 20.0).sin())
        .with_elevation(|u, v| 0.004 * (u * 3.1).sin() * (v * 1.7).cos() + 0.002 * (u * 11.0).cos())
        .with_header_text("$ROAD_CRG_MODS\nSCALE_Z_GRID = 1.5\n$\n");
    std::fs::write(dir.join("rough.crg"), rough.to_crg()).unwrap();
    let flat = RoadSpec::straight(60.0, 6.0, 0.1, 0.1)
        .starting_at(-40.0, 25.0, 0.3)
        .with_elevation(|u, v| 0.005 * (u * 2.3).sin() + 0.003 * (v * 5.0).cos());
    std::fs::write(dir.join("flat.crg"), flat.to_crg()).unwrap();
}

/// The shared map with `record` on its road, in `dir`.
fn map_with(dir: &Path, record: &str) -> Arc<Surface> {
    let shared = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/opendrive/esmini/curves_elevation.xodr");
    let text = std::fs::read_to_string(shared).unwrap();
    let at = text.rfind("</road>").unwrap();
    let text = format!("{}<surface>{record}</surface>\n{}", &text[..at], &text[at..]);
    let path = dir.join("map.xodr");
    std::fs::write(&path, text).unwrap();
    Arc::new(Surface::new(Map::load(&path).unwrap()).unwrap())
}

/// Points of the road (s, t) inside the record's stretch and the CRG's reach.
fn samples(s0: f64) -> Vec<(f64, f64)> {
    (0..40).map(|k| (s0 + 1.0 + k as f64 * 1.37, -2.5 + (k % 11) as f64 * 0.5)).collect()
}

#[test]
#[ignore = "needs the reference library: OPENCRG_CRG_REFERENCE=path/to/crg_reference_answers (test.sh builds it)"]
fn every_mode_agrees_with_the_reference_library() {
    let dir = std::env::temp_dir().join(format!("opencrg-odr-{}-reference", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    crg_files(&dir);
    let (mut compared, mut worst) = (0, 0.0f64);
    let cases = [
        ("attached same", "flat.crg", "none", r#"mode="attached" orientation="same" sOffset="100" tOffset="0.25""#),
        (
            "attached opposite",
            "flat.crg",
            "none",
            r#"mode="attached" orientation="opposite" sOffset="160" tOffset="-0.5""#,
        ),
        (
            "attached0 same",
            "rough.crg",
            "own",
            r#"mode="attached0" orientation="same" sOffset="100" zScale="0.5" zOffset="0.2""#,
        ),
        ("attached0 opposite", "rough.crg", "own", r#"mode="attached0" orientation="opposite" sOffset="160""#),
        ("genuine", "rough.crg", "own", r#"mode="genuine" sOffset="100" tOffset="0.5" hOffset="0.05""#),
        ("global", "flat.crg", "none", r#"mode="global" xOffset="140" yOffset="-25" hOffset="-0.2" zScale="2""#),
    ];
    for (name, file, modifiers, attributes) in cases {
        let record = format!(r#"<CRG file="{file}" sStart="100" sEnd="160" purpose="elevation" {attributes}/>"#);
        let surface = map_with(&dir, &record);
        let road = &surface.map().roads[0];
        let r = &road.crg[0];
        let mut probe = surface.probe();
        let mut queries = String::new();
        let mut expected_parts = Vec::new();
        for (s, t) in samples(100.0) {
            let p = road.surface_point(s, t);
            let own = p[2];
            let g = probe.ground(p[0], p[1]).unwrap_or_else(|| panic!("{name}: s {s} t {t} off the road"));
            assert_eq!(g.road, 0);
            // The CRG coordinates of the specification's formulas.
            let query = match name {
                n if n.starts_with("attached") => {
                    let (mut u, mut v) = (g.s - r.s_offset, g.t - r.t_offset);
                    if n.ends_with("opposite") {
                        (u, v) = (-u, -v);
                    }
                    format!("uv {u:.17e} {v:.17e}")
                }
                "genuine" => {
                    let at = road.reference(r.s_offset);
                    let (x0, y0) = (at.x - r.t_offset * at.hdg.sin(), at.y + r.t_offset * at.hdg.cos());
                    let crg = opencrg_core::Road::load(dir.join(file)).unwrap();
                    let line = crg.reference_line();
                    let a = at.hdg + r.h_offset - line.phi_first;
                    let (dx, dy) = (p[0] - x0, p[1] - y0);
                    let (xc, yc) =
                        (a.cos() * dx + a.sin() * dy + line.x_first, -a.sin() * dx + a.cos() * dy + line.y_first);
                    format!("xy {xc:.17e} {yc:.17e}")
                }
                _ => {
                    let (dx, dy) = (p[0] - r.x_offset, p[1] - r.y_offset);
                    let h = r.h_offset;
                    format!("xy {:.17e} {:.17e}", h.cos() * dx + h.sin() * dy, -h.sin() * dx + h.cos() * dy)
                }
            };
            queries.push_str(&query);
            queries.push('\n');
            expected_parts.push((g.z, own));
        }
        let answers = reference(&dir.join(file), modifiers, &queries);
        assert_eq!(answers.len(), expected_parts.len(), "{name}: answers");
        let attached = name.starts_with("attached ");
        for ((ours, own), crg) in expected_parts.iter().zip(&answers) {
            // The flat file's reference line lies at z 0: its grid alone is its height.
            let want = crg * r.z_scale + r.z_offset + if attached { *own } else { 0.0 };
            assert!(crg.is_finite(), "{name}: the reference has no value");
            let d = (ours - want).abs();
            worst = worst.max(d);
            assert!(d < 1e-3, "{name}: {ours} here, {want} from the reference");
            compared += 1;
        }
    }
    eprintln!("{compared} points in 6 modes and orientations: largest difference {worst:.2e} m");
    assert_eq!(compared, 240);
}
