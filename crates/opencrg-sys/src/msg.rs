//! Messages: level, warning budget and the application's callback.
//!
//! The library's own messages (sent by a [`Call`](crate::entry::Call)) and the
//! application's `crgMsgPrint` calls go the same way: formatted in the C shim, routed here.

use crate::lock::lock;
use std::ffi::{c_char, c_int};
use std::sync::atomic::{AtomicI32, Ordering};
use std::sync::Mutex;

/// Message levels of the classic API.
pub(crate) const NONE: c_int = 0;
/// Fatal errors.
pub(crate) const FATAL: c_int = 1;
/// Warnings.
pub(crate) const WARN: c_int = 2;
/// Notices.
pub(crate) const NOTICE: c_int = 3;
/// Debugging.
pub(crate) const DEBUG: c_int = 5;

/// The callback type of `crgMsgSetCallback`.
pub(crate) type Callback = unsafe extern "C" fn(c_int, *mut c_char) -> c_int;

static LEVEL: AtomicI32 = AtomicI32::new(NOTICE);
static WARN_BUDGET: AtomicI32 = AtomicI32::new(-1);
static CALLBACK: Mutex<Option<Callback>> = Mutex::new(None);

pub fn set_level(level: c_int) {
    if (NONE..=DEBUG).contains(&level) {
        LEVEL.store(level, Ordering::Relaxed);
    }
}

pub fn level() -> c_int {
    LEVEL.load(Ordering::Relaxed)
}

pub fn set_max_warnings(n: c_int) {
    WARN_BUDGET.store(n, Ordering::Relaxed);
}

pub fn is_printable(level: c_int) -> bool {
    level <= self::level() && WARN_BUDGET.load(Ordering::Relaxed) != 0
}

pub fn set_callback(cb: Option<Callback>) {
    *lock(&CALLBACK) = cb;
}

/// Whether a message of this level is wanted at all (the shim formats nothing otherwise).
extern "C" fn wanted(level: c_int) -> c_int {
    c_int::from(level <= self::level())
}

/// Routes a formatted message: to the application's callback, or (returning 1) back to
/// the shim to print on stderr while the warning budget lasts.
extern "C" fn route(level: c_int, text: *mut c_char) -> c_int {
    let cb = *lock(&CALLBACK);
    if let Some(cb) = cb {
        // SAFETY: the application registered this callback for exactly this use;
        // `text` is the shim's NUL-terminated buffer.
        unsafe { cb(level, text) };
        return 0;
    }
    let budget = WARN_BUDGET.load(Ordering::Relaxed);
    if budget == 0 {
        return 0;
    }
    if budget > 0 {
        WARN_BUDGET.store(budget - 1, Ordering::Relaxed);
    }
    1
}

type WantedHook = Option<extern "C" fn(c_int) -> c_int>;
type RouteHook = Option<extern "C" fn(c_int, *mut c_char) -> c_int>;

extern "C" {
    // Hidden symbols of the C shim: how it reaches this module without the library
    // exporting anything beyond the API.
    static mut opencrg_msg_wanted_hook: WantedHook;
    static mut opencrg_msg_route_hook: RouteHook;
}

/// Hands the shim its two hooks when the library is loaded (see `on_load`).
pub(crate) extern "C" fn install_hooks() {
    // SAFETY: runs once, from the loader, before any thread of the program can call
    // into the library; the statics are plain function pointers in the shim.
    unsafe {
        *std::ptr::addr_of_mut!(opencrg_msg_wanted_hook) = Some(wanted);
        *std::ptr::addr_of_mut!(opencrg_msg_route_hook) = Some(route);
    }
}
