//! Any bytes after a valid KRBI/KDBI header whose declared length follows the input.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&flags, body)) = data.split_first() else { return };
    let double = flags & 1 == 1;
    let channels = 2 + usize::from(flags >> 1 & 3);
    let width = if double { 8 } else { 4 };
    let rows = (body.len() / (width * channels)).max(1);
    let mut h = format!(
        "$ROAD_CRG\nREFERENCE_LINE_START_U = 1\nREFERENCE_LINE_END_U = {}\nREFERENCE_LINE_INCREMENT = 0.25\n\
         LONG_SECTION_V_RIGHT = -2\nLONG_SECTION_V_INCREMENT = 0.5\n$\n$KD_Definition\n#:{}\nD:reference line phi,rad\n",
        1.0 + 0.25 * (rows as f64 - 1.0),
        if double { "KDBI" } else { "KRBI" }
    );
    for i in 1..channels {
        h.push_str(&format!("D:long section {i},m\n"));
    }
    h.push_str("$\n$$$$$$$$\n");
    let mut bytes = h.into_bytes();
    bytes.extend_from_slice(body);
    if let Ok(road) = opencrg_core::Road::from_bytes(bytes, "fuzz.crg") {
        opencrg_fuzz_common::exercise(road);
    }
});

#[path = "common.rs"]
mod opencrg_fuzz_common;
