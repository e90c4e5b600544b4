//! A grid read in place: where its values lie in a binary file (record after record,
//! one per cross section, big-endian), and the operations the modifiers asked for since
//! it was opened (scaling, the offset folded in, NaN handling), replayed on each value
//! as it is read, with the single-precision arithmetic a grid in memory gets, so that
//! both give the same values to the last bit.

use crate::base::mapped_file::{Fault, MappedFile};
use crate::base::settings::NanMode;
use crate::model::nan_borders::fill_row_nans;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Where the grid's values lie in a binary file.
#[derive(Debug)]
pub(crate) struct Records {
    file: Arc<MappedFile>,
    path: PathBuf,
    /// Byte offset of the first record in the file.
    start: usize,
    /// Bytes of a record.
    len: usize,
    /// Bytes of a value: 4 (KRBI) or 8 (KDBI).
    width: usize,
    /// Byte offset in a record of each long section, in the order of v.
    columns: Box<[usize]>,
    /// Whether the long sections follow each other in the records (as nearly every file
    /// has them): then a run of them is read as one block.
    contiguous: bool,
    /// Cross sections (records).
    nu: usize,
}

impl Records {
    /// The records of `file` from byte `start`: `nu` of `len` bytes, each holding a value of
    /// `width` bytes per channel, the long sections in the channels `columns` (in the order
    /// of v). `None` when the file does not hold them all.
    pub(crate) fn new(
        file: Arc<MappedFile>,
        path: &Path,
        start: usize,
        (len, width): (usize, usize),
        columns: &[usize],
        nu: usize,
    ) -> Option<Records> {
        let end = nu.checked_mul(len)?.checked_add(start)?;
        if end > file.bytes().len() || !matches!(width, 4 | 8) || columns.iter().any(|&c| (c + 1) * width > len) {
            return None;
        }
        let columns: Box<[usize]> = columns.iter().map(|&c| c * width).collect();
        let contiguous = columns.windows(2).all(|w| w[1] == w[0] + width);
        Some(Records { file, path: path.to_path_buf(), start, len, width, columns, contiguous, nu })
    }

    /// The records `us` (their long sections `vs`, in the order of v) of this file, as
    /// records of their own: a part of the grid, read from the same file. `None` where
    /// the ranges leave the grid or hold fewer than two sections.
    pub(crate) fn part(
        &self,
        us: std::ops::RangeInclusive<usize>,
        vs: std::ops::RangeInclusive<usize>,
    ) -> Option<Records> {
        let (a, b, c, e) = (*us.start(), *us.end(), *vs.start(), *vs.end());
        if !(a < b && b < self.nu && c < e && e < self.nv()) {
            return None;
        }
        Some(Records {
            file: self.file.clone(),
            path: self.path.clone(),
            start: self.start + a * self.len,
            len: self.len,
            width: self.width,
            columns: self.columns[c..=e].into(),
            contiguous: self.columns[c..=e].windows(2).all(|w| w[1] == w[0] + self.width),
            nu: b - a + 1,
        })
    }

    /// Number of long sections.
    pub(crate) fn nv(&self) -> usize {
        self.columns.len()
    }

    /// Number of cross sections.
    pub(crate) fn nu(&self) -> usize {
        self.nu
    }

    /// The file.
    pub(crate) fn path(&self) -> &Path {
        &self.path
    }

    /// Whether the values read so far can be trusted (see [`MappedFile::check`]).
    pub(crate) fn check(&self) -> Result<(), Fault> {
        self.file.check()
    }

    /// Whether a read of the file faulted (no system call).
    pub(crate) fn faulted(&self) -> bool {
        self.file.faulted()
    }

    /// Where record `iu` starts. Only computed.
    #[inline(always)]
    pub(crate) fn record(&self, iu: usize) -> *const u8 {
        self.file.bytes().as_ptr().wrapping_add(self.start + iu * self.len)
    }

    /// Where the value of long section `iv` of record `iu` lies. Only computed.
    #[inline(always)]
    pub(crate) fn value_address(&self, iu: usize, iv: usize) -> *const u8 {
        self.record(iu).wrapping_add(self.columns.get(iv).copied().unwrap_or(0))
    }

    /// The value of long section `iv` in the record at `record`, as a grid in memory holds
    /// it (single precision).
    ///
    /// # Safety
    /// `record` is [`Records::record`] of a cross section below `nu`, and `iv < nv`.
    #[inline(always)]
    pub(crate) unsafe fn value(&self, record: *const u8, iv: usize) -> f32 {
        // SAFETY: `new` checked that every column of every record lies inside the mapping
        // (which keeps its length while the file is open, faults being caught).
        unsafe {
            let p = record.add(*self.columns.get_unchecked(iv));
            if self.width == 4 {
                decode_f32(p.cast::<[u8; 4]>().read_unaligned())
            } else {
                f64::from_be_bytes(p.cast::<[u8; 8]>().read_unaligned()) as f32
            }
        }
    }

    /// The values of cross section `iu` (below `nu`) into `row` (`nv` of them), as read.
    pub(crate) fn read_row(&self, iu: usize, row: &mut [f32]) {
        let n = row.len().min(self.nv());
        self.read_run(iu, 0, &mut row[..n]);
    }

    /// Where the run of `n` long sections from `iv` on starts in the first record, when
    /// such runs are `n` single-precision values next to each other in every record (the
    /// common case of a tile's run, read by [`read_words`]); `None` otherwise.
    pub(crate) fn words_start(&self, iv: usize, n: usize) -> Option<*const u8> {
        (self.contiguous && self.width == 4 && iv + n <= self.nv()).then(|| self.value_address(0, iv))
    }

    /// The values of the long sections `iv..iv + out.len()` (all below `nv`) of cross
    /// section `iu` (below `nu`) into `out`, as read.
    #[inline]
    pub(crate) fn read_run(&self, iu: usize, iv: usize, out: &mut [f32]) {
        let record = self.record(iu.min(self.nu - 1));
        if iv + out.len() > self.nv() {
            out.fill(f32::NAN);
            return;
        }
        if self.contiguous && !out.is_empty() {
            // SAFETY: the run lies inside the record (the columns follow each other and the
            // last one is below `nv`), which lies inside the mapping (`new`).
            let p = unsafe { record.add(self.columns[iv]) };
            if self.width == 4 {
                for (j, z) in out.iter_mut().enumerate() {
                    // SAFETY: as above.
                    *z = decode_f32(unsafe { p.add(4 * j).cast::<[u8; 4]>().read_unaligned() });
                }
            } else {
                for (j, z) in out.iter_mut().enumerate() {
                    // SAFETY: as above.
                    *z = f64::from_be_bytes(unsafe { p.add(8 * j).cast::<[u8; 8]>().read_unaligned() }) as f32;
                }
            }
        } else {
            for (j, z) in out.iter_mut().enumerate() {
                // SAFETY: the record is one of the file's, `iv + j < nv`.
                *z = unsafe { self.value(record, iv + j) };
            }
        }
    }

    /// Channel `column` (0-based) of record `iu` (below `nu`) as read, in double precision.
    pub(crate) fn channel(&self, iu: usize, column: usize) -> f64 {
        let p = self.record(iu.min(self.nu - 1)).wrapping_add(column * self.width);
        if (column + 1) * self.width > self.len {
            return f64::NAN;
        }
        // SAFETY: the record lies inside the mapping (`new`) and the column inside it.
        unsafe {
            if self.width == 4 {
                f64::from(f32::from_be_bytes(p.cast::<[u8; 4]>().read_unaligned()))
            } else {
                f64::from_be_bytes(p.cast::<[u8; 8]>().read_unaligned())
            }
        }
    }

    /// Lets the system drop the pages of the records `first..end` from this process's
    /// memory (see [`MappedFile::release`]).
    pub(crate) fn release(&self, first: usize, end: usize) {
        self.file.release(self.start + first * self.len, self.start + end * self.len);
    }
}

/// The `N` big-endian single-precision values at `p` as a grid in memory holds them (their
/// bits, a signalling NaN quieted), and whether one of them is NaN: the words are swapped
/// and tested together (quieted one by one only where one is NaN).
///
/// # Safety
/// `N * 4` bytes at `p` can be read.
#[inline(always)]
pub(crate) unsafe fn read_words<const N: usize>(p: *const u8, out: &mut [u32; N]) -> bool {
    let mut nan = false;
    for (j, w) in out.iter_mut().enumerate() {
        // SAFETY: the contract above.
        *w = u32::from_be(unsafe { p.add(4 * j).cast::<u32>().read_unaligned() });
        nan |= (*w & 0x7fff_ffff) > 0x7f80_0000;
    }
    if nan {
        for w in out.iter_mut() {
            *w = decode_f32(w.to_be_bytes()).to_bits();
        }
    }
    nan
}

/// A big-endian single-precision value as the grid in memory gets it (a signalling NaN
/// quieted, as the conversion through double precision does; without a branch, so that
/// runs of them are decoded in vector registers).
#[inline(always)]
fn decode_f32(bytes: [u8; 4]) -> f32 {
    let bits = u32::from_be_bytes(bytes);
    let nan = u32::from((bits & 0x7fff_ffff) > 0x7f80_0000);
    f32::from_bits(bits | (nan << 22))
}

/// An operation on the grid's values that a modifier asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum ValueOp {
    /// Every value multiplied by the factor.
    Scale(f32),
    /// The offset added to every value but NaN (the grid's mean folded in).
    Add(f32),
    /// NaN handling of the cross sections' borders (see `Grid::fill_nans`).
    Fill(NanMode, f32),
}

/// Whether `ops` change values without NaN (scaling, an offset: NaN handling changes only
/// NaN).
pub(crate) fn change_numbers(ops: &[ValueOp]) -> bool {
    ops.iter().any(|op| matches!(op, ValueOp::Scale(_) | ValueOp::Add(_)))
}

/// `values` (of one cross section) after `ops`; `false` where a NaN handling meets a NaN
/// among them (then their cross section decides, see [`RowWalker`], and `values` are
/// left half done).
#[inline]
pub(crate) fn apply(ops: &[ValueOp], values: &mut [f32]) -> bool {
    for op in ops {
        match *op {
            ValueOp::Scale(f) => values.iter_mut().for_each(|z| *z *= f),
            ValueOp::Add(a) => values.iter_mut().filter(|z| !z.is_nan()).for_each(|z| *z += a),
            ValueOp::Fill(NanMode::Keep, _) => {}
            ValueOp::Fill(..) => {
                if values.iter().fold(false, |nan, z| nan | z.is_nan()) {
                    return false;
                }
            }
        }
    }
    true
}

/// What NaN handling carries from one cross section to the next (per handling): whether
/// the cross section held a NaN, and whether its second pass copied a value.
#[derive(Debug, Clone, Copy, Default)]
struct Carry {
    had_nan: bool,
    applied: bool,
}

/// Cross sections after the operations, read one after another: NaN handling needs the
/// state the cross sections before left (a grid in memory handles them in order).
pub(crate) struct RowWalker<'a> {
    records: &'a Records,
    ops: &'a [ValueOp],
    carries: Vec<Carry>,
    /// The cross section in `row` (`usize::MAX`: none yet).
    at: usize,
    row: Vec<f32>,
}

impl<'a> RowWalker<'a> {
    /// A walker over `records` with `ops`.
    pub(crate) fn new(records: &'a Records, ops: &'a [ValueOp]) -> Self {
        let fills = ops.iter().filter(|op| matches!(op, ValueOp::Fill(..))).count();
        RowWalker { records, ops, carries: vec![Carry::default(); fills], at: usize::MAX, row: vec![0.0; records.nv()] }
    }

    /// Cross section `iu` after the operations. In order it reads one record; elsewhere it
    /// starts again as many cross sections before as there are NaN handlings: a handling's
    /// carry depends on the cross section before as it stood before that handling, so that
    /// many are enough for the exact values.
    pub(crate) fn row(&mut self, iu: usize) -> &[f32] {
        if self.at == usize::MAX || iu != self.at.wrapping_add(1) {
            self.carries.iter_mut().for_each(|c| *c = Carry::default());
            let first = iu.saturating_sub(self.carries.len());
            for earlier in first..iu {
                self.step(earlier);
            }
        }
        self.step(iu);
        &self.row
    }

    fn step(&mut self, iu: usize) {
        self.records.read_row(iu, &mut self.row);
        let mut fill = 0;
        for op in self.ops {
            match *op {
                ValueOp::Scale(f) => self.row.iter_mut().for_each(|z| *z *= f),
                ValueOp::Add(a) => self.row.iter_mut().filter(|z| !z.is_nan()).for_each(|z| *z += a),
                ValueOp::Fill(mode, offset) => {
                    let carry = &mut self.carries[fill];
                    fill += 1;
                    let has_nan = self.row.iter().any(|z| z.is_nan());
                    if has_nan {
                        let mut applied = carry.had_nan && carry.applied;
                        fill_row_nans(&mut self.row, mode, offset, &mut applied);
                        carry.applied = applied;
                    }
                    carry.had_nan = has_nan;
                }
            }
        }
        self.at = iu;
    }
}
