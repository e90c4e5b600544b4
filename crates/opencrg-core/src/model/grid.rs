//! The elevation grid: single-precision z values over (u index, v index), with the
//! positions of the long sections; the values in memory, or read in place from a binary
//! file (see `in_place` and `tiles`).

use crate::base::error::Error;
use crate::base::settings::NanMode;
use crate::model::in_place::{RowWalker, ValueOp};
use crate::model::nan_borders::fill_row_nans;
use crate::model::tiles::Tiles;
use std::ops::{Range, RangeInclusive};
use std::sync::{Arc, OnceLock};

/// How the v positions of the long sections were defined.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VLayout {
    /// `D:long section N`: a regular grid from the header's right border and increment.
    Indexed,
    /// `D:long section at v = X`: explicit positions, evaluated by search.
    Explicit,
}

/// Where a grid's values are.
#[derive(Debug)]
pub(crate) enum Store {
    /// In memory, NaN where the file has none, long section by long section (`iv * nu + iu`).
    Memory(Vec<f32>),
    /// Read in place from a binary file, through a pool of decoded tiles.
    InPlace(InPlace),
}

/// The values of a grid read in place.
#[derive(Debug)]
pub(crate) struct InPlace {
    pub(crate) tiles: Arc<Tiles>,
    /// Every value, read when [`Grid::values`] is first asked for.
    whole: OnceLock<Vec<f32>>,
}

impl InPlace {
    /// Values read in place through `tiles`.
    pub(crate) fn new(tiles: Tiles) -> Self {
        InPlace { tiles: Arc::new(tiles), whole: OnceLock::new() }
    }
}

/// A part of a grid read in place (some cross sections, some long sections), to make a
/// road of (see [`Grid::part`]): its values are read from the same file where they are
/// asked for.
#[derive(Debug)]
pub struct GridPart {
    pub(crate) tiles: Tiles,
}

/// Elevation grid: single-precision z values at (cross section `iu`, long section `iv`).
///
/// In memory the values are stored long section by long section (`iv * nu + iu`), as
/// the reference library keeps them: a wheel moving along the road reads neighbouring
/// values, and a lookup anywhere touches two runs of memory (the two long sections of
/// its cell), as a cross-section-major layout would. A grid read in place (see
/// [`Grid::is_in_place`]) reads them from its file where they are asked for.
/// [`Grid::at`] and [`Grid::rows`] read either; [`Grid::in_memory`] gives the values of
/// a grid in memory; [`Grid::values`], [`Grid::long_section`] and
/// [`Grid::cross_section`] read a grid in place whole first.
#[derive(Debug)]
pub struct Grid {
    /// Number of cross sections (u samples).
    pub nu: usize,
    /// Number of long sections (v samples).
    pub nv: usize,
    /// The values.
    pub(crate) store: Store,
    /// Offset added to every z value (changed by scaling and relocation).
    pub mean: f64,
    /// v positions of the long sections, increasing.
    pub v: Vec<f64>,
    /// The v range used for border decisions (header values, as the reference keeps them).
    pub v_first: f64,
    /// Upper end of the v range used for border decisions.
    pub v_last: f64,
    /// v increment (0 when the long sections are not evenly spaced).
    pub v_inc: f64,
    /// How the v positions were defined.
    pub layout: VLayout,
    /// Where the v search starts, at evenly spaced positions over `v_first..v_last`
    /// (empty when that range is empty); see [`Grid::v_interval`].
    pub(crate) v_table: Vec<usize>,
    /// `nv - 1` as a double: the largest grid fraction across the road (set where the
    /// grid is made; `nv` never changes).
    pub(crate) last_frac: f64,
}

/// The banking's v at `v` where banking acts within `range` (right, left): beyond it, v
/// counts as its border.
pub(crate) fn bank_v(v: f64, range: (f64, f64)) -> f64 {
    if v < range.0 {
        range.0
    } else if v > range.1 {
        range.1
    } else {
        v
    }
}

impl Grid {
    /// The v range of the long sections themselves: what `LONG_SECTION_V_RIGHT` and
    /// `_LEFT` must say of this grid (the range the road was read with may differ: a
    /// file without them is read with both 0, and the reference acts on that).
    pub fn sections_range(&self) -> (f64, f64) {
        (self.v[0], self.v[self.nv - 1])
    }
}

/// How far ahead along u (in values) a lookup also asks for the grid: the next cache line.
const AHEAD: usize = 16;

/// Entries of the v search table (as many as the reference library's).
const V_TABLE_SIZE: usize = 200;

/// `(size_t) x` as the reference library gets it on x86-64: truncation, and a huge
/// index for negative values, NaN and values out of range.
fn c_index(x: f64) -> usize {
    let t = x.trunc();
    // 2^63: the first value the conversion cannot hold.
    if (0.0..9_223_372_036_854_775_808.0).contains(&t) {
        t as usize
    } else {
        usize::MAX
    }
}

/// Asks the processor to start loading the values of the cell whose first corner is at
/// `p` in a grid whose long sections are `nu` values apart, a run of each of its two
/// long sections, into the second-level cache: for a lookup that comes many others
/// later (see `memory::prefetch_far`). The address is only computed, never read.
#[inline(always)]
pub(crate) fn prefetch_cell_far_from(p: *const f32, nu: usize) {
    crate::base::memory::prefetch_far(p);
    crate::base::memory::prefetch_far(p.wrapping_add(nu));
}

/// Asks the processor to start loading what a wheel moving along the road reads after
/// the cell whose first corner is at `p` in a grid whose long sections are `nu` values
/// apart: the following run of both long sections along u, and the long section beyond
/// the cell's nearer side across it (`upper`: the side of the second long section). Not
/// the cell itself: the lookup reads it at once. The addresses are only computed, never
/// read.
#[inline(always)]
pub(crate) fn prefetch_path_from(p: *const f32, nu: usize, upper: bool) {
    crate::base::memory::prefetch(p.wrapping_add(AHEAD));
    crate::base::memory::prefetch(p.wrapping_add(nu + AHEAD));
    crate::base::memory::prefetch(if upper { p.wrapping_add(2 * nu) } else { p.wrapping_sub(nu) });
}

impl Clone for Grid {
    fn clone(&self) -> Self {
        let store = match &self.store {
            Store::Memory(z) => Store::Memory(crate::base::memory::large_copy(z)),
            Store::InPlace(p) => Store::InPlace(InPlace { tiles: p.tiles.clone(), whole: OnceLock::new() }),
        };
        Grid { store, v: self.v.clone(), v_table: self.v_table.clone(), ..*self }
    }
}

impl PartialEq for Grid {
    /// Grids are equal when their sizes, positions and values are (a grid in place and
    /// one in memory with the same values too; a grid in place is then read whole).
    fn eq(&self, other: &Grid) -> bool {
        let same_values = match (&self.store, &other.store) {
            (Store::InPlace(a), Store::InPlace(b)) if Arc::ptr_eq(&a.tiles, &b.tiles) => true,
            _ => {
                let (a, b) = (self.values(), other.values());
                a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
            }
        };
        (self.nu, self.nv, self.mean, &self.v, self.v_first, self.v_last, self.v_inc, self.layout)
            == (other.nu, other.nv, other.mean, &other.v, other.v_first, other.v_last, other.v_inc, other.layout)
            && same_values
    }
}

impl Grid {
    /// Where the values of a grid in memory start (null for a grid in place: the
    /// prefetches aimed from it then ask for memory nobody reads, which costs nothing).
    #[inline(always)]
    pub(crate) fn memory_ptr(&self) -> *const f32 {
        match &self.store {
            Store::Memory(z) => z.as_ptr(),
            Store::InPlace(_) => std::ptr::null(),
        }
    }

    /// The values of the cell whose first corner is (`iu`, `iv`): (iu, iv), (iu + 1, iv),
    /// (iu, iv + 1), (iu + 1, iv + 1); `None` when that cell is not in the grid. A grid in
    /// place that cannot read them answers NaN (its [`Grid::fault`] tells why).
    #[inline(always)]
    pub(crate) fn corners(&self, iu: usize, iv: usize) -> Option<[f32; 4]> {
        match &self.store {
            Store::Memory(z) => {
                let cell = z.get(iv.wrapping_mul(self.nu).wrapping_add(iu)..)?.get(..self.nu.wrapping_add(2))?;
                let (&[c00, c10], &[c01, c11]) = (cell.first_chunk::<2>()?, cell.last_chunk::<2>()?);
                Some([c00, c10, c01, c11])
            }
            Store::InPlace(p) => {
                if iu.wrapping_add(1) >= self.nu || iv.wrapping_add(1) >= self.nv {
                    return None;
                }
                Some(p.tiles.corners(iu, iv).unwrap_or([f32::NAN; 4]))
            }
        }
    }

    /// Whether the values are read in place from the file (else they are in memory).
    pub fn is_in_place(&self) -> bool {
        matches!(self.store, Store::InPlace(_))
    }

    /// The tile pool of a grid read in place.
    pub(crate) fn tiles(&self) -> Option<&Arc<Tiles>> {
        match &self.store {
            Store::InPlace(p) => Some(&p.tiles),
            Store::Memory(_) => None,
        }
    }

    /// Why a grid read in place could not read its file (it was cut short or changed since
    /// it was opened), naming the file; `None` for a grid in memory and while all is well.
    pub fn fault(&self) -> Option<Error> {
        let tiles = self.tiles()?;
        let fault =
            tiles.fault().or_else(|| tiles.records().faulted().then_some(crate::base::mapped_file::Fault::Cut))?;
        Some(Error::reading(tiles.records().path(), fault.into_io()))
    }

    /// The cross sections `us` and long sections `vs` of a grid read in place whose values
    /// are as the file gives them (no modifier has acted on them), as a part a road can be
    /// made of without reading them; `None` otherwise (or where the ranges leave the grid).
    pub fn part(&self, us: RangeInclusive<usize>, vs: RangeInclusive<usize>) -> Option<GridPart> {
        let tiles = self.tiles().filter(|t| t.ops().is_empty())?;
        let records = tiles.records().part(us, vs)?;
        Some(GridPart { tiles: Tiles::new(Arc::new(records), Vec::new(), tiles.capacity()) })
    }

    /// Halves of tiles a grid read in place has read from its file so far (0 in memory;
    /// a tile is read half by half).
    pub fn tiles_read(&self) -> usize {
        self.tiles().map_or(0, |t| t.fills())
    }

    /// The z value at (u index, v index), without the mean offset (NaN where a grid read
    /// in place cannot read it).
    #[inline]
    pub fn at(&self, iu: usize, iv: usize) -> f32 {
        match &self.store {
            Store::Memory(z) => z[iv * self.nu + iu],
            Store::InPlace(_) => {
                assert!(iu < self.nu && iv < self.nv, "value ({iu}, {iv}) of {} x {}", self.nu, self.nv);
                let (cu, cv) = (iu.min(self.nu - 2), iv.min(self.nv - 2));
                let c = self.corners(cu, cv).unwrap_or([f32::NAN; 4]);
                c[usize::from(iu > cu) + 2 * usize::from(iv > cv)]
            }
        }
    }

    /// The values when they are held in memory (long section after long section,
    /// `iv * nu + iu`); `None` for a grid read in place.
    pub fn in_memory(&self) -> Option<&[f32]> {
        match &self.store {
            Store::Memory(z) => Some(z),
            Store::InPlace(_) => None,
        }
    }

    /// The values of long section `iv`, one per cross section.
    pub fn long_section(&self, iv: usize) -> &[f32] {
        &self.values()[iv * self.nu..(iv + 1) * self.nu]
    }

    /// The values of cross section `iu`, one per long section, right to left.
    pub fn cross_section(&self, iu: usize) -> impl ExactSizeIterator<Item = f32> + '_ {
        assert!(iu < self.nu, "cross section {iu} of {}", self.nu);
        let mut row = vec![0.0; self.nv];
        let read = self.rows(iu..iu + 1, |_, values| {
            row.copy_from_slice(values);
            Ok::<(), Error>(())
        });
        if read.is_err() {
            row.fill(f32::NAN);
        }
        row.into_iter()
    }

    /// Every value, long section after long section (`iv * nu + iu`). A grid read in
    /// place is read whole into memory the first time (NaN where it cannot be read), and
    /// kept: prefer [`Grid::rows`] for it.
    pub fn values(&self) -> &[f32] {
        match &self.store {
            Store::Memory(z) => z,
            Store::InPlace(p) => p.whole.get_or_init(|| self.read_whole()),
        }
    }

    /// Every value of a grid read in place, read from its file (NaN where it cannot be).
    fn read_whole(&self) -> Vec<f32> {
        let mut values = GridValues::new(self.nv, self.nu);
        let read = self.rows(0..self.nu, |_, row| {
            values.push(row.iter().copied());
            Ok::<(), Error>(())
        });
        let (mut z, _) = values.finish();
        if read.is_err() {
            z.fill(f32::NAN);
        }
        z
    }

    /// A copy of every value, long section after long section (`iv * nu + iu`); a grid
    /// read in place is read whole for it (NaN where it cannot be read).
    pub(crate) fn copied_values(&self) -> Vec<f32> {
        match &self.store {
            Store::Memory(z) => crate::base::memory::large_copy(z),
            Store::InPlace(p) => {
                p.whole.get().map_or_else(|| self.read_whole(), |z| crate::base::memory::large_copy(z))
            }
        }
    }

    /// Calls `f` with each cross section of `range` in turn (its index and its values,
    /// right to left), without the mean offset: from memory, or read from the file of a
    /// grid in place one record after another (the pages read handed back, so that a grid
    /// larger than memory streams through). Stops at the first error: `f`'s, or the one
    /// naming the file of a grid in place that could not be read (what was handed to `f`
    /// since the last check may be wrong then: the file is checked every 4096 records).
    pub fn rows<E: From<Error>>(
        &self,
        range: Range<usize>,
        mut f: impl FnMut(usize, &[f32]) -> std::result::Result<(), E>,
    ) -> std::result::Result<(), E> {
        let range = range.start.min(self.nu)..range.end.min(self.nu);
        match &self.store {
            Store::Memory(z) => {
                let mut row = vec![0.0f32; self.nv];
                for iu in range {
                    for (value, &z) in row.iter_mut().zip(z.iter().skip(iu).step_by(self.nu)) {
                        *value = z;
                    }
                    f(iu, &row)?;
                }
                Ok(())
            }
            Store::InPlace(p) => {
                let records = p.tiles.records();
                const BATCH: usize = 4096;
                let mut walker = RowWalker::new(records, p.tiles.ops());
                let mut start = range.start;
                while start < range.end {
                    let end = (start + BATCH).min(range.end);
                    for iu in start..end {
                        f(iu, walker.row(iu))?;
                    }
                    records.check().map_err(|fault| Error::reading(records.path(), fault.into_io()))?;
                    records.release(start, end);
                    start = end;
                }
                Ok(())
            }
        }
    }

    /// Index of the v interval for position `v` (0 to `nv - 2`), found as the reference
    /// library finds it: a bisection between bounds taken from a table built over the
    /// header's v range. Where the long sections lie inside that range (every
    /// consistent file) this is the interval holding `v`; where the header's range
    /// disagrees with the sections, the bounds (and so the answer) are the reference's.
    #[inline]
    pub fn v_interval(&self, v: f64) -> usize {
        let (mut lo, mut hi) = (0, self.nv - 1);
        let t = &self.v_table;
        if !t.is_empty() {
            let last = t.len() - 1;
            let slot = if v > self.v_first {
                c_index((v - self.v_first) / (self.v_last - self.v_first) * last as f64).min(last)
            } else {
                0
            };
            let mut center = t[slot];
            if self.v[center] <= v {
                center += 1;
            }
            let center = center.min(last);
            if slot > 0 {
                lo = t[slot - 1];
                if lo >= center && lo > 0 {
                    lo -= 1;
                }
            }
            if slot < last {
                hi = t[slot + 1];
                if hi <= center && hi < self.nv - 1 {
                    hi += 1;
                }
            }
        }
        self.bisect(v, lo, hi)
    }

    /// Narrows `lo..hi` to one interval: `lo` moves up past sections at or below `v`,
    /// `hi` down to sections above it.
    #[inline]
    fn bisect(&self, v: f64, mut lo: usize, mut hi: usize) -> usize {
        loop {
            let mid = (lo + hi) / 2;
            if mid <= lo {
                return lo;
            }
            match self.v.get(mid) {
                Some(&at) if v < at => hi = mid,
                _ => lo = mid,
            }
        }
    }

    /// Builds the table [`Grid::v_interval`] starts from: for evenly spaced positions
    /// over `v_first..v_last`, the interval a full bisection finds.
    pub(crate) fn build_v_table(&mut self) {
        let range = self.v_last - self.v_first;
        self.v_table = if range == 0.0 || self.nv < 2 {
            Vec::new()
        } else {
            (0..V_TABLE_SIZE)
                .map(|i| self.bisect(self.v_first + i as f64 * range / (V_TABLE_SIZE - 1) as f64, 0, self.nv - 1))
                .collect()
        };
    }

    /// Adds an operation on every value to a grid read in place: its values are read
    /// anew through it from now on.
    fn push_op(&mut self, op: ValueOp) {
        if let Store::InPlace(p) = &mut self.store {
            *p = InPlace::new(p.tiles.with_op(op));
        }
    }

    /// Folds the mean offset into the stored values (as the reference does when it
    /// prepares the data again).
    pub(crate) fn fold_mean(&mut self) {
        if self.mean != 0.0 {
            let add = self.mean as f32;
            match &mut self.store {
                Store::Memory(z) => z.iter_mut().filter(|z| !z.is_nan()).for_each(|z| *z += add),
                Store::InPlace(_) => self.push_op(ValueOp::Add(add)),
            }
            self.mean = 0.0;
        }
    }

    /// Multiplies every value (and the mean offset) by `factor`.
    pub(crate) fn scale(&mut self, factor: f64) {
        let f = factor as f32;
        match &mut self.store {
            Store::Memory(z) => z.iter_mut().for_each(|z| *z *= f),
            Store::InPlace(_) => self.push_op(ValueOp::Scale(f)),
        }
        self.mean *= factor;
    }

    /// Replaces NaNs at the borders of every cross section; returns how many were found
    /// (`None` for a grid read in place, whose values are handled where they are read).
    ///
    /// Scanning from the right border leftwards, a NaN takes its right neighbour's
    /// value (or `offset` for [`NanMode::SetZero`]); the first value copied in a
    /// pass gets `offset` added. Then the same from the left border rightwards.
    pub(crate) fn fill_nans(&mut self, mode: NanMode, offset: f64) -> Option<usize> {
        let (nu, nv) = (self.nu, self.nv);
        let z = match &mut self.store {
            Store::Memory(z) => z,
            Store::InPlace(_) => {
                self.push_op(ValueOp::Fill(mode, offset as f32));
                return None;
            }
        };
        if nu == 0 || nv == 0 {
            return Some(0);
        }
        // Which cross sections hold a NaN, read long section by long section in storage order.
        let mut with_nan = vec![false; nu];
        for long in z.chunks_exact(nu) {
            for (flag, z) in with_nan.iter_mut().zip(long) {
                *flag |= z.is_nan();
            }
        }
        let mut row = vec![0.0f32; nv];
        let mut total = 0;
        // Carried from one cross section's second pass into the next one's first, as the
        // reference carries it; a cross section without NaN leaves it false.
        let mut offset_applied = false;
        for (iu, _) in with_nan.iter().enumerate().filter(|(_, &nan)| nan) {
            if iu > 0 && !with_nan[iu - 1] {
                offset_applied = false;
            }
            for (value, z) in row.iter_mut().zip(z.iter().skip(iu).step_by(nu)) {
                *value = *z;
            }
            total += fill_row_nans(&mut row, mode, offset as f32, &mut offset_applied);
            for (z, value) in z.iter_mut().skip(iu).step_by(nu).zip(&row) {
                *z = *value;
            }
        }
        Some(total)
    }
}

/// The values of a grid as a file gives them, cross section by cross section, stored
/// long section by long section as they arrive (see [`Grid`]).
pub(crate) struct GridValues {
    z: Vec<f32>,
    nv: usize,
    /// Room per long section.
    stride: usize,
    /// Cross sections so far.
    nu: usize,
}

impl GridValues {
    /// Room for `capacity` cross sections of `nv` values (more are taken when they come).
    pub(crate) fn new(nv: usize, capacity: usize) -> Self {
        let stride = capacity.max(2);
        GridValues { z: crate::base::memory::large_zeroed(nv.saturating_mul(stride)), nv, stride, nu: 0 }
    }

    /// Adds the next cross section (its values right to left; missing ones stay 0).
    #[inline]
    pub(crate) fn push(&mut self, values: impl Iterator<Item = f32>) {
        if self.nu == self.stride {
            self.grow();
        }
        let at = self.nu;
        for (long, value) in self.z.chunks_exact_mut(self.stride).zip(values) {
            long[at] = value;
        }
        self.nu += 1;
    }

    #[cold]
    fn grow(&mut self) {
        let stride = self.stride.saturating_mul(2);
        let mut z = crate::base::memory::large_zeroed(self.nv.saturating_mul(stride));
        for (new, old) in z.chunks_exact_mut(stride).zip(self.z.chunks_exact(self.stride)) {
            new[..self.nu].copy_from_slice(&old[..self.nu]);
        }
        (self.z, self.stride) = (z, stride);
    }

    /// The values (`iv * nu + iu`) and the number of cross sections.
    pub(crate) fn finish(mut self) -> (Vec<f32>, usize) {
        let (nu, nv) = (self.nu, self.nv);
        if self.stride != nu {
            for iv in 1..nv {
                self.z.copy_within(iv * self.stride..iv * self.stride + nu, iv * nu);
            }
            self.z.truncate(nu * nv);
            if self.z.capacity() > nu * nv + nu * nv / 4 {
                self.z = crate::base::memory::large_copy(&self.z);
            }
        }
        (self.z, nu)
    }
}

/// What the elevation lookup needs to start fetching grid memory before the exact
/// cell is known: reciprocals of the increments (a multiplication is quicker than
/// the division the exact index takes; the estimate only aims a prefetch), and where the
/// values lie.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PrefetchHint {
    inv_u_inc: f64,
    inv_v_inc: f64,
    /// The first value in memory (for a grid read in place, or an uneven one, a value
    /// of this program's own with both reciprocals 0: the prefetch then asks for memory
    /// at hand, never for an address nothing maps, whose translation alone costs).
    base: *const f32,
}

// SAFETY: the pointer is only used to aim prefetches, never read.
unsafe impl Send for PrefetchHint {}
// SAFETY: as for `Send`.
unsafe impl Sync for PrefetchHint {}

/// What a hint that aims nowhere asks the processor to load.
static AT_HAND: [f32; 16] = [0.0; 16];

impl Default for PrefetchHint {
    fn default() -> Self {
        PrefetchHint { inv_u_inc: 0.0, inv_v_inc: 0.0, base: AT_HAND.as_ptr() }
    }
}

impl PrefetchHint {
    /// The hint for a grid whose cross sections are `u_inc` apart (none for an uneven grid
    /// or one read in place).
    pub(crate) fn new(u_inc: f64, g: &Grid) -> Self {
        match (g.layout, g.in_memory()) {
            (VLayout::Indexed, Some(z)) => {
                PrefetchHint { inv_u_inc: 1.0 / u_inc, inv_v_inc: 1.0 / g.v_inc, base: z.as_ptr() }
            }
            _ => PrefetchHint::default(),
        }
    }

    /// Asks the processor to start loading the grid cells around (u, v), some 20
    /// cycles before the exact index is known: worth it for lookups at random
    /// places, which miss the caches. A wrong estimate (or a stale hint) only loads
    /// other memory; nothing is read.
    #[inline(always)]
    pub(crate) fn prefetch(&self, g: &Grid, u_first: f64, u: f64, v: f64) {
        let (eu, ev) = ((u - u_first) * self.inv_u_inc, (v - g.v_first) * self.inv_v_inc);
        // The upper half of a cell is where twice the estimate truncates to an odd number.
        let upper = crate::base::memory::rough_index(2.0 * ev) & 1 == 1;
        let (iu, iv) = (crate::base::memory::rough_index(eu), crate::base::memory::rough_index(ev));
        let p = self.base.wrapping_add(iv.wrapping_mul(g.nu).wrapping_add(iu));
        crate::base::memory::prefetch(p);
        crate::base::memory::prefetch(p.wrapping_add(g.nu));
        prefetch_path_from(p, g.nu, upper);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grid of the given cross sections.
    fn grid(rows: Vec<f32>, nv: usize) -> Grid {
        let nu = rows.len() / nv;
        let mut values = GridValues::new(nv, 1);
        for row in rows.chunks_exact(nv) {
            values.push(row.iter().copied());
        }
        let (z, _) = values.finish();
        Grid {
            nu,
            nv,
            store: Store::Memory(z),
            mean: 0.0,
            v: (0..nv).map(|i| i as f64).collect(),
            v_first: 0.0,
            v_last: (nv - 1) as f64,
            v_inc: 1.0,
            layout: VLayout::Indexed,
            v_table: Vec::new(),
            last_frac: (nv - 1) as i64 as f64,
        }
    }

    #[test]
    fn nan_borders_take_the_last_value() {
        let n = f32::NAN;
        let mut g = grid(vec![n, n, 1.0, 2.0, n], 5);
        assert_eq!(g.fill_nans(NanMode::KeepLast, 0.0), Some(4), "both passes count");
        assert_eq!(g.cross_section(0).collect::<Vec<_>>(), vec![1.0, 1.0, 1.0, 2.0, 2.0]);
        let mut g = grid(vec![n, 1.0, n], 3);
        g.fill_nans(NanMode::SetZero, 5.0);
        assert_eq!(g.cross_section(0).collect::<Vec<_>>(), vec![5.0, 1.0, 5.0]);
    }

    /// The offset goes to the first value copied, and that mark carries from one cross
    /// section's second pass into the next one's first, but not across a cross section
    /// without NaN: the same as filling every cross section in turn.
    #[test]
    fn nan_offsets_carry_as_in_a_plain_pass_over_every_cross_section() {
        let n = f32::NAN;
        let rows = vec![
            n, 1.0, 2.0, n, // both passes copy, the mark stays set
            n, 3.0, n, 4.0, // first pass copies with the mark still set
            5.0, 6.0, 7.0, 8.0, // no NaN: clears the mark
            9.0, n, 10.0, 11.0, //
            n, n, n, n, // nothing to copy
        ];
        for mode in [NanMode::KeepLast, NanMode::SetZero, NanMode::Keep] {
            let mut g = grid(rows.clone(), 4);
            let found = g.fill_nans(mode, 0.5);
            let (mut expected, mut mark, mut count) = (rows.clone(), false, 0);
            for row in expected.chunks_exact_mut(4) {
                count += fill_row_nans(row, mode, 0.5, &mut mark);
            }
            assert_eq!(found, Some(count), "{mode:?}");
            let got: Vec<f32> = (0..g.nu).flat_map(|iu| g.cross_section(iu).collect::<Vec<_>>()).collect();
            assert_eq!(format!("{got:?}"), format!("{expected:?}"), "{mode:?}");
        }
    }

    /// Cross sections pushed beyond the first guess of their number, and fewer than it,
    /// land in long-section order.
    #[test]
    fn values_are_stored_long_section_by_long_section() {
        for capacity in [1, 3, 7, 100] {
            let mut values = GridValues::new(3, capacity);
            for iu in 0..7 {
                values.push((0..3).map(|iv| (10 * iu + iv) as f32));
            }
            let (z, nu) = values.finish();
            assert_eq!(nu, 7);
            let expected: Vec<f32> = (0..3).flat_map(|iv| (0..7).map(move |iu| (10 * iu + iv) as f32)).collect();
            assert_eq!(z, expected, "capacity {capacity}");
        }
    }

    #[test]
    fn v_interval_search() {
        let mut g = grid(vec![0.0; 4], 4);
        g.build_v_table();
        assert_eq!(g.v_table.len(), V_TABLE_SIZE);
        assert_eq!(g.v_interval(-1.0), 0);
        assert_eq!(g.v_interval(0.0), 0);
        assert_eq!(g.v_interval(1.5), 1);
        assert_eq!(g.v_interval(3.0), 2);
        assert_eq!(g.v_interval(9.0), 2);
    }
}
