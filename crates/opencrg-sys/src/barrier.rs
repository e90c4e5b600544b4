//! A memory barrier executed by every running thread of the process.
//!
//! The contact points' owner path (see `registry`) marks a slot busy with a plain
//! store and then reads whether its ownership still stands; a processor may let
//! that read pass the store. The rare thread that revokes an ownership makes up
//! for it by running a barrier on every thread at once: Linux's
//! `membarrier(MEMBARRIER_CMD_PRIVATE_EXPEDITED)` (on x86-64 and Arm alike: the kernel
//! runs a full barrier on every processor running a thread of the process), Windows'
//! `FlushProcessWriteBuffers` (the same guarantee, documented for exactly this use).
//! Where neither is available (another system, an old kernel, a sandbox refusing the
//! call) no thread is ever made owner and every access takes the lock.
//!
//! Under Miri (the model tests of the owner path: `cargo +nightly miri test -p
//! opencrg-sys --lib owner::`), which has no such call, the pair is modelled as the
//! memory model knows it: the barrier as a sequentially consistent fence, and the
//! owner's side ([`owner_side`]) as one too, which is what the barrier makes of the
//! owner's compiler fence on the processor that runs it. Miri then checks the protocol
//! with its data race detector and weak memory emulation.

use std::sync::atomic::{fence, Ordering};
use std::sync::OnceLock;

#[cfg(all(target_os = "linux", not(miri)))]
mod sys {
    use std::ffi::c_int;

    const PRIVATE_EXPEDITED: c_int = 1 << 3;
    const REGISTER_PRIVATE_EXPEDITED: c_int = 1 << 4;

    fn membarrier(cmd: c_int) -> bool {
        // SAFETY: membarrier takes no pointers; an unknown command only fails.
        unsafe { libc::syscall(libc::SYS_membarrier, cmd, 0 as c_int, 0 as c_int) == 0 }
    }

    pub fn register() -> bool {
        membarrier(REGISTER_PRIVATE_EXPEDITED)
    }

    pub fn run() -> bool {
        membarrier(PRIVATE_EXPEDITED)
    }
}

#[cfg(all(windows, not(miri)))]
mod sys {
    #[link(name = "kernel32")]
    extern "system" {
        fn FlushProcessWriteBuffers();
    }

    pub fn register() -> bool {
        true
    }

    pub fn run() -> bool {
        // SAFETY: no arguments, no preconditions; available since Windows Vista.
        unsafe { FlushProcessWriteBuffers() };
        true
    }
}

#[cfg(miri)]
mod sys {
    pub fn register() -> bool {
        true
    }

    pub fn run() -> bool {
        // The fences around this call in `everywhere` are the model of the barrier.
        true
    }
}

#[cfg(not(any(target_os = "linux", windows, miri)))]
mod sys {
    pub fn register() -> bool {
        false
    }

    pub fn run() -> bool {
        false
    }
}

static REGISTERED: OnceLock<bool> = OnceLock::new();

/// The owner's side of the barrier, between its busy mark and its check of the
/// ownership: keeps the compiler from moving the one across the other (the processor's
/// reordering is what [`everywhere`] covers, run by the thread that revokes).
#[inline(always)]
pub fn owner_side() {
    #[cfg(not(miri))]
    std::sync::atomic::compiler_fence(Ordering::SeqCst);
    #[cfg(miri)]
    fence(Ordering::SeqCst);
}

/// Whether [`everywhere`] can run (registers the process on first use).
pub fn available() -> bool {
    *REGISTERED.get_or_init(sys::register)
}

/// Runs a full memory barrier on every running thread of the process. Only called
/// after [`available`] said yes.
pub fn everywhere() {
    fence(Ordering::SeqCst);
    if !(available() && sys::run()) {
        // The kernel accepted the registration, after which the call cannot fail;
        // going on without the barrier could corrupt a contact point. Said on stderr, not
        // through the message callback: a lock is held here.
        eprintln!("FATAL: opencrg: membarrier failed after a successful registration; stopping");
        std::process::abort();
    }
    fence(Ordering::SeqCst);
}
