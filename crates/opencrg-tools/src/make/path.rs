//! Lines in the plane for making reference lines: a smooth curve through points (a
//! cubic spline over the chord length, continuous in heading and curvature)
//! and the walk along a polyline that puts points exactly one step apart, as a
//! reference line's heading channel places its cross sections.

use opencrg_core::budget::{filled, refused_of};
use opencrg_core::Result;

/// A point found by [`chord_walk`]: x, y and the polyline's parameter there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Stop {
    pub x: f64,
    pub y: f64,
    /// The parameter, linear along each polyline segment.
    pub t: f64,
}

/// Points along the polyline (`x`, `y`, parameter `t` at its vertices) starting at its
/// first vertex, each exactly `step` (straight-line distance) after the one before,
/// as far as the polyline reaches; its last vertex too where it lies a step from the
/// last point but for rounding. Refused: memory the system does not give.
pub(crate) fn chord_walk(x: &[f64], y: &[f64], t: &[f64], step: f64) -> Result<Vec<Stop>> {
    let n = x.len();
    let mut out = Vec::new();
    let expected = 1 + (t[n - 1] - t[0]).abs().div_euclid(step) as usize;
    out.try_reserve_exact(expected).map_err(|_| refused_of::<Stop>(expected, "the reference line's cross sections"))?;
    let (mut cx, mut cy) = (x[0], y[0]);
    out.push(Stop { x: cx, y: cy, t: t[0] });
    let mut seg = 0;
    // Where on `seg` the walk is (0 at its start, 1 at its end).
    let mut from = 0.0;
    let r2 = step * step;
    while seg + 1 < n {
        let (bx, by) = (x[seg + 1], y[seg + 1]);
        // A vertex a rounding error short of the step still counts as reached.
        if (bx - cx).powi(2) + (by - cy).powi(2) < r2 * (1.0 - 1e-9) {
            seg += 1;
            from = 0.0;
            continue;
        }
        // |A + s (B - A) - C| = step for the larger s: the circle's exit from the segment.
        let (ax, ay) = (x[seg], y[seg]);
        let (dx, dy) = (bx - ax, by - ay);
        let (ex, ey) = (ax - cx, ay - cy);
        let a = dx * dx + dy * dy;
        let b = 2.0 * (dx * ex + dy * ey);
        let c = ex * ex + ey * ey - r2;
        let s = (-b + (b * b - 4.0 * a * c).max(0.0).sqrt()) / (2.0 * a);
        if !s.is_finite() {
            // Coordinates so far apart that their squares leave the finite numbers: the
            // walk ends here, and the caller finds the line too short or refuses it.
            break;
        }
        let s = s.clamp(from, 1.0);
        cx = ax + s * dx;
        cy = ay + s * dy;
        out.push(Stop { x: cx, y: cy, t: t[seg] + s * (t[seg + 1] - t[seg]) });
        from = s;
    }
    // The polyline's end a rounding error short of one more step (the increment divides
    // a straight line's length, say) is a stop too: the walk ends where the line ends.
    let (ex, ey) = (x[n - 1], y[n - 1]);
    if n > 1 && (ex - cx).hypot(ey - cy) > step * (1.0 - END_SLACK) {
        out.push(Stop { x: ex, y: ey, t: t[n - 1] });
    }
    Ok(out)
}

/// How much shorter than a step (relative) the last one of a [`chord_walk`] may be: the
/// rounding that adding up a polyline's coordinates gathers, with room to spare.
const END_SLACK: f64 = 1e-6;

/// `count` points of the curve `at` (x/y at a parameter that runs from `t0` along it, at
/// about unit speed), one for every `step` of the parameter: the cross sections of a line
/// `step` apart in u that follows the curve. Each point lies exactly `step` (straight-line
/// distance) from the one before, aimed at the curve's point of its parameter. A chord is
/// shorter than the arc it spans, and the curve may run a little faster or slower than
/// its parameter, so the points drift along the curve from their aims by that difference
/// added up: about length × curvature² × increment² / 24, where the increment is the
/// larger of `step` and the spacing of the points the curve was drawn through (half a
/// millimetre over a kilometre of 100 m radius at 0.25 m). Across the curve each stays
/// within a chord's sagitta of it. Refused: memory the system does not give.
pub(crate) fn arc_walk(t0: f64, step: f64, count: usize, at: impl Fn(f64) -> (f64, f64)) -> Result<Vec<Stop>> {
    let mut out = Vec::new();
    out.try_reserve_exact(count).map_err(|_| refused_of::<Stop>(count, "the reference line's cross sections"))?;
    let (mut cx, mut cy) = at(t0);
    out.push(Stop { x: cx, y: cy, t: t0 });
    for k in 1..count {
        let t = t0 + k as f64 * step;
        let (ax, ay) = at(t);
        let (dx, dy) = (ax - cx, ay - cy);
        let d = dx.hypot(dy);
        if !(d > 0.0 && d.is_finite()) {
            // Coincident or unusable points: the walk ends here, and the caller finds the
            // line too short or refuses it.
            break;
        }
        cx += step * dx / d;
        cy += step * dy / d;
        out.push(Stop { x: cx, y: cy, t });
    }
    Ok(out)
}

/// A cubic spline through `(t[i], f[i])` (t increasing), with parabolic run-out at both
/// ends (the first and last pieces keep the curvature of their neighbours, so that a
/// curve that bends at its ends is followed there too).
pub(crate) struct Spline {
    t: Vec<f64>,
    f: Vec<f64>,
    /// Second derivatives at the knots.
    m: Vec<f64>,
}

impl Spline {
    /// The spline through the values (at least two knots; two give a straight line).
    pub fn new(t: &[f64], f: &[f64]) -> Spline {
        let n = t.len();
        let mut m = vec![0.0; n];
        if n > 2 {
            // The tridiagonal system for the inner second derivatives (Thomas algorithm),
            // m[0] = m[1] and m[n-1] = m[n-2] folded into its first and last rows.
            let mut c = vec![0.0; n];
            let mut d = vec![0.0; n];
            for i in 1..n - 1 {
                let h0 = t[i] - t[i - 1];
                let h1 = t[i + 1] - t[i];
                let rhs = 6.0 * ((f[i + 1] - f[i]) / h1 - (f[i] - f[i - 1]) / h0);
                let mut diag = 2.0 * (h0 + h1) - h0 * c[i - 1];
                if i == 1 {
                    diag += h0;
                }
                if i == n - 2 {
                    diag += h1;
                }
                c[i] = h1 / diag;
                d[i] = (rhs - h0 * d[i - 1]) / diag;
            }
            for i in (1..n - 1).rev() {
                m[i] = d[i] - c[i] * m[i + 1];
            }
            m[0] = m[1];
            m[n - 1] = m[n - 2];
        }
        Spline { t: t.to_vec(), f: f.to_vec(), m }
    }

    /// The value at `s` (the end pieces continue beyond the knots).
    pub fn at(&self, s: f64) -> f64 {
        let n = self.t.len();
        let i = self.t.partition_point(|&k| k <= s).clamp(1, n - 1) - 1;
        let h = self.t[i + 1] - self.t[i];
        let a = (self.t[i + 1] - s) / h;
        let b = (s - self.t[i]) / h;
        a * self.f[i]
            + b * self.f[i + 1]
            + ((a * a * a - a) * self.m[i] + (b * b * b - b) * self.m[i + 1]) * h * h / 6.0
    }
}

/// A smooth curve through points: x(t), y(t) (and z(t)) over the chord length t.
pub(crate) struct Curve {
    x: Spline,
    y: Spline,
    z: Option<Spline>,
    /// The chord length at the last point.
    pub length: f64,
}

impl Curve {
    /// The curve through the points (`z` optional); `None` when two neighbouring points
    /// coincide, with the index of the second.
    pub fn through(x: &[f64], y: &[f64], z: Option<&[f64]>) -> Result<Curve, usize> {
        let mut t = vec![0.0; x.len()];
        for i in 1..x.len() {
            let d = (x[i] - x[i - 1]).hypot(y[i] - y[i - 1]);
            if !(d > 1e-9) {
                return Err(i);
            }
            t[i] = t[i - 1] + d;
        }
        Ok(Curve {
            x: Spline::new(&t, x),
            y: Spline::new(&t, y),
            z: z.map(|z| Spline::new(&t, z)),
            length: t[t.len() - 1],
        })
    }

    /// The point at `t`.
    pub fn at(&self, t: f64) -> (f64, f64) {
        (self.x.at(t), self.y.at(t))
    }

    /// The elevation at `t`, when the points gave one.
    pub fn z_at(&self, t: f64) -> Option<f64> {
        self.z.as_ref().map(|z| z.at(t))
    }

    /// The curve as a polyline with points at most `spacing` apart in t. Refused: memory
    /// the system does not give.
    pub fn polyline(&self, spacing: f64) -> Result<(Vec<f64>, Vec<f64>, Vec<f64>)> {
        let n = (self.length / spacing).ceil().max(1.0) as usize;
        let what = "the polyline through the points";
        let (mut x, mut y, mut t) = (filled(n + 1, 0.0, what)?, filled(n + 1, 0.0, what)?, filled(n + 1, 0.0, what)?);
        for i in 0..=n {
            t[i] = self.length * i as f64 / n as f64;
            (x[i], y[i]) = self.at(t[i]);
        }
        Ok((x, y, t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_walk_keeps_its_step_on_a_bend() {
        // A quarter circle of radius 10 as 1,000 segments.
        let k = 1000;
        let a: Vec<f64> = (0..=k).map(|i| std::f64::consts::FRAC_PI_2 * i as f64 / k as f64).collect();
        let x: Vec<f64> = a.iter().map(|a| 10.0 * a.cos()).collect();
        let y: Vec<f64> = a.iter().map(|a| 10.0 * a.sin()).collect();
        let stops = chord_walk(&x, &y, &a, 0.5).unwrap();
        assert!(stops.len() >= 31, "{}", stops.len());
        for w in stops.windows(2) {
            let d = (w[1].x - w[0].x).hypot(w[1].y - w[0].y);
            assert!((d - 0.5).abs() < 1e-12, "{d}");
            assert!(w[1].t > w[0].t);
            assert!(((w[1].x.hypot(w[1].y)) - 10.0).abs() < 1e-5);
        }
    }

    #[test]
    fn the_arc_walk_keeps_the_length_and_stays_on_the_bend() {
        // A quarter circle of radius 10 by its arc length; steps of 1/31 of it and of 1.3.
        let length = 5.0 * std::f64::consts::PI;
        let circle = |t: f64| (10.0 * (t / 10.0).cos(), 10.0 * (t / 10.0).sin());
        for step in [length / 31.0, 1.3] {
            let count = (length / step + 1e-9).floor() as usize + 1;
            let stops = arc_walk(0.0, step, count, circle).unwrap();
            assert_eq!(stops.len(), count);
            for w in stops.windows(2) {
                let d = (w[1].x - w[0].x).hypot(w[1].y - w[0].y);
                assert!((d - step).abs() < 1e-12, "{d}");
                // On the circle within the chord's sagitta.
                assert!((w[1].x.hypot(w[1].y) - 10.0).abs() < step * step / 80.0 + 1e-9);
            }
            let end = stops[count - 1];
            assert!((end.t - step * (count - 1) as f64).abs() < 1e-9);
            // The last point near its aim (where the step divides the length, the curve's
            // end): within length x curvature^2 x step^2 / 24.
            let (ex, ey) = circle(step * (count - 1) as f64);
            let bound = length * step * step / 100.0 / 24.0;
            assert!((end.x - ex).hypot(end.y - ey) < bound, "{:?} {bound}", end);
        }
    }

    #[test]
    fn the_spline_is_exact_on_cubics_inside_and_smooth() {
        let t: Vec<f64> = (0..20).map(|i| i as f64 * 0.7).collect();
        let f: Vec<f64> = t.iter().map(|&s| (s * 0.3).sin()).collect();
        let s = Spline::new(&t, &f);
        for (k, &tk) in t.iter().enumerate() {
            assert!((s.at(tk) - f[k]).abs() < 1e-12);
        }
        let mid = 6.65;
        assert!((s.at(mid) - (mid * 0.3).sin()).abs() < 1e-4);
    }
}
