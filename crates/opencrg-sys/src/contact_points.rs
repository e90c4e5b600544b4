//! Contact points: creating and deleting them, their options and search histories.
#![allow(non_snake_case)] // the C API's parameter names

use crate::data_sets::{get_double, get_int, print_settings};
use crate::entry::answer;
use crate::ptr::out;
use crate::registry;
use opencrg_core::settings::{self, describe, name, Family, Kind, Value};
use std::ffi::{c_int, c_uint};

/// Creates a contact point on a data set; its id (>= 0) or -1.
#[no_mangle]
pub extern "C" fn crgContactPointCreate(dataSetId: c_int) -> c_int {
    answer!(-1, |call| {
        let id = registry::create_cp(dataSetId);
        if id < 0 {
            call.fatal(&format!("{}: invalid data set id <{dataSetId}>", call.name()));
        }
        id
    })
}

/// Deletes a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointDelete(cpId: c_int) -> c_int {
    answer!(0, |_| c_int::from(registry::delete_cp(cpId)))
}

/// Deletes every contact point of a data set (-1: of every data set).
#[no_mangle]
pub extern "C" fn crgContactPointDeleteAll(dataSetId: c_int) {
    answer!((), |_| registry::delete_cps_of((dataSetId != -1).then_some(dataSetId)))
}

/// Sets an integer option of a contact point. An integer that is not one of the
/// option's choices is kept, as the reference library keeps it, with a warning.
#[no_mangle]
pub extern "C" fn crgContactPointOptionSetInt(cpId: c_int, optionId: c_uint, optionValue: c_int) -> c_int {
    answer!(0, |call| match call.on_cp(cpId, |cp| cp.set_option_int_as_reference(optionId, optionValue)) {
        Some(r) => {
            if let (Ok(()), Err(e)) = (&r, settings::check(optionId, Value::Int(optionValue))) {
                call.warn(&format!("{}: {e}; kept, as the reference library keeps it", call.name()));
            }
            call.done(r)
        }
        None => 0,
    })
}

/// Sets a double option of a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointOptionSetDouble(cpId: c_int, optionId: c_uint, optionValue: f64) -> c_int {
    answer!(0, |call| {
        let kind_ok = describe(optionId) == Some((Family::Option, Kind::Double));
        match call.on_cp(cpId, |cp| kind_ok.then(|| cp.set_option_double(optionId, optionValue))) {
            Some(Some(r)) => call.done(r),
            Some(None) => {
                call.warn(&format!("{}: <{}> is not a double option", call.name(), name(optionId)));
                0
            }
            None => 0,
        }
    })
}

/// Reads an integer option of a contact point.
///
/// # Safety
/// `optionValue` is null or points to an int.
#[no_mangle]
pub unsafe extern "C" fn crgContactPointOptionGetInt(cpId: c_int, optionId: c_uint, optionValue: *mut c_int) -> c_int {
    // SAFETY: the contract above.
    let optionValue = unsafe { out(optionValue) };
    answer!(0, |call| call.on_cp(cpId, |cp| get_int(cp.options(), optionId, optionValue)).unwrap_or(0))
}

/// Reads a double option of a contact point.
///
/// # Safety
/// `optionValue` is null or points to a double.
#[no_mangle]
pub unsafe extern "C" fn crgContactPointOptionGetDouble(cpId: c_int, optionId: c_uint, optionValue: *mut f64) -> c_int {
    // SAFETY: the contract above.
    let optionValue = unsafe { out(optionValue) };
    answer!(0, |call| call.on_cp(cpId, |cp| get_double(cp.options(), optionId, optionValue)).unwrap_or(0))
}

/// Removes one option of a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointOptionRemove(cpId: c_int, optionId: c_uint) -> c_int {
    answer!(0, |call| call.on_cp(cpId, |cp| c_int::from(cp.remove_option(optionId))).unwrap_or(0))
}

/// Removes every option of a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointOptionRemoveAll(cpId: c_int) -> c_int {
    answer!(0, |call| call.on_cp(cpId, |cp| cp.clear_options()).map_or(0, |()| 1))
}

/// Prints the options of a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointOptionsPrint(cpId: c_int) {
    answer!((), |call| {
        if let Some(options) = call.on_cp(cpId, |cp| cp.options().clone()) {
            print_settings(call, &options, "option");
        }
    })
}

/// Restores the default options of a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointSetDefaultOptions(cpId: c_int) {
    answer!((), |call| {
        call.on_cp(cpId, |cp| cp.reset_options());
    })
}

/// Sets the size of a contact point's search history.
#[no_mangle]
pub extern "C" fn crgContactPointSetHistory(cpId: c_int, histSize: c_int) -> c_int {
    answer!(0, |call| {
        // The refusal is said once the contact point is released.
        match call.on_cp(cpId, |cp| usize::try_from(histSize).ok().map(|n| cp.set_history(n))) {
            Some(Some(r)) => call.done(r),
            _ => 0,
        }
    })
}

/// Sets the size of every contact point's search history.
#[no_mangle]
pub extern "C" fn crgContactPointSetHistoryForAllPoints(histSize: c_int) {
    answer!((), |call| {
        let Ok(n) = usize::try_from(histSize) else { return };
        // The refusals are said once every contact point is released.
        for refused in registry::update_all_cps(|cp| cp.set_history(n)).into_iter().filter_map(Result::err) {
            call.warn(&format!("{}: {refused}", call.name()));
        }
    })
}
