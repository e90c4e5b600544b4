//! Roads the project generates, written in each format and read back, give the same data.

use opencrg_core::synth::RoadSpec;
use opencrg_core::{DataFormat, Road};

fn curved_banked_sloped() -> RoadSpec {
    RoadSpec::straight(60.0, 4.0, 0.25, 0.1)
        .starting_at(10.0, -5.0, 0.3)
        .with_heading(|u| 0.3 + 0.01 * u)
        .with_slope(|u| 0.02 * (u / 10.0).sin())
        .with_bank(|u| -0.03 + 0.001 * u)
        .with_elevation(|u, v| if v > 1.85 && u < 5.0 { f64::NAN } else { 0.01 * (u * 3.0).sin() * (v * 2.0).cos() })
}

fn temp_path(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("opencrg-roundtrip-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn same_bits(a: &[f32], b: &[f32]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()))
}

/// Writes and reads back; `tag` keeps the files of tests running in parallel apart.
fn roundtrip(road: &Road, format: DataFormat, tag: &str) -> Road {
    let path = temp_path(&format!("road.{tag}.{}.crg", format.name()));
    opencrg_core::write(road, &path, format).unwrap();
    Road::load(&path).unwrap_or_else(|e| panic!("{}: {e}", format.name()))
}

#[test]
fn binary_formats_are_bit_exact() {
    for spec in [curved_banked_sloped(), curved_banked_sloped().with_sections(vec![-2.0, -1.0, -0.25, 0.0, 0.5, 2.0])] {
        let road = spec.build().unwrap();
        for format in [DataFormat::Kdbi, DataFormat::Krbi] {
            let back = roundtrip(&road, format, "binary");
            let (za, zb) = (road.grid().values(), back.grid().values());
            let first =
                za.iter().zip(zb.iter()).position(|(x, y)| x.to_bits() != y.to_bits() && !(x.is_nan() && y.is_nan()));
            assert!(
                same_bits(za, zb),
                "{} grid differs at {first:?}: {:?}",
                format.name(),
                first.map(|i| (za[i], zb[i]))
            );
            assert_eq!(road.grid().v, back.grid().v);
            assert_eq!(road.u_range(), back.u_range());
            assert_eq!(road.increments(), back.increments());
            let (a, b) = (road.reference_line(), back.reference_line());
            if format == DataFormat::Kdbi {
                assert_eq!(a.phi, b.phi, "KDBI heading must be exact");
                assert_eq!(a.x, b.x);
                assert_eq!(a.slope, b.slope);
                assert_eq!(a.bank, b.bank);
            } else {
                let phi_a = a.phi.as_ref().unwrap();
                let phi_b = b.phi.as_ref().unwrap();
                assert!(
                    phi_a.iter().zip(phi_b).all(|(x, y)| (*x as f32) == (*y as f32)),
                    "KRBI heading is single precision"
                );
            }
        }
    }
}

#[test]
fn text_formats_keep_their_precision() {
    let road = curved_banked_sloped().build().unwrap();
    for (format, tol) in [(DataFormat::Lrfi, 1e-7f64), (DataFormat::Ldfi, 1e-12)] {
        let back = roundtrip(&road, format, "text");
        let (a, b) = (road.grid().values(), back.grid().values());
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(b) {
            assert!(
                (x.is_nan() && y.is_nan()) || (x - y).abs() as f64 <= tol.max(1e-7),
                "{}: {x} vs {y}",
                format.name()
            );
        }
        let (pa, pb) = (road.reference_line().phi.as_ref().unwrap(), back.reference_line().phi.as_ref().unwrap());
        for (x, y) in pa.iter().zip(pb) {
            assert!((x - y).abs() <= tol * 10.0, "{}: heading {x} vs {y}", format.name());
        }
        assert_eq!(road.u_range(), back.u_range());
    }
}

#[test]
fn evaluation_survives_the_roundtrip() {
    let road = std::sync::Arc::new(curved_banked_sloped().build().unwrap());
    let back = std::sync::Arc::new(roundtrip(&road, DataFormat::Kdbi, "eval"));
    let a = opencrg_core::ContactPoint::new(road);
    let b = opencrg_core::ContactPoint::new(back);
    for i in 0..50 {
        let (u, v) = (i as f64 * 1.3 - 5.0, (i as f64 * 0.37).sin() * 2.5);
        let (za, zb) = (a.uv_to_z(u, v).unwrap(), b.uv_to_z(u, v).unwrap());
        assert!(za == zb || (za.is_nan() && zb.is_nan()), "{za} vs {zb}");
        assert_eq!(a.uv_to_xy(u, v).unwrap(), b.uv_to_xy(u, v).unwrap());
    }
}

/// Every option and modifier with a file keyword is written and read back with its value.
#[test]
fn every_setting_with_a_keyword_roundtrips() {
    use opencrg_core::settings::{Accepts, Family, Kind, SETTINGS};
    let mut road = curved_banked_sloped().build().unwrap();
    for (k, s) in SETTINGS.iter().enumerate() {
        if s.keyword.is_none() || s.accepts == Accepts::Count {
            continue;
        }
        let table = match s.family {
            Family::Option => road.options_mut(),
            Family::Modifier => road.modifiers_mut(),
        };
        match (s.kind, s.accepts) {
            (Kind::Int, Accepts::Flag) => table.set_int(s.id, s.id as i32).unwrap(),
            (Kind::Int, Accepts::Choice { max }) => table.set_int(s.id, (k as i32) % (max + 1)).unwrap(),
            (Kind::Int, _) => table.set_int(s.id, 1).unwrap(),
            (Kind::Double, _) => table.set_double(s.id, 0.125 + k as f64).unwrap(),
        }
    }
    let back = roundtrip(&road, DataFormat::Ldfi, "settings");
    assert_eq!(back.options(), road.options());
    assert_eq!(back.modifiers(), road.modifiers());
}
