//! `crgMsgPrint`, the API's one variadic function. Stable Rust cannot define a variadic
//! function, so the C shim defines it (as the hidden `opencrg_msg_print`) and the
//! exported symbol is this entry, which jumps there with every register and the stack
//! untouched: the arguments arrive as the caller passed them, under every calling
//! convention. Being a Rust function, it is exported with the others (rustc writes the
//! export list, on Linux and Windows alike), so the library needs no second one.

use std::ffi::{c_char, c_int};

#[cfg(not(any(target_arch = "x86_64", target_arch = "aarch64")))]
compile_error!("crgMsgPrint's entry (src/msg_entry.rs) has a jump for x86_64 and aarch64 only: add this processor's");

extern "C" {
    /// The shim's `crgMsgPrint` (csrc/msg_shim.c).
    pub(crate) fn opencrg_msg_print(level: c_int, format: *const c_char, ...);
}

/// Prints a message of the given level (printf-style), or hands it to the callback set
/// with `crgMsgSetCallback`: `void crgMsgPrint(int level, const char *format, ...)`.
///
/// # Safety
/// Called from C as the header declares it: `format` null or a printf format whose
/// conversions match the arguments that follow.
#[unsafe(naked)]
#[no_mangle]
pub unsafe extern "C" fn crgMsgPrint() {
    #[cfg(target_arch = "x86_64")]
    std::arch::naked_asm!("jmp {print}", print = sym opencrg_msg_print);
    #[cfg(target_arch = "aarch64")]
    std::arch::naked_asm!("b {print}", print = sym opencrg_msg_print);
}
