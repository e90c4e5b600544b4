//! The elevation grid: single-precision z values over (u index, v index), with the
//! positions of the long sections.

use crate::settings::NanMode;

/// How the v positions of the long sections were defined.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VLayout {
    /// `D:long section N`: a regular grid from the header's right border and increment.
    Indexed,
    /// `D:long section at v = X`: explicit positions, evaluated by search.
    Explicit,
}

/// Elevation grid stored cross section by cross section (`z[iu * nv + iv]`).
#[derive(Debug, PartialEq)]
pub struct Grid {
    /// Number of cross sections (u samples).
    pub nu: usize,
    /// Number of long sections (v samples).
    pub nv: usize,
    /// z values, NaN where the file has none.
    pub z: Vec<f32>,
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
}

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

impl Clone for Grid {
    fn clone(&self) -> Self {
        Grid { z: crate::memory::large_copy(&self.z), v: self.v.clone(), v_table: self.v_table.clone(), ..*self }
    }
}

impl Grid {
    /// Asks the processor to start loading the values of the cell whose first corner
    /// is (`iu`, `iv`): two rows. The address is only computed, never read.
    #[inline(always)]
    pub(crate) fn prefetch_cell(&self, iu: usize, iv: usize) {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
            let p = self.z.as_ptr().wrapping_add(iu.wrapping_mul(self.nv).wrapping_add(iv));
            // SAFETY: a prefetch never faults and reads nothing the program sees; the
            // address is computed with wrapping arithmetic and never dereferenced.
            unsafe {
                _mm_prefetch(p.cast(), _MM_HINT_T0);
                _mm_prefetch(p.wrapping_add(self.nv).cast(), _MM_HINT_T0);
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = (iu, iv);
    }

    /// The z value at (u index, v index).
    #[inline]
    pub fn at(&self, iu: usize, iv: usize) -> f32 {
        self.z[iu * self.nv + iv]
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

    /// Folds the mean offset into the stored values (as the reference does when it
    /// prepares the data again).
    pub(crate) fn fold_mean(&mut self) {
        if self.mean != 0.0 {
            let add = self.mean as f32;
            for z in self.z.iter_mut().filter(|z| !z.is_nan()) {
                *z += add;
            }
            self.mean = 0.0;
        }
    }

    /// Multiplies every value (and the mean offset) by `factor`.
    pub(crate) fn scale(&mut self, factor: f64) {
        let f = factor as f32;
        for z in self.z.iter_mut() {
            *z *= f;
        }
        self.mean *= factor;
    }

    /// Replaces NaNs at the borders of every cross section; returns how many were found.
    ///
    /// Scanning from the right border leftwards, a NaN takes its right neighbour's
    /// value (or `offset` for [`NanMode::SetZero`]); the first value copied in a
    /// pass gets `offset` added. Then the same from the left border rightwards.
    pub(crate) fn fill_nans(&mut self, mode: NanMode, offset: f64) -> usize {
        let nv = self.nv;
        let off = offset as f32;
        let mut total = 0;
        let mut offset_applied = false;
        for row in self.z.chunks_exact_mut(nv) {
            let mut found = 0;
            for v in 1..nv {
                if row[v].is_nan() {
                    found += 1;
                    match mode {
                        NanMode::SetZero => row[v] = off,
                        NanMode::KeepLast => {
                            row[v] = row[v - 1];
                            if !row[v].is_nan() && !offset_applied {
                                row[v] += off;
                                offset_applied = true;
                            }
                        }
                        NanMode::Keep => {}
                    }
                }
            }
            offset_applied = false;
            for v in (1..nv).rev() {
                if row[v - 1].is_nan() && !row[v].is_nan() {
                    found += 1;
                    match mode {
                        NanMode::SetZero => row[v - 1] = off,
                        NanMode::KeepLast => {
                            row[v - 1] = row[v];
                            if !offset_applied {
                                row[v - 1] += off;
                                offset_applied = true;
                            }
                        }
                        NanMode::Keep => {}
                    }
                }
            }
            total += found;
        }
        total
    }
}

/// What the elevation lookup needs to start fetching grid memory before the exact
/// cell is known: reciprocals of the increments (a multiplication is quicker than
/// the division the exact index takes; the estimate only aims a prefetch).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct PrefetchHint {
    inv_u_inc: f64,
    inv_v_inc: f64,
}

impl PrefetchHint {
    /// The hint for a grid whose cross sections are `u_inc` apart (none for an uneven grid).
    pub(crate) fn new(u_inc: f64, g: &Grid) -> Self {
        match g.layout {
            VLayout::Indexed => PrefetchHint { inv_u_inc: 1.0 / u_inc, inv_v_inc: 1.0 / g.v_inc },
            VLayout::Explicit => PrefetchHint::default(),
        }
    }

    /// Asks the processor to start loading the grid cells around (u, v), some 20
    /// cycles before the exact index is known: worth it for lookups at random
    /// places, which miss the caches. A wrong estimate (or a stale hint) only loads
    /// other memory; nothing is read.
    #[inline(always)]
    pub(crate) fn prefetch(&self, g: &Grid, u_first: f64, u: f64, v: f64) {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::{_mm_cvttsd_si64, _mm_set_sd};
            let (eu, ev) = ((u - u_first) * self.inv_u_inc, (v - g.v_first) * self.inv_v_inc);
            // SAFETY: SSE2 is part of every x86_64 target. The conversions truncate
            // (out of range gives some far index: harmless, unlike the work Rust's
            // saturating `as` does, as the prefetch reads nothing).
            let (iu, iv) = unsafe { (_mm_cvttsd_si64(_mm_set_sd(eu)), _mm_cvttsd_si64(_mm_set_sd(ev))) };
            g.prefetch_cell(iu as usize, iv as usize);
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = (g, u_first, u, v);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(z: Vec<f32>, nv: usize) -> Grid {
        let nu = z.len() / nv;
        Grid {
            nu,
            nv,
            z,
            mean: 0.0,
            v: (0..nv).map(|i| i as f64).collect(),
            v_first: 0.0,
            v_last: (nv - 1) as f64,
            v_inc: 1.0,
            layout: VLayout::Indexed,
            v_table: Vec::new(),
        }
    }

    #[test]
    fn nan_borders_take_the_last_value() {
        let n = f32::NAN;
        let mut g = grid(vec![n, n, 1.0, 2.0, n], 5);
        assert_eq!(g.fill_nans(NanMode::KeepLast, 0.0), 4, "both passes count");
        assert_eq!(g.z, vec![1.0, 1.0, 1.0, 2.0, 2.0]);
        let mut g = grid(vec![n, 1.0, n], 3);
        g.fill_nans(NanMode::SetZero, 5.0);
        assert_eq!(g.z, vec![5.0, 1.0, 5.0]);
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
