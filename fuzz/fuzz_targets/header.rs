//! Any bytes as a whole file: header sections, keywords, numbers, channels, file
//! references (relative names resolve in the fuzzer's folder, so most do not exist).
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(road) = opencrg_core::Road::from_bytes(data.to_vec(), "fuzz.crg") {
        opencrg_fuzz_common::exercise(road);
    }
});

#[path = "common.rs"]
mod opencrg_fuzz_common;
