//! `opencrg.ContactPoint`: a road with its own options and x/y search history.

use crate::evaluation::{evaluate, for_each_evaluation, set_option, set_options, Call, Refused};
use crate::names;
use crate::road::Road;
use ::opencrg_core as crg;
use ::opencrg_core::settings::Family;
use numpy::PyArrayMethods;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

/// A point of evaluation on a road: its own options and x/y search history.
///
/// `ContactPoint(road, *, history=None, **options)`: starts with the road's options
/// (from its file), then the keyword options (`border_mode_u=opencrg.BORDER_REPEAT`,
/// `border_offset_v=0.1`, ... see `opencrg.OPTIONS`); `history` sets the number of
/// search history entries. Evaluations accept numbers or arrays (broadcast together)
/// and give floats or arrays, NaN where a point is refused, the same values as the C
/// library's calls made point by point in order on one contact point.
///
/// A contact point pickles with its road (see `Road`), its options and its search history:
/// unpickled, it gives the same answers, its next x/y searches included.
#[pyclass(module = "opencrg")]
pub(crate) struct ContactPoint {
    road: Py<Road>,
    /// The road version the core contact point evaluates.
    seen: u64,
    inner: crg::ContactPoint,
    /// Which points the last evaluation refused.
    refused: Refused,
}

impl ContactPoint {
    /// Follows the road after modifiers or checks changed it (options and history kept).
    fn follow_road(&mut self, py: Python<'_>) {
        let road = self.road.bind(py).borrow();
        if road.version() != self.seen {
            self.inner.set_road(road.shared());
            self.seen = road.version();
        }
    }

    fn eval<'py>(
        &mut self,
        py: Python<'py>,
        call: Call,
        a: &Bound<'py, PyAny>,
        b: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.follow_road(py);
        evaluate(py, &mut self.inner, call, a, b, Some(&mut self.refused))
    }
}

#[pymethods]
impl ContactPoint {
    #[new]
    #[pyo3(signature = (road, *, history = None, **options))]
    pub(crate) fn new(
        road: Bound<'_, Road>,
        history: Option<usize>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Self> {
        let (shared, seen) = {
            let r = road.borrow();
            (r.shared(), r.version())
        };
        let mut inner = crg::ContactPoint::new(shared);
        if let Some(size) = history {
            inner.set_history(size).map_err(crate::errors::to_py)?;
        }
        set_options(&mut inner, options)?;
        Ok(ContactPoint { road: road.unbind(), seen, inner, refused: Refused::One(false) })
    }

    /// The road evaluated.
    #[getter]
    fn road(&self, py: Python<'_>) -> Py<Road> {
        self.road.clone_ref(py)
    }

    /// Which points the last evaluation refused: for a point given as numbers whether the C
    /// API's call refuses it (its return code 0; the values are then NaN, and a NaN answered
    /// is not a refusal); for arrays a boolean array of their shape, true where a point was
    /// answered NaN. False before any evaluation.
    #[getter]
    fn refused<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(match &self.refused {
            Refused::One(refused) => pyo3::types::PyBool::new(py, *refused).to_owned().into_any(),
            Refused::Many(flags, shape) => numpy::PyArray1::from_slice(py, flags).reshape(shape.clone())?.into_any(),
        })
    }

    /// The options in force, by name.
    #[getter]
    fn options<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        names::to_dict(py, self.inner.options())
    }

    /// Sets one option (`cp.set_option("border_mode_v", opencrg.BORDER_NONE)`).
    fn set_option(&mut self, name: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        set_option(&mut self.inner, name, value)
    }

    /// Removes one option: evaluation behaves as with the option absent.
    fn remove_option(&mut self, name: &str) -> PyResult<()> {
        let s = names::lookup(Family::Option, name)?;
        self.inner.remove_option(s.id);
        Ok(())
    }

    /// Restores the library's default options and search distances.
    fn reset_options(&mut self) {
        self.inner.reset_options();
    }

    /// Gives the x/y search history `size` entries (emptied).
    fn set_history(&mut self, size: usize) -> PyResult<()> {
        self.inner.set_history(size).map_err(crate::errors::to_py)
    }

    fn __repr__(&self) -> String {
        format!("<opencrg.ContactPoint on {}>", self.inner.road().header().path.display())
    }

    /// Pickling: the function that makes the contact point again, with its road, its
    /// options and its search history `(size, close², far², [(x, y, index), ...])`.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let make = py.import("opencrg")?.getattr("_contact_point_from_state")?;
        let h = self.inner.search_history();
        let history = (h.size, h.close_squared, h.far_squared, h.entries).into_pyobject(py)?;
        let options = names::to_dict(py, self.inner.options())?;
        let args = (self.road.clone_ref(py), options, history).into_pyobject(py)?;
        Ok((make, args))
    }
}

/// Makes a pickled contact point again (see `ContactPoint.__reduce__`).
#[pyfunction]
pub(crate) fn _contact_point_from_state(
    road: Bound<'_, Road>,
    options: &Bound<'_, PyDict>,
    history: (usize, f64, f64, Vec<(f64, f64, usize)>),
) -> PyResult<ContactPoint> {
    let mut cp = ContactPoint::new(road, None, None)?;
    cp.inner.clear_options();
    set_options(&mut cp.inner, Some(options))?;
    let (size, close_squared, far_squared, entries) = history;
    cp.inner.set_search_history(&crg::SearchHistory { size, close_squared, far_squared, entries });
    Ok(cp)
}

/// The evaluations as methods of `ContactPoint`: `cp.uv_to_z(u, v)`, ...
macro_rules! contact_point_evaluations {
    ($($doc:literal $name:ident($a:ident, $b:ident) $call:ident,)*) => {
        #[pymethods]
        impl ContactPoint {
            $(
                #[doc = $doc]
                fn $name<'py>(
                    &mut self,
                    py: Python<'py>,
                    $a: &Bound<'py, PyAny>,
                    $b: &Bound<'py, PyAny>,
                ) -> PyResult<Bound<'py, PyAny>> {
                    self.eval(py, Call::$call, $a, $b)
                }
            )*
        }
    };
}
for_each_evaluation!(contact_point_evaluations);
