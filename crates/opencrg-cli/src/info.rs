//! `opencrg info`: what a road file holds, as text or JSON.

use opencrg_core::header::Channel;
use opencrg_core::info::GridScan;
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

/// What a scan of the grid finds: at once for a grid in memory; for a grid read in place
/// only when `whole` asks (it reads the whole file, with a progress bar), else `None`.
pub fn scanned(road: &Road, whole: bool) -> Result<Option<GridScan>, String> {
    if road.grid().is_in_place() && !whole {
        return Ok(None);
    }
    let bar = indicatif::ProgressBar::new(road.grid().nu as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("scanning the grid {bar:40} {percent:>3} %  {elapsed}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    if !road.grid().is_in_place() {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    let found = opencrg_core::info::scan(road, &mut |done, _| bar.set_position(done as u64)).map_err(|e| e.to_string());
    bar.finish_and_clear();
    found.map(Some)
}

/// The facts `info` reports, as JSON (the grid's range and NaN cells null where it was
/// not scanned).
pub fn facts(road: &Road, path: &str, scan: Option<&GridScan>) -> Json {
    let h = road.header();
    let g = road.grid();
    let s = road.statistics();
    let (u0, u1) = road.u_range();
    let (v0, v1) = road.v_range();
    let (du, dv) = road.increments();
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
        "elevation": {
            "min": scan.map(|s| s.z_min), "max": scan.map(|s| s.z_max),
            "mean_start": s.z_mean_start, "mean_end": s.z_mean_end,
        },
        "nan_cells": scan.map(|s| s.nan_cells),
        "in_place": g.is_in_place(),
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
pub fn text(road: &Road, path: &str, scan: Option<&GridScan>) -> String {
    opencrg_core::info::text_scanned(road, path, scan)
}

/// `opencrg info`: what the file holds, as text or JSON; `scan`: its heights scanned.
pub(crate) fn run(road: &std::path::Path, json: bool, scan: bool) -> Result<(), crate::files::Failure> {
    let r = crate::files::load(road)?;
    let name = road.display().to_string();
    let scan = scanned(&r, scan)?;
    if json {
        let facts = facts(&r, &name, scan.as_ref());
        println!("{}", serde_json::to_string_pretty(&facts).map_err(|e| e.to_string())?);
    } else {
        print!("{}", text(&r, &name, scan.as_ref()));
    }
    Ok(())
}
