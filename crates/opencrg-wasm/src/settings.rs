//! Options and modifiers by name, as JavaScript gives them: the file's keywords in any
//! case (`BORDER_MODE_U`, `SCALE_Z_GRID`, and `CURV_MODE`), values as numbers; read from
//! the evaluator's one settings table.

use js_sys::{Object, Reflect};
use opencrg_core::settings::{Family, Kind, SettingInfo, Settings, Value, SETTINGS};
use wasm_bindgen::JsValue;

/// The setting of `family` named `name` (any case).
pub(crate) fn lookup(family: Family, name: &str) -> Result<&'static SettingInfo, Thrown> {
    SETTINGS.iter().find(|s| s.family == family && s.code_name().eq_ignore_ascii_case(name)).ok_or_else(|| {
        let known: Vec<String> = SETTINGS.iter().filter(|s| s.family == family).map(SettingInfo::code_name).collect();
        let what = if family == Family::Option { "option" } else { "modifier" };
        Thrown::request(&format!("unknown {what} '{name}'; known: {}", known.join(", ")))
    })
}

/// Sets `name` to `value` in `settings`, refused as the C API refuses it.
pub(crate) fn set(settings: &mut Settings, family: Family, name: &str, value: f64) -> Result<(), Thrown> {
    let info = lookup(family, name)?;
    let done = match info.kind {
        Kind::Int if value.fract() == 0.0 && value.abs() <= f64::from(i32::MAX) => {
            settings.set_int(info.id, value as i32)
        }
        Kind::Int => return Err(Thrown::request(&format!("{}: {value} is not an integer", info.code_name()))),
        Kind::Double => settings.set_double(info.id, value),
    };
    done.map_err(|e| Thrown::request(&format!("{} = {value}: {e}", info.code_name())))
}

/// The options of an object `{NAME: value, ...}` (none for `undefined`).
pub(crate) fn each(options: &JsValue, mut f: impl FnMut(&str, f64) -> Result<(), Thrown>) -> Result<(), Thrown> {
    if options.is_undefined() || options.is_null() {
        return Ok(());
    }
    let object: &Object =
        options.dyn_ref().ok_or_else(|| Thrown::request("options: an object {NAME: value} is needed"))?;
    for key in Object::keys(object).iter() {
        let name = key.as_string().unwrap_or_default();
        let value = Reflect::get(object, &key).map_err(|_| Thrown::request(&format!("{name}: unreadable")))?;
        let value = value.as_f64().ok_or_else(|| Thrown::request(&format!("{name}: a number is needed")))?;
        f(&name, value)?;
    }
    Ok(())
}

/// Settings as an object `{NAME: value}`.
pub(crate) fn object(settings: &Settings) -> Object {
    let out = Object::new();
    for (id, value) in settings.iter() {
        let name = opencrg_core::settings::info(id).map_or_else(|| id.to_string(), SettingInfo::code_name);
        let value = match value {
            Value::Int(i) => JsValue::from(i),
            Value::Double(d) => JsValue::from(d),
        };
        let _ = Reflect::set(&out, &name.into(), &value);
    }
    out
}

use crate::errors::Thrown;
use wasm_bindgen::JsCast;
