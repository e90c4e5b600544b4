//! Loads a road, evaluates it along a path and converts x/y back to u/v.
//!
//!     cargo run -p opencrg-core --example rust_evaluate -- examples/data/demo_road.crg

use opencrg_core::{ContactPoint, Road};
use std::sync::Arc;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args().nth(1).unwrap_or_else(|| "examples/data/demo_road.crg".into());
    let mut road = Road::load(&path)?;
    road.check()?;
    road.apply_modifiers();
    let road = Arc::new(road);
    let (u0, u1) = road.u_range();
    let (v0, v1) = road.v_range();
    println!("{path}: u {u0} .. {u1} m, v {v0} .. {v1} m");

    let mut cp = ContactPoint::new(road);
    for i in 0..=6 {
        let u = u0 + (u1 - u0) * i as f64 / 6.0;
        let (x, y) = cp.uv_to_xy(u, 0.5)?;
        let z = cp.uv_to_z(u, 0.5)?;
        let (phi, curv) = cp.uv_to_pk(u, 0.5)?;
        let (u2, v2) = cp.xy_to_uv(x, y)?;
        println!("u {u:7.2} v 0.50 -> x {x:9.3} y {y:9.3} z {z:8.5} phi {phi:7.4} curv {curv:8.5} -> back to u {u2:7.3} v {v2:6.3}");
    }
    Ok(())
}
