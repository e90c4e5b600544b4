//! Statuses and the importer's logger, FMI 2's (printf-like) and FMI 3's.

use std::ffi::{c_char, c_int, c_void, CString};

/// A call's status (FMI 2's and FMI 3's numbering agree).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(C)]
pub enum Status {
    /// Done.
    Ok = 0,
    /// Done, with something to say.
    Warning = 1,
    /// Not done; the instance may go on.
    Discard = 2,
    /// Not done: a wrong call or a road that cannot serve.
    Error = 3,
    /// The instance cannot go on.
    Fatal = 4,
}

/// FMI 2's logger: `(environment, instance name, status, category, format, ...)`
/// (called with a format that asks for no argument).
pub type Fmi2Logger = unsafe extern "C" fn(
    env: *mut c_void,
    instance: *const c_char,
    status: c_int,
    category: *const c_char,
    format: *const c_char,
    ...
);

/// FMI 3's logger: `(environment, status, category, message)`.
pub type Fmi3Logger =
    unsafe extern "C" fn(env: *mut c_void, status: c_int, category: *const c_char, message: *const c_char);

/// Where an instance's messages go.
#[derive(Clone)]
pub enum Logger {
    /// An FMI 2 logger, with the environment and the instance's name it is called with.
    Fmi2 { log: Fmi2Logger, env: *mut c_void, name: CString },
    /// An FMI 3 logger, with its environment.
    Fmi3 { log: Fmi3Logger, env: *mut c_void },
    /// None given.
    Silent,
}

/// Text as a C string (an inner NUL cut off there).
pub fn c_text(text: &str) -> CString {
    let cut = text.split('\0').next().unwrap_or("");
    CString::new(cut).unwrap_or_default()
}

impl Logger {
    /// Says `message` with `status`, in the category of its status.
    pub fn say(&self, status: Status, message: &str) {
        let category = c_text(match status {
            Status::Ok => "logAll",
            Status::Warning => "logStatusWarning",
            Status::Discard => "logStatusDiscard",
            Status::Error => "logStatusError",
            Status::Fatal => "logStatusFatal",
        });
        match self {
            // FMI 2's message is a printf format: its % doubled, it reads as the text to
            // an importer that formats it (and nearly so to one that does not).
            // SAFETY: the importer gave the logger for this instance; the strings live
            // through the call, and the format asks for no argument.
            Logger::Fmi2 { log, env, name } => unsafe {
                let format = c_text(&message.replace('%', "%%"));
                log(*env, name.as_ptr(), status as c_int, category.as_ptr(), format.as_ptr())
            },
            // SAFETY: as above; FMI 3's logger takes the message itself.
            Logger::Fmi3 { log, env } => unsafe {
                let message = c_text(message);
                log(*env, status as c_int, category.as_ptr(), message.as_ptr())
            },
            Logger::Silent => {}
        }
    }
}
