//! Any text as a `generate --surface` formula: parsed, and evaluated where it parses.
#![no_main]
use libfuzzer_sys::fuzz_target;

#[path = "../../crates/opencrg-cli/src/expr.rs"]
#[allow(dead_code)]
mod expr;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    match expr::parse(text) {
        Ok(e) => {
            for (u, v) in [(0.0, 0.0), (1.5, -0.5), (1e300, -1e-300), (f64::NAN, 1.0)] {
                let _ = e.at(u, v);
            }
        }
        Err(message) => assert!(!message.is_empty()),
    }
    let _ = expr::abridged(text);
});
