//! The binary inside every FMU `opencrg fmu` writes: the FMI 2.0 and 3.0 functions, model
//! exchange and co-simulation, as a thin translation onto `opencrg-fmu` (which loads the
//! road its `resources/` hold and answers under each wheel). One binary serves every
//! road; the FMU's model description and resources say which. No global state: each
//! instance holds its road and wheels, so instances on different threads never meet.
//!
//! Every export answers through one guard (`guard::on_instance`): no panic crosses into
//! the importer, and messages go to the importer's logger, never to stdout.

// Comparisons like `!(x >= 0.0)` are meant to reject NaN as well; they stay.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod abi;
mod fmi2;
mod fmi3;
mod guard;
mod instance;
mod lifecycle;
mod log;
mod states;
mod uri;

pub use fmi2::*;
pub use fmi3::*;
