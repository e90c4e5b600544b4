//! The npm package's native module: OpenCRG roads and OpenDRIVE maps in WebAssembly, a
//! thin translation of `opencrg-core` and `opencrg-odr` to JavaScript (wasm-bindgen).
//! Numbers or `Float64Array`s in, numbers or `Float64Array`s out, NaN where a point is
//! refused; errors are JavaScript `Error`s with the messages the command gives. The
//! package's `index.js` loads it (no init call in Node) and names the map classes `odr`.

mod contact;
mod drawing;
mod errors;
mod evaluate;
mod limits;
mod map;
mod road;
mod settings;
mod values;

pub use contact::ContactPoint;
pub use drawing::{decade_label, elevation_colours, figure_colours, tick_label, ticks};
pub use errors::Thrown;
pub use evaluate::evaluations;
pub use map::Map;
pub use road::{iso8608_classes, Road};
