//! The statistics a road reports (what the C API prints after loading) against a road
//! generated with known figures.

use opencrg_core::refline::LineFinding;
use opencrg_core::report::Event;
use opencrg_core::synth::RoadSpec;
use opencrg_core::{LoadOptions, Road};

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

/// A text road 4 m long at 1 m, two long sections, with the given extra `$ROAD_CRG`
/// lines and reference line channels (`phi` heading values, `xy` x/y points).
fn line_road(extra: &str, phi: Option<[f64; 5]>, xy: bool) -> Road {
    let mut s = format!(
        "$ROAD_CRG\nREFERENCE_LINE_START_U = 0\nREFERENCE_LINE_END_U = 4\nREFERENCE_LINE_INCREMENT = 1\n\
         LONG_SECTION_V_INCREMENT = 0.5\n{extra}$\n$KD_Definition\n#:LRFI\n"
    );
    if xy {
        s += "D:reference line x,m\nD:reference line y,m\n";
    }
    if phi.is_some() {
        s += "D:reference line phi,rad\n";
    }
    s += "D:long section 1,m\nD:long section 2,m\n$\n$$$$$$$$$$\n";
    for i in 0..5 {
        if xy {
            s += &format!("{:10.4}{:10.4}", i as f64, 0.0);
        }
        if let Some(phi) = phi {
            s += &format!("{:12.8}", phi[i]);
        }
        s += &format!("{:10.4}{:10.4}\n", 0.1, 0.2);
    }
    Road::from_bytes(s.into_bytes(), "line.crg").unwrap()
}

/// The warnings of a `line_road` load, and the one a finding would give.
fn warned(road: Road) -> Vec<String> {
    road.warnings().to_vec()
}

fn says(finding: LineFinding) -> Vec<String> {
    vec![format!("line.crg: {finding}")]
}

/// What building the reference line finds inconsistent or incomplete, each case once (a
/// warning of the load naming the file), nothing where the file is consistent; after
/// modifiers, the same as an event.
#[test]
fn reference_line_findings() {
    // Straight: no end point; an end point 1 mm off; one within the 0.5 mm tolerance.
    assert_eq!(warned(line_road("", None, false)), says(LineFinding::StraightEndComputed { end: (4.0, 0.0) }));
    let off = warned(line_road("REFERENCE_LINE_END_X = 4.001\nREFERENCE_LINE_END_Y = 0\n", None, false));
    assert_eq!(off, says(LineFinding::StraightEndDiffers { gap: (0.001, 0.0) }));
    assert!(warned(line_road("REFERENCE_LINE_END_X = 4.0003\nREFERENCE_LINE_END_Y = 0\n", None, false)).is_empty());
    // A heading channel (turning left 0.1 rad per metre) against an end point that does
    // not follow from it, and against the end it gives.
    let phi: [f64; 5] = [0.0, 0.1, 0.2, 0.3, 0.4];
    let end: (f64, f64) = (1..5).fold((0.0, 0.0), |(x, y), i| (x + phi[i].cos(), y + phi[i].sin()));
    let far = warned(line_road("REFERENCE_LINE_END_X = 4\nREFERENCE_LINE_END_Y = 0\n", Some(phi), false));
    assert!(far.len() == 1 && far[0].starts_with("line.crg: the heading channel, integrated back"), "{far:?}");
    let given = format!("REFERENCE_LINE_END_X = {:.12}\nREFERENCE_LINE_END_Y = {:.12}\n", end.0, end.1);
    assert!(warned(line_road(&given, Some(phi), false)).is_empty());
    // The slope integrated back from an end z that does not follow from it.
    let slope = "REFERENCE_LINE_END_X = 4\nREFERENCE_LINE_END_Y = 0\nREFERENCE_LINE_START_S = 0.01\n";
    assert!(warned(line_road(&format!("{slope}REFERENCE_LINE_END_Z = 0.04\n"), None, false)).is_empty());
    let z = warned(line_road(&format!("{slope}REFERENCE_LINE_END_Z = 0.05\n"), None, false));
    assert_eq!(z, says(LineFinding::SlopeMissesStart { gap: 0.01 }));
    // x/y channels.
    let xy = warned(line_road("REFERENCE_LINE_END_X = 4\nREFERENCE_LINE_END_Y = 0\n", None, true));
    assert_eq!(xy, says(LineFinding::XyChannelsNotUsed));
    // After modifiers (which prepare the line again) the finding is an event.
    let mut road = line_road("$ROAD_CRG_MODS\nSCALE_Z_GRID = 2\n$\n$ROAD_CRG\n", None, false);
    road.take_events();
    road.apply_modifiers();
    let events: Vec<_> = road.take_events().into_iter().filter(|e| matches!(e, Event::Line(_))).collect();
    assert!(matches!(events[..], [Event::Line(LineFinding::StraightEndComputed { .. })]), "{events:?}");
}
