//! Random client scripts: modifiers and options set through the API (every one, both
//! curvature modes, history settings), getters on every id, and query patterns:
//! a grid reaching past every border, random points inside, exact borders and grid
//! nodes, points far outside, and paths that carry the x/y search history along.

use crate::rng::Rng;
use opencrg_core::settings::{m, opt};
use std::fmt::Write as _;

/// Modifiers with values worth trying: (id, integer?, values).
const MODIFIERS: [(u32, bool, &[f64]); 24] = [
    (m::SCALE_Z, false, &[2.0, 0.5, -1.0, 0.0]),
    (m::SCALE_SLOPE, false, &[2.0, 0.0]),
    (m::SCALE_BANK, false, &[3.0, -1.0]),
    // Not below 0: the reference hangs in x/y to u/v on a road of negative length.
    (m::SCALE_LENGTH, false, &[2.0, 0.5]),
    // Not 0: crgCheck refuses it, and the reference answers NaN where the road has no width.
    (m::SCALE_WIDTH, false, &[1.5, 0.25]),
    (m::SCALE_CURVATURE, false, &[2.0, 0.5, -1.0, 0.0]),
    (m::GRID_NAN_MODE, true, &[0.0, 1.0, 2.0, 3.0]),
    (m::GRID_NAN_OFFSET, false, &[0.0, 0.1, -0.2]),
    (m::REFPOINT_V, false, &[0.0, 1.0, -0.5]),
    (m::REFPOINT_V_FRAC, false, &[0.0, 0.5, 1.0, 0.25]),
    (m::REFPOINT_V_OFFSET, false, &[0.0, -0.5]),
    (m::REFPOINT_U, false, &[0.0, 3.0, -1.0]),
    (m::REFPOINT_U_FRAC, false, &[0.0, 0.5, 1.0]),
    (m::REFPOINT_U_OFFSET, false, &[0.0, 1.0]),
    (m::REFPOINT_X, false, &[0.0, 100.0, -20.0]),
    (m::REFPOINT_Y, false, &[0.0, 50.0]),
    (m::REFPOINT_Z, false, &[0.0, 2.0]),
    (m::REFPOINT_PHI, false, &[0.0, 1.0, -2.5]),
    (m::REFLINE_OFFSET_X, false, &[0.0, 10.0]),
    (m::REFLINE_OFFSET_Y, false, &[0.0, -5.0]),
    (m::REFLINE_OFFSET_Z, false, &[0.0, 1.0]),
    (m::REFLINE_OFFSET_PHI, false, &[0.0, 0.5, 3.0]),
    (m::REFLINE_ROTCENTER_X, false, &[0.0, 5.0]),
    (m::REFLINE_ROTCENTER_Y, false, &[0.0, -3.0]),
];

/// Contact point options with values worth trying.
const OPTIONS: [(u32, bool, &[f64]); 17] = [
    (opt::BORDER_MODE_U, true, &[0.0, 1.0, 2.0, 3.0, 4.0]),
    (opt::BORDER_MODE_V, true, &[0.0, 1.0, 2.0, 3.0, 4.0]),
    (opt::CURV_MODE, true, &[0.0, 1.0]),
    (opt::BORDER_OFFSET_U, false, &[0.0, -0.5, 1.25]),
    (opt::BORDER_OFFSET_V, false, &[0.0, 0.3, -2.0]),
    (opt::SMOOTH_U_BEGIN, false, &[0.5, 2.0, 100.0]),
    (opt::SMOOTH_U_END, false, &[1.0, 3.0]),
    (opt::REFLINE_SEARCH_U, false, &[0.0, 5.0, -3.0]),
    (opt::REFLINE_SEARCH_U_FRAC, false, &[0.0, 0.5, 1.0]),
    (opt::REFLINE_CLOSE, false, &[0.3, 0.05, 3.0]),
    (opt::REFLINE_FAR, false, &[1.5, 0.2, 20.0]),
    (opt::REFLINE_CONTINUE, true, &[0.0, 1.0]),
    (opt::WARN_MSGS, true, &[-1.0, 0.0, 5.0]),
    (opt::CHECK_EPS, false, &[1e-6, 1e-3]),
    (opt::CHECK_INC, false, &[1e-3, 0.5]),
    (opt::CHECK_TOL, false, &[1e-4, 0.3]),
    (opt::WARN_CURV_GLOBAL, true, &[1.0, 0.0]),
];

/// One random script for the road in `road.crg`.
pub fn generate(rng: &mut Rng) -> String {
    let mut s = String::from("load road.crg\ninfo\n");
    if rng.chance(0.9) {
        line(&mut s, "check".into());
    }
    // Getters before anything is set: the file's modifiers and the defaults.
    for id in [m::GRID_NAN_MODE, m::REFPOINT_X, m::SCALE_Z, rng.int(20, 46) as u32] {
        line(&mut s, format!("modgi {id}"));
        line(&mut s, format!("modgd {id}"));
    }
    if rng.chance(0.5) {
        modifiers(rng, &mut s);
    }
    for id in [m::GRID_NAN_MODE, m::REFPOINT_V, m::REFPOINT_V_FRAC, m::REFPOINT_U_FRAC] {
        line(&mut s, format!("modgi {id}"));
        line(&mut s, format!("modgd {id}"));
    }
    match rng.int(0, 19) {
        0 => {}
        1 => {
            line(&mut s, "apply".into());
            line(&mut s, "apply".into());
        }
        _ => line(&mut s, "apply".into()),
    }
    line(&mut s, "info".into());
    line(&mut s, "cp".into());
    if rng.chance(0.1) {
        line(&mut s, "cpdef".into());
    }
    for (id, int, values) in OPTIONS {
        if rng.chance(0.15) {
            let v = rng.pick(values);
            line(&mut s, if int { format!("opti {id} {v}") } else { format!("optd {id} {v:?}") });
        }
    }
    if rng.chance(0.2) {
        line(&mut s, format!("hist {}", rng.pick(&[0, 1, 2, 5, 50])));
    }
    for id in [opt::BORDER_MODE_U, opt::BORDER_MODE_V, opt::CURV_MODE, opt::REFLINE_FAR, rng.int(0, 20) as u32] {
        line(&mut s, format!("optgi {id}"));
        line(&mut s, format!("optgd {id}"));
    }

    queries(rng, &mut s);
    let _ = writeln!(s, "cpdel");
    s
}

/// Appends one line to a script.
fn line(s: &mut String, text: String) {
    s.push_str(&text);
    s.push('\n');
}

/// Modifiers removed or set to their defaults, then some set (the reference point's or
/// the offsets' group mostly, not both).
fn modifiers(rng: &mut Rng, s: &mut String) {
    line(s, if rng.chance(0.8) { "modrm".into() } else { "modsetdef".into() });
    let by_refpoint = rng.chance(0.5);
    for (id, int, values) in MODIFIERS {
        let relocation = (m::REFPOINT_V..=m::REFLINE_ROTCENTER_Y).contains(&id);
        let refpoint_group = (m::REFPOINT_V..=m::REFPOINT_PHI).contains(&id);
        let p = if !relocation {
            0.2
        } else if refpoint_group == by_refpoint {
            0.35
        } else {
            0.03
        };
        if rng.chance(p) {
            let v = rng.pick(values);
            line(s, if int { format!("modi {id} {v}") } else { format!("modd {id} {v:?}") });
        }
    }
    if rng.chance(0.05) {
        line(s, format!("modi {} 1", m::SCALE_Z));
        line(s, format!("modd {} 1.0", m::GRID_NAN_MODE));
    }
    if rng.chance(0.5) {
        line(s, "check".into());
    }
}

/// The queries: a grid past every border, the exact borders and corners, random points on
/// and off the road, far outside, and paths.
fn queries(rng: &mut Rng, s: &mut String) {
    // A grid reaching 30 % of the length and 40 % of the width past every border.
    let (nu, nv) = (rng.int(4, 12), rng.int(3, 8));
    for a in 0..=nu {
        for b in 0..=nv {
            let fu = -0.3 + 1.6 * a as f64 / nu as f64;
            let fv = -0.4 + 1.8 * b as f64 / nv as f64;
            line(s, format!("qf {fu:?} {fv:?}"));
        }
    }
    // Exact borders and corners.
    for fu in [0.0, 1.0, 0.5] {
        for fv in [0.0, 1.0, 0.5] {
            line(s, format!("qf {fu:?} {fv:?}"));
        }
    }
    // Random points inside, and off the road in x/y.
    for _ in 0..rng.int(5, 25) {
        let (fu, fv) = (rng.unit(), rng.unit());
        line(s, format!("qf {fu:?} {fv:?}"));
    }
    for _ in 0..rng.int(2, 8) {
        let (fu, fv) = (rng.range(-0.2, 1.2), rng.range(-0.2, 1.2));
        let (dx, dy) = (rng.range(-3.0, 3.0), rng.range(-3.0, 3.0));
        line(s, format!("qo {fu:?} {fv:?} {dx:?} {dy:?}"));
    }
    // Far outside.
    for _ in 0..rng.int(1, 4) {
        let (fu, fv) = (rng.pick(&[-10.0, 11.0, 0.5]), rng.pick(&[-30.0, 31.0, 0.5]));
        line(s, format!("qf {fu:?} {fv:?}"));
        let (x, y) = (rng.range(-1e4, 1e4), rng.range(-1e4, 1e4));
        line(s, format!("xy {x:?} {y:?}"));
    }
    // Paths: small steps along u with a slowly changing v, forwards or backwards; some
    // so small that many steps fall in one grid cell (a wheel at walking pace).
    for _ in 0..rng.int(1, 3) {
        let steps = rng.int(10, 60);
        let (mut fu, fv0) = (rng.range(-0.1, 1.1), rng.range(-0.2, 1.2));
        let reach = if rng.chance(0.5) { 0.05 } else { 0.002 };
        let du = rng.range(-reach, reach);
        for k in 0..steps {
            let fv = fv0 + 0.1 * (k as f64 * 0.2).sin();
            line(s, format!("qf {fu:?} {fv:?}"));
            fu += du;
        }
    }
    if rng.chance(0.1) {
        line(s, "optrmall".into());
        line(s, "qf 0.5 0.5".into());
        line(s, "qf 1.2 -0.2".into());
    }
}
