//! The core's errors as Python exceptions.
//!
//! A missing file is `FileNotFoundError` (with `filename` set), other read and write
//! failures `OSError`; a file with wrong content `opencrg.FormatError` (also a
//! `ValueError`), a failed check `opencrg.CheckError`, a refused request (a setting or
//! option, a parameter out of range, a size beyond the memory limit)
//! `opencrg.RequestError` (also a `ValueError`). Every text names the file, and the line
//! and field where one is known.

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

/// The class `name` with the bases `CrgError` and `ValueError`, made once in `cell`.
fn value_error_class<'py>(
    py: Python<'py>,
    cell: &'static PyOnceLock<Py<PyType>>,
    name: &str,
    doc: &str,
) -> PyResult<&'py Bound<'py, PyType>> {
    let class = cell.get_or_try_init(py, || -> PyResult<Py<PyType>> {
        let bases = PyTuple::new(py, [py.get_type::<CrgError>(), py.get_type::<PyValueError>()])?;
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

/// An `opencrg.RequestError` saying `text`.
pub(crate) fn request_error(text: impl Into<String>) -> PyErr {
    let text = text.into();
    Python::attach(|py| match request_class(py) {
        Ok(class) => PyErr::from_type(class.clone(), text),
        Err(e) => e,
    })
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
    Ok(())
}

/// The Python exception of a core error.
pub(crate) fn to_py(e: Error) -> PyErr {
    let text = e.to_string();
    match e {
        Error::Io { path, source } | Error::Write { path, source } => {
            let errno = source.raw_os_error().unwrap_or(0);
            let file = path.display().to_string();
            if source.kind() == std::io::ErrorKind::NotFound {
                PyFileNotFoundError::new_err((errno, text, file))
            } else {
                PyOSError::new_err((errno, text, file))
            }
        }
        Error::Format { .. } => Python::attach(|py| match format_error(py) {
            Ok(class) => PyErr::from_type(class.clone(), text),
            Err(e) => e,
        }),
        Error::Check(_) => CheckError::new_err(text),
        Error::Setting(_) | Error::Eval(_) | Error::Analysis(_) | Error::Geo(_) | Error::Request(_) => {
            request_error(text)
        }
    }
}
