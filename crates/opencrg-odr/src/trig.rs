//! Sine and cosine without the maths library where the angle is small: the turns of a
//! reference line between two nearby stations and most superelevations are, and the
//! Taylor series to the eleventh power is exact to rounding there (within one unit of
//! the last place of the library's answer up to [`SMALL`], measured by the tests); the
//! turns within [`TINY`] need its first terms only.

use opencrg_core::math;

/// The largest angle (rad) [`small_sin_cos`] takes.
pub(crate) const SMALL: f64 = 0.1;

/// (sin a, cos a) for |a| up to [`SMALL`], by the Taylor series.
#[inline]
pub(crate) fn small_sin_cos(a: f64) -> (f64, f64) {
    // The series' coefficients after their first term, in powers of a^2, evaluated in
    // pairs (Estrin's scheme: a shorter chain of dependent operations than Horner's).
    const SIN: [f64; 5] = [-1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362_880.0, -1.0 / 39_916_800.0];
    const COS: [f64; 5] = [-0.5, 1.0 / 24.0, -1.0 / 720.0, 1.0 / 40_320.0, -1.0 / 3_628_800.0];
    let x = a * a;
    let (x2, x4) = (x * x, x * x * x * x);
    let series = |c: &[f64; 5]| (c[0] + c[1] * x) + x2 * (c[2] + c[3] * x) + x4 * c[4];
    let sin = a + a * x * series(&SIN);
    let cos = 1.0 + x * series(&COS);
    (sin, cos)
}

/// The largest angle (rad) [`tiny_sin_cos`] takes.
pub(crate) const TINY: f64 = 1e-3;

/// (sin a, cos a) for |a| up to [`TINY`], by the Taylor series to the fifth power (the
/// first terms left out are below 1e-21).
#[inline(always)]
pub(crate) fn tiny_sin_cos(a: f64) -> (f64, f64) {
    let x = a * a;
    (a + a * x * (-1.0 / 6.0 + x * (1.0 / 120.0)), 1.0 + x * (-0.5 + x * (1.0 / 24.0)))
}

/// (sin a, cos a) for any a: the series where it is small, the library elsewhere.
#[inline]
pub(crate) fn sin_cos(a: f64) -> (f64, f64) {
    if a.abs() <= SMALL {
        small_sin_cos(a)
    } else {
        math::sin_cos(a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_series_agrees_with_the_library_to_rounding() {
        let n = 200_000;
        type Series = fn(f64) -> (f64, f64);
        let series: [(&str, f64, Series); 2] = [("small", SMALL, small_sin_cos), ("tiny", TINY, tiny_sin_cos)];
        for (name, bound, sin_cos_of) in series {
            for i in 0..=n {
                let a = bound * (2.0 * i as f64 / n as f64 - 1.0);
                let ((s, c), (ls, lc)) = (sin_cos_of(a), a.sin_cos());
                assert!((s - ls).abs() <= f64::EPSILON * ls.abs(), "{name} sin {a}: {s} {ls}");
                assert!((c - lc).abs() <= f64::EPSILON, "{name} cos {a}: {c} {lc}");
            }
        }
        assert_eq!(sin_cos(0.0), (0.0, 1.0));
        assert_eq!(sin_cos(2.0), 2f64.sin_cos());
    }
}
