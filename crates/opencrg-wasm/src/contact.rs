//! `ContactPoint`: a road with options of its own and an x/y search history, its calls
//! made point by point in order, as the C API's.

use crate::errors::Thrown;
use crate::evaluate::call;
use crate::road::Road;
use crate::settings;
use js_sys::Uint8Array;
use opencrg_core::settings::Family;
use wasm_bindgen::prelude::*;

/// A point of evaluation: its own options and x/y search history.
#[wasm_bindgen]
pub struct ContactPoint {
    cp: opencrg_core::ContactPoint,
    refused: Vec<u8>,
}

#[wasm_bindgen]
impl ContactPoint {
    /// A contact point on `road` with the road's options and `options` on top
    /// (`{BORDER_MODE_U: 0, CURV_MODE: 1, ...}`: the file's keywords, any case).
    #[wasm_bindgen(constructor)]
    pub fn new(road: &Road, options: JsValue) -> Result<ContactPoint, Thrown> {
        Ok(ContactPoint { cp: road.contact_point(&options)?, refused: Vec::new() })
    }

    /// Sets one option by its keyword (any case).
    #[wasm_bindgen(js_name = setOption)]
    pub fn set_option(&mut self, name: &str, value: f64) -> Result<(), Thrown> {
        let mut table = self.cp.options().clone();
        settings::set(&mut table, Family::Option, name, value)?;
        let info = settings::lookup(Family::Option, name)?;
        match table.get(info.id) {
            Some(v) => self.cp.set_option_value(info.id, v).map_err(crate::errors::error),
            None => {
                self.cp.remove_option(info.id);
                Ok(())
            }
        }
    }

    /// The options in force, `{NAME: value}`.
    #[wasm_bindgen(getter)]
    pub fn options(&self) -> js_sys::Object {
        settings::object(self.cp.options())
    }

    /// Which points of the last call the library refused: 1 where the C API's call
    /// returns 0 (a number given), 1 where the answer is NaN (arrays given, which the
    /// batch calls answer); 0 for the others.
    #[wasm_bindgen(getter)]
    pub fn refused(&self) -> Uint8Array {
        Uint8Array::from(self.refused.as_slice())
    }

    /// Evaluation `index` of `evaluations()` at the points (a, b): what the package's
    /// `uvToZ`, `xyToNormal`, ... call.
    pub fn evaluate(&mut self, index: usize, a: &JsValue, b: &JsValue) -> Result<JsValue, Thrown> {
        call(&mut self.cp, crate::evaluate::nth(index)?, a, b, &mut self.refused)
    }
}
