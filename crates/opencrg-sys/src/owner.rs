//! A cell that one thread at a time may use, with a fast way for the thread that uses it
//! most: the lock-free *owner* path of the contact points.
//!
//! Access is guarded in two ways. The general way is a small lock: a flag taken with one
//! compare-and-swap. The fast way is for the cell's *owner*, the thread that used it for
//! the last several accesses in a row: it marks the cell busy with plain stores and no
//! atomic read-modify-write, which keeps the evaluation calls (millions per second, from
//! one thread per contact point) free of locked instructions. Any other thread first
//! takes the lock and revokes the ownership: it clears `owner`, forces a memory barrier on
//! every thread of the process (see [`crate::barrier`]) and waits until the owner is out
//! of the cell. Either the owner then sees the revocation before it touches the value, or
//! the revoker sees the owner's busy mark and waits.

use crate::thread_id::thread_id;
use std::cell::UnsafeCell;
use std::ops::{Deref, DerefMut};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// Locked accesses in a row by one thread after which it becomes the owner.
pub(crate) const OWNER_STREAK: u32 = 8;

/// A value reached by one thread at a time: through the lock, or the owner's way.
pub(crate) struct OwnedCell<T> {
    /// The owner's thread id, 0 when the cell has none.
    owner: AtomicUsize,
    /// Set by the owner while it works on the value the fast way.
    owner_busy: AtomicBool,
    /// The lock of every other access.
    locked: AtomicBool,
    /// Which thread made the last locked accesses, and how many in a row (guarded by `locked`).
    streak: UnsafeCell<(usize, u32)>,
    value: UnsafeCell<T>,
}

// SAFETY: `value` and `streak` are only reached through `Guard` (which holds the lock,
// with no owner left in the cell) or through the owner's path (with the busy mark set
// while ownership stands), never both at once (see the module's text). The value moves
// between threads, hence `T: Send`.
unsafe impl<T: Send> Sync for OwnedCell<T> {}

/// Waits a little: spins at first, then lets other threads run (the one being waited
/// for may have been descheduled).
fn back_off(spins: &mut u32) {
    *spins += 1;
    if *spins < 64 {
        std::hint::spin_loop();
    } else {
        std::thread::yield_now();
    }
}

/// The exclusive access to a cell's value through the lock.
pub(crate) struct Guard<'a, T>(&'a OwnedCell<T>);

/// The owner's busy mark; cleared when dropped (also when the access panics).
struct OwnerMark<'a, T>(&'a OwnedCell<T>);

impl<T> Drop for OwnerMark<'_, T> {
    fn drop(&mut self) {
        self.0.owner_busy.store(false, Ordering::Release);
    }
}

impl<T> OwnedCell<T> {
    /// A cell with no owner.
    pub(crate) fn new(value: T) -> Self {
        OwnedCell {
            owner: AtomicUsize::new(0),
            owner_busy: AtomicBool::new(false),
            locked: AtomicBool::new(false),
            streak: UnsafeCell::new((0, 0)),
            value: UnsafeCell::new(value),
        }
    }

    /// Runs `f` with exclusive access, the owner's way when this thread owns the cell,
    /// else through the lock (counted towards ownership).
    #[inline]
    pub(crate) fn with_mut<R>(&self, f: impl FnOnce(&mut T) -> R) -> R {
        let me = thread_id();
        // Exclusive access one way or the other, held until this function returns.
        let _access = self.enter_as_owner(me).ok_or_else(|| self.lock_for(me));
        // SAFETY: `_access` grants exclusive access to the value while it lives.
        f(unsafe { &mut *self.value.get() })
    }

    /// Runs `f` with exclusive access to the value when this thread owns the cell;
    /// `None` (without running `f`) otherwise: no lock and no call.
    #[inline(always)]
    pub(crate) fn with_owned_mut<R>(&self, f: impl FnOnce(&mut T) -> R) -> Option<R> {
        let _busy = self.enter_as_owner(thread_id())?;
        // SAFETY: the owner's busy mark is set while ownership stands: no other access
        // to the value exists until it is cleared.
        Some(f(unsafe { &mut *self.value.get() }))
    }

    /// Marks the cell busy the owner's way; `None` when this thread is not the owner.
    #[inline]
    fn enter_as_owner(&self, me: usize) -> Option<OwnerMark<'_, T>> {
        if self.owner.load(Ordering::Relaxed) != me {
            return None;
        }
        self.owner_busy.store(true, Ordering::Relaxed);
        let busy = OwnerMark(self);
        // The busy store stays before the check below (see `barrier::owner_side`).
        crate::barrier::owner_side();
        (self.owner.load(Ordering::Acquire) == me).then_some(busy)
    }

    /// Takes the lock for a thread that is not the owner, and counts the access.
    #[inline(never)]
    fn lock_for(&self, me: usize) -> Guard<'_, T> {
        let mut guard = self.lock();
        guard.count_access(me);
        guard
    }

    /// Takes the lock and makes sure no owner works in the cell.
    pub(crate) fn lock(&self) -> Guard<'_, T> {
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
        Guard(self)
    }

    /// The owning thread's id, 0 for none.
    #[cfg(test)]
    pub(crate) fn owner(&self) -> usize {
        self.owner.load(Ordering::Relaxed)
    }
}

impl<T> Guard<'_, T> {
    /// Counts this locked access by thread `me`; after enough of them in a row, makes it
    /// the owner (when the process can revoke ownership).
    pub(crate) fn count_access(&mut self, me: usize) {
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

    /// Leaves the cell without an owner (and without a streak): for a value replaced.
    pub(crate) fn disown(&mut self) {
        // `lock` left no owner but possibly this thread.
        self.0.owner.store(0, Ordering::Relaxed);
        // SAFETY: the lock is held.
        unsafe { *self.0.streak.get() = (0, 0) };
    }
}

impl<T> Deref for Guard<'_, T> {
    type Target = T;
    fn deref(&self) -> &T {
        // SAFETY: this guard holds the cell's lock and no owner works in the cell.
        unsafe { &*self.0.value.get() }
    }
}

impl<T> DerefMut for Guard<'_, T> {
    fn deref_mut(&mut self) -> &mut T {
        // SAFETY: this guard holds the cell's lock and no owner works in the cell.
        unsafe { &mut *self.0.value.get() }
    }
}

impl<T> Drop for Guard<'_, T> {
    fn drop(&mut self) {
        self.0.locked.store(false, Ordering::Release);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Adds one in two steps, with a wide window between them: two threads inside at
    /// the same time would lose updates.
    fn bump(value: &mut u64) {
        let v = *value;
        for _ in 0..200 {
            std::hint::spin_loop();
        }
        *value = v + 1;
    }

    #[test]
    fn a_thread_that_keeps_using_the_cell_owns_it_until_another_comes() {
        // Where membarrier is refused nobody may become owner; the test then checks that.
        let owner_path = crate::barrier::available();
        let cell = OwnedCell::new(0u64);
        assert_eq!(cell.owner(), 0);
        assert_eq!(cell.with_owned_mut(|v| *v), None, "no owner yet");
        for _ in 0..OWNER_STREAK {
            cell.with_mut(bump);
        }
        assert_eq!(cell.owner(), if owner_path { thread_id() } else { 0 });
        assert_eq!(cell.with_owned_mut(|v| *v), owner_path.then_some(u64::from(OWNER_STREAK)));
        std::thread::scope(|s| {
            s.spawn(|| cell.with_mut(bump));
        });
        assert_eq!(cell.owner(), 0, "another thread's access revokes the ownership");
        assert_eq!(cell.with_owned_mut(|v| *v), None);
        assert_eq!(cell.lock().clone(), u64::from(OWNER_STREAK + 1));
    }

    #[test]
    fn threads_sharing_the_cell_never_overlap() {
        let cell = OwnedCell::new(0u64);
        // (Miri interprets every instruction: fewer rounds, still many switches.)
        let (threads, rounds) = (4u64, if cfg!(miri) { 100 } else { 20_000u64 });
        std::thread::scope(|scope| {
            for t in 0..threads {
                let cell = &cell;
                scope.spawn(move || {
                    for i in 0..rounds {
                        cell.with_mut(bump);
                        // Runs of accesses long enough to take ownership, then a switch.
                        if (i + t) % 50 == 0 {
                            std::thread::yield_now();
                        }
                    }
                });
            }
        });
        assert_eq!(*cell.lock(), threads * rounds);
    }

    #[test]
    fn disowning_clears_the_owner() {
        let cell = OwnedCell::new(0u64);
        for _ in 0..OWNER_STREAK {
            cell.with_mut(bump);
        }
        cell.lock().disown();
        assert_eq!(cell.owner(), 0);
        assert_eq!(cell.with_owned_mut(|v| *v), None);
    }
}
