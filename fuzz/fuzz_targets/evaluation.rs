//! Small generated roads with random options and modifiers, evaluated at random points.
#![no_main]
use libfuzzer_sys::fuzz_target;
use opencrg_core::settings::{describe, Family, Kind};
use opencrg_core::synth::RoadSpec;

fn take_f64(data: &mut &[u8]) -> f64 {
    if data.len() < 8 {
        return 0.5;
    }
    let (head, rest) = data.split_at(8);
    *data = rest;
    f64::from_le_bytes(head.try_into().unwrap())
}

fn take_u8(data: &mut &[u8]) -> u8 {
    match data.split_first() {
        Some((&b, rest)) => {
            *data = rest;
            b
        }
        None => 0,
    }
}

fuzz_target!(|input: &[u8]| {
    let mut d = input;
    let shape = take_u8(&mut d);
    let n_u = 2 + usize::from(take_u8(&mut d) % 40);
    let curvature = f64::from(take_u8(&mut d) as i8) / 500.0;
    let mut spec = RoadSpec::straight((n_u - 1) as f64 * 0.5, 2.0, 0.5, 0.5);
    if shape & 1 == 1 {
        spec = spec.with_heading(move |u| curvature * u);
    }
    if shape & 2 == 2 {
        spec = spec.with_slope(|u| 0.01 * u.sin()).with_bank(|u| 0.02 * u.cos());
    }
    if shape & 4 == 4 {
        spec = spec.with_sections(vec![-1.0, -0.3, 0.0, 0.2, 1.0]);
    }
    spec = spec.with_elevation(move |u, v| if shape & 8 == 8 && v > 0.9 { f64::NAN } else { (u * v).sin() });
    let Ok(mut road) = spec.build() else { return };
    // random modifiers
    for _ in 0..take_u8(&mut d) % 6 {
        let id = 21 + u32::from(take_u8(&mut d) % 24);
        let value = take_f64(&mut d);
        match describe(id) {
            Some((Family::Modifier, Kind::Int)) => {
                let _ = road.modifiers_mut().set_int(id, value as i32);
            }
            Some((Family::Modifier, Kind::Double)) => {
                let _ = road.modifiers_mut().set_double(id, value);
            }
            _ => {}
        }
    }
    let _ = road.check();
    road.apply_modifiers();
    let mut cp = opencrg_core::ContactPoint::new(std::sync::Arc::new(road));
    // random options
    for _ in 0..take_u8(&mut d) % 6 {
        let id = 1 + u32::from(take_u8(&mut d) % 19);
        let value = take_f64(&mut d);
        match describe(id) {
            Some((Family::Option, Kind::Int)) => {
                let _ = cp.set_option_int(id, value as i32);
            }
            Some((Family::Option, Kind::Double)) => {
                let _ = cp.set_option_double(id, value);
            }
            _ => {}
        }
    }
    if take_u8(&mut d) & 1 == 1 {
        let _ = cp.set_history(usize::from(take_u8(&mut d) % 8));
    }
    while d.len() >= 16 {
        let (u, v) = (take_f64(&mut d), take_f64(&mut d));
        let _ = cp.uv_to_z(u, v);
        let _ = cp.uv_to_pk(u, v);
        if let Ok((x, y)) = cp.uv_to_xy(u, v) {
            let _ = cp.xy_to_z(x, y);
            let _ = cp.xy_to_pk(x, y);
        }
    }
});
