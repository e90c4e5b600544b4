//! One road continuing another.

use super::resample;
use opencrg_core::budget::Budget;
use opencrg_core::draft::Draft;
use opencrg_core::Road;
use opencrg_core::{Error, Result};
use std::sync::Arc;

/// `second` continuing `first`: its reference line turned and moved so that it starts
/// at `first`'s end point with `first`'s end heading and elevation. Its first cross
/// section lies on `first`'s last, which the result keeps. When the increments or long
/// sections differ, `second` is resampled onto `first`'s (its nodes outside `first`'s v
/// range are NaN); roads whose v ranges do not overlap are refused, and a resampled
/// `second` beyond `budget`.
pub fn append(first: &Road, second: &Arc<Road>, budget: &Budget) -> Result<Road> {
    let a = Draft::of(first);
    let same_u = (a.u_inc - second.increments().0).abs() <= 1e-9 * a.u_inc;
    let same_v = a.v.len() == second.grid().v.len()
        && a.v.iter().zip(&second.grid().v).all(|(p, q)| (p - q).abs() <= 1e-9 * (1.0 + p.abs()));
    let b = if same_u && same_v {
        Draft::of(second)
    } else {
        let (right, left) = second.v_range();
        if right > a.v[a.nv() - 1] || left < a.v[0] {
            let overlap = right.max(a.v[0]) < left.min(a.v[a.nv() - 1]);
            if !overlap {
                return Err(Error::out_of_range(format!(
                    "the second road's long sections (v {right} to {left} m) do not overlap the first's (v {} to {} m)",
                    a.v[0],
                    a.v[a.nv() - 1]
                )));
            }
        }
        let request = format!("the second road resampled onto the first's grid (u increment {} m)", a.u_inc);
        resample::onto(second, a.u_inc, a.v.clone(), a.regular, &request, budget, &|_, _, _| {})?
    };
    let what = format!(
        "appended by opencrg {}: {} continued by {}",
        env!("CARGO_PKG_VERSION"),
        first.header().path.display(),
        second.header().path.display()
    );
    joined(a, b).into_road(&what)
}

/// `b` continuing `a` (both with the same u increment and long sections): `b`'s first step
/// turned from `a`'s last by the mean of the turns beside the joint (`a`'s last and `b`'s
/// first), so that the curvature runs on across it (a road cut in two and joined again
/// is the road it was).
fn joined(a: Draft, b: Draft) -> Draft {
    let (na, nb) = (a.nu(), b.nu());
    let step_turn = |phi: &[f64], i: usize| phi.get(i + 1).zip(phi.get(i)).map(|(p, q)| p - q);
    let beside = [na.checked_sub(2).and_then(|i| step_turn(&a.phi, i)), step_turn(&b.phi, 1)];
    let known: Vec<f64> = beside.into_iter().flatten().collect();
    let across = if known.is_empty() { 0.0 } else { known.iter().sum::<f64>() / known.len() as f64 };
    let turn = a.phi[na - 1] + across - b.phi[1];
    let mut phi = a.phi.clone();
    phi.extend(b.phi[1..].iter().map(|p| p + turn));
    let both = |x: &Option<Vec<f64>>, y: &Option<Vec<f64>>| -> Option<Vec<f64>> {
        if x.is_none() && y.is_none() {
            return None;
        }
        let mut out = x.clone().unwrap_or_else(|| vec![0.0; na]);
        match y {
            Some(y) => out.extend_from_slice(&y[1..]),
            None => out.extend(std::iter::repeat_n(0.0, nb - 1)),
        }
        Some(out)
    };
    let slope = both(&a.slope, &b.slope);
    let bank = both(&a.bank, &b.bank);
    let n = na + nb - 1;
    let mut z = Vec::with_capacity(n * a.nv());
    for iv in 0..a.nv() {
        z.extend_from_slice(&a.z[iv * na..(iv + 1) * na]);
        z.extend_from_slice(&b.z[iv * nb + 1..(iv + 1) * nb]);
    }
    Draft { phi, slope, bank, z, moved: true, ..a }
}
