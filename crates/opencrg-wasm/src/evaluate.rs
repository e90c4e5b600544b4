//! The evaluation calls of roads and contact points, over points given as numbers or
//! arrays, in order on one contact point (as the C API's calls made point by point), NaN
//! where a point is refused.

use crate::values::Points;
use opencrg_core::{ContactPoint, Result};
use wasm_bindgen::{JsError, JsValue};

/// The answers of `N` values per point, and which points were refused.
fn each<const N: usize>(
    cp: &mut ContactPoint,
    p: &Points,
    refused: &mut Vec<u8>,
    f: impl Fn(&mut ContactPoint, f64, f64) -> Result<[f64; N]>,
) -> JsValue {
    let mut columns: Vec<Vec<f64>> = (0..N).map(|_| Vec::with_capacity(p.a.len())).collect();
    refused.clear();
    for (&a, &b) in p.a.iter().zip(&p.b) {
        let answer = f(cp, a, b);
        refused.push(u8::from(answer.is_err()));
        for (column, value) in columns.iter_mut().zip(answer.unwrap_or([f64::NAN; N])) {
            column.push(value);
        }
    }
    if N == 1 {
        p.one(columns.pop().unwrap_or_default())
    } else {
        p.many(columns)
    }
}

/// The call `call` at the points `a`, `b`; `refused` holds 1 for each point the
/// library refused (the C API's return code 0), 0 for the others.
pub(crate) fn call(
    cp: &mut ContactPoint,
    call: Call,
    a: &JsValue,
    b: &JsValue,
    refused: &mut Vec<u8>,
) -> std::result::Result<JsValue, JsError> {
    let names = if call.takes_xy() { ("x", "y") } else { ("u", "v") };
    let p = Points::new(a, b, names)?;
    let pair = |(a, b): (f64, f64)| [a, b];
    Ok(match call {
        Call::UvToZ => each(cp, &p, refused, |cp, u, v| cp.uv_to_z(u, v).map(|z| [z])),
        Call::XyToZ => each(cp, &p, refused, |cp, x, y| cp.xy_to_z(x, y).map(|z| [z])),
        Call::UvToXy => each(cp, &p, refused, |cp, u, v| cp.uv_to_xy(u, v).map(pair)),
        Call::XyToUv => each(cp, &p, refused, |cp, x, y| cp.xy_to_uv(x, y).map(pair)),
        Call::UvToPk => each(cp, &p, refused, |cp, u, v| cp.uv_to_pk(u, v).map(pair)),
        Call::XyToPk => each(cp, &p, refused, |cp, x, y| cp.xy_to_pk(x, y).map(pair)),
        Call::UvToNormal => each(cp, &p, refused, |cp, u, v| cp.uv_to_normal(u, v).map(|(z, n)| [z, n[0], n[1], n[2]])),
    })
}

/// The evaluation calls.
#[derive(Clone, Copy)]
pub(crate) enum Call {
    UvToZ,
    XyToZ,
    UvToXy,
    XyToUv,
    UvToPk,
    XyToPk,
    UvToNormal,
}

impl Call {
    fn takes_xy(self) -> bool {
        matches!(self, Call::XyToZ | Call::XyToUv | Call::XyToPk)
    }
}
