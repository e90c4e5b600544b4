//! Writing a road to a CRG file in any of the four data formats.
//!
//! The header carries the reference line start (and end, where the source gave it),
//! the long section layout, the road's options and modifiers; the data holds the
//! heading, slope and banking channels that the road has and the elevation grid.
//! Reading the file back gives the same data: bit-exact for KDBI (and for KRBI
//! where the source values are single precision), within the text format's
//! precision for LRFI and LDFI.

use crate::base::error::{Error, Result};
use crate::base::settings::{Accepts, Family, Settings, Value, SETTINGS};
use crate::model::grid::{bank_v, VLayout};
use crate::model::header::{keyword_of, DataFormat, RoadKey, OFFSET_KEYS};
use crate::model::road::Road;
use std::io::{self, BufWriter, Write};
use std::path::Path;

/// Writes `road` to `path` in `format`: all or nothing (the file is written beside
/// `path` under a temporary name, then renamed; a failure leaves `path` as it was).
pub fn write(road: &Road, path: impl AsRef<Path>, format: DataFormat) -> Result<()> {
    let path = path.as_ref();
    let err = |source| Error::writing(path, source);
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let temporary = path.with_file_name(format!(".{name}.{}.partial", std::process::id()));
    let written = (|| {
        let file = std::fs::File::create(&temporary)?;
        let mut out = BufWriter::with_capacity(1 << 20, file);
        write_to(road, &mut out, format)?;
        out.into_inner().map_err(|e| e.into_error())?.sync_all()?;
        std::fs::rename(&temporary, path)
    })();
    if written.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    written.map_err(err)
}

/// The settings of a family written back to a file: those with a keyword, in table order
/// (the message count lives in the header, not in the options).
fn written(settings: &Settings, family: Family) -> impl Iterator<Item = (&'static str, Value)> + '_ {
    SETTINGS.iter().filter(move |s| s.family == family && s.accepts != Accepts::Count).filter_map(|s| {
        let value = settings.get(s.id)?;
        // A check read from a file is switched on by 1 and stored as its identifier.
        let value = if s.accepts == Accepts::Flag { Value::Int(1) } else { value };
        Some((s.keyword?, value))
    })
}

fn value_text(v: Value) -> String {
    match v {
        Value::Int(i) => i.to_string(),
        Value::Double(d) => format!("{d:?}"),
    }
}

/// Writes `road` as a CRG file to any writer.
pub fn write_to(road: &Road, out: &mut impl Write, format: DataFormat) -> io::Result<()> {
    write_header(road, out)?;
    let by_points = write_definition(road, out, format)?;
    write_data(road, out, format, by_points)
}

/// A section's opening line, after the rule between sections.
fn section(out: &mut impl Write, name: &str) -> io::Result<()> {
    writeln!(out, "$!**********************************************************************")?;
    writeln!(out, "{name}")
}

/// The `$ROAD_CRG` values written, in this order: each value's key (whose keyword the
/// reader's table gives), the value and whether it is written.
fn road_values(road: &Road) -> [(RoadKey, f64, bool); 18] {
    let (l, g) = (&road.line, &road.grid);
    let ends_xy = l.defined.x_end && l.defined.y_end;
    // The long sections' own range (a road read from a file without it holds 0 and 0;
    // the grid values then carry the banking's share the change of range moves).
    let sections = g.sections_range();
    [
        (RoadKey::StartU, l.u_first, true),
        (RoadKey::EndU, l.u_last, true),
        (RoadKey::Increment, l.u_inc, true),
        (RoadKey::StartX, l.x_first, true),
        (RoadKey::StartY, l.y_first, true),
        (RoadKey::EndX, l.x_last, ends_xy),
        (RoadKey::EndY, l.y_last, ends_xy),
        (RoadKey::StartPhi, l.phi_first, true),
        (RoadKey::EndPhi, l.phi_last, true),
        (RoadKey::StartZ, l.z_first, l.defined.z_start),
        (RoadKey::EndZ, l.z_last, l.defined.z_end),
        (RoadKey::StartSlope, l.slope_first, l.slope_first != 0.0),
        (RoadKey::EndSlope, l.slope_last, l.slope_last != 0.0),
        (RoadKey::StartBank, l.bank_first, l.bank_first != 0.0),
        (RoadKey::EndBank, l.bank_last, l.bank_last != 0.0),
        (RoadKey::VRight, sections.0, true),
        (RoadKey::VLeft, sections.1, true),
        (RoadKey::VIncrement, g.v_inc, g.layout == VLayout::Indexed),
    ]
}

/// The comments, `$ROAD_CRG` and the options, modifiers and `$ROAD_CRG_MPRO` sections.
fn write_header(road: &Road, out: &mut impl Write) -> io::Result<()> {
    writeln!(out, "$CT")?;
    for c in &road.header.comments {
        writeln!(out, "{c}")?;
    }
    writeln!(out, "written by opencrg {}", env!("CARGO_PKG_VERSION"))?;
    section(out, "$ROAD_CRG")?;
    let mut kv = |k: &str, v: f64| writeln!(out, "{k:<25}= {v:?}");
    for (key, v, written) in road_values(road) {
        if written {
            kv(&keyword_of(key).to_ascii_uppercase(), v)?;
        }
    }
    // The global origin as it is now (modifiers that moved the road changed it), where
    // the file gave one or it is not the default.
    let o = road.global_origin();
    if road.header.road.offset.iter().any(Option::is_some) || o != Default::default() {
        for (k, v) in OFFSET_KEYS.iter().zip([o.x, o.y, o.z, o.phi]) {
            kv(k, v)?;
        }
    }
    for (k, v) in &road.header.road.extra {
        kv(k, *v)?;
    }
    for (name, family) in [("$ROAD_CRG_OPTS", Family::Option), ("$ROAD_CRG_MODS", Family::Modifier)] {
        section(out, name)?;
        let settings = if family == Family::Option { &road.options } else { &road.modifiers };
        for (name, v) in written(settings, family) {
            writeln!(out, "{name:<25}= {}", value_text(v))?;
        }
    }
    if !road.header.mpro.is_empty() {
        section(out, "$ROAD_CRG_MPRO")?;
        for (k, v) in &road.header.mpro {
            writeln!(out, "{k:<25}= {v}")?;
        }
    }
    Ok(())
}

/// `$KD_Definition`: the format and the channels; whether the reference line is written
/// by its points (a line given by points is; otherwise by its heading).
fn write_definition(road: &Road, out: &mut impl Write, format: DataFormat) -> io::Result<bool> {
    let (l, g) = (&road.line, &road.grid);
    section(out, "$KD_Definition")?;
    writeln!(out, "#:{}", format.name())?;
    let by_points = road.header.channels.contains(&crate::model::header::Channel::RefX);
    if by_points {
        writeln!(out, "D:reference line x,m")?;
        writeln!(out, "D:reference line y,m")?;
    }
    for (channel, name) in [(&l.phi, "phi,rad"), (&l.slope, "slope,m/m"), (&l.bank, "banking,m/m")] {
        if channel.is_some() {
            writeln!(out, "D:reference line {name}")?;
        }
    }
    for (i, v) in g.v.iter().enumerate() {
        match g.layout {
            VLayout::Indexed => writeln!(out, "D:long section {},m", i + 1)?,
            VLayout::Explicit => writeln!(out, "D:long section at v = {v:?},m")?,
        }
    }
    section(out, &"$".repeat(80))?;
    Ok(by_points)
}

/// The data: a record per cross section (the line's channels, then the heights), text or
/// big-endian binary, a binary file padded with NaN to whole 80-byte records.
fn write_data(road: &Road, out: &mut impl Write, format: DataFormat, by_points: bool) -> io::Result<()> {
    let (l, g) = (&road.line, &road.grid);
    let sections = g.sections_range();
    let width = format.field_width();
    let mut row: Vec<f64> = Vec::with_capacity(g.nv + 3);
    let mut text = String::new();
    let mut bytes_written = 0usize;
    let mean = g.mean;
    let read_range = (g.v_first, g.v_last);
    g.rows(0..g.nu, |iu, values| -> io::Result<()> {
        row.clear();
        if by_points {
            row.push(l.x[iu]);
            row.push(l.y[iu]);
        }
        for ch in [&l.phi, &l.slope, &l.bank].into_iter().flatten() {
            row.push(ch[iu]);
        }
        if l.has_bank && read_range != sections {
            // Banking acts within the sections' range in the file written: each node keeps
            // its surface.
            let bank = l.bank.as_ref().map_or(l.bank_first, |b| b[iu]);
            row.extend(
                values
                    .iter()
                    .zip(&g.v)
                    .map(|(&z, &v)| f64::from(z) + mean + bank * (bank_v(v, read_range) - bank_v(v, sections))),
            );
        } else {
            row.extend(values.iter().map(|&z| if mean == 0.0 { f64::from(z) } else { f64::from(z) + mean }));
        }
        if format.is_text() {
            text.clear();
            let per_line = 80 / width;
            for (i, v) in row.iter().enumerate() {
                if i > 0 && i % per_line == 0 {
                    text.push('\n');
                }
                fit(&mut text, *v, width);
            }
            text.push('\n');
            out.write_all(text.as_bytes())
        } else {
            bytes_written += row.len() * width;
            row.iter().try_for_each(|&v| binary(out, v, width))
        }
    })?;
    if !format.is_text() {
        while !bytes_written.is_multiple_of(80) {
            binary(out, f64::NAN, width)?;
            bytes_written += width;
        }
    }
    Ok(())
}

/// One value big-endian in `width` bytes (4: single precision, 8: double).
fn binary(out: &mut impl Write, v: f64, width: usize) -> io::Result<()> {
    if width == 4 {
        out.write_all(&(v as f32).to_be_bytes())
    } else {
        out.write_all(&v.to_be_bytes())
    }
}

/// Appends `v` in exactly `width` characters with as much precision as fits.
fn fit(out: &mut String, v: f64, width: usize) {
    use std::fmt::Write as _;
    if !v.is_finite() {
        out.push_str(&"*".repeat(width - 3));
        out.push_str("NaN");
        return;
    }
    let best = candidates(v, width).min_by(|a, b| (a.1).total_cmp(&b.1)).map(|c| c.0);
    match best {
        Some(s) => {
            let _ = write!(out, "{s:>width$}");
        }
        None => out.push_str(&"*".repeat(width)),
    }
}

/// Fixed and exponent renderings of `v` that fit in `width` characters, with their
/// errors. Fields may touch: the reader splits by width, not by blanks.
fn candidates(v: f64, width: usize) -> impl Iterator<Item = (String, f64)> {
    let room = width;
    let mut fixed = (0..room).rev().map(move |p| format!("{v:.p$}"));
    let sci = (0..room).rev().map(move |p| format!("{v:.p$e}"));
    fixed.find(|s| s.len() <= room).into_iter().chain(sci.clone().find(|s| s.len() <= room)).map(move |s| {
        let err = (s.parse::<f64>().unwrap_or(f64::INFINITY) - v).abs();
        (s, err)
    })
}

#[cfg(test)]
mod tests {
    use super::fit;

    #[test]
    fn fields_fit_their_width() {
        for (v, w) in [(0.0111111, 10), (-123456.789, 10), (1.234e-9, 10), (6.02e23, 10), (-0.5, 20), (1.0 / 3.0, 20)] {
            let mut s = String::new();
            fit(&mut s, v, w);
            assert_eq!(s.len(), w, "{s:?}");
            let back: f64 = s.trim().parse().unwrap();
            assert!((back - v).abs() <= v.abs() * 1e-5 + 1e-7, "{v} -> {s}");
        }
    }
}
