//! What every reader target does with a road that loaded: check, apply, evaluate
//! around and beyond it, write it back in every format and read that again.
use opencrg_core::{ContactPoint, DataFormat, Road};
use std::sync::Arc;

pub fn exercise(mut road: Road) {
    let _ = road.check();
    road.apply_modifiers();
    let road = Arc::new(road);
    let (u0, u1) = road.u_range();
    let (v0, v1) = road.v_range();
    let mut cp = ContactPoint::new(road.clone());
    for i in 0..=8 {
        for j in 0..=4 {
            let u = u0 - 1.0 + (u1 - u0 + 2.0) * f64::from(i) / 8.0;
            let v = v0 - 1.0 + (v1 - v0 + 2.0) * f64::from(j) / 4.0;
            let _ = cp.uv_to_z(u, v);
            let _ = cp.uv_to_pk(u, v);
            if let Ok((x, y)) = cp.uv_to_xy(u, v) {
                let _ = cp.xy_to_uv(x, y);
            }
        }
    }
    for format in [DataFormat::Lrfi, DataFormat::Ldfi, DataFormat::Krbi, DataFormat::Kdbi] {
        let mut out = Vec::new();
        if opencrg_core::writer::write_to(&road, &mut out, format).is_ok() {
            let _ = Road::from_bytes(out, "fuzz-written.crg");
        }
    }
}
