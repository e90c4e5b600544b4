//! Consistency checks of a road, its options and its modifiers (as `crgCheck`).

use crate::base::compat::Compat;
use crate::base::error::{Error, Result};
use crate::base::settings::{m, opt, Settings};
use crate::model::road::Road;

impl Road {
    /// Checks the options and modifiers and, when the options ask for it, the
    /// curvature of the reference line against the road's width.
    ///
    /// Like the reference, this completes the relocation modifiers with their
    /// defaults, and refuses a road whose line can be closed when the u border mode
    /// is 1.
    pub fn check(&mut self) -> Result<()> {
        if self.line.closed.is_some() && self.options.has_int(opt::BORDER_MODE_U, 1) {
            return Err(Error::Check("reference line can be closed but the u border mode is 1".into()));
        }
        check_options(&self.options)?;
        let mut defaulted = Vec::new();
        let checked = check_modifiers(&mut self.modifiers, self.compat, &mut defaulted);
        for (id, value) in defaulted {
            self.note(crate::model::report::Event::ModifierDefaulted { id, value });
        }
        checked?;
        let global = self.options.is_set(opt::WARN_CURV_GLOBAL);
        let local = self.options.is_set(opt::WARN_CURV_LOCAL);
        if (global || local) && !self.curvature_fits_width() {
            return Err(Error::Check("reference line curvature radius is smaller than the road's half width".into()));
        }
        Ok(())
    }

    /// Whether the tightest curve of the reference line leaves its center outside the road.
    fn curvature_fits_width(&self) -> bool {
        let l = &self.line;
        let (mut cmin, mut cmax) = (0.0f64, 0.0f64);
        let hd = l.curvature_scale(1);
        for i in 1..l.n - 1 {
            let c = l.curvature_at(i, 1, hd);
            if c < cmin {
                cmin = c;
            }
            if c > cmax {
                cmax = c;
            }
        }
        let (vmin, vmax) = (self.grid.v_first, self.grid.v_last);
        if cmax != 0.0 && vmax >= 1.0 / cmax {
            return false;
        }
        if cmin != 0.0 && 1.0 / cmin >= vmin {
            return false;
        }
        true
    }
}

fn refuse(what: &str, value: impl std::fmt::Display) -> Error {
    Error::Check(format!("illegal option {what}: {value}"))
}

fn check_options(o: &Settings) -> Result<()> {
    for (id, name) in [(opt::BORDER_MODE_U, "BORDER_MODE_U"), (opt::BORDER_MODE_V, "BORDER_MODE_V")] {
        if let Some(v) = o.get_int(id) {
            if !(0..=4).contains(&v) {
                return Err(refuse(name, v));
            }
        }
    }
    for (id, name) in [(opt::SMOOTH_U_BEGIN, "BORDER_SMOOTH_UBEG"), (opt::SMOOTH_U_END, "BORDER_SMOOTH_UEND")] {
        if let Some(v) = o.get_double(id) {
            if v < 0.0 {
                return Err(refuse(name, v));
            }
        }
    }
    if let Some(v) = o.get_int(opt::REFLINE_CONTINUE) {
        if !(0..=1).contains(&v) {
            return Err(refuse("REFLINE_CONTINUATION", v));
        }
    }
    let far = o.get_double(opt::REFLINE_FAR);
    if let Some(f) = far {
        if f < 0.0 {
            return Err(refuse("REFLINE_SEARCH_FAR", f));
        }
    }
    if let Some(c) = o.get_double(opt::REFLINE_CLOSE) {
        if c < 0.0 || far.is_some_and(|f| c >= f) {
            return Err(refuse("REFLINE_SEARCH_CLOSE", c));
        }
    }
    if let Some(w) = o.get_int(opt::WARN_MSGS) {
        if w < -1 {
            return Err(refuse("WARN_MSGS", w));
        }
    }
    let eps = o.get_double(opt::CHECK_EPS).ok_or_else(|| Error::Check("option CHECK_EPS is missing".into()))?;
    if !(1.0e-6..=1.0e-2).contains(&eps) {
        return Err(refuse("CHECK_EPS", eps));
    }
    let mid = 0.001;
    let inc = o.get_double(opt::CHECK_INC).ok_or_else(|| Error::Check("option CHECK_INC is missing".into()))?;
    let rounded = ((inc / mid + 0.5) as i32) as f64 * mid;
    if inc < mid * (1.0 - eps) || (rounded - inc).abs() > eps * mid.max(inc) {
        return Err(refuse("CHECK_INC", inc));
    }
    let tol = o.get_double(opt::CHECK_TOL).ok_or_else(|| Error::Check("option CHECK_TOL is missing".into()))?;
    if tol < eps * inc || tol > 0.5 * inc {
        return Err(refuse("CHECK_TOL", tol));
    }
    Ok(())
}

/// Checks the modifiers and completes the relocation ones with their defaults, noting
/// in `defaulted` the reference point coordinates it chose.
fn check_modifiers(mods: &mut Settings, compat: Compat, defaulted: &mut Vec<(u32, f64)>) -> Result<()> {
    for (id, name) in [(m::SCALE_LENGTH, "SCALE_LENGTH"), (m::SCALE_WIDTH, "SCALE_WIDTH")] {
        if let Some(v) = mods.get_double(id) {
            if v <= 0.0 {
                return Err(Error::Check(format!("illegal modifier {name}: {v}")));
            }
        }
    }
    if let Some(mode) = mods.get_int(m::GRID_NAN_MODE) {
        if !(0..=2).contains(&mode) {
            return Err(Error::Check(format!("illegal modifier GRID_NAN_MODE: {mode}")));
        }
    }
    if let Some(off) = mods.get_double(m::GRID_NAN_OFFSET) {
        match mods.get_int(m::GRID_NAN_MODE) {
            // The reference completes the mode with its default and then, reading the mode
            // it did not find as 0, refuses the offset all the same.
            None => {
                mods.set_int(m::GRID_NAN_MODE, 2)?;
                return Err(Error::Check(format!(
                    "GRID_NAN_OFFSET {off} given without GRID_NAN_MODE (the mode is now 2, keep last; check again)"
                )));
            }
            Some(0) => {
                return Err(Error::Check(format!("GRID_NAN_OFFSET {off} given with GRID_NAN_MODE 0 (keep NaN)")));
            }
            Some(_) => {}
        }
    }
    let offsets = [m::REFLINE_OFFSET_PHI, m::REFLINE_OFFSET_X, m::REFLINE_OFFSET_Y, m::REFLINE_OFFSET_Z];
    let refpoint = [
        m::REFPOINT_U_FRAC,
        m::REFPOINT_U,
        m::REFPOINT_V_FRAC,
        m::REFPOINT_V,
        m::REFPOINT_X,
        m::REFPOINT_Y,
        m::REFPOINT_Z,
        m::REFPOINT_PHI,
    ];
    let by_offset = offsets.iter().any(|&id| mods.is_set(id));
    let by_refpoint = refpoint.iter().any(|&id| mods.is_set(id));
    if by_offset {
        for id in offsets {
            if !mods.is_set(id) {
                mods.set_double(id, 0.0)?;
            }
        }
    }
    if by_offset && by_refpoint {
        for id in offsets {
            mods.remove(id);
        }
        return Err(Error::Check("relocation by reference point and by offset are both set".into()));
    }
    if by_refpoint {
        for (frac, abs, what) in [(m::REFPOINT_U_FRAC, m::REFPOINT_U, "u"), (m::REFPOINT_V_FRAC, m::REFPOINT_V, "v")] {
            match (mods.is_set(frac), mods.is_set(abs)) {
                (true, true) => {
                    return Err(Error::Check(format!(
                        "only one of REFPOINT_{0} and REFPOINT_{0}_FRACTION may be set",
                        what.to_uppercase()
                    )))
                }
                // Neither given: u starts at the first cross section; v is the
                // reference line's (the releases took the right border).
                (false, false) => {
                    let default = if what == "v" && compat == Compat::Upstream { abs } else { frac };
                    mods.set_double(default, 0.0)?;
                    defaulted.push((default, 0.0));
                }
                _ => {}
            }
        }
        for id in
            [m::REFPOINT_U_OFFSET, m::REFPOINT_V_OFFSET, m::REFPOINT_X, m::REFPOINT_Y, m::REFPOINT_Z, m::REFPOINT_PHI]
        {
            if !mods.is_set(id) {
                mods.set_double(id, 0.0)?;
            }
        }
    }
    Ok(())
}
