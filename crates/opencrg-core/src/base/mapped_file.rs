//! A file read through a read-only memory mapping: its pages come from the system's
//! cache, which every process mapping the same file shares, and are read only where
//! they are touched. What can go wrong while it is open is told, never fatal: a read of
//! a part cut off the file (see `fault_guard`), and a file changed in place since it
//! was opened (its size or modification time differ); [`MappedFile::check`] tells
//! both, and a reader checks after it has read.

use crate::base::fault_guard::{self, Registration};
use std::time::SystemTime;

/// What went wrong with a mapped file after it was opened.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Fault {
    /// A read reached a part that is no longer there (the file was cut short) or that
    /// the device could not read.
    Cut,
    /// The file was changed in place (another size or modification time).
    Changed,
}

impl Fault {
    /// The fault as an I/O error, for the message that names the file.
    pub(crate) fn into_io(self) -> std::io::Error {
        std::io::Error::new(
            std::io::ErrorKind::UnexpectedEof,
            match self {
                Fault::Cut => "the file was cut short (or could not be read) while it was open",
                Fault::Changed => "the file was changed while it was open",
            },
        )
    }
}

/// A file's size and modification time, as they were when it was opened.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Stamp {
    len: u64,
    modified: Option<SystemTime>,
}

impl Stamp {
    fn of(meta: &std::fs::Metadata) -> Stamp {
        Stamp { len: meta.len(), modified: meta.modified().ok() }
    }
}

/// A file mapped read-only, with the guard that catches faults on it.
#[derive(Debug)]
pub(crate) struct MappedFile {
    // Dropped first: the guard forgets the range before it is unmapped.
    guard: Option<Registration>,
    map: memmap2::Mmap,
    file: std::fs::File,
    stamp: Stamp,
}

impl MappedFile {
    /// Maps `file` (not empty).
    pub(crate) fn open(file: std::fs::File) -> std::io::Result<MappedFile> {
        let stamp = Stamp::of(&file.metadata()?);
        // SAFETY: the mapping is read-only; a file changed by another process while it is
        // mapped changes the bytes read (told by `check`), and a part cut off it faults
        // into the guard (told by `check`), never into memory safety of this process.
        let map = unsafe { memmap2::Mmap::map(&file)? };
        let guard = fault_guard::register(map.as_ptr(), map.len());
        Ok(MappedFile { guard, map, file, stamp })
    }

    /// The file's bytes as they are read: where a read faults, zeros (see
    /// [`MappedFile::check`]).
    #[inline]
    pub(crate) fn bytes(&self) -> &[u8] {
        &self.map
    }

    /// Whether what was read so far can be trusted: a fault on the mapping since it was
    /// opened, or the file changed since then, is told. A system call (the file's status):
    /// once per batch of reads.
    pub(crate) fn check(&self) -> Result<(), Fault> {
        if self.guard.as_ref().is_some_and(Registration::faulted) {
            return Err(Fault::Cut);
        }
        match self.file.metadata() {
            Ok(meta) if Stamp::of(&meta) == self.stamp => Ok(()),
            Ok(meta) if meta.len() < self.stamp.len => Err(Fault::Cut),
            _ => Err(Fault::Changed),
        }
    }

    /// Whether a fault on the mapping was caught since it was opened (no system call).
    #[inline]
    pub(crate) fn faulted(&self) -> bool {
        self.guard.as_ref().is_some_and(Registration::faulted)
    }

    /// Lets the system drop the pages in `start..end` from this process's memory: they
    /// were read and are not needed soon. The file stays in the system's cache.
    pub(crate) fn release(&self, start: usize, end: usize) {
        const PAGE: usize = 4096;
        let (first, last) = (start.div_ceil(PAGE) * PAGE, (end / PAGE * PAGE).min(self.map.len()));
        if last > first {
            crate::base::memory::release_mapped(&self.map, first, last - first);
        }
    }
}
