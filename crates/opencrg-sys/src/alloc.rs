//! The allocator hooks `crgCalloc`, `crgRealloc` and `crgFree`, which applications may
//! redirect to their own functions.

use std::ffi::c_void;
use std::sync::atomic::{AtomicUsize, Ordering};

pub type CallocFn = unsafe extern "C" fn(usize, usize) -> *mut c_void;
pub type ReallocFn = unsafe extern "C" fn(*mut c_void, usize) -> *mut c_void;
pub type FreeFn = unsafe extern "C" fn(*mut c_void);

static CALLOC: AtomicUsize = AtomicUsize::new(0);
static REALLOC: AtomicUsize = AtomicUsize::new(0);
static FREE: AtomicUsize = AtomicUsize::new(0);

fn store(slot: &AtomicUsize, f: Option<usize>) {
    slot.store(f.unwrap_or(0), Ordering::SeqCst);
}

pub fn set_calloc(f: Option<CallocFn>) {
    store(&CALLOC, f.map(|f| f as usize));
}

pub fn set_realloc(f: Option<ReallocFn>) {
    store(&REALLOC, f.map(|f| f as usize));
}

pub fn set_free(f: Option<FreeFn>) {
    store(&FREE, f.map(|f| f as usize));
}

pub fn calloc(n: usize, size: usize) -> *mut c_void {
    match CALLOC.load(Ordering::SeqCst) {
        // SAFETY: only ever stored from a `CallocFn`.
        0 => unsafe { libc::calloc(n, size) },
        f => unsafe { std::mem::transmute::<usize, CallocFn>(f)(n, size) },
    }
}

pub fn realloc(p: *mut c_void, size: usize) -> *mut c_void {
    match REALLOC.load(Ordering::SeqCst) {
        // SAFETY: only ever stored from a `ReallocFn`; `p` comes from the caller's
        // earlier crgCalloc/crgRealloc as the API requires.
        0 => unsafe { libc::realloc(p, size) },
        f => unsafe { std::mem::transmute::<usize, ReallocFn>(f)(p, size) },
    }
}

pub fn free(p: *mut c_void) {
    match FREE.load(Ordering::SeqCst) {
        // SAFETY: as for realloc.
        0 => unsafe { libc::free(p) },
        f => unsafe { std::mem::transmute::<usize, FreeFn>(f)(p) },
    }
}
