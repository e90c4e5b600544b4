//! Any bytes as an OpenDRIVE map: read, its roads evaluated along and across, and (when
//! it names no CRG file, which would be read from the fuzzer's folder) checked, indexed
//! and asked for the ground at points of its roads.
#![no_main]
use libfuzzer_sys::fuzz_target;
use opencrg_odr::{Map, Surface};
use std::path::Path;
use std::sync::Arc;

fuzz_target!(|data: &[u8]| {
    let Ok(map) = Map::from_bytes(data, Path::new("fuzz.xodr")) else { return };
    let mut points = Vec::new();
    for road in &map.roads {
        for k in 0..=4 {
            let s = road.length * f64::from(k) / 4.0;
            let r = road.reference(s);
            let _ = road.surface_point(s, 1.0);
            let _ = road.lane_at(s, -1.0);
            points.push((r.x, r.y));
        }
    }
    let records = map.roads.iter().any(|r| !r.crg.is_empty()) || map.junctions.iter().any(|j| !j.crg.is_empty());
    if records {
        return;
    }
    let _ = opencrg_odr::check(&map);
    if let Ok(surface) = Surface::new(map) {
        let mut probe = Arc::new(surface).probe();
        for (x, y) in points {
            let _ = probe.ground(x, y);
            let _ = probe.ground(x + 1.5, y - 0.5);
        }
    }
});
