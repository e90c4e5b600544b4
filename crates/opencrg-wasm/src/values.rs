//! Points in and answers out: numbers or arrays (`Float64Array`, or any array of numbers)
//! in, a number or a `Float64Array` out, pairs as two-element arrays.

use crate::errors::Thrown;
use js_sys::{Array, Float64Array};
use wasm_bindgen::{JsCast, JsValue};

/// The points of two coordinates: numbers (one point) or arrays of one length.
pub(crate) struct Points {
    pub a: Vec<f64>,
    pub b: Vec<f64>,
    /// Given as numbers: the answers are numbers too.
    pub scalar: bool,
}

fn numbers(value: &JsValue, what: &str) -> Result<(Vec<f64>, bool), Thrown> {
    if let Some(x) = value.as_f64() {
        return Ok((vec![x], true));
    }
    if let Some(array) = value.dyn_ref::<Float64Array>() {
        return Ok((array.to_vec(), false));
    }
    if Array::is_array(value) || js_sys::ArrayBuffer::is_view(value) {
        return Ok((Float64Array::new(value).to_vec(), false));
    }
    Err(Thrown::request(&format!("{what}: a number or an array of numbers is needed")))
}

impl Points {
    /// `a` and `b`, named `names` in messages.
    pub fn new(a: &JsValue, b: &JsValue, names: (&str, &str)) -> Result<Points, Thrown> {
        let ((a, one_a), (b, one_b)) = (numbers(a, names.0)?, numbers(b, names.1)?);
        if a.len() != b.len() {
            return Err(Thrown::request(&format!("{} has {} values, {} {}", names.0, a.len(), names.1, b.len())));
        }
        Ok(Points { a, b, scalar: one_a && one_b })
    }

    /// Answers of one value per point.
    pub fn one(&self, values: Vec<f64>) -> JsValue {
        if self.scalar {
            JsValue::from_f64(values[0])
        } else {
            Float64Array::from(values.as_slice()).into()
        }
    }

    /// Answers of several values per point: an array of numbers or of `Float64Array`s.
    pub fn many(&self, columns: Vec<Vec<f64>>) -> JsValue {
        columns.into_iter().map(|c| self.one(c)).collect::<Array>().into()
    }
}
