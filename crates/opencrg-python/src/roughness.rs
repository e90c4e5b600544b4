//! Roughness in Python: `Road.roughness` (the IRI and ISO 8608 class of wheel tracks)
//! and the module functions `iri` and `psd` on profiles given as numpy arrays.

use crate::errors;
use numpy::{AllowTypeChange, PyArray1, PyArrayLike1};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use pyo3::IntoPyObjectExt;

/// A spectrum as a dict: `gd_n0` (m³, w = 2), `w` and `gd_n0_fitted_w` (w fitted too),
/// `class`, `n_fitted`, `bands_n` and `bands_gd` (numpy), `segment_samples`, `segments`.
pub(crate) fn spectrum_dict<'py>(py: Python<'py>, s: &::opencrg_tools::psd::Spectrum) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("gd_n0", s.gd_n0)?;
    d.set_item("w", s.w)?;
    d.set_item("gd_n0_fitted_w", s.gd_n0_free)?;
    d.set_item("class", s.class.to_string())?;
    d.set_item("n_fitted", s.fitted)?;
    d.set_item("bands_n", PyArray1::from_iter(py, s.bands.iter().map(|b| b.0)))?;
    d.set_item("bands_gd", PyArray1::from_iter(py, s.bands.iter().map(|b| b.1)))?;
    d.set_item("segment_samples", s.segment_samples)?;
    d.set_item("segments", s.segments)?;
    Ok(d)
}

/// The tracks as a list of dicts: `v`, `iri` (m/km), `skipped_m`, `segments` (a list of
/// dicts `u_start`, `u_end`, `iri`, None where nothing was driven), `psd` (see
/// [`spectrum_dict`]).
pub(crate) fn tracks_list<'py>(
    py: Python<'py>,
    tracks: &[::opencrg_tools::roughness::Track],
) -> PyResult<Bound<'py, PyList>> {
    let list = PyList::empty(py);
    for t in tracks {
        let d = PyDict::new(py);
        d.set_item("v", t.v)?;
        d.set_item("iri", t.iri)?;
        d.set_item("skipped_m", t.skipped)?;
        let segments = PyList::empty(py);
        for s in &t.segments {
            let sd = PyDict::new(py);
            sd.set_item("u_start", s.u_start)?;
            sd.set_item("u_end", s.u_end)?;
            sd.set_item("iri", s.iri)?;
            segments.append(sd)?;
        }
        d.set_item("segments", segments)?;
        d.set_item("psd", spectrum_dict(py, &t.psd)?)?;
        list.append(d)?;
    }
    Ok(list)
}

/// ISO 8608's constants, for drawing the class bands: `ISO8608_N0` (cycles/m),
/// `ISO8608_LIMITS` (the upper limits of Gd(n0) of classes A to G, m³) and
/// `ISO8608_CLASSES` ("ABCDEFGH").
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("ISO8608_N0", ::opencrg_tools::psd::N0)?;
    m.add("ISO8608_LIMITS", ::opencrg_tools::psd::CLASS_LIMITS.to_vec())?;
    m.add("ISO8608_CLASSES", ::opencrg_tools::psd::CLASSES.iter().collect::<String>())?;
    Ok(())
}

/// The International Roughness Index (m/km, ASTM E1926) of a profile: elevations in m,
/// `dx` m apart, all finite, at least 11 m long. With `segment` (m), also the IRI of each
/// `segment` metres from the first sample: then `(iri, segments)`, a numpy array, NaN
/// for a segment without steps.
#[pyfunction]
#[pyo3(signature = (profile, dx, segment = None))]
pub(crate) fn iri<'py>(
    py: Python<'py>,
    profile: PyArrayLike1<'py, f64, AllowTypeChange>,
    dx: f64,
    segment: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let z: Vec<f64> = profile.as_array().iter().copied().collect();
    let r = py.detach(|| ::opencrg_tools::iri::response(&z, dx)).map_err(errors::to_py)?;
    let Some(segment) = segment else { return r.iri().into_bound_py_any(py) };
    let length = z.len().saturating_sub(1) as f64 * dx;
    let parts = ::opencrg_tools::iri::segment_iris(&[(0.0, &r)], length, segment).map_err(errors::to_py)?;
    let parts = parts.into_iter().map(|x| x.unwrap_or(f64::NAN));
    (r.iri(), PyArray1::from_iter(py, parts)).into_bound_py_any(py)
}

/// The displacement PSD of a profile (Welch, third-octave bands) and its ISO 8608 fit
/// and class, as a dict (see the guide).
#[pyfunction]
pub(crate) fn psd<'py>(
    py: Python<'py>,
    profile: PyArrayLike1<'py, f64, AllowTypeChange>,
    dx: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let z: Vec<f64> = profile.as_array().iter().copied().collect();
    let s = py.detach(|| ::opencrg_tools::psd::spectrum(&z, dx)).map_err(errors::to_py)?;
    spectrum_dict(py, &s)
}
