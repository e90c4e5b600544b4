//! The id tables the classic API demands: data sets and contact points.
//!
//! Data sets live in one table behind a lock. Contact points live in slots of
//! fixed address, each behind its own lock, so evaluation on different contact
//! points from different threads never waits on a shared lock.

use crate::panic::lock;
use opencrg::{ContactPoint, Road};
use std::cell::UnsafeCell;
use std::ffi::c_int;
use std::ops::{Deref, DerefMut};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, OnceLock};

/// A loaded data set.
pub struct DataSet {
    pub id: c_int,
    pub road: Arc<Road>,
}

/// A contact point and the data set it belongs to.
pub struct Cp {
    pub dataset: c_int,
    pub point: ContactPoint,
}

static DATASETS: Mutex<Vec<DataSet>> = Mutex::new(Vec::new());

const CHUNK: usize = 256;
const MAX_CHUNKS: usize = 4096;
static CHUNKS: [OnceLock<Box<[Slot]>>; MAX_CHUNKS] = [const { OnceLock::new() }; MAX_CHUNKS];

/// One contact point's place: a small lock of its own, on its own cache lines so
/// that threads working on neighbouring contact points do not slow each other.
///
/// The lock is a flag taken with one compare-and-swap and released with one store:
/// in correct use each contact point has one thread, so it is never contended, and
/// it is cheaper than a general mutex in the evaluation hot path. Contention (two
/// threads on one contact point) is still safe: the second thread waits.
#[repr(align(128))]
struct Slot {
    busy: AtomicBool,
    cp: UnsafeCell<Option<Cp>>,
}

// SAFETY: `cp` is only reached through `SlotGuard`, which holds the `busy` flag.
unsafe impl Sync for Slot {}

struct SlotGuard<'a>(&'a Slot);

impl Slot {
    fn new() -> Self {
        Slot { busy: AtomicBool::new(false), cp: UnsafeCell::new(None) }
    }

    fn lock(&self) -> SlotGuard<'_> {
        let mut spins = 0u32;
        while self.busy.compare_exchange_weak(false, true, Ordering::Acquire, Ordering::Relaxed).is_err() {
            spins += 1;
            if spins < 64 {
                std::hint::spin_loop();
            } else {
                std::thread::yield_now();
            }
        }
        SlotGuard(self)
    }
}

impl Deref for SlotGuard<'_> {
    type Target = Option<Cp>;
    fn deref(&self) -> &Option<Cp> {
        // SAFETY: this guard holds the slot's flag.
        unsafe { &*self.0.cp.get() }
    }
}

impl DerefMut for SlotGuard<'_> {
    fn deref_mut(&mut self) -> &mut Option<Cp> {
        // SAFETY: this guard holds the slot's flag.
        unsafe { &mut *self.0.cp.get() }
    }
}

impl Drop for SlotGuard<'_> {
    fn drop(&mut self) {
        self.0.busy.store(false, Ordering::Release);
    }
}
/// Number of contact point ids handed out so far (the table's size).
static CP_TABLE_SIZE: Mutex<usize> = Mutex::new(0);

fn slot(id: usize) -> Option<&'static Slot> {
    CHUNKS.get(id / CHUNK)?.get().map(|c| &c[id % CHUNK])
}

fn slot_or_create(id: usize) -> Option<&'static Slot> {
    let chunk = CHUNKS.get(id / CHUNK)?;
    Some(&chunk.get_or_init(|| (0..CHUNK).map(|_| Slot::new()).collect())[id % CHUNK])
}

/// Adds a road; returns its id (one more than the largest id in use).
pub fn add_dataset(road: Road) -> c_int {
    let mut sets = lock(&DATASETS);
    let id = sets.iter().map(|d| d.id).max().unwrap_or(0) + 1;
    sets.push(DataSet { id, road: Arc::new(road) });
    id
}

/// Runs `f` on a data set; `None` for an unknown id.
pub fn with_dataset<R>(id: c_int, f: impl FnOnce(&mut DataSet) -> R) -> Option<R> {
    let mut sets = lock(&DATASETS);
    sets.iter_mut().find(|d| d.id == id).map(f)
}

/// Changes a data set's road; contact points of that data set follow the change.
pub fn modify_road<R>(id: c_int, f: impl FnOnce(&mut Road) -> R) -> Option<R> {
    let (result, road) = with_dataset(id, |d| {
        let r = f(Arc::make_mut(&mut d.road));
        (r, d.road.clone())
    })?;
    for_each_cp(|cp| {
        if cp.dataset == id && !Arc::ptr_eq(cp.point.road(), &road) {
            cp.point.set_road(road.clone());
        }
    });
    Some(result)
}

/// Removes a data set and its contact points.
pub fn release_dataset(id: c_int) -> bool {
    let removed = {
        let mut sets = lock(&DATASETS);
        let before = sets.len();
        sets.retain(|d| d.id != id);
        sets.len() != before
    };
    if removed {
        delete_cps_of(Some(id));
    }
    removed
}

/// Ids of every data set.
pub fn dataset_ids() -> Vec<c_int> {
    lock(&DATASETS).iter().map(|d| d.id).collect()
}

/// Creates a contact point on a data set; its id, or -1.
pub fn create_cp(dataset: c_int) -> c_int {
    let Some(road) = with_dataset(dataset, |d| d.road.clone()) else { return -1 };
    let mut size = lock(&CP_TABLE_SIZE);
    let free = (0..*size).rev().find(|&i| slot(i).is_some_and(|s| s.lock().is_none()));
    let id = match free {
        Some(i) => i,
        None => {
            *size += 1;
            *size - 1
        }
    };
    let Some(s) = slot_or_create(id) else {
        *size -= usize::from(free.is_none());
        return -1;
    };
    *s.lock() = Some(Cp { dataset, point: ContactPoint::new(road) });
    id as c_int
}

/// Runs `f` on a contact point; `None` for an unknown id.
pub fn with_cp<R>(id: c_int, f: impl FnOnce(&mut Cp) -> R) -> Option<R> {
    let s = slot(usize::try_from(id).ok()?)?;
    let mut guard = s.lock();
    guard.as_mut().map(f)
}

/// Deletes one contact point.
pub fn delete_cp(id: c_int) -> bool {
    let Some(s) = usize::try_from(id).ok().and_then(slot) else { return false };
    s.lock().take().is_some()
}

fn for_each_cp(mut f: impl FnMut(&mut Cp)) {
    let size = *lock(&CP_TABLE_SIZE);
    for i in 0..size {
        if let Some(s) = slot(i) {
            if let Some(cp) = s.lock().as_mut() {
                f(cp);
            }
        }
    }
}

/// Deletes the contact points of one data set, or all of them (and empties the table).
pub fn delete_cps_of(dataset: Option<c_int>) {
    let mut size = lock(&CP_TABLE_SIZE);
    for i in 0..*size {
        if let Some(s) = slot(i) {
            let mut g = s.lock();
            if g.as_ref().is_some_and(|cp| dataset.is_none_or(|d| cp.dataset == d)) {
                *g = None;
            }
        }
    }
    if dataset.is_none() {
        *size = 0;
    }
}

/// Applies `f` to every contact point.
pub fn update_all_cps(f: impl FnMut(&mut Cp)) {
    for_each_cp(f);
}
