//! Objects the C API names by id and evaluates from many threads (contact points,
//! OpenDRIVE probes): each in a slot of fixed address with its own lock and its owner's
//! lock-free path ([`OwnedCell`]), so that calls on different objects from different
//! threads never wait on a shared lock, and a thread's calls on its own object take no
//! lock at all. Closures run on an object are `Send`, so that they cannot send a message
//! (see [`crate::entry`]).

use crate::lock::lock;
use crate::owner::OwnedCell;
use crate::thread_id::thread_id;
use std::collections::BTreeSet;
use std::ffi::c_int;
use std::sync::atomic::{AtomicI32, AtomicPtr, Ordering};
use std::sync::Mutex;

const CHUNK: usize = 256;
const MAX_CHUNKS: usize = 4096;

/// A table of objects by id: the slots, CHUNK at a time (null until the first object of a
/// chunk is made, under the `ids` lock, never freed after), and the ids handed out.
pub(crate) struct Slots<T> {
    chunks: [AtomicPtr<[Slot<T>; CHUNK]>; MAX_CHUNKS],
    ids: Mutex<Ids>,
}

/// One object's place, on its own cache lines so that threads working on neighbouring
/// objects do not slow each other.
#[repr(align(128))]
pub(crate) struct Slot<T> {
    /// The id of what the object was made from (a data set, a map), 0 when the slot is
    /// free (changed only under both the table's and the slot's lock).
    parent: AtomicI32,
    /// The object.
    pub(crate) cell: OwnedCell<Option<T>>,
}

/// The ids handed out so far: the table's size, and the free ids below it.
struct Ids {
    size: usize,
    free: BTreeSet<usize>,
}

impl<T: Send> Slots<T> {
    /// An empty table.
    pub(crate) const fn new() -> Self {
        Slots {
            chunks: [const { AtomicPtr::new(std::ptr::null_mut()) }; MAX_CHUNKS],
            ids: Mutex::new(Ids { size: 0, free: BTreeSet::new() }),
        }
    }

    /// The slot of `id`, when its chunk exists.
    pub(crate) fn slot(&self, id: usize) -> Option<&Slot<T>> {
        let chunk = self.chunks.get(id / CHUNK)?.load(Ordering::Acquire);
        // SAFETY: a chunk pointer is null or points to a chunk that lives as long as the table.
        unsafe { chunk.as_ref() }.map(|c| &c[id % CHUNK])
    }

    /// The slot of an id as the C API passes it: a negative id becomes an index past
    /// every chunk (one comparison in the hot path instead of two).
    #[inline(always)]
    fn slot_of(&self, id: c_int) -> Option<&Slot<T>> {
        self.slot(id as u32 as usize)
    }

    /// The slot of `id`, its chunk made when missing. Called with the `ids` lock held.
    fn slot_or_create(&self, id: usize) -> Option<&Slot<T>> {
        let entry = self.chunks.get(id / CHUNK)?;
        if entry.load(Ordering::Acquire).is_null() {
            let slots: Box<[Slot<T>]> =
                (0..CHUNK).map(|_| Slot { parent: AtomicI32::new(0), cell: OwnedCell::new(None) }).collect();
            let chunk: Box<[Slot<T>; CHUNK]> =
                slots.try_into().unwrap_or_else(|_| unreachable!("the chunk has CHUNK slots"));
            entry.store(Box::into_raw(chunk), Ordering::Release);
        }
        self.slot(id)
    }

    /// Stores `value`, made from `parent` (> 0); its id (the largest free one, else a new
    /// one), or -1 when the table is full.
    pub(crate) fn create(&self, parent: c_int, value: T) -> c_int {
        // The owner path's barrier is registered now, with the object, so that the
        // evaluation calls never make a system call (real-time callers rely on it).
        crate::barrier::available();
        let mut ids = lock(&self.ids);
        let id = ids.free.last().copied().unwrap_or(ids.size);
        let (Some(s), Ok(c_id)) = (self.slot_or_create(id), c_int::try_from(id)) else { return -1 };
        if id == ids.size {
            ids.size += 1;
        } else {
            ids.free.remove(&id);
        }
        let mut guard = s.cell.lock();
        *guard = Some(value);
        s.parent.store(parent, Ordering::Relaxed);
        guard.count_access(thread_id());
        c_id
    }

    /// Runs `f` on an object; `None` for an unknown id.
    #[inline]
    pub(crate) fn with_mut<R>(&self, id: c_int, f: impl FnOnce(&mut T) -> R + Send) -> Option<R> {
        self.slot_of(id)?.cell.with_mut(|v| v.as_mut().map(f))
    }

    /// Runs `f` on an object when this thread owns it; `None` (without running `f`)
    /// otherwise: the first try of the hottest entry points, with no lock and no call.
    /// `f` must not panic where this runs outside a panic guard.
    #[inline(always)]
    pub(crate) fn with_owned_mut<R>(&self, id: c_int, f: impl FnOnce(&mut T) -> R + Send) -> Option<R> {
        self.slot_of(id)?.cell.with_owned_mut(|v| v.as_mut().map(f)).flatten()
    }

    /// Deletes one object; gives it back (dropped after the table is unlocked).
    pub(crate) fn delete(&self, id: c_int) -> Option<T> {
        let mut ids = lock(&self.ids);
        let (id, s) = usize::try_from(id).ok().and_then(|i| Some((i, self.slot(i)?)))?;
        if s.parent.load(Ordering::Relaxed) == 0 {
            return None;
        }
        free_slot(&mut ids, id, s)
    }

    /// Runs `f` on every object made from `parent` (`None`: on every object).
    pub(crate) fn for_each_of(&self, parent: Option<c_int>, mut f: impl FnMut(&mut T) + Send) {
        let ids = lock(&self.ids);
        for i in 0..ids.size {
            let Some(s) = self.slot(i) else { continue };
            let p = s.parent.load(Ordering::Relaxed);
            if p != 0 && parent.is_none_or(|want| want == p) {
                if let Some(v) = s.cell.lock().as_mut() {
                    f(v);
                }
            }
        }
    }

    /// Deletes the objects made from `parent`, or all of them (and empties the table),
    /// showing each to `deleted` first.
    pub(crate) fn delete_of(&self, parent: Option<c_int>, mut deleted: impl FnMut(&T) + Send) {
        let mut ids = lock(&self.ids);
        for i in 0..ids.size {
            let Some(s) = self.slot(i) else { continue };
            let p = s.parent.load(Ordering::Relaxed);
            if p != 0 && parent.is_none_or(|want| want == p) {
                if let Some(v) = free_slot(&mut ids, i, s) {
                    deleted(&v);
                }
            }
        }
        if parent.is_none() {
            ids.size = 0;
            ids.free.clear();
        }
    }
}

/// Empties a slot that holds an object (the table's lock is held); the object.
fn free_slot<T>(ids: &mut Ids, id: usize, s: &Slot<T>) -> Option<T> {
    let mut guard = s.cell.lock();
    let value = guard.take();
    s.parent.store(0, Ordering::Relaxed);
    // The slot starts over without an owner.
    guard.disown();
    drop(guard);
    ids.free.insert(id);
    value
}
