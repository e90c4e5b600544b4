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

/// Evaluates `call` at the points (a, b) on `cp`, without the GIL: a point given as
/// numbers as the C API's call asks it, arrays through the batch calls. Which points were
/// refused goes to `refused` where one is given (found only then).
pub(crate) fn evaluate<'py>(
    py: Python<'py>,
    cp: &mut crg::ContactPoint,
    call: Call,
    a: &Bound<'py, PyAny>,
    b: &Bound<'py, PyAny>,
    refused: Option<&mut Refused>,
) -> PyResult<Bound<'py, PyAny>> {
    let points = Points::new([a, b])?;
    let [sa, sb] = points.slices()?;
    if points.is_scalar() {
        let (values, was_refused) = py.detach(|| cp.evaluate_one_or_nan(call, sa[0], sb[0]));
        if let Some(r) = refused {
            *r = Refused::One(was_refused);
        }
        return points.results(py, values.into_iter().map(|v| vec![v]).collect());
    }
    let outputs = py.detach(|| cp.evaluate_many(call, sa, sb));
    if let Some(r) = refused {
        *r = Refused::Many(Call::answered_nan(&outputs), points.shape().to_vec());
    }
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
