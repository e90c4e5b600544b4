//! Running the core's evaluations on Python inputs: its batch calls without the GIL, and
//! options set by their Python names.

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

/// The evaluations (the core's list).
pub(crate) use ::opencrg_core::Evaluation as Call;

/// Which points of an evaluation were refused.
pub(crate) enum Refused {
    /// One point given as numbers: whether the C API's call refuses it.
    One(bool),
    /// Points given as arrays: the points answered NaN (a refusal, or a NaN answer), and
    /// the inputs' shape.
    Many(Vec<bool>, Vec<usize>),
}

/// Evaluates `call` at the points (a, b) on `cp`, without the GIL, noting which points were
/// refused: a point given as numbers is asked as the C API's call asks it (a refusal known
/// as such), arrays through the batch calls.
pub(crate) fn evaluate<'py>(
    py: Python<'py>,
    cp: &mut crg::ContactPoint,
    call: Call,
    a: &Bound<'py, PyAny>,
    b: &Bound<'py, PyAny>,
) -> PyResult<(Bound<'py, PyAny>, Refused)> {
    let points = Points::new([a, b])?;
    let [sa, sb] = points.slices()?;
    if points.is_scalar() {
        let answer = py.detach(|| cp.evaluate_one(call, sa[0], sb[0]));
        let refused = answer.is_err();
        let values = answer.unwrap_or_else(|_| vec![f64::NAN; call.outputs()]);
        let outputs = values.into_iter().map(|v| vec![v]).collect();
        return Ok((points.results(py, outputs)?, Refused::One(refused)));
    }
    let outputs = py.detach(|| cp.evaluate_many(call, sa, sb));
    let refused = (0..sa.len()).map(|i| outputs.iter().any(|c| c[i].is_nan())).collect();
    let shape = points.shape().to_vec();
    Ok((points.results(py, outputs)?, Refused::Many(refused, shape)))
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
