//! `opencrg info`: what a road file holds, as text or JSON.

use opencrg_core::header::Channel;
use opencrg_core::settings::{name, Value};
use opencrg_core::{Road, Settings};
use serde_json::{json, Value as Json};

fn channel_name(c: &Channel) -> String {
    c.to_string()
}

fn settings_json(s: &Settings) -> Json {
    let map: serde_json::Map<String, Json> = s
        .iter()
        .map(|(id, v)| {
            let value = match v {
                Value::Int(i) => json!(i),
                Value::Double(d) => json!(d),
            };
            (name(id).to_string(), value)
        })
        .collect();
    Json::Object(map)
}

fn wgs84_json(road: &Road, end: bool) -> Json {
    match opencrg_core::info::wgs84(road, end) {
        Some(([lat, lon, alt], from)) => json!({ "lat": lat, "lon": lon, "alt": alt, "from": from }),
        None => Json::Null,
    }
}

/// The facts `info` reports, as JSON.
pub fn facts(road: &Road, path: &str) -> Json {
    let h = road.header();
    let g = road.grid();
    let s = road.statistics();
    let (u0, u1) = road.u_range();
    let (v0, v1) = road.v_range();
    let (du, dv) = road.increments();
    let nan = g.values().iter().filter(|z| z.is_nan()).count();
    let o = road.global_origin();
    json!({
        "file": path,
        "format": road.format().name(),
        "references": h.references.iter().map(|p| p.display().to_string()).collect::<Vec<_>>(),
        "channels": h.channels.iter().map(channel_name).collect::<Vec<_>>(),
        "cross_sections": g.nu,
        "long_sections": g.nv,
        "u": { "first": u0, "last": u1, "increment": du },
        "v": { "right": v0, "left": v1, "increment": dv, "borders": [g.v_first, g.v_last] },
        "reference_line": {
            "start": { "x": s.start.0, "y": s.start.1, "heading": s.start.2 },
            "end": { "x": s.end.0, "y": s.end.1, "heading": s.end.2 },
            "length": u1 - u0,
            "z": [s.z_line.0, s.z_line.1],
            "closed": road.closed_track().map(|(a, b)| vec![a, b]),
        },
        "elevation": { "min": s.z_min, "max": s.z_max, "mean_start": s.z_mean_start, "mean_end": s.z_mean_end },
        "nan_cells": nan,
        "global_origin": { "x": o.x, "y": o.y, "z": o.z, "phi": o.phi },
        "map_projection": h.map.as_ref().map(|m| json!({
            "projection": m.projection.name, "local_ellipsoid": m.local.name, "global_ellipsoid": m.global.name,
            "transformation": m.datum.kind.name(),
        })),
        "wgs84": { "start": wgs84_json(road, false), "end": wgs84_json(road, true) },
        "options": settings_json(road.options()),
        "modifiers": settings_json(road.modifiers()),
        "warnings": road.warnings(),
    })
}

/// The facts as lines of text.
pub fn text(road: &Road, path: &str) -> String {
    opencrg_core::info::text(road, path)
}
