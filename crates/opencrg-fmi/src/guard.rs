//! The one guard every export answers through: no panic crosses into the importer, a
//! null instance is refused, and a refusal is said through the instance's logger,
//! naming the export, after the instance is no longer borrowed (a logger that calls the
//! FMU again finds it free).

use crate::instance::{error, Instance, Refused};
use crate::log::Status;
use crate::states::State;
use std::ffi::{c_char, c_void, CStr};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// The name of the export this appears in, written nowhere but in its signature: a
/// function that reads it (only when a message needs it, off the hot path).
macro_rules! this_export {
    () => {{
        fn name() -> &'static str {
            fn here() {}
            $crate::guard::export_in(::std::any::type_name_of_val(&here))
        }
        name as fn() -> &'static str
    }};
}
pub(crate) use this_export;

/// The export's name in the type name of a function nested in it: the last path
/// segment starting with `fmi`.
pub(crate) fn export_in(path: &'static str) -> &'static str {
    path.rsplit("::").find(|s| s.starts_with("fmi")).unwrap_or(path)
}

/// Runs `body` on the instance behind `instance` and answers its status.
///
/// # Safety
/// `instance` is null or an instance this library made and has not freed, used by no
/// other thread during the call.
#[inline(always)]
pub(crate) unsafe fn on_instance(
    name: fn() -> &'static str,
    instance: *mut c_void,
    body: impl FnOnce(&mut Instance) -> Result<(), Refused>,
) -> Status {
    if instance.is_null() {
        return Status::Error;
    }
    let instance = instance.cast::<Instance>();
    // The refusal is kept aside, so that the answer of the unwinding guard is a flag:
    // the path of every call that succeeds tests one byte.
    let mut refused = None;
    // SAFETY: the caller's promise: a live instance of ours, this thread's alone.
    let outcome = catch_unwind(AssertUnwindSafe(|| match body(unsafe { &mut *instance }) {
        Ok(()) => true,
        Err(why) => {
            refused = Some(why);
            false
        }
    }));
    let (status, message) = match outcome {
        Ok(true) => return Status::Ok,
        Ok(false) => refused.map_or((Status::Error, String::new()), |r| (r.status, r.message)),
        Err(_) => {
            // SAFETY: as above; the body's borrow ended with the panic.
            unsafe { (*instance).state = State::Broken };
            (Status::Fatal, "an internal error (a panic): this instance cannot go on".to_string())
        }
    };
    // SAFETY: as above; the logger is copied out so that no borrow lives while it runs.
    let logger = unsafe { (*instance).logger().clone() };
    logger.say(status, &format!("{}: {message}", name()));
    status
}

/// Runs `body`; a panic answers `on_panic`.
pub(crate) fn guarded<T>(on_panic: T, body: impl FnOnce() -> T) -> T {
    catch_unwind(AssertUnwindSafe(body)).unwrap_or(on_panic)
}

/// The array of `n` values at `p` (none for `n` = 0); refused: null with `n` > 0.
///
/// # Safety
/// `p` is null or points to `n` readable values that outlive the call.
#[inline(always)]
pub(crate) unsafe fn slice<'a, T>(p: *const T, n: usize, what: &str) -> Result<&'a [T], Refused> {
    if n == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(null_array(what, n));
    }
    // SAFETY: the caller's promise.
    Ok(unsafe { std::slice::from_raw_parts(p, n) })
}

/// The writable array of `n` values at `p` (none for `n` = 0); refused: null with `n` > 0.
///
/// # Safety
/// `p` is null or points to `n` writable values, not otherwise referenced during the call.
#[inline(always)]
pub(crate) unsafe fn slice_mut<'a, T>(p: *mut T, n: usize, what: &str) -> Result<&'a mut [T], Refused> {
    if n == 0 {
        return Ok(&mut []);
    }
    if p.is_null() {
        return Err(null_array(what, n));
    }
    // SAFETY: the caller's promise.
    Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
}

/// The refusal of a null array of `n` values.
#[cold]
#[inline(never)]
fn null_array(what: &str, n: usize) -> Refused {
    error(format!("{what} is null for {n} values"))
}

/// A C string as text (lossy); `None` for null.
///
/// # Safety
/// `p` is null or a NUL-terminated string that outlives the call.
pub(crate) unsafe fn text(p: *const c_char) -> Option<String> {
    // SAFETY: the caller's promise.
    (!p.is_null()).then(|| unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned())
}

/// Refuses arrays of different lengths.
pub(crate) fn same_length(n_vr: usize, n_values: usize) -> Result<(), Refused> {
    if n_vr == n_values {
        Ok(())
    } else {
        Err(error(format!("{n_vr} value references but {n_values} values")))
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_export_is_named() {
        #[allow(non_snake_case)]
        fn fmi2GetReal_like() -> &'static str {
            this_export!()()
        }
        assert_eq!(fmi2GetReal_like(), "fmi2GetReal_like");
    }
}
