//! How every export answers: inside the one panic guard ([`answer_as`], through
//! `answer!`), with a [`Call`] that
//! knows the export's name (for its messages) and is the only way to send a message.
//!
//! The rule of the C layer, in its types: nothing sends a message while it holds a lock,
//! because the application's message callback may call the library again (the reference
//! library has no locks, and programs do that). A [`Call`] is neither `Send` nor `Sync`,
//! and every function that runs a closure under a lock (the registry's, the slot tables')
//! takes only `Send` closures: a closure that could reach the [`Call`] does not compile.
//! What a closure finds to say, it returns; the export says it once the lock is released.
//!
//! The export's name is written once, in its signature: [`call_name!`] reads it from the
//! type name of a function nested in the export.

use crate::msg_entry::opencrg_msg_print;
use crate::registry;
use opencrg_core::{ContactPoint, Road};
use std::any::Any;
use std::ffi::{c_int, CString};
use std::marker::PhantomData;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::Arc;

/// The export being answered: its name, and the right to send messages.
pub(crate) struct Call {
    name: fn() -> &'static str,
    /// Neither `Send` nor `Sync`: no closure run under a lock can hold it.
    _here: PhantomData<*const ()>,
}

/// The name of the export whose body this appears in (anywhere in it: a closure or a
/// function nested in it), as a function: the name is only worked out when a message or a
/// refusal needs it.
macro_rules! call_name {
    () => {{
        fn name() -> &'static str {
            fn here() {}
            $crate::entry::export_name(::std::any::type_name_of_val(&here))
        }
        name as fn() -> &'static str
    }};
}
pub(crate) use call_name;

/// Answers the export this appears in: `answer!(on_panic, |call| body)` runs the body
/// with the export's [`Call`] inside the panic guard.
macro_rules! answer {
    ($on_panic:expr, $body:expr) => {
        $crate::entry::answer_as($crate::entry::call_name!(), $on_panic, $body)
    };
}
pub(crate) use answer;

/// The export's name in the type name of a function nested in it: the last path
/// segment that is an export's (every export's name starts with `crg`).
pub(crate) fn export_name(path: &'static str) -> &'static str {
    path.rsplit("::").find(|s| s.starts_with("crg")).unwrap_or(path)
}

/// Runs `body` with the [`Call`] of the export `name` names; if it panics, says so (a
/// fatal message) and returns `on_panic`. The one panic guard: a panic never crosses the C boundary.
#[inline(always)]
pub(crate) fn answer_as<R>(name: fn() -> &'static str, on_panic: R, body: impl FnOnce(&Call) -> R) -> R {
    let call = Call { name, _here: PhantomData };
    match catch_unwind(AssertUnwindSafe(|| body(&call))) {
        Ok(r) => r,
        Err(payload) => {
            call.panicked(payload);
            on_panic
        }
    }
}

impl Call {
    /// The export's name.
    pub(crate) fn name(&self) -> &'static str {
        (self.name)()
    }

    /// Sends a message of `level` (a newline is added): through the C shim, as the
    /// application's `crgMsgPrint` calls go.
    pub(crate) fn send(&self, level: c_int, text: &str) {
        if level > crate::msg::level() {
            return;
        }
        let text = CString::new(format!("{text}\n").replace('\0', " ")).unwrap_or_default();
        // SAFETY: "%s" with one NUL-terminated string argument.
        unsafe { opencrg_msg_print(level, c"%s".as_ptr(), text.as_ptr()) }
    }

    /// A fatal message.
    pub(crate) fn fatal(&self, text: &str) {
        self.send(crate::msg::FATAL, text);
    }

    /// A warning.
    pub(crate) fn warn(&self, text: &str) {
        self.send(crate::msg::WARN, text);
    }

    /// A notice.
    pub(crate) fn notice(&self, text: &str) {
        self.send(crate::msg::NOTICE, text);
    }

    /// The warning for an unknown id of `what`.
    #[cold]
    #[inline(never)]
    pub(crate) fn unknown(&self, what: &str, id: c_int) {
        self.warn(&format!("{}: invalid {what} id <{id}>", self.name()));
    }

    /// 1 for `Ok`; a warning naming the error and 0 otherwise.
    pub(crate) fn done(&self, r: opencrg_core::Result<()>) -> c_int {
        match r {
            Ok(()) => 1,
            Err(e) => {
                self.warn(&format!("{}: {e}", self.name()));
                0
            }
        }
    }

    /// A data set's road, shared (the data set table is not held once this returns);
    /// `None` (after a warning) for an unknown id.
    pub(crate) fn road(&self, id: c_int) -> Option<Arc<Road>> {
        let road = registry::with_dataset(id, |d| d.road.clone());
        if road.is_none() {
            self.unknown("data set", id);
        }
        road
    }

    /// Runs `f` on a data set's road to change it (its contact points follow); `None`
    /// (after a warning) for an unknown id.
    pub(crate) fn change_road<R>(&self, id: c_int, f: impl FnOnce(&mut Road) -> R + Send) -> Option<R> {
        let r = registry::modify_road(id, f);
        if r.is_none() {
            self.unknown("data set", id);
        }
        r
    }

    /// Runs `f` on a contact point; `None` (after a warning) for an unknown id.
    #[inline(always)]
    pub(crate) fn on_cp<R>(&self, id: c_int, f: impl FnOnce(&mut ContactPoint) -> R + Send) -> Option<R> {
        let r = registry::with_cp(id, f);
        if r.is_none() {
            self.unknown("contact point", id);
        }
        r
    }

    /// Reports a panic caught by [`answer_as`] (kept out of line: the exports stay small).
    #[cold]
    #[inline(never)]
    fn panicked(&self, payload: Box<dyn Any + Send>) {
        let why = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown cause".into());
        self.fatal(&format!("{}: internal error ({why}); the call was refused", self.name()));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[allow(non_snake_case)] // named as an export
    fn crgSomeExport() -> &'static str {
        let name = call_name!();
        let closure = || call_name!();
        assert_eq!(closure()(), "crgSomeExport");
        name()
    }

    #[test]
    fn an_export_knows_its_name_from_its_signature() {
        assert_eq!(crgSomeExport(), "crgSomeExport");
        assert_eq!(export_name("opencrg_sys::api::crgEvaluv2z::general::name::here"), "crgEvaluv2z");
    }

    #[test]
    fn a_panic_becomes_the_refusal() {
        assert_eq!(answer_as(|| "crgTest", 7, |_| -> i32 { panic!("deliberately") }), 7);
        assert_eq!(answer_as(|| "crgTest", 7, |c| c.name().len() as i32), 7);
    }
}
