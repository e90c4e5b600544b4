//! Options and modifiers with typed values: an enum per choice, so that a Rust caller
//! cannot set `BORDER_MODE_U = 9`; numbers are checked against the settings table.
//!
//! ```
//! use opencrg_core::settings::BorderMode;
//! use opencrg_core::{CpOption, Modifier};
//! # let mut road = opencrg_core::synth::RoadSpec::straight(10.0, 2.0, 0.5, 0.5).build()?;
//! road.set_modifier(Modifier::RefLineOffsetPhi(0.1))?;
//! road.apply_modifiers();
//! let mut cp = opencrg_core::ContactPoint::new(std::sync::Arc::new(road));
//! cp.set_option(CpOption::BorderModeV(BorderMode::Repeat))?;
//! cp.set_option(CpOption::SmoothUBegin(2.0))?;
//! assert!(cp.set_option(CpOption::SmoothUEnd(0.0)).is_err());
//! # Ok::<(), opencrg_core::Error>(())
//! ```

use crate::base::error::Result;
use crate::base::settings::{m, opt, BorderMode, NanMode, Settings, Value};

/// Curvature modes (values of `CURV_MODE`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurvMode {
    /// The curvature of the parallel to the reference line at v (the default).
    Lateral = 0,
    /// The reference line's curvature.
    RefLine = 1,
}

/// Reference line continuation (values of `REFLINE_CONTINUE`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Continuation {
    /// Extrapolate beyond the ends (the default).
    Extrapolate = 0,
    /// Continue a closed track around.
    CloseTrack = 1,
}

/// A contact point option and its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CpOption {
    /// Border mode in u.
    BorderModeU(BorderMode),
    /// Border mode in v.
    BorderModeV(BorderMode),
    /// Curvature mode.
    CurvMode(CurvMode),
    /// z offset beyond the u borders.
    BorderOffsetU(f64),
    /// z offset beyond the v borders.
    BorderOffsetV(f64),
    /// Smoothing zone at the begin of the road (> 0).
    SmoothUBegin(f64),
    /// Smoothing zone at the end of the road (> 0).
    SmoothUEnd(f64),
    /// Preload the x/y search history at this u.
    RefLineSearchU(f64),
    /// Preload the x/y search history at this fraction of the u range.
    RefLineSearchUFrac(f64),
    /// Distance under which a history entry is a close hit.
    RefLineClose(f64),
    /// Distance under which a history entry is a far hit.
    RefLineFar(f64),
    /// Reference line continuation.
    RefLineContinue(Continuation),
    /// Maximum number of warning messages.
    WarnMsgs(i32),
    /// Expected minimum accuracy for checks.
    CheckEps(f64),
    /// Expected minimum increment for checks.
    CheckInc(f64),
    /// Expected absolute tolerance for checks.
    CheckTol(f64),
    /// Local curvature check on or off.
    WarnCurvLocal(bool),
    /// Global curvature check on or off.
    WarnCurvGlobal(bool),
}

/// A data set modifier and its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Modifier {
    /// Scale factor for the elevation grid.
    ScaleZ(f64),
    /// Scale factor for the slope.
    ScaleSlope(f64),
    /// Scale factor for the banking.
    ScaleBank(f64),
    /// Scale factor for the length (u).
    ScaleLength(f64),
    /// Scale factor for the width (v).
    ScaleWidth(f64),
    /// Scale factor for the reference line curvature.
    ScaleCurvature(f64),
    /// NaN handling of the grid.
    GridNanMode(NanMode),
    /// Offset added to former NaN values.
    GridNanOffset(f64),
    /// Reference point v (absolute).
    RefPointV(f64),
    /// Reference point v as a fraction of the width.
    RefPointVFrac(f64),
    /// Offset to the reference point v fraction.
    RefPointVOffset(f64),
    /// Reference point u (absolute).
    RefPointU(f64),
    /// Reference point u as a fraction of the length.
    RefPointUFrac(f64),
    /// Offset to the reference point u fraction.
    RefPointUOffset(f64),
    /// Target x of the reference point.
    RefPointX(f64),
    /// Target y of the reference point.
    RefPointY(f64),
    /// Target z of the reference point.
    RefPointZ(f64),
    /// Target heading of the reference point.
    RefPointPhi(f64),
    /// Reference line offset in x.
    RefLineOffsetX(f64),
    /// Reference line offset in y.
    RefLineOffsetY(f64),
    /// Reference line offset in z.
    RefLineOffsetZ(f64),
    /// Reference line rotation angle.
    RefLineOffsetPhi(f64),
    /// Rotation center x.
    RefLineRotCenterX(f64),
    /// Rotation center y.
    RefLineRotCenterY(f64),
}

impl CpOption {
    /// The identifier and the value to store (`None`: a check switched off, not stored).
    pub fn entry(self) -> (u32, Option<Value>) {
        use CpOption::*;
        let d = |id, v| (id, Some(Value::Double(v)));
        let i = |id, v: i32| (id, Some(Value::Int(v)));
        match self {
            BorderModeU(b) => i(opt::BORDER_MODE_U, b as i32),
            BorderModeV(b) => i(opt::BORDER_MODE_V, b as i32),
            CurvMode(c) => i(opt::CURV_MODE, c as i32),
            BorderOffsetU(v) => d(opt::BORDER_OFFSET_U, v),
            BorderOffsetV(v) => d(opt::BORDER_OFFSET_V, v),
            SmoothUBegin(v) => d(opt::SMOOTH_U_BEGIN, v),
            SmoothUEnd(v) => d(opt::SMOOTH_U_END, v),
            RefLineSearchU(v) => d(opt::REFLINE_SEARCH_U, v),
            RefLineSearchUFrac(v) => d(opt::REFLINE_SEARCH_U_FRAC, v),
            RefLineClose(v) => d(opt::REFLINE_CLOSE, v),
            RefLineFar(v) => d(opt::REFLINE_FAR, v),
            RefLineContinue(c) => i(opt::REFLINE_CONTINUE, c as i32),
            WarnMsgs(n) => i(opt::WARN_MSGS, n),
            CheckEps(v) => d(opt::CHECK_EPS, v),
            CheckInc(v) => d(opt::CHECK_INC, v),
            CheckTol(v) => d(opt::CHECK_TOL, v),
            // A check is stored as its own identifier, as a file's `= 1` sets it.
            WarnCurvLocal(on) => (opt::WARN_CURV_LOCAL, on.then_some(Value::Int(opt::WARN_CURV_LOCAL as i32))),
            WarnCurvGlobal(on) => (opt::WARN_CURV_GLOBAL, on.then_some(Value::Int(opt::WARN_CURV_GLOBAL as i32))),
        }
    }
}

impl Modifier {
    /// The identifier and the value to store.
    pub fn entry(self) -> (u32, Value) {
        use Modifier::*;
        let d = |id, v| (id, Value::Double(v));
        match self {
            ScaleZ(v) => d(m::SCALE_Z, v),
            ScaleSlope(v) => d(m::SCALE_SLOPE, v),
            ScaleBank(v) => d(m::SCALE_BANK, v),
            ScaleLength(v) => d(m::SCALE_LENGTH, v),
            ScaleWidth(v) => d(m::SCALE_WIDTH, v),
            ScaleCurvature(v) => d(m::SCALE_CURVATURE, v),
            GridNanMode(n) => (m::GRID_NAN_MODE, Value::Int(n as i32)),
            GridNanOffset(v) => d(m::GRID_NAN_OFFSET, v),
            RefPointV(v) => d(m::REFPOINT_V, v),
            RefPointVFrac(v) => d(m::REFPOINT_V_FRAC, v),
            RefPointVOffset(v) => d(m::REFPOINT_V_OFFSET, v),
            RefPointU(v) => d(m::REFPOINT_U, v),
            RefPointUFrac(v) => d(m::REFPOINT_U_FRAC, v),
            RefPointUOffset(v) => d(m::REFPOINT_U_OFFSET, v),
            RefPointX(v) => d(m::REFPOINT_X, v),
            RefPointY(v) => d(m::REFPOINT_Y, v),
            RefPointZ(v) => d(m::REFPOINT_Z, v),
            RefPointPhi(v) => d(m::REFPOINT_PHI, v),
            RefLineOffsetX(v) => d(m::REFLINE_OFFSET_X, v),
            RefLineOffsetY(v) => d(m::REFLINE_OFFSET_Y, v),
            RefLineOffsetZ(v) => d(m::REFLINE_OFFSET_Z, v),
            RefLineOffsetPhi(v) => d(m::REFLINE_OFFSET_PHI, v),
            RefLineRotCenterX(v) => d(m::REFLINE_ROTCENTER_X, v),
            RefLineRotCenterY(v) => d(m::REFLINE_ROTCENTER_Y, v),
        }
    }
}

impl Settings {
    /// Sets a value by identifier, checked as `set_int` / `set_double` check it.
    pub fn set_value(&mut self, id: u32, value: Value) -> Result<()> {
        match value {
            Value::Int(i) => self.set_int(id, i)?,
            Value::Double(d) => self.set_double(id, d)?,
        }
        Ok(())
    }

    /// Sets a modifier (in a table of modifiers).
    pub fn set_modifier(&mut self, modifier: Modifier) -> Result<()> {
        let (id, value) = modifier.entry();
        self.set_value(id, value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::settings::{info, Family, Kind, SETTINGS};

    fn every_option() -> Vec<CpOption> {
        use CpOption::*;
        vec![
            BorderModeU(BorderMode::Repeat),
            BorderModeV(BorderMode::Reflect),
            CurvMode(super::CurvMode::RefLine),
            BorderOffsetU(0.1),
            BorderOffsetV(0.2),
            SmoothUBegin(1.0),
            SmoothUEnd(2.0),
            RefLineSearchU(3.0),
            RefLineSearchUFrac(0.5),
            RefLineClose(0.3),
            RefLineFar(2.2),
            RefLineContinue(Continuation::CloseTrack),
            WarnMsgs(5),
            CheckEps(1e-6),
            CheckInc(1e-3),
            CheckTol(1e-4),
            WarnCurvLocal(true),
            WarnCurvGlobal(true),
        ]
    }

    fn every_modifier() -> Vec<Modifier> {
        use Modifier::*;
        let mut all = vec![GridNanMode(NanMode::SetZero)];
        let doubles: [fn(f64) -> Modifier; 23] = [
            ScaleZ,
            ScaleSlope,
            ScaleBank,
            ScaleLength,
            ScaleWidth,
            ScaleCurvature,
            GridNanOffset,
            RefPointV,
            RefPointVFrac,
            RefPointVOffset,
            RefPointU,
            RefPointUFrac,
            RefPointUOffset,
            RefPointX,
            RefPointY,
            RefPointZ,
            RefPointPhi,
            RefLineOffsetX,
            RefLineOffsetY,
            RefLineOffsetZ,
            RefLineOffsetPhi,
            RefLineRotCenterX,
            RefLineRotCenterY,
        ];
        all.extend(doubles.iter().map(|f| f(0.5)));
        all
    }

    #[test]
    fn every_setting_has_one_typed_form_of_its_table_type() {
        let mut ids: Vec<u32> = Vec::new();
        let kind_of = |v: Value| match v {
            Value::Int(_) => Kind::Int,
            Value::Double(_) => Kind::Double,
        };
        for o in every_option() {
            let (id, value) = o.entry();
            let row = info(id).expect("a known id");
            assert_eq!((row.family, Some(row.kind)), (Family::Option, value.map(kind_of)), "{o:?}");
            ids.push(id);
        }
        for md in every_modifier() {
            let (id, value) = md.entry();
            let row = info(id).expect("a known id");
            assert_eq!((row.family, row.kind), (Family::Modifier, kind_of(value)), "{md:?}");
            ids.push(id);
        }
        ids.sort_unstable();
        let table: Vec<u32> = SETTINGS.iter().map(|s| s.id).collect();
        assert_eq!(ids, table, "one typed form per row of the table");
    }

    #[test]
    fn values_are_checked_and_checks_switch_off() {
        let mut mods = Settings::empty_modifiers();
        mods.set_modifier(Modifier::GridNanMode(NanMode::Keep)).unwrap();
        assert_eq!(mods.get_int(m::GRID_NAN_MODE), Some(0));
        let mut opts = Settings::empty_options();
        let (id, value) = CpOption::SmoothUBegin(-1.0).entry();
        assert!(opts.set_value(id, value.unwrap()).is_err(), "the table's 'greater than zero'");
        assert_eq!(CpOption::WarnCurvGlobal(false).entry(), (opt::WARN_CURV_GLOBAL, None));
    }
}
