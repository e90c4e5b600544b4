//! Files the road tools write follow the rules ASAM's OpenCRG MATLAB tools check when
//! they read a file (`crg_read`, `crg_check`; learnt by running them on the tools' output):
//! the start and end headings are those of the first and last steps of the reference line;
//! every heading lies within [-pi, pi]; `LONG_SECTION_V_RIGHT` and `_LEFT` are the long
//! sections' own range; no centre of the reference line's curvature lies within the road's
//! width. Each tool's output is written, read back and checked; a cut starts with its
//! source's heading, a resampled road ends where its source ends.

use opencrg_core::synth::RoadSpec;
use opencrg_core::{Budget, ContactPoint, DataFormat, Road};
use opencrg_tools as tools;
use std::f64::consts::PI;
use std::sync::Arc;

/// The road as a file says it: written in `format` and read back.
fn as_written(road: &Road, format: DataFormat) -> Road {
    let mut bytes = Vec::new();
    opencrg_core::writer::write_to(road, &mut bytes, format).unwrap();
    Road::from_bytes(bytes, "written.crg").unwrap()
}

/// The rules, on a road read back from a file; `what` names it in a failure.
fn follows_the_rules(road: &Road, what: &str) {
    let h = &road.header().road;
    let l = road.reference_line();
    let step = |i: usize| (l.y[i + 1] - l.y[i]).atan2(l.x[i + 1] - l.x[i]);
    let same_direction = |a: f64, b: f64| (a.cos() - b.cos()).hypot(a.sin() - b.sin()) < 1e-6;
    let (start, end) = (h.start_phi.expect("a start heading"), h.end_phi.expect("an end heading"));
    assert!(same_direction(start, step(0)), "{what}: start heading {start}, first step {}", step(0));
    assert!(same_direction(end, step(l.n - 2)), "{what}: end heading {end}, last step {}", step(l.n - 2));
    for (i, p) in [start, end].into_iter().chain((0..l.n).map(|i| l.heading_at(i))).enumerate() {
        // The MATLAB tools' tolerance (CHECK_EPS): a text field rounds pi to 3.1415927.
        assert!(p.abs() <= PI * (1.0 + 1e-6), "{what}: heading {i} is {p}");
    }
    let v = &road.grid().v;
    assert_eq!((h.v_right, h.v_left), (Some(v[0]), Some(v[v.len() - 1])), "{what}: the v borders");
    // MATLAB's curvature of each inner point: the cross product of its two steps.
    let inc = l.u_inc;
    for i in 1..l.n - 1 {
        let (dx0, dy0, dx1, dy1) = (l.x[i] - l.x[i - 1], l.y[i] - l.y[i - 1], l.x[i + 1] - l.x[i], l.y[i + 1] - l.y[i]);
        let curvature = (dx0 * dy1 - dy0 * dx1) / inc.powi(3);
        if curvature.abs() > 1e-6 {
            let centre = 1.0 / curvature;
            assert!(
                !(v[0]..=v[v.len() - 1]).contains(&centre),
                "{what}: the centre of curvature at point {i} lies {centre} m aside, within the road"
            );
        }
    }
}

/// A road turning through more than half a circle (headings beyond pi), banked and sloped,
/// on a coarse line (1 m), with uneven long sections.
fn half_circle_plus() -> Arc<Road> {
    Arc::new(
        RoadSpec::straight(80.0, 6.0, 1.0, 0.5)
            .with_heading(|u| 0.5 + u / 20.0)
            .with_slope(|u| 0.02 * (u / 10.0).sin())
            .with_bank(|u| 0.03 * (u / 15.0).cos())
            .with_sections(vec![-3.0, -2.0, -0.5, 0.0, 0.5, 1.7, 3.0])
            .with_elevation(|u, v| 0.01 * (u * 0.9).sin() * (v * 1.3).cos())
            .build()
            .unwrap(),
    )
}

/// A fine straight road 10 m long.
fn short_straight() -> Arc<Road> {
    Arc::new(
        RoadSpec::straight(10.0, 3.4, 0.01, 0.1)
            .with_elevation(|u, v| 0.002 * (u * 3.0).sin() + 0.001 * v)
            .build()
            .unwrap(),
    )
}

#[test]
fn every_tool_writes_what_the_official_tools_accept() {
    let budget = Budget::machine();
    for (name, road) in [("half circle", half_circle_plus()), ("straight", short_straight())] {
        let (u0, u1) = road.u_range();
        let third = (u1 - u0) / 3.0;
        let made = [
            ("cut", tools::cut(&road, (u0 + third, u1 - third), None).unwrap()),
            ("cut across", tools::cut(&road, (u0 + 0.5 * third, u1), Some((-1.0, 1.2))).unwrap()),
            ("flip", tools::flip(&road).unwrap()),
            ("resample finer", tools::resample(&road, Some(0.25 * road.increments().0), None, &budget).unwrap()),
            ("resample coarser", tools::resample(&road, Some(3.0 * road.increments().0), Some(0.3), &budget).unwrap()),
            ("append", tools::append(&road, &road, &budget).unwrap()),
        ];
        for (tool, result) in made {
            for format in [DataFormat::Lrfi, DataFormat::Kdbi] {
                follows_the_rules(&as_written(&result, format), &format!("{tool} of the {name} road as {format:?}"));
            }
        }
    }
}

#[test]
fn a_cut_starts_with_its_sources_heading() {
    let road = half_circle_plus();
    let cut = tools::cut(&road, (30.0, 60.0), None).unwrap();
    let (a, b) = (ContactPoint::new(road.clone()), ContactPoint::new(Arc::new(cut.clone())));
    // Past the first cell (at least half a metre), where the reference library gives the
    // start heading and no curvature on any road.
    for u in [31.0, 31.5, 45.0, 59.5] {
        let (pa, ka) = a.uv_to_pk(u, 0.0).unwrap();
        let (pb, kb) = b.uv_to_pk(u, 0.0).unwrap();
        // The same direction (the cut's headings lie within [-pi, pi]).
        let turned = (pa - pb) / std::f64::consts::TAU;
        assert!(
            (turned - turned.round()).abs() < 1e-12 && (ka - kb).abs() < 1e-9,
            "u {u}: {pa} {ka} against {pb} {kb}"
        );
    }
    // Within it: the heading of the first step.
    let (p, k) = b.uv_to_pk(30.2, 0.0).unwrap();
    assert_eq!((p, k), (a.uv_to_pk(30.5, 0.0).unwrap().0, 0.0));
    assert!((p - 2.05).abs() < 1e-12, "{p}");
    assert_eq!(cut.header().road.start_phi, Some(road.reference_line().heading_at(31)));
}

#[test]
fn a_resampled_road_ends_where_its_source_ends() {
    let road = half_circle_plus();
    let budget = Budget::machine();
    for (du, last) in [(0.25, 80.0), (2.0, 80.0), (0.3, 79.8), (7.0, 77.0)] {
        let made = tools::resample(&road, Some(du), None, &budget).unwrap();
        let (u0, u1) = made.u_range();
        assert_eq!(u0, 0.0);
        assert!((u1 - last).abs() < 1e-9, "increment {du}: ends at {u1}");
        // The line ends where the source's does, where the increment divides the length:
        // within length x curvature^2 x increment^2 / 24, the increment the larger of the
        // two (here 1 m and a radius of 20 m: the drawing of a coarse, tight bend).
        if (80.0 / du).fract() == 0.0 {
            let (l, m) = (road.reference_line(), made.reference_line());
            let gap = (l.x[l.n - 1] - m.x[m.n - 1]).hypot(l.y[l.n - 1] - m.y[m.n - 1]);
            let bound = 80.0 * du.max(1.0).powi(2) / 400.0 / 24.0;
            assert!(gap < bound, "increment {du}: {gap} m from the end ({bound})");
        }
    }
}

#[test]
fn a_file_without_v_borders_is_written_with_its_sections_range() {
    // The long sections at -1.5..1.5, no LONG_SECTION_V_RIGHT/LEFT; banked, so that the
    // banking the reference library applies (at v = 0 only, for such a file) must stay.
    let mut file = String::from(
        "$ROAD_CRG
REFERENCE_LINE_INCREMENT = 1.0
$
$KD_Definition
#:LRFI
D:reference line phi,rad
D:reference line banking,m/m
D:long section at v = -1.500,m
D:long section at v = 0.000,m
D:long section at v = 1.500,m
$
$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$
",
    );
    for i in 0..6 {
        for value in [0.01 * i as f64, 0.02, 0.001 * i as f64, 0.002 * i as f64, 0.003] {
            file.push_str(&format!("{value:>10.7}"));
        }
        file.push('\n');
    }
    let source = Road::from_bytes(file.into_bytes(), "no_borders.crg").unwrap();
    assert_eq!((source.header().road.v_right, source.header().road.v_left), (None, None));
    for format in [DataFormat::Lrfi, DataFormat::Kdbi] {
        let written = as_written(&source, format);
        assert_eq!((written.header().road.v_right, written.header().road.v_left), (Some(-1.5), Some(1.5)));
        let (a, b) = (ContactPoint::new(Arc::new(source.clone())), ContactPoint::new(Arc::new(written)));
        for u in [0.0, 1.0, 2.5, 5.0] {
            for v in [-1.5, -0.7, 0.0, 1.5] {
                let (za, zb) = (a.uv_to_z(u, v).unwrap(), b.uv_to_z(u, v).unwrap());
                assert!((za - zb).abs() < 1e-6, "{format:?} u {u} v {v}: {za} {zb}");
            }
        }
    }
}
