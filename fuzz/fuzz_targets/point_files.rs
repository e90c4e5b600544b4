//! Any bytes as a point file: the first byte picks the kind (text table, PLY, LAS, LAZ),
//! the rest is the file. Points that read are gridded into a small road.
#![no_main]
use libfuzzer_sys::fuzz_target;
use opencrg_tools::{import, parse_points, Import};
use opencrg_core::Budget;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let Some((&kind, bytes)) = data.split_first() else { return };
    let name = ["fuzz.csv", "fuzz.xyz", "fuzz.ply", "fuzz.las", "fuzz.laz"][usize::from(kind % 5)];
    let Ok(points) = parse_points(bytes, Path::new(name)) else { return };
    if points.z.is_some() && points.len() >= 3 && points.len() <= 10_000 {
        let how = Import { u_inc: 0.5, v_inc: 0.5, ..Import::default() };
        let _ = import(&points, &how, &|_, _, _| {}, &Budget::with_bytes(8 << 20));
    }
});
