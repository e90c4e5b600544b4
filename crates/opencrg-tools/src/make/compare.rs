//! How far two roads' surfaces are apart.

use super::nodes::{rows_of_nodes, Node, Progress, SurfaceProbe};
use opencrg_core::budget::filled;
use opencrg_core::Result;
use opencrg_core::Road;
use std::sync::atomic::{AtomicUsize, Ordering};
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
/// them (the second found by its own x/y search). The first road's cross sections are
/// taken a block at a time (a road larger than memory streams through; a road read in
/// place reads only the nodes' cells of the second).
pub fn compare(first: &Arc<Road>, second: &Arc<Road>, progress: Progress) -> Result<Comparison> {
    let v = first.grid().v.clone();
    let nu = first.reference_line().n;
    let probes = || (opencrg_core::ContactPoint::new(first.clone()), SurfaceProbe::new(second));
    // Each node's difference; +inf where only the first has a value, NaN where it has none.
    let difference = |(a, b): &mut (opencrg_core::ContactPoint, SurfaceProbe), node: Node| {
        let Ok(za) = a.uv_to_z(node.u, node.v) else { return f32::NAN };
        if za.is_nan() {
            return f32::NAN;
        }
        match b.at(node.x, node.y) {
            Some((zb, _, _)) if !zb.is_nan() => (zb - za) as f32,
            _ => f32::INFINITY,
        }
    };
    let mut c =
        Comparison { compared: 0, only_first: 0, max_difference: 0.0, at: [f64::NAN; 4], signed: 0.0, rms: 0.0 };
    let mut worst = None;
    let mut sum2 = 0.0;
    let rows = (BLOCK_NODES / v.len().max(1)).max(64);
    let mut block = filled(rows * v.len(), f32::NAN, "a block of the first road's nodes")?;
    let done = AtomicUsize::new(0);
    for start in (0..nu).step_by(rows) {
        let count = rows.min(nu - start);
        let block = &mut block[..count * v.len()];
        rows_of_nodes(first, start, &v, &probes, &difference, block, &|k| {
            progress("comparing", done.fetch_add(k, Ordering::Relaxed) as u64 + k as u64, nu as u64)
        });
        for (k, &d) in block.iter().enumerate() {
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
            // The largest difference, of equal ones the first long section by long section.
            let (iu, iv) = (start + k / v.len(), k % v.len());
            let earlier = worst.is_none_or(|(wu, wv)| (iv, iu) < (wv, wu));
            if d.abs() > c.max_difference || worst.is_none() || (d.abs() == c.max_difference && earlier) {
                c.max_difference = d.abs();
                c.signed = d;
                worst = Some((iu, iv));
            }
        }
    }
    progress("comparing", nu as u64, nu as u64);
    if let Some((iu, iv)) = worst {
        let u = first.reference_line().u_at(iu);
        let (x, y) = opencrg_core::ContactPoint::new(first.clone()).uv_to_xy(u, v[iv]).unwrap_or((f64::NAN, f64::NAN));
        c.at = [u, v[iv], x, y];
        c.rms = (sum2 / c.compared as f64).sqrt();
    }
    Ok(c)
}

/// How many nodes of the first road are compared at a time.
const BLOCK_NODES: usize = 1 << 22;
