//! `opencrg.ContactPoint`: evaluation with options and an x/y search history, over
//! numpy arrays through the core's batch calls, with the GIL released.

use crate::arrays::Pair;
use crate::errors;
use crate::names;
use crate::road::Road;
use ::opencrg as crg;
use ::opencrg::settings::{Family, Value};
use pyo3::prelude::*;
use pyo3::types::PyDict;

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
    let points = Pair::new(a, b)?;
    let (sa, sb) = points.slices()?;
    debug_assert_eq!(sa.len(), points.len());
    let outputs = py.detach(|| run(cp, call, sa, sb));
    points.results(py, outputs)
}

/// Sets an option by its Python name on a core contact point.
pub(crate) fn set_option(cp: &mut crg::ContactPoint, name: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
    let s = names::lookup(Family::Option, name)?;
    let result = match names::value_for(s, value)? {
        Some(Value::Int(i)) => cp.set_option_int(s.id, i),
        Some(Value::Double(d)) => cp.set_option_double(s.id, d),
        None => {
            cp.remove_option(s.id);
            Ok(())
        }
    };
    result.map_err(errors::to_py)
}

/// Sets every keyword argument as an option.
pub(crate) fn set_options(cp: &mut crg::ContactPoint, options: Option<&Bound<'_, PyDict>>) -> PyResult<()> {
    for (key, value) in options.into_iter().flat_map(|d| d.iter()) {
        set_option(cp, &key.extract::<String>()?, &value)?;
    }
    Ok(())
}

/// A point of evaluation on a road: its own options and x/y search history.
///
/// `ContactPoint(road, *, history=None, **options)`: starts with the road's options
/// (from its file), then the keyword options (`border_mode_u=opencrg.BORDER_REPEAT`,
/// `border_offset_v=0.1`, ... see `opencrg.OPTIONS`); `history` sets the number of
/// search history entries. Evaluations accept numbers or arrays (broadcast together)
/// and give floats or arrays, NaN where a point is refused, the same values as the C
/// library's calls made point by point in order on one contact point.
#[pyclass(module = "opencrg")]
pub(crate) struct ContactPoint {
    road: Py<Road>,
    /// The road version the core contact point evaluates.
    seen: u64,
    inner: crg::ContactPoint,
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
        evaluate(py, &mut self.inner, call, a, b)
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
            inner.set_history(size);
        }
        set_options(&mut inner, options)?;
        Ok(ContactPoint { road: road.unbind(), seen, inner })
    }

    /// The road evaluated.
    #[getter]
    fn road(&self, py: Python<'_>) -> Py<Road> {
        self.road.clone_ref(py)
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
    fn set_history(&mut self, size: usize) {
        self.inner.set_history(size);
    }

    /// Elevation z at (u, v).
    fn uv_to_z<'py>(
        &mut self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(py, Call::UvToZ, u, v)
    }

    /// Elevation z at (x, y).
    fn xy_to_z<'py>(
        &mut self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        y: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(py, Call::XyToZ, x, y)
    }

    /// (x, y) of (u, v).
    fn uv_to_xy<'py>(
        &mut self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(py, Call::UvToXy, u, v)
    }

    /// (u, v) of (x, y).
    fn xy_to_uv<'py>(
        &mut self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        y: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(py, Call::XyToUv, x, y)
    }

    /// (heading, curvature) at (u, v).
    fn uv_to_pk<'py>(
        &mut self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(py, Call::UvToPk, u, v)
    }

    /// (heading, curvature) at (x, y).
    fn xy_to_pk<'py>(
        &mut self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        y: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(py, Call::XyToPk, x, y)
    }

    /// (z, nx, ny, nz) at (u, v): elevation and the surface's upward unit normal in x/y/z.
    fn uv_to_normal<'py>(
        &mut self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(py, Call::UvToNormal, u, v)
    }

    /// (z, nx, ny, nz) at (x, y): elevation and the surface's upward unit normal in x/y/z.
    fn xy_to_normal<'py>(
        &mut self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        y: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(py, Call::XyToNormal, x, y)
    }

    fn __repr__(&self) -> String {
        format!("<opencrg.ContactPoint on {}>", self.inner.road().header().path.display())
    }
}
