//! The `opencrg` Python module: roads loaded and evaluated by the Rust core, with
//! numpy arrays in and out and the GIL released while the core works.
//!
//! - `road`: `opencrg.Road`, the loaded data (grid, reference line, header sections,
//!   modifiers, checks, writing);
//! - `contact`: `opencrg.ContactPoint`, a road with options and a search history;
//! - `evaluation`: the core's batch calls on Python inputs, options by name;
//! - `arrays`: turning Python scalars and array-likes into slices and back;
//! - `names`: the options' and modifiers' Python names, from the core's settings table;
//! - `recipe`: how a road was made and changed, what a pickled road carries;
//! - `roughness`: IRI and ISO 8608 of tracks and profiles;
//! - `tools`: new roads from roads (cut, flip, append, resample, filter, slope, banking)
//!   and from points (generate, import_points), point files, comparisons;
//! - `odr`: `opencrg.odr`, OpenDRIVE maps with CRG surfaces;
//! - `fmu`: `write_fmu`, a road or a map packed as an FMU;
//! - `errors`: the core's errors as Python exceptions.

use pyo3::prelude::*;

mod arrays;
mod contact;
mod errors;
mod evaluation;
mod fmu;
mod georef;
mod names;
mod odr;
mod recipe;
mod road;
mod roughness;
mod tools;

/// The module `opencrg`.
#[pymodule(name = "opencrg")]
fn opencrg_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<road::Road>()?;
    m.add("ReferenceLine", road::reference_line_class(m.py())?)?;
    m.add_class::<contact::ContactPoint>()?;
    m.add_function(wrap_pyfunction!(road::_road_from_recipe, m)?)?;
    m.add_function(wrap_pyfunction!(contact::_contact_point_from_state, m)?)?;
    m.add_function(wrap_pyfunction!(roughness::iri, m)?)?;
    m.add_function(wrap_pyfunction!(roughness::psd, m)?)?;
    roughness::register(m)?;
    m.add_function(wrap_pyfunction!(tools::generate, m)?)?;
    m.add_function(wrap_pyfunction!(tools::import_points, m)?)?;
    m.add_function(wrap_pyfunction!(tools::read_points, m)?)?;
    m.add_function(wrap_pyfunction!(tools::compare, m)?)?;
    m.add_function(wrap_pyfunction!(fmu::write_fmu, m)?)?;
    errors::register(m)?;
    names::register(m)?;
    odr::register(m)?;
    Ok(())
}
