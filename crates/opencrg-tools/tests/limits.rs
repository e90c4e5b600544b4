//! Requests one typo away from sensible ones: each tool sizes what it would make before it
//! allocates, and refuses beyond its budget with a message naming the request, the size
//! and the limit; parameters out of range are refused in the user's terms.

use opencrg_core::synth::RoadSpec;
use opencrg_core::{Budget, ContactPoint, Error, Road};
use opencrg_tools::mesh::grid_mesh;
use opencrg_tools::simplify::simplified_mesh;
use opencrg_tools::{self as tools, Filter, Import, Layout, Points};
use std::sync::Arc;

fn road() -> Arc<Road> {
    let spec = RoadSpec::straight(60.0, 4.0, 0.1, 0.25)
        .with_heading(|u| 0.01 * u)
        .with_elevation(|u, v| 0.01 * (u * 0.7).sin() * (v + 1.0));
    Arc::new(spec.build().unwrap())
}

fn line() -> Points {
    let x: Vec<f64> = (0..=50).map(|i| i as f64 * 2.0).collect();
    Points { y: x.iter().map(|x| 10.0 * (x / 30.0).sin()).collect(), x, z: None }
}

/// A refusal of the kind a request gets, its text holding every piece of `parts`.
fn refused<T>(result: opencrg_core::Result<T>, parts: &[&str]) {
    match result {
        Err(e @ (Error::TooLarge(_) | Error::OutOfRange(_))) => {
            let text = e.to_string();
            // The kind says which: beyond the memory limit, or a value not taken.
            assert_eq!(matches!(e, Error::TooLarge(_)), text.contains("the limit is"), "{text}");
            for p in parts {
                assert!(text.contains(p), "'{p}' not in: {text}");
            }
        }
        Err(e) => panic!("refused as another kind of error: {e}"),
        Ok(_) => panic!("not refused: {parts:?}"),
    }
}

#[test]
fn roads_beyond_the_machine_are_refused_before_anything_is_made() {
    let (r, machine) = (road(), Budget::machine().raised_with("--max-memory"));
    refused(
        tools::resample(&r, Some(1e-9), None, &machine),
        &["u increment of 1e-9 m", "60,000,000,001 cross sections x 17 long sections", "the limit is", "--max-memory"],
    );
    refused(tools::resample(&r, Some(1e-7), Some(1e-7), &machine), &["v increment of 1e-7 m", "the limit is"]);
    let layout = |width, u_inc, v_inc| Layout { width, u_inc, v_inc };
    refused(tools::generate(&line(), layout(3.0, 1e-9, 0.1), None, &machine), &["u increment of 1e-9 m", "the limit"]);
    refused(tools::generate(&line(), layout(3.0, 0.1, 1e-11), None, &machine), &["v increment of 1e-11 m"]);
    refused(tools::generate(&line(), layout(3e9, 0.1, 0.1), None, &machine), &["3e9 m wide"]);
    let cloud = Points { x: vec![0.0, 50.0, 0.0, 50.0], y: vec![-2.0, -2.0, 2.0, 2.0], z: Some(vec![0.0; 4]) };
    let how = Import { u_inc: 1e-9, v_inc: 0.1, width: Some(4.0), ..Import::default() };
    refused(tools::import(&cloud, &how, &|_, _, _| {}, &machine), &["u increment of 1e-9 m"]);
    let how = Import { u_inc: 0.1, v_inc: 0.1, width: Some(1e12), ..Import::default() };
    refused(tools::import(&cloud, &how, &|_, _, _| {}, &machine), &["1e12 m wide"]);
    assert!(tools::resample(&r, Some(0.05), Some(0.1), &machine).is_ok());
}

#[test]
fn a_given_limit_is_kept_and_named() {
    let r = road();
    let small = Budget::with_bytes(1_000_000).raised_with("max_memory=");
    refused(
        tools::resample(&r, Some(0.01), None, &small),
        &["6,001 cross sections", "the limit is 1.00 MB (max_memory= raises it)"],
    );
    // Just under the limit it is made, and the sizes agree with what was made.
    let made = tools::resample(&r, Some(0.05), None, &Budget::with_bytes(2_000_000)).unwrap();
    assert_eq!(made.grid().nu, 1201);
    let cp = ContactPoint::new(r.clone());
    refused(grid_mesh(&cp, None, None, &Budget::with_bytes(10_000)), &["a mesh of 601 x 17 grid nodes", "vertices"]);
    refused(simplified_mesh(&cp, None, None, 0.001, &Budget::with_bytes(10_000), &mut |_| {}), &["lattice points"]);
    assert!(grid_mesh(&cp, None, None, &Budget::machine()).is_ok());
    let line = line();
    refused(
        tools::generate(&line, Layout { width: 4.0, u_inc: 0.01, v_inc: 0.01 }, None, &small),
        &["the limit is 1.00 MB"],
    );
}

#[test]
fn filters_wider_than_the_road_are_refused() {
    let (r, machine) = (road(), Budget::machine());
    refused(
        tools::filter(&r, Filter::Median(1_000_001), &machine),
        &["median of 1000001 x 1000001", "wider than the road"],
    );
    refused(tools::filter(&r, Filter::Gauss(1e9), &machine), &["sigma 1e9 m", "beyond the road"]);
    refused(tools::filter(&r, Filter::Gauss(f64::NAN), &machine), &["positive number"]);
    refused(tools::filter(&r, Filter::Limit(1e300, -1e300), &machine), &["limits 1e300:-1e300"]);
    // A window wider than the road one way but not the other is still a filter.
    assert!(tools::filter(&r, Filter::Median(21), &machine).is_ok());
    assert!(tools::filter(&r, Filter::Gauss(1e-300), &machine).is_ok());
}

#[test]
fn parameters_out_of_range_are_refused_in_the_users_terms() {
    let (r, machine) = (road(), Budget::machine());
    refused(tools::resample(&r, Some(-1.0), None, &machine), &["u increment -1 m must be a positive number"]);
    refused(tools::resample(&r, None, Some(f64::NAN), &machine), &["v increment NaN m"]);
    refused(tools::resample(&r, Some(f64::INFINITY), None, &machine), &["u increment inf m"]);
    refused(
        tools::generate(&line(), Layout { width: f64::INFINITY, u_inc: 0.1, v_inc: 0.1 }, None, &machine),
        &["width inf m"],
    );
    refused(opencrg_tools::roughness::roughness(&r, &[0.0], 1e-300), &["segment length 1e-300 m", "u increment"]);
    refused(opencrg_tools::roughness::roughness(&r, &[1e300], 10.0), &["track at v = 1e300 m lies outside"]);
    refused(tools::cut(&r, (1e300, 2e300), None), &["u range 1e300:2e300"]);
    let z: Vec<f64> = (0..2000).map(|i| (i as f64 * 0.1).sin() * 0.01).collect();
    let response = opencrg_tools::iri::response(&z, 0.05).unwrap();
    refused(opencrg_tools::iri::segment_iris(&[(0.0, &response)], 100.0, 1e-300), &["segment length 1e-300 m"]);
}

#[test]
fn point_files_claiming_more_than_they_hold_are_refused() {
    let header = |count: &str, format: &str| {
        format!("ply\nformat {format} 1.0\nelement vertex {count}\nproperty double x\nproperty double y\nproperty double z\nend_header\n")
    };
    for (count, format) in [("99999999999999999", "binary_little_endian"), ("18446744073709551615", "ascii")] {
        let mut bytes = header(count, format).into_bytes();
        bytes.extend_from_slice(b"1 2 3\n");
        let e = tools::parse_points(&bytes, std::path::Path::new("claims.ply")).unwrap_err().to_string();
        assert!(e.contains("claims.ply"), "{e}");
    }
    let bad = tools::parse_points(b"LASF not really", std::path::Path::new("bad.las")).unwrap_err().to_string();
    assert!(bad.contains("bad.las"), "{bad}");
}

/// Found by the `tools` fuzz target: a line through points far apart (the spline through
/// them leaves the finite numbers) reached the walk along its polyline with NaN.
#[test]
fn lines_through_points_beyond_the_finite_are_refused() {
    let layout = Layout { width: 3.0, u_inc: 0.5, v_inc: 0.5 };
    for (x, y) in [
        (vec![0.0, 1e300, -1e300, 5.0], vec![0.0, 0.5, 1e300, 0.0]),
        (vec![0.0, 1e200, 3.0, 1e-300], vec![1e250, -1e250, 0.0, 1.0]),
        (vec![0.0, 1.0, 1.0 + 1e-300, 2.0], vec![0.0, 0.0, 0.0, 0.0]),
        (vec![-3.380843063978214e221; 4], vec![2.37, 2.55, -0.2, 0.5]),
    ] {
        let result = tools::generate(&Points { x, y, z: None }, layout, None, &Budget::with_bytes(8 << 20));
        if let Err(e) = result {
            assert!(matches!(e, Error::OutOfRange(_)), "{e}");
        }
    }
}
