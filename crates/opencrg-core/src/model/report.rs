//! What a road reports about itself: the figures the reference library prints after
//! preparing a road, and the events of loading, checking and applying modifiers, for
//! a front end (the C API prints them as messages) to pass on.

use crate::base::math;
use crate::model::grid::Grid;
use crate::model::refline::{LineFinding, RefLine};
use std::path::PathBuf;

/// Figures of a prepared road.
#[derive(Debug, Clone, PartialEq)]
pub struct Statistics {
    /// Mean elevation of the first cross section (NaN cells left out).
    pub z_mean_start: f64,
    /// Mean elevation of the last cross section.
    pub z_mean_end: f64,
    /// Lowest elevation of the grid (no lower than the start mean's own value bounds it);
    /// NaN for a grid read in place (finding it would read the whole grid).
    pub z_min: f64,
    /// Highest elevation of the grid; NaN for a grid read in place.
    pub z_max: f64,
    /// u of the first cross section.
    pub u_first: f64,
    /// u of the last cross section.
    pub u_last: f64,
    /// x, y and heading of the reference line's first segment.
    pub start: (f64, f64, f64),
    /// x, y and heading of the reference line's last segment.
    pub end: (f64, f64, f64),
    /// v of the right border.
    pub v_first: f64,
    /// v of the left border.
    pub v_last: f64,
    /// Tightest right curve of the reference line (negative curvature, 1/m; 0 if none).
    pub curvature_right: f64,
    /// Tightest left curve of the reference line (1/m; 0 if none).
    pub curvature_left: f64,
    /// First and last value of the banking channel, when there is one.
    pub banking: Option<(f64, f64)>,
    /// Reference line z at the start and the end (0 when no slope is defined).
    pub z_line: (f64, f64),
}

/// Something that happened to a road, worth telling its user.
#[derive(Debug, Clone, PartialEq)]
pub enum Event {
    /// A file named by `$ROAD_CRG_FILE` was read.
    FileImported(PathBuf),
    /// The reference line was integrated from the heading channel (else it is straight).
    LineFromHeading,
    /// The reference line z was integrated from the slope.
    LineZFromSlope,
    /// Building the reference line found the file inconsistent or incomplete.
    Line(LineFinding),
    /// The road was prepared (after loading, or after modifiers that change data).
    Prepared(Box<Statistics>),
    /// Whether the reference line can be closed, and over which u range.
    ClosedTrack(Option<(f64, f64)>),
    /// `crgCheck` completed a relocation modifier with its default.
    ModifierDefaulted {
        /// The modifier's identifier (see [`crate::settings::name`]).
        id: u32,
        /// The value it was given.
        value: f64,
    },
    /// NaN handling of the grid borders: how many cells were NaN.
    NansHandled(usize),
    /// NaN handling of the grid borders of a road read in place: it acts where values are
    /// read (the cells are not counted, which would read the whole grid).
    NansHandledWhereRead,
    /// The road was moved: the point moved, by how much, and the rotation.
    Relocated {
        /// Rotation center (x, y).
        center: (f64, f64),
        /// Rotation angle, rad.
        angle: f64,
        /// Translation (x, y, z).
        shift: (f64, f64, f64),
    },
}

/// The lowest and highest value, NaN left out (infinities when there is none). Eight
/// lanes of comparisons that are false for NaN, so the loop becomes vector min/max
/// instructions: the grid of a large road is scanned at memory speed.
fn finite_range(values: &[f32]) -> (f32, f32) {
    const LANES: usize = 8;
    let (mut lo, mut hi) = ([f32::INFINITY; LANES], [f32::NEG_INFINITY; LANES]);
    let chunks = values.chunks_exact(LANES);
    let rest = chunks.remainder();
    for chunk in chunks {
        for k in 0..LANES {
            lo[k] = if chunk[k] < lo[k] { chunk[k] } else { lo[k] };
            hi[k] = if chunk[k] > hi[k] { chunk[k] } else { hi[k] };
        }
    }
    for &z in rest {
        lo[0] = if z < lo[0] { z } else { lo[0] };
        hi[0] = if z > hi[0] { z } else { hi[0] };
    }
    (lo.into_iter().fold(f32::INFINITY, f32::min), hi.into_iter().fold(f32::NEG_INFINITY, f32::max))
}

impl Statistics {
    /// The figures of a reference line and grid as they are now.
    pub(crate) fn of(l: &RefLine, g: &Grid) -> Statistics {
        let mean_of = |row: &mut dyn Iterator<Item = f32>| {
            let (sum, n) = row.filter(|z| !z.is_nan()).fold((0.0, 0usize), |(s, n), z| (s + f64::from(z), n + 1));
            if n > 0 {
                sum / n as f64
            } else {
                0.0
            }
        };
        let z_mean_start = mean_of(&mut g.cross_section(0));
        let z_mean_end = mean_of(&mut g.cross_section(g.nu - 1));
        let (z_min, z_max) = match g.in_memory() {
            Some(values) => {
                let (lo, hi) = finite_range(values);
                (z_mean_start.min(f64::from(lo)), z_mean_start.max(f64::from(hi)))
            }
            None => (f64::NAN, f64::NAN),
        };
        let n = l.n;
        let heading = |a: usize, b: usize| math::atan2(l.y[b] - l.y[a], l.x[b] - l.x[a]);
        let (mut right, mut left) = (0.0f64, 0.0f64);
        let hd = l.curvature_scale(1);
        for i in 1..n - 1 {
            let c = l.curvature_at(i, 1, hd);
            right = right.min(c);
            left = left.max(c);
        }
        Statistics {
            z_mean_start: z_mean_start + g.mean,
            z_mean_end: z_mean_end + g.mean,
            z_min: z_min + g.mean,
            z_max: z_max + g.mean,
            u_first: l.u_first,
            u_last: l.u_last,
            start: (l.x[0], l.y[0], heading(0, 1)),
            end: (l.x[n - 1], l.y[n - 1], heading(n - 2, n - 1)),
            v_first: g.v_first,
            v_last: g.v_last,
            curvature_right: right,
            curvature_left: left,
            banking: l.bank.as_ref().map(|b| (b[0], b[b.len() - 1])),
            z_line: l.z.as_ref().map_or((0.0, 0.0), |z| (z[0], z[n - 1])),
        }
    }
}
