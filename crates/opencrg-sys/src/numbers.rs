//! The NaN tests of the OpenCRG 1.2.0 API.
#![allow(non_snake_case)] // the C API's parameter names

use crate::ptr::input;
use std::ffi::c_int;

/// 1 if the double is NaN (OpenCRG 1.2.0 API).
///
/// # Safety
/// `dValue` is null or points to a double.
#[no_mangle]
pub unsafe extern "C" fn crgIsNan(dValue: *mut f64) -> c_int {
    // SAFETY: the contract above.
    c_int::from(unsafe { input(dValue) }.is_some_and(|v| v.is_nan()))
}

/// 1 if the float is NaN (OpenCRG 1.2.0 API).
///
/// # Safety
/// `fValue` is null or points to a float.
#[no_mangle]
pub unsafe extern "C" fn crgIsNanf(fValue: *mut f32) -> c_int {
    // SAFETY: the contract above.
    c_int::from(unsafe { input(fValue) }.is_some_and(|v| v.is_nan()))
}
