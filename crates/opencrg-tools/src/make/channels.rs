//! Moving slope and banking between the reference line and the grid.
//!
//! A road's surface is its grid value plus the reference line's elevation (from the
//! slope) plus banking times v. Applying a channel folds it into the grid and drops it
//! from the line; extracting finds it in the grid (per cross section, the straight line
//! that best fits the grid values across v: its value at v = 0 for the slope, its
//! gradient for the banking) and moves it to the line. Both keep the surface; removing
//! drops the channel and flattens the surface by it.

use opencrg_core::draft::{slopes_for, Draft};
use opencrg_core::Road;
use opencrg_core::{Error, Result};

/// Which reference line channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineChannel {
    /// The slope (the reference line's elevation along u).
    Slope,
    /// The banking (elevation across v per metre of v).
    Banking,
}

/// What to do with it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChannelAction {
    /// Find it in the grid and move it to the reference line (the surface is kept).
    Extract,
    /// Fold it into the grid and drop it from the reference line (the surface is kept).
    Apply,
    /// Drop it (the surface loses it).
    Remove,
}

/// `road` with its slope or banking extracted, applied or removed.
pub fn change_channel(road: &Road, channel: LineChannel, action: ChannelAction) -> Result<Road> {
    let mut d = Draft::of(road);
    let nu = d.nu();
    let name = match channel {
        LineChannel::Slope => "slope",
        LineChannel::Banking => "banking",
    };
    let has = match channel {
        LineChannel::Slope => d.slope.is_some() || d.z_start != 0.0,
        LineChannel::Banking => d.bank.is_some(),
    };
    if action != ChannelAction::Extract && !has {
        return Err(Error::out_of_range(format!("the road has no {name} to {}", verb(action))));
    }
    match (channel, action) {
        (LineChannel::Slope, ChannelAction::Apply) => {
            let line = d.line_z();
            for long in d.z.chunks_exact_mut(nu) {
                for (z, l) in long.iter_mut().zip(&line) {
                    *z = (f64::from(*z) + l) as f32;
                }
            }
            d.slope = None;
            d.z_start = 0.0;
        }
        (LineChannel::Slope, ChannelAction::Remove) => {
            d.slope = None;
            d.z_start = 0.0;
        }
        (LineChannel::Banking, ChannelAction::Apply) => fold_banking(&mut d),
        (LineChannel::Banking, ChannelAction::Remove) => d.bank = None,
        (_, ChannelAction::Extract) => {
            if channel == LineChannel::Banking {
                // The banking found acts across all the long sections.
                fold_banking(&mut d);
                d.bank_v = (d.v[0], d.v[d.nv() - 1]);
            }
            let fits: Vec<(f64, f64)> = (0..nu).map(|iu| fit_across(&d.z, nu, &d.v, iu)).collect();
            if fits.iter().all(|f| f.0.is_nan()) {
                return Err(Error::out_of_range(format!("the grid holds no values to extract a {name} from")));
            }
            let fits = fill_gaps(fits);
            let mut line = d.line_z();
            let mut bank: Vec<f64> = (0..nu).map(|i| d.bank_at(i)).collect();
            for (iv, long) in d.z.chunks_exact_mut(nu).enumerate() {
                for (iu, z) in long.iter_mut().enumerate() {
                    let moved = match channel {
                        LineChannel::Slope => fits[iu].0,
                        LineChannel::Banking => fits[iu].1 * d.v[iv],
                    };
                    *z = (f64::from(*z) - moved) as f32;
                }
            }
            match channel {
                LineChannel::Slope => {
                    line.iter_mut().zip(&fits).for_each(|(l, f)| *l += f.0);
                    d.slope = Some(slopes_for(&line, d.u_inc));
                    d.z_start = line[0];
                }
                LineChannel::Banking => {
                    bank.iter_mut().zip(&fits).for_each(|(b, f)| *b += f.1);
                    d.bank = Some(bank);
                }
            }
        }
    }
    d.into_road(&format!("{name} {} by opencrg {}", past(action), env!("CARGO_PKG_VERSION")))
}

/// The banking folded into the grid and dropped from the line.
fn fold_banking(d: &mut Draft) {
    let nu = d.nu();
    let mut z = std::mem::take(&mut d.z);
    for (iv, long) in z.chunks_exact_mut(nu).enumerate() {
        for (iu, z) in long.iter_mut().enumerate() {
            *z = (f64::from(*z) + d.bank_term(iu, d.v[iv])) as f32;
        }
    }
    d.z = z;
    d.bank = None;
}

fn verb(a: ChannelAction) -> &'static str {
    match a {
        ChannelAction::Extract => "extract",
        ChannelAction::Apply => "apply",
        ChannelAction::Remove => "remove",
    }
}

fn past(a: ChannelAction) -> &'static str {
    match a {
        ChannelAction::Extract => "extracted from the grid",
        ChannelAction::Apply => "applied to the grid",
        ChannelAction::Remove => "removed",
    }
}

/// The least-squares line z = a + b v through the cross section's values (NaN left out):
/// (a, b), NaN when fewer than two values.
fn fit_across(z: &[f32], nu: usize, v: &[f64], iu: usize) -> (f64, f64) {
    let (mut n, mut sv, mut sz, mut svv, mut svz) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (iv, &vv) in v.iter().enumerate() {
        let zz = f64::from(z[iv * nu + iu]);
        if zz.is_nan() {
            continue;
        }
        n += 1.0;
        sv += vv;
        sz += zz;
        svv += vv * vv;
        svz += vv * zz;
    }
    let det = n * svv - sv * sv;
    if n < 2.0 || det.abs() < 1e-12 {
        return (f64::NAN, f64::NAN);
    }
    let b = (n * svz - sv * sz) / det;
    ((sz - b * sv) / n, b)
}

/// Cross sections without a fit take the nearest fitted one's.
fn fill_gaps(mut fits: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    let mut last = fits.iter().copied().find(|f| !f.0.is_nan()).unwrap_or((0.0, 0.0));
    for f in fits.iter_mut() {
        if f.0.is_nan() {
            *f = last;
        } else {
            last = *f;
        }
    }
    fits
}
