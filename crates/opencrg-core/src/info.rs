//! What a road holds, as people read it: the text `opencrg info` prints, for every
//! binding that shows a road (the command's JSON gives the same facts).

use crate::base::settings::{name, Settings, Value};
use crate::geo::earth::Earth;
use crate::model::header::Channel;
use crate::model::road::Road;

/// The settings as `name = value` items.
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

/// The start (`false`) or end (`true`) of the reference line in WGS 84: latitude,
/// longitude (degrees), height, and where it comes from (the map projection, or the
/// file's keywords when it has none).
pub fn wgs84(road: &Road, end: bool) -> Option<([f64; 3], &'static str)> {
    if let Ok(earth) = Earth::of(road) {
        let l = road.reference_line();
        let i = if end { l.n - 1 } else { 0 };
        return earth.xyz_to_llh(road, [l.x[i], l.y[i], l.z_at(i)]).ok().map(|p| (p, "map projection"));
    }
    road.header().road.wgs84(end).map(|p| (p, "file keywords"))
}

/// What `road` holds, line by line, the file named `path`.
pub fn text(road: &Road, path: &str) -> String {
    let h = road.header();
    let g = road.grid();
    let s = road.statistics();
    let ((u0, u1), (v0, v1), (du, dv)) = (road.u_range(), road.v_range(), road.increments());
    let mut out = String::new();
    let mut line = |k: &str, v: String| out.push_str(&format!("{k:<15}{v}\n"));
    line("file", format!("{path} ({})", road.format().name()));
    if !h.references.is_empty() {
        line("references", h.references.iter().map(|p| p.display().to_string()).collect::<Vec<_>>().join(", "));
    }
    line(
        "size",
        format!(
            "{} cross sections x {} long sections ({} cells), {} channels",
            g.nu,
            g.nv,
            g.nu * g.nv,
            h.channels.len()
        ),
    );
    let other: Vec<String> = h
        .channels
        .iter()
        .filter(|c| !matches!(c, Channel::SectionAt(_) | Channel::SectionIndex(_)))
        .map(ToString::to_string)
        .collect();
    line("line channels", if other.is_empty() { "none".into() } else { other.join(", ") });
    line("u", format!("{u0} .. {u1} m, increment {du} m"));
    line("v", format!("{v0} .. {v1} m, increment {dv} m"));
    let point = |(x, y, heading): (f64, f64, f64)| format!("x {x:.4} m, y {y:.4} m, heading {heading:.4} rad");
    line("start", point(s.start));
    line("end", point(s.end));
    line("length", format!("{} m", u1 - u0));
    line("line z", format!("{:.4} .. {:.4} m", s.z_line.0, s.z_line.1));
    line(
        "closed",
        match road.closed_track() {
            Some((a, b)) => format!("yes, over u = {a:.4} .. {b:.4} m"),
            None => "no".into(),
        },
    );
    match g.in_memory() {
        Some(values) => {
            line("elevation", format!("{:.4} .. {:.4} m", s.z_min, s.z_max));
            line("NaN cells", format!("{}", values.iter().filter(|z| z.is_nan()).count()));
        }
        None => line(
            "grid",
            format!(
                "read in place ({} tiles of the file read so far); its range and NaN cells are not scanned",
                g.tiles_read()
            ),
        ),
    }
    let o = road.global_origin();
    if o != Default::default() {
        line("global origin", format!("x {} m, y {} m, z {} m, heading {} rad", o.x, o.y, o.z, o.phi));
    }
    if let Some(m) = &h.map {
        let datum = m.datum.kind.name();
        line("map", format!("{} on {}, {datum} to {}", m.projection.name, m.local.name, m.global.name));
    }
    for (end, label) in [(false, "start WGS 84"), (true, "end WGS 84")] {
        if let Some(([lat, lon, alt], from)) = wgs84(road, end) {
            line(label, format!("lat {lat:.9}, lon {lon:.9}, alt {alt:.3} m ({from})"));
        }
    }
    line("options", settings_text(road.options()));
    line("modifiers", settings_text(road.modifiers()));
    for w in road.warnings() {
        line("warning", w.clone());
    }
    out
}
