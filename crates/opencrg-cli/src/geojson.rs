//! `opencrg export ROAD OUT.geojson`: the reference line and the road's outline in WGS 84
//! (RFC 7946: longitude, latitude, height), through the road's map projection.

use opencrg_core::{ContactPoint, Earth, Road};
use serde_json::{json, Value};
use std::path::Path;

/// Longitude, latitude and height of the local point (x, y, z) of `road`.
fn position(earth: &Earth, road: &Road, xyz: [f64; 3]) -> Result<Value, String> {
    let [lat, lon, alt] = earth.xyz_to_llh(road, xyz).map_err(|e| e.to_string())?;
    Ok(json!([lon, lat, alt]))
}

/// The GeoJSON document of the road `cp` evaluates.
pub fn document(cp: &mut ContactPoint) -> Result<Value, String> {
    let road = cp.road().clone();
    let earth = Earth::of(&road).map_err(|e| e.to_string())?;
    let l = road.reference_line();
    let line = (0..l.n).map(|i| position(&earth, &road, [l.x[i], l.y[i], l.z_at(i)])).collect::<Result<Vec<_>, _>>()?;
    // The outline: the right border along u, the left one back, closed; each point at the
    // height of the reference line across from it.
    let (v_right, v_left) = road.v_range();
    let mut ring = Vec::with_capacity(2 * l.n + 1);
    let along_right = (0..l.n).map(|i| (i, v_right));
    let back_left = (0..l.n).rev().map(|i| (i, v_left));
    for (i, v) in along_right.chain(back_left) {
        let (x, y) = cp.uv_to_xy(l.u_at(i), v).map_err(|e| e.to_string())?;
        ring.push(position(&earth, &road, [x, y, l.z_at(i)])?);
    }
    ring.push(ring[0].clone());
    let name = road.header().path.display().to_string();
    Ok(json!({
        "type": "FeatureCollection",
        "features": [
            {
                "type": "Feature",
                "properties": { "name": "reference line", "file": name, "u": [l.u_at(0), l.u_at(l.n - 1)] },
                "geometry": { "type": "LineString", "coordinates": line },
            },
            {
                "type": "Feature",
                "properties": { "name": "outline", "file": name, "v": [v_right, v_left] },
                "geometry": { "type": "Polygon", "coordinates": [ring] },
            },
        ],
    }))
}

/// Writes the GeoJSON of the road to `out` (all or nothing: a temporary file renamed).
pub fn write(cp: &mut ContactPoint, out: &Path) -> Result<String, String> {
    let doc = document(cp)?;
    let text = serde_json::to_string(&doc).map_err(|e| e.to_string())?;
    let partial = out.with_extension("geojson.partial");
    std::fs::write(&partial, text).map_err(|e| format!("{}: {e}", partial.display()))?;
    std::fs::rename(&partial, out).map_err(|e| format!("{}: {e}", out.display()))?;
    let points = cp.road().reference_line().n;
    Ok(format!("{}: reference line and outline in WGS 84 ({points} points along u)", out.display()))
}
