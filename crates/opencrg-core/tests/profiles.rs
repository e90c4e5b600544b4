//! The two behaviour profiles on a road the test generates: the three answers in
//! which ASAM's current code and its releases 2.0.1/1.2.0 differ.

use opencrg_core::synth::RoadSpec;
use opencrg_core::{Compat, ContactPoint, Road};
use std::sync::Arc;

/// A road that turns left at a constant rate, starting at (100, 50) with heading 0.3,
/// v from -2 (right) to 3 (left).
fn turning() -> RoadSpec {
    RoadSpec::straight(20.0, 5.0, 0.25, 0.5)
        .with_sections((0..=10).map(|i| -2.0 + 0.5 * i as f64).collect())
        .starting_at(100.0, 50.0, 0.3)
        .with_heading(|u| 0.3 + 0.02 * u)
        .with_elevation(|u, v| 0.01 * u + 0.05 * v)
}

fn load(spec: &RoadSpec, compat: Compat) -> Road {
    Road::from_bytes_with(spec.to_crg(), "turning.crg", compat).unwrap()
}

#[test]
fn first_point_of_the_integrated_reference_line() {
    let spec = turning();
    let up = load(&spec, Compat::Upstream);
    let rel = load(&spec, Compat::Release201);
    assert_eq!(up.compat(), Compat::Upstream);
    let (lu, lr) = (up.reference_line(), rel.reference_line());
    // The current code starts at the header's point, the releases at the origin.
    assert_eq!((lu.x[0], lu.y[0]), (100.0, 50.0));
    assert_eq!((lr.x[0], lr.y[0]), (0.0, 0.0));
    // Both then take the same steps.
    for i in 1..lu.n {
        assert!((lu.x[i] - lr.x[i] - 100.0).abs() < 1e-9 && (lu.y[i] - lr.y[i] - 50.0).abs() < 1e-9, "point {i}");
    }
}

#[test]
fn heading_of_uv_to_pk() {
    let spec = turning();
    for (compat, offset) in [(Compat::Upstream, 1), (Compat::Release201, 0)] {
        let road = Arc::new(load(&spec, compat));
        let phi = road.reference_line().phi.clone().unwrap();
        let cp = ContactPoint::new(road);
        // u = 10.1 lies in segment 40 (u 10.0 to 10.25).
        let (heading, _) = cp.uv_to_pk(10.1, 0.0).unwrap();
        assert_eq!(heading, phi[40 + offset], "{compat}");
    }
}

#[test]
fn default_reference_point_of_the_relocation() {
    let spec = turning();
    for (compat, v_at_origin) in [(Compat::Upstream, 0.0), (Compat::Release201, -2.0)] {
        let mut road = load(&spec, compat);
        road.check().unwrap();
        road.apply_modifiers();
        let cp = ContactPoint::new(Arc::new(road));
        let (x, y) = cp.uv_to_xy(0.0, v_at_origin).unwrap();
        assert!(x.abs() < 1e-9 && y.abs() < 1e-9, "{compat}: ({x}, {y})");
        let (heading, _) = cp.uv_to_pk(0.0, 0.0).unwrap();
        assert!(heading.abs() < 1e-12, "{compat}: start heading {heading} after relocation");
    }
}
