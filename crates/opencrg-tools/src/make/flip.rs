//! The same road driven the other way.

use opencrg_core::draft::Draft;
use opencrg_core::Result;
use opencrg_core::Road;
use std::f64::consts::PI;

/// `road` driven the other way: u runs from its end to its start, v is mirrored (left
/// becomes right), headings turn by half a turn, slope and banking change sign; the
/// surface stays at the same place. u starts where the road's started.
pub fn flip(road: &Road) -> Result<Road> {
    let what = format!("flipped by opencrg {}: driven the other way", env!("CARGO_PKG_VERSION"));
    let mut d = Draft::of(road);
    let grid = std::mem::take(&mut d.z);
    flipped(d, &grid).into_road(&what)
}

/// The draft, whose elevations are `grid`, driven the other way.
fn flipped(d: Draft, grid: &[f32]) -> Draft {
    let n = d.nu();
    let (x, y) = d.line_xy();
    let z = d.line_z();
    // The step into new section k is the old step into section n - k, reversed.
    // One half turn for all, so the headings stay as continuous as they were.
    let half = if d.phi[n - 1] > 0.0 { -PI } else { PI };
    let turn = |p: f64| p + half;
    let mut phi: Vec<f64> = (0..n).map(|k| turn(d.phi[(n - k).min(n - 1)])).collect();
    phi[0] = phi.get(1).copied().unwrap_or(phi[0]);
    let slope = d.slope.as_ref().map(|s| {
        let mut out: Vec<f64> = (0..n).map(|k| -s[(n - k).min(n - 1)]).collect();
        out[0] = out.get(1).copied().unwrap_or(0.0);
        out
    });
    let bank = d.bank.as_ref().map(|b| b.iter().rev().map(|b| -b).collect());
    let nv = d.nv();
    let mut turned = Vec::with_capacity(grid.len());
    for iv in (0..nv).rev() {
        turned.extend(grid[iv * n..(iv + 1) * n].iter().rev());
    }
    Draft {
        start: (x[n - 1], y[n - 1]),
        z_start: z[n - 1],
        phi,
        slope,
        bank,
        v: d.v.iter().rev().map(|v| -v).collect(),
        bank_v: (-d.bank_v.1, -d.bank_v.0),
        z: turned,
        moved: true,
        ..d
    }
}
