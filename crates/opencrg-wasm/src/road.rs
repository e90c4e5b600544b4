//! `Road`: a CRG file read from bytes, checked, modified, and evaluated with default
//! options (or those given with a call).

use crate::errors::Thrown;
use crate::evaluate::call;
use crate::settings;
use js_sys::{Array, Float32Array, Object, Reflect, Uint8Array};
use opencrg_core::settings::Family;
use opencrg_core::{Compat, ContactPoint, Settings};
use std::sync::Arc;
use wasm_bindgen::prelude::*;

/// A road: a CRG file in any of the four formats.
#[wasm_bindgen]
pub struct Road {
    road: Arc<opencrg_core::Road>,
}

impl Road {
    /// A contact point with the road's options and `options` on top.
    pub(crate) fn contact_point(&self, options: &JsValue) -> Result<ContactPoint, Thrown> {
        let mut cp = ContactPoint::new(self.road.clone());
        // Only the options given go through the setter, as a C program sets them after
        // `crgContactPointCreate`: the file's own take effect as there (setting a search
        // distance again would also move the history's reach).
        let mut table = Settings::empty_options();
        settings::each(options, |name, value| settings::set(&mut table, Family::Option, name, value))?;
        for (id, value) in table.iter() {
            cp.set_option_value(id, value).map_err(crate::errors::error)?;
        }
        Ok(cp)
    }
}

#[wasm_bindgen]
impl Road {
    /// Reads a CRG file held in `bytes`, named `name` in messages; `options`:
    /// `{compat: "2.0.1" | "current", files: {name: Uint8Array, ...}}`, the files its
    /// `$ROAD_CRG_FILE` references are read from. The modifiers are not applied yet.
    #[wasm_bindgen(js_name = fromBytes)]
    pub fn from_bytes(bytes: &[u8], name: Option<String>, options: JsValue) -> Result<Road, Thrown> {
        let name = name.unwrap_or_else(|| "road.crg".into());
        let get = |key: &str| -> JsValue {
            if options.is_object() {
                Reflect::get(&options, &key.into()).unwrap_or(JsValue::UNDEFINED)
            } else {
                JsValue::UNDEFINED
            }
        };
        let compat = match get("compat").as_string() {
            Some(text) => text.parse::<Compat>().map_err(|e| Thrown::request(&e.to_string()))?,
            None => Compat::default(),
        };
        let files = get("files");
        let mut held = Vec::new();
        if let Some(object) = files.dyn_ref::<Object>() {
            for key in Object::keys(object).iter() {
                let value = Reflect::get(object, &key).unwrap_or(JsValue::UNDEFINED);
                let bytes = Uint8Array::new(&value).to_vec();
                held.push((key.as_string().unwrap_or_default(), bytes));
            }
        }
        let road = opencrg_core::Road::from_bytes_with_files(bytes.to_vec(), &name, &held, compat)
            .map_err(crate::errors::error)?;
        Ok(Road { road: Arc::new(road) })
    }

    /// Checks the road as `crgCheck` does; throws when it fails.
    pub fn check(&mut self) -> Result<(), Thrown> {
        Arc::make_mut(&mut self.road).check().map_err(crate::errors::error)
    }

    /// Applies the modifiers to the data (`crgDataSetModifiersApply`).
    #[wasm_bindgen(js_name = applyModifiers)]
    pub fn apply_modifiers(&mut self) {
        Arc::make_mut(&mut self.road).apply_modifiers();
    }

    /// Sets one modifier by its keyword (any case); it acts at the next `applyModifiers()`.
    #[wasm_bindgen(js_name = setModifier)]
    pub fn set_modifier(&mut self, name: &str, value: f64) -> Result<(), Thrown> {
        settings::set(Arc::make_mut(&mut self.road).modifiers_mut(), Family::Modifier, name, value)
    }

    /// Removes every modifier (the file's and the defaults).
    #[wasm_bindgen(js_name = clearModifiers)]
    pub fn clear_modifiers(&mut self) {
        Arc::make_mut(&mut self.road).modifiers_mut().clear();
    }

    /// `[uFirst, uLast]`.
    #[wasm_bindgen(getter, js_name = uRange)]
    pub fn u_range(&self) -> Vec<f64> {
        let (a, b) = self.road.u_range();
        vec![a, b]
    }

    /// `[vRight, vLeft]`.
    #[wasm_bindgen(getter, js_name = vRange)]
    pub fn v_range(&self) -> Vec<f64> {
        let (a, b) = self.road.v_range();
        vec![a, b]
    }

    /// `[uIncrement, vIncrement]`.
    #[wasm_bindgen(getter)]
    pub fn increments(&self) -> Vec<f64> {
        let (a, b) = self.road.increments();
        vec![a, b]
    }

    /// `[uStart, uEnd]` of a closed track, or `null`.
    #[wasm_bindgen(getter, js_name = closedTrack)]
    pub fn closed_track(&self) -> JsValue {
        match self.road.closed_track() {
            Some((a, b)) => js_sys::Float64Array::from([a, b].as_slice()).into(),
            None => JsValue::NULL,
        }
    }

    /// `[closed, uStart, uEnd]` as the C API's `crgDataSetGetUtilityDataClosedTrack`
    /// reports it: 1 or 0, and the u range found the last time the line could be closed
    /// (0 and 0 if never), also when modifiers have since opened it.
    #[wasm_bindgen(getter, js_name = closedTrackReport)]
    pub fn closed_track_report(&self) -> Vec<f64> {
        let (closed, a, b) = self.road.closed_track_report();
        vec![f64::from(u8::from(closed)), a, b]
    }

    /// The v of the long sections.
    #[wasm_bindgen(getter)]
    pub fn v(&self) -> Vec<f64> {
        self.road.grid().v.clone()
    }

    /// The elevation grid, cross section after cross section (`nu * nv` values: the
    /// value at cross section `i`, long section `j` at `i * nv + j`), NaN kept.
    #[wasm_bindgen(getter)]
    pub fn grid(&self) -> Float32Array {
        let g = self.road.grid();
        let nv = g.v.len();
        let nu = g.values().len() / nv.max(1);
        let mut out = Vec::with_capacity(nu * nv);
        for iu in 0..nu {
            out.extend(g.cross_section(iu));
        }
        Float32Array::from(out.as_slice())
    }

    /// The header: `comments`, `road_crg`, `options`, `modifiers`, `mpro`, `references`,
    /// `format`, `channels`.
    #[wasm_bindgen(getter)]
    pub fn header(&self) -> Object {
        let h = self.road.header();
        let out = Object::new();
        let set = |key: &str, value: JsValue| {
            let _ = Reflect::set(&out, &key.into(), &value);
        };
        set("comments", h.comments.iter().map(|c| JsValue::from(c.as_str())).collect::<Array>().into());
        let road = Object::new();
        for (key, value) in h.road.entries() {
            let _ = Reflect::set(&road, &key.into(), &value.into());
        }
        set("road_crg", road.into());
        set("options", settings::object(&h.options).into());
        set("modifiers", settings::object(&h.modifiers).into());
        let mpro = Object::new();
        for (key, value) in &h.mpro {
            let _ = Reflect::set(&mpro, &key.as_str().into(), &value.as_str().into());
        }
        set("mpro", mpro.into());
        let references = h.references.iter().map(|p| JsValue::from(p.display().to_string())).collect::<Array>();
        set("references", references.into());
        set("format", h.format.name().into());
        set("channels", h.channels.iter().map(|c| JsValue::from(c.to_string())).collect::<Array>().into());
        out
    }

    /// The roughness of wheel tracks as `opencrg roughness` gives it: per track (`tracks`:
    /// their v, default -0.85, 0 and 0.85 m) `{v, iri, segments: [{uStart, uEnd, iri}],
    /// gdN0, w, iso8608, skipped}` (IRI in m/km over segments of `segment` m, default 100;
    /// a segment without data has iri `null`; `bands`: the displacement PSD as `[n, Gd(n)]`
    /// per third-octave band, cycles/m and m³).
    pub fn roughness(&self, tracks: Option<Vec<f64>>, segment: Option<f64>) -> Result<Array, Thrown> {
        let tracks = tracks.unwrap_or_else(|| opencrg_tools::roughness::DEFAULT_TRACKS.to_vec());
        let segment = segment.unwrap_or(opencrg_tools::roughness::DEFAULT_SEGMENT);
        let found = opencrg_tools::roughness::roughness(&self.road, &tracks, segment).map_err(crate::errors::error)?;
        let out = Array::new();
        for track in found {
            let t = Object::new();
            let put = |o: &Object, k: &str, v: JsValue| {
                let _ = Reflect::set(o, &k.into(), &v);
            };
            put(&t, "v", track.v.into());
            put(&t, "iri", track.iri.into());
            let segments = Array::new();
            for s in &track.segments {
                let o = Object::new();
                put(&o, "uStart", s.u_start.into());
                put(&o, "uEnd", s.u_end.into());
                put(&o, "iri", s.iri.map_or(JsValue::NULL, JsValue::from));
                segments.push(&o);
            }
            put(&t, "segments", segments.into());
            let bands = Array::new();
            for &(n, gd) in &track.psd.bands {
                bands.push(&Array::of2(&n.into(), &gd.into()));
            }
            put(&t, "bands", bands.into());
            put(&t, "gdN0", track.psd.gd_n0.into());
            put(&t, "w", track.psd.w.into());
            put(&t, "iso8608", track.psd.class.to_string().into());
            put(&t, "skipped", track.skipped.into());
            out.push(&t);
        }
        Ok(out)
    }

    /// The 3D view of `opencrg view` (one HTML page, the file named `name`), on every k-th
    /// cross section where the road has more than `max_vertices` grid nodes (default one
    /// million).
    #[wasm_bindgen(js_name = viewPage)]
    pub fn view_page(&self, name: &str, max_vertices: Option<usize>) -> Result<String, Thrown> {
        let cp = ContactPoint::new(self.road.clone());
        let budget = opencrg_core::Budget::with_bytes(crate::limits::VIEW_MEMORY);
        opencrg_tools::view::road_view(&cp, name, None, None, max_vertices.unwrap_or(1_000_000), &budget)
            .map(|v| v.page)
            .map_err(crate::errors::error)
    }

    /// What `opencrg info` says of the road, the file named `name`.
    pub fn info(&self, name: &str) -> String {
        opencrg_core::info::text(&self.road, name)
    }

    /// Evaluation `index` of `evaluations()` at the points (a, b), with contact point
    /// `options` for this call: what the package's `uvToZ`, `xyToNormal`, ... call.
    pub fn evaluate(&self, index: usize, a: &JsValue, b: &JsValue, options: JsValue) -> Result<JsValue, Thrown> {
        let mut cp = self.contact_point(&options)?;
        call(&mut cp, crate::evaluate::nth(index)?, a, b, &mut Vec::new())
    }
}

/// The ISO 8608 road classes the roughness is classified by: `{n0, limits, classes}` (the
/// reference spatial frequency in cycles/m, the limits of Gd(n0) between the classes in m³,
/// the classes' letters).
#[wasm_bindgen(js_name = iso8608Classes)]
pub fn iso8608_classes() -> Object {
    use opencrg_tools::psd::{CLASSES, CLASS_LIMITS, N0};
    let o = Object::new();
    let limits: Array = CLASS_LIMITS.iter().map(|&l| JsValue::from(l)).collect();
    let _ = Reflect::set(&o, &"n0".into(), &N0.into());
    let _ = Reflect::set(&o, &"limits".into(), &limits.into());
    let _ = Reflect::set(&o, &"classes".into(), &CLASSES.iter().collect::<String>().into());
    o
}
