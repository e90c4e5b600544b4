//! Core evaluation speed, without the C layer: `cargo bench -p opencrg`.
//! Prints nanoseconds per call for each evaluation on generated roads.

use opencrg_core::synth::RoadSpec;
use opencrg_core::ContactPoint;
use std::hint::black_box;
use std::sync::Arc;
use std::time::Instant;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn time(name: &str, road: &str, n: usize, mut f: impl FnMut(usize)) {
    let t = Instant::now();
    for i in 0..n {
        f(i);
    }
    let ns = t.elapsed().as_nanos() as f64 / n as f64;
    println!("{road:<22} {name:<24} {ns:8.1} ns/call {:10.1} Mq/s", 1e3 / ns);
}

/// Random x/y to u/v without history on the same winding shape at growing lengths:
/// the cost should grow with the log of the length (a linear scan would grow 100x).
fn search_scaling() {
    for km in [1.0, 10.0, 100.0] {
        let length = km * 1000.0;
        let road = RoadSpec::straight(length, 2.0, 0.1, 0.5).with_heading(|u| (u / 300.0).sin()).build().expect("road");
        let road = Arc::new(road);
        let mut rng = Rng(1234567);
        let probe = ContactPoint::new(road.clone());
        let n = 200_000;
        let xy: Vec<(f64, f64)> =
            (0..n).map(|_| probe.uv_to_xy(length * rng.next(), 2.0 * rng.next() - 1.0).expect("inside")).collect();
        let mut cp = ContactPoint::new(road);
        cp.set_history(0).unwrap();
        time("xy_to_uv (no history)", &format!("winding {km} km"), n, |i| {
            black_box(cp.xy_to_uv(xy[i].0, xy[i].1).unwrap());
        });
    }
}

fn main() {
    search_scaling();
    let roads = [
        ("demo 120 m", RoadSpec::straight(120.0, 6.0, 0.5, 0.25).with_heading(|u| 0.2 + 0.4 * (u / 120.0).powi(2))),
        ("track 100 m at 1 cm", RoadSpec::straight(100.0, 4.0, 0.01, 0.01).with_elevation(|u, v| (u * 3.0).sin() * v)),
        ("winding 10 km", RoadSpec::straight(10_000.0, 4.0, 0.05, 0.5).with_heading(|u| 3.0 * (u / 400.0).sin())),
    ];
    let n = 2_000_000;
    for (name, spec) in roads {
        let mut road = spec.build().expect("generated road");
        road.apply_modifiers();
        let road = Arc::new(road);
        let (u0, u1) = road.u_range();
        let (v0, v1) = road.v_range();
        let mut rng = Rng(88172645463325252);
        let pts: Vec<(f64, f64)> = (0..n).map(|_| (u0 + (u1 - u0) * rng.next(), v0 + (v1 - v0) * rng.next())).collect();
        let cp = ContactPoint::new(road.clone());
        let xy: Vec<(f64, f64)> = pts.iter().map(|&(u, v)| cp.uv_to_xy(u, v).unwrap()).collect();
        time("uv_to_z", name, n, |i| {
            black_box(cp.uv_to_z(pts[i].0, pts[i].1).unwrap());
        });
        time("uv_to_xy", name, n, |i| {
            black_box(cp.uv_to_xy(pts[i].0, pts[i].1).unwrap());
        });
        time("uv_to_pk", name, n, |i| {
            black_box(cp.uv_to_pk(pts[i].0, pts[i].1).unwrap());
        });
        let mut fresh = ContactPoint::new(road.clone());
        fresh.set_history(0).unwrap();
        time("xy_to_uv (no history)", name, n / 10, |i| {
            black_box(fresh.xy_to_uv(xy[i].0, xy[i].1).unwrap());
        });
    }
}
