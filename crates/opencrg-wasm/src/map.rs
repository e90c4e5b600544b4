//! `odr.Map`: an OpenDRIVE map read from bytes with the CRG files its records name, and
//! the ground at world points.

use crate::errors::Thrown;
use crate::values::Points;
use js_sys::{Array, Object, Reflect, Uint8Array};
use opencrg_odr::{Map as OdrMap, Surface};
use std::path::Path;
use std::sync::Arc;
use wasm_bindgen::prelude::*;

/// An OpenDRIVE map with its CRG files laid on.
#[wasm_bindgen(js_name = OdrMap)]
pub struct Map {
    surface: Arc<Surface>,
}

fn set(object: &Object, key: &str, value: JsValue) {
    let _ = Reflect::set(object, &key.into(), &value);
}

#[wasm_bindgen(js_class = OdrMap)]
impl Map {
    /// Reads the map in `bytes` (named `name` in messages) and lays on it the CRG files
    /// of `files` (`{name: Uint8Array}`): a record takes the file named as its `file`
    /// attribute is written, else the one of the same last path component.
    #[wasm_bindgen(js_name = fromBytes)]
    pub fn from_bytes(bytes: &[u8], files: JsValue, name: Option<String>) -> Result<Map, Thrown> {
        let name = name.unwrap_or_else(|| "map.xodr".into());
        let mut held = Vec::new();
        if let Some(object) = files.dyn_ref::<Object>() {
            for key in Object::keys(object).iter() {
                let value = Reflect::get(object, &key).unwrap_or(JsValue::UNDEFINED);
                held.push((key.as_string().unwrap_or_default(), Uint8Array::new(&value).to_vec()));
            }
        }
        let map = OdrMap::from_bytes(bytes, Path::new(&name)).map_err(crate::errors::error)?;
        let surface = Surface::from_files(map, &held).map_err(crate::errors::error)?;
        Ok(Map { surface: Arc::new(surface) })
    }

    /// The CRG files the map in `bytes` names (each once, as its records write them):
    /// the files [`Map::from_bytes`] wants beside the map.
    #[wasm_bindgen(js_name = crgFilesOf)]
    pub fn crg_files_of(bytes: &[u8], name: Option<String>) -> Result<Vec<String>, Thrown> {
        let name = name.unwrap_or_else(|| "map.xodr".into());
        let map = OdrMap::from_bytes(bytes, Path::new(&name)).map_err(crate::errors::error)?;
        Ok(map.crg_file_names().into_iter().map(String::from).collect())
    }

    /// The ground at world points: `{z, friction, road, lane, s, t}`, each a number or a
    /// `Float64Array` (NaN off every road; `road` is the index into `roadIds`, -1 off
    /// every road; friction NaN where neither a record nor the lane's material gives one).
    pub fn ground(&self, x: &JsValue, y: &JsValue) -> Result<Object, Thrown> {
        let p = Points::new(x, y, ("x", "y"))?;
        let n = p.a.len();
        let mut columns = vec![vec![f64::NAN; n]; 4];
        let (mut road, mut lane) = (vec![-1.0; n], vec![0.0; n]);
        let mut probe = self.surface.probe();
        for i in 0..n {
            if let Some(g) = probe.ground(p.a[i], p.b[i]) {
                for (column, value) in columns.iter_mut().zip([g.z, g.friction, g.s, g.t]) {
                    column[i] = value;
                }
                (road[i], lane[i]) = (g.road as f64, f64::from(g.lane));
            }
        }
        let out = Object::new();
        for (key, column) in ["z", "friction", "s", "t"].into_iter().zip(columns) {
            set(&out, key, p.one(column));
        }
        set(&out, "road", p.one(road));
        set(&out, "lane", p.one(lane));
        Ok(out)
    }

    /// The surface's upward unit normal at world points: `[nx, ny, nz]` (NaN off every
    /// road).
    pub fn normal(&self, x: &JsValue, y: &JsValue) -> Result<JsValue, Thrown> {
        let p = Points::new(x, y, ("x", "y"))?;
        let mut columns: Vec<Vec<f64>> = (0..3).map(|_| Vec::with_capacity(p.a.len())).collect();
        let mut probe = self.surface.probe();
        for (&x, &y) in p.a.iter().zip(&p.b) {
            let n = probe.normal(x, y).unwrap_or([f64::NAN; 3]);
            for (column, value) in columns.iter_mut().zip(n) {
                column.push(value);
            }
        }
        Ok(p.many(columns))
    }

    /// The checker's findings, one text each (empty when clean).
    pub fn check(&self) -> Array {
        self.surface.check().iter().map(|f| JsValue::from(f.to_string())).collect()
    }

    /// The roads' ids, in the file's order.
    #[wasm_bindgen(getter, js_name = roadIds)]
    pub fn road_ids(&self) -> Array {
        self.surface.map().roads.iter().map(|r| JsValue::from(r.id.as_str())).collect()
    }

    /// The roads' lengths, in the file's order.
    #[wasm_bindgen(getter, js_name = roadLengths)]
    pub fn road_lengths(&self) -> Vec<f64> {
        self.surface.map().roads.iter().map(|r| r.length).collect()
    }

    /// The 3D view of `opencrg odr view` (one HTML page, the map named `name`), CRG
    /// records outlined, the surface within `maxError` m (default 5 mm).
    #[wasm_bindgen(js_name = viewPage)]
    pub fn view_page(&self, name: &str, max_error: Option<f64>) -> Result<String, Thrown> {
        let options =
            opencrg_tools::map_mesh::MeshOptions { max_error: Some(max_error.unwrap_or(0.005)), ..Default::default() };
        let budget = opencrg_core::Budget::with_bytes(crate::limits::VIEW_MEMORY);
        opencrg_tools::view::map_view(&self.surface, name, &options, &budget)
            .map(|v| v.page)
            .map_err(crate::errors::error)
    }

    /// What `opencrg odr info` says, as text.
    pub fn info(&self) -> String {
        self.surface.map().info().to_string()
    }

    /// The world point `[x, y, z]` of the surface at (s, t) of the road `road` (its
    /// id), CRG records laid on.
    #[wasm_bindgen(js_name = stToXyz)]
    pub fn st_to_xyz(&self, road: &str, s: &JsValue, t: &JsValue) -> Result<JsValue, Thrown> {
        let index = self
            .surface
            .map()
            .road_index(road)
            .ok_or_else(|| Thrown::request(&format!("no road '{road}' in the map")))?;
        let p = Points::new(s, t, ("s", "t"))?;
        let mut columns: Vec<Vec<f64>> = (0..3).map(|_| Vec::with_capacity(p.a.len())).collect();
        let mut probe = self.surface.probe();
        for (&s, &t) in p.a.iter().zip(&p.b) {
            let xyz = probe.ground_st(index, s, t).map_or([f64::NAN; 3], |(x, y, g)| [x, y, g.z]);
            for (column, value) in columns.iter_mut().zip(xyz) {
                column.push(value);
            }
        }
        Ok(p.many(columns))
    }
}
