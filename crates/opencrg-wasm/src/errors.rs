//! What the module throws: JavaScript `Error`s whose `name` says the kind, with the
//! command's messages. The package's `index.js` has a class for each kind, so callers tell
//! them apart with `instanceof` as Python's callers do with its exception classes.

use wasm_bindgen::JsValue;

/// An `Error` to throw, its `name` the kind.
pub struct Thrown(js_sys::Error);

impl Thrown {
    /// A request the module refuses before any work (an argument it does not take).
    pub(crate) fn request(message: &str) -> Thrown {
        Thrown::named("RequestError", message)
    }

    fn named(kind: &str, message: &str) -> Thrown {
        let e = js_sys::Error::new(message);
        e.set_name(kind);
        Thrown(e)
    }
}

impl From<Thrown> for JsValue {
    fn from(t: Thrown) -> JsValue {
        t.0.into()
    }
}

/// The evaluator's error, its kind named as the Python package's exception classes are.
pub(crate) fn error(e: opencrg_core::Error) -> Thrown {
    use opencrg_core::Error;
    let kind = match &e {
        Error::NotFound { .. } => "NotFoundError",
        Error::Io { .. } => "IoError",
        Error::Format { .. } => "FormatError",
        Error::Check(_) => "CheckError",
        Error::TooLarge(_) => "TooLargeError",
        Error::OutOfRange(_) => "OutOfRangeError",
    };
    Thrown::named(kind, &e.to_string())
}
