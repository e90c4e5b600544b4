//! The id tables the classic API demands: data sets and contact points.
//!
//! Data sets live in one table behind a lock. Contact points live in slots of
//! fixed address, each behind its own lock, so evaluation on different contact
//! points from different threads never waits on a shared lock.

use crate::lock::lock;
use opencrg::{ContactPoint, Road};
use std::cell::UnsafeCell;
use std::collections::BTreeSet;
use std::ffi::c_int;
use std::ops::{Deref, DerefMut};
use std::sync::atomic::{compiler_fence, AtomicBool, AtomicI32, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, OnceLock};

/// A loaded data set.
pub struct DataSet {
    pub id: c_int,
    pub road: Arc<Road>,
}

static DATASETS: Mutex<Vec<DataSet>> = Mutex::new(Vec::new());

const CHUNK: usize = 256;
const MAX_CHUNKS: usize = 4096;
static CHUNKS: [OnceLock<Box<[Slot; CHUNK]>>; MAX_CHUNKS] = [const { OnceLock::new() }; MAX_CHUNKS];

/// One contact point's place, on its own cache lines so that threads working on
/// neighbouring contact points do not slow each other.
///
/// Access is guarded in two ways. The general way is a small lock: a flag taken
/// with one compare-and-swap. The fast way is for the slot's *owner*, the thread
/// that used the contact point for the last several calls in a row: it marks the
/// slot busy with plain stores and no atomic read-modify-write, which keeps the
/// evaluation calls (millions per second, from one thread per contact point) free
/// of locked instructions. Any other thread first takes the lock and revokes the
/// ownership: it clears `owner`, forces a memory barrier on every thread of the
/// process (see [`crate::barrier`]) and waits until the owner is out of the slot.
/// Either the owner then sees the revocation before it touches the contact point,
/// or the revoker sees the owner's busy mark and waits.
#[repr(align(128))]
struct Slot {
    /// The owner's thread id, 0 when the slot has none.
    owner: AtomicUsize,
    /// Set by the owner while it works on the contact point the fast way.
    owner_busy: AtomicBool,
    /// The lock of every other access.
    locked: AtomicBool,
    /// The data set of the contact point held, 0 when the slot is free (changed
    /// only under both the table's and the slot's lock).
    dataset: AtomicI32,
    /// Which thread made the last locked accesses, and how many in a row (guarded by `locked`).
    streak: UnsafeCell<(usize, u32)>,
    cp: UnsafeCell<Option<ContactPoint>>,
}

// SAFETY: `cp` and `streak` are only reached through `SlotGuard` (which holds the
// lock, with no owner left in the slot) or through `with_cp`'s owner path (with the
// busy mark set while ownership stands), never both at once (see `Slot`).
unsafe impl Sync for Slot {}

/// Waits a little: spins at first, then lets other threads run (the one being
/// waited for may have been descheduled).
fn back_off(spins: &mut u32) {
    *spins += 1;
    if *spins < 64 {
        std::hint::spin_loop();
    } else {
        std::thread::yield_now();
    }
}

/// Locked accesses in a row by one thread after which it becomes the owner.
const OWNER_STREAK: u32 = 8;

/// This thread's id: non-zero and unique among running threads. An id is reused
/// only after its thread ended, and an ended thread is in no slot.
#[inline]
fn thread_id() -> usize {
    #[cfg(all(target_arch = "x86_64", target_os = "linux"))]
    {
        // The thread pointer's self-reference (what pthread_self returns with glibc
        // and musl), read without a call.
        let id: usize;
        // SAFETY: on x86_64 Linux fs:0 always holds the thread control block's own
        // address; reading it has no side effects.
        unsafe { std::arch::asm!("mov {}, fs:0", out(reg) id, options(nostack, readonly, preserves_flags, pure)) };
        id
    }
    #[cfg(not(all(target_arch = "x86_64", target_os = "linux")))]
    {
        // SAFETY: pthread_self has no preconditions.
        unsafe { libc::pthread_self() as usize }
    }
}

/// The exclusive access to a slot's contact point through the lock.
struct SlotGuard<'a>(&'a Slot);

/// The owner's busy mark; cleared when dropped (also when the access panics).
struct OwnerGuard<'a>(&'a Slot);

impl Drop for OwnerGuard<'_> {
    fn drop(&mut self) {
        self.0.owner_busy.store(false, Ordering::Release);
    }
}

impl Slot {
    fn new() -> Self {
        Slot {
            owner: AtomicUsize::new(0),
            owner_busy: AtomicBool::new(false),
            locked: AtomicBool::new(false),
            dataset: AtomicI32::new(0),
            streak: UnsafeCell::new((0, 0)),
            cp: UnsafeCell::new(None),
        }
    }

    /// Marks the slot busy the owner's way; `None` when this thread is not the owner.
    #[inline]
    fn enter_as_owner(&self, me: usize) -> Option<OwnerGuard<'_>> {
        if self.owner.load(Ordering::Relaxed) != me {
            return None;
        }
        self.owner_busy.store(true, Ordering::Relaxed);
        let busy = OwnerGuard(self);
        // Keeps the compiler from moving the busy store after the check below; the
        // processor's own reordering of the two is what the revoker's barrier covers.
        compiler_fence(Ordering::SeqCst);
        (self.owner.load(Ordering::Acquire) == me).then_some(busy)
    }

    /// Takes the lock for a thread that is not the owner, and counts the access.
    #[inline(never)]
    fn lock_for(&self, me: usize) -> SlotGuard<'_> {
        let mut guard = self.lock();
        guard.note_access(me);
        guard
    }

    /// Takes the lock and makes sure no owner works in the slot.
    fn lock(&self) -> SlotGuard<'_> {
        let mut spins = 0u32;
        while self.locked.compare_exchange_weak(false, true, Ordering::Acquire, Ordering::Relaxed).is_err() {
            back_off(&mut spins);
        }
        let owner = self.owner.load(Ordering::Relaxed);
        if owner != 0 && owner != thread_id() {
            self.owner.store(0, Ordering::Relaxed);
            crate::barrier::everywhere();
            let mut spins = 0u32;
            while self.owner_busy.load(Ordering::Acquire) {
                back_off(&mut spins);
            }
        }
        SlotGuard(self)
    }
}

impl SlotGuard<'_> {
    /// Counts this locked access; after enough of them in a row by this thread,
    /// makes it the owner (when the process can revoke ownership).
    fn note_access(&mut self, me: usize) {
        // SAFETY: the lock is held.
        let streak = unsafe { &mut *self.0.streak.get() };
        if streak.0 == me {
            streak.1 = streak.1.saturating_add(1);
        } else {
            *streak = (me, 1);
        }
        if streak.1 >= OWNER_STREAK && crate::barrier::available() {
            self.0.owner.store(me, Ordering::Release);
        }
    }
}

impl Deref for SlotGuard<'_> {
    type Target = Option<ContactPoint>;
    fn deref(&self) -> &Option<ContactPoint> {
        // SAFETY: this guard holds the slot's lock and no owner works in the slot.
        unsafe { &*self.0.cp.get() }
    }
}

impl DerefMut for SlotGuard<'_> {
    fn deref_mut(&mut self) -> &mut Option<ContactPoint> {
        // SAFETY: this guard holds the slot's lock and no owner works in the slot.
        unsafe { &mut *self.0.cp.get() }
    }
}

impl Drop for SlotGuard<'_> {
    fn drop(&mut self) {
        self.0.locked.store(false, Ordering::Release);
    }
}
/// The contact point ids handed out so far: the table's size, and the free ids below it.
struct CpTable {
    size: usize,
    free: BTreeSet<usize>,
}

/// Held while contact points are created or deleted.
static CP_TABLE: Mutex<CpTable> = Mutex::new(CpTable { size: 0, free: BTreeSet::new() });

fn slot(id: usize) -> Option<&'static Slot> {
    CHUNKS.get(id / CHUNK)?.get().map(|c| &c[id % CHUNK])
}

fn slot_or_create(id: usize) -> Option<&'static Slot> {
    let chunk = CHUNKS.get(id / CHUNK)?;
    let new_chunk = || {
        let slots: Box<[Slot]> = (0..CHUNK).map(|_| Slot::new()).collect();
        slots.try_into().unwrap_or_else(|_| unreachable!("the chunk has CHUNK slots"))
    };
    Some(&chunk.get_or_init(new_chunk)[id % CHUNK])
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
    for_each_cp_of(Some(id), |cp| {
        if !Arc::ptr_eq(cp.road(), &road) {
            cp.set_road(road.clone());
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

/// Creates a contact point on a data set; its id (the largest free one, else a new
/// one), or -1.
pub fn create_cp(dataset: c_int) -> c_int {
    let Some(road) = with_dataset(dataset, |d| d.road.clone()) else { return -1 };
    let mut table = lock(&CP_TABLE);
    let id = table.free.last().copied().unwrap_or(table.size);
    let (Some(s), Ok(c_id)) = (slot_or_create(id), c_int::try_from(id)) else { return -1 };
    if id == table.size {
        table.size += 1;
    } else {
        table.free.remove(&id);
    }
    let mut guard = s.lock();
    *guard = Some(ContactPoint::new(road));
    s.dataset.store(dataset, Ordering::Relaxed);
    guard.note_access(thread_id());
    c_id
}

/// Runs `f` on a contact point; `None` for an unknown id.
#[inline]
pub fn with_cp<R>(id: c_int, f: impl FnOnce(&mut ContactPoint) -> R) -> Option<R> {
    let s = slot(usize::try_from(id).ok()?)?;
    let me = thread_id();
    // Exclusive access one way or the other, held until this function returns.
    let _access = s.enter_as_owner(me).ok_or_else(|| s.lock_for(me));
    // SAFETY: `_access` grants exclusive access to the contact point while it lives.
    unsafe { &mut *s.cp.get() }.as_mut().map(f)
}

/// Runs `f` on a contact point when this thread owns it; `None` (without running
/// `f`) otherwise: the first try of the hottest entry points, with no lock and no
/// call. `f` must not panic (this runs outside any panic guard).
#[inline(always)]
pub fn with_owned_cp<R>(id: c_int, f: impl FnOnce(&ContactPoint) -> R) -> Option<R> {
    let s = slot(usize::try_from(id).ok()?)?;
    let _busy = s.enter_as_owner(thread_id())?;
    // SAFETY: the owner's busy mark is set while ownership stands.
    unsafe { &*s.cp.get() }.as_ref().map(f)
}

/// Deletes one contact point.
pub fn delete_cp(id: c_int) -> bool {
    let mut table = lock(&CP_TABLE);
    let Some((id, s)) = usize::try_from(id).ok().and_then(|i| Some((i, slot(i)?))) else { return false };
    if s.dataset.load(Ordering::Relaxed) == 0 {
        return false;
    }
    free_slot(&mut table, id, s);
    true
}

/// Empties a slot that holds a contact point (the table's lock is held).
fn free_slot(table: &mut CpTable, id: usize, s: &Slot) {
    let mut guard = s.lock();
    *guard = None;
    s.dataset.store(0, Ordering::Relaxed);
    // `lock` left no owner but possibly this thread; the slot starts over without one.
    s.owner.store(0, Ordering::Relaxed);
    drop(guard);
    table.free.insert(id);
}

/// Runs `f` on every contact point of a data set (`None`: of every data set).
fn for_each_cp_of(dataset: Option<c_int>, mut f: impl FnMut(&mut ContactPoint)) {
    let table = lock(&CP_TABLE);
    for i in 0..table.size {
        let Some(s) = slot(i) else { continue };
        let d = s.dataset.load(Ordering::Relaxed);
        if d != 0 && dataset.is_none_or(|want| want == d) {
            if let Some(cp) = s.lock().as_mut() {
                f(cp);
            }
        }
    }
}

/// Deletes the contact points of one data set, or all of them (and empties the table).
pub fn delete_cps_of(dataset: Option<c_int>) {
    let mut table = lock(&CP_TABLE);
    for i in 0..table.size {
        let Some(s) = slot(i) else { continue };
        let d = s.dataset.load(Ordering::Relaxed);
        if d != 0 && dataset.is_none_or(|want| want == d) {
            free_slot(&mut table, i, s);
        }
    }
    if dataset.is_none() {
        table.size = 0;
        table.free.clear();
    }
}

/// Applies `f` to every contact point.
pub fn update_all_cps(f: impl FnMut(&mut ContactPoint)) {
    for_each_cp_of(None, f);
}

#[cfg(test)]
mod tests {
    use super::*;
    use opencrg::settings::opt;
    use opencrg::synth::RoadSpec;

    fn new_cp() -> c_int {
        let road = RoadSpec::straight(10.0, 2.0, 0.5, 0.5).build().expect("a valid road");
        create_cp(add_dataset(road))
    }

    fn counter(cp: &ContactPoint) -> f64 {
        cp.options().get_double(opt::BORDER_OFFSET_U).unwrap_or(0.0)
    }

    /// Adds one to a counter kept in the contact point's options, by reading and
    /// writing it back (two steps: a second thread inside at the same time loses updates).
    fn bump(cp: &mut ContactPoint) {
        let v = counter(cp);
        // A wide window between the two steps, so that an overlap would show.
        for _ in 0..200 {
            std::hint::spin_loop();
        }
        cp.set_option_double(opt::BORDER_OFFSET_U, v + 1.0).expect("a double option");
    }

    #[test]
    fn a_thread_using_a_contact_point_becomes_its_owner() {
        // Where membarrier is refused nobody may become owner; the test then checks that.
        let owner_path = crate::barrier::available();
        if !owner_path {
            eprintln!("membarrier is not available here: checking that every call takes the lock");
        }
        let id = new_cp();
        let s = slot(id as usize).expect("a slot");
        assert_eq!(s.owner.load(Ordering::Relaxed), 0);
        for _ in 0..OWNER_STREAK {
            with_cp(id, bump);
        }
        let expected_owner = if owner_path { thread_id() } else { 0 };
        assert_eq!(s.owner.load(Ordering::Relaxed), expected_owner);
        std::thread::spawn(move || with_cp(id, bump)).join().expect("no panic");
        assert_eq!(s.owner.load(Ordering::Relaxed), 0, "another thread's access revokes the ownership");
        assert_eq!(with_cp(id, |cp| counter(cp)), Some(f64::from(OWNER_STREAK + 1)));
        assert!(delete_cp(id));
        assert_eq!(with_cp(id, |cp| counter(cp)), None);
    }

    #[test]
    fn threads_sharing_a_contact_point_never_overlap() {
        let id = new_cp();
        let (threads, rounds) = (4u32, 20_000u32);
        std::thread::scope(|scope| {
            for t in 0..threads {
                scope.spawn(move || {
                    for i in 0..rounds {
                        with_cp(id, bump);
                        // Runs of calls long enough to take ownership, then a switch.
                        if (i + t) % 50 == 0 {
                            std::thread::yield_now();
                        }
                    }
                });
            }
        });
        assert_eq!(with_cp(id, |cp| counter(cp)), Some(f64::from(threads * rounds)));
    }
}
