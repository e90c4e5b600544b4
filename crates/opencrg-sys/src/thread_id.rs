//! This thread's id, for the contact points' owner path (see `owner`): non-zero and
//! unique among running threads. An id is reused only after its thread ended, and an
//! ended thread owns no contact point it is still working in.
//!
//! Where the platform keeps a per-thread pointer in a register, the id is that pointer,
//! read without a call: the thread control block's self-reference on x86_64 Linux
//! (`fs:0`, what `pthread_self` returns with glibc and musl), the thread pointer on
//! 64-bit Arm Linux (`tpidr_el0`), the thread environment block's self-reference on
//! 64-bit Windows (`gs:0x30`). Elsewhere (and under Miri, which runs no assembly), the
//! address of a thread-local byte.

/// This thread's id (see the module's text).
#[inline(always)]
pub(crate) fn thread_id() -> usize {
    let id: usize;
    #[cfg(all(target_arch = "x86_64", target_os = "linux", not(miri)))]
    // SAFETY: fs:0 always holds the thread control block's own address there; reading
    // it has no side effects.
    unsafe {
        std::arch::asm!("mov {}, fs:0", out(reg) id, options(nostack, readonly, preserves_flags, pure))
    };
    #[cfg(all(target_arch = "aarch64", target_os = "linux", not(miri)))]
    // SAFETY: reading the thread pointer register has no side effects; the C library
    // sets it to the thread's own control block before the thread runs any code.
    unsafe {
        std::arch::asm!("mrs {}, tpidr_el0", out(reg) id, options(nomem, nostack, preserves_flags, pure))
    };
    #[cfg(all(target_arch = "x86_64", windows, not(miri)))]
    // SAFETY: gs:0x30 always holds the thread environment block's own address on 64-bit
    // Windows; reading it has no side effects.
    unsafe {
        std::arch::asm!("mov {}, gs:0x30", out(reg) id, options(nostack, readonly, preserves_flags, pure))
    };
    #[cfg(any(
        miri,
        not(any(
            all(target_arch = "x86_64", target_os = "linux"),
            all(target_arch = "aarch64", target_os = "linux"),
            all(target_arch = "x86_64", windows)
        ))
    ))]
    {
        thread_local!(static MARK: u8 = const { 0 });
        id = MARK.with(|m| m as *const u8 as usize);
    }
    id
}

#[cfg(test)]
mod tests {
    use super::thread_id;

    /// Each thread has its own non-zero id, the same at every call.
    #[test]
    fn ids_differ_between_running_threads() {
        let mine = thread_id();
        assert_ne!(mine, 0);
        assert_eq!(mine, thread_id());
        let barrier = std::sync::Barrier::new(4);
        let ids: Vec<usize> = std::thread::scope(|s| {
            let handles: Vec<_> = (0..4)
                .map(|_| {
                    s.spawn(|| {
                        barrier.wait();
                        let id = thread_id();
                        barrier.wait();
                        id
                    })
                })
                .collect();
            handles.into_iter().map(|h| h.join().unwrap()).collect()
        });
        for (i, a) in ids.iter().enumerate() {
            assert_ne!(*a, 0);
            assert_ne!(*a, mine);
            assert!(ids[i + 1..].iter().all(|b| b != a), "{ids:?}");
        }
    }
}
