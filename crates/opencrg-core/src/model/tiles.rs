//! The decoded values of a grid read in place, in tiles laid out for the wheel: a tile
//! holds 1024 cross sections of 16 long sections (and the next cross and long section,
//! so that every cell whose first corner lies in it lies wholly in it), long section by
//! long section, in single precision after the modifiers' operations; a lookup reads
//! four values of one tile, as a grid in memory reads four of its own.
//!
//! The file holds cross section after cross section: a wheel moving along the road meets
//! a new record (a new page of the file) every centimetre. Read in place, each cell a
//! wheel enters would cost two cache misses in the file (measured: three to six times
//! the lookup in memory at 30 to 50 m/s); a tile is read half by half, each half one
//! pass over 513 records when a lookup first reaches it, reading only the 17 values of
//! each that it keeps, and then serves every wheel that drives over it as memory does.
//! A wheel that weaves into the next strip of long sections reads no more of it than
//! with tiles of half the length; a wheel driving on enters a tile half as often.
//!
//! Tiles live in a pool of slots of bounded size (the road's cache, say 64 MiB); a
//! directory gives the slot of each tile present. Lookups take no lock and write nothing
//! shared: each slot carries a sequence number that is odd while the slot is written and
//! grows with every change, and a lookup that reads the same even number before and after
//! its values has read one tile whole (a sequence lock). A contact point may also pin a
//! tile (a pin): a pinned slot is never filled again until unpinned, so the contact
//! point reads it as plain memory, as it reads a grid in memory. Filling a tile takes the
//! pool's lock only to claim the slot filled longest ago that nobody pins and to mark the
//! tile as being read; the records are read and the file checked outside it (threads read
//! different tiles at once), then the tile is published. The second half of a tile is
//! read into the tile's slot, pinned meanwhile, and published by a bit of its own
//! (lookups in the first half go on). A lookup whose tile another thread is reading
//! reads its cell from the file meanwhile.

use crate::base::mapped_file::Fault;
use crate::model::in_place::{apply, change_numbers, read_words, Records, RowWalker, ValueOp};
use std::num::NonZeroU32;
use std::sync::atomic::{fence, AtomicU32, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, PoisonError};

/// Cross sections a tile holds cells of: a wheel enters the next tile along every 10.24 m
/// at 1 cm (the longer the tile, the rarer the switch: measured in docs/performance.md).
pub const TILE_U: usize = 1024;
/// Cross sections of the half of a tile read from the file at once: a tile is read half
/// by half, each when a lookup first reaches it (a wheel weaving into the next strip of
/// long sections reads no more than it needs).
pub const HALF_U: usize = TILE_U / 2;
/// Long sections a tile holds cells of.
pub const TILE_V: usize = 16;
/// Values between a tile's long sections.
pub(crate) const TILE_STRIDE: usize = TILE_U + 17;
/// Values of a tile.
const TILE_LEN: usize = TILE_STRIDE * (TILE_V + 1);
/// Values of a tile from the first cross section of its second half on.
const HALF_LEN: usize = TILE_LEN - HALF_U;
/// Bytes of a tile.
pub const TILE_BYTES: usize = TILE_LEN * 4;
/// What a slot holds for no tile (the directory holds 0 for a tile not present, else its
/// slot plus one).
const ABSENT: u32 = u32::MAX;
/// What the directory holds for a tile being read (no slot: lookups and pins find it
/// absent).
const READING: u32 = u32::MAX;
/// The fewest slots a pool has, whatever its size: a few wheels' tiles at once.
const MIN_SLOTS: usize = 16;

/// One slot of the pool: which tile it holds, its sequence number, how many pins keep it
/// (`CLAIMED` while it is being filled), and which halves of the tile were read (bit `h`)
/// or are being read (bit `2 + h`).
struct Slot {
    seq: AtomicU32,
    tile: AtomicU32,
    pins: AtomicU32,
    halves: AtomicU32,
}

/// Adds a pin to `slot` unless it is being filled (or holds as many pins as it can).
fn pin_slot(slot: &Slot) -> bool {
    let mut pins = slot.pins.load(Ordering::Relaxed);
    loop {
        if pins == CLAIMED || pins == CLAIMED - 1 {
            return false;
        }
        match slot.pins.compare_exchange_weak(pins, pins + 1, Ordering::Acquire, Ordering::Relaxed) {
            Ok(_) => return true,
            Err(now) => pins = now,
        }
    }
}

/// The bit of [`Slot::halves`] that says half `half` was read.
#[inline(always)]
pub(crate) const fn read_bit(half: usize) -> u32 {
    1 << half
}

/// The bits of [`Slot::halves`] that say which halves were read.
const READ_BITS: u32 = read_bit(0) | read_bit(1);

/// The bit of [`Slot::halves`] that says half `half` is being read.
#[inline(always)]
const fn reading_bit(half: usize) -> u32 {
    4 << half
}

/// What [`Tiles::claim`] gives the thread that is to read a half of a tile.
enum Claim {
    /// The half was read meanwhile.
    Present,
    /// A slot for the tile, none of it read: the slot and its sequence number (now odd).
    Slot(usize, u32),
    /// The tile's slot, its other half read (pinned for the pass).
    Half(usize),
}

/// What a slot's pin count holds while the slot is being filled.
const CLAIMED: u32 = u32::MAX;

/// Why a tile was not filled.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum FillError {
    /// The file cannot be read.
    File(Fault),
    /// Every slot is pinned.
    Full,
    /// Another thread is reading the tile.
    Busy,
}

/// A tile kept in its slot for a contact point: until the pin is handed back to its pool
/// ([`Tiles::unpin`]), the slot holds this tile and nothing writes it. It holds no
/// reference to the pool (entering a tile is one atomic write, not three): whoever holds
/// it keeps the pool alive and hands it back (a pin never handed back keeps its slot
/// from being filled again, nothing worse).
#[derive(Debug)]
pub(crate) struct Pin {
    /// The slot, plus one (four bytes, none of them zero: a contact point moves its pins
    /// on with its windows when it enters a tile).
    slot: NonZeroU32,
}

/// The tile (its column along, its row across) holding the cell whose first corner is
/// (`iu`, `iv`).
#[inline(always)]
pub(crate) fn tile_of(iu: usize, iv: usize) -> (usize, usize) {
    (iu / TILE_U, iv / TILE_V)
}

/// The half of its tile (0 or 1) that holds the cell whose first corner is `iu` along.
#[inline(always)]
pub(crate) fn half_of(iu: usize) -> usize {
    iu % TILE_U / HALF_U
}

/// What filling needs, behind the pool's lock.
struct FillState {
    /// Slots used so far (the pool grows up to its size).
    used: usize,
    /// The slot filled next once all are used (the one filled longest ago).
    next: usize,
    /// The first fault met: after it nothing more is read from the file.
    fault: Option<Fault>,
}

/// The tile pool of a grid read in place with a list of operations.
pub(crate) struct Tiles {
    records: Arc<Records>,
    ops: Vec<ValueOp>,
    /// Tiles across the road.
    tiles_v: usize,
    directory: Box<[AtomicU32]>,
    slots: Box<[Slot]>,
    values: Box<[AtomicU32]>,
    fill: Mutex<FillState>,
    /// Halves of tiles read so far.
    fills: AtomicUsize,
}

impl std::fmt::Debug for Tiles {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Tiles")
            .field("file", &self.records.path())
            .field("ops", &self.ops)
            .field("slots", &self.slots.len())
            .finish()
    }
}

impl Tiles {
    /// A pool of at most `cache_bytes` for `records` read with `ops`.
    pub(crate) fn new(records: Arc<Records>, ops: Vec<ValueOp>, cache_bytes: usize) -> Tiles {
        let tiles_u = records.nu().saturating_sub(1).div_ceil(TILE_U).max(1);
        let tiles_v = records.nv().saturating_sub(1).div_ceil(TILE_V).max(1);
        let count = tiles_u * tiles_v;
        let slots = (cache_bytes / TILE_BYTES).max(MIN_SLOTS).min(count).min(ABSENT as usize - 1);
        Tiles {
            records,
            ops,
            tiles_v,
            directory: crate::base::memory::large_zeroed_atomics(count),
            slots: (0..slots)
                .map(|_| Slot {
                    seq: AtomicU32::new(0),
                    tile: AtomicU32::new(ABSENT),
                    pins: AtomicU32::new(0),
                    halves: AtomicU32::new(0),
                })
                .collect(),
            values: crate::base::memory::large_zeroed_atomics(slots * TILE_LEN),
            fill: Mutex::new(FillState { used: 0, next: 0, fault: None }),
            fills: AtomicUsize::new(0),
        }
    }

    /// The same records with `op` after the operations so far, in a new pool of the same size.
    pub(crate) fn with_op(&self, op: ValueOp) -> Tiles {
        let mut ops = self.ops.clone();
        ops.push(op);
        Tiles::new(self.records.clone(), ops, self.capacity())
    }

    /// The pool's size in bytes.
    pub(crate) fn capacity(&self) -> usize {
        self.slots.len() * TILE_BYTES
    }

    /// The records read.
    pub(crate) fn records(&self) -> &Records {
        &self.records
    }

    /// The operations applied to every value read.
    pub(crate) fn ops(&self) -> &[ValueOp] {
        &self.ops
    }

    /// Halves of tiles read so far.
    pub(crate) fn fills(&self) -> usize {
        self.fills.load(Ordering::Relaxed)
    }

    /// The first fault met reading the file, if any.
    pub(crate) fn fault(&self) -> Option<Fault> {
        self.fill.lock().unwrap_or_else(PoisonError::into_inner).fault
    }

    /// The values of the cell whose first corner is (`iu`, `iv`) (each below the last
    /// cross and long section): (iu, iv), (iu + 1, iv), (iu, iv + 1), (iu + 1, iv + 1).
    /// `None` when its tile cannot be read (the fault is kept, see [`Tiles::fault`]).
    #[inline]
    pub(crate) fn corners(&self, iu: usize, iv: usize) -> Option<[f32; 4]> {
        let (id, at) = self.place(iu, iv)?;
        let half = half_of(iu);
        loop {
            if let Some(values) = self.try_read(id, at, half) {
                return Some(values);
            }
            match self.fill(id, half) {
                Ok(()) => {}
                Err(FillError::Full | FillError::Busy) => return self.read_corners(iu, iv),
                Err(FillError::File(_)) => return None,
            }
        }
    }

    /// The cell's values read from the file directly (every slot being pinned, or the tile
    /// being read by another thread).
    #[cold]
    fn read_corners(&self, iu: usize, iv: usize) -> Option<[f32; 4]> {
        let mut walker = RowWalker::new(&self.records, &self.ops);
        let (a, b) = {
            let row = walker.row(iu);
            (*row.get(iv)?, *row.get(iv + 1)?)
        };
        let row = walker.row(iu + 1);
        let values = [a, *row.get(iv)?, b, *row.get(iv + 1)?];
        self.records.check().ok().map(|()| values)
    }

    /// Pins the tile holding the cell whose first corner is (`iu`, `iv`), when it is
    /// present (nothing is read from the file; nothing can panic), with where its values
    /// lie, long section by long section, [`TILE_STRIDE`] apart (valid as long as the
    /// pool lives and the pin is not handed back). The pin is handed back to this pool
    /// ([`Tiles::unpin`]). Also which halves of the tile were read then (bit `h`: half
    /// `h`, see [`read_bit`]); `None` too where the cell's own half was not read.
    pub(crate) fn pin(&self, iu: usize, iv: usize) -> Option<(Pin, *const f32, u32)> {
        let (id, _) = self.place(iu, iv)?;
        let (s, slot) = self.slot_of(id)?;
        let pin = Pin { slot: u32::try_from(s + 1).ok().and_then(NonZeroU32::new)? };
        let values = self.values.get(s * TILE_LEN..)?.as_ptr().cast::<f32>();
        if !pin_slot(slot) {
            return None;
        }
        // Pinned, the slot keeps what it holds; it may have been filled anew before.
        let halves = slot.halves.load(Ordering::Acquire) & READ_BITS;
        if slot.tile.load(Ordering::Acquire) as usize != id || halves & read_bit(half_of(iu)) == 0 {
            slot.pins.fetch_sub(1, Ordering::Release);
            return None;
        }
        Some((pin, values, halves))
    }

    /// The slot the directory gives for tile `id` (which may hold another tile by now).
    #[inline(always)]
    fn slot_of(&self, id: usize) -> Option<(usize, &Slot)> {
        let s = self.directory.get(id)?.load(Ordering::Acquire).wrapping_sub(1) as usize;
        Some((s, self.slots.get(s)?))
    }

    /// Which halves of the tile of the cell (`iu`, `iv`) were read (bit `h`: half `h`), as
    /// far as a contact point pinning it needs to know: 0 where the tile is not present.
    /// A half once read stays so while the tile is pinned.
    pub(crate) fn halves(&self, iu: usize, iv: usize) -> u32 {
        let present = |(id, _)| self.slot_of(id).filter(|(_, slot)| slot.tile.load(Ordering::Acquire) as usize == id);
        self.place(iu, iv).and_then(present).map_or(0, |(_, slot)| slot.halves.load(Ordering::Acquire) & READ_BITS)
    }

    /// Asks the processor to start loading what a wheel at the cell (`iu`, `iv`) reads first
    /// in the next half of a tile along: the first values there of the long sections
    /// around the cell's (one before, two after), when that half was read (the tile not
    /// pinned: the slot may be filled anew meanwhile, which costs only the loads). Only
    /// addresses are computed.
    pub(crate) fn ask_for_next_along(&self, iu: usize, iv: usize) {
        let next = (iu / HALF_U + 1) * HALF_U;
        let Some((id, at)) = self.place(next, iv) else { return };
        let Some((s, slot)) = self.slot_of(id) else { return };
        if slot.halves.load(Ordering::Relaxed) & read_bit(half_of(next)) == 0 {
            return;
        }
        let p = self.values[s * TILE_LEN + at % TILE_STRIDE..].as_ptr();
        let row = iv % TILE_V;
        for r in row.saturating_sub(1)..(row + 3).min(TILE_V + 1) {
            crate::base::memory::prefetch(p.wrapping_add(r * TILE_STRIDE));
            crate::base::memory::prefetch(p.wrapping_add(r * TILE_STRIDE + 15));
        }
    }

    /// How many pins the pool's slots hold now.
    #[cfg(test)]
    pub(crate) fn pinned(&self) -> usize {
        let held = |s: &Slot| s.pins.load(Ordering::Acquire);
        self.slots.iter().map(held).filter(|&p| p != CLAIMED).map(|p| p as usize).sum()
    }

    /// Hands back a pin of this pool: its slot may be filled again once nobody else pins it.
    pub(crate) fn unpin(&self, pin: Pin) {
        if let Some(slot) = self.slots.get(pin.slot.get() as usize - 1) {
            slot.pins.fetch_sub(1, Ordering::Release);
        }
    }

    /// The tile of the cell (`iu`, `iv`) and where the cell's first corner lies in it.
    #[inline(always)]
    fn place(&self, iu: usize, iv: usize) -> Option<(usize, usize)> {
        let (tu, tv) = tile_of(iu, iv);
        let id = tu * self.tiles_v + tv;
        let at = (iv - tv * TILE_V) * TILE_STRIDE + (iu - tu * TILE_U);
        (tv < self.tiles_v && id < self.directory.len()).then_some((id, at))
    }

    /// The cell's values when its tile is present and its half `half` was read.
    #[inline(always)]
    fn try_read(&self, id: usize, at: usize, half: usize) -> Option<[f32; 4]> {
        let (s, slot) = self.slot_of(id)?;
        let seq = slot.seq.load(Ordering::Acquire);
        if seq & 1 != 0
            || slot.tile.load(Ordering::Relaxed) as usize != id
            || slot.halves.load(Ordering::Acquire) & read_bit(half) == 0
        {
            return None;
        }
        let v = self.values.get(s * TILE_LEN + at..)?.get(..TILE_STRIDE + 2)?;
        // What a wheel moving on along u reads next, as a grid in memory asks for it (only
        // the addresses are computed).
        crate::base::memory::prefetch(v.as_ptr().wrapping_add(AHEAD));
        crate::base::memory::prefetch(v.as_ptr().wrapping_add(TILE_STRIDE + AHEAD));
        let read = |a: &AtomicU32| f32::from_bits(a.load(Ordering::Relaxed));
        let values = [read(&v[0]), read(&v[1]), read(&v[TILE_STRIDE]), read(&v[TILE_STRIDE + 1])];
        fence(Ordering::Acquire);
        (slot.seq.load(Ordering::Relaxed) == seq).then_some(values)
    }

    /// Reads half `half` of tile `id` into its slot (unless another thread did meanwhile,
    /// or is doing it): the slot [`Tiles::claim`] gives, read outside the pool's lock, then
    /// published.
    #[cold]
    fn fill(&self, id: usize, half: usize) -> Result<(), FillError> {
        let (s, seq) = match self.claim(id, half)? {
            Claim::Present => return Ok(()),
            Claim::Half(s) => return self.fill_half(id, half, s),
            Claim::Slot(s, seq) => (s, seq),
        };
        let slot = &self.slots[s];
        let decoded = self.decode(id, half, self.half_values(s, half));
        let (tile, halves) = if decoded.is_ok() { (id as u32, read_bit(half)) } else { (ABSENT, 0) };
        slot.halves.store(halves, Ordering::Relaxed);
        slot.tile.store(tile, Ordering::Relaxed);
        slot.seq.store(seq.wrapping_add(2), Ordering::Release);
        // The directory before the slot is given free: whoever claims the slot next finds
        // the tile where it clears it.
        let result = match decoded {
            Ok(()) => {
                self.directory[id].store(s as u32 + 1, Ordering::Release);
                self.fills.fetch_add(1, Ordering::Relaxed);
                Ok(())
            }
            Err(fault) => {
                self.directory[id].store(0, Ordering::Release);
                Err(self.keep_fault(fault))
            }
        };
        slot.pins.store(0, Ordering::Release);
        result
    }

    /// Reads half `half` of tile `id` into slot `s`, which holds the tile's other half
    /// (pinned by [`Tiles::claim`] for the pass, so that nobody fills it anew meanwhile),
    /// then publishes it. Lookups in the other half go on meanwhile: the long sections'
    /// values at the halves' common cross section are written again with the same bits.
    fn fill_half(&self, id: usize, half: usize, s: usize) -> Result<(), FillError> {
        let slot = &self.slots[s];
        let decoded = self.decode(id, half, self.half_values(s, half));
        // Read (if it was) and no longer being read, at once.
        let read = if decoded.is_ok() { read_bit(half) } else { 0 };
        slot.halves.fetch_xor(read | reading_bit(half), Ordering::Release);
        slot.pins.fetch_sub(1, Ordering::Release);
        match decoded {
            Ok(()) => {
                self.fills.fetch_add(1, Ordering::Relaxed);
                Ok(())
            }
            Err(fault) => Err(self.keep_fault(fault)),
        }
    }

    /// The values of half `half` of the tile in slot `s`: from its first cross section on,
    /// to the slot's end.
    fn half_values(&self, s: usize, half: usize) -> &[AtomicU32] {
        &self.values[s * TILE_LEN + half * HALF_U..(s + 1) * TILE_LEN]
    }

    /// The first fault met, `fault` if it is the first, kept for [`Tiles::fault`].
    fn keep_fault(&self, fault: Fault) -> FillError {
        let mut state = self.fill.lock().unwrap_or_else(PoisonError::into_inner);
        FillError::File(*state.fault.get_or_insert(fault))
    }

    /// Under the pool's lock, what the thread that is to read half `half` of tile `id` reads
    /// it into: nothing where the half was read; the tile's slot where its other half was
    /// (pinned, the half marked as being read); else a new slot and its sequence number
    /// (now odd), the tile marked as being read: the next slot nobody pins, in the order
    /// they were filled.
    fn claim(&self, id: usize, half: usize) -> Result<Claim, FillError> {
        let mut state = self.fill.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(fault) = state.fault {
            return Err(FillError::File(fault));
        }
        let entry = self.directory[id].load(Ordering::Acquire);
        if entry == READING {
            return Err(FillError::Busy);
        }
        let present = entry.wrapping_sub(1) as usize;
        if let Some(slot) = self.slots.get(present).filter(|s| s.tile.load(Ordering::Relaxed) as usize == id) {
            let halves = slot.halves.load(Ordering::Acquire);
            if halves & read_bit(half) != 0 {
                return Ok(Claim::Present);
            }
            if halves & reading_bit(half) != 0 {
                return Err(FillError::Busy);
            }
            // A slot is given to another tile only under this lock: pinned now, it keeps
            // this one while the half is read.
            if !pin_slot(slot) {
                return Err(FillError::Busy);
            }
            slot.halves.fetch_or(reading_bit(half), Ordering::Relaxed);
            return Ok(Claim::Half(present));
        }
        let claim =
            |s: usize| self.slots[s].pins.compare_exchange(0, CLAIMED, Ordering::Acquire, Ordering::Relaxed).is_ok();
        let s = if state.used < self.slots.len() && claim(state.used) {
            state.used += 1;
            state.used - 1
        } else {
            let n = self.slots.len();
            let found = (0..n).map(|k| (state.next + k) % n).find(|&s| claim(s)).ok_or(FillError::Full)?;
            state.next = (found + 1) % n;
            found
        };
        let slot = &self.slots[s];
        let old = slot.tile.load(Ordering::Relaxed);
        if let Some(entry) = self.directory.get(old as usize) {
            entry.store(0, Ordering::Relaxed);
        }
        let seq = slot.seq.load(Ordering::Relaxed);
        slot.seq.store(seq.wrapping_add(1), Ordering::Relaxed);
        fence(Ordering::Release);
        self.directory[id].store(READING, Ordering::Relaxed);
        Ok(Claim::Slot(s, seq))
    }

    /// Reads half `half` of tile `id` (its cross sections and the next) from the file into
    /// `out` (the slot's values from the half's first cross section on), then checks that
    /// the file could be trusted. Record by record: its run of values read (as one run of
    /// words where the run lies so in every record), the operations applied to it where
    /// they change it, and each value written straight to its long section.
    fn decode(&self, id: usize, half: usize, out: &[AtomicU32]) -> Result<(), Fault> {
        const RUN: usize = TILE_V + 1;
        let r = &*self.records;
        let (tu, tv) = (id / self.tiles_v, id % self.tiles_v);
        let (iu0, iv0) = (tu * TILE_U + half * HALF_U, tv * TILE_V);
        let (nu, nv) = (r.nu(), r.nv());
        let columns = RUN.min(nv - iv0);
        let last = nu - 1 - iu0;
        let words = r.words_start(iv0, RUN);
        let change = change_numbers(&self.ops);
        let stride = r.record(1) as usize - r.record(0) as usize;
        let mut walker: Option<RowWalker> = None;
        let mut run = [0u32; RUN];
        let mut row = [0.0f32; RUN];
        // The tile's long sections from the half's first cross section on (one length check
        // here, none in the pass); beyond the last long section of the road the tile
        // repeats it (never read as a corner).
        let longs = &out[..HALF_LEN];
        for k in 0..HALF_U + 1 {
            let i = k.min(last);
            // What the records a few on hold is asked for now: the pass waits for memory,
            // not for arithmetic.
            let ahead = r.value_address(iu0 + (i + AHEAD_RECORDS).min(last), iv0);
            crate::base::memory::prefetch(ahead);
            crate::base::memory::prefetch(ahead.wrapping_add(4 * TILE_V));
            // The lines the pass writes three lines on: each record that of one of the
            // first 16 long sections, so each long section's once a line (they lie a page
            // apart: the processor's own prefetcher follows few of them; the seventeenth
            // is left to it).
            let j = k % LINE_VALUES;
            crate::base::memory::prefetch_for_write(longs.as_ptr().wrapping_add(j * TILE_STRIDE + k - j + WRITE_AHEAD));
            let nan = match words {
                // SAFETY: `words_start` found every record's run of RUN values whole in
                // the record, and `iu0 + i` is a record of the file.
                Some(start) => unsafe { read_words(start.add((iu0 + i) * stride), &mut run) },
                None => {
                    r.read_run(iu0 + i, iv0, &mut row[..columns]);
                    for (w, z) in run.iter_mut().zip(&row[..columns]) {
                        *w = z.to_bits();
                    }
                    true
                }
            };
            // The operations change a value only by scaling or an offset, or where a NaN
            // is handled.
            if change || (nan && !self.ops.is_empty()) {
                for (z, w) in row.iter_mut().zip(run.iter()) {
                    *z = f32::from_bits(*w);
                }
                let values = &mut row[..columns];
                if !apply(&self.ops, values) {
                    let whole = walker.get_or_insert_with(|| RowWalker::new(r, &self.ops)).row(iu0 + i);
                    values.copy_from_slice(&whole[iv0..iv0 + columns]);
                }
                for (w, z) in run.iter_mut().zip(values.iter()) {
                    *w = z.to_bits();
                }
            }
            if columns < RUN {
                let edge = run[columns - 1];
                run[columns..].fill(edge);
            }
            for (j, &w) in run.iter().enumerate() {
                longs[j * TILE_STRIDE + k].store(w, Ordering::Relaxed);
            }
        }
        r.check()
    }
}

/// How far ahead along u (in values) a lookup asks for the tile: the next cache line.
const AHEAD: usize = 16;

/// How many records ahead of the one it decodes a tile's pass asks for.
const AHEAD_RECORDS: usize = 16;

/// Values of a cache line.
const LINE_VALUES: usize = 16;

/// How far ahead along a long section (in values) a tile's pass asks for the lines it
/// writes: three lines.
const WRITE_AHEAD: usize = 3 * LINE_VALUES;
