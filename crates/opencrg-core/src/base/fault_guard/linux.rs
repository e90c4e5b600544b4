//! Linux: a SIGBUS at an address inside a guarded mapping gets a page of zeros mapped over
//! the page that faulted; any other goes to the handler that was there before.

use super::table;
use std::ffi::{c_int, c_void};
use std::sync::atomic::{AtomicPtr, AtomicUsize, Ordering};

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

/// Nothing to undo when a mapping is no longer guarded (its pages of zeros go with it).
pub(super) fn forget(_slot: usize) {}

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

/// The SIGBUS handler: a fault inside a guarded mapping gets a page of zeros and marks
/// the mapping; anything else goes on to the previous handler.
extern "C" fn on_fault(sig: c_int, info: *mut libc::siginfo_t, context: *mut c_void) {
    // SAFETY: the system hands a valid siginfo to a SA_SIGINFO handler.
    let (addr, code) = unsafe { ((*info).si_addr() as usize, (*info).si_code) };
    if code > 0 && table::fault_at(addr).is_some() {
        let page = PAGE.load(Ordering::Relaxed);
        // SAFETY: the page lies inside a mapping this library made and still holds (it is
        // registered); mapping zeros over it changes only what its readers see, and they
        // are told through `faulted`. mmap is a plain system call, safe in a signal
        // handler.
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
