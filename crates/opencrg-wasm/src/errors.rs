//! The evaluator's errors as JavaScript `Error`s.

use wasm_bindgen::JsError;

/// The evaluator's error as a JavaScript `Error`, with the command's message.
pub(crate) fn error(e: opencrg_core::Error) -> JsError {
    JsError::new(&e.to_string())
}
