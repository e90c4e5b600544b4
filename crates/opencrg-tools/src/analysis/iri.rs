//! The International Roughness Index (IRI, ASTM E1926) of a longitudinal profile.
//!
//! The index is the suspension travel a standard quarter car (the "golden car" of
//! World Bank Technical Paper 46, Sayers et al.) accumulates at 80 km/h, divided by the
//! distance driven: the mean of |sprung velocity - unsprung velocity| / speed, in m/km.
//! Written from the published description:
//! - the car, per unit sprung mass: tyre spring `k1` = 653 s⁻², suspension spring
//!   `k2` = 63.3 s⁻², damper `c` = 6 s⁻¹, unsprung to sprung mass ratio `mu` = 0.15;
//!   states: sprung and unsprung displacement and velocity;
//! - the profile is smoothed by a 250 mm moving average, which the method applies as the
//!   slope over a base of `k = max(1, round(0.25 m / dx))` samples; the car is driven by
//!   that slope, so its states are the displacements' rates divided by the speed;
//! - the state transition over one sample interval, `exp(A·dt)` with `dt = dx / v` and the
//!   input held over the interval, is computed here for the profile's own interval (the
//!   exponential of the augmented system matrix, by scaling and squaring);
//! - the states start at rest on the slope of the first 11 m (both displacement rates
//!   equal to it, both accelerations 0).

use opencrg_core::units::Num;
use opencrg_core::{Error, Result};

/// The golden car's tyre spring per unit sprung mass, in s⁻².
pub const K1: f64 = 653.0;
/// Its suspension spring per unit sprung mass, in s⁻².
pub const K2: f64 = 63.3;
/// Its damper per unit sprung mass, in s⁻¹.
pub const C: f64 = 6.0;
/// Its unsprung mass per unit sprung mass.
pub const MU: f64 = 0.15;
/// Its speed, in m/s (80 km/h).
pub const SPEED: f64 = 80.0 / 3.6;
/// The base length of the moving average, in m.
pub const AVERAGE_BASE: f64 = 0.25;
/// The length over which the initial states are taken, in m.
pub const INITIAL_LENGTH: f64 = 11.0;

/// The quarter car advanced by one sample interval: `x ← st·x + pr·slope`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct QuarterCar {
    st: [[f64; 4]; 4],
    pr: [f64; 4],
}

impl QuarterCar {
    /// The golden car stepping `dx` metres at 80 km/h.
    pub(crate) fn golden(dx: f64) -> Self {
        // The system matrix and the input column, states (zs, zs', zu, zu'), augmented
        // with a zero row so that one exponential gives the transition and the response
        // to an input held over the interval.
        let a = [
            [0.0, 1.0, 0.0, 0.0, 0.0],
            [-K2, -C, K2, C, 0.0],
            [0.0, 0.0, 0.0, 1.0, 0.0],
            [K2 / MU, C / MU, -(K1 + K2) / MU, -C / MU, K1 / MU],
            [0.0; 5],
        ];
        let dt = dx / SPEED;
        let e = exp5(a.map(|row| row.map(|x| x * dt)));
        let mut st = [[0.0; 4]; 4];
        let mut pr = [0.0; 4];
        for i in 0..4 {
            st[i].copy_from_slice(&e[i][..4]);
            pr[i] = e[i][4];
        }
        QuarterCar { st, pr }
    }

    /// Advances `x` by one interval with the input `slope`.
    #[inline]
    pub(crate) fn step(&self, x: &mut [f64; 4], slope: f64) {
        let old = *x;
        for (xi, (row, pr)) in x.iter_mut().zip(self.st.iter().zip(self.pr)) {
            *xi = row[0] * old[0] + row[1] * old[1] + row[2] * old[2] + row[3] * old[3] + pr * slope;
        }
    }
}

/// The exponential of a 5×5 matrix: its Taylor series on the matrix scaled below norm
/// 1/2, squared back.
fn exp5(m: [[f64; 5]; 5]) -> [[f64; 5]; 5] {
    let norm = m.iter().map(|row| row.iter().map(|x| x.abs()).sum::<f64>()).fold(0.0, f64::max);
    let squarings = if norm > 0.5 { (norm / 0.5).log2().ceil() as i32 } else { 0 };
    let scale = 0.5f64.powi(squarings);
    let m = m.map(|row| row.map(|x| x * scale));
    let mut sum = identity5();
    let mut term = identity5();
    for k in 1..=20 {
        term = mul5(&term, &m).map(|row| row.map(|x| x / k as f64));
        for (s, t) in sum.iter_mut().zip(&term) {
            for (s, t) in s.iter_mut().zip(t) {
                *s += t;
            }
        }
    }
    for _ in 0..squarings {
        sum = mul5(&sum, &sum);
    }
    sum
}

fn identity5() -> [[f64; 5]; 5] {
    let mut m = [[0.0; 5]; 5];
    for (i, row) in m.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    m
}

fn mul5(a: &[[f64; 5]; 5], b: &[[f64; 5]; 5]) -> [[f64; 5]; 5] {
    let mut p = [[0.0; 5]; 5];
    for (i, row) in p.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = (0..5).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    p
}

/// The rectified slope of each step of the car along a profile: what the IRI averages.
#[derive(Debug, Clone, PartialEq)]
pub struct Response {
    /// Sample interval of the profile, in m.
    pub dx: f64,
    /// Samples of the moving average's base.
    pub base: usize,
    /// |sprung - unsprung displacement rate| / speed after each step (m/m); step `i` is
    /// driven by the slope between samples `i` and `i + base`.
    pub rectified: Vec<f64>,
}

impl Response {
    /// Where step `i` lies along the profile, in m from its first sample: the middle of
    /// the moving average's base.
    pub fn position(&self, i: usize) -> f64 {
        (i as f64 + 0.5 * self.base as f64) * self.dx
    }

    /// The IRI in m/km of the steps whose positions lie in `start..end` (m from the first
    /// sample); `None` without any.
    pub fn iri_between(&self, start: f64, end: f64) -> Option<f64> {
        let first = ((start / self.dx - 0.5 * self.base as f64).ceil().max(0.0)) as usize;
        let (mut sum, mut n) = (0.0, 0usize);
        for i in first..self.rectified.len() {
            let x = self.position(i);
            if x >= end {
                break;
            }
            if x >= start {
                sum += self.rectified[i];
                n += 1;
            }
        }
        (n > 0).then(|| 1000.0 * sum / n as f64)
    }

    /// The IRI in m/km of the whole profile.
    pub fn iri(&self) -> f64 {
        1000.0 * self.rectified.iter().sum::<f64>() / self.rectified.len() as f64
    }
}

/// The samples of the moving average's base: 0.25 m / `dx` rounded, halves up (the
/// quotient taken with a margin, so that 0.25 / 0.1, 2.4999999999999996 in floating
/// point, counts as the 2.5 it stands for), at least 1.
pub fn base_samples(dx: f64) -> usize {
    ((AVERAGE_BASE / dx * (1.0 + 1e-12)).round() as usize).max(1)
}

/// The IRI in m/km of each `segment` metres of a track `length` m long (the last segment
/// ends at the track's end), over the steps of `runs`: responses with where their first
/// sample lies (m from the track's start). A step counts in the segment its position
/// (see [`Response::position`]) falls in; `None` for a segment without steps. Refused: a
/// segment that is not a positive number or shorter than the runs' sample interval.
pub fn segment_iris(runs: &[(f64, &Response)], length: f64, segment: f64) -> Result<Vec<Option<f64>>> {
    let dx = runs.iter().map(|(_, r)| r.dx).fold(0.0, f64::max);
    if !(segment > 0.0 && segment.is_finite()) || segment < dx {
        return Err(Error::out_of_range(format!(
            "segment length {} m; it must be a positive number of at least the sample interval ({dx} m)",
            Num(segment)
        )));
    }
    let count = (length / segment - 1e-9).ceil().max(1.0) as usize;
    let mut sums = vec![(0.0, 0usize); count];
    for (start, response) in runs {
        for (i, rs) in response.rectified.iter().enumerate() {
            let k = (((start + response.position(i)) / segment).floor().max(0.0) as usize).min(count - 1);
            sums[k].0 += rs;
            sums[k].1 += 1;
        }
    }
    Ok(sums.iter().map(|&(sum, n)| (n > 0).then(|| 1000.0 * sum / n as f64)).collect())
}

/// Drives the golden car along `profile` (elevations in m, `dx` m apart, all finite).
/// Refused: a profile too short for the initial 11 m and one step, a `dx` not positive.
pub fn response(profile: &[f64], dx: f64) -> Result<Response> {
    if !(dx > 0.0 && dx.is_finite()) {
        return Err(Error::out_of_range(format!("IRI: sample interval {dx} m; it must be positive")));
    }
    let base = base_samples(dx);
    let start = (INITIAL_LENGTH / dx).round() as usize;
    let needed = start.max(base) + 1;
    if profile.len() < needed {
        return Err(Error::out_of_range(format!(
            "IRI: a profile of {:.3} m ({} samples {dx} m apart) is too short: the initial states need {INITIAL_LENGTH} m ({needed} samples)",
            profile.len().saturating_sub(1) as f64 * dx,
            profile.len()
        )));
    }
    if let Some(i) = profile.iter().position(|z| !z.is_finite()) {
        return Err(Error::out_of_range(format!("IRI: sample {i} of the profile is not a number")));
    }
    let car = QuarterCar::golden(dx);
    let initial = (profile[start] - profile[0]) / (start as f64 * dx);
    let mut x = [initial, 0.0, initial, 0.0];
    let spread = base as f64 * dx;
    let rectified = profile
        .windows(base + 1)
        .map(|w| {
            car.step(&mut x, (w[base] - w[0]) / spread);
            (x[0] - x[2]).abs()
        })
        .collect();
    Ok(Response { dx, base, rectified })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The transition over two intervals is that over one, applied twice.
    #[test]
    fn transition_composes() {
        let (one, two) = (QuarterCar::golden(0.05), QuarterCar::golden(0.1));
        let (mut a, mut b) = ([0.01, -0.3, 0.02, 0.5], [0.01, -0.3, 0.02, 0.5]);
        one.step(&mut a, 0.004);
        one.step(&mut a, 0.004);
        two.step(&mut b, 0.004);
        for (p, q) in a.iter().zip(b) {
            assert!((p - q).abs() < 1e-12, "{a:?} {b:?}");
        }
    }

    /// At rest on a slope held constant, the car stays at rest on it.
    #[test]
    fn a_constant_slope_is_a_fixed_point() {
        let car = QuarterCar::golden(0.25);
        let mut x = [0.03, 0.0, 0.03, 0.0];
        car.step(&mut x, 0.03);
        for (p, q) in x.iter().zip([0.03, 0.0, 0.03, 0.0]) {
            assert!((p - q).abs() < 1e-12, "{x:?}");
        }
    }
}
