//! The common case of an elevation lookup: a point inside an evenly spaced grid with no
//! smoothing zone set, where no option matters. Vehicle models ask for it under every
//! wheel at every step, so it has a path of its own: the cell is found from numbers
//! copied into the contact point, the grid is read without bounds checks (the bounds
//! were proven once, when the contact point took the road), and a contact point keeps
//! the terms of its last cell, which a wheel moving a few millimetres per step reads
//! again and again. The answers are those of the general path, bit for bit: the same
//! operations (those of `interpolation`) on the same values.

use crate::model::grid::{prefetch_cell_far_from, prefetch_path_from, Store, VLayout};
use crate::model::road::Road;
use crate::model::tile_bounds::{inner_bound, TileBounds};
use crate::model::tiles::{half_of, read_bit, tile_of, Pin, Tiles, HALF_U, TILE_STRIDE, TILE_U, TILE_V};
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
///
/// The common case applies inside its windows, tried in turn: for a grid in memory one, the
/// road's range and its values; for a grid read in place up to [`WINDOWS`], each the cells
/// of the halves read of one pinned tile (see [`PlainGrid::enter_window`]; at first
/// without their last cross sections, see [`EDGE`]), whose values its base and `nu` then
/// address as they address a grid in memory. A point outside them takes another path,
/// which widens or moves a window. The unused windows' bounds are NaN.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlainGrid {
    windows: [Bounds; WINDOWS],
    /// The road's range of the common case: from the first cross section to the largest u
    /// whose grid fraction lies below the last cross section's, and the same across.
    road: [f64; 4],
    u_first: f64,
    u_inc: f64,
    v_first: f64,
    v_inc: f64,
    /// The tile (along, across) of each window.
    window_tiles: [(usize, usize); WINDOWS],
    /// The tiles of a grid read in place (null for a grid in memory).
    tiles: *const Tiles,
    /// Where the cells of each tile lie (the road's; empty for a grid in memory).
    bounds: *const TileBounds,
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

/// How many windows the common case tries: a contact point shared by the four wheels of
/// a car reads four tiles at a time, and two more keep the window of a tile one wheel
/// left while another still reads it (the window given up is the one entered longest ago).
pub(crate) const WINDOWS: usize = 6;

/// Cross sections at each end of what a window holds of its tile (the halves of it read).
/// A window entered at the start of that (a wheel moving on along u) leaves out those at
/// its end at first: the first lookup there widens it ([`PlainGrid::widen_window`]), and
/// its contact point asks for the next half along, some steps before the wheel enters it
/// (21 steps at 30 m/s on 1 cm cross sections, at 1 kHz).
const EDGE: usize = 64;

/// Whether the cell `iu` along lies at the end of its half of a tile (see [`EDGE`]).
pub(crate) fn near_tile_end(iu: usize) -> bool {
    iu % HALF_U >= HALF_U - EDGE
}

/// The halves along (first, last; numbered from the grid's start) that a window on the
/// tile of the cell `iu` along can hold when the tile's halves `halves` were read (see
/// [`read_bit`]): the cell's and the other one where it was read too; `None` where the
/// cell's own was not read.
fn held_halves(iu: usize, halves: u32) -> Option<(usize, usize)> {
    let (tu, h) = (iu / TILE_U, half_of(iu));
    if halves & read_bit(h) == 0 {
        return None;
    }
    let first = if halves & read_bit(0) != 0 { 0 } else { h };
    let last = if halves & read_bit(1) != 0 { 1 } else { h };
    Some((2 * tu + first, 2 * tu + last))
}

/// Where the common case applies in one window, and where the window's values lie.
#[derive(Debug, Clone, Copy)]
struct Bounds {
    /// u from, u to, v from, v to: all four NaN or none (see [`Bounds::new`]).
    range: [f64; 4],
    /// The values, long section by long section, `nu` apart: the grid in memory, or a tile
    /// rebased so that the first corner of cell (iu, iv) is at `iv * nu + iu` for every
    /// cell of the window (null for a window not set).
    z: *const f32,
}

impl Bounds {
    const NONE: Bounds = Bounds { range: [f64::NAN; 4], z: std::ptr::null() };

    /// The window of `range` (u from, u to, v from, v to) with its values at `z`; a
    /// window that holds no point where any bound is NaN.
    fn new(range: [f64; 4], z: *const f32) -> Bounds {
        match range.iter().any(|b| b.is_nan()) {
            true => Bounds { z, ..Bounds::NONE },
            false => Bounds { range, z },
        }
    }

    /// Whether (u, v) lies in the window (false for NaN). Across first, as a branch of
    /// its own (written as one condition, the compiler tests u first): the windows a
    /// contact point shared by four wheels tries before the right one are mostly those
    /// of the other wheel track, on other long sections (with a car's four wheels,
    /// 2.6 comparisons a lookup in the windows tried before the right one instead of 3.4).
    /// Each upper bound is tested as "not above", which the processor compares with the
    /// bound where it lies in memory (a NaN coordinate or window already failed the test
    /// of the lower bound, and a window's bounds are all NaN or none).
    #[inline(always)]
    fn holds(&self, u: f64, v: f64) -> bool {
        let [u_lo, u_hi, v_lo, v_hi] = self.range;
        if !(v >= v_lo) || v > v_hi {
            return false;
        }
        u >= u_lo && !(u > u_hi)
    }
}

/// Whether the road's arrays have the sizes the unchecked reads of [`PlainGrid`] rely
/// on: at least two samples along and across, `nu * nv` grid values (or records of `nv`
/// values), one channel value per reference line sample, and the index bounds the cell
/// search clamps to.
fn sizes_agree(road: &Road) -> bool {
    let (l, g) = (&road.line, &road.grid);
    let per_sample = |c: &Option<Vec<f64>>| c.as_ref().is_none_or(|c| c.len() == l.n);
    let values_agree = match &g.store {
        Store::Memory(z) => g.nu.checked_mul(g.nv) == Some(z.len()),
        Store::InPlace(p) => p.tiles.records().nu() == g.nu && p.tiles.records().nv() == g.nv,
    };
    l.n == g.nu
        && g.nu >= 2
        && g.nv >= 2
        && values_agree
        && per_sample(&l.z)
        && per_sample(&l.bank)
        && l.last_frac == (l.n - 1) as f64
        && g.last_frac == (g.nv - 1) as f64
}

impl PlainGrid {
    /// The common case of `road` evaluated with `options`. For a grid read in place the
    /// cell's values come from its tiles ([`PlainGrid::tile_terms`]), not from
    /// [`PlainGrid::terms`].
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
        let range = [
            bound(l.u_first),
            bound(inner_bound(l.u_first, l.u_last, l.u_inc, l.last_frac)),
            bound(g.v_first),
            bound(inner_bound(g.v_first, g.v_last, g.v_inc, g.last_frac)),
        ];
        // A grid read in place has no window yet.
        let mut windows = [Bounds::NONE; WINDOWS];
        if !g.is_in_place() {
            windows[0] = Bounds::new(range, g.memory_ptr());
        }
        PlainGrid {
            windows,
            window_tiles: [(usize::MAX, usize::MAX); WINDOWS],
            road: range,
            u_first: l.u_first,
            u_inc: l.u_inc,
            v_first: g.v_first,
            v_inc: g.v_inc,
            tiles: g.tiles().map_or(std::ptr::null(), std::sync::Arc::as_ptr),
            bounds: &road.tile_bounds,
            nu: if g.is_in_place() { TILE_STRIDE } else { l.n },
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
        let z = self.windows.iter().find(|w| w.holds(u, v))?.z;
        self.cell_inside(u, v, z)
    }

    /// [`PlainGrid::cell`] within the road's range (also outside the windows; its values
    /// are not at hand: see [`PlainGrid::tile_terms`]).
    #[inline]
    pub(crate) fn road_cell(&self, u: f64, v: f64) -> Option<PlainCell> {
        let [u_lo, u_hi, v_lo, v_hi] = self.road;
        if !(u >= u_lo && u <= u_hi && v >= v_lo && v <= v_hi) {
            return None;
        }
        self.cell_inside(u, v, std::ptr::null())
    }

    /// `cell` (of [`PlainGrid::road_cell`] at (u, v)) read from window 0, when the point
    /// lies in it (as after the window of its tile was entered); `None` otherwise.
    #[inline]
    pub(crate) fn in_first_window(&self, cell: PlainCell, u: f64, v: f64) -> Option<PlainCell> {
        let w = &self.windows[0];
        w.holds(u, v).then_some(PlainCell { z: w.z, ..cell })
    }

    /// The cell of a point inside the road's range of the common case, whose window's
    /// values are at `z`.
    #[inline(always)]
    fn cell_inside(&self, u: f64, v: f64, z: *const f32) -> Option<PlainCell> {
        // Inside, 0 <= fu < nu - 1 and 0 <= fv < nv - 1 (see `inner_bound`): the
        // general path's index is the truncation.
        let fu = (u - self.u_first) / self.u_inc;
        let fv = (v - self.v_first) / self.v_inc;
        // SAFETY: both fractions are finite and far below 2^63 (the bounds above).
        let (iu, iv) = unsafe { (fu.to_int_unchecked::<i64>(), fv.to_int_unchecked::<i64>()) };
        Some(PlainCell { iu: iu as usize, fu: fu - iu as f64, iv: iv as usize, fv: fv - iv as f64, v, z })
    }

    /// Where the first corner of `cell` lies in the grid's values. Only computed, never
    /// read.
    #[inline(always)]
    fn corner(&self, cell: &PlainCell) -> *const f32 {
        cell.z.wrapping_add(cell.iv.wrapping_mul(self.nu).wrapping_add(cell.iu))
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

    /// Whether the grid is read in place.
    #[inline(always)]
    pub(crate) fn in_place(&self) -> bool {
        !self.tiles.is_null()
    }

    /// Makes the tile of the cell (`iu`, `iv`) of a grid read in place, pinned as `pin`
    /// with its values at `values` and its halves `halves` read ([`Tiles::pin`]), window 0,
    /// the windows before it moving one on (the last one's tile is the caller's to hand
    /// back: `pins` holds the pins of the windows as they were, and is moved on alike).
    /// The common case then applies to the points whose cells lie in the halves of the
    /// tile read (and in the road's range; entered at their start, not yet their end: see
    /// [`EDGE`]), found exactly as [`PlainGrid::cell`] finds them, and reads their values
    /// from the tile.
    pub(crate) fn enter_window(
        &mut self,
        (iu, iv): (usize, usize),
        pin: Pin,
        values: *const f32,
        halves: u32,
        pins: &mut [Option<Pin>; WINDOWS],
    ) -> Option<Pin> {
        let (tu, tv) = tile_of(iu, iv);
        let range = match held_halves(iu, halves) {
            Some((first, last)) => {
                let range = self.halves_range((first, last), tv);
                // Entered at its start, the window leaves the end out (any bound below the
                // tile's own leaves out only points that then take another path; a NaN
                // bound stays).
                let before_end = self.u_first + ((last + 1) * HALF_U - EDGE) as f64 * self.u_inc;
                match range {
                    [u_from, u_to, v_from, v_to] if iu - first * HALF_U < EDGE && before_end < u_to => {
                        [u_from, before_end, v_from, v_to]
                    }
                    range => range,
                }
            }
            None => [f64::NAN; 4],
        };
        let z = values.wrapping_sub(tv * TILE_V * TILE_STRIDE + tu * TILE_U);
        let gone = pins[WINDOWS - 1].take();
        for k in (1..WINDOWS).rev() {
            self.windows[k] = self.windows[k - 1];
            self.window_tiles[k] = self.window_tiles[k - 1];
            pins[k] = pins[k - 1].take();
        }
        self.windows[0] = Bounds::new(range, z);
        self.window_tiles[0] = (tu, tv);
        pins[0] = Some(pin);
        gone
    }

    /// Where the cells of the halves `first..=last` along and of tile row `tv` lie: u from,
    /// u to, v from, v to (NaN beyond the grid).
    fn halves_range(&self, (first, last): (usize, usize), tv: usize) -> [f64; 4] {
        // SAFETY: the bounds belong to the road, which is alive while the contact point
        // holding this `PlainGrid` holds it.
        let bounds = unsafe { &*self.bounds };
        match (bounds.along(first), bounds.along(last), bounds.across(tv)) {
            (Some([u_from, _]), Some([_, u_to]), Some([v_from, v_to])) => [u_from, u_to, v_from, v_to],
            _ => [f64::NAN; 4],
        }
    }

    /// Removes the windows of a grid read in place (no point takes the common case until
    /// another is set).
    pub(crate) fn clear_windows(&mut self) {
        if self.in_place() {
            self.windows = [Bounds::NONE; WINDOWS];
            self.window_tiles = [(usize::MAX, usize::MAX); WINDOWS];
        }
    }

    /// `cell` (of [`PlainGrid::road_cell`] at (u, v)) read from the window of its tile when
    /// there is one and the cell's half of the tile was read (as when the window left out
    /// the end of what it held, where the cell lies, or the tile's other half was read
    /// since): the window then holds every half of its tile read. `None` otherwise.
    pub(crate) fn widen_window(&mut self, cell: PlainCell, u: f64, v: f64) -> Option<PlainCell> {
        let (tu, tv) = tile_of(cell.iu, cell.iv);
        let k = self.window_tiles.iter().position(|&t| t == (tu, tv))?;
        // SAFETY: the window's tile is pinned, so its pool is alive (the road holds it).
        let halves = unsafe { self.tiles.as_ref()? }.halves(cell.iu, cell.iv);
        let range = self.halves_range(held_halves(cell.iu, halves)?, tv);
        let w = &mut self.windows[k];
        *w = Bounds::new(range, w.z);
        w.holds(u, v).then_some(PlainCell { z: w.z, ..cell })
    }

    /// The terms of `cell`'s grid values, read from the road's grid in memory or from the
    /// window's tile.
    ///
    /// # Safety
    /// The road this `PlainGrid` was made from is alive, its window's tile (if any) is
    /// pinned, and `cell` came from [`PlainGrid::cell`] of this `PlainGrid`: then
    /// [`sizes_agree`] held and `cell.iu <= nu - 2`, `cell.iv <= nv - 2` (in memory), or the
    /// cell lies in the window's tile, so every read is inside its array.
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

    /// The terms of `cell`'s grid values, read from the tiles of the road's grid read in
    /// place (a tile not yet present is read from the file); `None` where the file cannot
    /// be read (the general path then tells why).
    ///
    /// # Safety
    /// The road this `PlainGrid` was made from is alive, and `cell` came from
    /// [`PlainGrid::cell`] of this `PlainGrid`.
    #[inline]
    pub(crate) unsafe fn tile_terms(&self, cell: &PlainCell) -> Option<CellTerms> {
        // SAFETY: the tiles belong to the road, which is alive (the contract above).
        let [c00, c10, c01, c11] = unsafe { self.tiles.as_ref()?.corners(cell.iu, cell.iv) }?;
        Some(CellTerms { iu: cell.iu, iv: cell.iv, corners: corner_terms(c00, c10, c01, c11) })
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
    /// Where the values of the cell's window lie (see [`Bounds`]).
    z: *const f32,
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

impl PlainCell {
    /// The cell's interval indices along and across.
    #[inline]
    pub(crate) fn indices(&self) -> (usize, usize) {
        (self.iu, self.iv)
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    const RANGE: [f64; 4] = [1.0, 2.0, -1.0, 1.0];

    #[test]
    fn a_window_holds_its_bounds_and_nothing_beyond() {
        let w = Bounds::new(RANGE, std::ptr::null());
        let cases = [
            (1.0, -1.0, true),
            (2.0, 1.0, true),
            (1.5, 0.0, true),
            (2f64.next_up(), 0.0, false),
            (1f64.next_down(), 0.0, false),
            (1.5, 1f64.next_up(), false),
            (1.5, (-1f64).next_down(), false),
            (f64::NAN, 0.0, false),
            (1.5, f64::NAN, false),
            (f64::INFINITY, 0.0, false),
            (1.5, f64::NEG_INFINITY, false),
        ];
        for (u, v, inside) in cases {
            assert_eq!(w.holds(u, v), inside, "({u}, {v})");
        }
    }

    #[test]
    fn a_window_with_a_nan_bound_holds_nothing() {
        for k in 0..4 {
            let mut range = RANGE;
            range[k] = f64::NAN;
            let w = Bounds::new(range, std::ptr::null());
            for (u, v) in [(1.5, 0.0), (1e300, 0.0), (-1e300, 0.0), (1.5, 1e300), (1.5, -1e300)] {
                assert!(!w.holds(u, v), "bound {k} NaN holds ({u}, {v})");
            }
        }
    }
}
