//! The Python names of options and modifiers, read from the core's settings table: the
//! file keyword in lower case (`border_mode_u`, `refline_offset_phi`), or, for a setting
//! files cannot carry, its C constant without prefix in snake case (`curv_mode`).

use ::opencrg_core::settings::{self, Accepts, Family, Kind, SettingInfo, Settings, Value, SETTINGS};
use ::opencrg_core::settings::{BorderMode, NanMode};
use ::opencrg_core::{Continuation, CurvMode};
use pyo3::exceptions::{PyKeyError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The Python name of a setting: its name in code, lower-cased.
pub(crate) fn python_name(s: &SettingInfo) -> String {
    s.code_name().to_ascii_lowercase()
}

/// The setting of `family` named `name` in Python.
pub(crate) fn lookup(family: Family, name: &str) -> PyResult<&'static SettingInfo> {
    SETTINGS.iter().find(|s| s.family == family && python_name(s) == name).ok_or_else(|| {
        let known: Vec<String> = SETTINGS.iter().filter(|s| s.family == family).map(python_name).collect();
        let what = if family == Family::Option { "option" } else { "modifier" };
        PyKeyError::new_err(format!("unknown {what} '{name}'; known: {}", known.join(", ")))
    })
}

/// A Python value checked against what the setting accepts; `None` for a check
/// switched off (the table holds only the checks that are on).
pub(crate) fn value_for(s: &SettingInfo, value: &Bound<'_, PyAny>) -> PyResult<Option<Value>> {
    let name = python_name(s);
    match s.kind {
        Kind::Int => {
            if value.is_instance_of::<pyo3::types::PyFloat>() {
                return Err(PyTypeError::new_err(format!("{name} takes an integer")));
            }
            let v: i64 = value.extract().map_err(|_| PyTypeError::new_err(format!("{name} takes an integer")))?;
            // (A choice out of range is refused by the core, with the C API's message.)
            let v = match s.accepts {
                // A check is on or off; the table stores it as its identifier.
                Accepts::Flag => match v {
                    0 => return Ok(None),
                    1 => i64::from(s.id),
                    _ => return Err(crate::errors::request_error(format!("{name} = {v}: expected True or False"))),
                },
                _ => v,
            };
            let v =
                i32::try_from(v).map_err(|_| crate::errors::request_error(format!("{name} = {v}: out of range")))?;
            Ok(Some(Value::Int(v)))
        }
        Kind::Double => {
            let v: f64 = value.extract().map_err(|_| PyTypeError::new_err(format!("{name} takes a number")))?;
            Ok(Some(Value::Double(v)))
        }
    }
}

/// A table as a dict of Python names to values.
pub(crate) fn to_dict<'py>(py: Python<'py>, table: &Settings) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for (id, value) in table.iter() {
        let Some(s) = settings::info(id) else { continue };
        match value {
            Value::Int(i) if s.accepts == Accepts::Flag => dict.set_item(python_name(s), i != 0)?,
            Value::Int(i) => dict.set_item(python_name(s), i)?,
            Value::Double(d) => dict.set_item(python_name(s), d)?,
        }
    }
    Ok(dict)
}

/// The named values of the choices, as module constants.
const CONSTANTS: [(&str, i32); 12] = [
    ("BORDER_NONE", BorderMode::None as i32),
    ("BORDER_EX_ZERO", BorderMode::ExZero as i32),
    ("BORDER_EX_KEEP", BorderMode::ExKeep as i32),
    ("BORDER_REPEAT", BorderMode::Repeat as i32),
    ("BORDER_REFLECT", BorderMode::Reflect as i32),
    ("REFLINE_EXTRAPOLATE", Continuation::Extrapolate as i32),
    ("REFLINE_CLOSE_TRACK", Continuation::CloseTrack as i32),
    ("CURV_LATERAL", CurvMode::Lateral as i32),
    ("CURV_REFLINE", CurvMode::RefLine as i32),
    ("GRID_NAN_KEEP", NanMode::Keep as i32),
    ("GRID_NAN_SET_ZERO", NanMode::SetZero as i32),
    ("GRID_NAN_KEEP_LAST", NanMode::KeepLast as i32),
];

/// Adds the choice constants, the lists of option and modifier names and the evaluation
/// calls' names (the core's list, which the methods of `Road` and `ContactPoint` follow).
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("EVALUATIONS", ::opencrg_core::Evaluation::ALL.map(::opencrg_core::Evaluation::name).to_vec())?;
    for (name, value) in CONSTANTS {
        m.add(name, value)?;
    }
    let names = |family| SETTINGS.iter().filter(|s| s.family == family).map(python_name).collect::<Vec<_>>();
    m.add("OPTIONS", names(Family::Option))?;
    m.add("MODIFIERS", names(Family::Modifier))?;
    Ok(())
}
