//! `opencrg info`: what a road file holds, as text or JSON.

use opencrg::header::Channel;
use opencrg::settings::{name, Value};
use opencrg::{Road, Settings};
use serde_json::{json, Value as Json};

fn channel_name(c: &Channel) -> String {
    match c {
        Channel::RefX => "reference line x".into(),
        Channel::RefY => "reference line y".into(),
        Channel::RefU => "reference line u".into(),
        Channel::RefPhi => "reference line heading".into(),
        Channel::RefSlope => "reference line slope".into(),
        Channel::RefBank => "reference line banking".into(),
        Channel::SectionAt(v) => format!("long section at v = {v}"),
        Channel::SectionIndex(n) => format!("long section {n}"),
    }
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

fn settings_text(s: &Settings) -> String {
    let items: Vec<String> = s
        .iter()
        .map(|(id, v)| match v {
            Value::Int(i) => format!("{} = {i}", name(id)),
            Value::Double(d) => format!("{} = {d}", name(id)),
        })
        .collect();
    if items.is_empty() {
        "none".into()
    } else {
        items.join(", ")
    }
}

/// The facts `info` reports, as JSON (the text form is made from the same object).
pub fn facts(road: &Road, path: &str) -> Json {
    let h = road.header();
    let g = road.grid();
    let s = road.statistics();
    let (u0, u1) = road.u_range();
    let (v0, v1) = road.v_range();
    let (du, dv) = road.increments();
    let nan = g.z.iter().filter(|z| z.is_nan()).count();
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
        "options": settings_json(road.options()),
        "modifiers": settings_json(road.modifiers()),
        "warnings": road.warnings(),
    })
}

/// The facts as lines of text.
pub fn text(road: &Road, path: &str) -> String {
    let f = facts(road, path);
    let n = |v: &Json| v.as_f64().map_or("?".to_string(), |x| format!("{x}"));
    let mut out = String::new();
    let mut line = |k: &str, v: String| out.push_str(&format!("{k:<15}{v}\n"));
    line("file", format!("{} ({})", path, f["format"].as_str().unwrap_or("?")));
    let refs = road.header().references.iter().map(|p| p.display().to_string()).collect::<Vec<_>>();
    if !refs.is_empty() {
        line("references", refs.join(", "));
    }
    let g = road.grid();
    line(
        "size",
        format!(
            "{} cross sections x {} long sections ({} cells), {} channels",
            g.nu,
            g.nv,
            g.nu * g.nv,
            road.header().channels.len()
        ),
    );
    let other: Vec<String> = road
        .header()
        .channels
        .iter()
        .filter(|c| !matches!(c, Channel::SectionAt(_) | Channel::SectionIndex(_)))
        .map(channel_name)
        .collect();
    line("line channels", if other.is_empty() { "none".into() } else { other.join(", ") });
    line("u", format!("{} .. {} m, increment {} m", n(&f["u"]["first"]), n(&f["u"]["last"]), n(&f["u"]["increment"])));
    line("v", format!("{} .. {} m, increment {} m", n(&f["v"]["right"]), n(&f["v"]["left"]), n(&f["v"]["increment"])));
    let r = &f["reference_line"];
    line(
        "start",
        format!(
            "x {:.4} m, y {:.4} m, heading {:.4} rad",
            r["start"]["x"].as_f64().unwrap_or(0.0),
            r["start"]["y"].as_f64().unwrap_or(0.0),
            r["start"]["heading"].as_f64().unwrap_or(0.0)
        ),
    );
    line(
        "end",
        format!(
            "x {:.4} m, y {:.4} m, heading {:.4} rad",
            r["end"]["x"].as_f64().unwrap_or(0.0),
            r["end"]["y"].as_f64().unwrap_or(0.0),
            r["end"]["heading"].as_f64().unwrap_or(0.0)
        ),
    );
    line("length", format!("{} m", n(&r["length"])));
    line("line z", format!("{:.4} .. {:.4} m", r["z"][0].as_f64().unwrap_or(0.0), r["z"][1].as_f64().unwrap_or(0.0)));
    line(
        "closed",
        match road.closed_track() {
            Some((a, b)) => format!("yes, over u = {a:.4} .. {b:.4} m"),
            None => "no".into(),
        },
    );
    let e = &f["elevation"];
    line("elevation", format!("{:.4} .. {:.4} m", e["min"].as_f64().unwrap_or(0.0), e["max"].as_f64().unwrap_or(0.0)));
    line("NaN cells", format!("{}", f["nan_cells"]));
    line("options", settings_text(road.options()));
    line("modifiers", settings_text(road.modifiers()));
    for w in road.warnings() {
        line("warning", w.clone());
    }
    out
}
