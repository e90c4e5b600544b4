//! The statistics a road reports (what the C API prints after loading) against a road
//! generated with known figures.

use opencrg::report::Event;
use opencrg::synth::RoadSpec;
use opencrg::{LoadOptions, Road};

#[test]
fn figures_of_a_generated_road() {
    // 40 m along heading 0.5 from (10, 20), v from -2 to 2, z = 0.01 u - 0.1 v + 0.3,
    // banking 0.02 to 0.06, slope 0.05.
    let spec = RoadSpec::straight(40.0, 4.0, 0.5, 0.5)
        .starting_at(10.0, 20.0, 0.5)
        .with_heading(|_| 0.5)
        .with_bank(|u| 0.02 + 0.001 * u)
        .with_slope(|_| 0.05)
        .with_elevation(|u, v| 0.01 * u - 0.1 * v + 0.3);
    let options = LoadOptions { report_statistics: true, ..LoadOptions::default() };
    let mut road = Road::from_bytes_with(spec.to_crg(), "generated.crg", options).unwrap();
    let s = road.statistics();
    let near = |a: f64, b: f64| (a - b).abs() < 1e-5;
    assert!(near(s.z_mean_start, 0.3) && near(s.z_mean_end, 0.7), "{s:?}");
    assert!(near(s.z_min, 0.1) && near(s.z_max, 0.9), "{s:?}");
    assert_eq!((s.u_first, s.u_last), (0.0, 40.0));
    assert!(near(s.start.0, 10.0) && near(s.start.1, 20.0) && near(s.start.2, 0.5));
    assert!(near(s.end.0, 10.0 + 40.0 * 0.5f64.cos()) && near(s.end.1, 20.0 + 40.0 * 0.5f64.sin()));
    assert!(near(s.end.2, 0.5));
    assert_eq!((s.v_first, s.v_last), (-2.0, 2.0));
    assert!(near(s.curvature_left, 0.0) && near(s.curvature_right, 0.0));
    assert_eq!(s.banking, Some((0.02, 0.06)));
    assert!(near(s.z_line.0, 0.0) && near(s.z_line.1, 2.0), "{:?}", s.z_line);
    // Loading reported how the line was built and these same figures.
    let events = road.take_events();
    assert!(events.contains(&Event::LineFromHeading) && events.contains(&Event::LineZFromSlope));
    assert!(events.contains(&Event::Prepared(Box::new(s))));
    assert!(road.take_events().is_empty());
    // Without asking, no grid scan and no statistics event.
    let mut quiet = spec.build().unwrap();
    assert!(!quiet.take_events().iter().any(|e| matches!(e, Event::Prepared(_))));
}
