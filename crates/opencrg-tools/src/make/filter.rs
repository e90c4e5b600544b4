//! Filters of the elevation grid: Gaussian smoothing, median, limits, filling NaN.
//! They change the grid values (the elevations relative to the reference line); the
//! reference line, its slope and its banking stay as they are.

use opencrg_core::budget::{filled, Budget};
use opencrg_core::draft::Draft;
use opencrg_core::units::Num;
use opencrg_core::Road;
use opencrg_core::{Error, Result};

/// What to do to the grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Filter {
    /// A Gaussian of this standard deviation (metres, the same along u and across v);
    /// NaN nodes stay NaN and do not count.
    Gauss(f64),
    /// The median of the `n` x `n` nodes around each node (`n` odd), NaN not counted.
    Median(usize),
    /// Values below the first bound raised to it, above the second lowered to it.
    Limit(f64, f64),
    /// NaN nodes filled: linearly between the nearest values of their cross section, the
    /// nearest value beyond the last one; empty cross sections from their neighbours.
    FillNan,
}

impl std::fmt::Display for Filter {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Filter::Gauss(s) => write!(f, "Gaussian of sigma {} m", Num(*s)),
            Filter::Median(n) => write!(f, "median of {n} x {n} nodes"),
            Filter::Limit(a, b) => write!(f, "values limited to {a} to {b} m"),
            Filter::FillNan => write!(f, "NaN filled"),
        }
    }
}

/// `road` with `filter` applied to its grid. Refused: a parameter out of range, a window
/// wider than the road in both directions (it would read the whole grid for every node),
/// the filter's copies of the grid beyond `budget`.
pub fn filter(road: &Road, filter: Filter, budget: &Budget) -> Result<Road> {
    let (nu, nv) = (road.grid().nu, road.grid().nv);
    let (length, width) = (road.u_range().1 - road.u_range().0, road.v_range().1 - road.v_range().0);
    let request = format!("a {filter}");
    // The road's grid as a draft, the filter's result, the road made from it.
    budget.admit(&request, (nu * nv) as f64, "grid values", 12.0)?;
    match filter {
        Filter::Gauss(sigma) => {
            if !(sigma > 0.0 && sigma.is_finite()) {
                return Err(Error::out_of_range(format!("Gaussian sigma {} m must be a positive number", Num(sigma))));
            }
            if 3.0 * sigma > length.max(width) {
                return Err(Error::out_of_range(format!(
                    "a Gaussian of sigma {} m reaches {} m each way, beyond the road ({length} m long, {width} m wide)",
                    Num(sigma),
                    Num(3.0 * sigma)
                )));
            }
        }
        Filter::Median(n) => {
            if n == 0 || n.is_multiple_of(2) {
                return Err(Error::out_of_range(format!("median window {n} must be an odd number of nodes")));
            }
            if n / 2 >= nu.max(nv) {
                return Err(Error::out_of_range(format!(
                    "a median of {n} x {n} nodes is wider than the road ({nu} x {nv} nodes) both ways"
                )));
            }
        }
        _ => {}
    }
    let mut d = Draft::of(road);
    match filter {
        Filter::Gauss(sigma) => gauss(&mut d.z, nu, &d.v, d.u_inc, sigma)?,
        Filter::Median(n) => d.z = median(&d.z, nu, nv, n / 2)?,
        Filter::Limit(lo, hi) => {
            if !(lo <= hi) {
                return Err(Error::out_of_range(format!(
                    "limits {}:{} must be two numbers, the lower first",
                    Num(lo),
                    Num(hi)
                )));
            }
            for z in d.z.iter_mut().filter(|z| !z.is_nan()) {
                *z = z.clamp(lo as f32, hi as f32);
            }
        }
        Filter::FillNan => {
            if d.z.iter().all(|z| z.is_nan()) {
                return Err(Error::out_of_range("the grid holds no value to fill NaN from"));
            }
            fill_nan(&mut d.z, nu, &d.v);
        }
    }
    d.into_road(&format!("filtered by opencrg {}: {filter}", env!("CARGO_PKG_VERSION")))
}

/// Normalised Gaussian weights at offsets -r..=r of spacing `step`, r at most `reach`.
fn kernel(sigma: f64, step: f64, reach: usize) -> Vec<f64> {
    let r = ((3.0 * sigma / step).ceil() as usize).min(reach);
    (0..=2 * r).map(|k| (-((k as f64 - r as f64) * step).powi(2) / (2.0 * sigma * sigma)).exp()).collect()
}

/// Weighted sum over the values a kernel covers, NaN left out and the weights that
/// remain normalised; NaN where the centre is NaN.
fn smooth_line(values: &[f32], weight: impl Fn(usize, usize) -> Option<f64>, reach: usize, out: &mut [f32]) {
    let n = values.len();
    for (i, o) in out.iter_mut().enumerate() {
        if values[i].is_nan() {
            *o = f32::NAN;
            continue;
        }
        let (mut sum, mut total) = (0.0, 0.0);
        let from = i.saturating_sub(reach);
        for (j, &z) in values.iter().enumerate().take((i + reach + 1).min(n)).skip(from) {
            if let (false, Some(w)) = (z.is_nan(), weight(i, j)) {
                sum += w * f64::from(z);
                total += w;
            }
        }
        *o = (sum / total) as f32;
    }
}

fn gauss(z: &mut [f32], nu: usize, v: &[f64], u_inc: f64, sigma: f64) -> Result<()> {
    let k = kernel(sigma, u_inc, nu);
    let r = k.len() / 2;
    let mut out = filled(nu, 0.0f32, "a Gaussian's long section")?;
    for long in z.chunks_exact_mut(nu) {
        smooth_line(long, |i, j| Some(k[j + r - i]), r, &mut out);
        long.copy_from_slice(&out);
    }
    // Across: by distance in v, so that uneven long sections get their due weights.
    let nv = v.len();
    let dv_min = v.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
    let reach = ((3.0 * sigma / dv_min).ceil() as usize).min(nv);
    let weight = |i: usize, j: usize| {
        let d = v[j] - v[i];
        (d.abs() <= 3.0 * sigma).then(|| (-d * d / (2.0 * sigma * sigma)).exp())
    };
    let (mut row, mut smoothed) = (vec![0.0f32; nv], vec![0.0f32; nv]);
    for iu in 0..nu {
        for (iv, r) in row.iter_mut().enumerate() {
            *r = z[iv * nu + iu];
        }
        smooth_line(&row, weight, reach, &mut smoothed);
        for (iv, s) in smoothed.iter().enumerate() {
            z[iv * nu + iu] = *s;
        }
    }
    Ok(())
}

fn median(z: &[f32], nu: usize, nv: usize, r: usize) -> Result<Vec<f32>> {
    let mut out = filled(z.len(), f32::NAN, "the median's grid")?;
    let mut window = Vec::with_capacity((2 * r + 1).min(nu) * (2 * r + 1).min(nv));
    for iv in 0..nv {
        for iu in 0..nu {
            if z[iv * nu + iu].is_nan() {
                continue;
            }
            window.clear();
            for jv in iv.saturating_sub(r)..(iv + r + 1).min(nv) {
                let long = &z[jv * nu..(jv + 1) * nu];
                window.extend(long[iu.saturating_sub(r)..(iu + r + 1).min(nu)].iter().filter(|z| !z.is_nan()));
            }
            let mid = window.len() / 2;
            let (_, m, _) = window.select_nth_unstable_by(mid, f32::total_cmp);
            out[iv * nu + iu] = *m;
        }
    }
    Ok(out)
}

/// NaN nodes filled as [`Filter::FillNan`] says.
pub(crate) fn fill_nan(z: &mut [f32], nu: usize, v: &[f64]) {
    let nv = v.len();
    let mut row = vec![0.0f32; nv];
    let mut empty = vec![false; nu];
    for (iu, is_empty) in empty.iter_mut().enumerate() {
        for (iv, r) in row.iter_mut().enumerate() {
            *r = z[iv * nu + iu];
        }
        let known: Vec<usize> = (0..nv).filter(|&i| !row[i].is_nan()).collect();
        if known.is_empty() {
            *is_empty = true;
            continue;
        }
        for iv in 0..nv {
            if !row[iv].is_nan() {
                continue;
            }
            let after = known.partition_point(|&k| k < iv);
            row[iv] = match (after.checked_sub(1).map(|p| known[p]), known.get(after)) {
                (Some(a), Some(&b)) => {
                    let w = (v[iv] - v[a]) / (v[b] - v[a]);
                    (f64::from(row[a]) * (1.0 - w) + f64::from(row[b]) * w) as f32
                }
                (Some(a), None) => row[a],
                (None, Some(&b)) => row[b],
                (None, None) => f32::NAN,
            };
        }
        for (iv, r) in row.iter().enumerate() {
            z[iv * nu + iu] = *r;
        }
    }
    // Empty cross sections: between the nearest full ones along u.
    let full: Vec<usize> = (0..nu).filter(|&i| !empty[i]).collect();
    for iu in (0..nu).filter(|&i| empty[i]) {
        let after = full.partition_point(|&k| k < iu);
        let (a, b) = (after.checked_sub(1).map(|p| full[p]), full.get(after).copied());
        for long in z.chunks_exact_mut(nu) {
            long[iu] = match (a, b) {
                (Some(a), Some(b)) => {
                    let w = (iu - a) as f64 / (b - a) as f64;
                    (f64::from(long[a]) * (1.0 - w) + f64::from(long[b]) * w) as f32
                }
                (Some(a), None) => long[a],
                (None, Some(b)) => long[b],
                (None, None) => f32::NAN,
            };
        }
    }
}
