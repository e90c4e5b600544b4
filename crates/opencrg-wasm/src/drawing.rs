//! The drawing rules of the command's figures for the web page: the elevation colours,
//! the ticks of axes and their labels, the tracks' colours (`opencrg_tools::drawing`).

use js_sys::{Array, Object, Reflect};
use opencrg_tools::drawing;
use wasm_bindgen::prelude::*;

/// The colours of values `t` in 0..1 (clamped): three bytes (red, green, blue) each.
#[wasm_bindgen(js_name = elevationColours)]
pub fn elevation_colours(t: &[f64]) -> Vec<u8> {
    t.iter().flat_map(|&t| drawing::elevation_colour(t)).collect()
}

/// At most `atMost` ticks over [a, b] at the smallest round step that gives no more.
#[wasm_bindgen]
pub fn ticks(a: f64, b: f64, at_most: usize) -> Vec<f64> {
    drawing::ticks(a, b, at_most)
}

/// A tick's label (at most six decimals, no trailing zeros).
#[wasm_bindgen(js_name = tickLabel)]
pub fn tick_label(v: f64) -> String {
    drawing::tick_label(v)
}

/// A power of ten's label (10 with a superscript exponent; plain from 0.001 to 1000).
#[wasm_bindgen(js_name = decadeLabel)]
pub fn decade_label(v: f64) -> String {
    drawing::decade_label(v)
}

/// The colours as CSS: `{tracks: ["rgb(r,g,b)", ...], reference: "rgb(...)"}`.
#[wasm_bindgen(js_name = figureColours)]
pub fn figure_colours() -> Object {
    let css = |[r, g, b]: [u8; 3]| JsValue::from(format!("rgb({r},{g},{b})"));
    let o = Object::new();
    let tracks: Array = drawing::TRACK_COLOURS.into_iter().map(css).collect();
    let _ = Reflect::set(&o, &"tracks".into(), &tracks.into());
    let _ = Reflect::set(&o, &"reference".into(), &css(drawing::REFERENCE_GREY));
    o
}
