//! The evaluation calls of roads and contact points over points given as numbers or
//! arrays: numbers one call each, as the C API's calls (a refusal known as such), arrays
//! through the evaluator's batch calls; in order on one contact point, NaN where a point
//! is refused.

use crate::errors::Thrown;
use crate::values::Points;
use opencrg_core::{ContactPoint, Evaluation};
use wasm_bindgen::JsValue;

/// `call` at the points `a`, `b`; `refused` holds 1 for each point the library refused
/// (the C API's return code 0) where numbers were given, and for each point answered
/// NaN where arrays were given.
pub(crate) fn call(
    cp: &mut ContactPoint,
    call: Evaluation,
    a: &JsValue,
    b: &JsValue,
    refused: &mut Vec<u8>,
) -> Result<JsValue, Thrown> {
    let names = if call.takes_xy() { ("x", "y") } else { ("u", "v") };
    let p = Points::new(a, b, names)?;
    refused.clear();
    let columns = if p.scalar {
        let (values, was_refused) = cp.evaluate_one_or_nan(call, p.a[0], p.b[0]);
        refused.push(u8::from(was_refused));
        values.into_iter().map(|v| vec![v]).collect()
    } else {
        let columns = cp.evaluate_many(call, &p.a, &p.b);
        refused.extend(Evaluation::answered_nan(&columns).into_iter().map(u8::from));
        columns
    };
    Ok(if call.outputs() == 1 { p.one(columns.into_iter().next().unwrap_or_default()) } else { p.many(columns) })
}

/// The evaluation at `index` of the core's list.
pub(crate) fn nth(index: usize) -> Result<Evaluation, Thrown> {
    Evaluation::ALL.get(index).copied().ok_or_else(|| Thrown::request(&format!("no evaluation {index}")))
}

/// A snake-case name in camel case (`uv_to_z` -> `uvToZ`).
fn camel(name: &str) -> String {
    let mut out = String::with_capacity(name.len());
    let mut upper = false;
    for c in name.chars() {
        match c {
            '_' => upper = true,
            c if upper => {
                out.extend(c.to_uppercase());
                upper = false;
            }
            c => out.push(c),
        }
    }
    out
}

/// The evaluations roads and contact points have, from the core's one list, in the
/// order `evaluate` takes them: `[{name, inputs, outputs}]` (`uvToZ`, `["u", "v"]`,
/// `["z"]`). The package's `index.js` makes a method of each.
#[wasm_bindgen::prelude::wasm_bindgen]
pub fn evaluations() -> js_sys::Array {
    let strings = |names: &[&str]| names.iter().map(|n| JsValue::from_str(n)).collect::<js_sys::Array>();
    Evaluation::ALL
        .iter()
        .map(|e| {
            let o = js_sys::Object::new();
            let _ = js_sys::Reflect::set(&o, &"name".into(), &camel(e.name()).into());
            let _ = js_sys::Reflect::set(&o, &"inputs".into(), &strings(&e.inputs()).into());
            let _ = js_sys::Reflect::set(&o, &"outputs".into(), &strings(e.output_names()).into());
            JsValue::from(o)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    #[test]
    fn names_are_camel_cased() {
        assert_eq!(super::camel("uv_to_z"), "uvToZ");
        assert_eq!(super::camel("xy_to_normal"), "xyToNormal");
    }
}
