//! Gauss-Legendre quadrature: the integrals along curves that have no closed form (the
//! clothoid's position, the arc length of cubic curves). Sixteen points integrate
//! polynomials of degree 31 exactly; split where the integrand turns by at most a radian,
//! they leave errors far below rounding. Over short stretches where the integrand turns
//! little, fewer points do the same ([`points_for_turn`]).

use opencrg_core::math;
use std::sync::OnceLock;

/// A rule: nodes on -1..1 and their weights (the first `n` entries).
type Rule = ([f64; 16], [f64; 16]);

/// The `n`-point rule (n up to 16): Newton's method on the Legendre polynomial from
/// Chebyshev's estimate of each root.
fn make(n: usize) -> Rule {
    let (mut nodes, mut weights) = ([0.0; 16], [0.0; 16]);
    let order = n as f64;
    for i in 0..n {
        let mut x = math::cos(std::f64::consts::PI * (i as f64 + 0.75) / (order + 0.5));
        let mut derivative = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let k = k as f64;
                let p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = order * (x * p1 - p0) / (x * x - 1.0);
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
}

/// The rules of 2, 4, 8 and 16 points.
fn rule(n: usize) -> (&'static [f64], &'static [f64]) {
    static RULES: OnceLock<[Rule; 4]> = OnceLock::new();
    let rules = RULES.get_or_init(|| [make(2), make(4), make(8), make(16)]);
    let (k, n) = match n {
        0..=2 => (0, 2),
        3..=4 => (1, 4),
        5..=8 => (2, 8),
        _ => (3, 16),
    };
    (&rules[k].0[..n], &rules[k].1[..n])
}

/// How many points integrate cos and sin of an angle that turns through `turn` radians
/// (its rate changing by less) over an interval to rounding (errors below 1e-15 of the
/// interval, measured by the tests): four up to 0.01 rad, eight up to a radian, sixteen
/// beyond.
pub(crate) fn points_for_turn(turn: f64) -> usize {
    let turn = turn.abs();
    if turn < 0.01 {
        4
    } else if turn < 1.0 {
        8
    } else {
        16
    }
}

/// The integral of `f` from `a` to `b`, split into `pieces` equal intervals with the
/// `points`-point rule on each.
pub(crate) fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64, pieces: usize, points: usize) -> f64 {
    let (nodes, weights) = rule(points);
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

/// The integrals of two functions over the same points (cosine and sine of one angle),
/// over `pieces` equal intervals with the `points`-point rule on each.
pub(crate) fn integrate_pair(
    f: impl Fn(f64) -> (f64, f64),
    a: f64,
    b: f64,
    pieces: usize,
    points: usize,
) -> (f64, f64) {
    let (nodes, weights) = rule(points);
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
        assert!((integrate(|x| x.powi(31) + 3.0 * x * x, 0.0, 2.0, 1, 16) - (2f64.powi(32) / 32.0 + 8.0)).abs() < 1e-6);
        for n in [2, 4, 8, 16] {
            let (_, w) = rule(n);
            assert_eq!(w.len(), n);
            assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-14, "{n}: {}", w.iter().sum::<f64>());
        }
        // C(1) and S(1), the Fresnel integrals of cos/sin(pi x^2 / 2) from 0 to 1.
        let fresnel = |x: f64| {
            let a = std::f64::consts::FRAC_PI_2 * x * x;
            (a.cos(), a.sin())
        };
        let (c, s) = integrate_pair(fresnel, 0.0, 1.0, 2, 16);
        assert!((c - 0.779_893_400_376_822_8).abs() < 1e-15, "{c}");
        assert!((s - 0.438_259_147_390_354_8).abs() < 1e-15, "{s}");
    }

    #[test]
    fn few_points_suffice_where_the_angle_turns_little() {
        // An angle turning through `turn` over [0, 1] with a quadratic part: each order
        // against sixteen points split into 64 pieces.
        for turn in [1e-6, 1e-4, 0.005, 0.0099, 0.2, 0.99] {
            let f = |t: f64| {
                let a = 0.3 + turn * t * (0.6 + 0.4 * t);
                (a.cos(), a.sin())
            };
            let exact = integrate_pair(f, 0.0, 1.0, 64, 16);
            let quick = integrate_pair(f, 0.0, 1.0, 1, points_for_turn(turn));
            assert!(
                (quick.0 - exact.0).abs() < 1e-15 && (quick.1 - exact.1).abs() < 1e-15,
                "{turn}: {quick:?} {exact:?}"
            );
        }
    }
}
