//! The classic OpenCRG C API (`crgBaseLib.h`) over the `opencrg` crate.
//!
//! A thin translation layer: ids to handles, pointers to references, `Result` to
//! 1/0. Global state (the id tables, the message settings, the allocator hooks)
//! exists only here, behind locks, because the classic API demands ids.

mod alloc;
mod api;
mod barrier;
mod c_path;
mod constants;
mod extensions;
mod georef;
mod lock;
mod msg;
mod msg_entry;
mod odr;
mod on_load;
mod owner;
mod panic;
mod perf_stat;
mod profile;
mod ptr;
mod registry;
mod report;
mod slots;
mod thread_id;

pub use api::*;
pub use constants::*;
pub use extensions::*;
pub use georef::*;
pub use msg_entry::crgMsgPrint;
pub use odr::*;
