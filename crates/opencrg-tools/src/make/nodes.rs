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
    let (nu, nv) = (frame.reference_line().n, v.len());
    // Cross section by cross section first (each thread fills whole rows), turned after.
    let mut by_row = filled(nu * nv, f32::NAN, "the values at the new road's nodes")?;
    let done = AtomicUsize::new(0);
    rows_of_nodes(frame, 0, v, &state, &value, &mut by_row, &|k| {
        progress("evaluating", done.fetch_add(k, Ordering::Relaxed) as u64 + k as u64, nu as u64)
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

/// `value(state, node)` at every node of `frame`'s cross sections from `first` on and of
/// the long sections at `v`, into `out` cross section by cross section (`[k * nv + iv]`
/// for cross section `first + k`; as many as `out` holds; NaN where a node has no x/y),
/// on all cores, each thread with its own `state()`; `done(k)` told of every 64 cross
/// sections finished.
pub(crate) fn rows_of_nodes<S>(
    frame: &Arc<Road>,
    first: usize,
    v: &[f64],
    state: &(impl Fn() -> S + Sync),
    value: &(impl Fn(&mut S, Node) -> f32 + Sync),
    out: &mut [f32],
    done: &(dyn Fn(usize) + Sync),
) {
    let line = frame.reference_line();
    let nv = v.len().max(1);
    let rows = out.len() / nv;
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()).min(rows.div_ceil(64)).max(1);
    let rows_per = rows.div_ceil(threads).max(1);
    std::thread::scope(|scope| {
        for (chunk, part) in out.chunks_mut(rows_per * nv).enumerate() {
            scope.spawn(move || {
                let cp = ContactPoint::new(frame.clone());
                let mut s = state();
                for (k, row) in part.chunks_mut(nv).enumerate() {
                    let iu = first + chunk * rows_per + k;
                    let u = line.u_at(iu);
                    for (iv, out) in row.iter_mut().enumerate() {
                        *out = match cp.uv_to_xy(u, v[iv]) {
                            Ok((x, y)) => value(&mut s, Node { iu, u, v: v[iv], x, y }),
                            Err(_) => f32::NAN,
                        };
                    }
                    if k % 64 == 63 {
                        done(64);
                    }
                }
            });
        }
    });
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
