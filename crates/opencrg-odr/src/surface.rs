//! Road coordinates to world: the reference line in three dimensions, and the point of
//! the road's surface at (s, t).
//!
//! The cross section at s is the plane through the reference line point turned by the
//! superelevation about the horizontal tangent (the heading's direction): t runs along
//! `e_t = (-cos r sin h, cos r cos h, sin r)`, heights above the cross section along
//! `e_h = (sin r sin h, -sin r cos h, cos r)`, with h the heading and r the
//! superelevation. A point at t thus lies `t cos r` from the reference line on the ground.
//! The lateral shape and the lanes' heights lift the surface along `e_h`.

use crate::geometry::{Geometry, Pose};
use crate::lanes::LaneSpan;
use crate::map::Road;
use opencrg_core::math;

/// A point of a road's reference line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RefPoint {
    /// x (m).
    pub x: f64,
    /// y (m).
    pub y: f64,
    /// z: the elevation (m).
    pub z: f64,
    /// Heading (rad).
    pub hdg: f64,
    /// The elevation's slope dz/ds.
    pub slope: f64,
    /// The superelevation (rad).
    pub roll: f64,
}

impl RefPoint {
    /// The unit vector along t.
    pub fn e_t(&self) -> [f64; 3] {
        let (sh, ch) = math::sin_cos(self.hdg);
        let (sr, cr) = math::sin_cos(self.roll);
        [-cr * sh, cr * ch, sr]
    }

    /// The unit vector of heights above the cross section.
    pub fn e_h(&self) -> [f64; 3] {
        let (sh, ch) = math::sin_cos(self.hdg);
        let (sr, cr) = math::sin_cos(self.roll);
        [sr * sh, -sr * ch, cr]
    }

    /// The point `t` along the cross section and `h` above it.
    pub fn at(&self, t: f64, h: f64) -> [f64; 3] {
        let (et, eh) = (self.e_t(), self.e_h());
        [self.x + t * et[0] + h * eh[0], self.y + t * et[1] + h * eh[1], self.z + t * et[2] + h * eh[2]]
    }
}

impl Road {
    /// The reference line record holding at `s` (before the first, the first).
    pub fn geometry_at(&self, s: f64) -> Option<&Geometry> {
        let after = self.plan.partition_point(|g| g.s <= s);
        self.plan.get(after.saturating_sub(1))
    }

    /// The reference line at `s`.
    pub fn reference(&self, s: f64) -> RefPoint {
        let nan = Pose { x: f64::NAN, y: f64::NAN, hdg: f64::NAN, curvature: f64::NAN };
        let Pose { x, y, hdg, .. } = self.geometry_at(s).map_or(nan, |g| g.pose(s - g.s));
        RefPoint {
            x,
            y,
            z: self.elevation.at(s),
            hdg,
            slope: self.elevation.slope_at(s),
            roll: self.superelevation.at(s),
        }
    }

    /// The lane at (s, t) with its borders.
    pub fn lane_at(&self, s: f64, t: f64) -> Option<LaneSpan<'_>> {
        self.lane_place(s, t).map(|(span, _)| span)
    }

    /// The lane at (s, t) with its borders, and s less its section's start.
    pub(crate) fn lane_place(&self, s: f64, t: f64) -> Option<(LaneSpan<'_>, f64)> {
        let (section, ds) = self.lanes.section_at(s)?;
        section.lane_at(ds, t, self.lanes.offset.at(s)).map(|span| (span, ds))
    }

    /// The lateral shape's height at (s, t): each group's polynomials along t, linear
    /// between the groups before and after s, the last group's beyond it.
    pub fn shape_height(&self, s: f64, t: f64) -> f64 {
        let at_group = |g: &crate::map::ShapeGroup| {
            let after = g.along_t.partition_point(|c| c.s <= t);
            g.along_t.get(after.saturating_sub(1)).map_or(0.0, |c| c.value(t - c.s))
        };
        let after = self.shape.partition_point(|g| g.s <= s);
        match (after.checked_sub(1).map(|i| &self.shape[i]), self.shape.get(after)) {
            (Some(a), Some(b)) if b.s > a.s => {
                let w = (s - a.s) / (b.s - a.s);
                at_group(a) * (1.0 - w) + at_group(b) * w
            }
            (Some(a), _) => at_group(a),
            (None, Some(b)) => at_group(b),
            (None, None) => 0.0,
        }
    }

    /// The lane's height at (s, t): its inner and outer heights, linear between its
    /// borders (0 outside the lanes).
    pub fn lane_height(&self, s: f64, t: f64) -> f64 {
        let Some((section, ds)) = self.lanes.section_at(s) else { return 0.0 };
        let Some(span) = section.lane_at(ds, t, self.lanes.offset.at(s)) else { return 0.0 };
        span_height(&span, ds, t)
    }
}

/// The height of the lane `span` at t, `ds` after its section's start.
pub(crate) fn span_height(span: &LaneSpan, ds: f64, t: f64) -> f64 {
    height_across(span.lane.height_at(ds), span.inner, span.outer, t)
}

/// The height at t of a lane between `inner` and `outer` (t) whose heights there are
/// `heights`: linear between its borders.
#[inline]
pub(crate) fn height_across((h_inner, h_outer): (f64, f64), inner: f64, outer: f64, t: f64) -> f64 {
    if h_inner == h_outer || outer == inner {
        return h_inner;
    }
    h_inner + (h_outer - h_inner) * (t - inner) / (outer - inner)
}

impl Road {
    /// The height of the surface above the cross section at (s, t): lateral shape and
    /// lane height.
    pub fn height_above_section(&self, s: f64, t: f64) -> f64 {
        self.shape_height(s, t) + self.lane_height(s, t)
    }

    /// The world point of the road's surface at (s, t).
    pub fn surface_point(&self, s: f64, t: f64) -> [f64; 3] {
        self.reference(s).at(t, self.height_above_section(s, t))
    }
}
