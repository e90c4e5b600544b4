//! The displacement power spectral density of a longitudinal profile and its ISO 8608
//! road class.
//!
//! The density is estimated by Welch's method: segments of a power of two samples,
//! overlapping by half, each with its linear trend removed and a Hann window applied,
//! their one-sided periodograms averaged (`realfft` for the transforms). It is then
//! averaged in third-octave bands around n0 · 2^(j/3) and fitted by least squares in
//! log-log form with ISO 8608's `Gd(n) = Gd(n0) · (n / n0)^-w`, n0 = 0.1 cycles/m: once
//! with the standard's waviness w = 2 (which gives the class), once with w fitted too.

use opencrg_core::{Error, Result};
use realfft::RealFftPlanner;

/// ISO 8608's reference spatial frequency, in cycles/m.
pub const N0: f64 = 0.1;
/// The band of spatial frequencies ISO 8608 classifies, in cycles/m.
pub const BAND: (f64, f64) = (0.011, 2.83);
/// The upper limits of Gd(n0) of classes A to G, in m³ (H lies above G's).
pub const CLASS_LIMITS: [f64; 7] = [32e-6, 128e-6, 512e-6, 2048e-6, 8192e-6, 32768e-6, 131072e-6];
/// The class names, A to H.
pub const CLASSES: [char; 8] = ['A', 'B', 'C', 'D', 'E', 'F', 'G', 'H'];

/// The ISO 8608 class of a road with this Gd(n0) (m³).
pub fn class_of(gd_n0: f64) -> char {
    CLASSES[CLASS_LIMITS.iter().take_while(|&&limit| gd_n0 >= limit).count()]
}

/// A profile's density and its fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Spectrum {
    /// Samples per segment.
    pub segment_samples: usize,
    /// Segments averaged.
    pub segments: usize,
    /// Third-octave band centres (cycles/m) and the mean density in each (m³), for the
    /// bands inside the fitted range that hold at least one frequency.
    pub bands: Vec<(f64, f64)>,
    /// The spatial frequencies fitted over, in cycles/m.
    pub fitted: (f64, f64),
    /// Gd(n0) of the fit with w = 2, in m³.
    pub gd_n0: f64,
    /// Gd(n0) of the fit with w fitted too, in m³.
    pub gd_n0_free: f64,
    /// The fitted waviness.
    pub w: f64,
    /// The ISO 8608 class of `gd_n0`.
    pub class: char,
}

/// The samples of one segment: the smallest power of two covering the lowest frequency
/// ISO 8608 classifies (1 / 0.011 m), halved while the profile holds fewer than two.
fn segment_samples(len: usize, dx: f64) -> usize {
    let mut n = ((1.0 / (BAND.0 * dx)).ceil() as usize).next_power_of_two().max(16);
    while n > 16 && 2 * n > len {
        n /= 2;
    }
    n
}

/// The one-sided density by Welch's method: frequencies (cycles/m) and densities (m³)
/// from the second bin up to below the Nyquist frequency, and the segment count.
fn welch(profile: &[f64], dx: f64, n: usize) -> (Vec<(f64, f64)>, usize) {
    let fft = RealFftPlanner::<f64>::new().plan_fft_forward(n);
    let window: Vec<f64> = (0..n).map(|j| 0.5 - 0.5 * (std::f64::consts::TAU * j as f64 / n as f64).cos()).collect();
    let power: f64 = window.iter().map(|w| w * w).sum();
    let mut input = fft.make_input_vec();
    let mut output = fft.make_output_vec();
    let mut sum = vec![0.0; n / 2 + 1];
    let mut segments = 0;
    let mut start = 0;
    while start + n <= profile.len() {
        let seg = &profile[start..start + n];
        // The least-squares line through the segment, removed.
        let mid = (n as f64 - 1.0) / 2.0;
        let mean = seg.iter().sum::<f64>() / n as f64;
        let (sxy, sxx) = seg.iter().enumerate().fold((0.0, 0.0), |(sxy, sxx), (j, z)| {
            let t = j as f64 - mid;
            (sxy + t * (z - mean), sxx + t * t)
        });
        let slope = sxy / sxx;
        for (j, (slot, z)) in input.iter_mut().zip(seg).enumerate() {
            *slot = (z - mean - slope * (j as f64 - mid)) * window[j];
        }
        // The lengths match the plan: the transform cannot fail.
        if fft.process(&mut input, &mut output).is_ok() {
            for (s, x) in sum.iter_mut().zip(&output) {
                *s += x.norm_sqr();
            }
            segments += 1;
        }
        start += n / 2;
    }
    let scale = 2.0 * dx / (power * segments.max(1) as f64);
    let density = (2..n / 2).map(|m| (m as f64 / (n as f64 * dx), sum[m] * scale)).collect();
    (density, segments)
}

/// The density of `profile` (elevations in m, `dx` m apart, all finite) and its ISO 8608
/// fit. Refused: fewer than 32 samples, or no third-octave band inside the range.
pub fn spectrum(profile: &[f64], dx: f64) -> Result<Spectrum> {
    if !(dx > 0.0 && dx.is_finite()) {
        return Err(Error::out_of_range(format!("PSD: sample interval {dx} m; it must be positive")));
    }
    if profile.len() < 32 {
        return Err(Error::out_of_range(format!(
            "PSD: a profile of {} samples is too short (at least 32 are needed)",
            profile.len()
        )));
    }
    if let Some(i) = profile.iter().position(|z| !z.is_finite()) {
        return Err(Error::out_of_range(format!("PSD: sample {i} of the profile is not a number")));
    }
    let n = segment_samples(profile.len(), dx);
    let (density, segments) = welch(profile, dx, n);
    let low = BAND.0.max(2.0 / (n as f64 * dx));
    // Below 80 % of the Nyquist frequency, where the window's leakage and aliasing stay small.
    let high = BAND.1.min(0.4 / dx);
    let mut bands = Vec::new();
    for j in -60i32..=60 {
        let centre = N0 * 2f64.powf(j as f64 / 3.0);
        let (lo, hi) = (centre * 2f64.powf(-1.0 / 6.0), centre * 2f64.powf(1.0 / 6.0));
        if lo < low || hi > high {
            continue;
        }
        let inside: Vec<f64> = density.iter().filter(|(f, _)| *f >= lo && *f < hi).map(|&(_, g)| g).collect();
        if !inside.is_empty() {
            bands.push((centre, inside.iter().sum::<f64>() / inside.len() as f64));
        }
    }
    let usable: Vec<(f64, f64)> =
        bands.iter().filter(|(_, g)| *g > 0.0).map(|&(f, g)| ((f / N0).log10(), g.log10())).collect();
    if usable.len() < 2 {
        return Err(Error::out_of_range(format!(
            "PSD: between {low:.4} and {high:.4} cycles/m the profile ({} samples, {dx} m apart) leaves fewer than two third-octave bands to fit",
            profile.len()
        )));
    }
    let count = usable.len() as f64;
    let gd_n0 = 10f64.powf(usable.iter().map(|(x, y)| y + 2.0 * x).sum::<f64>() / count);
    let (mx, my) = (usable.iter().map(|p| p.0).sum::<f64>() / count, usable.iter().map(|p| p.1).sum::<f64>() / count);
    let sxy: f64 = usable.iter().map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = usable.iter().map(|(x, _)| (x - mx) * (x - mx)).sum();
    let w = -sxy / sxx;
    let gd_n0_free = 10f64.powf(my + w * mx);
    Ok(Spectrum {
        segment_samples: n,
        segments,
        bands,
        fitted: (low, high),
        gd_n0,
        gd_n0_free,
        w,
        class: class_of(gd_n0),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn classes_follow_the_limits() {
        assert_eq!(class_of(16e-6), 'A');
        assert_eq!(class_of(32e-6), 'B');
        assert_eq!(class_of(256e-6), 'C');
        assert_eq!(class_of(1024e-6), 'D');
        assert_eq!(class_of(4096e-6), 'E');
        assert_eq!(class_of(262144e-6), 'H');
    }

    /// A sine's power lands in the band holding its frequency, with its variance.
    #[test]
    fn a_sine_has_its_variance_at_its_frequency() {
        let (dx, a, f) = (0.1, 0.01, 0.5);
        let z: Vec<f64> = (0..20_000).map(|i| a * (std::f64::consts::TAU * f * i as f64 * dx).sin()).collect();
        let n = segment_samples(z.len(), dx);
        let (density, _) = welch(&z, dx, n);
        let df = 1.0 / (n as f64 * dx);
        let variance: f64 = density.iter().map(|(_, g)| g * df).sum();
        assert!((variance / (a * a / 2.0) - 1.0).abs() < 0.02, "{variance}");
        let peak = density.iter().cloned().fold((0.0, 0.0), |m, p| if p.1 > m.1 { p } else { m });
        assert!((peak.0 - f).abs() <= df, "{peak:?}");
    }
}
