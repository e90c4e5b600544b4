//! The road tools with random parameters on small roads, under a budget of 8 MB (and the
//! address-space limit `fuzz/run.sh` sets): every request is answered or refused; none
//! aborts, panics or allocates beyond its budget.
#![no_main]
use libfuzzer_sys::fuzz_target;
use opencrg_tools::mesh::grid_mesh;
use opencrg_tools::simplify::simplified_mesh;
use opencrg_core::synth::RoadSpec;
use opencrg_tools::{self as tools, ChannelAction, Filter, Layout, LineChannel, Points};
use opencrg_core::{Budget, ContactPoint};
use std::sync::Arc;

/// The next number of the input: an f64 from 8 bytes, or one of a few telling values
/// picked by one byte.
fn number(d: &mut &[u8]) -> f64 {
    let Some((&pick, rest)) = d.split_first() else { return 0.5 };
    *d = rest;
    const TELLING: [f64; 12] = [0.0, -1.0, 1e-9, 1e-300, 1e300, f64::NAN, f64::INFINITY, 0.1, 0.5, 3.0, 1e9, -0.2];
    if pick < 128 {
        return TELLING[usize::from(pick) % TELLING.len()];
    }
    if d.len() < 8 {
        return f64::from(pick) / 100.0;
    }
    let (head, rest) = d.split_at(8);
    *d = rest;
    f64::from_le_bytes(head.try_into().unwrap_or([0; 8]))
}

fn byte(d: &mut &[u8]) -> u8 {
    let Some((&b, rest)) = d.split_first() else { return 0 };
    *d = rest;
    b
}

fuzz_target!(|input: &[u8]| {
    let mut d = input;
    let budget = Budget::with_bytes(8 << 20);
    let n_u = 2 + usize::from(byte(&mut d) % 60);
    let curvature = f64::from(byte(&mut d) as i8) / 400.0;
    let spec = RoadSpec::straight((n_u - 1) as f64 * 0.5, 2.0, 0.5, 0.25)
        .with_heading(move |u| curvature * u)
        .with_slope(|u| 0.01 * u.sin())
        .with_elevation(|u, v| 0.01 * (u * v).sin());
    let Ok(road) = spec.build() else { return };
    let road = Arc::new(road);
    let _ = match byte(&mut d) % 11 {
        0 => tools::resample(&road, Some(number(&mut d)), Some(number(&mut d)), &budget).map(|_| ()),
        1 => tools::resample(&road, Some(number(&mut d)), None, &budget).map(|_| ()),
        2 => tools::filter(&road, Filter::Gauss(number(&mut d)), &budget).map(|_| ()),
        3 => tools::filter(&road, Filter::Median(number(&mut d).abs() as usize), &budget).map(|_| ()),
        4 => tools::filter(&road, Filter::Limit(number(&mut d), number(&mut d)), &budget).map(|_| ()),
        5 => tools::cut(&road, (number(&mut d), number(&mut d)), Some((number(&mut d), number(&mut d)))).map(|_| ()),
        6 => {
            let x: Vec<f64> = (0..4).map(|_| number(&mut d)).collect();
            let y: Vec<f64> = (0..4).map(|_| number(&mut d)).collect();
            let layout = Layout { width: number(&mut d), u_inc: number(&mut d), v_inc: number(&mut d) };
            tools::generate(&Points { x, y, z: None }, layout, None, &budget).map(|_| ())
        }
        7 => tools::append(&road, &road, &budget).map(|_| ()),
        8 => {
            let action =
                [ChannelAction::Extract, ChannelAction::Apply, ChannelAction::Remove][usize::from(byte(&mut d) % 3)];
            tools::change_channel(&road, LineChannel::Slope, action).map(|_| ())
        }
        9 => {
            let cp = ContactPoint::new(road.clone());
            let range = Some((number(&mut d), number(&mut d)));
            grid_mesh(&cp, range, None, &budget).map(|_| ())
        }
        _ => {
            let cp = ContactPoint::new(road.clone());
            simplified_mesh(&cp, None, None, number(&mut d), &budget, &mut |_| {}).map(|_| ())
        }
    };
    let _ = opencrg_tools::roughness::roughness(&road, &[number(&mut d)], number(&mut d));
});
