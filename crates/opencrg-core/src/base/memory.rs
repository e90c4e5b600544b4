//! The memory of the large arrays evaluation reads: how the elevation grid is
//! allocated, how lookups ask for it ahead of time, how the pages of a mapped file
//! are given back once read, and how much memory the process can still get (the
//! platform differences of all four live here).
//!
//! Random queries over a grid of tens of megabytes miss the processor's address
//! translation cache on nearly every call when the grid sits in 4 KiB pages; in
//! 2 MiB pages a few dozen entries cover it. Where Linux offers transparent huge
//! pages on request (`madvise` mode) the grid's memory asks for them before it is
//! first written. Elsewhere nothing changes.

/// An empty vector with room for `capacity` values, its memory advised to use huge pages.
fn large_vec<T>(capacity: usize) -> Vec<T> {
    let v: Vec<T> = Vec::with_capacity(capacity);
    advise_huge_pages(v.as_ptr().cast(), v.capacity() * std::mem::size_of::<T>());
    v
}

/// `len` zeros in memory advised to use huge pages. Large blocks come from the system
/// already zeroed and are advised before their first use.
pub(crate) fn large_zeroed(len: usize) -> Vec<f32> {
    let v = vec![0.0f32; len];
    advise_huge_pages(v.as_ptr().cast(), v.len() * std::mem::size_of::<f32>());
    v
}

/// `len` atomics of value 0 in memory the system gives zeroed (only what is written is
/// backed), advised to use huge pages.
pub(crate) fn large_zeroed_atomics(len: usize) -> Box<[std::sync::atomic::AtomicU32]> {
    let mut v = std::mem::ManuallyDrop::new(vec![0u32; len]);
    advise_huge_pages(v.as_ptr().cast(), v.len() * std::mem::size_of::<u32>());
    // SAFETY: AtomicU32 has the size, alignment and bit validity of u32; the vector's
    // allocation is handed over whole.
    unsafe { Vec::from_raw_parts(v.as_mut_ptr().cast::<std::sync::atomic::AtomicU32>(), v.len(), v.capacity()) }
        .into_boxed_slice()
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

/// Lets the system drop the pages of `map` in `start..start + len` (page aligned) from
/// this process's memory: they have been read and will not be read again. Their file
/// stays in the system's cache; the mapping is read-only, so nothing can be lost.
/// Without such advice (Windows) the pages stay until the mapping is closed at the end
/// of the load.
#[cfg(unix)]
pub(crate) fn release_mapped(map: &memmap2::Mmap, start: usize, len: usize) {
    // SAFETY: DontNeed on a read-only shared file mapping only drops resident pages;
    // later reads fault them in again from the file.
    let _ = unsafe { map.unchecked_advise_range(memmap2::UncheckedAdvice::DontNeed, start, len) };
}

#[cfg(not(unix))]
pub(crate) fn release_mapped(_map: &memmap2::Mmap, _start: usize, _len: usize) {}

/// The bytes this process can still get: the least of the system's available memory,
/// the room left in its control group and under its address-space limit, where the
/// platform tells them; `None` where it tells none.
pub(crate) fn available_bytes() -> Option<u64> {
    [system_available(), group_room(), address_space_room()].into_iter().flatten().min()
}

/// Linux: `MemAvailable` of `/proc/meminfo` (what can be had without swapping).
#[cfg(target_os = "linux")]
fn system_available() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// Windows: the physical memory available (`GlobalMemoryStatusEx`).
#[cfg(windows)]
fn system_available() -> Option<u64> {
    #[repr(C)]
    struct MemoryStatusEx {
        length: u32,
        memory_load: u32,
        total_phys: u64,
        avail_phys: u64,
        total_page_file: u64,
        avail_page_file: u64,
        total_virtual: u64,
        avail_virtual: u64,
        avail_extended_virtual: u64,
    }
    #[link(name = "kernel32")]
    extern "system" {
        fn GlobalMemoryStatusEx(buffer: *mut MemoryStatusEx) -> i32;
    }
    let mut status = MemoryStatusEx {
        length: std::mem::size_of::<MemoryStatusEx>() as u32,
        memory_load: 0,
        total_phys: 0,
        avail_phys: 0,
        total_page_file: 0,
        avail_page_file: 0,
        total_virtual: 0,
        avail_virtual: 0,
        avail_extended_virtual: 0,
    };
    // SAFETY: the structure has the layout the call documents, its length field set as
    // it requires; the call writes only inside it.
    let ok = unsafe { GlobalMemoryStatusEx(&mut status) };
    (ok != 0).then_some(status.avail_phys.min(status.avail_virtual))
}

#[cfg(not(any(target_os = "linux", windows)))]
fn system_available() -> Option<u64> {
    None
}

/// Linux: the room under the memory limit of the process's control group (cgroup v2:
/// `memory.max` less `memory.current`), as containers set it.
#[cfg(target_os = "linux")]
fn group_room() -> Option<u64> {
    let own = std::fs::read_to_string("/proc/self/cgroup").ok()?;
    let path = own.lines().find_map(|l| l.strip_prefix("0::"))?;
    let dir = std::path::Path::new("/sys/fs/cgroup").join(path.trim_start_matches('/'));
    let read = |name: &str| std::fs::read_to_string(dir.join(name)).ok()?.trim().parse::<u64>().ok();
    let max = read("memory.max")?;
    Some(max.saturating_sub(read("memory.current").unwrap_or(0)))
}

#[cfg(not(target_os = "linux"))]
fn group_room() -> Option<u64> {
    None
}

/// Unix: the room under the address-space limit (`ulimit -v`) beyond what the process
/// maps already (Linux tells that in `/proc/self/statm`; elsewhere the limit itself).
#[cfg(unix)]
fn address_space_room() -> Option<u64> {
    let mut limit = libc::rlimit { rlim_cur: 0, rlim_max: 0 };
    // SAFETY: getrlimit writes one rlimit into the structure it is given.
    if unsafe { libc::getrlimit(libc::RLIMIT_AS, &mut limit) } != 0 || limit.rlim_cur == libc::RLIM_INFINITY {
        return None;
    }
    let mapped = std::fs::read_to_string("/proc/self/statm")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<u64>().ok())
        .map_or(0, |pages| {
            // SAFETY: sysconf only reads a system constant.
            pages * unsafe { libc::sysconf(libc::_SC_PAGESIZE) }.max(4096) as u64
        });
    Some(limit.rlim_cur.saturating_sub(mapped))
}

#[cfg(not(unix))]
fn address_space_room() -> Option<u64> {
    None
}

/// The cache a prefetch fills, as x86 numbers it: the first level (`_MM_HINT_T0`, on
/// Arm `PLDL1KEEP`) or the second (`_MM_HINT_T1`, `PLDL2KEEP`).
const FIRST_LEVEL: i32 = 3;
const SECOND_LEVEL: i32 = 2;

/// Asks the processor to start loading the cache line holding `p` into the cache
/// `LEVEL`. Never faults and reads nothing the program sees, whatever `p` is.
#[inline(always)]
fn prefetch_into<const LEVEL: i32, T>(p: *const T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch never faults and reads nothing the program sees; the address is
    // never dereferenced.
    unsafe {
        std::arch::x86_64::_mm_prefetch::<LEVEL>(p.cast())
    };
    #[cfg(target_arch = "aarch64")]
    // SAFETY: as above; `prfm` is a hint that never faults.
    unsafe {
        if LEVEL == FIRST_LEVEL {
            std::arch::asm!("prfm pldl1keep, [{0}]", in(reg) p, options(nostack, readonly, preserves_flags));
        } else {
            std::arch::asm!("prfm pldl2keep, [{0}]", in(reg) p, options(nostack, readonly, preserves_flags));
        }
    };
    #[cfg(not(any(target_arch = "x86_64", target_arch = "aarch64")))]
    let _ = p;
}

/// Asks the processor to start loading the cache line holding `p` into its caches.
#[inline(always)]
pub(crate) fn prefetch<T>(p: *const T) {
    prefetch_into::<FIRST_LEVEL, T>(p);
}

/// [`prefetch`] into the second-level cache only: for data needed after many other
/// loads have been started (a batch's cells blocks ahead). That cache tracks more
/// misses at once than the first, so more of them overlap.
#[inline(always)]
pub(crate) fn prefetch_far<T>(p: *const T) {
    prefetch_into::<SECOND_LEVEL, T>(p);
}

/// Asks the processor to start loading the cache line holding `p` into its first-level
/// cache to be written (x86 `prefetchw`, Arm `PSTL1KEEP`): for lines a pass writes soon,
/// many at once, more than the processor's own prefetcher follows. Never faults and
/// changes nothing the program sees, whatever `p` is.
#[inline(always)]
pub(crate) fn prefetch_for_write<T>(p: *const T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch never faults and changes nothing the program sees; the address
    // is never dereferenced.
    unsafe {
        std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_ET0 }>(p.cast())
    };
    #[cfg(target_arch = "aarch64")]
    // SAFETY: as above; `prfm` is a hint that never faults.
    unsafe {
        std::arch::asm!("prfm pstl1keep, [{0}]", in(reg) p, options(nostack, readonly, preserves_flags));
    };
    #[cfg(not(any(target_arch = "x86_64", target_arch = "aarch64")))]
    let _ = p;
}

/// `x` truncated to an index for a prefetch: out of range and NaN give some far index
/// (harmless there), without the work Rust's saturating conversion does.
#[inline(always)]
pub(crate) fn rough_index(x: f64) -> usize {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_cvttsd_si64, _mm_set_sd};
        // SAFETY: SSE2 is part of every x86_64 target.
        unsafe { _mm_cvttsd_si64(_mm_set_sd(x)) as usize }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        x as i64 as usize
    }
}
