//! Roads on the earth in Python: the global origin and the conversions between local
//! x/y/z, projected east/north/height and geodetic latitude/longitude/height, vectorised
//! over numpy arrays like the evaluations.

use crate::arrays::Points;
use crate::errors;
use crate::recipe::Step;
use crate::road::Road;
use ::opencrg_core as crg;
use pyo3::prelude::*;

/// Converts every point of three broadcast coordinates with `f`; NaN where it fails.
fn convert<'py>(
    py: Python<'py>,
    inputs: [&Bound<'py, PyAny>; 3],
    f: impl Fn([f64; 3]) -> crg::Result<[f64; 3]> + Send + Sync,
) -> PyResult<Bound<'py, PyAny>> {
    let points = Points::new(inputs)?;
    let [a, b, c] = points.slices()?;
    let outputs = py.detach(|| {
        let mut out: Vec<Vec<f64>> = (0..3).map(|_| Vec::with_capacity(a.len())).collect();
        for i in 0..a.len() {
            let r = f([a[i], b[i], c[i]]).unwrap_or([f64::NAN; 3]);
            for (column, value) in out.iter_mut().zip(r) {
                column.push(value);
            }
        }
        out
    });
    points.results(py, outputs)
}

impl Road {
    /// The road and the chain of its map projection; `ValueError` for a road without one.
    fn on_earth(&self) -> PyResult<(std::sync::Arc<crg::Road>, crg::Earth)> {
        let road = self.shared();
        let earth = crg::Earth::of(&road).map_err(errors::to_py)?;
        Ok((road, earth))
    }
}

#[pymethods]
impl Road {
    /// The global origin `(x, y, z, phi)`: how the local frame sits in the projected
    /// east/north/height frame (`REFERENCE_LINE_OFFSET_*`, kept up to date by modifiers
    /// that move the road). Setting it moves the global frame, not the road.
    #[getter]
    fn global_origin(&self) -> (f64, f64, f64, f64) {
        let o = self.shared().global_origin();
        (o.x, o.y, o.z, o.phi)
    }

    #[setter]
    fn set_global_origin(&mut self, py: Python<'_>, origin: (f64, f64, f64, f64)) -> PyResult<()> {
        let (x, y, z, phi) = origin;
        if ![x, y, z, phi].iter().all(|v| v.is_finite()) {
            return Err(crate::errors::request_error("the global origin must be finite"));
        }
        self.change(py, Step::SetGlobalOrigin([x, y, z, phi]))
    }

    /// East, north and height `(e, n, h)` of local points `(x, y, z)` (scalars or arrays,
    /// broadcast together).
    fn xyz_to_enh<'py>(
        &self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        y: &Bound<'py, PyAny>,
        z: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let road = self.shared();
        convert(py, [x, y, z], |p| Ok(road.xyz_to_enh(p[0], p[1], p[2])))
    }

    /// Local points `(x, y, z)` at east, north and height `(e, n, h)`.
    fn enh_to_xyz<'py>(
        &self,
        py: Python<'py>,
        e: &Bound<'py, PyAny>,
        n: &Bound<'py, PyAny>,
        h: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let road = self.shared();
        convert(py, [e, n, h], |p| Ok(road.enh_to_xyz(p[0], p[1], p[2])))
    }

    /// Latitude, longitude (degrees) and height `(lat, lon, alt)` on the global ellipsoid
    /// (WGS 84 unless the map section names another) of local points `(x, y, z)`.
    /// Raises `ValueError` for a road without a map projection; NaN for points the
    /// projection cannot take.
    fn xyz_to_llh<'py>(
        &self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        y: &Bound<'py, PyAny>,
        z: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (road, earth) = self.on_earth()?;
        convert(py, [x, y, z], |p| earth.xyz_to_llh(&road, p))
    }

    /// Local points `(x, y, z)` at latitude, longitude (degrees) and height on the global
    /// ellipsoid. Raises `ValueError` for a road without a map projection.
    fn llh_to_xyz<'py>(
        &self,
        py: Python<'py>,
        lat: &Bound<'py, PyAny>,
        lon: &Bound<'py, PyAny>,
        alt: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (road, earth) = self.on_earth()?;
        convert(py, [lat, lon, alt], |p| earth.llh_to_xyz(&road, p))
    }

    /// The map projection of the road's `$ROAD_CRG_MPRO` section as a dict (ellipsoids,
    /// datum transformation, projection parameters; angles in radians), or `None`.
    #[getter]
    fn map_projection<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, pyo3::types::PyDict>>> {
        let road = self.shared();
        let Some(m) = road.header().map.as_ref() else { return Ok(None) };
        let d = pyo3::types::PyDict::new(py);
        d.set_item("global_ellipsoid", (&m.global.name, m.global.a, m.global.b))?;
        d.set_item("local_ellipsoid", (&m.local.name, m.local.a, m.local.b))?;
        d.set_item("transformation", m.datum.kind.name())?;
        d.set_item("ds", m.datum.ds)?;
        d.set_item("rotation", m.datum.rotation.to_vec())?;
        d.set_item("translation", m.datum.translation.to_vec())?;
        let p = &m.projection;
        d.set_item("projection", &p.name)?;
        d.set_item("scale", p.scale)?;
        d.set_item("lat0", p.lat0)?;
        d.set_item("lon0", p.lon0)?;
        d.set_item("false_east", p.false_east)?;
        d.set_item("false_north", p.false_north)?;
        Ok(Some(d))
    }
}
