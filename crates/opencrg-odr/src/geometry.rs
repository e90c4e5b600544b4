//! The records of a road's reference line (`<planView><geometry>`): line, arc, spiral,
//! poly3 and paramPoly3, each giving x, y and heading at a distance along it, in double
//! precision.

use crate::quadrature::{integrate, integrate_pair, points_for_turn};
use crate::trig;
use opencrg_core::math;

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
#[derive(Debug, Clone, Copy, Default, PartialEq)]
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

/// The most a spiral record may turn, its largest curvature times its length (rad): ten
/// full circles, far beyond any road's transition curve. The reader refuses a record
/// beyond it, so that a point of a spiral never costs more than 63 quadrature pieces.
pub(crate) const MAX_SPIRAL_TURN: f64 = 20.0 * std::f64::consts::PI;

/// Quadrature pieces for an integrand that turns through `turn` radians: one per radian
/// (the 16-point rule is exact to rounding over a radian, however long the piece), at
/// most 4096 (beyond a record's end, where the shape continues).
fn pieces(turn: f64) -> usize {
    (turn.abs().ceil() as usize).clamp(1, 4096)
}

/// The largest turn (rad) between two stations for which [`turned_path`] is exact to
/// rounding.
pub(crate) const CLOSED_TURN: f64 = trig::TINY;

/// Where a path turning by `a s + b s^2` (s from 0 to 1 over the length `length`) ends,
/// in the frame of its start: the integrals of cos and sin of the turn by their series,
/// the turn's powers integrated in closed form. Exact to rounding while the turn stays
/// within [`CLOSED_TURN`] (the first terms left out are below 1e-17 of the length).
#[inline(always)]
pub(crate) fn turned_path(a: f64, b: f64, length: f64) -> (f64, f64) {
    // The integrals over 0..1 of (a s + b s^2)^n.
    let (a2, b2, ab) = (a * a, b * b, a * b);
    const THIRD: f64 = 1.0 / 3.0;
    let i1 = 0.5 * a + THIRD * b;
    let i2 = THIRD * a2 + 0.5 * ab + 0.2 * b2;
    let i3 = 0.25 * a * a2 + 0.6 * a2 * b + 0.5 * ab * b + (1.0 / 7.0) * b * b2;
    let i4 = 0.2 * a2 * a2 + (2.0 / 3.0) * a2 * ab + (6.0 / 7.0) * a2 * b2 + 0.5 * ab * b2 + (1.0 / 9.0) * b2 * b2;
    (length * (1.0 - 0.5 * i2 + (1.0 / 24.0) * i4), length * (i1 - (1.0 / 6.0) * i3))
}

/// Where a path turning by `k0 t + rate t^2 / 2` at t ends after `delta`, in the frame of
/// its start, by quadrature (the turn `turn` at most [`trig::SMALL`]).
#[inline(never)]
fn turning_path(k0: f64, rate: f64, delta: f64, turn: f64) -> (f64, f64) {
    integrate_pair(
        |t| {
            let (s, c) = trig::small_sin_cos(t * (k0 + 0.5 * rate * t));
            (c, s)
        },
        0.0,
        delta,
        1,
        points_for_turn(turn),
    )
}

/// A pose of a record with what moving on from it cheaply needs: its distance from the
/// record's start, the heading's sine and cosine, and on cubic curves the curve's parameter.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Station {
    /// Its distance from the record's start.
    pub ds: f64,
    /// The pose.
    pub pose: Pose,
    /// The heading's sine.
    pub sin: f64,
    /// The heading's cosine.
    pub cos: f64,
    /// The curve's parameter (poly3: u, paramPoly3: p; 0 on other shapes).
    param: f64,
    /// Sine and cosine of the record's start heading.
    frame: (f64, f64),
}

/// A cubic curve's point at parameter p in its record's frame: (u, v), the tangent
/// (du/dp, dv/dp) and the curvature.
struct CurvePoint {
    u: f64,
    v: f64,
    du: f64,
    dv: f64,
    curvature: f64,
}

impl Geometry {
    /// The pose `ds` after the record's start (beyond its ends the shape continues).
    pub fn pose(&self, ds: f64) -> Pose {
        self.placed(ds).0
    }

    /// The station `ds` after the record's start, computed from the record alone.
    pub(crate) fn station(&self, ds: f64) -> Station {
        let (pose, param, frame) = self.placed(ds);
        let (sin, cos) = match self.shape {
            Shape::Line => frame,
            _ => trig::sin_cos(pose.hdg),
        };
        Station { ds, pose, sin, cos, param, frame }
    }

    /// The pose `ds` after the record's start, the curve's parameter there, and the sine
    /// and cosine of the record's start heading.
    fn placed(&self, ds: f64) -> (Pose, f64, (f64, f64)) {
        let (local_x, local_y, turn, curvature, param) = self.local(ds);
        let (sin, cos) = math::sin_cos(self.hdg);
        let pose = Pose {
            x: self.x + cos * local_x - sin * local_y,
            y: self.y + sin * local_x + cos * local_y,
            hdg: self.hdg + turn,
            curvature,
        };
        (pose, param, (sin, cos))
    }

    /// The point `ds` after the record's start (x and y of [`Geometry::pose`]), `frame` the
    /// sine and cosine of the record's start heading.
    pub(crate) fn point_in(&self, (sin, cos): (f64, f64), ds: f64) -> [f64; 2] {
        let (local_x, local_y, ..) = self.local(ds);
        [self.x + cos * local_x - sin * local_y, self.y + sin * local_x + cos * local_y]
    }

    /// The point `ds` after the record's start in the record's own frame, the turn
    /// from its start heading, the curvature and the curve's parameter there.
    fn local(&self, ds: f64) -> (f64, f64, f64, f64, f64) {
        match self.shape {
            Shape::Line => (ds, 0.0, 0.0, 0.0, 0.0),
            Shape::Arc { curvature: k } => {
                // The chord 2 sin(k ds / 2) / k, at half the turn: exact as k goes to 0.
                let half = 0.5 * k * ds;
                let (sin, cos) = math::sin_cos(half);
                let chord = if k == 0.0 { ds } else { 2.0 * sin / k };
                (chord * cos, chord * sin, k * ds, k, 0.0)
            }
            Shape::Spiral { start, end } => {
                let rate = if self.length > 0.0 { (end - start) / self.length } else { 0.0 };
                let angle = |t: f64| t * (start + 0.5 * rate * t);
                let turn_rate = start.abs().max((start + rate * ds).abs());
                let (x, y) = integrate_pair(
                    |t| {
                        let (sin, cos) = math::sin_cos(angle(t));
                        (cos, sin)
                    },
                    0.0,
                    ds,
                    pieces(turn_rate * ds),
                    16,
                );
                (x, y, angle(ds), start + rate * ds, 0.0)
            }
            Shape::Poly3 { .. } | Shape::ParamPoly3 { .. } => {
                let (guess, range) = self.parameter_scale(ds);
                let p = self.parameter_for(ds, guess, range);
                let c = self.curve_point(p);
                (c.u, c.v, math::atan2(c.dv, c.du), c.curvature, p)
            }
        }
    }

    /// The station `ds` after the record's start, reached from the station `from`
    /// without the maths library: on a line directly; on an arc or a spiral by the turn
    /// between them (at most [`trig::SMALL`]); on a cubic curve by the arc length from
    /// `from`'s parameter (within an eighth of the curve). `None` beyond those bounds.
    /// With it, whether `ds` is near `from`: the cheapest ways served (a turn within
    /// [`CLOSED_TURN`], a 256th of a cubic curve), which a wheel moving centimetres per
    /// step keeps to. The station is written to `out`.
    #[inline(always)]
    pub(crate) fn station_from(&self, from: &Station, ds: f64, out: &mut Station) -> Option<bool> {
        let delta = ds - from.ds;
        let (sf, cf) = from.frame;
        let (pose, sin, cos, param, near) = match self.shape {
            Shape::Line => {
                let pose = Pose { x: self.x + cf * ds, y: self.y + sf * ds, hdg: self.hdg, curvature: 0.0 };
                (pose, sf, cf, 0.0, true)
            }
            Shape::Arc { .. } | Shape::Spiral { .. } => {
                let (start, rate) = match self.shape {
                    Shape::Spiral { start, end } if self.length > 0.0 => (start, (end - start) / self.length),
                    Shape::Spiral { start, .. } => (start, 0.0),
                    Shape::Arc { curvature } => (curvature, 0.0),
                    _ => unreachable!(),
                };
                let k0 = from.pose.curvature;
                let k1 = start + rate * ds;
                let turn = k0.abs().max(k1.abs()) * delta.abs();
                if !(turn <= trig::SMALL) {
                    return None;
                }
                let bend = delta * (k0 + 0.5 * rate * delta);
                let ((lx, ly), (st, ct)) = if turn <= CLOSED_TURN {
                    (turned_path(k0 * delta, 0.5 * rate * delta * delta, delta), trig::tiny_sin_cos(bend))
                } else {
                    (turning_path(k0, rate, delta, turn), trig::small_sin_cos(bend))
                };
                let p = from.pose;
                let pose = Pose {
                    x: p.x + from.cos * lx - from.sin * ly,
                    y: p.y + from.sin * lx + from.cos * ly,
                    hdg: self.hdg + ds * (start + 0.5 * rate * ds),
                    curvature: k1,
                };
                let (sin, cos) = (from.sin * ct + from.cos * st, from.cos * ct - from.sin * st);
                (pose, sin, cos, 0.0, turn <= CLOSED_TURN)
            }
            Shape::Poly3 { .. } | Shape::ParamPoly3 { .. } => {
                let (_, range) = self.parameter_scale(ds);
                let (p, near) = self.parameter_near(from.param, delta, range)?;
                let c = self.curve_point(p);
                let pose = Pose {
                    x: self.x + cf * c.u - sf * c.v,
                    y: self.y + sf * c.u + cf * c.v,
                    hdg: self.hdg + math::atan2(c.dv, c.du),
                    curvature: c.curvature,
                };
                let n = math::hypot(c.du, c.dv);
                let (tu, tv) = (c.du / n, c.dv / n);
                (pose, sf * tu + cf * tv, cf * tu - sf * tv, p, near)
            }
        };
        *out = Station { ds, pose, sin, cos, param, frame: from.frame };
        Some(near)
    }

    /// The length of the curve itself: for poly3 and paramPoly3 the arc length over the
    /// parameter range the record declares (p from 0 to 1 or to its length, u from 0 to the
    /// point `length` along the curve); the declared length otherwise.
    pub fn curve_length(&self) -> f64 {
        match self.shape {
            Shape::ParamPoly3 { u, v, normalized } => {
                let end = if normalized { 1.0 } else { self.length };
                integrate(|p| math::hypot(cubic_slope(&u, p), cubic_slope(&v, p)), 0.0, end, 16, 16)
            }
            _ => self.length,
        }
    }

    /// A cubic curve's tangent (du/dp, dv/dp) at parameter p.
    fn tangent(&self, p: f64) -> (f64, f64) {
        match self.shape {
            Shape::Poly3 { coefficients } => (1.0, cubic_slope(&coefficients, p)),
            Shape::ParamPoly3 { u, v, .. } => (cubic_slope(&u, p), cubic_slope(&v, p)),
            _ => (1.0, 0.0),
        }
    }

    /// A cubic curve's speed |d(u, v)/dp| at parameter p.
    fn speed(&self, p: f64) -> f64 {
        let (a, b) = self.tangent(p);
        math::hypot(a, b)
    }

    /// A cubic curve's point at parameter p.
    fn curve_point(&self, p: f64) -> CurvePoint {
        match self.shape {
            Shape::Poly3 { coefficients: c } => {
                let slope = cubic_slope(&c, p);
                let curvature = cubic_bend(&c, p) / math::pow_three_halves(1.0 + slope * slope);
                CurvePoint { u: p, v: cubic(&c, p), du: 1.0, dv: slope, curvature }
            }
            Shape::ParamPoly3 { u, v, .. } => {
                let (du, dv) = (cubic_slope(&u, p), cubic_slope(&v, p));
                let curvature =
                    (du * cubic_bend(&v, p) - dv * cubic_bend(&u, p)) / math::pow_three_halves(du * du + dv * dv);
                CurvePoint { u: cubic(&u, p), v: cubic(&v, p), du, dv, curvature }
            }
            _ => CurvePoint { u: p, v: 0.0, du: 1.0, dv: 0.0, curvature: 0.0 },
        }
    }

    /// A cubic curve's first guess of the parameter at `ds`, and the parameter's whole range.
    fn parameter_scale(&self, ds: f64) -> (f64, f64) {
        match self.shape {
            Shape::ParamPoly3 { normalized, .. } => {
                let end = if normalized { 1.0 } else { self.length };
                (if self.length > 0.0 { ds * end / self.length } else { 0.0 }, end)
            }
            _ => (ds, self.length),
        }
    }

    /// The curve parameter at distance `ds` along a cubic curve: the arc length from 0
    /// to p equals `ds` (where the record's declared length and the curve's own differ, s
    /// follows the curve). Newton's method from `guess`; `range` is the parameter's whole
    /// range.
    fn parameter_for(&self, ds: f64, guess: f64, range: f64) -> f64 {
        // Up to eight pieces over the whole curve: the speed of a cubic is smooth.
        let arc = |p: f64| {
            integrate(|q| self.speed(q), 0.0, p, (8.0 * (p / range).abs()).ceil().clamp(1.0, 64.0) as usize, 16)
        };
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
            let step = f / self.speed(p).max(1e-12);
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

    /// The curve parameter `delta` along a cubic curve from parameter `from`, by Newton's
    /// method on the arc length from `from` (one piece: sixteen points, eight within a
    /// 32nd of the range, four within a 256th), and whether it lies within that 256th;
    /// `None` beyond an eighth of `range` or without convergence.
    fn parameter_near(&self, from: f64, delta: f64, range: f64) -> Option<(f64, bool)> {
        let range = range.abs();
        let mut p = from + delta / self.speed(from).max(1e-12);
        for _ in 0..20 {
            let span = (p - from).abs();
            if !(span <= range / 8.0) {
                return None;
            }
            let points = if span * 256.0 <= range {
                4
            } else if span * 32.0 <= range {
                8
            } else {
                16
            };
            let f = integrate(|q| self.speed(q), from, p, 1, points) - delta;
            let next = p - f / self.speed(p).max(1e-12);
            if (next - p).abs() <= 1e-14 * (1.0 + p.abs()) {
                return Some((next, (next - from).abs() * 256.0 <= range));
            }
            p = next;
        }
        None
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

    #[test]
    fn stations_reached_from_a_station_agree_with_the_record() {
        let shapes = [
            (Shape::Line, 100.0),
            (Shape::Arc { curvature: -0.04 }, 100.0),
            (Shape::Spiral { start: 0.002, end: 0.05 }, 120.0),
            (Shape::Poly3 { coefficients: [0.1, 0.02, 0.003, -0.00004] }, 60.0),
            (Shape::ParamPoly3 { u: [0.0, 40.0, 5.0, -2.0], v: [0.0, 1.0, 6.0, -3.0], normalized: true }, 45.0),
            (Shape::ParamPoly3 { u: [0.0, 1.0, 0.01, 0.0], v: [0.0, 0.0, 0.004, 0.0001], normalized: false }, 40.0),
        ];
        for (shape, length) in shapes {
            let g = g(shape, length);
            let from = g.station(20.0);
            let (mut near, mut far, mut refused) = (0, 0, 0);
            for delta in [0.0, 1e-7, 0.003, -0.02, 0.05, 0.4, -1.5, 2.5, 4.0, -8.0, 15.0] {
                let mut st = Station::default();
                let Some(close) = g.station_from(&from, 20.0 + delta, &mut st) else {
                    refused += 1;
                    continue;
                };
                if close {
                    near += 1;
                } else {
                    far += 1;
                }
                let exact = g.station(20.0 + delta);
                let (a, b) = (st.pose, exact.pose);
                let off = (a.x - b.x).hypot(a.y - b.y);
                assert!(off < 1e-12, "{shape:?} {delta}: {off}");
                assert!(
                    (a.hdg - b.hdg).abs() < 1e-13 && (a.curvature - b.curvature).abs() < 1e-13,
                    "{shape:?} {delta}"
                );
                assert!((st.sin - exact.sin).abs() < 1e-14 && (st.cos - exact.cos).abs() < 1e-14, "{shape:?} {delta}");
                assert!((st.sin.hypot(st.cos) - 1.0).abs() < 1e-15);
            }
            // Centimetre steps are served the cheapest way; far stations are refused where
            // the turn or the curve's stretch is too long.
            assert!(near >= 4, "{shape:?}: {near} near");
            if !matches!(shape, Shape::Line) {
                assert!(far + refused >= 3, "{shape:?}: {far} far, {refused} refused");
            }
        }
    }
}
