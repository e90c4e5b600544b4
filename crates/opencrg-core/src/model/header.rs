//! What a file's header says, as data: its sections' values, the data format and the
//! channels. The reading (syntax, sections, references) lives in `read`.

use crate::base::settings::Settings;
use std::path::{Path, PathBuf};

/// Everything the header sections of a file and the files it references say.
#[derive(Debug, Clone)]
pub struct Header {
    /// The file that was loaded.
    pub path: PathBuf,
    /// `$CT` lines.
    pub comments: Vec<String>,
    /// `$ROAD_CRG` parameters.
    pub road: RoadParams,
    /// Data format from `#:` (KRBI when absent).
    pub format: DataFormat,
    /// `D:` channels in column order.
    pub channels: Vec<Channel>,
    /// Options from `$ROAD_CRG_OPTS` over the defaults.
    pub options: Settings,
    /// Modifiers: the defaults, or exactly those of a `$ROAD_CRG_MODS` section.
    pub modifiers: Settings,
    /// `$ROAD_CRG_MPRO` key/value pairs as written (keys lower case).
    pub mpro: Vec<(String, String)>,
    /// The map projection the `$ROAD_CRG_MPRO` section describes, if it has one.
    pub map: Option<crate::model::georef::MapProjection>,
    /// Tolerances of the map checks (`CHECK_PRO`, `CHECK_WGS` of `$ROAD_CRG_OPTS`).
    pub map_tolerances: crate::model::georef::MapTolerances,
    /// Files read through `$ROAD_CRG_FILE`, in reading order.
    pub references: Vec<PathBuf>,
    /// `WARN_MSGS` from the options section, if given.
    pub warn_msgs: Option<i32>,
    /// Things worth telling the user that did not stop the reading.
    pub warnings: Vec<String>,
    /// Whether the top file itself numbered its long sections (`D:long section N`).
    /// Evaluation finds v cells by index only then: the reference library forgets that
    /// a referenced file numbered them, and looks numbered sections up by position.
    pub top_file_numbers_sections: bool,
    /// Whether the file (or a file it references) has a `$ROAD_CRG_MODS` section: without,
    /// `modifiers` are the reference library's defaults, which users that lay the road
    /// in a frame of their own (OpenDRIVE) leave out.
    pub modifiers_given: bool,
}

impl Header {
    /// A header that gives nothing yet: no comments or channels, the default options
    /// and modifiers, format KRBI. `path` names the file it stands for.
    pub fn new(path: &Path) -> Header {
        Header {
            path: path.to_path_buf(),
            comments: Vec::new(),
            road: RoadParams::default(),
            format: DataFormat::Krbi,
            channels: Vec::new(),
            options: Settings::default_options(),
            modifiers: Settings::default_modifiers(),
            mpro: Vec::new(),
            map: None,
            map_tolerances: crate::model::georef::MapTolerances::default(),
            references: Vec::new(),
            warn_msgs: None,
            warnings: Vec::new(),
            top_file_numbers_sections: false,
            modifiers_given: false,
        }
    }
}

/// The `$ROAD_CRG` parameters as written in the file (`None` where absent).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RoadParams {
    /// `REFERENCE_LINE_START_U`.
    pub start_u: Option<f64>,
    /// `REFERENCE_LINE_END_U`.
    pub end_u: Option<f64>,
    /// `REFERENCE_LINE_START_X`.
    pub start_x: Option<f64>,
    /// `REFERENCE_LINE_START_Y`.
    pub start_y: Option<f64>,
    /// `REFERENCE_LINE_START_Z`.
    pub start_z: Option<f64>,
    /// `REFERENCE_LINE_START_PHI`.
    pub start_phi: Option<f64>,
    /// `REFERENCE_LINE_START_B` (banking).
    pub start_bank: Option<f64>,
    /// `REFERENCE_LINE_START_S` (slope).
    pub start_slope: Option<f64>,
    /// `REFERENCE_LINE_END_X`.
    pub end_x: Option<f64>,
    /// `REFERENCE_LINE_END_Y`.
    pub end_y: Option<f64>,
    /// `REFERENCE_LINE_END_Z`.
    pub end_z: Option<f64>,
    /// `REFERENCE_LINE_END_PHI`.
    pub end_phi: Option<f64>,
    /// `REFERENCE_LINE_END_B`.
    pub end_bank: Option<f64>,
    /// `REFERENCE_LINE_END_S`.
    pub end_slope: Option<f64>,
    /// `REFERENCE_LINE_INCREMENT`.
    pub increment: Option<f64>,
    /// `LONG_SECTION_V_RIGHT`.
    pub v_right: Option<f64>,
    /// `LONG_SECTION_V_LEFT`.
    pub v_left: Option<f64>,
    /// `LONG_SECTION_V_INCREMENT`.
    pub v_increment: Option<f64>,
    /// `REFERENCE_LINE_OFFSET_X`, `_Y`, `_Z` and `_PHI`: the global origin.
    pub offset: [Option<f64>; 4],
    /// WGS84 values (`REFERENCE_LINE_START_LON` ... `REFERENCE_LINE_END_ALT`) and any
    /// other key of the section, in file order.
    pub extra: Vec<(String, f64)>,
    /// Which end values the top file itself gave. Only these choose how the reference
    /// line is integrated: the reference library forgets which ones a referenced file
    /// gave (it keeps their values, though).
    pub top_file_gives: EndsGiven,
}

/// The keywords of the global origin, in the order of [`RoadParams::offset`].
pub const OFFSET_KEYS: [&str; 4] =
    ["REFERENCE_LINE_OFFSET_X", "REFERENCE_LINE_OFFSET_Y", "REFERENCE_LINE_OFFSET_Z", "REFERENCE_LINE_OFFSET_PHI"];

/// End values of the reference line that a file gave.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct EndsGiven {
    /// `REFERENCE_LINE_END_X`.
    pub x_end: bool,
    /// `REFERENCE_LINE_END_Y`.
    pub y_end: bool,
    /// `REFERENCE_LINE_START_Z`.
    pub z_start: bool,
    /// `REFERENCE_LINE_END_Z`.
    pub z_end: bool,
}

/// The `$ROAD_CRG` values the road uses.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum RoadKey {
    StartU,
    EndU,
    StartX,
    StartY,
    StartZ,
    StartPhi,
    StartBank,
    StartSlope,
    EndX,
    EndY,
    EndZ,
    EndPhi,
    EndBank,
    EndSlope,
    Increment,
    VRight,
    VLeft,
    VIncrement,
}

/// `$ROAD_CRG` keywords (lower case) and the values they set.
pub(crate) const ROAD_KEYS: [(&str, RoadKey); 18] = [
    ("reference_line_start_u", RoadKey::StartU),
    ("reference_line_end_u", RoadKey::EndU),
    ("reference_line_start_x", RoadKey::StartX),
    ("reference_line_start_y", RoadKey::StartY),
    ("reference_line_start_z", RoadKey::StartZ),
    ("reference_line_start_phi", RoadKey::StartPhi),
    ("reference_line_start_b", RoadKey::StartBank),
    ("reference_line_start_s", RoadKey::StartSlope),
    ("reference_line_end_x", RoadKey::EndX),
    ("reference_line_end_y", RoadKey::EndY),
    ("reference_line_end_z", RoadKey::EndZ),
    ("reference_line_end_phi", RoadKey::EndPhi),
    ("reference_line_end_b", RoadKey::EndBank),
    ("reference_line_end_s", RoadKey::EndSlope),
    ("reference_line_increment", RoadKey::Increment),
    ("long_section_v_right", RoadKey::VRight),
    ("long_section_v_left", RoadKey::VLeft),
    ("long_section_v_increment", RoadKey::VIncrement),
];

/// The keyword (lower case) of a `$ROAD_CRG` value, from [`ROAD_KEYS`].
pub(crate) fn keyword_of(key: RoadKey) -> &'static str {
    ROAD_KEYS.iter().find(|(_, k)| *k == key).map_or("", |(word, _)| word)
}

impl RoadParams {
    /// The values given, under their keywords (upper case), then the other keys of the
    /// section in file order.
    pub fn entries(&self) -> Vec<(String, f64)> {
        let mut copy = self.clone();
        let mut out: Vec<(String, f64)> = ROAD_KEYS
            .iter()
            .filter_map(|&(word, key)| copy.slot(key).map(|v| (word.to_ascii_uppercase(), v)))
            .collect();
        for (word, v) in OFFSET_KEYS.iter().zip(self.offset) {
            out.extend(v.map(|v| (word.to_string(), v)));
        }
        out.extend(self.extra.iter().map(|(k, v)| (k.to_ascii_uppercase(), *v)));
        out
    }

    /// A value kept among the other keys (`extra`), by its keyword in any case: for
    /// example `REFERENCE_LINE_START_LAT`.
    pub fn extra_value(&self, keyword: &str) -> Option<f64> {
        self.extra.iter().rev().find(|(k, _)| k.eq_ignore_ascii_case(keyword)).map(|(_, v)| *v)
    }

    /// The WGS 84 position given for the start (`false`) or end (`true`) of the
    /// reference line: latitude and longitude in degrees, altitude in metres (`None`
    /// where the file gives no such pair; the altitude 0 when it gives none).
    pub fn wgs84(&self, end: bool) -> Option<[f64; 3]> {
        let which = if end { "END" } else { "START" };
        let get = |what: &str| self.extra_value(&format!("REFERENCE_LINE_{which}_{what}"));
        Some([get("LAT")?, get("LON")?, get("ALT").unwrap_or(0.0)])
    }

    /// The value a keyword sets.
    pub(crate) fn slot(&mut self, key: RoadKey) -> &mut Option<f64> {
        match key {
            RoadKey::StartU => &mut self.start_u,
            RoadKey::EndU => &mut self.end_u,
            RoadKey::StartX => &mut self.start_x,
            RoadKey::StartY => &mut self.start_y,
            RoadKey::StartZ => &mut self.start_z,
            RoadKey::StartPhi => &mut self.start_phi,
            RoadKey::StartBank => &mut self.start_bank,
            RoadKey::StartSlope => &mut self.start_slope,
            RoadKey::EndX => &mut self.end_x,
            RoadKey::EndY => &mut self.end_y,
            RoadKey::EndZ => &mut self.end_z,
            RoadKey::EndPhi => &mut self.end_phi,
            RoadKey::EndBank => &mut self.end_bank,
            RoadKey::EndSlope => &mut self.end_slope,
            RoadKey::Increment => &mut self.increment,
            RoadKey::VRight => &mut self.v_right,
            RoadKey::VLeft => &mut self.v_left,
            RoadKey::VIncrement => &mut self.v_increment,
        }
    }
}

/// The data formats of the data section.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DataFormat {
    /// `LRFI`: text, 10-character fields, 8 per 80-character line.
    Lrfi,
    /// `LDFI`: text, 20-character fields, 4 per 80-character line.
    Ldfi,
    /// `KRBI`: big-endian 4-byte floats.
    Krbi,
    /// `KDBI`: big-endian 8-byte doubles.
    Kdbi,
}

impl DataFormat {
    /// The format named after `#:` (any case, comments after it ignored); `None` for
    /// anything but the four formats of the specification.
    pub fn from_letters(letters: &str) -> Option<Self> {
        let name = letters.split('!').next().unwrap_or("").trim().to_ascii_uppercase();
        Some(match name.as_str() {
            "LRFI" => DataFormat::Lrfi,
            "LDFI" => DataFormat::Ldfi,
            "KRBI" => DataFormat::Krbi,
            "KDBI" => DataFormat::Kdbi,
            _ => return None,
        })
    }

    /// The format's name as written after `#:`.
    pub fn name(self) -> &'static str {
        match self {
            DataFormat::Lrfi => "LRFI",
            DataFormat::Ldfi => "LDFI",
            DataFormat::Krbi => "KRBI",
            DataFormat::Kdbi => "KDBI",
        }
    }

    /// Whether the data is text.
    pub fn is_text(self) -> bool {
        matches!(self, DataFormat::Lrfi | DataFormat::Ldfi)
    }

    /// Width of one value: characters for text, bytes for binary.
    pub(crate) fn field_width(self) -> usize {
        match self {
            DataFormat::Lrfi => 10,
            DataFormat::Ldfi => 20,
            DataFormat::Krbi => 4,
            DataFormat::Kdbi => 8,
        }
    }
}

/// One `D:` channel definition.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Channel {
    /// Reference line x.
    RefX,
    /// Reference line y.
    RefY,
    /// Reference line u.
    RefU,
    /// Reference line heading.
    RefPhi,
    /// Reference line banking.
    RefBank,
    /// Reference line slope.
    RefSlope,
    /// A long section at an explicit v.
    SectionAt(f64),
    /// The n-th long section of a regular v grid.
    SectionIndex(f64),
}

impl std::fmt::Display for Channel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Channel::RefX => f.write_str("reference line x"),
            Channel::RefY => f.write_str("reference line y"),
            Channel::RefU => f.write_str("reference line u"),
            Channel::RefPhi => f.write_str("reference line heading"),
            Channel::RefSlope => f.write_str("reference line slope"),
            Channel::RefBank => f.write_str("reference line banking"),
            Channel::SectionAt(v) => write!(f, "long section at v = {v}"),
            Channel::SectionIndex(n) => write!(f, "long section {n}"),
        }
    }
}
