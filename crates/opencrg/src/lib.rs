//! OpenCRG road surfaces in pure Rust.
//!
//! [`Road::load`] reads a `.crg` file in any of the four formats (LRFI, LDFI, KRBI,
//! KDBI), following `$ROAD_CRG_FILE` references; [`ContactPoint`] evaluates it:
//! x/y from u/v, u/v from x/y, elevation, heading and curvature, with the options of
//! the classic OpenCRG C API. [`write()`] saves a road in any format.
//!
//! ```no_run
//! use std::sync::Arc;
//! let road = Arc::new(opencrg::Road::load("road.crg")?);
//! let mut cp = opencrg::ContactPoint::new(road);
//! let z = cp.uv_to_z(10.0, 0.5)?;
//! let (u, v) = cp.xy_to_uv(3.0, 4.0)?;
//! # Ok::<(), opencrg::Error>(())
//! ```
#![warn(missing_docs)]
// Comparisons like `!(x > 0.0)` are meant to reject NaN as well; they stay.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod batch;
mod check;
mod compat;
mod contact;
mod error;
pub mod eval;
pub mod grid;
pub mod header;
mod memory;
mod modifiers;
mod normal;
pub mod reader;
pub mod records;
pub mod refline;
pub mod report;
mod road;
pub mod search;
pub mod settings;
pub mod synth;
pub mod writer;

pub use compat::{Compat, UnknownCompat};
pub use contact::ContactPoint;
pub use error::{Error, Location, Result};
pub use header::DataFormat;
pub use road::{LoadOptions, Road};
pub use settings::{Settings, Value};
pub use writer::write;

/// The README's Rust code, compiled by `cargo test` as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;
