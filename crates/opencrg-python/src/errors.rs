//! The core's errors as Python exceptions.
//!
//! A missing file is `FileNotFoundError` (with `filename` set), other read and write
//! failures `OSError`; a file with wrong content `opencrg.FormatError` (also a
//! `ValueError`), a failed check `opencrg.CheckError`, a refused setting or option
//! `ValueError`. Every text names the file, and the line and field where one is known.

use ::opencrg::Error;
use pyo3::exceptions::{PyException, PyFileNotFoundError, PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyDict, PyTuple, PyType};

pyo3::create_exception!(opencrg, CrgError, PyException, "Base of the errors of this module.");
pyo3::create_exception!(opencrg, CheckError, CrgError, "A road refused by `Road.check()`.");

/// `FormatError(CrgError, ValueError)`, made once: a class with two bases.
static FORMAT_ERROR: PyOnceLock<Py<PyType>> = PyOnceLock::new();

fn format_error(py: Python<'_>) -> PyResult<&Bound<'_, PyType>> {
    let class = FORMAT_ERROR.get_or_try_init(py, || -> PyResult<Py<PyType>> {
        let bases = PyTuple::new(py, [py.get_type::<CrgError>(), py.get_type::<PyValueError>()])?;
        let namespace = PyDict::new(py);
        namespace.set_item("__doc__", "A road file whose content is wrong (names the file, line and field).")?;
        namespace.set_item("__module__", "opencrg")?;
        let class = py.get_type::<PyType>().call1(("FormatError", bases, namespace))?;
        Ok(class.cast_into::<PyType>()?.unbind())
    })?;
    Ok(class.bind(py))
}

/// Adds the exception classes to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("CrgError", py.get_type::<CrgError>())?;
    m.add("FormatError", format_error(py)?)?;
    m.add("CheckError", py.get_type::<CheckError>())?;
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
            PyValueError::new_err(text)
        }
    }
}
