//! Option and modifier tables.
//!
//! Contact point options and data set modifiers share one numbering (the classic
//! API's `dCrgCpOption*` and `dCrgMod*` identifiers never overlap). Each table is a
//! fixed array indexed by identifier, so a lookup in the evaluation hot path is an
//! index, not a search.

/// Identifiers of contact point options (values of the classic `dCrgCpOption*`).
pub mod opt {
    /// Border mode in u direction (integer, see [`super::BorderMode`]).
    pub const BORDER_MODE_U: u32 = 1;
    /// Border mode in v direction (integer, see [`super::BorderMode`]).
    pub const BORDER_MODE_V: u32 = 2;
    /// Curvature mode (integer: 0 lateral, 1 reference line).
    pub const CURV_MODE: u32 = 3;
    /// z offset beyond the u borders (double).
    pub const BORDER_OFFSET_U: u32 = 5;
    /// z offset beyond the v borders (double).
    pub const BORDER_OFFSET_V: u32 = 6;
    /// Smoothing zone at the begin of the road (double, > 0).
    pub const SMOOTH_U_BEGIN: u32 = 7;
    /// Smoothing zone at the end of the road (double, > 0).
    pub const SMOOTH_U_END: u32 = 8;
    /// Preload the x/y search history at this u (double).
    pub const REFLINE_SEARCH_U: u32 = 9;
    /// Preload the x/y search history at this fraction of the u range (double).
    pub const REFLINE_SEARCH_U_FRAC: u32 = 10;
    /// Distance under which a history entry is a close hit (double).
    pub const REFLINE_CLOSE: u32 = 11;
    /// Distance under which a history entry is a far hit (double).
    pub const REFLINE_FAR: u32 = 12;
    /// Reference line continuation (integer: 0 extrapolate, 1 close track).
    pub const REFLINE_CONTINUE: u32 = 13;
    /// Maximum number of warning messages (integer).
    pub const WARN_MSGS: u32 = 14;
    /// Expected minimum accuracy for checks (double).
    pub const CHECK_EPS: u32 = 15;
    /// Expected minimum increment for checks (double).
    pub const CHECK_INC: u32 = 16;
    /// Expected absolute tolerance for checks (double).
    pub const CHECK_TOL: u32 = 17;
    /// Local curvature check (integer).
    pub const WARN_CURV_LOCAL: u32 = 18;
    /// Global curvature check (integer).
    pub const WARN_CURV_GLOBAL: u32 = 19;
}

/// Identifiers of data set modifiers (values of the classic `dCrgMod*`).
pub mod m {
    /// Scale factor for the elevation grid.
    pub const SCALE_Z: u32 = 21;
    /// Scale factor for the slope.
    pub const SCALE_SLOPE: u32 = 22;
    /// Scale factor for the banking.
    pub const SCALE_BANK: u32 = 23;
    /// Scale factor for the length (u).
    pub const SCALE_LENGTH: u32 = 24;
    /// Scale factor for the width (v).
    pub const SCALE_WIDTH: u32 = 25;
    /// Scale factor for the reference line curvature.
    pub const SCALE_CURVATURE: u32 = 26;
    /// NaN handling mode of the grid borders (integer, see [`super::NanMode`]).
    pub const GRID_NAN_MODE: u32 = 27;
    /// Offset added to former NaN values.
    pub const GRID_NAN_OFFSET: u32 = 28;
    /// Reference point v (absolute).
    pub const REFPOINT_V: u32 = 29;
    /// Reference point v as a fraction of the width.
    pub const REFPOINT_V_FRAC: u32 = 30;
    /// Offset to the reference point v fraction.
    pub const REFPOINT_V_OFFSET: u32 = 31;
    /// Reference point u (absolute).
    pub const REFPOINT_U: u32 = 32;
    /// Reference point u as a fraction of the length.
    pub const REFPOINT_U_FRAC: u32 = 33;
    /// Offset to the reference point u fraction.
    pub const REFPOINT_U_OFFSET: u32 = 34;
    /// Target x of the reference point.
    pub const REFPOINT_X: u32 = 35;
    /// Target y of the reference point.
    pub const REFPOINT_Y: u32 = 36;
    /// Target z of the reference point.
    pub const REFPOINT_Z: u32 = 37;
    /// Target heading of the reference point.
    pub const REFPOINT_PHI: u32 = 38;
    /// Reference line offset in x.
    pub const REFLINE_OFFSET_X: u32 = 39;
    /// Reference line offset in y.
    pub const REFLINE_OFFSET_Y: u32 = 40;
    /// Reference line offset in z.
    pub const REFLINE_OFFSET_Z: u32 = 41;
    /// Reference line rotation angle.
    pub const REFLINE_OFFSET_PHI: u32 = 42;
    /// Rotation center x.
    pub const REFLINE_ROTCENTER_X: u32 = 43;
    /// Rotation center y.
    pub const REFLINE_ROTCENTER_Y: u32 = 44;
}

/// Number of slots in a table (the classic `dCrgSizeOptList` plus one).
pub const TABLE_SIZE: usize = 51;

/// Border modes (values of `BORDER_MODE_U` / `BORDER_MODE_V`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BorderMode {
    /// Refuse the evaluation.
    None = 0,
    /// z is zero (plus the border offset).
    ExZero = 1,
    /// Keep the last value (plus the border offset).
    ExKeep = 2,
    /// Repeat the data.
    Repeat = 3,
    /// Reflect the data.
    Reflect = 4,
}

/// NaN handling modes of the grid (values of `GRID_NAN_MODE`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NanMode {
    /// Keep NaNs.
    Keep = 0,
    /// Replace NaNs by zero (plus offset).
    SetZero = 1,
    /// Replace NaNs by the last valid value of the cross section (plus offset).
    KeepLast = 2,
}

/// The value type a setting identifier takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// An integer setting.
    Int,
    /// A double setting.
    Double,
}

/// Which table a setting identifier belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    /// A contact point option.
    Option,
    /// A data set modifier.
    Modifier,
}

/// Which values a setting accepts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Accepts {
    /// Any number.
    Any,
    /// A choice among `0..=max`.
    Choice {
        /// The largest choice.
        max: i32,
    },
    /// A number greater than zero.
    Positive,
    /// A check switched on by the value 1 in a file (stored as the setting's identifier).
    Flag,
    /// A count of messages (read from a file into the header, not into the options).
    Count,
}

/// Everything known about one option or modifier: the one table the reader, the
/// writer, the printers and the C constants are served from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SettingInfo {
    /// The identifier (value of the classic C constant).
    pub id: u32,
    /// Option or modifier.
    pub family: Family,
    /// Integer or double.
    pub kind: Kind,
    /// The keyword in `$ROAD_CRG_OPTS` / `$ROAD_CRG_MODS` (upper case; read in any case).
    pub keyword: Option<&'static str>,
    /// The name printed in messages and printouts.
    pub name: &'static str,
    /// The classic C API's constant.
    pub c_constant: &'static str,
    /// The value [`Settings::default_options`] / [`Settings::default_modifiers`] set.
    pub default: Option<Value>,
    /// Which values are accepted.
    pub accepts: Accepts,
}

impl SettingInfo {
    /// The setting's name in code (the Python package lower-cases it, JavaScript takes
    /// it in any case): its file keyword (`BORDER_MODE_U`), or, for a setting files
    /// cannot carry, its C constant without prefix in snake case (`CURV_MODE`).
    pub fn code_name(&self) -> String {
        if let Some(word) = self.keyword {
            return word.to_string();
        }
        let bare = self.c_constant.trim_start_matches("dCrgCpOption").trim_start_matches("dCrgMod");
        let mut out = String::new();
        for (i, c) in bare.chars().enumerate() {
            if c.is_ascii_uppercase() && i > 0 {
                out.push('_');
            }
            out.push(c.to_ascii_uppercase());
        }
        out
    }
}

// One argument per column keeps each table row on one line.
#[allow(clippy::too_many_arguments)]
const fn row(
    id: u32,
    family: Family,
    kind: Kind,
    keyword: Option<&'static str>,
    name: &'static str,
    c_constant: &'static str,
    default: Option<Value>,
    accepts: Accepts,
) -> SettingInfo {
    SettingInfo { id, family, kind, keyword, name, c_constant, default, accepts }
}

use Accepts::{Any, Choice, Count, Flag, Positive};
use Family::{Modifier as M, Option as O};
use Kind::{Double as D, Int as I};

/// Every option and modifier, in identifier order.
#[rustfmt::skip]
pub const SETTINGS: [SettingInfo; 42] = [
    row(opt::BORDER_MODE_U, O, I, Some("BORDER_MODE_U"), "border mode u", "dCrgCpOptionBorderModeU", Some(Value::Int(2)), Choice { max: 4 }),
    row(opt::BORDER_MODE_V, O, I, Some("BORDER_MODE_V"), "border mode v", "dCrgCpOptionBorderModeV", Some(Value::Int(2)), Choice { max: 4 }),
    row(opt::CURV_MODE, O, I, None, "curvature evaluation mode", "dCrgCpOptionCurvMode", Some(Value::Int(0)), Choice { max: 1 }),
    row(opt::BORDER_OFFSET_U, O, D, Some("BORDER_OFFSET_U"), "offset at u border", "dCrgCpOptionBorderOffsetU", None, Any),
    row(opt::BORDER_OFFSET_V, O, D, Some("BORDER_OFFSET_V"), "offset at v border", "dCrgCpOptionBorderOffsetV", None, Any),
    row(opt::SMOOTH_U_BEGIN, O, D, Some("BORDER_SMOOTH_UBEG"), "smoothing zone at begin", "dCrgCpOptionSmoothUBegin", None, Positive),
    row(opt::SMOOTH_U_END, O, D, Some("BORDER_SMOOTH_UEND"), "smoothing zone at end", "dCrgCpOptionSmoothUEnd", None, Positive),
    row(opt::REFLINE_SEARCH_U, O, D, Some("REFLINE_SEARCH_U"), "refline search value u", "dCrgCpOptionRefLineSearchU", None, Any),
    row(opt::REFLINE_SEARCH_U_FRAC, O, D, Some("REFLINE_SEARCH_UFRAC"), "refline search value uFrac", "dCrgCpOptionRefLineSearchUFrac", None, Any),
    row(opt::REFLINE_CLOSE, O, D, Some("REFLINE_SEARCH_CLOSE"), "refline search close criteria", "dCrgCpOptionRefLineClose", None, Any),
    row(opt::REFLINE_FAR, O, D, Some("REFLINE_SEARCH_FAR"), "refline search far criteria", "dCrgCpOptionRefLineFar", None, Any),
    row(opt::REFLINE_CONTINUE, O, I, Some("REFLINE_CONTINUATION"), "refline continuation mode", "dCrgCpOptionRefLineContinue", None, Choice { max: 1 }),
    row(opt::WARN_MSGS, O, I, Some("WARN_MSGS"), "maximum number of warning messages", "dCrgCpOptionWarnMsgs", None, Count),
    row(opt::CHECK_EPS, O, D, Some("CHECK_EPS"), "expected min. accuracy", "dCrgCpOptionCheckEps", Some(Value::Double(1e-6)), Any),
    row(opt::CHECK_INC, O, D, Some("CHECK_INC"), "expected min. increment", "dCrgCpOptionCheckInc", Some(Value::Double(1e-3)), Any),
    row(opt::CHECK_TOL, O, D, Some("CHECK_TOL"), "expected abs. tolerance", "dCrgCpOptionCheckTol", Some(Value::Double(1e-4)), Any),
    row(opt::WARN_CURV_LOCAL, O, I, Some("WARN_CURV_LOCAL"), "local curvature check", "dCrgCpOptionWarnCurvLocal", None, Flag),
    row(opt::WARN_CURV_GLOBAL, O, I, Some("WARN_CURV_GLOBAL"), "global curvature check", "dCrgCpOptionWarnCurvGlobal", None, Flag),
    row(m::SCALE_Z, M, D, Some("SCALE_Z_GRID"), "modifier z scale", "dCrgModScaleZ", None, Any),
    row(m::SCALE_SLOPE, M, D, Some("SCALE_SLOPE"), "modifier slope scale", "dCrgModScaleSlope", None, Any),
    row(m::SCALE_BANK, M, D, Some("SCALE_BANKING"), "modifier bank scale", "dCrgModScaleBank", None, Any),
    row(m::SCALE_LENGTH, M, D, Some("SCALE_LENGTH"), "modifier length scale", "dCrgModScaleLength", None, Any),
    row(m::SCALE_WIDTH, M, D, Some("SCALE_WIDTH"), "modifier width scale", "dCrgModScaleWidth", None, Any),
    row(m::SCALE_CURVATURE, M, D, Some("SCALE_CURVATURE"), "modifier curvature scale", "dCrgModScaleCurvature", None, Any),
    row(m::GRID_NAN_MODE, M, I, Some("GRID_NAN_MODE"), "modifier grid NaN mode", "dCrgModGridNaNMode", Some(Value::Int(2)), Choice { max: 2 }),
    row(m::GRID_NAN_OFFSET, M, D, Some("GRID_NAN_OFFSET"), "modifier grid NaN offset", "dCrgModGridNaNOffset", None, Any),
    row(m::REFPOINT_V, M, D, Some("REFPOINT_V"), "modifier reference point v", "dCrgModRefPointV", None, Any),
    row(m::REFPOINT_V_FRAC, M, D, Some("REFPOINT_V_FRACTION"), "modifier reference point v fraction", "dCrgModRefPointVFrac", None, Any),
    row(m::REFPOINT_V_OFFSET, M, D, Some("REFPOINT_V_OFFSET"), "modifier reference point v offset", "dCrgModRefPointVOffset", None, Any),
    row(m::REFPOINT_U, M, D, Some("REFPOINT_U"), "modifier reference point u", "dCrgModRefPointU", None, Any),
    row(m::REFPOINT_U_FRAC, M, D, Some("REFPOINT_U_FRACTION"), "modifier reference point u fraction", "dCrgModRefPointUFrac", None, Any),
    row(m::REFPOINT_U_OFFSET, M, D, Some("REFPOINT_U_OFFSET"), "modifier reference point u offset", "dCrgModRefPointUOffset", None, Any),
    row(m::REFPOINT_X, M, D, Some("REFPOINT_X"), "reference point x", "dCrgModRefPointX", Some(Value::Double(0.0)), Any),
    row(m::REFPOINT_Y, M, D, Some("REFPOINT_Y"), "reference point y", "dCrgModRefPointY", Some(Value::Double(0.0)), Any),
    row(m::REFPOINT_Z, M, D, Some("REFPOINT_Z"), "reference point z", "dCrgModRefPointZ", Some(Value::Double(0.0)), Any),
    row(m::REFPOINT_PHI, M, D, Some("REFPOINT_PHI"), "reference point phi", "dCrgModRefPointPhi", Some(Value::Double(0.0)), Any),
    row(m::REFLINE_OFFSET_X, M, D, Some("REFLINE_OFFSET_X"), "modifier reference line offset x", "dCrgModRefLineOffsetX", None, Any),
    row(m::REFLINE_OFFSET_Y, M, D, Some("REFLINE_OFFSET_Y"), "modifier reference line offset y", "dCrgModRefLineOffsetY", None, Any),
    row(m::REFLINE_OFFSET_Z, M, D, Some("REFLINE_OFFSET_Z"), "modifier reference line offset z", "dCrgModRefLineOffsetZ", None, Any),
    row(m::REFLINE_OFFSET_PHI, M, D, Some("REFLINE_OFFSET_PHI"), "modifier reference line offset phi", "dCrgModRefLineOffsetPhi", None, Any),
    row(m::REFLINE_ROTCENTER_X, M, D, Some("REFLINE_ROTCENTER_X"), "modifier reference line rotation center x", "dCrgModRefLineRotCenterX", None, Any),
    row(m::REFLINE_ROTCENTER_Y, M, D, Some("REFLINE_ROTCENTER_Y"), "modifier reference line rotation center y", "dCrgModRefLineRotCenterY", None, Any),
];

/// Row of each identifier in [`SETTINGS`] (`u8::MAX`: no setting).
const ROW_OF: [u8; TABLE_SIZE] = {
    let mut rows = [u8::MAX; TABLE_SIZE];
    let mut i = 0;
    while i < SETTINGS.len() {
        rows[SETTINGS[i].id as usize] = i as u8;
        i += 1;
    }
    rows
};

/// The table row of an identifier; `None` for unknown identifiers.
pub fn info(id: u32) -> Option<&'static SettingInfo> {
    let row = *ROW_OF.get(id as usize)?;
    SETTINGS.get(row as usize)
}

/// The setting of a family whose file keyword is the longest prefix of `word` (any
/// case): files are read that way, so `REFPOINT_U_FRACTION` is not `REFPOINT_U`, and a
/// keyword with a suffix still counts.
pub fn by_keyword(family: Family, word: &str) -> Option<&'static SettingInfo> {
    let starts = |k: &str| word.len() >= k.len() && word.as_bytes()[..k.len()].eq_ignore_ascii_case(k.as_bytes());
    SETTINGS
        .iter()
        .filter(|s| s.family == family && s.keyword.is_some_and(starts))
        .max_by_key(|s| s.keyword.map_or(0, str::len))
}

/// Family and type of a known identifier; `None` for unknown identifiers.
pub fn describe(id: u32) -> Option<(Family, Kind)> {
    info(id).map(|s| (s.family, s.kind))
}

/// Whether setting `id` accepts `value` by the table's rule (a choice among its
/// choices, a number greater than zero where one is needed): the one check, and its
/// message, every binding refuses a value with. The C API's setters keep an integer
/// that is not a choice, as the reference library keeps it, and warn with this message.
pub fn check(id: u32, value: Value) -> Result<(), SettingError> {
    let Some(s) = info(id) else { return Ok(()) };
    match (s.accepts, value) {
        (Accepts::Choice { max }, Value::Int(v)) if !(0..=max).contains(&v) => {
            Err(SettingError::NotAChoice { name: s.name, value: v, max })
        }
        (Accepts::Positive, Value::Double(v)) if !(v > 0.0) => {
            Err(SettingError::Refused { name: s.name, value: v, why: "must be greater than zero" })
        }
        _ => Ok(()),
    }
}

/// A short human-readable name of a setting, used in messages and printouts.
pub fn name(id: u32) -> &'static str {
    info(id).map_or("unknown", |s| s.name)
}

/// The value of one setting.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// An integer value.
    Int(i32),
    /// A double value.
    Double(f64),
}

/// Why a setting was refused.
#[derive(Debug, Clone, PartialEq)]
pub enum SettingError {
    /// The identifier is not one of this table's family.
    UnknownId {
        /// The identifier given.
        id: u32,
        /// "option" or "modifier".
        family: &'static str,
    },
    /// The value has the wrong type for the identifier.
    WrongType {
        /// The setting's name.
        name: &'static str,
        /// "integer" or "double".
        expected: &'static str,
    },
    /// An integer that is not one of the setting's choices.
    NotAChoice {
        /// The setting's name.
        name: &'static str,
        /// The value given.
        value: i32,
        /// The largest choice.
        max: i32,
    },
    /// The value is outside what the setting accepts.
    Refused {
        /// The setting's name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// Why.
        why: &'static str,
    },
}

impl std::fmt::Display for SettingError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SettingError::UnknownId { id, family } => write!(f, "{id} is not a known {family} identifier"),
            SettingError::WrongType { name, expected } => write!(f, "setting <{name}> takes {expected} values"),
            SettingError::NotAChoice { name, value, max } => {
                write!(f, "<{name}> = {value} is not one of its choices 0 to {max}")
            }
            SettingError::Refused { name, value, why } => write!(f, "value {value} for <{name}> is refused: {why}"),
        }
    }
}

impl std::error::Error for SettingError {}

/// A table of settings of one family, indexed by identifier.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    family: Family,
    slots: [Option<Value>; TABLE_SIZE],
}

impl Settings {
    /// An empty table of contact point options.
    pub fn empty_options() -> Self {
        Settings { family: Family::Option, slots: [None; TABLE_SIZE] }
    }

    /// An empty table of data set modifiers.
    pub fn empty_modifiers() -> Self {
        Settings { family: Family::Modifier, slots: [None; TABLE_SIZE] }
    }

    /// The reference library's default options.
    pub fn default_options() -> Self {
        let mut s = Self::empty_options();
        s.reset_options();
        s
    }

    /// The reference library's default modifiers.
    pub fn default_modifiers() -> Self {
        let mut s = Self::empty_modifiers();
        s.reset_modifiers();
        s
    }

    /// Replaces every option by the defaults.
    pub fn reset_options(&mut self) {
        self.reset(Family::Option);
    }

    /// Replaces every modifier by the defaults.
    pub fn reset_modifiers(&mut self) {
        self.reset(Family::Modifier);
    }

    fn reset(&mut self, family: Family) {
        self.clear();
        for s in SETTINGS.iter().filter(|s| s.family == family) {
            self.slots[s.id as usize] = s.default;
        }
    }

    fn kind_of(&self, id: u32) -> Result<(Kind, &'static str), SettingError> {
        match describe(id) {
            Some((family, kind)) if family == self.family => Ok((kind, name(id))),
            _ => Err(SettingError::UnknownId {
                id,
                family: match self.family {
                    Family::Option => "option",
                    Family::Modifier => "modifier",
                },
            }),
        }
    }

    /// Sets an integer setting.
    pub fn set_int(&mut self, id: u32, value: i32) -> Result<(), SettingError> {
        let (kind, name) = self.kind_of(id)?;
        if kind != Kind::Int {
            return Err(SettingError::WrongType { name, expected: "double" });
        }
        self.slots[id as usize] = Some(Value::Int(value));
        Ok(())
    }

    /// Sets a double setting.
    pub fn set_double(&mut self, id: u32, value: f64) -> Result<(), SettingError> {
        let (kind, name) = self.kind_of(id)?;
        if kind != Kind::Double {
            return Err(SettingError::WrongType { name, expected: "integer" });
        }
        check(id, Value::Double(value))?;
        self.slots[id as usize] = Some(Value::Double(value));
        Ok(())
    }

    /// The value of a setting, if set.
    #[inline]
    pub fn get(&self, id: u32) -> Option<Value> {
        self.slots.get(id as usize).copied().flatten()
    }

    /// The integer value of a setting, if set (a double setting reads as its integer slot, 0).
    #[inline]
    pub fn get_int(&self, id: u32) -> Option<i32> {
        match self.get(id)? {
            Value::Int(i) => Some(i),
            Value::Double(_) => Some(0),
        }
    }

    /// The double value of a setting, if set (an integer setting reads as 0.0).
    #[inline]
    pub fn get_double(&self, id: u32) -> Option<f64> {
        match self.get(id)? {
            Value::Double(d) => Some(d),
            Value::Int(_) => Some(0.0),
        }
    }

    /// Whether the setting is set.
    #[inline]
    pub fn is_set(&self, id: u32) -> bool {
        self.get(id).is_some()
    }

    /// Whether an integer setting is set to exactly this value.
    #[inline]
    pub fn has_int(&self, id: u32, value: i32) -> bool {
        self.get_int(id) == Some(value)
    }

    /// Removes one setting; false when the identifier is outside the table.
    pub fn remove(&mut self, id: u32) -> bool {
        match self.slots.get_mut(id as usize) {
            Some(slot) => {
                *slot = None;
                true
            }
            None => false,
        }
    }

    /// Removes every setting.
    pub fn clear(&mut self) {
        self.slots = [None; TABLE_SIZE];
    }

    /// Every setting that is set, in identifier order.
    pub fn iter(&self) -> impl Iterator<Item = (u32, Value)> + '_ {
        self.slots.iter().enumerate().filter_map(|(i, v)| v.map(|v| (i as u32, v)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_choice_is_checked_by_its_range() {
        let mut choices = 0;
        for s in SETTINGS {
            if let Accepts::Choice { max } = s.accepts {
                choices += 1;
                assert!((0..=max).all(|v| check(s.id, Value::Int(v)).is_ok()), "{}", s.name);
                for v in [-1, max + 1, i32::MIN, i32::MAX] {
                    let e = check(s.id, Value::Int(v)).unwrap_err().to_string();
                    assert_eq!(e, format!("<{}> = {v} is not one of its choices 0 to {max}", s.name));
                }
            }
        }
        assert!(choices >= 4, "{choices}");
        assert!(check(opt::SMOOTH_U_END, Value::Double(0.0)).is_err());
        assert!(check(opt::BORDER_OFFSET_U, Value::Double(-5.0)).is_ok());
    }

    #[test]
    fn types_are_enforced() {
        let mut o = Settings::default_options();
        assert!(o.set_int(opt::BORDER_MODE_U, 3).is_ok());
        assert!(o.set_double(opt::BORDER_MODE_U, 3.0).is_err());
        assert!(o.set_int(opt::BORDER_OFFSET_U, 1).is_err());
        assert!(o.set_double(m::SCALE_Z, 1.0).is_err(), "modifier id refused by an option table");
        assert!(o.set_int(4, 1).is_err(), "unknown id refused");
        assert!(o.set_double(opt::SMOOTH_U_BEGIN, 0.0).is_err());
        assert_eq!(o.get_int(opt::BORDER_MODE_U), Some(3));
        assert!(o.remove(opt::BORDER_MODE_U));
        assert_eq!(o.get_int(opt::BORDER_MODE_U), None);
        assert!(!o.remove(99));
    }

    #[test]
    fn keywords_match_by_longest_prefix() {
        let id = |w| by_keyword(Family::Modifier, w).map(|s| s.id);
        assert_eq!(id("refpoint_u_fraction"), Some(m::REFPOINT_U_FRAC));
        assert_eq!(id("REFPOINT_U"), Some(m::REFPOINT_U));
        assert_eq!(id("refpoint_u_offsetx"), Some(m::REFPOINT_U_OFFSET));
        assert_eq!(id("refpoint"), None);
        assert_eq!(by_keyword(Family::Option, "refpoint_u").map(|s| s.id), None);
        assert_eq!(by_keyword(Family::Option, "refline_search_ufrac").map(|s| s.id), Some(opt::REFLINE_SEARCH_U_FRAC));
    }

    #[test]
    fn defaults_match_the_reference() {
        let o = Settings::default_options();
        assert_eq!(o.get_int(opt::BORDER_MODE_V), Some(2));
        assert_eq!(o.get_double(opt::CHECK_TOL), Some(1e-4));
        let md = Settings::default_modifiers();
        assert_eq!(md.get_int(m::GRID_NAN_MODE), Some(2));
        assert_eq!(md.iter().count(), 5);
    }
}
