//! The allocator hooks `crgCalloc`, `crgRealloc` and `crgFree`, which applications may
//! redirect to their own functions, and their exports.

use std::ffi::c_void;
use std::sync::atomic::{AtomicUsize, Ordering};

pub(crate) type CallocFn = unsafe extern "C" fn(usize, usize) -> *mut c_void;
pub(crate) type ReallocFn = unsafe extern "C" fn(*mut c_void, usize) -> *mut c_void;
pub(crate) type FreeFn = unsafe extern "C" fn(*mut c_void);

static CALLOC: AtomicUsize = AtomicUsize::new(0);
static REALLOC: AtomicUsize = AtomicUsize::new(0);
static FREE: AtomicUsize = AtomicUsize::new(0);

fn store(slot: &AtomicUsize, f: Option<usize>) {
    slot.store(f.unwrap_or(0), Ordering::SeqCst);
}

pub(crate) fn set_calloc(f: Option<CallocFn>) {
    store(&CALLOC, f.map(|f| f as usize));
}

pub(crate) fn set_realloc(f: Option<ReallocFn>) {
    store(&REALLOC, f.map(|f| f as usize));
}

pub(crate) fn set_free(f: Option<FreeFn>) {
    store(&FREE, f.map(|f| f as usize));
}

/// Zeroed memory from the hook, or from the C library.
pub(crate) fn calloc(n: usize, size: usize) -> *mut c_void {
    match CALLOC.load(Ordering::SeqCst) {
        // SAFETY: calloc accepts any sizes.
        0 => unsafe { libc::calloc(n, size) },
        // SAFETY: a non-zero value was only ever stored from a `CallocFn`, which the
        // caller of crgCallocSetCallback promised behaves as calloc.
        f => unsafe { std::mem::transmute::<usize, CallocFn>(f)(n, size) },
    }
}

/// Memory resized by the hook, or by the C library.
///
/// # Safety
/// `p` is null or came from [`calloc`] or [`realloc`] and was not freed since.
pub(crate) unsafe fn realloc(p: *mut c_void, size: usize) -> *mut c_void {
    match REALLOC.load(Ordering::SeqCst) {
        // SAFETY: `p` is as the contract above says.
        0 => unsafe { libc::realloc(p, size) },
        // SAFETY: only ever stored from a `ReallocFn` (promised to behave as realloc);
        // `p` as the contract above says.
        f => unsafe { std::mem::transmute::<usize, ReallocFn>(f)(p, size) },
    }
}

/// Memory given back to the hook, or to the C library.
///
/// # Safety
/// As for [`realloc`].
pub(crate) unsafe fn free(p: *mut c_void) {
    match FREE.load(Ordering::SeqCst) {
        // SAFETY: `p` is as the contract above says.
        0 => unsafe { libc::free(p) },
        // SAFETY: only ever stored from a `FreeFn` (promised to behave as free).
        f => unsafe { std::mem::transmute::<usize, FreeFn>(f)(p) },
    }
}

/// Allocates zeroed memory through the library's allocator hook.
#[no_mangle]
pub extern "C" fn crgCalloc(nmemb: usize, size: usize) -> *mut c_void {
    calloc(nmemb, size)
}

/// Reallocates memory through the library's allocator hook.
///
/// # Safety
/// `ptr` is null or came from `crgCalloc` or `crgRealloc` and was not freed since.
#[no_mangle]
pub unsafe extern "C" fn crgRealloc(ptr: *mut c_void, size: usize) -> *mut c_void {
    // SAFETY: the contract above.
    unsafe { realloc(ptr, size) }
}

/// Frees memory through the library's allocator hook.
///
/// # Safety
/// `ptr` is null or came from `crgCalloc` or `crgRealloc` and was not freed since.
#[no_mangle]
pub unsafe extern "C" fn crgFree(ptr: *mut c_void) {
    // SAFETY: the contract above.
    unsafe { free(ptr) }
}

/// Installs the application's calloc (null restores the C library's).
#[no_mangle]
pub extern "C" fn crgCallocSetCallback(func: Option<unsafe extern "C" fn(nmemb: usize, size: usize) -> *mut c_void>) {
    set_calloc(func);
}

/// Installs the application's realloc (null restores the C library's).
#[no_mangle]
pub extern "C" fn crgReallocSetCallback(
    func: Option<unsafe extern "C" fn(ptr: *mut c_void, size: usize) -> *mut c_void>,
) {
    set_realloc(func);
}

/// Installs the application's free (null restores the C library's).
#[no_mangle]
pub extern "C" fn crgFreeSetCallback(func: Option<unsafe extern "C" fn(ptr: *mut c_void)>) {
    set_free(func);
}
