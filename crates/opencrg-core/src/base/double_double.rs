//! Double-double numbers: an unevaluated sum of two `f64` carrying about 106 bits.
//!
//! Built from plain additions and multiplications only (Dekker's and Knuth's exact
//! transformations, no fused multiply-add), so every platform computes the same bits.
//! Valid away from overflow and underflow, which is where [`crate::base::portable_math`]
//! uses it.

use std::ops::Neg;

/// A number `hi + lo` with `|lo| <= ulp(hi) / 2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Dd {
    pub(crate) hi: f64,
    pub(crate) lo: f64,
}

/// `a + b` exactly as a rounded sum and its error (any order of magnitude).
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a + b` exactly, for `|a| >= |b|` (or `a` zero).
#[inline]
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// Veltkamp's split of `a` into two halves of 26 bits each.
#[inline]
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `a * b` exactly as a rounded product and its error (Dekker).
#[inline]
pub(crate) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

impl Dd {
    /// The exact value `x`.
    #[inline]
    pub(crate) const fn new(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// The normalised sum of two parts.
    #[inline]
    fn from_sum((a, b): (f64, f64)) -> Dd {
        let (hi, lo) = two_sum(a, b);
        Dd { hi, lo }
    }

    /// The exact product of two doubles.
    #[inline]
    pub(crate) fn prod(a: f64, b: f64) -> Dd {
        let (hi, lo) = two_prod(a, b);
        Dd { hi, lo }
    }

    /// `self + b`, accurate also when the two nearly cancel.
    #[inline]
    pub(crate) fn add(self, b: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, b.hi);
        let (t, f) = two_sum(self.lo, b.lo);
        let (s, e) = fast_two_sum(s, e + t);
        let (hi, lo) = fast_two_sum(s, e + f);
        Dd { hi, lo }
    }

    /// `self + b` for a double `b`.
    #[inline]
    pub(crate) fn add_f(self, b: f64) -> Dd {
        let (s, e) = two_sum(self.hi, b);
        let (hi, lo) = fast_two_sum(s, e + self.lo);
        Dd { hi, lo }
    }

    /// `self * b`.
    #[inline]
    pub(crate) fn mul(self, b: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, b.hi);
        let (hi, lo) = fast_two_sum(p, e + (self.hi * b.lo + self.lo * b.hi));
        Dd { hi, lo }
    }

    /// `self * b` for a double `b`.
    #[inline]
    pub(crate) fn mul_f(self, b: f64) -> Dd {
        let (p, e) = two_prod(self.hi, b);
        let (hi, lo) = fast_two_sum(p, e + self.lo * b);
        Dd { hi, lo }
    }

    /// `self / b` (one correction step after the double quotient).
    #[inline]
    pub(crate) fn div(self, b: Dd) -> Dd {
        let q = self.hi / b.hi;
        let r = self.add(b.mul_f(q).neg());
        Dd::from_sum((q, r.hi / b.hi))
    }

    /// The double nearest to `hi + lo` (the parts are normalised: `hi` is it).
    #[inline]
    pub(crate) fn round(self) -> f64 {
        self.hi + self.lo
    }
}

impl Neg for Dd {
    type Output = Dd;

    /// `-self`.
    #[inline]
    fn neg(self) -> Dd {
        Dd { hi: -self.hi, lo: -self.lo }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_and_sums_are_exact() {
        let (a, b) = (1.0 + f64::EPSILON, 1.0 - f64::EPSILON);
        let (p, e) = two_prod(a, b);
        assert_eq!(p, 1.0);
        assert_eq!(e, -f64::EPSILON * f64::EPSILON);
        let (s, e) = two_sum(1.0, 1e-30);
        assert_eq!((s, e), (1.0, 1e-30));
    }

    #[test]
    fn division_carries_the_remainder() {
        let third = Dd::new(1.0).div(Dd::new(3.0));
        let back = third.mul_f(3.0).add_f(-1.0);
        assert!(back.hi.abs() < 1e-31, "{back:?}");
        assert_ne!(third.lo, 0.0);
    }
}
