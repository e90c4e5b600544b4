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

// The layers, each using only those before it (checked by tests/architecture.rs):
// `base` (errors, settings, profiles, memory), `model` (the road as data), `read` and
// `write` (files to model and back, beside each other), `query` (evaluation, search,
// contact points, modifiers, checks), `geo`, `analysis`, `export`, `synth`, and `tools` on top.
mod base {
    pub(crate) mod budget;
    pub(crate) mod compat;
    pub(crate) mod error;
    pub(crate) mod memory;
    pub(crate) mod setting_values;
    pub mod settings;
    pub mod units;
}
mod model {
    pub mod georef;
    pub mod grid;
    pub mod header;
    pub mod refline;
    pub mod report;
    pub(crate) mod road;
    pub(crate) mod sample_index;
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
    pub mod earth;
    pub(crate) mod helmert;
    pub(crate) mod map_check;
}
mod analysis {
    pub mod iri;
    pub mod psd;
    pub mod roughness;
}
mod export {
    pub(crate) mod gltf;
    pub mod mesh;
    pub mod mesh_files;
    pub mod simplify;
}
pub mod synth;
pub mod tools {
    //! Making new roads: from a road (cut, flip, append, resample, filter, slope and
    //! banking moved between the reference line and the grid) and from points (a
    //! reference line through them, a point cloud gridded along one); and comparing two
    //! surfaces. Each makes a new [`Road`](crate::Road); the input is left as it was. The
    //! result keeps the header's comments, options, modifiers and map data, adds a
    //! comment saying what was done, and is written with [`write`](crate::write).
    mod append;
    mod channels;
    mod compare;
    mod cut;
    mod draft;
    mod filter;
    mod flip;
    mod generate;
    mod import;
    mod nodes;
    mod path;
    mod point_files;
    mod resample;

    pub use append::append;
    pub use channels::{change_channel, ChannelAction, LineChannel};
    pub use compare::{compare, Comparison};
    pub use cut::cut;
    pub use filter::{filter, Filter};
    pub use flip::flip;
    pub use generate::{generate, Layout, Points, Surface};
    pub use import::{import, Import};
    pub use nodes::Progress;
    pub use point_files::{parse_points, read_points};
    pub use resample::resample;
}

pub use analysis::{iri, psd, roughness};
pub use base::budget::{parse_bytes, Budget};
pub use base::settings;
pub use base::units;
use base::{budget, compat, error, memory};
use export::gltf;
pub use export::{mesh, mesh_files, simplify};
pub use geo::earth::Earth;
pub use geo::map_check::map_disagreements;
pub use model::{georef, grid, header, refline, report};
use model::{road, sample_index};
use query::{contact, eval, interpolation, normal, plain, search};
pub use read::reader;
use read::{build, map_section, records, syntax};
pub use write::writer;

pub use base::setting_values::{Continuation, CpOption, CurvMode, Modifier};
pub use compat::{Compat, UnknownCompat};
pub use contact::{ContactPoint, SearchHistory};
pub use error::{Error, Location, Result};
pub use header::{Channel, DataFormat};
pub use road::{LoadOptions, Road};
pub use settings::{Settings, Value};
pub use writer::write;

/// The README's Rust code, compiled by `cargo test` as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;

/// The user guide's Rust page, compiled by `cargo test` as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../../docs/rust.md")]
pub struct RustGuideDoctests;
