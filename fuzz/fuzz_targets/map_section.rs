//! Any bytes as the `$ROAD_CRG_MPRO` section of a small valid road: ellipsoids,
//! projections, zones, datum transformations and their numbers. A road that loads is
//! checked against its WGS 84 keywords and taken to the earth and back.
#![no_main]
use libfuzzer_sys::fuzz_target;
use opencrg_core::{Earth, Road};

const HEAD: &str = "$ROAD_CRG\nREFERENCE_LINE_START_U = 0\nREFERENCE_LINE_END_U = 2\n\
REFERENCE_LINE_INCREMENT = 1\nREFERENCE_LINE_OFFSET_X = 500000\nREFERENCE_LINE_OFFSET_Y = 5300000\n$\n$ROAD_CRG_MPRO\n";
const TAIL: &str = "\n$\n$KD_Definition\n#:LRFI\nD:long section at v = -1.000,m\nD:long section at v = 1.000,m\n$\n\
 0.0 0.0\n 0.0 0.0\n 0.0 0.0\n";

fuzz_target!(|data: &[u8]| {
    let Ok(section) = std::str::from_utf8(data) else { return };
    if section.contains('$') {
        return;
    }
    let file = format!("{HEAD}{section}{TAIL}");
    let Ok(road) = Road::from_bytes(file.into_bytes(), "fuzz.crg") else { return };
    let _ = opencrg_core::map_disagreements(&road);
    if let Ok(earth) = Earth::of(&road) {
        for xyz in [[0.0, 0.0, 0.0], [2.0, 1.0, 5.0], [-1e7, 3e6, 0.0]] {
            if let Ok(llh) = earth.xyz_to_llh(&road, xyz) {
                let _ = earth.llh_to_xyz(&road, llh);
            }
        }
    }
});
