//! The classic OpenCRG C API (`crgBaseLib.h`) and the OpenDRIVE calls of `crgOdr.h`,
//! over the `opencrg-core` and `opencrg-odr` crates.
//!
//! A thin translation layer: ids to handles, pointers to references, `Result` to
//! 1/0. Global state (the id tables, the message settings, the allocator hooks)
//! exists only here, behind locks, because the classic API demands ids. Every export
//! answers through `entry`: one panic guard, its messages sent through the call, none
//! of them while a lock is held.

// The exports, in the order the header declares them (cbindgen reads the modules in this
// order).
mod loading;

mod data_sets;

mod messages;

mod alloc;

mod numbers;

mod contact_points;

mod evaluation;

mod extensions;

mod georef;

mod odr;

mod perf_stat;

// What they stand on.
mod barrier;
mod c_path;
mod compat;
mod constants;
mod entry;
mod lock;
mod msg;
mod msg_entry;
mod on_load;
mod owner;
mod ptr;
mod registry;
mod report;
mod slots;
mod thread_id;

pub use alloc::*;
pub use constants::*;
pub use contact_points::*;
pub use data_sets::*;
pub use evaluation::*;
pub use extensions::*;
pub use georef::*;
pub use loading::*;
pub use messages::*;
pub use msg_entry::crgMsgPrint;
pub use numbers::*;
pub use odr::*;
pub use perf_stat::*;
