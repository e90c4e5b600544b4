//! Running the core's evaluations on Python inputs: the batch calls without the GIL,
//! and options set by their Python names.

use crate::arrays::Points;
use crate::errors;
use crate::names;
use ::opencrg_core as crg;
use ::opencrg_core::settings::Family;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Calls `$emit!` with every evaluation as `"doc" name(first, second) Call,`: the one
/// list from which `Road` and `ContactPoint` get their evaluation methods.
macro_rules! for_each_evaluation {
    ($emit:ident) => {
        $emit! {
            "Elevation z at (u, v)." uv_to_z(u, v) UvToZ,
            "Elevation z at (x, y)." xy_to_z(x, y) XyToZ,
            "(x, y) of (u, v)." uv_to_xy(u, v) UvToXy,
            "(u, v) of (x, y)." xy_to_uv(x, y) XyToUv,
            "(heading, curvature) at (u, v)." uv_to_pk(u, v) UvToPk,
            "(heading, curvature) at (x, y)." xy_to_pk(x, y) XyToPk,
            "(z, nx, ny, nz) at (u, v): elevation and the surface's upward unit normal in x/y/z." uv_to_normal(u, v) UvToNormal,
            "(z, nx, ny, nz) at (x, y): elevation and the surface's upward unit normal in x/y/z." xy_to_normal(x, y) XyToNormal,
        }
    };
}
pub(crate) use for_each_evaluation;

/// The evaluations, each with the number of values it gives per point.
#[derive(Clone, Copy)]
pub(crate) enum Call {
    UvToZ,
    XyToZ,
    UvToXy,
    XyToUv,
    UvToPk,
    XyToPk,
    UvToNormal,
    XyToNormal,
}

impl Call {
    fn outputs(self) -> usize {
        match self {
            Call::UvToZ | Call::XyToZ => 1,
            Call::UvToXy | Call::XyToUv | Call::UvToPk | Call::XyToPk => 2,
            Call::UvToNormal | Call::XyToNormal => 4,
        }
    }
}

/// Runs `call` on every point, in order, on one contact point: the classic calls'
/// answers (history included); NaN where a point is refused.
fn run(cp: &mut crg::ContactPoint, call: Call, a: &[f64], b: &[f64]) -> Vec<Vec<f64>> {
    let n = a.len();
    let mut out = vec![vec![f64::NAN; n]; call.outputs()];
    match (call, out.as_mut_slice()) {
        (Call::UvToZ, [z]) => {
            cp.uv_to_z_many(a, b, z);
        }
        (Call::XyToZ, [z]) => {
            cp.xy_to_z_many(a, b, z);
        }
        (Call::UvToXy, [x, y]) => {
            cp.uv_to_xy_many(a, b, x, y);
        }
        (Call::XyToUv, [u, v]) => {
            cp.xy_to_uv_many(a, b, u, v);
        }
        (Call::UvToPk, [phi, curv]) => {
            cp.uv_to_pk_many(a, b, phi, curv);
        }
        (Call::XyToPk, [phi, curv]) => {
            cp.xy_to_pk_many(a, b, phi, curv);
        }
        (Call::UvToNormal | Call::XyToNormal, [z, nx, ny, nz]) => {
            for i in 0..n {
                let normal = match call {
                    Call::UvToNormal => cp.uv_to_normal(a[i], b[i]),
                    _ => cp.xy_to_normal(a[i], b[i]),
                };
                if let Ok((height, [x, y, up])) = normal {
                    (z[i], nx[i], ny[i], nz[i]) = (height, x, y, up);
                }
            }
        }
        _ => unreachable!("one output vector per value of the call"),
    }
    out
}

/// Evaluates `call` at the points (a, b) on `cp`, without the GIL.
pub(crate) fn evaluate<'py>(
    py: Python<'py>,
    cp: &mut crg::ContactPoint,
    call: Call,
    a: &Bound<'py, PyAny>,
    b: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let points = Points::new([a, b])?;
    let [sa, sb] = points.slices()?;
    let outputs = py.detach(|| run(cp, call, sa, sb));
    points.results(py, outputs)
}

/// Sets an option by its Python name on a core contact point.
pub(crate) fn set_option(cp: &mut crg::ContactPoint, name: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
    let s = names::lookup(Family::Option, name)?;
    match names::value_for(s, value)? {
        Some(v) => cp.set_option_value(s.id, v).map_err(errors::to_py),
        None => {
            cp.remove_option(s.id);
            Ok(())
        }
    }
}

/// Sets every keyword argument as an option.
pub(crate) fn set_options(cp: &mut crg::ContactPoint, options: Option<&Bound<'_, PyDict>>) -> PyResult<()> {
    for (key, value) in options.into_iter().flat_map(|d| d.iter()) {
        set_option(cp, &key.extract::<String>()?, &value)?;
    }
    Ok(())
}
