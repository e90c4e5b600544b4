//! Many threads loading roads and evaluating shared roads through their own contact
//! points give exactly the results of a single-threaded run.

use opencrg_core::synth::RoadSpec;
use opencrg_core::{ContactPoint, Road};
use std::sync::Arc;

fn spec(k: u32) -> RoadSpec {
    let c = 0.002 * f64::from(k + 1);
    RoadSpec::straight(80.0, 4.0, 0.25, 0.25)
        .with_heading(move |u| c * u)
        .with_slope(|u| 0.01 * (u / 7.0).sin())
        .with_elevation(move |u, v| (u * 0.3 + f64::from(k)).sin() * 0.01 + 0.002 * v)
}

/// Every evaluation along a weaving path, bit patterns collected.
fn run(road: Arc<Road>) -> Vec<u64> {
    let mut cp = ContactPoint::new(road);
    let mut out = Vec::with_capacity(4000);
    for i in 0..800 {
        let u = -5.0 + 90.0 * f64::from(i) / 800.0;
        let v = 2.5 * (f64::from(i) * 0.05).sin();
        let (x, y) = cp.uv_to_xy(u, v).unwrap();
        let (u2, v2) = cp.xy_to_uv(x, y).unwrap();
        let z = cp.uv_to_z(u, v).unwrap();
        let (phi, curv) = cp.uv_to_pk(u, v).unwrap();
        out.extend([x, y, u2, v2, z, phi, curv].map(f64::to_bits));
    }
    out
}

#[test]
fn threads_sharing_roads_match_a_single_thread() {
    let roads: Vec<Arc<Road>> = (0..4).map(|k| Arc::new(spec(k).build().unwrap())).collect();
    let expected: Vec<Vec<u64>> = roads.iter().map(|r| run(r.clone())).collect();
    std::thread::scope(|s| {
        let handles: Vec<_> = (0..16)
            .map(|t| {
                let road = roads[t % roads.len()].clone();
                s.spawn(move || (t % 4, run(road)))
            })
            .collect();
        for h in handles {
            let (k, got) = h.join().unwrap();
            assert!(got == expected[k], "thread results differ from the single-threaded run for road {k}");
        }
    });
}

#[test]
fn threads_loading_different_roads() {
    let dir = std::env::temp_dir().join(format!("opencrg-threads-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let paths: Vec<_> = (0..8u32)
        .map(|k| {
            let p = dir.join(format!("road{k}.crg"));
            std::fs::write(&p, spec(k % 4).to_crg()).unwrap();
            p
        })
        .collect();
    let expected: Vec<Vec<u64>> = (0..4).map(|k| run(Arc::new(spec(k).build().unwrap()))).collect();
    std::thread::scope(|s| {
        for (k, p) in paths.iter().enumerate() {
            let expected = &expected;
            s.spawn(move || {
                let road = Arc::new(Road::load(p).unwrap());
                assert!(run(road) == expected[k % 4], "road {k} loaded on a thread differs");
            });
        }
    });
}
