//! The message settings of the classic API: level, how many are printed, the callback.
#![allow(non_snake_case)] // the C API's parameter names

use crate::msg;
use std::ffi::{c_char, c_int};

/// Sets the message level.
#[no_mangle]
pub extern "C" fn crgMsgSetLevel(level: c_int) {
    msg::set_level(level);
}

/// Limits the number of messages printed (-1: no limit).
#[no_mangle]
pub extern "C" fn crgMsgSetMaxWarnMsgs(maxNo: c_int) {
    msg::set_max_warnings(maxNo);
}

/// Kept for compatibility; log messages are not limited separately.
#[no_mangle]
pub extern "C" fn crgMsgSetMaxLogMsgs(_maxNo: c_int) {}

/// Whether a message of this level would be printed.
#[no_mangle]
pub extern "C" fn crgMsgIsPrintable(level: c_int) -> c_int {
    c_int::from(msg::is_printable(level))
}

/// Sends messages to a callback instead of standard output (null restores printing).
#[no_mangle]
pub extern "C" fn crgMsgSetCallback(func: Option<unsafe extern "C" fn(level: c_int, message: *mut c_char) -> c_int>) {
    msg::set_callback(func);
}
