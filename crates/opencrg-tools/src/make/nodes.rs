//! Values at every grid node of a road being made, computed on all cores: each node's
//! x/y comes from the new road's own reference line (as the library places it), the
//! value from a function of the node.

use opencrg_core::budget::filled;
use opencrg_core::settings::BorderMode;
use opencrg_core::ContactPoint;
use opencrg_core::CpOption;
use opencrg_core::Result;
use opencrg_core::Road;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

/// Where a grid node lies: its indices, u, v and x/y.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Node {
    pub iu: usize,
    pub u: f64,
    pub v: f64,
    pub x: f64,
    pub y: f64,
}

/// Tells how much of a long computation is done: (stage, done, total).
pub type Progress<'a> = &'a (dyn Fn(&str, u64, u64) + Sync);

/// `value(state, node)` at every node of `frame`'s cross sections and of the long
/// sections at `v` (not necessarily the frame's own), long section by long section
/// (`[iv * nu + iu]`). Each thread makes its own state with `state()`. Refused: memory
/// the system does not give.
pub(crate) fn at_nodes<S>(
    frame: &Arc<Road>,
    v: &[f64],
    state: impl Fn() -> S + Sync,
    value: impl Fn(&mut S, Node) -> f32 + Sync,
    progress: Progress,
) -> Result<Vec<f32>> {
    let line = frame.reference_line();
    let (nu, nv) = (line.n, v.len());
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()).min(nu.div_ceil(64)).max(1);
    let rows_per = nu.div_ceil(threads);
    // Cross section by cross section first (each thread fills whole rows), turned after.
    let mut by_row = filled(nu * nv, f32::NAN, "the values at the new road's nodes")?;
    let done = AtomicUsize::new(0);
    std::thread::scope(|scope| {
        for (chunk, rows) in by_row.chunks_mut(rows_per * nv).enumerate() {
            let (state, value, done) = (&state, &value, &done);
            scope.spawn(move || {
                let cp = ContactPoint::new(frame.clone());
                let mut s = state();
                for (k, row) in rows.chunks_mut(nv).enumerate() {
                    let iu = chunk * rows_per + k;
                    let u = line.u_at(iu);
                    for (iv, out) in row.iter_mut().enumerate() {
                        let Ok((x, y)) = cp.uv_to_xy(u, v[iv]) else { continue };
                        *out = value(&mut s, Node { iu, u, v: v[iv], x, y });
                    }
                    if k % 64 == 63 {
                        progress("evaluating", done.fetch_add(64, Ordering::Relaxed) as u64 + 64, nu as u64);
                    }
                }
            });
        }
    });
    progress("evaluating", nu as u64, nu as u64);
    let mut out = filled(nu * nv, 0.0f32, "the new road's grid")?;
    for (iu, row) in by_row.chunks_exact(nv).enumerate() {
        for (iv, &z) in row.iter().enumerate() {
            out[iv * nu + iu] = z;
        }
    }
    Ok(out)
}

/// A contact point that reads the surface of `road` at x/y, or says there is none: the
/// border modes keep the edge values, so that points on the edges count (the x/y search
/// may place them a little outside: at the ends of a curved line, the normal the search
/// uses is not quite the one that placed them), and points more than half an increment
/// outside the data are refused.
pub(crate) struct SurfaceProbe {
    cp: ContactPoint,
    u: (f64, f64),
    v: (f64, f64),
    slack: f64,
}

impl SurfaceProbe {
    /// A probe of `road`'s surface.
    pub fn new(road: &Arc<Road>) -> SurfaceProbe {
        let mut cp = ContactPoint::new(road.clone());
        for o in [CpOption::BorderModeU(BorderMode::ExKeep), CpOption::BorderModeV(BorderMode::ExKeep)] {
            // Both options exist in every profile.
            let _ = cp.set_option(o);
        }
        let dv = road.grid().v.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
        SurfaceProbe { cp, u: road.u_range(), v: road.v_range(), slack: 0.5 * road.increments().0.min(dv) }
    }

    /// The surface's z at x/y with its u/v, or `None` off the road.
    pub fn at(&mut self, x: f64, y: f64) -> Option<(f64, f64, f64)> {
        let (u, v) = self.cp.xy_to_uv(x, y).ok()?;
        let s = self.slack;
        let inside = u >= self.u.0 - s && u <= self.u.1 + s && v >= self.v.0 - s && v <= self.v.1 + s;
        if !inside {
            return None;
        }
        self.cp.uv_to_z(u, v).ok().map(|z| (z, u, v))
    }
}
