//! The reference line: u axis, x/y points integrated from the heading channel (or a
//! straight line), z integrated from the slope, banking, and closed-track data.

use crate::base::compat::Compat;
use crate::base::math;

/// Which optional end values the header defined.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Defined {
    /// `REFERENCE_LINE_END_X` was given.
    pub x_end: bool,
    /// `REFERENCE_LINE_END_Y` was given.
    pub y_end: bool,
    /// `REFERENCE_LINE_START_Z` was given.
    pub z_start: bool,
    /// `REFERENCE_LINE_END_Z` was given.
    pub z_end: bool,
    /// The data has reference line x and y channels (they set the u axis; x/y are
    /// computed from the start point and the heading all the same).
    pub xy_channels: bool,
}

/// What building the reference line found inconsistent or incomplete in the file:
/// worth a warning, as the reference warns of the same.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LineFinding {
    /// A straight line (no heading channel) without both `REFERENCE_LINE_END_X` and
    /// `_Y`: its end is the one its start, heading and length give.
    StraightEndComputed {
        /// The end point used (x, y), m.
        end: (f64, f64),
    },
    /// A straight line's end, from its start, heading and length, lies more than 0.5 mm
    /// from the end point the header gives.
    StraightEndDiffers {
        /// Header's end minus the line's end (x, y), m.
        gap: (f64, f64),
    },
    /// The heading channel integrated back from the header's end point misses the
    /// header's start point by more than 1e-6 times the line's length (the line is
    /// blended between both integrations).
    HeadingMissesStart {
        /// Header's start minus the backward integration's start (x, y), m.
        gap: (f64, f64),
    },
    /// The slope integrated back from `REFERENCE_LINE_END_Z` misses
    /// `REFERENCE_LINE_START_Z` by more than 1e-6 times the line's length.
    SlopeMissesStart {
        /// The absolute difference, m.
        gap: f64,
    },
    /// The data's x and y channels give the u axis only; x/y are integrated.
    XyChannelsNotUsed,
}

impl std::fmt::Display for LineFinding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            LineFinding::StraightEndComputed { end } => write!(
                f,
                "straight reference line without REFERENCE_LINE_END_X and _Y: its end ({:.4}, {:.4}) \
                 is taken from the start point, heading and length",
                end.0, end.1
            ),
            LineFinding::StraightEndDiffers { gap } => write!(
                f,
                "the end point the header gives lies ({:.4}, {:.4}) m from the end of the straight \
                 reference line its start point, heading and length give",
                gap.0, gap.1
            ),
            LineFinding::HeadingMissesStart { gap } => write!(
                f,
                "the heading channel, integrated back from the header's end point, misses its start \
                 point by ({:.4}, {:.4}) m; the line is blended between both ends",
                gap.0, gap.1
            ),
            LineFinding::SlopeMissesStart { gap } => write!(
                f,
                "the slope, integrated back from REFERENCE_LINE_END_Z, misses REFERENCE_LINE_START_Z \
                 by {gap:.5} m; the line z is blended between both ends"
            ),
            LineFinding::XyChannelsNotUsed => f.write_str(
                "the reference line x and y channels set the u axis only; x/y are integrated from the \
                 start point and the heading",
            ),
        }
    }
}

/// The reference line of a road.
#[derive(Debug, Clone, PartialEq)]
pub struct RefLine {
    /// u of the first cross section.
    pub u_first: f64,
    /// u of the last cross section.
    pub u_last: f64,
    /// Distance between cross sections.
    pub u_inc: f64,
    /// Number of cross sections.
    pub n: usize,
    /// x of every cross section's reference point.
    pub x: Vec<f64>,
    /// y of every cross section's reference point.
    pub y: Vec<f64>,
    /// Start x (header).
    pub x_first: f64,
    /// Start y (header).
    pub y_first: f64,
    /// End x (header, or the integrated end point).
    pub x_last: f64,
    /// End y (header, or the integrated end point).
    pub y_last: f64,
    /// Heading channel: `phi[i]` is the heading from point `i - 1` to point `i` (`phi[0]` is the start heading).
    pub phi: Option<Vec<f64>>,
    /// Start heading.
    pub phi_first: f64,
    /// End heading.
    pub phi_last: f64,
    /// Slope channel.
    pub slope: Option<Vec<f64>>,
    /// Start slope (constant slope when there is no channel).
    pub slope_first: f64,
    /// End slope.
    pub slope_last: f64,
    /// Banking channel.
    pub bank: Option<Vec<f64>>,
    /// Start banking (constant banking when there is no channel).
    pub bank_first: f64,
    /// End banking.
    pub bank_last: f64,
    /// Whether any banking is defined.
    pub has_bank: bool,
    /// z of the reference line, when a slope is defined.
    pub z: Option<Vec<f64>>,
    /// Start z.
    pub z_first: f64,
    /// End z.
    pub z_last: f64,
    /// Which end values the header gave.
    pub defined: Defined,
    /// sin and cos of the start and end headings.
    pub(crate) trig: Trig,
    /// u range over which the line can be closed into a loop.
    pub closed: Option<(f64, f64)>,
    /// The u range found the last time the line could be closed ((0, 0) before): what
    /// the classic API reports, also after modifiers made the line open.
    pub last_closed_range: (f64, f64),
    /// Per segment: the scaled normals at its start and end point (see [`RefLine::update_caches`]).
    pub(crate) normals: Vec<[f64; 4]>,
    /// Per segment: its length (what the x/y search divides by to get v).
    pub(crate) seg_len: Vec<f64>,
    /// Per cross section: the point and its direction, as the x/y search reads them.
    pub(crate) search: Vec<SearchPoint>,
    /// `n - 1` as a double: the largest grid fraction along u (set where the line is
    /// made; `n` never changes).
    pub(crate) last_frac: f64,
    /// Per cross section: the reference line curvature over 0.5 m (see [`RefLine::curvature_step`]).
    pub(crate) curvature: Vec<f64>,
    /// [`RefLine::curvature_step`] as of the last cache update.
    pub(crate) curv_step: usize,
}

/// Cached sines and cosines of the end headings.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Trig {
    pub first_sin: f64,
    pub first_cos: f64,
    pub last_sin: f64,
    pub last_cos: f64,
}

impl RefLine {
    /// u of cross section `i`.
    pub fn u_at(&self, i: usize) -> f64 {
        self.u_first + i as f64 * self.u_inc
    }

    /// Heading at cross section `i` (the constant heading when the line has no channel).
    pub fn heading_at(&self, i: usize) -> f64 {
        self.phi.as_ref().map_or(self.phi_first, |p| p[i])
    }

    /// Elevation of the line at cross section `i` (the constant when it has none).
    pub fn z_at(&self, i: usize) -> f64 {
        self.z.as_ref().map_or(self.z_first, |z| z[i])
    }

    /// Computes x/y of every cross section: a straight line along the start heading,
    /// or Euler steps along the heading channel. When the header gives the end
    /// point, a backward pass from the end is blended with the forward pass so the
    /// line meets both ends.
    ///
    /// The releases ([`Compat::Release201`]) start the forward pass from the point the
    /// line already holds (the origin after loading, or the backward pass's first point)
    /// instead of the header's start point. End points that disagree with the line, or a
    /// missing one, go to `findings`.
    pub(crate) fn integrate_xy(&mut self, compat: Compat, findings: &mut Vec<LineFinding>) {
        let from_start = compat == Compat::Upstream;
        let n = self.n;
        let inc = self.u_inc;
        let both_ends = self.defined.x_end && self.defined.y_end;
        let Some(phi) = &self.phi else {
            let (s, c) = math::sin_cos(self.phi_first);
            for i in 0..n {
                self.x[i] = self.x_first + i as f64 * inc * c;
                self.y[i] = self.y_first + i as f64 * inc * s;
            }
            if both_ends {
                let gap = (self.x_last - self.x[n - 1], self.y_last - self.y[n - 1]);
                if gap.0.abs() > 5e-4 || gap.1.abs() > 5e-4 {
                    findings.push(LineFinding::StraightEndDiffers { gap });
                }
            } else {
                self.x_last = self.x[n - 1];
                self.y_last = self.y[n - 1];
                findings.push(LineFinding::StraightEndComputed { end: (self.x_last, self.y_last) });
            }
            return;
        };
        if both_ends {
            self.x[n - 1] = self.x_last;
            self.y[n - 1] = self.y_last;
            for i in (1..n).rev() {
                self.x[i - 1] = self.x[i] - inc * math::cos(phi[i]);
                self.y[i - 1] = self.y[i] - inc * math::sin(phi[i]);
            }
            let gap = (self.x_first - self.x[0], self.y_first - self.y[0]);
            if math::hypot(gap.0, gap.1) > 1e-6 * (self.u_last - self.u_first) {
                findings.push(LineFinding::HeadingMissesStart { gap });
            }
            if from_start {
                self.x[0] = self.x_first;
                self.y[0] = self.y_first;
            }
            for i in 0..n - 1 {
                let f = (i + 1) as f64 / (n - 1) as f64;
                self.x[i + 1] = (1.0 - f) * (self.x[i] + inc * math::cos(phi[i + 1])) + f * self.x[i + 1];
                self.y[i + 1] = (1.0 - f) * (self.y[i] + inc * math::sin(phi[i + 1])) + f * self.y[i + 1];
            }
        } else {
            if from_start {
                self.x[0] = self.x_first;
                self.y[0] = self.y_first;
            }
            for i in 0..n - 1 {
                self.x[i + 1] = self.x[i] + inc * math::cos(phi[i + 1]);
                self.y[i + 1] = self.y[i] + inc * math::sin(phi[i + 1]);
            }
            self.x_last = self.x[n - 1];
            self.y_last = self.y[n - 1];
        }
    }

    /// Computes the reference line z from the slope channel or the constant start
    /// slope; nothing to do (and false) when neither is given. An end z that disagrees
    /// with the slope goes to `findings`.
    pub(crate) fn integrate_z(&mut self, findings: &mut Vec<LineFinding>) -> bool {
        if self.slope_first == 0.0 && self.slope.is_none() {
            return false;
        }
        let n = self.n;
        let inc = self.u_inc;
        let slope_at = |s: &Option<Vec<f64>>, i: usize| s.as_ref().map_or(self.slope_first, |v| v[i]);
        let mut z = self.z.take().unwrap_or_else(|| vec![0.0; n]);
        if self.defined.z_end {
            z[n - 1] = self.z_last;
            for i in (1..n).rev() {
                z[i - 1] = z[i] - slope_at(&self.slope, i) * inc;
            }
            let gap = (z[0] - self.z_first).abs();
            if gap > (self.u_last - self.u_first) * 1e-6 {
                findings.push(LineFinding::SlopeMissesStart { gap });
            }
            z[0] = self.z_first;
            for i in 0..n.saturating_sub(2) {
                let f = i as f64 / (n - 1) as f64;
                z[i + 1] = (1.0 - f) * (z[i] + slope_at(&self.slope, i + 1) * inc) + f * z[i + 1];
            }
        } else {
            z[0] = self.z_first;
            for i in 0..n - 1 {
                z[i + 1] = z[i] + slope_at(&self.slope, i + 1) * inc;
            }
            self.z_last = z[n - 1];
        }
        self.z = Some(z);
        true
    }

    /// Updates the cached end headings and finds whether the line can be closed: the
    /// continuations of both ends must meet ahead of the end and behind the start.
    pub(crate) fn update_utility(&mut self) {
        self.update_trig();
        self.closed = None;
        let (a1, a2) = (self.x_first, self.y_first);
        let (m1, m2) = (self.trig.first_cos, self.trig.first_sin);
        let (b1, b2) = (self.x_last, self.y_last);
        let (n1, n2) = (self.trig.last_cos, self.trig.last_sin);
        let along = m1 * n1 + m2 * n2;
        if along <= 0.5 {
            return;
        }
        let l = ((a2 - b2) * m2 + (a1 - b1) * m1) / along;
        if !(l > 0.0) {
            return;
        }
        let k = ((b2 - a2) * n2 + (b1 - a1) * n1) / along;
        if !(k < 0.0) {
            return;
        }
        let mut range = (self.u_first + 0.5 * k * along, self.u_last + 0.5 * l * along);
        let cross = m1 * n2 - m2 * n1;
        if cross.abs() > 1e-6 {
            let l = (m1 * (a2 - b2) + m2 * (b1 - a1)) / cross;
            if l >= 0.0 {
                let k = (n1 * (a2 - b2) + n2 * (b1 - a1)) / cross;
                if k <= 0.0 {
                    range = (self.u_first + k, self.u_last + l);
                }
            }
        }
        self.closed = Some(range);
        self.last_closed_range = range;
    }

    pub(crate) fn update_trig(&mut self) {
        self.trig = Trig {
            first_sin: math::sin(self.phi_first),
            first_cos: math::cos(self.phi_first),
            last_sin: math::sin(self.phi_last),
            last_cos: math::cos(self.phi_last),
        };
    }

    /// Index of the u interval holding `u` and the fraction within it, clamped to the data
    /// (the fraction may lie outside 0..1 beyond the ends).
    #[inline]
    pub(crate) fn interval(&self, u: f64) -> (usize, f64) {
        let f = (u - self.u_first) / self.u_inc;
        let last = self.n - 2;
        let i = if f < 0.0 {
            0
        } else if !(f < last as i64 as f64) {
            last
        } else {
            // SAFETY: 0 <= f < n - 2 here (NaN took the branch above): finite, within i64.
            unsafe { f.to_int_unchecked::<i64>() as usize }
        };
        (i, f - i as i64 as f64)
    }

    /// Number of cross sections spanning 0.5 m (at least 1): the step of the curvature estimate.
    pub(crate) fn curvature_step(&self) -> usize {
        ((0.5 / self.u_inc) as usize).max(1)
    }

    /// Recomputes what evaluation reads per segment and per cross section, from the
    /// current x/y: the normals at both ends of every segment, scaled so their
    /// component along the segment's own normal is 1 (v is measured along them), and
    /// the curvature at every cross section. The formulas are those evaluation used
    /// to apply per call, so the answers are bit for bit the same. The arrays are filled
    /// anew in their own memory (a road prepared again, by modifiers, takes no more).
    pub(crate) fn update_caches(&mut self) {
        let (xs, ys, n) = (&self.x, &self.y, self.n);
        refill(
            &mut self.normals,
            (0..n - 1).map(|i| {
                let (p1, p2) = ((xs[i], ys[i]), (xs[i + 1], ys[i + 1]));
                let n12 = normalized(-(p2.1 - p1.1), p2.0 - p1.0);
                let n1 = if i > 0 { normalized(-(p2.1 - ys[i - 1]), p2.0 - xs[i - 1]) } else { n12 };
                let n2 = if i + 2 < n { normalized(-(ys[i + 2] - p1.1), xs[i + 2] - p1.0) } else { n12 };
                let (a, b) = (stretch(n1, n12), stretch(n2, n12));
                [a.0, a.1, b.0, b.1]
            }),
        );
        refill(
            &mut self.seg_len,
            xs.windows(2).zip(ys.windows(2)).map(|(x, y)| {
                let (dx, dy) = (x[1] - x[0], y[1] - y[0]);
                (dx * dx + dy * dy).sqrt()
            }),
        );
        refill(
            &mut self.search,
            (0..n).map(|i| {
                let (before, after) = (i.saturating_sub(1), (i + 1).min(n - 1));
                SearchPoint { x: xs[i], y: ys[i], dx: xs[after] - xs[before], dy: ys[after] - ys[before] }
            }),
        );
        let k = self.curvature_step();
        self.curv_step = k;
        let mut curvature = std::mem::take(&mut self.curvature);
        let hd = self.curvature_scale(k);
        refill(&mut curvature, (0..n).map(|i| if i >= k && i + k < n { self.curvature_at(i, k, hd) } else { 0.0 }));
        self.curvature = curvature;
    }

    /// The factor of [`RefLine::curvature_at`] for points `k` apart (the same for every
    /// cross section: computed once for all of them).
    pub(crate) fn curvature_scale(&self, k: usize) -> f64 {
        1.0 / math::cube(self.u_inc * k as f64)
    }

    /// Curvature at cross section `i` from the points `i - k`, `i`, `i + k`, with the
    /// factor `hd` of [`RefLine::curvature_scale`] for `k`.
    #[inline]
    pub(crate) fn curvature_at(&self, i: usize, k: usize, hd: f64) -> f64 {
        let dx0 = self.x[i] - self.x[i - k];
        let dx1 = self.x[i + k] - self.x[i];
        let dy0 = self.y[i] - self.y[i - k];
        let dy1 = self.y[i + k] - self.y[i];
        (dx0 * dy1 - dy0 * dx1) * hd
    }
}

/// Replaces the values of `v` by `values`, in the memory `v` holds already where it has
/// room (a fresh allocation of the same size would leave the old one's memory with the
/// allocator: a road prepared again would hold its caches twice).
fn refill<T>(v: &mut Vec<T>, values: impl Iterator<Item = T>) {
    v.clear();
    v.extend(values);
}

/// A reference line point as the x/y search reads it, in one record: the point, and the
/// direction from the point before it to the point after it (at the ends, from or to the
/// end point itself).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
#[repr(C, align(32))]
pub(crate) struct SearchPoint {
    pub x: f64,
    pub y: f64,
    pub dx: f64,
    pub dy: f64,
}

impl SearchPoint {
    /// How far (x, y) lies ahead of the point along its direction (scaled by the
    /// direction's length): `(x - px) dx + (y - py) dy`.
    #[inline(always)]
    pub(crate) fn ahead(&self, x: f64, y: f64) -> f64 {
        (x - self.x) * self.dx + (y - self.y) * self.dy
    }
}

#[inline]
fn normalized(x: f64, y: f64) -> (f64, f64) {
    let len = (x * x + y * y).sqrt();
    if len < 1e-10 {
        (x, y)
    } else {
        (x / len, y / len)
    }
}

/// Scales a point normal so its component along the segment normal is 1.
#[inline]
fn stretch(n: (f64, f64), n12: (f64, f64)) -> (f64, f64) {
    let dot = n.0 * n12.0 + n.1 * n12.1;
    if dot.abs() > 1e-10 {
        (n.0 / dot, n.1 / dot)
    } else {
        n
    }
}
