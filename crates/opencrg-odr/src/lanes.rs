//! Lane sections and lanes: where each lane's borders lie across the road (widths or
//! borders added outwards from the lane offset), the lanes' heights and materials.

use crate::profile::{Cubic, Profile};

/// A lane's raised or lowered surface from `s_offset` (from its section's start) on: the
/// heights at its inner and outer border, linear between them, held until the next record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Height {
    /// Where it starts, from the lane section's start.
    pub s_offset: f64,
    /// Height at the inner border (m).
    pub inner: f64,
    /// Height at the outer border (m).
    pub outer: f64,
}

/// A lane's material from `s_offset` on.
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    /// Where it starts, from the lane section's start.
    pub s_offset: f64,
    /// The friction coefficient, when given.
    pub friction: Option<f64>,
    /// The surface's name, when given.
    pub surface: Option<String>,
}

/// One lane of a section.
#[derive(Debug, Clone, PartialEq)]
pub struct Lane {
    /// Its id: positive to the left of the centre lane, negative to the right.
    pub id: i32,
    /// Its type (`driving`, `sidewalk`, `none`, ...).
    pub kind: String,
    /// Whether it keeps level instead of following superelevation (`level="true"`).
    pub level: bool,
    /// Its width along s (records' s from the section's start); empty when given by borders.
    pub width: Vec<Cubic>,
    /// Its outer border's t along s, when given that way (records' s from the section's start).
    pub border: Vec<Cubic>,
    /// Its heights.
    pub heights: Vec<Height>,
    /// Its materials.
    pub materials: Vec<Material>,
}

/// The record among `records` (sorted by offset) that holds at `ds`.
fn holding<T>(records: &[T], ds: f64, offset: impl Fn(&T) -> f64) -> Option<&T> {
    let after = records.partition_point(|r| offset(r) <= ds);
    records.get(after.saturating_sub(1))
}

impl Lane {
    /// Its width `ds` after its section's start.
    pub fn width_at(&self, ds: f64) -> f64 {
        holding(&self.width, ds, |r| r.s).map_or(0.0, |r| r.value(ds - r.s))
    }

    /// How its outer border is given `ds` after its section's start.
    pub(crate) fn edge(&self, ds: f64) -> Edge {
        if self.width.is_empty() {
            if let Some(b) = holding(&self.border, ds, |r| r.s) {
                return Edge::Border(*b);
            }
        }
        holding(&self.width, ds, |r| r.s).map_or(Edge::Inner, |w| Edge::Width(*w))
    }

    /// Its heights (inner, outer) `ds` after its section's start.
    pub fn height_at(&self, ds: f64) -> (f64, f64) {
        holding(&self.heights, ds, |h| h.s_offset).map_or((0.0, 0.0), |h| (h.inner, h.outer))
    }

    /// Its friction `ds` after its section's start, when a material gives one.
    pub fn friction_at(&self, ds: f64) -> Option<f64> {
        holding(&self.materials, ds, |m| m.s_offset).and_then(|m| m.friction)
    }
}

/// How a lane's outer border is given where one record of its widths or borders holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Edge {
    /// Its width from the inner border outwards.
    Width(Cubic),
    /// Its border's t.
    Border(Cubic),
    /// No record: the outer border is the inner one.
    Inner,
}

impl Edge {
    /// t of the outer border `ds` after the section's start, the inner border at `inner`
    /// and t growing outwards as `sign`.
    #[inline(always)]
    pub(crate) fn outer(&self, ds: f64, inner: f64, sign: f64) -> f64 {
        match self {
            Edge::Border(b) => b.value(ds - b.s),
            Edge::Width(w) => inner + sign * w.value(ds - w.s),
            Edge::Inner => inner,
        }
    }
}

/// Which lane holds t among the lanes `left` and `right` of the centre lane (each side
/// outwards), the centre lane at `offset`, `outer(lane, inner, sign)` giving a lane's outer
/// border from its inner one (t growing outwards as `sign`): the lane whose borders enclose
/// t (on a border, the outer lane), with its inner and outer border; `None` beyond the
/// outermost lanes or on the centre line of a side without lanes.
#[inline(always)]
pub(crate) fn find_lane<'a, L>(
    t: f64,
    offset: f64,
    (left, right): (&'a [L], &'a [L]),
    outer: impl Fn(&L, f64, f64) -> f64,
) -> Option<(&'a L, f64, f64)> {
    let mut inner = offset;
    if t >= offset {
        for lane in left {
            let o = outer(lane, inner, 1.0);
            if t < o || (t == o && t == inner) {
                return Some((lane, inner, o));
            }
            inner = o;
        }
    } else {
        for lane in right {
            let o = outer(lane, inner, -1.0);
            if t > o && t <= inner || (t == o && t == inner) {
                return Some((lane, inner, o));
            }
            inner = o;
        }
    }
    None
}

/// A lane section: from `s` on, its lanes to the left (ids 1, 2, ...) and to the right
/// (ids -1, -2, ...), each ordered outwards.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneSection {
    /// Where it starts.
    pub s: f64,
    /// The lanes left of the centre, outwards.
    pub left: Vec<Lane>,
    /// The lanes right of the centre, outwards.
    pub right: Vec<Lane>,
}

/// Where one lane lies across the road at some s: between `inner` and `outer` (t, m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaneSpan<'a> {
    /// The lane.
    pub lane: &'a Lane,
    /// t of its border nearer the centre.
    pub inner: f64,
    /// t of its border farther out.
    pub outer: f64,
}

impl LaneSection {
    /// The lanes of one side (`left` or right) at `ds` after the section's start, outwards,
    /// with their borders, the centre lane at `offset`.
    pub fn spans(&self, left: bool, ds: f64, offset: f64) -> impl Iterator<Item = LaneSpan<'_>> {
        let lanes = if left { &self.left } else { &self.right };
        let sign = if left { 1.0 } else { -1.0 };
        let mut inner = offset;
        lanes.iter().map(move |lane| {
            let outer = lane.edge(ds).outer(ds, inner, sign);
            let span = LaneSpan { lane, inner, outer };
            inner = outer;
            span
        })
    }

    /// Whether any of its lanes has a height record.
    pub fn has_heights(&self) -> bool {
        self.left.iter().chain(&self.right).any(|l| !l.heights.is_empty())
    }

    /// The lane at `t`, `ds` after the section's start, with its borders: the lane whose
    /// borders enclose t (on a border, the outer lane); `None` beyond the outermost lanes
    /// or on the centre line of a section without lanes there.
    pub fn lane_at(&self, ds: f64, t: f64, offset: f64) -> Option<LaneSpan<'_>> {
        let (lane, inner, outer) =
            find_lane(t, offset, (&self.left, &self.right), |lane, inner, sign| lane.edge(ds).outer(ds, inner, sign))?;
        Some(LaneSpan { lane, inner, outer })
    }
}

/// The lane sections of a road, sorted by s, and its lane offset.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Lanes {
    /// The centre lane's t along s (`<laneOffset>`).
    pub offset: Profile,
    /// The sections, sorted by s.
    pub sections: Vec<LaneSection>,
}

impl Lanes {
    /// The section holding at `s` and `s` less its start.
    pub fn section_at(&self, s: f64) -> Option<(&LaneSection, f64)> {
        holding(&self.sections, s, |l| l.s).map(|l| (l, s - l.s))
    }
}
