//! The surface on a new grid, each node evaluated by the library.

use super::nodes::{at_nodes, Progress, SurfaceProbe};
use super::path::{arc_walk, Curve};
use opencrg_core::budget::{filled, Budget};
use opencrg_core::draft::{headings_through, slopes_for, Draft};
use opencrg_core::units::Num;
use opencrg_core::Road;
use opencrg_core::{Error, Result};
use std::sync::Arc;

/// `road`'s surface on a grid of cross sections `u_inc` apart and long sections `v_inc`
/// apart (each the road's own when `None`). The new cross sections keep the old u range:
/// they start at the road's start, and the last lies at its end where `u_inc` divides the
/// length, within one increment of it otherwise; each lies on a smooth curve through the
/// old reference line's points (within its chord's shortfall where the curve bends between
/// two of them, see `arc_walk`); each node's z is the old surface at the node's x/y.
/// Refused: an increment that is not a positive number, a grid beyond `budget`.
pub fn resample(road: &Arc<Road>, u_inc: Option<f64>, v_inc: Option<f64>, budget: &Budget) -> Result<Road> {
    let du = u_inc.unwrap_or(road.increments().0);
    let (right, left) = road.v_range();
    let request = format!(
        "resampling with a u increment of {} m and {}",
        Num(du),
        v_inc.map_or("the road's long sections".to_string(), |dv| format!("a v increment of {} m", Num(dv)))
    );
    let (v, regular) = match v_inc {
        None => (road.grid().v.clone(), road.grid().layout == opencrg_core::grid::VLayout::Indexed),
        Some(dv) => {
            let n = position_count(right, left, dv, "v increment")?;
            let (u_first, u_last) = road.u_range();
            budget.admit_road(&request, cross_sections(u_last - u_first, du)?, n, 0.0)?;
            (positions(right, dv, n as usize)?, true)
        }
    };
    let what = format!("resampled by opencrg {}: u increment {du} m, v increment {}", env!("CARGO_PKG_VERSION"), {
        v_inc.map_or("as before".to_string(), |dv| format!("{dv} m"))
    });
    onto(road, du, v, regular, &request, budget, &|_, _, _| {})?.into_road(&what)
}

/// How many cross sections `du` apart a line `length` long holds (as a float: any count).
pub(crate) fn cross_sections(length: f64, du: f64) -> Result<f64> {
    if !(du > 0.0 && du.is_finite()) {
        return Err(Error::out_of_range(format!("u increment {} m must be a positive number", Num(du))));
    }
    Ok((length / du + 1e-9).floor() + 1.0)
}

/// How many positions `inc` apart fit from `first` to `last` (as a float: any count,
/// sized before anything is made); refused: an increment that is not a positive number,
/// fewer than two positions.
pub(crate) fn position_count(first: f64, last: f64, inc: f64, what: &str) -> Result<f64> {
    if !(inc > 0.0 && inc.is_finite()) {
        return Err(Error::out_of_range(format!("{what} {} m must be a positive number", Num(inc))));
    }
    let n = ((last - first) / inc + 1e-9).floor() + 1.0;
    if !(n >= 2.0) {
        return Err(Error::out_of_range(format!(
            "a {what} of {} m leaves fewer than two nodes in {first} to {last} m",
            Num(inc)
        )));
    }
    Ok(n)
}

/// `n` positions `inc` apart from `first`. Refused: memory the system does not give.
pub(crate) fn positions(first: f64, inc: f64, n: usize) -> Result<Vec<f64>> {
    let mut p = filled(n, first, "the long sections")?;
    for (i, x) in p.iter_mut().enumerate() {
        *x += i as f64 * inc;
    }
    Ok(p)
}

/// `road`'s surface as a draft with cross sections `du` apart and long sections at `v`,
/// sized against `budget` first (`request` says what was asked, for a refusal).
pub(crate) fn onto(
    road: &Arc<Road>,
    du: f64,
    v: Vec<f64>,
    regular: bool,
    request: &str,
    budget: &Budget,
    progress: Progress,
) -> Result<Draft> {
    let line = road.reference_line();
    budget.admit_road(&request, cross_sections(line.u_last - line.u_first, du)?, v.len() as f64, 0.0)?;
    let old = Draft::line_of(road);
    let count = cross_sections(line.u_last - line.u_first, du)? as usize;
    // The new line follows a smooth curve through the old line's points (its parameter,
    // the length along the old line, is u): finer cross sections bend gently between
    // the old ones instead of turning each old corner in one step.
    let curve = Curve::through(&line.x, &line.y, None)
        .map_err(|i| Error::out_of_range(format!("the reference line's points {} and {i} coincide", i - 1)))?;
    let stops = arc_walk(line.u_first, du, count, |u| curve.at(u - line.u_first))?;
    if stops.len() < 2 {
        return Err(Error::out_of_range(format!(
            "a u increment of {du} m leaves fewer than two cross sections on a road {} m long",
            line.u_last - line.u_first
        )));
    }
    let phi = headings_through(&stops.iter().map(|s| (s.x, s.y)).collect::<Vec<_>>());
    let old_z = old.line_z();
    let lerp = |values: &dyn Fn(usize) -> f64, u: f64| {
        let f = ((u - old.u_first) / old.u_inc).clamp(0.0, (old.nu() - 1) as f64);
        let i = (f.floor() as usize).min(old.nu() - 2);
        let w = f - i as f64;
        values(i) * (1.0 - w) + values(i + 1) * w
    };
    let line_z: Vec<f64> = stops.iter().map(|s| lerp(&|i| old_z[i], s.t)).collect();
    let slope = old.slope.as_ref().map(|_| slopes_for(&line_z, du));
    let bank = old.bank.as_ref().map(|b| stops.iter().map(|s| lerp(&|i| b[i], s.t)).collect());
    let mut new = Draft {
        u_first: old.u_first,
        u_inc: du,
        start: (stops[0].x, stops[0].y),
        z_start: line_z[0],
        phi,
        slope,
        bank,
        regular,
        bank_v: (v[0], v[v.len() - 1]),
        moved: true,
        ..old
    };
    let frame = Arc::new(new.frame(v[0], v[v.len() - 1])?);
    let z_line = new.line_z();
    let shape = &new;
    let z = at_nodes(
        &frame,
        &v,
        || SurfaceProbe::new(road),
        |probe, node| match probe.at(node.x, node.y) {
            Some((z, _, _)) => (z - z_line[node.iu] - shape.bank_term(node.iu, node.v)) as f32,
            None => f32::NAN,
        },
        progress,
    )?;
    new.z = z;
    new.v = v;
    Ok(new)
}
