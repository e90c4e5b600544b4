//! Work done when the library is loaded, before `main` or before the loading
//! program's `dlopen`/`LoadLibrary` returns: the message shim gets its hooks (see
//! `msg`). ELF systems run the functions listed in `.init_array`; the C runtime of
//! Windows (MinGW's and Microsoft's alike) those in `.CRT$XCU`.

// (Not under Miri, which runs no C code: there is no shim to hook.)
#[cfg(not(miri))]
#[used]
#[cfg_attr(windows, link_section = ".CRT$XCU")]
#[cfg_attr(not(windows), link_section = ".init_array")]
static ON_LOAD: extern "C" fn() = crate::msg::install_hooks;

// Under Miri the hooks stay unused but compiled.
#[cfg(miri)]
const _: extern "C" fn() = crate::msg::install_hooks;
