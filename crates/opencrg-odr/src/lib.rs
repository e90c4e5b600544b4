//! OpenDRIVE maps with OpenCRG surfaces.
//!
//! [`Map::load`] reads an `.xodr` file (OpenDRIVE 1.4 to 1.9): the roads' reference lines
//! (line, arc, spiral, poly3, paramPoly3), elevation, superelevation, lateral shape, lane
//! offset, lane sections with widths, borders, heights and materials, junctions, and the
//! `<surface><CRG>` records that lay OpenCRG files on roads and junctions. Everything is
//! computed in double precision: [`Road::reference`] gives the reference line at s,
//! [`Road::surface_point`] the road's surface at (s, t). [`Surface`] answers at any world
//! x/y, through a [`Probe`] per wheel: road, lane, s, t, height, normal and friction with
//! the CRG records laid on.
//!
//! ```no_run
//! let map = opencrg_odr::Map::load("town.xodr")?;
//! let road = map.road("12").unwrap();
//! let [x, y, z] = road.surface_point(25.0, -1.75);
//! # Ok::<(), opencrg_core::Error>(())
//! ```
#![warn(missing_docs)]
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod check;
mod crg;
mod geometry;
mod ground;
mod info;
mod lanes;
mod last_wins;
mod locate;
mod map;
mod patch;
mod profile;
mod quadrature;
mod read;
mod surface;
mod trig;
mod xml;

pub use check::{check, Finding};
pub use geometry::{Geometry, Pose, Shape};
pub use ground::{Ground, Probe, Surface};
pub use info::{MapInfo, RecordInfo};
pub use lanes::{Height, Lane, LaneSection, LaneSpan, Lanes, Material};
pub use locate::{RoadIndex, RoadPos};
pub use map::{CrgMode, CrgOrientation, CrgPurpose, CrgRecord, Header, Junction, Map, Road, ShapeGroup};
pub use profile::{Cubic, Profile};
pub use surface::RefPoint;
