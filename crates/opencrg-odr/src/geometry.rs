//! The records of a road's reference line (`<planView><geometry>`): line, arc, spiral,
//! poly3 and paramPoly3, each giving x, y and heading at a distance along it, in double
//! precision.

use crate::quadrature::{integrate, integrate_pair, points_for_turn};

/// The shape of one record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// A straight line.
    Line,
    /// A circular arc of this curvature (1/m, positive to the left).
    Arc {
        /// Curvature.
        curvature: f64,
    },
    /// A clothoid whose curvature changes linearly from `start` to `end` along it.
    Spiral {
        /// Curvature at the start.
        start: f64,
        /// Curvature at the end.
        end: f64,
    },
    /// v = a + b u + c u^2 + d u^3 in the record's own frame (u along its start heading).
    Poly3 {
        /// The polynomial's coefficients a, b, c, d.
        coefficients: [f64; 4],
    },
    /// u(p) and v(p) as cubics of p in the record's own frame.
    ParamPoly3 {
        /// u's coefficients a, b, c, d.
        u: [f64; 4],
        /// v's coefficients a, b, c, d.
        v: [f64; 4],
        /// Whether p runs from 0 to 1 (`pRange="normalized"`) rather than 0 to the length.
        normalized: bool,
    },
}

/// One record of the reference line: where it starts (s, x, y, heading), how long it is
/// and its shape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Geometry {
    /// s of its start.
    pub s: f64,
    /// x of its start.
    pub x: f64,
    /// y of its start.
    pub y: f64,
    /// Heading at its start (rad).
    pub hdg: f64,
    /// Its length along the line.
    pub length: f64,
    /// Its shape.
    pub shape: Shape,
}

/// A point of a reference line: x, y and heading.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// x (m).
    pub x: f64,
    /// y (m).
    pub y: f64,
    /// Heading (rad).
    pub hdg: f64,
    /// Curvature (1/m, positive to the left).
    pub curvature: f64,
}

fn cubic(c: &[f64; 4], p: f64) -> f64 {
    c[0] + p * (c[1] + p * (c[2] + p * c[3]))
}

fn cubic_slope(c: &[f64; 4], p: f64) -> f64 {
    c[1] + p * (2.0 * c[2] + p * 3.0 * c[3])
}

fn cubic_bend(c: &[f64; 4], p: f64) -> f64 {
    2.0 * c[2] + 6.0 * c[3] * p
}

/// Quadrature pieces for an integrand that turns through `turn` radians: one per radian,
/// and at least one per 100 m of `length` (at most 4096: a spiral turning through more
/// than 650 full circles is no road).
fn pieces(turn: f64, length: f64) -> usize {
    (turn.abs().max(length.abs() / 100.0).ceil() as usize).clamp(1, 4096)
}

impl Geometry {
    /// The pose `ds` after the record's start (beyond its ends the shape continues).
    pub fn pose(&self, ds: f64) -> Pose {
        let (local_x, local_y, turn, curvature) = match self.shape {
            Shape::Line => (ds, 0.0, 0.0, 0.0),
            Shape::Arc { curvature: k } => {
                // The chord 2 sin(k ds / 2) / k, at half the turn: exact as k goes to 0.
                let half = 0.5 * k * ds;
                let chord = if k == 0.0 { ds } else { 2.0 * half.sin() / k };
                (chord * half.cos(), chord * half.sin(), k * ds, k)
            }
            Shape::Spiral { start, end } => {
                let rate = if self.length > 0.0 { (end - start) / self.length } else { 0.0 };
                let angle = |t: f64| t * (start + 0.5 * rate * t);
                let turn_rate = start.abs().max((start + rate * ds).abs());
                let (x, y) = integrate_pair(
                    |t| {
                        let a = angle(t);
                        (a.cos(), a.sin())
                    },
                    0.0,
                    ds,
                    pieces(turn_rate * ds, ds),
                    16,
                );
                (x, y, angle(ds), start + rate * ds)
            }
            Shape::Poly3 { coefficients } => {
                let u = self.parameter_for(ds, &|u| (1.0, cubic_slope(&coefficients, u)), ds, self.length);
                let slope = cubic_slope(&coefficients, u);
                let bend = cubic_bend(&coefficients, u) / (1.0 + slope * slope).powf(1.5);
                (u, cubic(&coefficients, u), slope.atan(), bend)
            }
            Shape::ParamPoly3 { u, v, normalized } => {
                let end = if normalized { 1.0 } else { self.length };
                let guess = if self.length > 0.0 { ds * end / self.length } else { 0.0 };
                let p = self.parameter_for(ds, &|p| (cubic_slope(&u, p), cubic_slope(&v, p)), guess, end);
                let (du, dv) = (cubic_slope(&u, p), cubic_slope(&v, p));
                let bend = (du * cubic_bend(&v, p) - dv * cubic_bend(&u, p)) / (du * du + dv * dv).powf(1.5);
                (cubic(&u, p), cubic(&v, p), dv.atan2(du), bend)
            }
        };
        let (sin, cos) = self.hdg.sin_cos();
        Pose {
            x: self.x + cos * local_x - sin * local_y,
            y: self.y + sin * local_x + cos * local_y,
            hdg: self.hdg + turn,
            curvature,
        }
    }

    /// The pose `ds` after the record's start, from the pose `from` known `from_ds` after
    /// it: for a spiral, its heading integrated over the stretch between them only, with
    /// as few points as the stretch's turn needs (a wheel moving centimetres per step
    /// takes two); for the other shapes [`Geometry::pose`].
    pub fn pose_from(&self, from_ds: f64, from: Pose, ds: f64) -> Pose {
        let Shape::Spiral { start, end } = self.shape else { return self.pose(ds) };
        let rate = if self.length > 0.0 { (end - start) / self.length } else { 0.0 };
        let heading = |t: f64| self.hdg + t * (start + 0.5 * rate * t);
        let (k0, k1) = (start + rate * from_ds, start + rate * ds);
        let turn = k0.abs().max(k1.abs()) * (ds - from_ds).abs();
        if turn > 0.5 {
            return self.pose(ds);
        }
        let (dx, dy) = integrate_pair(
            |t| {
                let a = heading(t);
                (a.cos(), a.sin())
            },
            from_ds,
            ds,
            1,
            points_for_turn(turn),
        );
        Pose { x: from.x + dx, y: from.y + dy, hdg: heading(ds), curvature: k1 }
    }

    /// The length of the curve itself: for poly3 and paramPoly3 the arc length over the
    /// parameter range the record declares (p from 0 to 1 or to its length, u from 0 to the
    /// point `length` along the curve); the declared length otherwise.
    pub fn curve_length(&self) -> f64 {
        match self.shape {
            Shape::ParamPoly3 { u, v, normalized } => {
                let end = if normalized { 1.0 } else { self.length };
                integrate(|p| cubic_slope(&u, p).hypot(cubic_slope(&v, p)), 0.0, end, 16)
            }
            _ => self.length,
        }
    }

    /// The curve parameter at distance `ds` along a cubic curve whose derivative with
    /// respect to its parameter is `tangent(p)`: the arc length from 0 to p equals `ds`
    /// (where the record's declared length and the curve's own differ, s follows the
    /// curve). Newton's method from `guess`; `range` is the parameter's whole range.
    fn parameter_for(&self, ds: f64, tangent: &dyn Fn(f64) -> (f64, f64), guess: f64, range: f64) -> f64 {
        let speed = |p: f64| {
            let (a, b) = tangent(p);
            a.hypot(b)
        };
        // Up to eight pieces over the whole curve: the speed of a cubic is smooth.
        let arc = |p: f64| integrate(speed, 0.0, p, (8.0 * (p / range).abs()).ceil().clamp(1.0, 64.0) as usize);
        // Newton's method, kept inside a shrinking bracket.
        let mut p = guess;
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        for _ in 0..40 {
            let f = arc(p) - ds;
            if f > 0.0 {
                hi = hi.min(p);
            } else {
                lo = lo.max(p);
            }
            let step = f / speed(p).max(1e-12);
            let mut next = p - step;
            if !(next > lo && next < hi) && lo.is_finite() && hi.is_finite() {
                next = 0.5 * (lo + hi);
            }
            if (next - p).abs() <= 1e-14 * (1.0 + p.abs()) {
                return next;
            }
            p = next;
        }
        p
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn g(shape: Shape, length: f64) -> Geometry {
        Geometry { s: 0.0, x: 1.0, y: 2.0, hdg: 0.3, length, shape }
    }

    #[test]
    fn an_arc_is_a_circle() {
        let k = 0.02;
        let p = g(Shape::Arc { curvature: k }, 100.0).pose(70.0);
        let (cx, cy) = (1.0 - 0.3f64.sin() / k, 2.0 + 0.3f64.cos() / k);
        assert!(((p.x - cx).hypot(p.y - cy) - 1.0 / k).abs() < 1e-12);
        assert!((p.hdg - (0.3 + k * 70.0)).abs() < 1e-15);
        let flat = g(Shape::Arc { curvature: 0.0 }, 10.0).pose(10.0);
        assert!((flat.x - (1.0 + 10.0 * 0.3f64.cos())).abs() < 1e-14);
    }

    #[test]
    fn a_spiral_follows_the_fresnel_integrals_and_its_limits() {
        // The unit clothoid (curvature pi s) from 0 to 1: x = C(1), y = S(1).
        let c = Geometry {
            s: 0.0,
            x: 0.0,
            y: 0.0,
            hdg: 0.0,
            length: 1.0,
            shape: Shape::Spiral { start: 0.0, end: std::f64::consts::PI },
        };
        let p = c.pose(1.0);
        assert!(
            (p.x - 0.779_893_400_376_822_8).abs() < 1e-15 && (p.y - 0.438_259_147_390_354_8).abs() < 1e-15,
            "{p:?}"
        );
        // Constant curvature: the arc.
        let (sp, arc) = (g(Shape::Spiral { start: 0.01, end: 0.01 }, 300.0), g(Shape::Arc { curvature: 0.01 }, 300.0));
        for ds in [0.0, 17.0, 150.0, 300.0] {
            let (a, b) = (sp.pose(ds), arc.pose(ds));
            assert!((a.x - b.x).abs() < 1e-9 && (a.y - b.y).abs() < 1e-9 && (a.hdg - b.hdg).abs() < 1e-14);
        }
    }

    #[test]
    fn cubic_curves_are_walked_by_arc_length() {
        // A paramPoly3 tracing a straight line at uneven speed: s is still the distance.
        let pp = g(Shape::ParamPoly3 { u: [0.0, 2.0, 3.0, 5.0], v: [0.0; 4], normalized: true }, 10.0);
        for ds in [0.0, 2.5, 7.0, 10.0] {
            let p = pp.pose(ds);
            assert!(((p.x - 1.0).hypot(p.y - 2.0) - ds).abs() < 1e-12, "{ds} {p:?}");
        }
        // poly3 along a parabola: the distance walked equals the arc length integral.
        let k = 0.01;
        let poly = g(Shape::Poly3 { coefficients: [0.0, 0.0, k, 0.0] }, 50.0);
        let u: f64 = 40.0;
        let length = (u * (1.0 + 4.0 * k * k * u * u).sqrt() / 2.0) + (2.0 * k * u).asinh() / (4.0 * k);
        let p = poly.pose(length);
        let (dx, dy) = (p.x - 1.0, p.y - 2.0);
        let (local_u, local_v) = (dx * 0.3f64.cos() + dy * 0.3f64.sin(), -dx * 0.3f64.sin() + dy * 0.3f64.cos());
        assert!((local_u - u).abs() < 1e-9 && (local_v - k * u * u).abs() < 1e-9, "{local_u} {local_v}");
    }
}
