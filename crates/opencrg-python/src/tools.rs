//! The road tools: methods of `Road` that make new roads (cut, flip, append, resample,
//! filter, slope and banking), and module functions that make roads from points
//! (`generate`, `import_points`), read point files and compare surfaces. Points are
//! numpy arrays of shape (n, 2) or (n, 3), or the path of a point file.

use crate::errors::{budget, request_error, to_py};
use crate::recipe::Recipe;
use crate::road::Road;
use ::opencrg_core as crg;
use ::opencrg_tools::{self as tools, ChannelAction, Filter, Import, Layout, LineChannel, Points};
use numpy::{PyArray2, PyArrayMethods, PyReadonlyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;
use std::sync::Arc;

/// A new Python road from what a tool made.
fn made(road: crg::Road) -> Road {
    let road = Arc::new(road);
    Road::from_core_shared(road.clone(), Recipe::made(road))
}

fn action(name: &str) -> PyResult<ChannelAction> {
    match name {
        "extract" => Ok(ChannelAction::Extract),
        "apply" => Ok(ChannelAction::Apply),
        "remove" => Ok(ChannelAction::Remove),
        other => Err(request_error(format!("unknown action '{other}': extract, apply or remove"))),
    }
}

/// A two-dimensional array-like as contiguous float64.
fn float_matrix<'py>(given: &Bound<'py, PyAny>) -> PyResult<PyReadonlyArray2<'py, f64>> {
    let np = given.py().import("numpy")?;
    let array = np.call_method1("require", (given, np.getattr("float64")?, "CA"))?;
    Ok(array.cast_into::<PyArray2<f64>>()?.readonly())
}

/// Points from an array of shape (n, 2) or (n, 3), or from a point file.
fn points(given: &Bound<'_, PyAny>) -> PyResult<Points> {
    if let Ok(path) = given.extract::<PathBuf>() {
        return tools::read_points(&path).map_err(to_py);
    }
    let array = float_matrix(given)
        .map_err(|_| request_error("points: expected an array of shape (n, 2) or (n, 3), or a file path"))?;
    let a = array.as_array();
    if a.ncols() != 2 && a.ncols() != 3 {
        return Err(request_error(format!("points: {} columns, expected 2 (x, y) or 3 (x, y, z)", a.ncols())));
    }
    Ok(Points { x: a.column(0).to_vec(), y: a.column(1).to_vec(), z: (a.ncols() == 3).then(|| a.column(2).to_vec()) })
}

#[pymethods]
impl Road {
    /// The part of the road between `u = (from, to)` (and `v = (from, to)`): the grid
    /// nodes inside, the surface where it was.
    #[pyo3(signature = (u, v = None))]
    fn cut(&self, py: Python<'_>, u: (f64, f64), v: Option<(f64, f64)>) -> PyResult<Road> {
        let road = self.shared();
        py.detach(|| tools::cut(&road, u, v)).map(made).map_err(to_py)
    }

    /// The same road driven the other way (u reversed, v mirrored), the surface where it was.
    fn flip(&self, py: Python<'_>) -> PyResult<Road> {
        let road = self.shared();
        py.detach(|| tools::flip(&road)).map(made).map_err(to_py)
    }

    /// `other` continuing this road from its end point, heading and height (resampled to
    /// this road's grid where the grids differ).
    #[pyo3(signature = (other, *, max_memory = None))]
    fn append(&self, py: Python<'_>, other: &Road, max_memory: Option<&Bound<'_, PyAny>>) -> PyResult<Road> {
        let (road, other, budget) = (self.shared(), other.shared(), budget(max_memory)?);
        py.detach(|| tools::append(&road, &other, &budget)).map(made).map_err(to_py)
    }

    /// The surface on a new grid (`None`: the road's own increment or long sections).
    #[pyo3(signature = (u_inc = None, v_inc = None, *, max_memory = None))]
    fn resample(
        &self,
        py: Python<'_>,
        u_inc: Option<f64>,
        v_inc: Option<f64>,
        max_memory: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Road> {
        let (road, budget) = (self.shared(), budget(max_memory)?);
        py.detach(|| tools::resample(&road, u_inc, v_inc, &budget)).map(made).map_err(to_py)
    }

    /// The grid filtered by one of: `gauss=SIGMA` (m), `median=N` (N x N nodes, N odd),
    /// `limit=(zmin, zmax)`, `fill_nan=True`.
    #[pyo3(signature = (*, gauss = None, median = None, limit = None, fill_nan = false, max_memory = None))]
    fn filter(
        &self,
        py: Python<'_>,
        gauss: Option<f64>,
        median: Option<i64>,
        limit: Option<(f64, f64)>,
        fill_nan: bool,
        max_memory: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Road> {
        let median = median
            .map(|n| {
                usize::try_from(n)
                    .map_err(|_| request_error(format!("median window {n} must be an odd number of nodes")))
            })
            .transpose()?;
        let chosen = [gauss.map(Filter::Gauss), median.map(Filter::Median), limit.map(|(a, b)| Filter::Limit(a, b))]
            .into_iter()
            .flatten()
            .chain(fill_nan.then_some(Filter::FillNan))
            .collect::<Vec<_>>();
        let [filter] = chosen[..] else {
            return Err(request_error("filter: give exactly one of gauss, median, limit, fill_nan"));
        };
        let (road, budget) = (self.shared(), budget(max_memory)?);
        py.detach(|| tools::filter(&road, filter, &budget)).map(made).map_err(to_py)
    }

    /// The slope moved between the reference line and the grid: `"extract"` (grid to
    /// line), `"apply"` (line to grid) or `"remove"`.
    fn slope(&self, py: Python<'_>, action: &str) -> PyResult<Road> {
        let (road, a) = (self.shared(), self::action(action)?);
        py.detach(|| tools::change_channel(&road, LineChannel::Slope, a)).map(made).map_err(to_py)
    }

    /// The banking moved between the reference line and the grid: `"extract"`, `"apply"`
    /// or `"remove"`.
    fn banking(&self, py: Python<'_>, action: &str) -> PyResult<Road> {
        let (road, a) = (self.shared(), self::action(action)?);
        py.detach(|| tools::change_channel(&road, LineChannel::Banking, a)).map(made).map_err(to_py)
    }
}

/// A road along a smooth line through `points` (x, y and optionally z, which gives the
/// slope), `width` wide; its grid from `surface`: a function called once with the
/// arrays u and v of every node (shape (nu, nv)) returning z of that shape, or a `Road`
/// whose surface is taken at the same u/v; flat without.
#[pyfunction]
#[pyo3(signature = (points, width, u_inc, v_inc, surface = None, *, max_memory = None))]
pub(crate) fn generate(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    width: f64,
    u_inc: f64,
    v_inc: f64,
    surface: Option<&Bound<'_, PyAny>>,
    max_memory: Option<&Bound<'_, PyAny>>,
) -> PyResult<Road> {
    let line = self::points(points)?;
    let layout = Layout { width, u_inc, v_inc };
    let budget = budget(max_memory)?;
    let flat = py.detach(|| tools::generate(&line, layout, None, &budget)).map_err(to_py)?;
    let Some(surface) = surface else { return Ok(made(flat)) };
    if let Ok(other) = surface.extract::<PyRef<'_, Road>>() {
        let cp = crg::ContactPoint::new(other.shared());
        let f = move |u: f64, v: f64| cp.uv_to_z(u, v).unwrap_or(f64::NAN);
        return py.detach(|| tools::generate(&line, layout, Some(&f), &budget)).map(made).map_err(to_py);
    }
    let (nu, nv) = (flat.grid().nu, flat.grid().nv);
    let u: Vec<f64> = (0..nu).map(|i| flat.reference_line().u_at(i)).collect();
    let v = flat.grid().v.clone();
    let uu = PyArray2::from_vec2(py, &u.iter().map(|&u| vec![u; nv]).collect::<Vec<_>>())?;
    let vv = PyArray2::from_vec2(py, &vec![v.clone(); nu])?;
    let z = surface.call1((uu, vv))?;
    let z = float_matrix(&z)
        .map_err(|_| request_error("surface: the function must return an array of the shape of its inputs"))?;
    let z = z.as_array();
    if z.shape() != [nu, nv] {
        return Err(request_error(format!("surface: returned shape {:?}, expected ({nu}, {nv})", z.shape())));
    }
    let z = z.to_owned();
    let (u0, du, v0, dv) = (u[0], u_inc, v[0], v.get(1).map_or(1.0, |v1| v1 - v[0]));
    let f = move |uq: f64, vq: f64| {
        let i = (((uq - u0) / du).round() as usize).min(nu - 1);
        let j = (((vq - v0) / dv).round() as usize).min(nv - 1);
        z[[i, j]]
    };
    py.detach(|| tools::generate(&line, layout, Some(&f), &budget)).map(made).map_err(to_py)
}

/// A road from a point cloud (an array (n, 3) or a point file): gridded along `refline`
/// (points or a file; without, a line fitted through the cloud), `width` wide (without,
/// as far as the cloud reaches), each node linear in the Delaunay triangle around it;
/// `crop` ((x0, x1), (y0, y1)) keeps only the points within it.
#[pyfunction]
#[pyo3(signature = (cloud, u_inc, v_inc, *, refline = None, width = None, max_edge = None, fill_nan = false, crop = None, max_memory = None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn import_points(
    py: Python<'_>,
    cloud: &Bound<'_, PyAny>,
    u_inc: f64,
    v_inc: f64,
    refline: Option<&Bound<'_, PyAny>>,
    width: Option<f64>,
    max_edge: Option<f64>,
    fill_nan: bool,
    crop: Option<((f64, f64), (f64, f64))>,
    max_memory: Option<&Bound<'_, PyAny>>,
) -> PyResult<Road> {
    let cloud = points(cloud)?;
    let refline = refline.map(points).transpose()?;
    let crop = crop.map(|(x, y)| [x, y]);
    let how = Import { refline, width, u_inc, v_inc, max_edge, fill: fill_nan, crop };
    let budget = budget(max_memory)?;
    py.detach(|| tools::import(&cloud, &how, &|_, _, _| {}, &budget)).map(made).map_err(to_py)
}

/// The points of a file (CSV/XYZ, PLY, LAS/LAZ) as an array of shape (n, 2) or (n, 3).
#[pyfunction]
pub(crate) fn read_points<'py>(py: Python<'py>, path: PathBuf) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let p = py.detach(|| tools::read_points(&path)).map_err(to_py)?;
    let rows: Vec<Vec<f64>> = (0..p.len())
        .map(|i| match &p.z {
            Some(z) => vec![p.x[i], p.y[i], z[i]],
            None => vec![p.x[i], p.y[i]],
        })
        .collect();
    Ok(PyArray2::from_vec2(py, &rows)?)
}

/// The second road's surface against the first's at the first's grid nodes (same x/y):
/// a dict with `max_difference`, `signed` (b - a there), `at` (u, v, x, y), `rms`,
/// `compared` and `only_in_a` (nodes where b has no surface).
#[pyfunction]
pub(crate) fn compare<'py>(py: Python<'py>, a: &Road, b: &Road) -> PyResult<Bound<'py, PyDict>> {
    let (ra, rb) = (a.shared(), b.shared());
    let c = py.detach(|| tools::compare(&ra, &rb, &|_, _, _| {})).map_err(to_py)?;
    let d = PyDict::new(py);
    d.set_item("max_difference", c.max_difference)?;
    d.set_item("signed", c.signed)?;
    d.set_item("at", c.at.to_vec())?;
    d.set_item("rms", c.rms)?;
    d.set_item("compared", c.compared)?;
    d.set_item("only_in_a", c.only_first)?;
    Ok(d)
}
