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

/// What a pass over the whole grid finds: how many cells are NaN, and the lowest and
/// highest elevation as the road's statistics give them (see
/// [`Statistics`](crate::report::Statistics)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridScan {
    /// Cells without an elevation.
    pub nan_cells: usize,
    /// The lowest elevation.
    pub z_min: f64,
    /// The highest elevation.
    pub z_max: f64,
}

/// Scans the grid of `road`: from memory, or read from the file of a grid read in place
/// cross section after cross section (its pages handed back as it goes, so that a grid
/// larger than memory passes through), `progress` told (cross sections done, in all)
/// every 64 Mi values. Refused: a file that could not be read, naming it.
pub fn scan(road: &Road, progress: &mut dyn FnMut(usize, usize)) -> crate::base::error::Result<GridScan> {
    let g = road.grid();
    let s = road.statistics();
    if !g.is_in_place() {
        let nan_cells = g.values().iter().filter(|z| z.is_nan()).count();
        return Ok(GridScan { nan_cells, z_min: s.z_min, z_max: s.z_max });
    }
    let (mut nan_cells, mut lo, mut hi) = (0, f32::INFINITY, f32::NEG_INFINITY);
    let every = ((64 << 20) / g.nv.max(1)).max(1);
    g.rows(0..g.nu, |iu, row| {
        for &z in row {
            if z.is_nan() {
                nan_cells += 1;
            } else {
                lo = lo.min(z);
                hi = hi.max(z);
            }
        }
        if iu % every == 0 {
            progress(iu, g.nu);
        }
        Ok::<(), crate::base::error::Error>(())
    })?;
    progress(g.nu, g.nu);
    let start = s.z_mean_start - g.mean;
    Ok(GridScan { nan_cells, z_min: start.min(f64::from(lo)) + g.mean, z_max: start.max(f64::from(hi)) + g.mean })
}

/// What `road` holds, line by line, the file named `path` (a grid read in place not
/// scanned: see [`text_scanned`]).
pub fn text(road: &Road, path: &str) -> String {
    let g = road.grid();
    let scanned = (!g.is_in_place()).then(|| scan(road, &mut |_, _| {}).ok()).flatten();
    text_scanned(road, path, scanned.as_ref())
}

/// [`text`] with what a scan of the grid found (for a grid read in place: else it says
/// the grid was not scanned).
pub fn text_scanned(road: &Road, path: &str, scanned: Option<&GridScan>) -> String {
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
    match scanned {
        Some(scan) => {
            line("elevation", format!("{:.4} .. {:.4} m", scan.z_min, scan.z_max));
            line("NaN cells", format!("{}", scan.nan_cells));
        }
        None => line("elevation", "not scanned: the grid is read in place (--scan reads it whole)".into()),
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
