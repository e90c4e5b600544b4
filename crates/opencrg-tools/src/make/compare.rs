//! How far two roads' surfaces are apart.

use super::nodes::{at_nodes, Progress, SurfaceProbe};
use opencrg_core::Result;
use opencrg_core::Road;
use std::sync::Arc;

/// The differences between two surfaces at the grid nodes of the first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Comparison {
    /// Nodes of the first road with an elevation on both surfaces.
    pub compared: usize,
    /// Nodes of the first road with an elevation where the second has none (outside it
    /// or NaN).
    pub only_first: usize,
    /// The largest |z_second - z_first| over the compared nodes (0 when none).
    pub max_difference: f64,
    /// Where it is: the first road's u, v and x, y (NaN when nothing was compared).
    pub at: [f64; 4],
    /// The signed difference there, z_second - z_first.
    pub signed: f64,
    /// The root mean square of the differences.
    pub rms: f64,
}

/// The second surface against the first at the first's grid nodes: each node's z on
/// the first road and the second's z at the same x/y, both as the library evaluates
/// them (the second found by its own x/y search). Refused: memory the system does not
/// give for the first road's nodes.
pub fn compare(first: &Arc<Road>, second: &Arc<Road>, progress: Progress) -> Result<Comparison> {
    let v = first.grid().v.clone();
    let probes = || (opencrg_core::ContactPoint::new(first.clone()), SurfaceProbe::new(second));
    // Each node's difference; +inf where only the first has a value, NaN where it has none.
    let diff = at_nodes(
        first,
        &v,
        probes,
        |(a, b), node| {
            let Ok(za) = a.uv_to_z(node.u, node.v) else { return f32::NAN };
            if za.is_nan() {
                return f32::NAN;
            }
            match b.at(node.x, node.y) {
                Some((zb, _, _)) if !zb.is_nan() => (zb - za) as f32,
                _ => f32::INFINITY,
            }
        },
        progress,
    )?;
    let nu = first.reference_line().n;
    let mut c =
        Comparison { compared: 0, only_first: 0, max_difference: 0.0, at: [f64::NAN; 4], signed: 0.0, rms: 0.0 };
    let mut worst = None;
    let mut sum2 = 0.0;
    for (k, &d) in diff.iter().enumerate() {
        if d.is_nan() {
            continue;
        }
        if d.is_infinite() {
            c.only_first += 1;
            continue;
        }
        c.compared += 1;
        let d = f64::from(d);
        sum2 += d * d;
        if d.abs() > c.max_difference || worst.is_none() {
            c.max_difference = d.abs();
            c.signed = d;
            worst = Some(k);
        }
    }
    if let Some(k) = worst {
        let (iu, iv) = (k % nu, k / nu);
        let u = first.reference_line().u_at(iu);
        let (x, y) = opencrg_core::ContactPoint::new(first.clone()).uv_to_xy(u, v[iv]).unwrap_or((f64::NAN, f64::NAN));
        c.at = [u, v[iv], x, y];
        c.rms = (sum2 / c.compared as f64).sqrt();
    }
    Ok(c)
}
