//! The one panic guard used by every entry point: a panic never crosses the C boundary.

use std::any::Any;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Runs `f`; if it panics, reports a fatal message and returns `on_panic`.
#[inline(always)]
pub fn guard<R>(name: &str, on_panic: R, f: impl FnOnce() -> R) -> R {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(payload) => {
            report_panic(name, payload);
            on_panic
        }
    }
}

/// Reports a panic caught by [`guard`] (kept out of line: the entry points stay small).
#[cold]
#[inline(never)]
fn report_panic(name: &str, payload: Box<dyn Any + Send>) {
    let why = payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown cause".into());
    crate::msg::fatal(&format!("{name}: internal error ({why}); the call was refused"));
}
