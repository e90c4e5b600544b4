//! Every option and modifier on roads the tests generate, against values worked out
//! by hand: a straight road with a planar surface, a circle, a banked and sloped road.

use opencrg_core::settings::{m, opt};
use opencrg_core::synth::RoadSpec;
use opencrg_core::{ContactPoint, Road};
use std::f64::consts::PI;
use std::sync::Arc;

/// Grid values are single precision: compare with that tolerance.
const TOL: f64 = 1e-6;

fn near(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

macro_rules! assert_near {
    ($a:expr, $b:expr) => {
        assert_near!($a, $b, TOL)
    };
    ($a:expr, $b:expr, $tol:expr) => {{
        let (a, b) = ($a, $b);
        assert!(near(a, b, $tol), "{} = {a}, expected {b}", stringify!($a));
    }};
}

/// 10 m long, v from -1 to 1, 0.5 m grid, z = 0.1 u + 0.2 v, straight along x.
fn plane() -> Road {
    RoadSpec::straight(10.0, 2.0, 0.5, 0.5).with_elevation(|u, v| 0.1 * u + 0.2 * v).build().unwrap()
}

fn cp(road: Road) -> ContactPoint {
    ContactPoint::new(Arc::new(road))
}

fn with(road: Road, options: &[(u32, f64)]) -> ContactPoint {
    let mut c = cp(road);
    for &(id, value) in options {
        match opencrg_core::settings::describe(id).unwrap().1 {
            opencrg_core::settings::Kind::Int => c.set_option_int(id, value as i32).unwrap(),
            opencrg_core::settings::Kind::Double => c.set_option_double(id, value).unwrap(),
        }
    }
    c
}

#[test]
fn straight_road_inside() {
    let mut c = cp(plane());
    assert_eq!(c.uv_to_xy(3.0, 0.5).unwrap(), (3.0, 0.5));
    let (u, v) = c.xy_to_uv(3.0, 0.5).unwrap();
    assert_near!(u, 3.0, 1e-12);
    assert_near!(v, 0.5, 1e-12);
    assert_near!(c.uv_to_z(3.0, 0.5).unwrap(), 0.4);
    assert_near!(c.uv_to_z(7.3, -0.9).unwrap(), 0.73 - 0.18);
    assert_near!(c.xy_to_z(7.3, -0.9).unwrap(), 0.73 - 0.18);
    assert_eq!(c.uv_to_pk(5.0, 0.0).unwrap(), (0.0, 0.0));
    // Before the start and past the end the line continues straight.
    assert_eq!(c.uv_to_xy(-2.0, 1.0).unwrap(), (-2.0, 1.0));
    assert_eq!(c.uv_to_xy(12.0, -1.0).unwrap(), (12.0, -1.0));
    let (u, v) = c.xy_to_uv(13.0, 0.25).unwrap();
    assert_near!(u, 13.0, 1e-12);
    assert_near!(v, 0.25, 1e-12);
    assert!(c.uv_to_z(f64::NAN, 0.0).is_err());
}

#[test]
fn border_modes_in_u() {
    // keep last (default), with and without offset
    assert_near!(cp(plane()).uv_to_z(12.0, 0.0).unwrap(), 1.0);
    assert_near!(cp(plane()).uv_to_z(-3.0, 0.5).unwrap(), 0.1);
    assert_near!(with(plane(), &[(opt::BORDER_OFFSET_U, 0.5)]).uv_to_z(12.0, 0.0).unwrap(), 1.5);
    // none refuses
    assert!(with(plane(), &[(opt::BORDER_MODE_U, 0.0)]).uv_to_z(12.0, 0.0).is_err());
    assert!(with(plane(), &[(opt::BORDER_MODE_U, 0.0)]).uv_to_z(5.0, 0.0).is_ok());
    // zero: the offset only
    assert_near!(with(plane(), &[(opt::BORDER_MODE_U, 1.0)]).uv_to_z(12.0, 0.5).unwrap(), 0.0);
    assert_near!(
        with(plane(), &[(opt::BORDER_MODE_U, 1.0), (opt::BORDER_OFFSET_U, -0.25)]).uv_to_z(-1.0, 0.5).unwrap(),
        -0.25
    );
    // repeat: u = 12 is u = 2 of the next period
    assert_near!(with(plane(), &[(opt::BORDER_MODE_U, 3.0)]).uv_to_z(12.0, 0.0).unwrap(), 0.2);
    assert_near!(with(plane(), &[(opt::BORDER_MODE_U, 3.0)]).uv_to_z(-3.0, 0.0).unwrap(), 0.7);
    // reflect: u = 12 mirrors to u = 8
    assert_near!(with(plane(), &[(opt::BORDER_MODE_U, 4.0)]).uv_to_z(12.0, 0.0).unwrap(), 0.8);
}

#[test]
fn border_modes_in_v() {
    assert_near!(cp(plane()).uv_to_z(5.0, 3.0).unwrap(), 0.7);
    assert_near!(with(plane(), &[(opt::BORDER_OFFSET_V, 1.0)]).uv_to_z(5.0, -3.0).unwrap(), 0.3 + 1.0);
    assert!(with(plane(), &[(opt::BORDER_MODE_V, 0.0)]).uv_to_z(5.0, 1.5).is_err());
    assert_near!(with(plane(), &[(opt::BORDER_MODE_V, 1.0)]).uv_to_z(5.0, 1.5).unwrap(), 0.0);
    // repeat: v = 1.5 lies 0.5 into the next period from v = -1
    assert_near!(with(plane(), &[(opt::BORDER_MODE_V, 3.0)]).uv_to_z(5.0, 1.5).unwrap(), 0.5 - 0.1);
    // reflect: v = 1.5 mirrors at v = 1 to v = 0.5
    assert_near!(with(plane(), &[(opt::BORDER_MODE_V, 4.0)]).uv_to_z(5.0, 1.5).unwrap(), 0.5 + 0.1);
}

#[test]
fn smoothing_zones() {
    let begin = with(plane(), &[(opt::SMOOTH_U_BEGIN, 2.0)]);
    assert_near!(begin.uv_to_z(1.0, 0.5).unwrap(), (0.1 + 0.1) * 0.5);
    assert_near!(begin.uv_to_z(0.0, 0.5).unwrap(), 0.0);
    assert_near!(begin.uv_to_z(5.0, 0.5).unwrap(), 0.6);
    let end = with(plane(), &[(opt::SMOOTH_U_END, 2.0)]);
    assert_near!(end.uv_to_z(9.0, 0.0).unwrap(), 0.9 * 0.5);
    assert_near!(end.uv_to_z(12.0, 0.0).unwrap(), 0.0);
}

/// A circle of radius 20 m: heading u / 20, one full turn.
fn circle() -> Road {
    let r = 20.0;
    RoadSpec::straight(2.0 * PI * r, 3.0, 0.1, 0.5).with_heading(move |u| u / r).build().unwrap()
}

#[test]
fn circle_heading_curvature_and_search() {
    let mut c = cp(circle());
    let (phi, curv) = c.uv_to_pk(30.05, 0.0).unwrap();
    assert_near!(phi, 30.1 / 20.0, 1e-9);
    assert_near!(curv, 1.0 / 20.0, 1e-4);
    // lateral curvature: the parallel 2 m to the left has radius 18 m
    assert_near!(c.uv_to_pk(30.05, 2.0).unwrap().1, 1.0 / 18.0, 1e-4);
    let mut reference_line = with(circle(), &[(opt::CURV_MODE, 1.0)]);
    assert_near!(reference_line.uv_to_pk(30.05, 2.0).unwrap().1, 1.0 / 20.0, 1e-4);
    // x/y round trips, with and without history
    for &(u, v) in &[(5.0, 1.0), (40.0, -1.2), (100.0, 0.3), (120.0, 0.0)] {
        let (x, y) = c.uv_to_xy(u, v).unwrap();
        let (u2, v2) = c.xy_to_uv(x, y).unwrap();
        assert_near!(u2, u, 1e-9);
        assert_near!(v2, v, 1e-9);
        let (u3, _) = reference_line.xy_to_uv(x, y).unwrap();
        assert_near!(u3, u, 1e-9);
    }
    // the circle's points lie 20 m from its center (0, 20), up to the Euler steps' error
    let (x, y) = c.uv_to_xy(31.4, 0.0).unwrap();
    assert_near!((x * x + (y - 20.0) * (y - 20.0)).sqrt(), 20.0, 0.1);
    // 95 % of a circle leaves a gap that the track can be closed over; closing the
    // track maps u past the end back to the start
    let r = 20.0;
    let arc = || RoadSpec::straight(0.95 * 2.0 * PI * r, 3.0, 0.1, 0.5).with_heading(move |u| u / r).build().unwrap();
    let (cmin, cmax) = arc().closed_track().expect("the arc can be closed");
    assert!(cmin < 0.0 && cmax > 0.95 * 2.0 * PI * r, "the closing range reaches past both ends");
    let closed = with(arc(), &[(opt::REFLINE_CONTINUE, 1.0)]);
    let (cmin, cmax) = closed.road().closed_track().unwrap();
    let period = cmax - cmin;
    let (a, b) = (closed.uv_to_xy(10.0 + period, 0.5).unwrap(), closed.uv_to_xy(10.0, 0.5).unwrap());
    assert_near!(a.0, b.0, 1e-9);
    assert_near!(a.1, b.1, 1e-9);
}

#[test]
fn search_history_options() {
    let mut c = cp(circle());
    c.set_history(3).unwrap();
    c.set_option_double(opt::REFLINE_SEARCH_U, 60.0).unwrap();
    let (x, y) = c.uv_to_xy(61.0, 0.5).unwrap();
    let (u, _) = c.xy_to_uv(x, y).unwrap();
    assert_near!(u, 61.0, 1e-9);
    c.set_option_double(opt::REFLINE_SEARCH_U_FRAC, 0.5).unwrap();
    c.set_option_double(opt::REFLINE_CLOSE, 0.5).unwrap();
    c.set_option_double(opt::REFLINE_FAR, 3.0).unwrap();
    let (u, _) = c.xy_to_uv(x, y).unwrap();
    assert_near!(u, 61.0, 1e-9);
    c.reset_options();
    assert_eq!(c.options().get_double(opt::REFLINE_FAR), Some(2.2));
}

/// Straight, slope 0.1, banking 0.05, flat grid plus 0.01 u.
fn banked_sloped() -> Road {
    RoadSpec::straight(10.0, 2.0, 0.5, 0.5)
        .with_slope(|_| 0.1)
        .with_bank(|_| 0.05)
        .with_elevation(|u, _| 0.01 * u)
        .build()
        .unwrap()
}

#[test]
fn slope_and_banking() {
    let c = cp(banked_sloped());
    assert_near!(c.uv_to_z(4.0, 1.0).unwrap(), 0.4 + 0.05 + 0.04);
    assert_near!(c.uv_to_z(4.0, -1.0).unwrap(), 0.4 - 0.05 + 0.04);
    // outside in v the banking stays that of the border
    assert_near!(c.uv_to_z(4.0, 3.0).unwrap(), 0.4 + 0.05 + 0.04);
    // smoothing blends towards the reference line's z at the start
    let s = with(banked_sloped(), &[(opt::SMOOTH_U_BEGIN, 2.0)]);
    assert_near!(s.uv_to_z(1.0, 0.0).unwrap(), (0.1 + 0.01) * 0.5);
}

fn applied(mut road: Road, mods: &[(u32, f64)]) -> ContactPoint {
    road.modifiers_mut().clear();
    for &(id, value) in mods {
        if id == m::GRID_NAN_MODE {
            road.modifiers_mut().set_int(id, value as i32).unwrap();
        } else {
            road.modifiers_mut().set_double(id, value).unwrap();
        }
    }
    road.check().unwrap();
    road.apply_modifiers();
    cp(road)
}

#[test]
fn scaling_modifiers() {
    assert_near!(applied(banked_sloped(), &[(m::SCALE_SLOPE, 2.0)]).uv_to_z(4.0, 0.0).unwrap(), 0.8 + 0.04);
    assert_near!(applied(banked_sloped(), &[(m::SCALE_BANK, 2.0)]).uv_to_z(4.0, 1.0).unwrap(), 0.4 + 0.1 + 0.04);
    assert_near!(applied(banked_sloped(), &[(m::SCALE_Z, 3.0)]).uv_to_z(4.0, 0.0).unwrap(), 0.4 + 0.12);
    let long = applied(plane(), &[(m::SCALE_LENGTH, 2.0)]);
    assert_eq!(long.road().u_range(), (0.0, 20.0));
    assert_near!(long.uv_to_z(8.0, 0.0).unwrap(), 0.4);
    let wide = applied(plane(), &[(m::SCALE_WIDTH, 2.0)]);
    assert_eq!(wide.road().v_range(), (-2.0, 2.0));
    assert_near!(wide.uv_to_z(0.0, 2.0).unwrap(), 0.2);
    let curved = applied(circle(), &[(m::SCALE_CURVATURE, 0.0)]);
    assert_near!(curved.uv_to_pk(30.05, 0.0).unwrap().1, 0.0, 1e-12);
}

#[test]
fn relocation_modifiers() {
    let by_point = applied(
        plane(),
        &[(m::REFPOINT_V, 0.0), (m::REFPOINT_X, 100.0), (m::REFPOINT_Y, 50.0), (m::REFPOINT_PHI, PI / 2.0)],
    );
    let (x, y) = by_point.uv_to_xy(0.0, 0.0).unwrap();
    assert_near!(x, 100.0, 1e-9);
    assert_near!(y, 50.0, 1e-9);
    let (x, y) = by_point.uv_to_xy(1.0, 0.0).unwrap();
    assert_near!(x, 100.0, 1e-9);
    assert_near!(y, 51.0, 1e-9);
    // the reference point at the middle of the road, lifted to z = 10 (without
    // REFPOINT_V the point would be at the right border: REFPOINT_V_FRACTION 0)
    let mid = applied(plane(), &[(m::REFPOINT_U_FRAC, 0.5), (m::REFPOINT_V, 0.0), (m::REFPOINT_Z, 10.0)]);
    let (x, y) = mid.uv_to_xy(5.0, 0.0).unwrap();
    assert_near!(x, 0.0, 1e-9);
    assert_near!(y, 0.0, 1e-9);
    assert_near!(mid.uv_to_z(5.0, 0.0).unwrap(), 10.0);
    // by offset: rotate 90 degrees about the start, then shift
    let shifted =
        applied(plane(), &[(m::REFLINE_OFFSET_PHI, PI / 2.0), (m::REFLINE_OFFSET_X, 10.0), (m::REFLINE_OFFSET_Z, 2.0)]);
    let (x, y) = shifted.uv_to_xy(3.0, 0.0).unwrap();
    assert_near!(x, 10.0, 1e-9);
    assert_near!(y, 3.0, 1e-9);
    assert_near!(shifted.uv_to_z(3.0, 0.0).unwrap(), 2.3);
    // both ways at once are refused by the check
    let mut both = plane();
    both.modifiers_mut().set_double(m::REFLINE_OFFSET_X, 1.0).unwrap();
    assert!(both.check().is_err());
}

#[test]
fn nan_modifiers() {
    let holes = || {
        RoadSpec::straight(4.0, 2.0, 1.0, 0.5)
            .with_elevation(|u, v| if v > 0.6 || (u < 0.5 && v < -0.6) { f64::NAN } else { 1.0 + v })
            .build()
            .unwrap()
    };
    let keep = applied(holes(), &[(m::GRID_NAN_MODE, 0.0)]);
    assert!(keep.uv_to_z(2.0, 1.0).unwrap().is_nan());
    let last = applied(holes(), &[(m::GRID_NAN_MODE, 2.0)]);
    assert_near!(last.uv_to_z(2.0, 1.0).unwrap(), 1.5);
    assert_near!(last.uv_to_z(0.0, -1.0).unwrap(), 0.5);
    let zero = applied(holes(), &[(m::GRID_NAN_MODE, 1.0), (m::GRID_NAN_OFFSET, 0.25)]);
    assert_near!(zero.uv_to_z(2.0, 1.0).unwrap(), 0.25);
}

/// The common-case elevation (what the C entry point tries first) answers exactly
/// where no option matters, with the general answer bit for bit, and nowhere else.
#[test]
fn plain_elevation_matches_the_general_one() {
    let mut plain = 0;
    for smoothing in [false, true] {
        let mut c = cp(banked_sloped());
        if smoothing {
            c.set_option_double(opt::SMOOTH_U_BEGIN, 2.0).unwrap();
        }
        let (u0, u1) = c.road().u_range();
        let (v0, v1) = c.road().v_range();
        for i in -20..=220 {
            for j in -20..=120 {
                let (u, v) = (u0 + (u1 - u0) * f64::from(i) / 200.0, v0 + (v1 - v0) * f64::from(j) / 100.0);
                // The last cross and long section are left to the general path.
                let inside = (u0..=u1).contains(&u) && (v0..=v1).contains(&v);
                let before_last = u < u1 && v < v1;
                match c.uv_to_z_plain(u, v) {
                    Some(z) => {
                        assert!(inside && !smoothing, "answered at ({u}, {v}), smoothing {smoothing}");
                        assert_eq!(z.to_bits(), c.uv_to_z(u, v).unwrap().to_bits(), "at ({u}, {v})");
                        plain += 1;
                    }
                    None => assert!(!(inside && before_last) || smoothing, "no answer inside at ({u}, {v})"),
                }
            }
        }
    }
    assert!(plain > 10_000, "{plain} plain answers");
    assert_eq!(cp(plane()).uv_to_z_plain(f64::NAN, 0.0), None);
}
