//! Gauss-Legendre quadrature: the integrals along curves that have no closed form (the
//! clothoid's position, the arc length of cubic curves). Sixteen points integrate
//! polynomials of degree 31 exactly; split where the integrand turns by at most a radian,
//! they leave errors far below rounding.

use std::sync::OnceLock;

/// The nodes (on -1..1) and weights of the sixteen-point rule.
const ORDER: usize = 16;

fn rule() -> &'static ([f64; ORDER], [f64; ORDER]) {
    static RULE: OnceLock<([f64; ORDER], [f64; ORDER])> = OnceLock::new();
    RULE.get_or_init(|| {
        let (mut nodes, mut weights) = ([0.0; ORDER], [0.0; ORDER]);
        let n = ORDER as f64;
        for i in 0..ORDER {
            // Newton's method on the Legendre polynomial from Chebyshev's estimate of its root.
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n + 0.5)).cos();
            let mut derivative = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=ORDER {
                    let k = k as f64;
                    let p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                derivative = n * (x * p1 - p0) / (x * x - 1.0);
                let step = p1 / derivative;
                x -= step;
                if step.abs() < 1e-17 {
                    break;
                }
            }
            nodes[i] = x;
            weights[i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
        }
        (nodes, weights)
    })
}

/// The integral of `f` from `a` to `b`, split into `pieces` equal intervals.
pub(crate) fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64, pieces: usize) -> f64 {
    let (nodes, weights) = rule();
    let pieces = pieces.max(1);
    let h = (b - a) / pieces as f64;
    let mut sum = 0.0;
    for k in 0..pieces {
        let mid = a + (k as f64 + 0.5) * h;
        let part: f64 = nodes.iter().zip(weights).map(|(x, w)| w * f(mid + 0.5 * h * x)).sum();
        sum += 0.5 * h * part;
    }
    sum
}

/// The integrals of two functions over the same points (cosine and sine of one angle).
pub(crate) fn integrate_pair(f: impl Fn(f64) -> (f64, f64), a: f64, b: f64, pieces: usize) -> (f64, f64) {
    let (nodes, weights) = rule();
    let pieces = pieces.max(1);
    let h = (b - a) / pieces as f64;
    let (mut sx, mut sy) = (0.0, 0.0);
    for k in 0..pieces {
        let mid = a + (k as f64 + 0.5) * h;
        let (mut px, mut py) = (0.0, 0.0);
        for (x, w) in nodes.iter().zip(weights) {
            let (fx, fy) = f(mid + 0.5 * h * x);
            px += w * fx;
            py += w * fy;
        }
        sx += 0.5 * h * px;
        sy += 0.5 * h * py;
    }
    (sx, sy)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polynomials_and_the_fresnel_integrals_come_out_exact() {
        assert!((integrate(|x| x.powi(31) + 3.0 * x * x, 0.0, 2.0, 1) - (2f64.powi(32) / 32.0 + 8.0)).abs() < 1e-6);
        let (_, w) = rule();
        assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-14, "{}", w.iter().sum::<f64>());
        // C(1) and S(1), the Fresnel integrals of cos/sin(pi x^2 / 2) from 0 to 1.
        let (c, s) = integrate_pair(
            |x| {
                let a = std::f64::consts::FRAC_PI_2 * x * x;
                (a.cos(), a.sin())
            },
            0.0,
            1.0,
            2,
        );
        assert!((c - 0.779_893_400_376_822_8).abs() < 1e-15, "{c}");
        assert!((s - 0.438_259_147_390_354_8).abs() < 1e-15, "{s}");
    }
}
