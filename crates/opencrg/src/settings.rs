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

/// Family and type of a known identifier; `None` for unknown identifiers.
pub fn describe(id: u32) -> Option<(Family, Kind)> {
    use Family::*;
    use Kind::*;
    Some(match id {
        opt::BORDER_MODE_U
        | opt::BORDER_MODE_V
        | opt::CURV_MODE
        | opt::REFLINE_CONTINUE
        | opt::WARN_MSGS
        | opt::WARN_CURV_LOCAL
        | opt::WARN_CURV_GLOBAL => (Option, Int),
        opt::BORDER_OFFSET_U..=opt::REFLINE_FAR | opt::CHECK_EPS..=opt::CHECK_TOL => (Option, Double),
        m::GRID_NAN_MODE => (Modifier, Int),
        m::SCALE_Z..=m::REFLINE_ROTCENTER_Y => (Modifier, Double),
        _ => return None,
    })
}

/// A short human-readable name of a setting, used in messages and printouts.
pub fn name(id: u32) -> &'static str {
    match id {
        opt::BORDER_MODE_U => "border mode u",
        opt::BORDER_MODE_V => "border mode v",
        opt::CURV_MODE => "curvature evaluation mode",
        opt::BORDER_OFFSET_U => "offset at u border",
        opt::BORDER_OFFSET_V => "offset at v border",
        opt::SMOOTH_U_BEGIN => "smoothing zone at begin",
        opt::SMOOTH_U_END => "smoothing zone at end",
        opt::REFLINE_SEARCH_U => "refline search value u",
        opt::REFLINE_SEARCH_U_FRAC => "refline search value uFrac",
        opt::REFLINE_CLOSE => "refline search close criteria",
        opt::REFLINE_FAR => "refline search far criteria",
        opt::REFLINE_CONTINUE => "refline continuation mode",
        opt::WARN_MSGS => "maximum number of warning messages",
        opt::CHECK_EPS => "expected min. accuracy",
        opt::CHECK_INC => "expected min. increment",
        opt::CHECK_TOL => "expected abs. tolerance",
        opt::WARN_CURV_LOCAL => "local curvature check",
        opt::WARN_CURV_GLOBAL => "global curvature check",
        m::SCALE_Z => "modifier z scale",
        m::SCALE_SLOPE => "modifier slope scale",
        m::SCALE_BANK => "modifier bank scale",
        m::SCALE_LENGTH => "modifier length scale",
        m::SCALE_WIDTH => "modifier width scale",
        m::SCALE_CURVATURE => "modifier curvature scale",
        m::GRID_NAN_MODE => "modifier grid NaN mode",
        m::GRID_NAN_OFFSET => "modifier grid NaN offset",
        m::REFPOINT_V => "modifier reference point v",
        m::REFPOINT_V_FRAC => "modifier reference point v fraction",
        m::REFPOINT_V_OFFSET => "modifier reference point v offset",
        m::REFPOINT_U => "modifier reference point u",
        m::REFPOINT_U_FRAC => "modifier reference point u fraction",
        m::REFPOINT_U_OFFSET => "modifier reference point u offset",
        m::REFPOINT_X => "reference point x",
        m::REFPOINT_Y => "reference point y",
        m::REFPOINT_Z => "reference point z",
        m::REFPOINT_PHI => "reference point phi",
        m::REFLINE_OFFSET_X => "modifier reference line offset x",
        m::REFLINE_OFFSET_Y => "modifier reference line offset y",
        m::REFLINE_OFFSET_Z => "modifier reference line offset z",
        m::REFLINE_OFFSET_PHI => "modifier reference line offset phi",
        m::REFLINE_ROTCENTER_X => "modifier reference line rotation center x",
        m::REFLINE_ROTCENTER_Y => "modifier reference line rotation center y",
        _ => "unknown",
    }
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
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SettingError {
    /// The identifier is not one of this table's family.
    #[error("{id} is not a known {family} identifier")]
    UnknownId {
        /// The identifier given.
        id: u32,
        /// "option" or "modifier".
        family: &'static str,
    },
    /// The value has the wrong type for the identifier.
    #[error("setting <{name}> takes {expected} values")]
    WrongType {
        /// The setting's name.
        name: &'static str,
        /// "integer" or "double".
        expected: &'static str,
    },
    /// The value is outside what the setting accepts.
    #[error("value {value} for <{name}> is refused: {why}")]
    Refused {
        /// The setting's name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// Why.
        why: &'static str,
    },
}

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
        self.clear();
        self.slots[opt::CURV_MODE as usize] = Some(Value::Int(0));
        self.slots[opt::BORDER_MODE_U as usize] = Some(Value::Int(BorderMode::ExKeep as i32));
        self.slots[opt::BORDER_MODE_V as usize] = Some(Value::Int(BorderMode::ExKeep as i32));
        self.slots[opt::CHECK_EPS as usize] = Some(Value::Double(1e-6));
        self.slots[opt::CHECK_INC as usize] = Some(Value::Double(1e-3));
        self.slots[opt::CHECK_TOL as usize] = Some(Value::Double(1e-4));
    }

    /// Replaces every modifier by the defaults.
    pub fn reset_modifiers(&mut self) {
        self.clear();
        self.slots[m::GRID_NAN_MODE as usize] = Some(Value::Int(NanMode::KeepLast as i32));
        for id in [m::REFPOINT_X, m::REFPOINT_Y, m::REFPOINT_Z, m::REFPOINT_PHI] {
            self.slots[id as usize] = Some(Value::Double(0.0));
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
        if (id == opt::SMOOTH_U_BEGIN || id == opt::SMOOTH_U_END) && !(value > 0.0) {
            return Err(SettingError::Refused { name, value, why: "must be greater than zero" });
        }
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
    fn defaults_match_the_reference() {
        let o = Settings::default_options();
        assert_eq!(o.get_int(opt::BORDER_MODE_V), Some(2));
        assert_eq!(o.get_double(opt::CHECK_TOL), Some(1e-4));
        let md = Settings::default_modifiers();
        assert_eq!(md.get_int(m::GRID_NAN_MODE), Some(2));
        assert_eq!(md.iter().count(), 5);
    }
}
