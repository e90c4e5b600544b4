//! Work on OpenCRG road surfaces and OpenDRIVE maps, on the evaluator of `opencrg-core`.
//!
//! Making new roads: from a road ([`cut`], [`flip`], [`append`], [`resample`],
//! [`filter`], slope and banking moved between the reference line and the grid with
//! [`change_channel`]) and from points ([`generate`]: a reference line through them;
//! [`import`]: a point cloud gridded along one); comparing two surfaces ([`compare`]).
//! Each makes a new [`Road`](opencrg_core::Road); the input is left as it was. The result
//! keeps the header's comments, options, modifiers and map data, adds a comment saying
//! what was done, and is written with [`opencrg_core::write`].
//!
//! Measuring a road: [`iri`], [`psd`] and [`roughness`] (the International Roughness
//! Index and the ISO 8608 class of wheel tracks). Meshes for 3D tools: [`mesh`] (the
//! grid), [`simplify`] (within an error bound), [`map_mesh`] (the drivable surface of an
//! OpenDRIVE map), written by [`mesh_files`]; a road or a map in 3D in one HTML page
//! ([`view`]). A road or a map as an FMU for simulation
//! tools: [`fmu`].
//!
//! ```no_run
//! let road = std::sync::Arc::new(opencrg_core::Road::load("road.crg")?);
//! let part = opencrg_tools::cut(&road, (100.0, 350.0), None)?;
//! opencrg_core::write(&part, "part.crg", opencrg_core::DataFormat::Kdbi)?;
//! # Ok::<(), opencrg_core::Error>(())
//! ```
#![warn(missing_docs)]
// Comparisons like `!(x > 0.0)` are meant to reject NaN as well; they stay.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

// The layers, each using only those before it (checked by opencrg-core's
// tests/architecture.rs): `analysis` and `export` beside each other, `make` on top.
// Modules use each other by these paths (`crate::export::mesh`); what users reach is
// re-exported below.
mod analysis {
    pub mod iri;
    pub mod psd;
    pub mod roughness;
}
mod export {
    pub mod drawing;
    #[cfg(feature = "fmu")]
    pub mod fmu;
    pub(crate) mod gltf;
    pub mod map_mesh;
    pub mod mesh;
    pub mod mesh_files;
    pub mod simplify;
    pub mod view;
}
mod make {
    pub(crate) mod append;
    pub(crate) mod channels;
    pub(crate) mod compare;
    pub(crate) mod cut;
    pub(crate) mod filter;
    pub(crate) mod flip;
    pub(crate) mod generate;
    #[cfg(feature = "point-clouds")]
    pub(crate) mod import;
    pub(crate) mod las_points;
    pub(crate) mod nodes;
    pub(crate) mod path;
    pub(crate) mod point_files;
    pub(crate) mod resample;
}

pub use analysis::{iri, psd, roughness};
#[cfg(feature = "fmu")]
pub use export::fmu;
pub use export::{drawing, map_mesh, mesh, mesh_files, simplify, view};
pub use make::append::append;
pub use make::channels::{change_channel, ChannelAction, LineChannel};
pub use make::compare::{compare, Comparison};
pub use make::cut::cut;
pub use make::filter::{filter, Filter};
pub use make::flip::flip;
pub use make::generate::{generate, ElevationFn, Layout, Points};
#[cfg(feature = "point-clouds")]
pub use make::import::{import, Import};
pub use make::nodes::Progress;
pub use make::point_files::{parse_points, read_points};
pub use make::resample::resample;

/// The user guide's Rust page, compiled by `cargo test` as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../../docs/rust.md")]
pub struct RustGuideDoctests;
