//! Times of the OpenDRIVE layer, in one process (bench/odr.sh runs it in alternating
//! rounds and reports medians):
//!
//! - `load MAP`: milliseconds to read the map (`Map::load`) and to make it ready to answer
//!   (`Surface::new`: the index, no CRG files in the shared maps);
//! - `wheels DIR [FROM STEPS]`: four wheels of a car at 1 kHz, 20 m/s along a 1 km road
//!   with an attached CRG file (1.6 million nodes, written to DIR), from s = FROM (10 m) for
//!   STEPS steps (45,000: to s = 910 m): ns per wheel query, and ns per
//!   `ContactPoint::xy_to_z` on the same CRG file along paths of the same length;
//! - `random MAP`: ground queries at random points of the map's extent, queries per second.

use opencrg_core::synth::RoadSpec;
use opencrg_odr::{Map, Surface};
use std::path::Path;
use std::sync::Arc;
use std::time::Instant;

fn load(path: &str) {
    let t = Instant::now();
    let map = Map::load(path).unwrap();
    let read = t.elapsed().as_secs_f64() * 1e3;
    let t = Instant::now();
    let surface = Surface::new(map).unwrap();
    let ready = t.elapsed().as_secs_f64() * 1e3;
    println!("load {path}: read {read:.2} ms, index {ready:.2} ms, {} roads", surface.map().roads.len());
}

const MAP: &str = r#"<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="8"/>
<road id="track" length="1000" junction="-1">
<planView>
<geometry s="0" x="0" y="0" hdg="0" length="300"><line/></geometry>
<geometry s="300" x="300" y="0" hdg="0" length="200"><spiral curvStart="0" curvEnd="0.004"/></geometry>
<geometry s="500" x="ARC_X" y="ARC_Y" hdg="ARC_HDG" length="500"><arc curvature="0.004"/></geometry>
</planView>
<elevationProfile><elevation s="0" a="10" b="0.02" c="0" d="0"/></elevationProfile>
<lateralProfile><superelevation s="0" a="0.02" b="0" c="0" d="0"/></lateralProfile>
<lanes><laneSection s="0">
<left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left>
<center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes>
<surface><CRG file="track.crg" sStart="0" sEnd="1000" mode="attached" orientation="same"/></surface>
</road></OpenDRIVE>"#;

fn wheels(dir: &str, from: f64, steps: usize) {
    let dir = Path::new(dir);
    std::fs::create_dir_all(dir).unwrap();
    let crg = dir.join("track.crg");
    if !crg.exists() {
        let spec = RoadSpec::straight(1000.0, 4.0, 0.05, 0.05)
            .with_elevation(|u, v| 0.003 * (u * 7.1).sin() * (v * 3.3).cos() + 0.001 * (u * 23.0).sin());
        std::fs::write(&crg, spec.to_crg()).unwrap();
    }
    // The arc starts where the spiral ends.
    let spiral = opencrg_odr::Geometry {
        s: 300.0,
        x: 300.0,
        y: 0.0,
        hdg: 0.0,
        length: 200.0,
        shape: opencrg_odr::Shape::Spiral { start: 0.0, end: 0.004 },
    };
    let end = spiral.pose(200.0);
    let map = MAP
        .replace("ARC_X", &end.x.to_string())
        .replace("ARC_Y", &end.y.to_string())
        .replace("ARC_HDG", &end.hdg.to_string());
    std::fs::write(dir.join("track.xodr"), map).unwrap();
    let surface = Arc::new(Surface::load(dir.join("track.xodr")).unwrap());
    let road = &surface.map().roads[0];
    // Four wheels at (0, +-0.8) and (2.7, +-0.8) from the car's reference point, 1 kHz at 20 m/s.
    let wheel_st = [(0.0, 0.8), (0.0, -0.8), (2.7, 0.8), (2.7, -0.8)];
    let paths: Vec<Vec<(f64, f64)>> = wheel_st
        .iter()
        .map(|&(ds, t)| {
            (0..steps)
                .map(|i| {
                    let p = road.surface_point(from + ds + i as f64 * 0.02, t);
                    (p[0], p[1])
                })
                .collect()
        })
        .collect();
    let mut probes: Vec<_> = (0..4).map(|_| surface.probe()).collect();
    let t = Instant::now();
    let mut sum = 0.0;
    for i in 0..steps {
        for (path, probe) in paths.iter().zip(probes.iter_mut()) {
            let (x, y) = path[i];
            sum += probe.ground(x, y).map_or(0.0, |g| g.z);
        }
    }
    let ns = t.elapsed().as_secs_f64() * 1e9 / (4 * steps) as f64;
    // The same CRG file alone along straight paths of the same length and step.
    let crg_road = Arc::new(opencrg_core::Road::load(&crg).unwrap());
    let mut cps: Vec<_> = (0..4).map(|_| opencrg_core::ContactPoint::new(crg_road.clone())).collect();
    let t = Instant::now();
    let mut sum2 = 0.0;
    for i in 0..steps {
        for (w, &(ds, v)) in wheel_st.iter().enumerate() {
            sum2 += cps[w].xy_to_z(from + ds + i as f64 * 0.02, v).unwrap_or(0.0);
        }
    }
    let plain = t.elapsed().as_secs_f64() * 1e9 / (4 * steps) as f64;
    println!("wheels: {ns:.1} ns per wheel query on the map, {plain:.1} ns per xy_to_z on the CRG alone (sums {sum:.3} {sum2:.3})");
}

fn random(path: &str) {
    let surface = Arc::new(Surface::load(path).unwrap());
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for r in &surface.map().roads {
        for k in 0..=10 {
            let p = r.reference(r.length * k as f64 / 10.0);
            lo = [lo[0].min(p.x), lo[1].min(p.y)];
            hi = [hi[0].max(p.x), hi[1].max(p.y)];
        }
    }
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let points: Vec<(f64, f64)> =
        (0..200_000).map(|_| (lo[0] + next() * (hi[0] - lo[0]), lo[1] + next() * (hi[1] - lo[1]))).collect();
    let mut probe = surface.probe();
    let t = Instant::now();
    let hits = points.iter().filter(|&&(x, y)| probe.ground(x, y).is_some()).count();
    let qps = points.len() as f64 / t.elapsed().as_secs_f64();
    println!("random {path}: {qps:.0} queries/s, {hits} of {} on a road", points.len());
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    match (args.get(1).map(String::as_str), args.get(2)) {
        (Some("load"), Some(p)) => load(p),
        (Some("wheels"), Some(d)) => {
            let from = args.get(3).map_or(Some(10.0), |v| v.parse().ok());
            let steps = args.get(4).map_or(Some(45_000), |v| v.parse().ok());
            // The front wheels 2.7 m ahead, 2 cm a step, stay on the 1 km road.
            let on_road = |from: f64, steps: usize| from >= 0.0 && from + 2.7 + steps as f64 * 0.02 <= 1000.0;
            match (from, steps) {
                (Some(from), Some(steps)) if steps > 0 && on_road(from, steps) => wheels(d, from, steps),
                _ => {
                    eprintln!("odr_bench wheels: FROM (m) and STEPS (2 cm each) must keep the wheels on the 1 km road");
                    std::process::exit(2);
                }
            }
        }
        (Some("random"), Some(p)) => random(p),
        _ => {
            eprintln!("usage: odr_bench load MAP | wheels DIR [FROM STEPS] | random MAP");
            std::process::exit(2);
        }
    }
}
