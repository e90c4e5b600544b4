//! The guard that keeps a fault on a mapped file from ending the process (the platform
//! difference of reading files in place lives here: `linux` and `windows`, each the
//! handler of its platform's fault).
//!
//! Reading a page of a mapped file that was cut short, or that the device cannot read (a
//! disk error, a network share gone), raises SIGBUS on Linux and an in-page error on
//! Windows, either of which ends the process. While a mapping is registered here, such a
//! fault at an address inside it is answered instead: the mapping is marked as faulted,
//! what the read reaches is replaced by zeros, and the read that faulted goes on (reading
//! zeros). Whoever reads the mapping asks [`Registration::faulted`] after its reads and
//! throws away what it read when they faulted. A fault anywhere else goes on as it would
//! have (to the handler that was there before, or ending the process).
//!
//! This is the one process-wide state of the evaluator: fault handlers belong to the
//! process. It is installed the first time a file is mapped, holds only the address
//! ranges of the open mappings, and keeps the library that holds it loaded (a handler
//! must not point into a library that is unloaded, as an FMU's may be).
//!
//! Elsewhere (macOS, the other Unixes) nothing is guarded.

#[cfg(target_os = "linux")]
mod linux;
#[cfg(windows)]
mod windows;
#[cfg(target_os = "linux")]
use linux as platform;
#[cfg(windows)]
use windows as platform;

/// A mapping registered with the guard, until dropped.
#[derive(Debug)]
pub(crate) struct Registration {
    #[cfg(any(target_os = "linux", windows))]
    slot: usize,
}

/// Registers the mapping at `start` of `len` bytes. `None` when the guard has no room left
/// (or the platform has none): the mapping is then read unguarded.
#[cfg(any(target_os = "linux", windows))]
pub(crate) fn register(start: *const u8, len: usize) -> Option<Registration> {
    platform::install();
    table::register(start as usize, len).map(|slot| Registration { slot })
}

/// Registers nothing where the platform's faults are not handled.
#[cfg(not(any(target_os = "linux", windows)))]
pub(crate) fn register(_start: *const u8, _len: usize) -> Option<Registration> {
    None
}

impl Registration {
    /// Whether a read of the mapping has faulted since it was registered (it stays so).
    #[inline]
    pub(crate) fn faulted(&self) -> bool {
        #[cfg(any(target_os = "linux", windows))]
        {
            table::faulted(self.slot)
        }
        #[cfg(not(any(target_os = "linux", windows)))]
        {
            false
        }
    }
}

#[cfg(any(target_os = "linux", windows))]
impl Drop for Registration {
    fn drop(&mut self) {
        platform::forget(self.slot);
        table::unregister(self.slot);
    }
}

/// The address ranges of the guarded mappings, which the handlers read.
#[cfg(any(target_os = "linux", windows))]
mod table {
    use std::sync::atomic::{fence, AtomicBool, AtomicUsize, Ordering};

    /// How many mappings can be guarded at once.
    pub(super) const SLOTS: usize = 1024;

    /// One guarded mapping: its address range (`start` 0 while the slot is free) and
    /// whether a read of it faulted.
    struct Slot {
        taken: AtomicBool,
        start: AtomicUsize,
        end: AtomicUsize,
        faulted: AtomicBool,
    }

    #[allow(clippy::declare_interior_mutable_const)] // each slot of the table is its own
    const FREE: Slot = Slot {
        taken: AtomicBool::new(false),
        start: AtomicUsize::new(0),
        end: AtomicUsize::new(0),
        faulted: AtomicBool::new(false),
    };

    static TABLE: [Slot; SLOTS] = [FREE; SLOTS];

    /// Takes a free slot for the mapping at `start` of `len` bytes; `None` where all are
    /// taken.
    pub(super) fn register(start: usize, len: usize) -> Option<usize> {
        let i = TABLE
            .iter()
            .position(|s| s.taken.compare_exchange(false, true, Ordering::AcqRel, Ordering::Relaxed).is_ok())?;
        let slot = &TABLE[i];
        slot.faulted.store(false, Ordering::Relaxed);
        slot.end.store(start + len, Ordering::Relaxed);
        slot.start.store(start, Ordering::Release);
        Some(i)
    }

    /// Frees slot `i` (its mapping is about to be unmapped).
    pub(super) fn unregister(i: usize) {
        let slot = &TABLE[i];
        slot.start.store(0, Ordering::Release);
        slot.taken.store(false, Ordering::Release);
    }

    /// Whether a read of slot `i`'s mapping faulted since it was registered.
    #[inline]
    pub(super) fn faulted(i: usize) -> bool {
        // The reads of the mapping come before this load: a fault they met was answered
        // (in this thread, or in another that replaced what they read) before it.
        fence(Ordering::Acquire);
        TABLE[i].faulted.load(Ordering::Relaxed)
    }

    /// The slot of the guarded mapping holding `addr`, marked as faulted, and the
    /// mapping's range; `None` where no guarded mapping holds it. Safe in a fault handler
    /// (atomic loads and stores only).
    pub(super) fn fault_at(addr: usize) -> Option<(usize, usize, usize)> {
        TABLE.iter().enumerate().find_map(|(i, slot)| {
            let start = slot.start.load(Ordering::Acquire);
            let end = slot.end.load(Ordering::Relaxed);
            (start != 0 && addr >= start && addr < end).then(|| {
                slot.faulted.store(true, Ordering::SeqCst);
                (i, start, end - start)
            })
        })
    }

    /// The range of the mapping of slot `i` (`start` 0 where it is free).
    #[cfg(windows)]
    pub(super) fn range(i: usize) -> (usize, usize) {
        let slot = &TABLE[i];
        let start = slot.start.load(Ordering::Acquire);
        (start, slot.end.load(Ordering::Relaxed).saturating_sub(start))
    }
}
