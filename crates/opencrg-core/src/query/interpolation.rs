//! The interpolation arithmetic of an elevation lookup, shared by the general path and
//! the common case's own (`plain`), so that both give the same answers bit for bit.

/// The four corner values of a cell, (iu, iv), (iu + 1, iv), (iu, iv + 1) and
/// (iu + 1, iv + 1), as the bilinear interpolation takes them: the first corner and
/// the differences along u, along v, and across.
#[inline(always)]
pub(crate) fn corner_terms(c00: f32, c10: f32, c01: f32, c11: f32) -> [f64; 4] {
    let z00 = f64::from(c00);
    let z10 = f64::from(c10) - z00;
    let z01 = f64::from(c01);
    let z11 = f64::from(c11) - (z10 + z01);
    [z00, z10, z01 - z00, z11]
}

/// The bilinear interpolation of a cell's [`corner_terms`] at fractions (fu, fv).
#[inline(always)]
pub(crate) fn bilinear(t: &[f64; 4], fu: f64, fv: f64) -> f64 {
    let [z00, z10, z01, z11] = *t;
    (z11 * fv + z10) * fu + z01 * fv + z00
}

/// The start of an interval of a channel and its rise, as [`lerp_at`] takes them.
#[inline(always)]
pub(crate) fn lerp_terms(a: f64, b: f64) -> [f64; 2] {
    [a, b - a]
}

/// The value a fraction `f` of the way along an interval given by [`lerp_terms`].
#[inline(always)]
pub(crate) fn lerp_at(t: [f64; 2], f: f64) -> f64 {
    t[0] + f * t[1]
}
