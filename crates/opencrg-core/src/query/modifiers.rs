//! Applying modifiers: scaling, NaN handling of the grid borders, and relocation of
//! the road by reference point or by offset and rotation.

use crate::base::math;
use crate::base::settings::{m, NanMode, Settings};
use crate::model::grid::VLayout;
use crate::model::road::Road;
use crate::query::eval::{self, EvalOptions};

impl Road {
    /// Applies the road's modifiers once to its data (as `crgDataSetModifiersApply`).
    ///
    /// Scaling and NaN handling change the data and the derived reference line; the
    /// relocation then moves the road so the reference point lands on the target
    /// (or rotates and shifts it by the offsets). The modifiers stay set, so applying
    /// twice applies them twice.
    pub fn apply_modifiers(&mut self) {
        let mods = self.modifiers.clone();
        let mut prepare = false;
        if let Some(f) = mods.get_double(m::SCALE_Z) {
            prepare = true;
            self.grid.scale(f);
        }
        let l = &mut self.line;
        if let Some(f) = mods.get_double(m::SCALE_SLOPE) {
            prepare = true;
            scale_values(&mut l.slope, f);
            l.slope_first *= f;
            l.slope_last *= f;
            l.defined.z_end = false;
        }
        if let Some(f) = mods.get_double(m::SCALE_BANK) {
            scale_values(&mut l.bank, f);
            l.bank_first *= f;
            l.bank_last *= f;
        }
        if let Some(f) = mods.get_double(m::SCALE_LENGTH) {
            prepare = true;
            l.u_last = l.u_first + f * (l.u_last - l.u_first);
            l.u_inc *= f;
            l.defined.x_end = false;
            l.defined.y_end = false;
            l.defined.z_end = false;
        }
        if let Some(f) = mods.get_double(m::SCALE_WIDTH) {
            prepare = true;
            let g = &mut self.grid;
            g.v.iter_mut().for_each(|v| *v *= f);
            g.v_first *= f;
            g.v_last *= f;
            g.v_inc *= f;
        }
        if let Some(f) = mods.get_double(m::SCALE_CURVATURE) {
            prepare = true;
            let first = l.phi_first;
            match &mut l.phi {
                Some(phi) => {
                    phi.iter_mut().skip(1).for_each(|p| *p = first + f * (*p - first));
                    l.phi_last = phi[phi.len() - 1];
                }
                None => l.phi_last = first,
            }
            l.update_trig();
            l.defined.x_end = false;
            l.defined.y_end = false;
        }
        if let Some(mode) = mods.get_int(m::GRID_NAN_MODE) {
            prepare = true;
            let (mode, offset) = match mode {
                1 => (NanMode::SetZero, mods.get_double(m::GRID_NAN_OFFSET).unwrap_or(0.0)),
                2 => (NanMode::KeepLast, mods.get_double(m::GRID_NAN_OFFSET).unwrap_or(0.0)),
                _ => (NanMode::Keep, 0.0),
            };
            let event = match self.grid.fill_nans(mode, offset) {
                Some(found) => crate::model::report::Event::NansHandled(found),
                None => crate::model::report::Event::NansHandledWhereRead,
            };
            self.note(event);
        }
        if prepare {
            self.prepare();
        }
        self.relocate(&mods);
    }

    /// Elevation evaluated without any options, 0 where that refuses (used to find
    /// the z of the rotation center).
    fn z_without_options(&self, u: f64, v: f64) -> f64 {
        let (l, g) = (&self.line, &self.grid);
        if u < l.u_first || u > l.u_last {
            return 0.0;
        }
        let outside_v = match g.layout {
            VLayout::Indexed => v < g.v_first || v > g.v_last,
            // Outside, unless within the snap distance of either border (even when the
            // borders are inconsistent, as a right border past a missing left one).
            VLayout::Explicit => {
                let snaps = (v - g.v_first).abs() < eval::V_BORDER_SNAP || (v - g.v_last).abs() < eval::V_BORDER_SNAP;
                (v < g.v_first || v > g.v_last) && !snaps
            }
        };
        if outside_v {
            return 0.0;
        }
        eval::uv_to_z(self, &EvalOptions::from(&Settings::empty_options()), u, v).unwrap_or(0.0)
    }

    fn relocate(&mut self, mods: &Settings) {
        let l = &self.line;
        let mut target = [0.0f64; 3];
        let mut angle = 0.0;
        let mut by_refpoint = false;
        let mut set = |id: u32, slot: &mut f64| {
            if let Some(d) = mods.get_double(id) {
                *slot = d;
                by_refpoint = true;
            }
        };
        set(m::REFPOINT_X, &mut target[0]);
        set(m::REFPOINT_Y, &mut target[1]);
        set(m::REFPOINT_Z, &mut target[2]);
        set(m::REFPOINT_PHI, &mut angle);
        let mut u = l.u_first;
        let mut v = 0.0;
        set(m::REFPOINT_U, &mut u);
        set(m::REFPOINT_V, &mut v);
        // A fraction (plus its offset) overrides the absolute position.
        if let Some(f) = mods.get_double(m::REFPOINT_U_FRAC) {
            u = l.u_first + f * (l.u_last - l.u_first) + mods.get_double(m::REFPOINT_U_OFFSET).unwrap_or(0.0);
            by_refpoint = true;
        }
        if let Some(f) = mods.get_double(m::REFPOINT_V_FRAC) {
            let g = &self.grid;
            v = g.v_first + f * (g.v_last - g.v_first) + mods.get_double(m::REFPOINT_V_OFFSET).unwrap_or(0.0);
            by_refpoint = true;
        }

        let (from, center, angle) = if by_refpoint {
            let options = EvalOptions::from(&self.options);
            let (x, y) = eval::uv_to_xy(self, &options, u, v);
            let z = eval::uv_to_z(self, &options, u, v).unwrap_or(0.0);
            let (phi, _) = eval::uv_to_pk(self, &options, u, v);
            ([x, y, z], (x, y), angle - phi)
        } else {
            let from_xy = (l.x_first, l.y_first);
            let center = (
                mods.get_double(m::REFLINE_ROTCENTER_X).unwrap_or(from_xy.0),
                mods.get_double(m::REFLINE_ROTCENTER_Y).unwrap_or(from_xy.1),
            );
            let mut any = false;
            let mut take = |id: u32| {
                mods.get_double(id).map_or(0.0, |d| {
                    any = true;
                    d
                })
            };
            let offset = [take(m::REFLINE_OFFSET_X), take(m::REFLINE_OFFSET_Y), take(m::REFLINE_OFFSET_Z)];
            let rot = take(m::REFLINE_OFFSET_PHI);
            if !any {
                return;
            }
            let z = self.z_without_options(0.0, 0.0);
            target = [offset[0] + from_xy.0, offset[1] + from_xy.1, offset[2] + z];
            ([from_xy.0, from_xy.1, z], center, rot)
        };

        self.note(crate::model::report::Event::Relocated {
            center,
            angle,
            shift: (target[0] - from[0], target[1] - from[1], target[2] - from[2]),
        });
        let l = &mut self.line;
        if let Some(phi) = &mut l.phi {
            phi.iter_mut().for_each(|p| *p += angle);
        }
        l.phi_first += angle;
        l.phi_last += angle;
        l.update_trig();
        let (dx, dy, dz) = (target[0] - from[0], target[1] - from[1], target[2] - from[2]);
        let mv = |x: &mut f64, y: &mut f64| {
            rotate(x, y, center, angle);
            *x += dx;
            *y += dy;
        };
        let first = (l.x_first, l.y_first);
        mv(&mut l.x_first, &mut l.y_first);
        self.origin = self.origin.after_move(first, (l.x_first, l.y_first), angle, dz);
        mv(&mut l.x_last, &mut l.y_last);
        for (x, y) in l.x.iter_mut().zip(l.y.iter_mut()) {
            mv(x, y);
        }
        if let Some(z) = &mut l.z {
            z.iter_mut().for_each(|z| *z += dz);
            l.z_first += dz;
            l.z_last += dz;
        } else if l.defined.z_start {
            l.z_first += dz;
            l.z_last += dz;
        } else {
            self.grid.mean += dz;
        }
        self.line.update_caches();
        self.index = std::mem::take(&mut self.index).rebuilt(&self.line);
    }
}

fn scale_values(values: &mut Option<Vec<f64>>, factor: f64) {
    if let Some(v) = values {
        v.iter_mut().for_each(|x| *x *= factor);
    }
}

/// Rotates a point around a center by an angle (through its polar coordinates).
fn rotate(x: &mut f64, y: &mut f64, center: (f64, f64), angle: f64) {
    let dx = *x - center.0;
    let dy = *y - center.1;
    let a = math::atan2(dy, dx) + angle;
    let r = (dx * dx + dy * dy).sqrt();
    *x = center.0 + r * math::cos(a);
    *y = center.1 + r * math::sin(a);
}
