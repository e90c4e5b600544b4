//! A file name from C as a path: the bytes as the platform's C library reads a name
//! given to `fopen`. On Unix they are the name itself; on Windows they are text in the
//! process's ANSI code page, turned into the UTF-16 name Windows stores.

use std::ffi::CStr;
use std::path::PathBuf;

/// The path `name` names.
#[cfg(unix)]
pub(crate) fn path_of(name: &CStr) -> PathBuf {
    use std::os::unix::ffi::OsStrExt;
    PathBuf::from(std::ffi::OsStr::from_bytes(name.to_bytes()))
}

/// The path `name` names.
#[cfg(windows)]
pub(crate) fn path_of(name: &CStr) -> PathBuf {
    use std::os::windows::ffi::OsStringExt;
    /// `CP_ACP`: the process's ANSI code page, as the C runtime's `fopen` uses.
    const ANSI_CODE_PAGE: u32 = 0;
    #[link(name = "kernel32")]
    extern "system" {
        fn MultiByteToWideChar(
            code_page: u32,
            flags: u32,
            text: *const u8,
            len: i32,
            wide: *mut u16,
            wide_len: i32,
        ) -> i32;
    }
    let bytes = name.to_bytes();
    let Ok(len) = i32::try_from(bytes.len()) else { return PathBuf::from(String::from_utf8_lossy(bytes).as_ref()) };
    if len == 0 {
        return PathBuf::new();
    }
    // SAFETY: `bytes` holds `len` bytes; a null output with length 0 asks for the size.
    let wide_len = unsafe { MultiByteToWideChar(ANSI_CODE_PAGE, 0, bytes.as_ptr(), len, std::ptr::null_mut(), 0) };
    let mut wide = vec![0u16; usize::try_from(wide_len).unwrap_or(0)];
    // SAFETY: `wide` has room for the `wide_len` units the first call asked for.
    let written = unsafe { MultiByteToWideChar(ANSI_CODE_PAGE, 0, bytes.as_ptr(), len, wide.as_mut_ptr(), wide_len) };
    wide.truncate(usize::try_from(written).unwrap_or(0));
    PathBuf::from(std::ffi::OsString::from_wide(&wide))
}
