//! Regression tests for the differences the differential tester found against the
//! reference library, each on a small road written here: the reference's answer is
//! what a drop-in must give.

use opencrg_core::settings::{m, opt};
use opencrg_core::{ContactPoint, Road};
use std::path::PathBuf;
use std::sync::Arc;

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("opencrg-quirks-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// An LRFI road: `road` lines for `$ROAD_CRG`, channel definitions, rows of values.
fn lrfi(road: &str, channels: &[&str], rows: &[Vec<f64>]) -> String {
    let mut s = format!("$ROAD_CRG\n{road}$\n$KD_Definition\n#:LRFI\n");
    for c in channels {
        s += &format!("D:{c}\n");
    }
    s += &format!("$\n{}\n", "$".repeat(80));
    for row in rows {
        for (k, v) in row.iter().enumerate() {
            if k > 0 && k % 8 == 0 {
                s.push('\n');
            }
            s += &if v.is_nan() { format!("{:>10}", "NaN") } else { format!("{v:>10.6}") };
        }
        s.push('\n');
    }
    s
}

fn load_text(text: &str) -> Road {
    Road::from_bytes(text.as_bytes().to_vec(), "test.crg").unwrap()
}

fn cp(road: Road) -> ContactPoint {
    ContactPoint::new(Arc::new(road))
}

/// Five cross sections 1 m apart, three numbered long sections 0.5 m apart.
fn rows(f: impl Fn(usize, usize) -> f64) -> Vec<Vec<f64>> {
    (0..5).map(|i| (0..3).map(|j| f(i, j)).collect()).collect()
}

const NUMBERED: [&str; 3] = ["long section 1,m", "long section 2,m", "long section 3,m"];

#[test]
fn nan_as_first_slope_or_banking_value_loads() {
    // PyOpenCRG writes NaN as the first value of these channels; the integration never reads it.
    let channels = ["reference line slope,m/m", "reference line banking,m/m", NUMBERED[0], NUMBERED[1], NUMBERED[2]];
    let data: Vec<Vec<f64>> = (0..5)
        .map(|i| if i == 0 { vec![f64::NAN, f64::NAN, 0.0, 0.0, 0.0] } else { vec![0.1, 0.0, 0.0, 0.0, 0.0] })
        .collect();
    let road = load_text(&lrfi("REFERENCE_LINE_INCREMENT = 1.0\nLONG_SECTION_V_INCREMENT = 0.5\n", &channels, &data));
    assert!(!road.warnings().iter().any(|w| w.contains("NaN")), "{:?}", road.warnings());
    let c = cp(road);
    assert!((c.uv_to_z(3.0, 0.0).unwrap() - 0.3).abs() < 1e-9);
    // NaN later in a channel also loads, with a warning naming the record.
    let mut later = data.clone();
    later[2][0] = f64::NAN;
    let road = load_text(&lrfi("REFERENCE_LINE_INCREMENT = 1.0\nLONG_SECTION_V_INCREMENT = 0.5\n", &channels, &later));
    assert!(road.warnings().iter().any(|w| w.contains("record 3") && w.contains("slope")), "{:?}", road.warnings());
}

#[test]
fn nan_offset_without_nan_mode_fails_the_check_after_setting_the_mode() {
    let mut road = load_text(&lrfi(
        "REFERENCE_LINE_INCREMENT = 1.0\nLONG_SECTION_V_INCREMENT = 0.5\n",
        &NUMBERED,
        &rows(|_, _| 0.0),
    ));
    road.modifiers_mut().clear();
    road.modifiers_mut().set_double(m::GRID_NAN_OFFSET, 0.1).unwrap();
    road.modifiers_mut().set_double(m::REFPOINT_X, 1.0).unwrap();
    assert!(road.check().is_err());
    assert_eq!(road.modifiers().get_int(m::GRID_NAN_MODE), Some(2));
    // The check stopped before completing the relocation modifiers.
    assert!(!road.modifiers().is_set(m::REFPOINT_U_FRAC));
}

#[test]
fn end_point_of_a_referenced_file_does_not_choose_the_integration() {
    let d = dir("ends");
    // A turning line whose header end point is 0.2 m off the forward integration.
    let channels = ["reference line phi,rad", NUMBERED[0], NUMBERED[1], NUMBERED[2]];
    let data: Vec<Vec<f64>> = (0..5).map(|i| vec![0.1 * i as f64, 0.0, 0.0, 0.0]).collect();
    let mut end = (0.0f64, 0.0f64);
    for i in 1..5 {
        end.0 += (0.1 * i as f64).cos();
        end.1 += (0.1 * i as f64).sin();
    }
    let header = format!(
        "REFERENCE_LINE_INCREMENT = 1.0\nLONG_SECTION_V_INCREMENT = 0.5\nREFERENCE_LINE_END_X = {}\nREFERENCE_LINE_END_Y = {}\n",
        end.0 + 0.2,
        end.1
    );
    std::fs::write(d.join("data.crg"), lrfi(&header, &channels, &data)).unwrap();
    std::fs::write(d.join("top.crg"), "$ROAD_CRG_FILE\ndata.crg\n$\n").unwrap();
    // Loaded itself, the end point pulls the line; through a reference it does not.
    let direct = Road::load(d.join("data.crg")).unwrap();
    let referenced = Road::load(d.join("top.crg")).unwrap();
    assert!((direct.reference_line().x[4] - (end.0 + 0.2)).abs() < 1e-9);
    assert!((referenced.reference_line().x[4] - end.0).abs() < 1e-9);
}

#[test]
fn numbered_sections_of_a_referenced_file_are_looked_up_by_position() {
    let d = dir("numbered");
    let header = "REFERENCE_LINE_INCREMENT = 1.0\nLONG_SECTION_V_RIGHT = -0.5\nLONG_SECTION_V_LEFT = 0.5\nLONG_SECTION_V_INCREMENT = 0.5\n";
    std::fs::write(d.join("data.crg"), lrfi(header, &NUMBERED, &rows(|_, j| j as f64))).unwrap();
    std::fs::write(d.join("top.crg"), "$ROAD_CRG_FILE\ndata.crg\n$\n").unwrap();
    // Just past the left border, with border mode none: the position lookup snaps to
    // the border (1e-8 m), the index lookup refuses.
    let v = 0.5 + 1e-9;
    let mut direct = cp(Road::load(d.join("data.crg")).unwrap());
    let mut referenced = cp(Road::load(d.join("top.crg")).unwrap());
    for c in [&mut direct, &mut referenced] {
        c.set_option_int(opt::BORDER_MODE_V, 0).unwrap();
    }
    assert!(direct.uv_to_z(2.0, v).is_err());
    assert!((referenced.uv_to_z(2.0, v).unwrap() - 2.0).abs() < 1e-6);
}

#[test]
fn zero_width_v_range_reflects_to_the_point_itself() {
    // Only the increment is given: the v borders are both 0, and the reference's
    // reflection across an empty range gives back the point's own value.
    let mut c = cp(load_text(&lrfi(
        "REFERENCE_LINE_INCREMENT = 1.0\nLONG_SECTION_V_INCREMENT = 0.5\n",
        &NUMBERED,
        &rows(|_, j| j as f64),
    )));
    c.set_option_int(opt::BORDER_MODE_V, 4).unwrap();
    assert!((c.uv_to_z(2.0, 0.5).unwrap() - 1.0).abs() < 1e-6);
    assert!((c.uv_to_z(2.0, 0.75).unwrap() - 1.5).abs() < 1e-6);
}

#[test]
fn closed_track_data_stays_after_a_modifier_opens_the_line() {
    // Almost a circle: the heading turns by 0.97 of a full turn over 41 cross sections.
    let n = 41;
    let turn = 0.97 * 2.0 * std::f64::consts::PI;
    let channels = ["reference line phi,rad", NUMBERED[0], NUMBERED[1], NUMBERED[2]];
    let data: Vec<Vec<f64>> = (0..n).map(|i| vec![turn * i as f64 / (n - 1) as f64, 0.0, 0.0, 0.0]).collect();
    let mut road = load_text(&lrfi(
        &format!("REFERENCE_LINE_INCREMENT = 1.0\nLONG_SECTION_V_INCREMENT = 0.5\nREFERENCE_LINE_END_PHI = {turn}\n"),
        &channels,
        &data,
    ));
    let (closed, a, b) = road.closed_track_report();
    assert!(closed && b > a);
    road.modifiers_mut().clear();
    road.modifiers_mut().set_double(m::SCALE_CURVATURE, 0.5).unwrap();
    road.apply_modifiers();
    assert_eq!(road.closed_track(), None);
    assert_eq!(road.closed_track_report(), (false, a, b));
}

#[test]
fn relocation_center_z_snaps_to_a_missing_left_border() {
    // Sections at v = 0.25, 0.5, 0.75 with no LONG_SECTION_V_LEFT: the left border is 0,
    // so v = 0 snaps to it and the rotation center's z is read from the data (NaN here),
    // which the reference then adds to every elevation.
    let at = ["long section at v = 0.25,m", "long section at v = 0.5,m", "long section at v = 0.75,m"];
    let mut road = load_text(&lrfi(
        "REFERENCE_LINE_INCREMENT = 1.0\n",
        &at,
        &rows(|i, j| if i == 0 && j != 1 { f64::NAN } else { 0.0 }),
    ));
    road.modifiers_mut().clear();
    road.modifiers_mut().set_double(m::REFLINE_OFFSET_PHI, 0.5).unwrap();
    road.apply_modifiers();
    assert!(cp(road).uv_to_z(2.0, 0.5).unwrap().is_nan());
}

#[test]
fn v_lookup_bounds_come_from_the_header_range() {
    // Numbered sections (through a reference, so looked up by position) from -2.0 in
    // 0.01 m steps, while the header claims a left border at 5: the reference's search
    // table spans -2 .. 5 and bounds the search to the wrong interval.
    let d = dir("vtable");
    let header = "REFERENCE_LINE_INCREMENT = 1.0\nLONG_SECTION_V_RIGHT = -2.0\nLONG_SECTION_V_LEFT = 5.0\n";
    let seven = (1..=7).map(|i| format!("long section {i},m")).collect::<Vec<_>>();
    let seven: Vec<&str> = seven.iter().map(String::as_str).collect();
    let rows: Vec<Vec<f64>> = (0..5).map(|_| (0..7).map(|j| j as f64).collect()).collect();
    std::fs::write(d.join("data.crg"), lrfi(header, &seven, &rows)).unwrap();
    std::fs::write(d.join("top.crg"), "$ROAD_CRG_FILE\ndata.crg\n$\n").unwrap();
    let road = Road::load(d.join("top.crg")).unwrap();
    let g = road.grid();
    // v = -1.965 lies in interval 3 (-1.97 .. -1.96); the bounded search ends in interval 2.
    assert_eq!(g.v_interval(-1.965), 2);
    // A consistent header gives the true interval.
    std::fs::write(d.join("data.crg"), lrfi(&header.replace("5.0", "-1.94"), &seven, &rows)).unwrap();
    assert_eq!(Road::load(d.join("top.crg")).unwrap().grid().v_interval(-1.965), 3);
}
