//! `write_fmu`: a CRG file or an OpenDRIVE map packed as an FMU for simulation tools.

use crate::errors::{request_error, to_py};
use ::opencrg_fmu::Fmi;
use ::opencrg_tools::fmu::{binaries_in, write_fmu as pack, Binary, FmuOptions};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::{Path, PathBuf};

/// The FMU binaries: in `binaries`, else in `$OPENCRG_FMU_BINARIES`, else those the
/// installed package carries (its `fmu` folder).
fn binaries(py: Python<'_>, named: Option<PathBuf>) -> PyResult<Vec<Binary>> {
    let (folder, whence) = match named {
        Some(folder) => (folder, "binaries"),
        None => match std::env::var_os("OPENCRG_FMU_BINARIES") {
            Some(folder) => (PathBuf::from(folder), "OPENCRG_FMU_BINARIES"),
            None => {
                let init: PathBuf = py.import("opencrg")?.getattr("__file__")?.extract()?;
                (init.parent().unwrap_or(Path::new(".")).join("fmu"), "the package's fmu folder")
            }
        },
    };
    let found = binaries_in(&folder);
    if found.is_empty() {
        return Err(request_error(format!(
            "{whence} ({}): no FMU binary there (PLATFORM/FILE, as x86_64-linux/libopencrg_fmi.so); \
             a package built from source carries none: build opencrg-fmi and name its folder",
            folder.display()
        )));
    }
    Ok(found)
}

/// Packs the road in `road` (a CRG file, or an OpenDRIVE map with the CRG files its
/// records name) as an FMU in `path`: FMI 2.0 or 3.0 (`fmi`), model exchange and
/// co-simulation, answering height, normal and friction under `wheels` wheels; with
/// `road_outside`, a CRG file is named by its absolute path instead of packed. Returns
/// what was packed: `identifier`, `resources`, `platforms`, `variables`.
#[pyfunction]
#[pyo3(signature = (road, path, wheels = 4, fmi = 2, binaries = None, *, road_outside = false))]
pub(crate) fn write_fmu<'py>(
    py: Python<'py>,
    road: PathBuf,
    path: PathBuf,
    wheels: u32,
    fmi: u32,
    binaries: Option<PathBuf>,
    road_outside: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let fmi = match fmi {
        2 => Fmi::V2,
        3 => Fmi::V3,
        other => return Err(request_error(format!("fmi={other}: 2 or 3"))),
    };
    let options = FmuOptions { wheels, fmi, binaries: self::binaries(py, binaries)?, outside: road_outside };
    let report = py.detach(|| pack(&road, &path, &options)).map_err(to_py)?;
    let d = PyDict::new(py);
    d.set_item("identifier", report.identifier)?;
    d.set_item("resources", report.resources)?;
    d.set_item("platforms", report.platforms.iter().map(|p| p.tuple()).collect::<Vec<_>>())?;
    d.set_item("variables", report.variables)?;
    Ok(d)
}
