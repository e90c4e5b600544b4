//! The common case of an elevation lookup: a point inside an evenly spaced grid with no
//! smoothing zone set, where no option matters. Vehicle models ask for it under every
//! wheel at every step, so it has a path of its own: the cell is found from numbers
//! copied into the contact point, the grid is read without bounds checks (the bounds
//! were proven once, when the contact point took the road), and a contact point keeps
//! the terms of its last cell, which a wheel moving a few millimetres per step reads
//! again and again. The answers are those of the general path, bit for bit: the same
//! operations (those of `interpolation`) on the same values.

use crate::model::grid::{prefetch_cell_far_from, prefetch_path_from, VLayout};
use crate::model::road::Road;
use crate::query::eval::EvalOptions;
use crate::query::interpolation::{bilinear, corner_terms, lerp_at, lerp_terms};

/// How far ahead along u (in values) an elevation lookup asks for the reference line
/// channels it reads (elevation, banking): two cache lines, a few steps of a wheel at
/// 50 m/s on 1 cm cross sections.
const CHANNEL_AHEAD: usize = 16;

/// How a reference line channel (elevation or banking) enters the common case.
#[derive(Debug, Clone, Copy, PartialEq)]
enum LineTerm {
    /// Not at all (no banking).
    Absent,
    /// A constant (the channel is not given: its start value).
    Constant(f64),
    /// Interpolated along u from the channel's samples (one per cross section) here.
    Channel(*const f64),
}

/// What the common case reads, copied out of the road and the options into the contact
/// point: the numbers that find a point's cell, and where the road keeps its grid
/// values and reference line channels, whose sizes were checked once (so they are read
/// unchecked). Where the common case never applies (an uneven grid, a smoothing zone, a
/// road whose arrays disagree with its sizes) its bounds are NaN: every comparison with
/// them fails, so no point lies inside.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlainGrid {
    u_first: f64,
    /// The largest u whose grid fraction lies below the last cross section's.
    u_inner: f64,
    u_inc: f64,
    v_first: f64,
    /// The largest v whose grid fraction lies below the last long section's.
    v_inner: f64,
    v_inc: f64,
    /// The grid's values, long section by long section, `nu` apart.
    z: *const f32,
    nu: usize,
    mean: f64,
    line_z: LineTerm,
    bank: LineTerm,
}

// SAFETY: the pointers are only read, and point into a road that nobody changes while
// it lives (a road is shared through `Arc` and never changed in place); the contact
// point that holds a `PlainGrid` holds its road.
unsafe impl Send for PlainGrid {}
// SAFETY: as for `Send`.
unsafe impl Sync for PlainGrid {}

/// The largest `b <= last` for which `(b - first) / inc` lies below `limit` (and so
/// does that of every x from `first` to `b`: subtraction and division by a positive
/// increment never decrease as x grows); NaN where it is not found within a few steps
/// down from `last`.
fn inner_bound(first: f64, last: f64, inc: f64, limit: f64) -> f64 {
    let mut b = last;
    for _ in 0..64 {
        if (b - first) / inc < limit {
            return b;
        }
        b = b.next_down();
    }
    f64::NAN
}

/// Whether the road's arrays have the sizes the unchecked reads of [`PlainGrid`] rely
/// on: at least two samples along and across, `nu * nv` grid values, one channel value
/// per reference line sample, and the index bounds the cell search clamps to.
fn sizes_agree(road: &Road) -> bool {
    let (l, g) = (&road.line, &road.grid);
    let per_sample = |c: &Option<Vec<f64>>| c.as_ref().is_none_or(|c| c.len() == l.n);
    l.n == g.nu
        && g.nu >= 2
        && g.nv >= 2
        && g.nu.checked_mul(g.nv) == Some(g.values().len())
        && per_sample(&l.z)
        && per_sample(&l.bank)
        && l.last_frac == (l.n - 1) as f64
        && g.last_frac == (g.nv - 1) as f64
}

impl PlainGrid {
    /// The common case of `road` evaluated with `options`.
    pub(crate) fn new(road: &Road, options: &EvalOptions) -> Self {
        let (l, g) = (&road.line, &road.grid);
        // Positive increments make every fraction of a point inside non-negative, which
        // `PlainGrid::cell` relies on.
        let applies = options.no_smoothing()
            && g.layout == VLayout::Indexed
            && l.u_inc > 0.0
            && g.v_inc > 0.0
            && sizes_agree(road);
        let bound = |x: f64| if applies { x } else { f64::NAN };
        let term = |channel: &Option<Vec<f64>>, first: f64| match channel {
            Some(c) => LineTerm::Channel(c.as_ptr()),
            None => LineTerm::Constant(first),
        };
        PlainGrid {
            u_first: bound(l.u_first),
            u_inner: bound(inner_bound(l.u_first, l.u_last, l.u_inc, l.last_frac)),
            u_inc: l.u_inc,
            v_first: bound(g.v_first),
            v_inner: bound(inner_bound(g.v_first, g.v_last, g.v_inc, g.last_frac)),
            v_inc: g.v_inc,
            z: g.values().as_ptr(),
            nu: l.n,
            mean: g.mean,
            line_z: term(&l.z, l.z_first),
            bank: if l.has_bank { term(&l.bank, l.bank_first) } else { LineTerm::Absent },
        }
    }

    /// The cell of (u, v) when the point is of the common case; `None` otherwise (also
    /// for NaN, and for the points within a rounding step of the last cross or long
    /// section, which the general path answers). The same cell the general path finds
    /// for it.
    #[inline(always)]
    pub(crate) fn cell(&self, u: f64, v: f64) -> Option<PlainCell> {
        if !(u >= self.u_first && u <= self.u_inner && v >= self.v_first && v <= self.v_inner) {
            return None;
        }
        // Inside, 0 <= fu < nu - 1 and 0 <= fv < nv - 1 (see `inner_bound`): the
        // general path's index is the truncation.
        let fu = (u - self.u_first) / self.u_inc;
        let fv = (v - self.v_first) / self.v_inc;
        // SAFETY: both fractions are finite and far below 2^63 (the bounds above).
        let (iu, iv) = unsafe { (fu.to_int_unchecked::<i64>(), fv.to_int_unchecked::<i64>()) };
        Some(PlainCell { iu: iu as usize, fu: fu - iu as f64, iv: iv as usize, fv: fv - iv as f64, v })
    }

    /// Where the first corner of `cell` lies in the grid's values. Only computed, never
    /// read.
    #[inline(always)]
    fn corner(&self, cell: &PlainCell) -> *const f32 {
        self.z.wrapping_add(cell.iv.wrapping_mul(self.nu).wrapping_add(cell.iu))
    }

    /// Asks the processor to start loading the cell's grid values into the second-level
    /// cache, for an evaluation many others later (the batch's blocks ahead).
    #[inline(always)]
    pub(crate) fn prefetch_far(&self, cell: &PlainCell) {
        prefetch_cell_far_from(self.corner(cell), self.nu);
    }

    /// Asks the processor to start loading what a wheel moving on from `cell` reads next
    /// (see [`prefetch_path_from`]).
    #[inline(always)]
    pub(crate) fn prefetch_path(&self, cell: &PlainCell) {
        prefetch_path_from(self.corner(cell), self.nu, cell.fv > 0.5);
    }

    /// The terms of `cell`'s grid values, read from the road.
    ///
    /// # Safety
    /// The road this `PlainGrid` was made from is alive, and `cell` came from
    /// [`PlainGrid::cell`] of this `PlainGrid`: then [`sizes_agree`] held, and
    /// `cell.iu <= nu - 2` and `cell.iv <= nv - 2`, so every read is inside its array.
    #[inline(always)]
    pub(crate) unsafe fn terms(&self, cell: &PlainCell) -> CellTerms {
        let nu = self.nu;
        // SAFETY: (iv + 1) * nu + iu + 1 <= nu * nv - 1 (the contract above).
        let corners = unsafe {
            let p = self.corner(cell);
            corner_terms(*p, *p.add(1), *p.add(nu), *p.add(nu + 1))
        };
        CellTerms { iu: cell.iu, iv: cell.iv, corners }
    }

    /// The elevation at `cell` from the terms of its grid values.
    ///
    /// # Safety
    /// As for [`PlainGrid::terms`].
    #[inline(always)]
    pub(crate) unsafe fn elevation(&self, t: &CellTerms, cell: &PlainCell) -> f64 {
        let iu = cell.iu;
        let channel = |c: *const f64| {
            // What a wheel moving on reads some steps later (only the address is computed).
            crate::base::memory::prefetch(c.wrapping_add(iu + CHANNEL_AHEAD));
            // SAFETY: the channel has nu values and iu + 1 <= nu - 1 (the contract above).
            unsafe { lerp_at(lerp_terms(*c.add(iu), *c.add(iu + 1)), cell.fu) }
        };
        let mut z = bilinear(&t.corners, cell.fu, cell.fv) + self.mean;
        z += match self.line_z {
            LineTerm::Channel(c) => channel(c),
            LineTerm::Constant(c) => c,
            LineTerm::Absent => 0.0,
        };
        let bank = match self.bank {
            LineTerm::Absent => return z,
            LineTerm::Constant(c) => c,
            LineTerm::Channel(c) => channel(c),
        };
        z + bank * cell.v
    }
}

/// Where a point of the common case lies: its cell's interval indices and fractions,
/// and its v (for the banking).
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlainCell {
    iu: usize,
    fu: f64,
    iv: usize,
    fv: f64,
    v: f64,
}

/// A cell's grid values as the interpolation takes them (its [`corner_terms`]), with
/// the cell's indices. A contact point keeps those of its last cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct CellTerms {
    corners: [f64; 4],
    iu: usize,
    iv: usize,
}

impl CellTerms {
    /// Terms that belong to no cell (their indices lie beyond every grid).
    pub(crate) const NONE: CellTerms = CellTerms { corners: [0.0; 4], iu: usize::MAX, iv: usize::MAX };

    /// Whether these are the terms of `cell`'s cell.
    #[inline(always)]
    pub(crate) fn of(&self, cell: &PlainCell) -> bool {
        self.iu == cell.iu && self.iv == cell.iv
    }
}
