//! Allocation of the large arrays evaluation reads at random: the elevation grid.
//!
//! Random queries over a grid of tens of megabytes miss the processor's address
//! translation cache on nearly every call when the grid sits in 4 KiB pages; in
//! 2 MiB pages a few dozen entries cover it. Where Linux offers transparent huge
//! pages on request (`madvise` mode) the grid's memory asks for them before it is
//! first written. Elsewhere nothing changes.

/// An empty vector with room for `capacity` values, its memory advised to use huge pages.
pub(crate) fn large_vec<T>(capacity: usize) -> Vec<T> {
    let v: Vec<T> = Vec::with_capacity(capacity);
    advise_huge_pages(v.as_ptr().cast(), v.capacity() * std::mem::size_of::<T>());
    v
}

/// A copy of `values` in memory advised to use huge pages.
pub(crate) fn large_copy<T: Copy>(values: &[T]) -> Vec<T> {
    let mut v = large_vec(values.len());
    v.extend_from_slice(values);
    v
}

#[cfg(target_os = "linux")]
fn advise_huge_pages(start: *const u8, len: usize) {
    const HUGE: usize = 2 << 20;
    let (first, end) = ((start as usize).next_multiple_of(HUGE), (start as usize + len) / HUGE * HUGE);
    if end > first {
        // SAFETY: the range lies inside an allocation this process owns; the advice
        // changes only how the kernel backs it, never its contents or its lifetime.
        // Refusal (huge pages disabled) is harmless and ignored.
        unsafe { libc::madvise(first as *mut libc::c_void, end - first, libc::MADV_HUGEPAGE) };
    }
}

#[cfg(not(target_os = "linux"))]
fn advise_huge_pages(_start: *const u8, _len: usize) {}
