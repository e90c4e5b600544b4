//! `opencrg.odr`: OpenDRIVE maps with CRG surfaces. `Map(path)` reads a map, indexes its
//! roads and loads its CRG files; `ground(x, y)` answers height, friction, road, lane, s
//! and t at world points (numpy arrays of any shape, broadcast), `normal(x, y)` the
//! surface's upward normal, `st_to_xyz(road, s, t)` the world point of road coordinates.
//! Maps pickle as their path and are read again where they are unpickled.

use crate::arrays::Points;
use crate::errors::{request_error, to_py};
use crate::road::matrix;
use ::opencrg_core::units::Count;
use numpy::{PyArray1, PyArrayMethods};
use opencrg_odr::Surface;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use std::path::PathBuf;
use std::sync::Arc;

/// An OpenDRIVE map ready to answer at world points.
#[pyclass(module = "opencrg.odr", name = "Map", frozen)]
pub(crate) struct Map {
    surface: Arc<Surface>,
    path: PathBuf,
}

/// Integers in the inputs' shape (a Python int for scalar inputs).
fn ints<'py>(
    py: Python<'py>,
    values: Vec<i64>,
    points: &Points<'py, 2>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    if points.is_scalar() {
        return Ok(values[0].into_pyobject(py)?.into_any());
    }
    Ok(PyArray1::from_vec(py, values).reshape(shape.to_vec())?.into_any())
}

#[pymethods]
impl Map {
    /// Reads the map in `path` (its CRG files relative to its folder).
    #[new]
    fn new(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        let surface = py.detach(|| Surface::load(&path)).map_err(to_py)?;
        Ok(Map { surface: Arc::new(surface), path })
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let class = py.get_type::<Map>().into_any();
        Ok((class, PyTuple::new(py, [self.path.clone()])?))
    }

    fn __repr__(&self) -> String {
        let m = self.surface.map();
        let (roads, junctions) = (Count(m.roads.len(), "road"), Count(m.junctions.len(), "junction"));
        format!("opencrg.odr.Map('{}': {roads}, {junctions})", self.path.display())
    }

    /// The file read.
    #[getter]
    fn path(&self) -> String {
        self.path.display().to_string()
    }

    /// The roads' ids, in the file's order (`ground`'s `road` indexes this list).
    #[getter]
    fn road_ids(&self) -> Vec<String> {
        self.surface.map().roads.iter().map(|r| r.id.clone()).collect()
    }

    /// The roads' lengths (m), in the same order.
    #[getter]
    fn road_lengths(&self) -> Vec<f64> {
        self.surface.map().roads.iter().map(|r| r.length).collect()
    }

    /// How many junctions the map has.
    #[getter]
    fn junctions(&self) -> usize {
        self.surface.map().junctions.len()
    }

    /// The checker's findings, one text each (empty when clean).
    fn check(&self, py: Python<'_>) -> Vec<String> {
        let surface = self.surface.clone();
        py.detach(|| opencrg_odr::check(surface.map()).iter().map(ToString::to_string).collect())
    }

    /// The ground at world points: a dict of `z`, `friction`, `s`, `t` (NaN off every
    /// road), `road` (the index into `road_ids`, -1 off every road) and `lane`.
    fn ground<'py>(
        &self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        y: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let points = Points::new([x, y])?;
        let [xs, ys] = points.slices()?;
        let surface = self.surface.clone();
        let n = xs.len();
        let (mut z, mut mu, mut s, mut t) =
            (vec![f64::NAN; n], vec![f64::NAN; n], vec![f64::NAN; n], vec![f64::NAN; n]);
        let (mut road, mut lane) = (vec![-1i64; n], vec![0i64; n]);
        py.detach(|| {
            let mut probe = surface.probe();
            for i in 0..n {
                if let Some(g) = probe.ground(xs[i], ys[i]) {
                    (z[i], mu[i], s[i], t[i]) = (g.z, g.friction, g.s, g.t);
                    (road[i], lane[i]) = (g.road as i64, i64::from(g.lane));
                }
            }
        });
        let shape = points.shape().to_vec();
        let d = PyDict::new(py);
        for (name, values) in [("z", z), ("friction", mu), ("s", s), ("t", t)] {
            d.set_item(name, points.results(py, vec![values])?)?;
        }
        d.set_item("road", ints(py, road, &points, &shape)?)?;
        d.set_item("lane", ints(py, lane, &points, &shape)?)?;
        Ok(d)
    }

    /// The surface's upward unit normal at world points: (nx, ny, nz), NaN off every road.
    fn normal<'py>(
        &self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        y: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let points = Points::new([x, y])?;
        let [xs, ys] = points.slices()?;
        let surface = self.surface.clone();
        let n = xs.len();
        let mut out = [vec![f64::NAN; n], vec![f64::NAN; n], vec![f64::NAN; n]];
        py.detach(|| {
            let mut probe = surface.probe();
            for i in 0..n {
                if let Some(v) = probe.normal(xs[i], ys[i]) {
                    for k in 0..3 {
                        out[k][i] = v[k];
                    }
                }
            }
        });
        points.results(py, out.into())
    }

    /// The drivable surface as a mesh (see the guide): a dict of numpy arrays `positions`
    /// (n x 3 float64, world x/y/z), `normals` (n x 3 float32), `texcoords` (n x 2
    /// float32: s over the road's length, lambda across the lane), `triangles` (m x 3
    /// uint32), per vertex `friction` (-1 where none), `road` (index into `road_ids`),
    /// `lane`, `s`, `t` (float32), and `groups`: one dict per lane of a lane section
    /// (`name`, `road`, `lane`, `section`, `type`, `triangles`: its first and end index).
    /// `roads`: ids; `lanes`: types (default every type but `none`); `max_error` (m): the
    /// CRG detail thinned to it (default: at the CRG grid's resolution, 1 mm elsewhere).
    #[pyo3(signature = (max_error = None, roads = None, lanes = None, *, max_memory = None))]
    fn to_mesh<'py>(
        &self,
        py: Python<'py>,
        max_error: Option<f64>,
        roads: Option<Vec<String>>,
        lanes: Option<Vec<String>>,
        max_memory: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let mesh = self.mesh(py, max_error, roads, lanes, max_memory)?;
        let d = PyDict::new(py);
        d.set_item("positions", matrix(py, &mesh.positions)?)?;
        d.set_item("normals", matrix(py, &mesh.normals)?)?;
        d.set_item("texcoords", matrix(py, &mesh.texcoords)?)?;
        d.set_item("triangles", matrix(py, &mesh.triangles)?)?;
        for v in &mesh.values {
            d.set_item(&v.name, PyArray1::from_slice(py, &v.values))?;
        }
        let groups = pyo3::types::PyList::empty(py);
        for g in &mesh.groups {
            let item: Bound<'py, PyDict> =
                py.import("json")?.getattr("loads")?.call1((format!("{{{}}}", g.extras),))?.cast_into()?;
            item.set_item("name", &g.name)?;
            item.set_item("triangles", (g.triangles.start, g.triangles.end))?;
            groups.append(item)?;
        }
        d.set_item("groups", groups)?;
        Ok(d)
    }

    /// Writes the mesh of `to_mesh` to `path`, the format from its extension: `.glb`,
    /// `.obj`, `.ply` or `.stl`.
    #[pyo3(signature = (path, max_error = None, roads = None, lanes = None, *, max_memory = None))]
    fn write_mesh<'py>(
        &self,
        py: Python<'py>,
        path: PathBuf,
        max_error: Option<f64>,
        roads: Option<Vec<String>>,
        lanes: Option<Vec<String>>,
        max_memory: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<()> {
        let format = opencrg_tools::mesh_files::MeshFormat::from_path(&path).ok_or_else(|| {
            request_error(format!("{}: unknown mesh format; .glb, .obj, .ply or .stl", path.display()))
        })?;
        let mesh = self.mesh(py, max_error, roads, lanes, max_memory)?;
        py.detach(|| opencrg_tools::mesh_files::write_mesh(&mesh, &path, format)).map_err(to_py)
    }

    /// The world point (x, y, z) of the surface at (s, t) of the road `road` (its id),
    /// CRG records laid on.
    fn st_to_xyz<'py>(
        &self,
        py: Python<'py>,
        road: &str,
        s: &Bound<'py, PyAny>,
        t: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let index =
            self.surface.map().road_index(road).ok_or_else(|| request_error(format!("no road '{road}' in the map")))?;
        let points = Points::new([s, t])?;
        let [ss, ts] = points.slices()?;
        let surface = self.surface.clone();
        let n = ss.len();
        let mut out = [vec![f64::NAN; n], vec![f64::NAN; n], vec![f64::NAN; n]];
        py.detach(|| {
            let mut probe = surface.probe();
            for i in 0..n {
                if let Some((x, y, g)) = probe.ground_st(index, ss[i], ts[i]) {
                    (out[0][i], out[1][i], out[2][i]) = (x, y, g.z);
                }
            }
        });
        points.results(py, out.into())
    }
}

impl Map {
    /// The map's mesh for `to_mesh` and `write_mesh`.
    fn mesh(
        &self,
        py: Python<'_>,
        max_error: Option<f64>,
        roads: Option<Vec<String>>,
        lanes: Option<Vec<String>>,
        max_memory: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<opencrg_tools::mesh::Mesh> {
        let budget = crate::errors::budget(max_memory)?;
        let options = opencrg_tools::map_mesh::MeshOptions { roads, lane_types: lanes, max_error };
        let surface = self.surface.clone();
        py.detach(|| opencrg_tools::map_mesh::map_mesh(&surface, &options, &budget)).map_err(to_py)
    }
}

/// Adds the submodule `opencrg.odr` (importable as such).
pub(crate) fn register(parent: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = parent.py();
    let m = PyModule::new(py, "odr")?;
    m.add("__doc__", "OpenDRIVE maps with OpenCRG surfaces: height, normal and friction at world points.")?;
    m.add_class::<Map>()?;
    parent.add_submodule(&m)?;
    py.import("sys")?.getattr("modules")?.set_item("opencrg.odr", &m)?;
    Ok(())
}
