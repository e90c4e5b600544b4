//! The guard that keeps a fault on a mapped file from ending the process (the platform
//! difference of reading files in place lives here).
//!
//! Reading a page of a mapped file that was cut short (or that the device cannot read)
//! raises SIGBUS on Linux, which ends the process. While a mapping is registered here, a
//! SIGBUS at an address inside it is answered instead: the page is replaced by a page of
//! zeros, the mapping is marked as faulted, and the read that faulted goes on (reading
//! zeros). Whoever reads the mapping asks [`Registration::faulted`] after its reads and
//! throws away what it read when they faulted. A SIGBUS anywhere else goes to the handler
//! that was there before (or ends the process as it would have).
//!
//! This is the one process-wide state of the evaluator: signal handlers belong to the
//! process. It is installed the first time a file is mapped, holds only the address
//! ranges of the open mappings, and keeps the library that holds it loaded (a handler
//! must not point into a library that is unloaded, as an FMU's may be).
//!
//! Elsewhere nothing is guarded: Windows refuses to cut short a mapped file.

/// A mapping registered with the guard, until dropped.
#[derive(Debug)]
pub(crate) struct Registration {
    #[cfg(target_os = "linux")]
    slot: usize,
}

/// Registers the mapping at `start` of `len` bytes. `None` when the guard has no room left
/// (or the platform has none): the mapping is then read unguarded.
#[cfg(target_os = "linux")]
pub(crate) fn register(start: *const u8, len: usize) -> Option<Registration> {
    linux::install();
    linux::register(start as usize, len).map(|slot| Registration { slot })
}

/// Registers nothing where faults on mapped files are not signals.
#[cfg(not(target_os = "linux"))]
pub(crate) fn register(_start: *const u8, _len: usize) -> Option<Registration> {
    None
}

impl Registration {
    /// Whether a read of the mapping has faulted since it was registered (it stays so).
    #[inline]
    pub(crate) fn faulted(&self) -> bool {
        #[cfg(target_os = "linux")]
        {
            linux::faulted(self.slot)
        }
        #[cfg(not(target_os = "linux"))]
        {
            false
        }
    }
}

#[cfg(target_os = "linux")]
impl Drop for Registration {
    fn drop(&mut self) {
        linux::unregister(self.slot);
    }
}

#[cfg(target_os = "linux")]
mod linux {
    use std::ffi::{c_int, c_void};
    use std::sync::atomic::{fence, AtomicBool, AtomicPtr, AtomicUsize, Ordering};

    /// How many mappings can be guarded at once.
    const SLOTS: usize = 1024;

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
    /// The handler that was installed before ours (null: the default action).
    static PREVIOUS: AtomicPtr<libc::sigaction> = AtomicPtr::new(std::ptr::null_mut());
    /// The system's page size.
    static PAGE: AtomicUsize = AtomicUsize::new(4096);
    static INSTALL: std::sync::Once = std::sync::Once::new();

    /// Installs the handler once.
    pub(super) fn install() {
        INSTALL.call_once(|| {
            keep_loaded();
            // SAFETY: sysconf reads a constant; sigaction reads and writes the structures
            // it is given, which are plain data zeroed before use.
            unsafe {
                let page = libc::sysconf(libc::_SC_PAGESIZE);
                if page > 0 {
                    PAGE.store(page as usize, Ordering::Relaxed);
                }
                let mut old: libc::sigaction = std::mem::zeroed();
                if libc::sigaction(libc::SIGBUS, std::ptr::null(), &mut old) != 0 {
                    return;
                }
                PREVIOUS.store(Box::into_raw(Box::new(old)), Ordering::Release);
                let mut new: libc::sigaction = std::mem::zeroed();
                new.sa_sigaction = on_fault as *const () as usize;
                new.sa_flags = libc::SA_SIGINFO | libc::SA_ONSTACK | libc::SA_NODEFER;
                libc::sigemptyset(&mut new.sa_mask);
                libc::sigaction(libc::SIGBUS, &new, std::ptr::null_mut());
            }
        });
    }

    /// Marks the library holding this code as never to be unloaded (its handler stays
    /// installed after an FMU or a Python module is released).
    fn keep_loaded() {
        // SAFETY: dladdr fills the structure for an address of this library; dlopen with
        // RTLD_NOLOAD only takes another reference to a library already loaded, which is
        // never released.
        unsafe {
            let mut info: libc::Dl_info = std::mem::zeroed();
            if libc::dladdr(on_fault as *const c_void, &mut info) != 0 && !info.dli_fname.is_null() {
                libc::dlopen(info.dli_fname, libc::RTLD_NOW | libc::RTLD_NOLOAD | libc::RTLD_NODELETE);
            }
        }
    }

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

    pub(super) fn unregister(i: usize) {
        let slot = &TABLE[i];
        slot.start.store(0, Ordering::Release);
        slot.taken.store(false, Ordering::Release);
    }

    #[inline]
    pub(super) fn faulted(i: usize) -> bool {
        // The reads of the mapping come before this load: a fault they met was answered
        // (in this thread, or in another that replaced the page they read) before it.
        fence(Ordering::Acquire);
        TABLE[i].faulted.load(Ordering::Relaxed)
    }

    /// The SIGBUS handler: a fault inside a guarded mapping gets a page of zeros and marks
    /// the mapping; anything else goes on to the previous handler.
    extern "C" fn on_fault(sig: c_int, info: *mut libc::siginfo_t, context: *mut c_void) {
        // SAFETY: the system hands a valid siginfo to a SA_SIGINFO handler.
        let (addr, code) = unsafe { ((*info).si_addr() as usize, (*info).si_code) };
        if code > 0 {
            for slot in &TABLE {
                let start = slot.start.load(Ordering::Acquire);
                if start != 0 && addr >= start && addr < slot.end.load(Ordering::Relaxed) {
                    slot.faulted.store(true, Ordering::SeqCst);
                    let page = PAGE.load(Ordering::Relaxed);
                    // SAFETY: the page lies inside a mapping this library made and still
                    // holds (it is registered); mapping zeros over it changes only what its
                    // readers see, and they are told through `faulted`. mmap is a plain
                    // system call, safe in a signal handler.
                    let p = unsafe {
                        libc::mmap(
                            (addr & !(page - 1)) as *mut c_void,
                            page,
                            libc::PROT_READ,
                            libc::MAP_PRIVATE | libc::MAP_ANONYMOUS | libc::MAP_FIXED,
                            -1,
                            0,
                        )
                    };
                    if p != libc::MAP_FAILED {
                        return;
                    }
                    break;
                }
            }
        }
        // SAFETY: the previous handler was read from the system; calling it with the
        // arguments the system gave ours is what the system would have done.
        unsafe { chain(sig, info, context) };
    }

    /// Hands the signal to the handler installed before ours; for the default action (or
    /// none), restores it so that the fault ends the process as it would have.
    unsafe fn chain(sig: c_int, info: *mut libc::siginfo_t, context: *mut c_void) {
        let previous = PREVIOUS.load(Ordering::Acquire);
        // SAFETY: set once from the system's own structure, never freed.
        if let Some(p) = unsafe { previous.as_ref() } {
            let handler = p.sa_sigaction;
            if handler != libc::SIG_DFL && handler != libc::SIG_IGN {
                if p.sa_flags & libc::SA_SIGINFO != 0 {
                    // SAFETY: a SA_SIGINFO handler has this signature.
                    let f: extern "C" fn(c_int, *mut libc::siginfo_t, *mut c_void) =
                        unsafe { std::mem::transmute(handler) };
                    f(sig, info, context);
                } else {
                    // SAFETY: a plain handler has this signature.
                    let f: extern "C" fn(c_int) = unsafe { std::mem::transmute(handler) };
                    f(sig);
                }
                return;
            }
        }
        // SAFETY: restoring the default action; a signal that was sent, not raised by a
        // fault, is raised again to take it.
        unsafe {
            let mut default: libc::sigaction = std::mem::zeroed();
            default.sa_sigaction = libc::SIG_DFL;
            libc::sigemptyset(&mut default.sa_mask);
            libc::sigaction(sig, &default, std::ptr::null_mut());
            if (*info).si_code <= 0 {
                libc::raise(sig);
            }
        }
    }
}
