//! `opencrg.Road`: a loaded road, its data as read-only numpy arrays, its header
//! sections as dicts, modifiers, checks, writing, and evaluation with keyword options.

use crate::errors;
use crate::evaluation::{evaluate, for_each_evaluation, set_options, Call};
use crate::names;
use crate::recipe::{Recipe, Step};
use ::opencrg_core as crg;
use ::opencrg_core::settings::Family;
use ::opencrg_core::{Compat, DataFormat, LoadOptions, ReadInPlace};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyDict, PyList, PyTuple, PyType};
use std::path::PathBuf;
use std::sync::Arc;

/// The behaviour profile: the argument, else `OPENCRG_COMPAT` as in the C library.
fn compat(given: Option<&str>) -> PyResult<Compat> {
    let text = match given {
        Some(text) => text.to_string(),
        None => std::env::var("OPENCRG_COMPAT").unwrap_or_default(),
    };
    text.parse().map_err(|e: crg::UnknownCompat| crate::errors::request_error(e.to_string()))
}

/// When a binary road is read in place: `None` as `OPENCRG_IN_PLACE` says (else from
/// 1 GiB on), `True` always, `False` never, or a size such as `"256M"` (or bytes) from
/// which on.
fn in_place(given: Option<&Bound<'_, PyAny>>) -> PyResult<ReadInPlace> {
    let Some(given) = given.filter(|g| !g.is_none()) else { return Ok(ReadInPlace::Auto) };
    if let Ok(always) = given.extract::<bool>() {
        return Ok(if always { ReadInPlace::Always } else { ReadInPlace::Never });
    }
    if let Ok(bytes) = given.extract::<u64>() {
        return Ok(ReadInPlace::From(bytes));
    }
    let text: String = given.extract().map_err(|_| errors::request_error("in_place: True, False, None or a size"))?;
    ReadInPlace::parse(&text).map_err(|e| errors::request_error(format!("in_place={e}")))
}

/// The tile cache of a road read in place: bytes, or a size such as `"256M"`.
fn cache(given: Option<&Bound<'_, PyAny>>) -> PyResult<Option<u64>> {
    let Some(given) = given.filter(|g| !g.is_none()) else { return Ok(None) };
    if let Ok(bytes) = given.extract::<u64>() {
        return Ok(Some(bytes));
    }
    let text: String = given.extract().map_err(|_| errors::request_error("cache: bytes or a size such as \"256M\""))?;
    crg::parse_bytes(&text).map(Some).map_err(|e| errors::request_error(format!("cache={e}")))
}

/// `ReferenceLine(u, x, y, phi, z)`, a named tuple made once.
static REFERENCE_LINE: PyOnceLock<Py<PyType>> = PyOnceLock::new();

/// The named tuple `opencrg.ReferenceLine` (`u, x, y, phi, z`).
pub(crate) fn reference_line_class(py: Python<'_>) -> PyResult<&Bound<'_, PyType>> {
    let class = REFERENCE_LINE.get_or_try_init(py, || -> PyResult<Py<PyType>> {
        let namedtuple = py.import("collections")?.getattr("namedtuple")?;
        let class = namedtuple.call1(("ReferenceLine", ["u", "x", "y", "phi", "z"]))?;
        class.setattr("__module__", "opencrg")?;
        Ok(class.cast_into::<PyType>()?.unbind())
    })?;
    Ok(class.bind(py))
}

/// A road loaded from a CRG file (LRFI, LDFI, KRBI or KDBI), following its file
/// references.
///
/// `Road(path, *, compat=None)`: `compat` chooses the reference behaviour, `"2.0.1"`
/// for the releases 2.0.1/1.2.0 or `"upstream"` (the default); when not given, the
/// environment variable `OPENCRG_COMPAT` decides, as in the C library. The modifiers of
/// the file are not applied until `apply_modifiers()` is called.
///
/// A road pickles (for `multiprocessing`, Dask, Ray): a road read from a file as the
/// file's path (read again where it is unpickled, which refuses a file changed since), a
/// road made from bytes as its bytes, each with its profile and the checks and modifiers
/// applied since; unpickled, it gives the same answers.
#[pyclass(module = "opencrg")]
pub(crate) struct Road {
    inner: Arc<crg::Road>,
    /// Counts the changes (modifiers, checks): contact points follow the road by it.
    version: u64,
    /// The grid array handed out since the last change.
    grid: Option<Py<PyAny>>,
    /// How to make this road again.
    recipe: Recipe,
}

impl Road {
    /// The core road, shared with contact points.
    pub(crate) fn shared(&self) -> Arc<crg::Road> {
        Arc::clone(&self.inner)
    }

    /// The number of changes so far.
    pub(crate) fn version(&self) -> u64 {
        self.version
    }

    pub(crate) fn from_core(road: crg::Road, recipe: Recipe) -> Self {
        Road::from_core_shared(Arc::new(road), recipe)
    }

    /// A road already shared (with its recipe, for one a tool made).
    pub(crate) fn from_core_shared(road: Arc<crg::Road>, recipe: Recipe) -> Self {
        Road { inner: road, version: 0, grid: None, recipe }
    }

    /// Takes `step` on the road and notes it in the recipe: contact points made before
    /// see the change at their next call.
    pub(crate) fn change(&mut self, py: Python<'_>, step: Step) -> PyResult<()> {
        self.version += 1;
        self.grid = None;
        let road = Arc::make_mut(&mut self.inner);
        let result = py.detach(|| step.apply(road));
        self.recipe.push(step);
        result.map_err(errors::to_py)
    }

    fn eval_with<'py>(
        &self,
        py: Python<'py>,
        call: Call,
        a: &Bound<'py, PyAny>,
        b: &Bound<'py, PyAny>,
        options: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let mut cp = crg::ContactPoint::new(self.shared());
        set_options(&mut cp, options)?;
        evaluate(py, &mut cp, call, a, b, None)
    }
}

impl Road {
    /// The surface mesh with `options`, simplified within `max_error` when given (see
    /// `to_mesh`).
    fn mesh(
        &self,
        py: Python<'_>,
        u: Option<(f64, f64)>,
        v: Option<(f64, f64)>,
        max_error: Option<f64>,
        max_memory: Option<&Bound<'_, PyAny>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<::opencrg_tools::mesh::Mesh> {
        let mut cp = crg::ContactPoint::new(self.shared());
        set_options(&mut cp, options)?;
        let budget = errors::budget(max_memory)?;
        py.detach(|| match max_error {
            Some(bound) => ::opencrg_tools::simplify::simplified_mesh(&cp, u, v, bound, &budget, &mut |_| {}),
            None => ::opencrg_tools::mesh::grid_mesh(&cp, u, v, &budget),
        })
        .map_err(errors::to_py)
    }
}

/// A read-only numpy array holding a copy of `values`.
fn frozen<'py, T: numpy::Element + Copy>(py: Python<'py>, values: &[T]) -> PyResult<Bound<'py, PyArray1<T>>> {
    let array = PyArray1::from_slice(py, values);
    array.getattr("flags")?.setattr("writeable", false)?;
    Ok(array)
}

#[pymethods]
impl Road {
    #[new]
    #[pyo3(signature = (path, *, compat = None, in_place = None, cache = None))]
    fn new(
        py: Python<'_>,
        path: PathBuf,
        compat: Option<&str>,
        in_place: Option<&Bound<'_, PyAny>>,
        cache: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let options = LoadOptions {
            compat: self::compat(compat)?,
            in_place: self::in_place(in_place)?,
            tile_cache: self::cache(cache)?,
            ..LoadOptions::default()
        };
        let road = py.detach(|| crg::Road::load_with(&path, options)).map_err(errors::to_py)?;
        let recipe = Recipe::file(&path, options, road.grid().is_in_place());
        Ok(Road::from_core(road, recipe))
    }

    /// Whether the road's grid is read in place from its file (else it is in memory).
    #[getter]
    fn in_place(&self) -> bool {
        self.inner.grid().is_in_place()
    }

    /// A road from the bytes of a CRG file; `name` stands for the file in messages and
    /// relative file references are looked up beside it.
    #[staticmethod]
    #[pyo3(signature = (data, name = "<bytes>", *, compat = None))]
    fn from_bytes(py: Python<'_>, data: Vec<u8>, name: &str, compat: Option<&str>) -> PyResult<Self> {
        let options = LoadOptions { compat: self::compat(compat)?, ..LoadOptions::default() };
        let data = Arc::new(data);
        let road = py.detach(|| crg::Road::from_bytes_with(data.to_vec(), name, options)).map_err(errors::to_py)?;
        Ok(Road::from_core(road, Recipe::bytes(data, name, options.compat)))
    }

    /// Pickling: the function that makes the road again, and its recipe.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let make = py.import("opencrg")?.getattr("_road_from_recipe")?;
        Ok((make, PyTuple::new(py, [self.recipe.to_py(py)?])?))
    }

    /// Checks the road as `crgCheck` does; raises `opencrg.CheckError` when it fails.
    fn check(&mut self, py: Python<'_>) -> PyResult<()> {
        self.change(py, Step::Check)
    }

    /// Applies the modifiers (the file's, or those set since) to the data.
    fn apply_modifiers(&mut self, py: Python<'_>) -> PyResult<()> {
        self.change(py, Step::ApplyModifiers)
    }

    /// Sets one modifier (`road.set_modifier("refline_offset_phi", 0.5)`, see
    /// `opencrg.MODIFIERS`); it acts at the next `apply_modifiers()`.
    fn set_modifier(&mut self, py: Python<'_>, name: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let s = names::lookup(Family::Modifier, name)?;
        match names::value_for(s, value)? {
            Some(v) => self.change(py, Step::SetModifier(s.id, v)),
            None => self.change(py, Step::RemoveModifier(s.id)),
        }
    }

    /// Removes one modifier.
    fn remove_modifier(&mut self, py: Python<'_>, name: &str) -> PyResult<()> {
        let s = names::lookup(Family::Modifier, name)?;
        self.change(py, Step::RemoveModifier(s.id))
    }

    /// Removes every modifier.
    fn clear_modifiers(&mut self, py: Python<'_>) -> PyResult<()> {
        self.change(py, Step::ClearModifiers)
    }

    /// The modifiers, by name.
    #[getter]
    fn modifiers<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        names::to_dict(py, self.inner.modifiers())
    }

    /// The road's options (the defaults and the file's), by name: where contact points start.
    #[getter]
    fn options<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        names::to_dict(py, self.inner.options())
    }

    /// Writes the road to `path` in `format` (`"KDBI"`, `"KRBI"`, `"LDFI"` or `"LRFI"`).
    #[pyo3(signature = (path, format = "KDBI"))]
    fn write(&self, py: Python<'_>, path: PathBuf, format: &str) -> PyResult<()> {
        let format = DataFormat::from_letters(format).ok_or_else(|| {
            crate::errors::request_error(format!("unknown format '{format}': KDBI, KRBI, LDFI or LRFI"))
        })?;
        py.detach(|| crg::write(&self.inner, &path, format)).map_err(errors::to_py)
    }

    /// (first, last) u of the data.
    #[getter]
    fn u_range(&self) -> (f64, f64) {
        self.inner.u_range()
    }

    /// (right, left) v of the data.
    #[getter]
    fn v_range(&self) -> (f64, f64) {
        self.inner.v_range()
    }

    /// (u, v) increments.
    #[getter]
    fn increments(&self) -> (f64, f64) {
        self.inner.increments()
    }

    /// (u begin, u end) of a closed track, or None.
    #[getter]
    fn closed_track(&self) -> Option<(f64, f64)> {
        self.inner.closed_track()
    }

    /// (closed, u begin, u end) as the C API's `crgDataSetGetUtilityDataClosedTrack` reports
    /// them: whether the line is closed, and the u range found the last time it could be
    /// closed ((0.0, 0.0) if never), also when modifiers have since opened it.
    #[getter]
    fn closed_track_report(&self) -> (bool, f64, f64) {
        self.inner.closed_track_report()
    }

    /// The behaviour profile: `"upstream"` or `"2.0.1"`.
    #[getter]
    fn compat(&self) -> String {
        self.inner.compat().to_string()
    }

    /// The file loaded.
    #[getter]
    fn path(&self) -> String {
        self.inner.header().path.display().to_string()
    }

    /// The data format of the file: `"KRBI"`, `"KDBI"`, `"LRFI"` or `"LDFI"`.
    #[getter]
    fn format(&self) -> &'static str {
        self.inner.format().name()
    }

    /// What the reader noticed without refusing the file (misspelt keywords, ...).
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.inner.warnings().to_vec()
    }

    /// The elevation grid, float32, shape (number of cross sections, number of long
    /// sections), NaN kept; read-only.
    #[getter]
    fn grid(&mut self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        if let Some(grid) = &self.grid {
            return Ok(grid.clone_ref(py));
        }
        let g = self.inner.grid();
        // Stored long section by long section: an nv x nu array, seen as its transpose.
        let array = PyArray1::from_slice(py, g.values()).reshape([g.nv, g.nu])?.transpose()?;
        array.getattr("flags")?.setattr("writeable", false)?;
        let array = array.into_any().unbind();
        self.grid = Some(array.clone_ref(py));
        Ok(array)
    }

    /// v of each long section (float64, read-only).
    #[getter]
    fn v<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        frozen(py, &self.inner.grid().v)
    }

    /// The reference line at each cross section: a named tuple of read-only float64
    /// arrays `(u, x, y, phi, z)`.
    #[getter]
    fn reference_line<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let class = reference_line_class(py)?;
        let l = self.inner.reference_line();
        let each = |f: &dyn Fn(usize) -> f64| (0..l.n).map(f).collect::<Vec<f64>>();
        let columns =
            [each(&|i| l.u_at(i)), l.x.clone(), l.y.clone(), each(&|i| l.heading_at(i)), each(&|i| l.z_at(i))];
        let arrays = columns.iter().map(|c| frozen(py, c)).collect::<PyResult<Vec<_>>>()?;
        class.call1(PyTuple::new(py, arrays)?)
    }

    /// The header sections as read: `comments` ($CT lines), `road_crg` ($ROAD_CRG
    /// keywords and values), `options` ($ROAD_CRG_OPTS over the defaults), `modifiers`,
    /// `mpro` ($ROAD_CRG_MPRO), `references` (files read through $ROAD_CRG_FILE),
    /// `format` and `channels` ($KD_Definition).
    #[getter]
    fn header<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let h = self.inner.header();
        let dict = PyDict::new(py);
        dict.set_item("comments", PyList::new(py, &h.comments)?)?;
        let road = PyDict::new(py);
        for (key, value) in h.road.entries() {
            road.set_item(key, value)?;
        }
        dict.set_item("road_crg", road)?;
        dict.set_item("options", names::to_dict(py, &h.options)?)?;
        dict.set_item("modifiers", names::to_dict(py, &h.modifiers)?)?;
        let mpro = PyDict::new(py);
        for (key, value) in &h.mpro {
            mpro.set_item(key, value)?;
        }
        dict.set_item("mpro", mpro)?;
        let references: Vec<String> = h.references.iter().map(|p| p.display().to_string()).collect();
        dict.set_item("references", references)?;
        dict.set_item("format", h.format.name())?;
        let channels: Vec<String> = h.channels.iter().map(ToString::to_string).collect();
        dict.set_item("channels", channels)?;
        Ok(dict)
    }

    /// The surface as a triangle mesh at the grid nodes with u in `u` and v in `v`
    /// (`(from, to)` in m; the whole road by default), evaluated with `options`: a dict
    /// of numpy arrays `positions` (n x 3 float64, x/y/z), `normals` (n x 3 float32),
    /// `texcoords` (n x 2 float32), `triangles` (m x 3 uint32), `u` and `v` (the nodes;
    /// vertex `i * len(v) + j` lies at `u[i]`, `v[j]`). Cells without elevation are left out.
    /// With `max_error` (m): a simplified mesh whose z stays within it of the road's at
    /// every grid node, its `u` and `v` empty.
    #[pyo3(signature = (u = None, v = None, max_error = None, *, max_memory = None, **options))]
    fn to_mesh<'py>(
        &self,
        py: Python<'py>,
        u: Option<(f64, f64)>,
        v: Option<(f64, f64)>,
        max_error: Option<f64>,
        max_memory: Option<&Bound<'py, PyAny>>,
        options: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let mesh = self.mesh(py, u, v, max_error, max_memory, options)?;
        let d = PyDict::new(py);
        d.set_item("positions", matrix(py, &mesh.positions)?)?;
        d.set_item("normals", matrix(py, &mesh.normals)?)?;
        d.set_item("texcoords", matrix(py, &mesh.texcoords)?)?;
        d.set_item("triangles", matrix(py, &mesh.triangles)?)?;
        d.set_item("u", PyArray1::from_slice(py, &mesh.u))?;
        d.set_item("v", PyArray1::from_slice(py, &mesh.v))?;
        Ok(d)
    }

    /// Writes the surface mesh (see `to_mesh`) to `path`, the format from its extension:
    /// `.obj`, `.stl`, `.ply` or `.glb`.
    #[pyo3(signature = (path, u = None, v = None, max_error = None, *, max_memory = None, **options))]
    #[allow(clippy::too_many_arguments)]
    fn write_mesh<'py>(
        &self,
        py: Python<'py>,
        path: PathBuf,
        u: Option<(f64, f64)>,
        v: Option<(f64, f64)>,
        max_error: Option<f64>,
        max_memory: Option<&Bound<'py, PyAny>>,
        options: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<()> {
        let format = ::opencrg_tools::mesh_files::MeshFormat::from_path(&path).ok_or_else(|| {
            crate::errors::request_error(format!("{}: unknown mesh format; .obj, .stl, .ply or .glb", path.display()))
        })?;
        let mesh = self.mesh(py, u, v, max_error, max_memory, options)?;
        py.detach(|| ::opencrg_tools::mesh_files::write_mesh(&mesh, &path, format)).map_err(errors::to_py)
    }

    /// How rough the road is along wheel tracks at `tracks` (v in m; default -0.85, 0 and
    /// 0.85): per track the IRI (m/km) over it and per `segment` metres, and the ISO 8608
    /// density, fit and class; a list of dicts (see the guide).
    #[pyo3(signature = (tracks = None, segment = ::opencrg_tools::roughness::DEFAULT_SEGMENT))]
    fn roughness<'py>(&self, py: Python<'py>, tracks: Option<Vec<f64>>, segment: f64) -> PyResult<Bound<'py, PyList>> {
        let tracks = tracks.unwrap_or_else(|| ::opencrg_tools::roughness::DEFAULT_TRACKS.to_vec());
        let road = self.shared();
        let found =
            py.detach(|| ::opencrg_tools::roughness::roughness(&road, &tracks, segment)).map_err(errors::to_py)?;
        crate::roughness::tracks_list(py, &found)
    }

    fn __repr__(&self) -> String {
        let (u0, u1) = self.inner.u_range();
        let (v0, v1) = self.inner.v_range();
        format!(
            "<opencrg.Road {} ({}), u {u0} .. {u1} m, v {v0} .. {v1} m>",
            self.inner.header().path.display(),
            self.inner.format().name()
        )
    }
}

/// The evaluations as methods of `Road`: `road.uv_to_z(u, v, **options)`, ... on a new
/// contact point with the road's options and the keyword options.
macro_rules! road_evaluations {
    ($($doc:literal $name:ident($a:ident, $b:ident) $call:ident,)*) => {
        #[pymethods]
        impl Road {
            $(
                #[doc = $doc]
                #[doc = ""]
                #[doc = "Options as keyword arguments (see `opencrg.OPTIONS`)."]
                #[pyo3(signature = ($a, $b, **options))]
                fn $name<'py>(
                    &self,
                    py: Python<'py>,
                    $a: &Bound<'py, PyAny>,
                    $b: &Bound<'py, PyAny>,
                    options: Option<&Bound<'py, PyDict>>,
                ) -> PyResult<Bound<'py, PyAny>> {
                    self.eval_with(py, Call::$call, $a, $b, options)
                }
            )*
        }
    };
}
for_each_evaluation!(road_evaluations);

/// Makes a pickled road again (see `Road.__reduce__`).
#[pyfunction]
pub(crate) fn _road_from_recipe(py: Python<'_>, state: &Bound<'_, PyAny>) -> PyResult<Road> {
    let recipe = Recipe::from_py(state)?;
    let road = recipe.make(py)?;
    Ok(Road::from_core(road, recipe))
}

/// Rows of `K` values as a numpy array of shape (rows, K).
pub(crate) fn matrix<'py, T: numpy::Element + Copy, const K: usize>(
    py: Python<'py>,
    rows: &[[T; K]],
) -> PyResult<Bound<'py, numpy::PyArray2<T>>> {
    PyArray1::from_iter(py, rows.iter().flatten().copied()).reshape([rows.len(), K])
}
