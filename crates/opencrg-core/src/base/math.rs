//! The transcendental functions roads are computed with, chosen per platform here only.
//!
//! With glibc (Linux on any processor) they are the C library's, as in the reference
//! library built there: the answers the conformance suites hold. Everywhere else
//! (Windows, macOS, WebAssembly, musl) they are [`crate::base::portable_math`]'s
//! correctly rounded ones. glibc's are correctly rounded at all but about 1 argument in
//! 700, so these platforms give Linux's answers far more often than with their own C
//! library (the `libm` compiled into WebAssembly differs from glibc at about 1 sine in 33
//! and 1 arc tangent in 6); docs/performance.md has the figures.

/// The correctly rounded functions, on every platform (those of this module where the
/// C library is not glibc).
pub use crate::base::portable_math as portable;

#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
pub use portable::{atan2, cos, cube, hypot, pow_three_halves, sin, sin_cos};

/// The platform C library's functions, under the names of the portable ones.
#[cfg(all(target_os = "linux", target_env = "gnu"))]
mod c_library {
    /// The sine of `x`.
    #[inline]
    pub fn sin(x: f64) -> f64 {
        x.sin()
    }

    /// The cosine of `x`.
    #[inline]
    pub fn cos(x: f64) -> f64 {
        x.cos()
    }

    /// The sine and the cosine of `x`.
    #[inline]
    pub fn sin_cos(x: f64) -> (f64, f64) {
        (x.sin(), x.cos())
    }

    /// The angle of the point `(x, y)` from the x axis, in (-pi, pi].
    #[inline]
    pub fn atan2(y: f64, x: f64) -> f64 {
        y.atan2(x)
    }

    /// `sqrt(x^2 + y^2)` without overflow.
    #[inline]
    pub fn hypot(x: f64, y: f64) -> f64 {
        x.hypot(y)
    }

    /// `x` cubed as C's `pow(x, 3.0)`.
    #[inline]
    pub fn cube(x: f64) -> f64 {
        x.powf(3.0)
    }

    /// `x` to the power 1.5 as C's `pow(x, 1.5)`.
    #[inline]
    pub fn pow_three_halves(x: f64) -> f64 {
        x.powf(1.5)
    }
}
#[cfg(all(target_os = "linux", target_env = "gnu"))]
pub use c_library::{atan2, cos, cube, hypot, pow_three_halves, sin, sin_cos};
