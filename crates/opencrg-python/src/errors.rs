//! The core's errors as Python exceptions, one class per kind of the core's `Error`.
//!
//! A missing file is `FileNotFoundError` (with `filename` set), other read and write
//! failures `OSError`; a file with wrong content `opencrg.FormatError` (also a
//! `ValueError`), a failed check `opencrg.CheckError`; a refused request
//! `opencrg.RequestError` (also a `ValueError`), as `opencrg.TooLargeError` (also a
//! `MemoryError`) when it is beyond the memory limit and `opencrg.OutOfRangeError` when a
//! value is one the request does not take (a parameter out of range, a setting or option
//! refused). Every text names the file, and the line and field where one is known.

use ::opencrg_core::{Budget, Error};
use pyo3::exceptions::{PyException, PyFileNotFoundError, PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyDict, PyTuple, PyType};

pyo3::create_exception!(opencrg, CrgError, PyException, "Base of the errors of this module.");
pyo3::create_exception!(opencrg, CheckError, CrgError, "A road refused by `Road.check()`.");

/// `FormatError(CrgError, ValueError)` and `RequestError(CrgError, ValueError)`, each
/// made once: classes with two bases.
static FORMAT_ERROR: PyOnceLock<Py<PyType>> = PyOnceLock::new();
static REQUEST_ERROR: PyOnceLock<Py<PyType>> = PyOnceLock::new();
static TOO_LARGE_ERROR: PyOnceLock<Py<PyType>> = PyOnceLock::new();
static OUT_OF_RANGE_ERROR: PyOnceLock<Py<PyType>> = PyOnceLock::new();

/// The class `name` with the bases `CrgError` and `ValueError`, made once in `cell`.
fn value_error_class<'py>(
    py: Python<'py>,
    cell: &'static PyOnceLock<Py<PyType>>,
    name: &str,
    doc: &str,
) -> PyResult<&'py Bound<'py, PyType>> {
    class_of(py, cell, name, doc, || Ok([py.get_type::<CrgError>(), py.get_type::<PyValueError>()]))
}

/// The class `name` with the bases `bases` gives, made once in `cell`.
fn class_of<'py, const N: usize>(
    py: Python<'py>,
    cell: &'static PyOnceLock<Py<PyType>>,
    name: &str,
    doc: &str,
    bases: impl FnOnce() -> PyResult<[Bound<'py, PyType>; N]>,
) -> PyResult<&'py Bound<'py, PyType>> {
    let class = cell.get_or_try_init(py, || -> PyResult<Py<PyType>> {
        let bases = PyTuple::new(py, bases()?)?;
        let namespace = PyDict::new(py);
        namespace.set_item("__doc__", doc)?;
        namespace.set_item("__module__", "opencrg")?;
        let class = py.get_type::<PyType>().call1((name, bases, namespace))?;
        Ok(class.cast_into::<PyType>()?.unbind())
    })?;
    Ok(class.bind(py))
}

fn format_error(py: Python<'_>) -> PyResult<&Bound<'_, PyType>> {
    value_error_class(
        py,
        &FORMAT_ERROR,
        "FormatError",
        "A road file whose content is wrong (names the file, line and field).",
    )
}

fn request_class(py: Python<'_>) -> PyResult<&Bound<'_, PyType>> {
    value_error_class(
        py,
        &REQUEST_ERROR,
        "RequestError",
        "A request refused before any work: a parameter out of range, a size beyond the memory limit, \
         a setting or option the library does not take.",
    )
}

fn too_large_class(py: Python<'_>) -> PyResult<&Bound<'_, PyType>> {
    class_of(
        py,
        &TOO_LARGE_ERROR,
        "TooLargeError",
        "A request that would take more memory than it may (max_memory=, or half of what the system has).",
        || Ok([request_class(py)?.clone(), py.get_type::<pyo3::exceptions::PyMemoryError>()]),
    )
}

fn out_of_range_class(py: Python<'_>) -> PyResult<&Bound<'_, PyType>> {
    class_of(
        py,
        &OUT_OF_RANGE_ERROR,
        "OutOfRangeError",
        "A value the request does not take: a parameter out of range, a setting or option refused, \
         a road without what the request needs.",
        || Ok([request_class(py)?.clone()]),
    )
}

/// An exception of the class `class` gives, saying `text`.
fn raised(class: impl for<'py> FnOnce(Python<'py>) -> PyResult<&'py Bound<'py, PyType>>, text: String) -> PyErr {
    Python::attach(|py| match class(py) {
        Ok(class) => PyErr::from_type(class.clone(), text),
        Err(e) => e,
    })
}

/// The refusal of an argument the binding itself does not take (an `opencrg.OutOfRangeError`,
/// an `opencrg.RequestError`) saying `text`.
pub(crate) fn request_error(text: impl Into<String>) -> PyErr {
    raised(out_of_range_class, text.into())
}

/// The memory limit of one call: `max_memory` in bytes (an int, or a text like "8G" or
/// "512MiB"), or half of what the system has available when `None`.
pub(crate) fn budget(max_memory: Option<&Bound<'_, PyAny>>) -> PyResult<Budget> {
    let Some(given) = max_memory else { return Ok(Budget::machine().raised_with("max_memory=")) };
    let bytes = if let Ok(n) = given.extract::<i128>() {
        u64::try_from(n)
            .ok()
            .filter(|&n| n > 0)
            .ok_or_else(|| request_error(format!("max_memory={n}: at least one byte")))?
    } else if let Ok(text) = given.extract::<String>() {
        ::opencrg_core::parse_bytes(&text).map_err(|e| request_error(format!("max_memory={e}")))?
    } else {
        return Err(request_error("max_memory: bytes as an int, or a text like '8G' or '512MiB'"));
    };
    Ok(Budget::with_bytes(bytes).raised_with("max_memory="))
}

/// Adds the exception classes to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("CrgError", py.get_type::<CrgError>())?;
    m.add("FormatError", format_error(py)?)?;
    m.add("CheckError", py.get_type::<CheckError>())?;
    m.add("RequestError", request_class(py)?)?;
    m.add("TooLargeError", too_large_class(py)?)?;
    m.add("OutOfRangeError", out_of_range_class(py)?)?;
    Ok(())
}

/// The Python exception of a core error.
pub(crate) fn to_py(e: Error) -> PyErr {
    let text = e.to_string();
    match e {
        Error::NotFound { path, source } => {
            PyFileNotFoundError::new_err((source.raw_os_error().unwrap_or(0), text, path.display().to_string()))
        }
        Error::Io { path, source, .. } => {
            PyOSError::new_err((source.raw_os_error().unwrap_or(0), text, path.display().to_string()))
        }
        Error::Format { .. } => raised(format_error, text),
        Error::Check(_) => CheckError::new_err(text),
        Error::TooLarge(_) => raised(too_large_class, text),
        Error::OutOfRange(_) => raised(out_of_range_class, text),
    }
}
