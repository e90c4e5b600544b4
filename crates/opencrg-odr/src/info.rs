//! What a map holds, in figures: its roads, junctions, length and extent, and its CRG
//! records; one typed value ([`MapInfo`]) written as text (`Display`) and as JSON
//! ([`MapInfo::to_json`]), as `opencrg odr info` prints it.

use crate::map::{CrgMode, CrgPurpose, CrgRecord, Map};
use std::fmt::{self, Display, Write};

/// The facts of a map.
#[derive(Debug, Clone, PartialEq)]
pub struct MapInfo {
    /// The file it was read from.
    pub file: String,
    /// OpenDRIVE's version, `major.minor`.
    pub opendrive: String,
    /// The map's name.
    pub name: String,
    /// How many roads it has.
    pub roads: usize,
    /// How many of them connect roads in junctions.
    pub connecting_roads: usize,
    /// How many junctions it has.
    pub junctions: usize,
    /// The roads' length added up, m.
    pub length: f64,
    /// The roads' extent with their lanes (x0, y0, x1, y1), m; `None` without a road.
    pub extent: Option<[f64; 4]>,
    /// The CRG records of its roads, then of its junctions.
    pub crg_records: Vec<RecordInfo>,
}

/// One CRG record of a map.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordInfo {
    /// Where it lies: `road ID` or `junction ID`.
    pub on: String,
    /// Its file, as the map writes it.
    pub file: String,
    /// How it is laid on the road.
    pub mode: CrgMode,
    /// What it gives.
    pub purpose: CrgPurpose,
    /// Where along the road it starts, m.
    pub s_start: f64,
    /// Where it ends, m; `None`: at the road's end.
    pub s_end: Option<f64>,
    /// Its line in the map's file.
    pub line: usize,
}

impl CrgMode {
    /// The mode as the map writes it.
    pub fn name(self) -> &'static str {
        match self {
            CrgMode::Attached => "attached",
            CrgMode::Attached0 => "attached0",
            CrgMode::Genuine => "genuine",
            CrgMode::Global => "global",
        }
    }
}

impl CrgPurpose {
    /// The purpose as the map writes it.
    pub fn name(self) -> &'static str {
        match self {
            CrgPurpose::Elevation => "elevation",
            CrgPurpose::Friction => "friction",
        }
    }
}

impl Display for CrgMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl Display for CrgPurpose {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// About a million cross sections in all sample the map's extent, shared by length.
const EXTENT_SAMPLES: f64 = 1e6;

impl Map {
    /// The extent of the map's roads (x0, y0, x1, y1), their lanes included, from their
    /// outermost borders (and the lane offset, where the lanes start beyond the reference
    /// line) every 2 m (at most 10,000 cross sections a road, and about a million in all,
    /// shared by length); `None` without a road.
    pub fn extent(&self) -> Option<[f64; 4]> {
        let mut e = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
        let total = self.length();
        for road in &self.roads {
            let share = if total > 0.0 { (EXTENT_SAMPLES * road.length / total).ceil() } else { 1.0 };
            let n = (road.length / 2.0).ceil().min(share).clamp(1.0, 10_000.0) as usize;
            for k in 0..=n {
                let s = road.length * k as f64 / n as f64;
                let Some((section, ds)) = road.lanes.section_at(s) else { continue };
                let offset = road.lanes.offset.at(s);
                let borders =
                    [true, false].into_iter().flat_map(|left| section.spans(left, ds, offset).last().map(|l| l.outer));
                for t in borders.chain([0.0, offset]) {
                    let [x, y, _] = road.surface_point(s, t);
                    if x.is_finite() && y.is_finite() {
                        e = [e[0].min(x), e[1].min(y), e[2].max(x), e[3].max(y)];
                    }
                }
            }
        }
        e[0].is_finite().then_some(e)
    }

    /// What the map holds.
    pub fn info(&self) -> MapInfo {
        let record = |on: String, c: &CrgRecord| RecordInfo {
            on,
            file: c.file.clone(),
            mode: c.mode,
            purpose: c.purpose,
            s_start: c.s_start,
            s_end: c.s_end.is_finite().then_some(c.s_end),
            line: c.line,
        };
        let on_roads = self.roads.iter().flat_map(|r| r.crg.iter().map(move |c| (format!("road {}", r.id), c)));
        let on_junctions =
            self.junctions.iter().flat_map(|j| j.crg.iter().map(move |c| (format!("junction {}", j.id), c)));
        MapInfo {
            file: self.path.display().to_string(),
            opendrive: format!("{}.{}", self.header.rev_major, self.header.rev_minor),
            name: self.header.name.clone(),
            roads: self.roads.len(),
            connecting_roads: self.roads.iter().filter(|r| r.junction.is_some()).count(),
            junctions: self.junctions.len(),
            length: self.roads.iter().map(|r| r.length).sum(),
            extent: self.extent(),
            crg_records: on_roads.chain(on_junctions).map(|(on, c)| record(on, c)).collect(),
        }
    }
}

impl Display for MapInfo {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "file           {} (OpenDRIVE {})", self.file, self.opendrive)?;
        writeln!(
            f,
            "roads          {} ({} connecting roads in junctions), {:.1} m in all",
            self.roads, self.connecting_roads, self.length
        )?;
        writeln!(f, "junctions      {}", self.junctions)?;
        if let Some([x0, y0, x1, y1]) = self.extent {
            writeln!(f, "extent         x {x0:.2} .. {x1:.2} m, y {y0:.2} .. {y1:.2} m")?;
        }
        writeln!(f, "CRG records    {}", self.crg_records.len())?;
        for r in &self.crg_records {
            let end = r.s_end.map_or("end".to_string(), |e| format!("{e}"));
            writeln!(
                f,
                "  {}: {} ({}, {}), s {} to {end}, line {}",
                r.on,
                r.file,
                r.mode,
                r.purpose,
                number(r.s_start),
                r.line
            )?;
        }
        Ok(())
    }
}

impl MapInfo {
    /// The facts as JSON: an object with the fields of [`MapInfo`] (the extent as
    /// `{"x": [x0, x1], "y": [y0, y1]}`, each record an object), keys in alphabetical
    /// order, two spaces an indent.
    pub fn to_json(&self) -> String {
        let records: Vec<Json> = self
            .crg_records
            .iter()
            .map(|r| {
                Json::Object(vec![
                    ("file", Json::Text(r.file.clone())),
                    ("line", Json::Number(r.line as f64)),
                    ("mode", Json::Text(r.mode.name().into())),
                    ("on", Json::Text(r.on.clone())),
                    ("purpose", Json::Text(r.purpose.name().into())),
                    ("s_end", r.s_end.map_or(Json::Null, Json::Number)),
                    ("s_start", Json::Number(r.s_start)),
                ])
            })
            .collect();
        let extent = self.extent.map_or(Json::Null, |[x0, y0, x1, y1]| {
            Json::Object(vec![
                ("x", Json::Array(vec![Json::Number(x0), Json::Number(x1)])),
                ("y", Json::Array(vec![Json::Number(y0), Json::Number(y1)])),
            ])
        });
        let info = Json::Object(vec![
            ("connecting_roads", Json::Number(self.connecting_roads as f64)),
            ("crg_records", Json::Array(records)),
            ("extent", extent),
            ("file", Json::Text(self.file.clone())),
            ("junctions", Json::Number(self.junctions as f64)),
            ("length", Json::Number(self.length)),
            ("name", Json::Text(self.name.clone())),
            ("opendrive", Json::Text(self.opendrive.clone())),
            ("roads", Json::Number(self.roads as f64)),
        ]);
        let mut out = String::new();
        info.write(&mut out, 0);
        out
    }
}

/// A number as JSON and the text write it: integers without a fraction.
fn number(x: f64) -> String {
    if x.is_finite() && x == x.trunc() && x.abs() < 1e15 {
        format!("{}", x as i64)
    } else {
        format!("{x}")
    }
}

/// A JSON value, enough for [`MapInfo::to_json`].
enum Json {
    Null,
    Number(f64),
    Text(String),
    Array(Vec<Json>),
    Object(Vec<(&'static str, Json)>),
}

impl Json {
    /// Writes the value at `depth` levels of indentation.
    fn write(&self, out: &mut String, depth: usize) {
        let indent = |out: &mut String, d: usize| out.push_str(&"  ".repeat(d));
        match self {
            Json::Null => out.push_str("null"),
            Json::Number(x) if !x.is_finite() => out.push_str("null"),
            Json::Number(x) if *x == x.trunc() && x.abs() < 1e15 && (*x != 0.0 || x.is_sign_positive()) => {
                let _ = write!(out, "{}", *x as i64);
            }
            Json::Number(x) => {
                let _ = write!(out, "{x:?}");
            }
            Json::Text(s) => {
                out.push('"');
                for c in s.chars() {
                    match c {
                        '"' => out.push_str("\\\""),
                        '\\' => out.push_str("\\\\"),
                        c if (c as u32) < 0x20 => {
                            let _ = write!(out, "\\u{:04x}", c as u32);
                        }
                        c => out.push(c),
                    }
                }
                out.push('"');
            }
            Json::Array(items) if items.is_empty() => out.push_str("[]"),
            Json::Array(items) => {
                out.push_str("[\n");
                for (i, item) in items.iter().enumerate() {
                    indent(out, depth + 1);
                    item.write(out, depth + 1);
                    out.push_str(if i + 1 < items.len() { ",\n" } else { "\n" });
                }
                indent(out, depth);
                out.push(']');
            }
            Json::Object(fields) => {
                out.push_str("{\n");
                for (i, (key, value)) in fields.iter().enumerate() {
                    indent(out, depth + 1);
                    let _ = write!(out, "\"{key}\": ");
                    value.write(out, depth + 1);
                    out.push_str(if i + 1 < fields.len() { ",\n" } else { "\n" });
                }
                indent(out, depth);
                out.push('}');
            }
        }
    }
}
