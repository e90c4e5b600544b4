//! The wheels answer what the C API's calls answer: on a CRG file, (u, v) of
//! `crgEvalxy2uv` and heading and curvature of `crgEvaluv2pk` at them, made in turn on
//! one contact point as a program would, and z of `crgEvalxy2z` on another (here the
//! evaluator's own contact points, which the C API wraps: a search starts where the
//! contact point's last one ended, and a wheel searches once a position), to the bit,
//! along paths over the road and off it; on a map, what a probe of its own answers.

use opencrg_core::{Compat, ContactPoint};
use opencrg_fmu::{Quantity, Terrain, Wheels};
use std::path::{Path, PathBuf};

fn demo(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/data").join(name)
}

/// Points along the road's reference line with v swinging across it and beyond.
fn path(road: &std::sync::Arc<opencrg_core::Road>, n: usize) -> Vec<(f64, f64)> {
    let ((u0, u1), (v0, v1)) = (road.u_range(), road.v_range());
    let cp = ContactPoint::new(road.clone());
    (0..n)
        .map(|k| {
            let f = k as f64 / (n - 1) as f64;
            let u = u0 - 2.0 + f * (u1 - u0 + 4.0);
            let v = 0.5 * (v0 + v1) + 0.6 * (v1 - v0) * (k as f64 * 0.37).sin();
            cp.uv_to_xy(u, v).unwrap()
        })
        .collect()
}

fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

/// One CRG file: the first wheel against contact points making the C API's calls.
fn crg_agrees(file: &Path) -> usize {
    let terrain = Terrain::load_crg(file, Compat::default()).unwrap();
    let Terrain::Crg(road) = &terrain else { unreachable!() };
    let mut wheels = Wheels::new(&terrain, 2, (0.0, 0.0), &[]).unwrap();
    let (mut cp, mut z_cp) = (ContactPoint::new(road.clone()), ContactPoint::new(road.clone()));
    let points = path(road, 400);
    let mut on = 0;
    for &(x, y) in &points {
        wheels.set(0, Quantity::X, x);
        wheels.set(0, Quantity::Y, y);
        // The C API's answers; 0 where it refuses.
        let found = cp.xy_to_uv(x, y).ok();
        let (u, v) = found.unwrap_or((0.0, 0.0));
        let z = z_cp.xy_to_z(x, y).ok().filter(|z| z.is_finite()).unwrap_or(0.0);
        let (phi, curv) = found.and_then(|(u, v)| cp.uv_to_pk(u, v).ok()).unwrap_or((0.0, 0.0));
        let got = [Quantity::U, Quantity::V, Quantity::Z, Quantity::Heading, Quantity::Curvature]
            .map(|q| wheels.real(0, q, 1.0));
        for (q, (g, want)) in ["u", "v", "z", "heading", "curvature"].iter().zip(got.iter().zip([u, v, z, phi, curv])) {
            assert!(same(*g, want), "{}: ({x}, {y}): {q} {g} against {want}", file.display());
        }
        on += usize::from(wheels.on_road(0));
    }
    assert!(
        on > points.len() / 4 && on < points.len(),
        "{}: {on} of {} points on the road",
        file.display(),
        points.len()
    );
    points.len()
}

#[test]
fn the_demo_road_answers_as_the_c_api() {
    crg_agrees(&demo("demo_road.crg"));
}

#[test]
#[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
fn shared_samples_answer_as_the_c_api() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/conformance");
    let mut checked = 0;
    for sub in ["crg-txt", "crg-bin"] {
        let mut files: Vec<PathBuf> = std::fs::read_dir(dir.join(sub)).unwrap().map(|e| e.unwrap().path()).collect();
        files.sort();
        for file in files.iter().filter(|f| f.extension().is_some_and(|e| e == "crg")) {
            // Files the C API's check refuses are refused by the FMU too (and tested so).
            if Terrain::load_crg(file, Compat::default()).is_err() {
                continue;
            }
            checked += crg_agrees(file);
        }
    }
    assert!(checked >= 5_000, "{checked} points");
}

#[test]
fn off_the_road_and_bad_input_give_the_documented_values() {
    let terrain = Terrain::load_map(&demo("demo_map.xodr"), &[]).unwrap();
    let mut wheels = Wheels::new(&terrain, 1, (0.0, 0.0), &[]).unwrap();
    for (x, y) in [(1e6, 1e6), (f64::NAN, 0.0), (0.0, f64::INFINITY)] {
        wheels.set(0, Quantity::X, x);
        wheels.set(0, Quantity::Y, y);
        assert!(!wheels.on_road(0), "({x}, {y})");
        let values =
            [Quantity::Z, Quantity::Friction, Quantity::Nx, Quantity::Ny, Quantity::Nz, Quantity::S, Quantity::T]
                .map(|q| wheels.real(0, q, 0.7));
        assert_eq!(values, [0.0, 0.7, 0.0, 0.0, 1.0, 0.0, 0.0], "({x}, {y})");
        assert_eq!((wheels.integer(0, Quantity::Road), wheels.integer(0, Quantity::Lane)), (-1, 0));
    }
    let crg = Terrain::load_crg(&demo("demo_road.crg"), Compat::default()).unwrap();
    let mut wheels =
        Wheels::new(&crg, 1, (0.0, 0.0), &[(opencrg_core::settings::opt::BORDER_MODE_U, opencrg_core::Value::Int(0))])
            .unwrap();
    for (x, y) in [(f64::NAN, 0.0), (0.0, f64::INFINITY), (f64::NEG_INFINITY, 1.0), (f64::INFINITY, f64::NAN)] {
        wheels.set(0, Quantity::X, x);
        wheels.set(0, Quantity::Y, y);
        assert!(!wheels.on_road(0), "({x}, {y})");
        let values = [Quantity::Z, Quantity::Friction, Quantity::Nx, Quantity::Ny, Quantity::Nz]
            .map(|q| wheels.real(0, q, 0.7))
            .into_iter()
            .chain([Quantity::U, Quantity::V, Quantity::Heading, Quantity::Curvature].map(|q| wheels.real(0, q, 0.7)));
        assert_eq!(values.collect::<Vec<_>>(), [0.0, 0.7, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0], "({x}, {y})");
    }
    wheels.set(0, Quantity::X, -50.0);
    wheels.set(0, Quantity::Y, 0.0);
    assert!(!wheels.on_road(0));
    assert_eq!(wheels.real(0, Quantity::Z, 1.0), 0.0, "refused beyond the border with border mode none");
    assert_eq!(wheels.real(0, Quantity::Friction, 0.8), 0.8);
}

/// The get path (`read_reals`, by table) answers what the single reads answer, the
/// inputs read back as set (a NaN's bits too), and stops at the first reference it is
/// given no wheel of.
#[test]
fn the_get_path_answers_as_the_single_reads() {
    let terrain = Terrain::load_crg(&demo("demo_road.crg"), Compat::default()).unwrap();
    let Terrain::Crg(road) = &terrain else { unreachable!() };
    let (mut fast, mut single) =
        (Wheels::new(&terrain, 2, (0.0, 0.0), &[]).unwrap(), Wheels::new(&terrain, 2, (0.0, 0.0), &[]).unwrap());
    let asked = [
        (1, Quantity::Z),
        (0, Quantity::X),
        (0, Quantity::Z),
        (1, Quantity::Y),
        (0, Quantity::U),
        (1, Quantity::Friction),
    ];
    let vrs: Vec<u32> = (0..asked.len() as u32).collect();
    let odd = f64::from_bits(f64::NAN.to_bits() | 0x1234);
    let mut points = path(road, 50);
    points.push((odd, 1.0));
    for (k, &(x, y)) in points.iter().enumerate() {
        for w in [&mut fast, &mut single] {
            w.set(0, Quantity::X, x);
            w.set(0, Quantity::Y, y);
            w.set(1, Quantity::X, x + 0.5);
            w.set(1, Quantity::Y, -y);
        }
        let mut out = [0.0; 6];
        // Every other step, the wheels' answers are computed by the single reads first.
        if k % 2 == 0 {
            single.real(1, Quantity::Z, 0.6);
        }
        assert_eq!(fast.read_reals(&vrs, &mut out, 0.6, |vr| asked.get(vr as usize).copied()), asked.len());
        let want = asked.map(|(i, q)| single.real(i, q, 0.6));
        for (q, (g, w)) in asked.iter().zip(out.iter().zip(want)) {
            assert_eq!(g.to_bits(), w.to_bits(), "({x}, {y}): {q:?}");
        }
        assert_eq!(out[1].to_bits(), x.to_bits(), "x reads back as set");
        assert_eq!(out[3].to_bits(), (-y).to_bits(), "y reads back as set");
    }
    let mut out = [0.0; 3];
    assert_eq!(fast.read_reals(&[0, 99, 1], &mut out, 0.6, |vr| asked.get(vr as usize).copied()), 1);
    assert_eq!(fast.read_reals(&[0], &mut out, 0.6, |_| Some((2, Quantity::Z))), 0, "no third wheel");
}
