//! OpenCRG road surfaces in pure Rust.
//!
//! [`Road::load`] reads a `.crg` file in any of the four formats (LRFI, LDFI, KRBI,
//! KDBI), following `$ROAD_CRG_FILE` references; [`ContactPoint`] evaluates it:
//! x/y from u/v, u/v from x/y, elevation, heading and curvature, with the options of
//! the classic OpenCRG C API. [`write()`] saves a road in any format.
//!
//! ```no_run
//! use std::sync::Arc;
//! let road = Arc::new(opencrg_core::Road::load("road.crg")?);
//! let mut cp = opencrg_core::ContactPoint::new(road);
//! let z = cp.uv_to_z(10.0, 0.5)?;
//! let (u, v) = cp.xy_to_uv(3.0, 4.0)?;
//! # Ok::<(), opencrg_core::Error>(())
//! ```
#![warn(missing_docs)]
// Comparisons like `!(x > 0.0)` are meant to reject NaN as well; they stay.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

// The layers, each using only those before it (checked by tests/architecture.rs):
// `base` (errors, settings, profiles, memory, units), `model` (the road as data), `read`
// and `write` (files to model and back, beside each other), `parts` (a road as arrays and
// back), `query` (evaluation, search, contact points, modifiers, checks), `geo`, and
// `info` and `synth` on top. Modules use each other by these paths (`crate::model::grid`); what users
// reach is re-exported below.
mod base {
    pub mod budget;
    pub(crate) mod compat;
    pub(crate) mod double_double;
    pub(crate) mod error;
    pub(crate) mod fault_guard;
    pub(crate) mod mapped_file;
    pub mod math;
    pub(crate) mod memory;
    pub(crate) mod pair;
    pub mod portable_math;
    pub(crate) mod setting_values;
    pub mod settings;
    pub mod units;
}
mod model {
    pub mod georef;
    pub mod grid;
    pub mod header;
    pub(crate) mod in_place;
    pub(crate) mod nan_borders;
    pub mod refline;
    pub mod report;
    pub(crate) mod road;
    pub(crate) mod sample_index;
    pub(crate) mod tile_bounds;
    pub mod tiles;
}
mod read {
    pub(crate) mod build;
    pub(crate) mod map_section;
    pub mod reader;
    pub(crate) mod records;
    pub(crate) mod syntax;
}
mod write {
    pub mod writer;
}
mod parts {
    pub mod draft;
}
mod query {
    pub(crate) mod batch;
    pub(crate) mod check;
    pub(crate) mod contact;
    pub(crate) mod eval;
    pub(crate) mod interpolation;
    pub(crate) mod modifiers;
    pub(crate) mod normal;
    pub(crate) mod plain;
    pub(crate) mod search;
}
mod geo {
    pub(crate) mod earth;
    pub(crate) mod helmert;
    pub(crate) mod map_check;
}
pub mod info;
pub mod synth;

pub use base::budget::{parse_bytes, Budget};
pub use base::compat::{Compat, UnknownCompat};
pub use base::error::{Error, Location, Result};
pub use base::setting_values::{Continuation, CpOption, CurvMode, Modifier};
pub use base::settings::{Settings, Value};
pub use base::{budget, math, settings, units};
pub use geo::earth::Earth;
pub use geo::map_check::map_disagreements;
pub use model::header::{Channel, DataFormat};
pub use model::road::{LoadOptions, ReadInPlace, Road, DEFAULT_IN_PLACE_FROM, DEFAULT_TILE_CACHE};
pub use model::{georef, grid, header, refline, report, tiles};
pub use parts::draft;
pub use query::batch::Evaluation;
pub use query::contact::{ContactPoint, SearchHistory};
pub use read::reader;
pub use write::writer::{self, write};

/// The README's Rust code, compiled by `cargo test` as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;
