//! The one panic guard used by every entry point: a panic never crosses the C boundary.

use std::panic::{catch_unwind, AssertUnwindSafe};

/// Runs `f`; if it panics, reports a fatal message and returns `on_panic`.
pub fn guard<R>(name: &str, on_panic: R, f: impl FnOnce() -> R) -> R {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(payload) => {
            let why = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown cause".into());
            crate::msg::fatal(&format!("{name}: internal error ({why}); the call was refused"));
            on_panic
        }
    }
}

/// Locks a mutex, recovering the data if an earlier panic poisoned it.
pub fn lock<T>(m: &std::sync::Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}
