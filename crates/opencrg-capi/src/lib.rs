//! The C libraries `libopencrg.so` and `libopencrg.a`: every function and constant of
//! `opencrg-sys` (the classic API and its extensions, `crgBaseLib.h`), nothing else.

pub use opencrg_sys::*;
