//! The surface on a new grid, each node evaluated by the library.

use super::draft::{headings_through, slopes_for, Draft};
use super::nodes::{at_nodes, Progress, SurfaceProbe};
use super::path::chord_walk;
use crate::error::{Error, Result};
use crate::road::Road;
use std::sync::Arc;

/// `road`'s surface on a grid of cross sections `u_inc` apart and long sections `v_inc`
/// apart (each the road's own when `None`). The new reference line's points lie on the
/// old one, exactly `u_inc` apart; each node's z is the old surface at the node's x/y.
pub fn resample(road: &Arc<Road>, u_inc: Option<f64>, v_inc: Option<f64>) -> Result<Road> {
    let du = u_inc.unwrap_or(road.increments().0);
    let (right, left) = road.v_range();
    let (v, regular) = match v_inc {
        None => (road.grid().v.clone(), road.grid().layout == crate::grid::VLayout::Indexed),
        Some(dv) => (positions(right, left, dv)?, true),
    };
    let what = format!("resampled by opencrg {}: u increment {du} m, v increment {}", env!("CARGO_PKG_VERSION"), {
        v_inc.map_or("as before".to_string(), |dv| format!("{dv} m"))
    });
    onto(road, du, v, regular, &|_, _, _| {})?.into_road(&what)
}

/// Evenly spaced positions from `first` to at most `last`.
pub(crate) fn positions(first: f64, last: f64, inc: f64) -> Result<Vec<f64>> {
    if !(inc > 0.0 && inc.is_finite()) {
        return Err(Error::Request(format!("increment {inc} must be a positive number")));
    }
    let n = ((last - first) / inc + 1e-9).floor() as usize + 1;
    if n < 2 {
        return Err(Error::Request(format!(
            "an increment of {inc} m leaves fewer than two nodes in {first} to {last} m"
        )));
    }
    Ok((0..n).map(|i| first + i as f64 * inc).collect())
}

/// `road`'s surface as a draft with cross sections `du` apart and long sections at `v`.
pub(crate) fn onto(road: &Arc<Road>, du: f64, v: Vec<f64>, regular: bool, progress: Progress) -> Result<Draft> {
    if !(du > 0.0 && du.is_finite()) {
        return Err(Error::Request(format!("u increment {du} must be a positive number")));
    }
    let old = Draft::line_of(road);
    let line = road.reference_line();
    let u_old: Vec<f64> = (0..line.n).map(|i| line.u_at(i)).collect();
    let stops = chord_walk(&line.x, &line.y, &u_old, du);
    if stops.len() < 2 {
        return Err(Error::Request(format!(
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
    );
    new.z = z;
    new.v = v;
    Ok(new)
}
