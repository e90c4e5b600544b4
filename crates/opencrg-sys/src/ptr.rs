//! The caller's pointers as Rust references: the one place where the C API's pointer
//! contracts are taken at their word. Every export turns each pointer it receives into
//! an `Option` of a reference here, then works with references only.

use std::ffi::{c_char, CStr};

/// The caller's output pointer as a reference; `None` when it is null.
///
/// # Safety
/// A non-null `p` must point to a writable, initialised `T`, valid for `'a`, that nothing
/// else reads or writes meanwhile.
#[inline(always)]
pub(crate) unsafe fn out<'a, T>(p: *mut T) -> Option<&'a mut T> {
    // SAFETY: the caller's promise; `as_mut` checks for null.
    unsafe { p.as_mut() }
}

/// The caller's input pointer as a reference; `None` when it is null.
///
/// # Safety
/// A non-null `p` must point to an initialised `T` that stays valid and unchanged for `'a`.
#[inline(always)]
pub(crate) unsafe fn input<'a, T>(p: *const T) -> Option<&'a T> {
    // SAFETY: the caller's promise; `as_ref` checks for null.
    unsafe { p.as_ref() }
}

/// `n` values at `p` as a slice; `None` for a null pointer (an empty slice for n = 0).
///
/// # Safety
/// A non-null `p` must point to `n` readable values that stay valid and unchanged for `'a`.
pub(crate) unsafe fn in_array<'a, T>(p: *const T, n: usize) -> Option<&'a [T]> {
    match (p.is_null(), n) {
        (_, 0) => Some(&[]),
        (true, _) => None,
        // SAFETY: the caller's promise, passed on from the C API's contract.
        (false, _) => Some(unsafe { std::slice::from_raw_parts(p, n) }),
    }
}

/// `n` values at `p` as a writable slice; `None` for a null pointer.
///
/// # Safety
/// A non-null `p` must point to `n` writable values, valid for `'a`, that nothing else
/// reads or writes meanwhile.
pub(crate) unsafe fn out_array<'a, T>(p: *mut T, n: usize) -> Option<&'a mut [T]> {
    match (p.is_null(), n) {
        (_, 0) => Some(&mut []),
        (true, _) => None,
        // SAFETY: the caller's promise, passed on from the C API's contract.
        (false, _) => Some(unsafe { std::slice::from_raw_parts_mut(p, n) }),
    }
}

/// The caller's NUL-terminated string; `None` when the pointer is null.
///
/// # Safety
/// A non-null `p` must point to a NUL-terminated string that stays valid and unchanged
/// for `'a`.
pub(crate) unsafe fn in_str<'a>(p: *const c_char) -> Option<&'a CStr> {
    if p.is_null() {
        return None;
    }
    // SAFETY: non-null, and the caller's promise for the rest.
    Some(unsafe { CStr::from_ptr(p) })
}

/// Writes the pair `f` gives: 1, or 0 when an output is missing or `f` gives nothing.
pub(crate) fn put_pair(a: Option<&mut f64>, b: Option<&mut f64>, f: impl FnOnce() -> Option<(f64, f64)>) -> i32 {
    let (Some(a), Some(b)) = (a, b) else { return 0 };
    match f() {
        Some((x, y)) => {
            (*a, *b) = (x, y);
            1
        }
        None => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn null_pointers_give_none_and_others_their_values() {
        let mut x = 1.5f64;
        // SAFETY: null, or a local that outlives the references.
        unsafe {
            assert!(out::<f64>(std::ptr::null_mut()).is_none());
            *out(&mut x).unwrap() = 2.5;
            assert_eq!(input(&x).copied(), Some(2.5));
            assert!(in_array::<f64>(std::ptr::null(), 3).is_none());
            assert_eq!(in_array::<f64>(std::ptr::null(), 0), Some(&[][..]));
            assert_eq!(in_str(c"road.crg".as_ptr()).map(CStr::to_bytes), Some(&b"road.crg"[..]));
            assert!(in_str(std::ptr::null()).is_none());
        }
    }
}
