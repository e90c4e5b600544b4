//! Any bytes after a valid LRFI/LDFI header: the data section's parser.
#![no_main]
use libfuzzer_sys::fuzz_target;

const HEADER: &str =
    "$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 0.5\nLONG_SECTION_V_RIGHT = -1\nLONG_SECTION_V_LEFT = 1\n$\n\
$KD_Definition\n#:LRFI\nD:reference line phi,rad\nD:reference line slope,m/m\nD:long section at v = -1.0,m\n\
D:long section at v = 0.25,m\nD:long section at v = 1.0,m\n$\n$$$$$$$$\n";

fuzz_target!(|data: &[u8]| {
    let (format, body) = match data.split_first() {
        Some((b, rest)) if b & 1 == 1 => ("#:LDFI", rest),
        Some((_, rest)) => ("#:LRFI", rest),
        None => return,
    };
    let mut bytes = HEADER.replace("#:LRFI", format).into_bytes();
    bytes.extend_from_slice(body);
    if let Ok(road) = opencrg_core::Road::from_bytes(bytes, "fuzz.crg") {
        opencrg_fuzz_common::exercise(road);
    }
});

#[path = "common.rs"]
mod opencrg_fuzz_common;
