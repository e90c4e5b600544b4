//! How a road was made and what was done to it since: what a pickled `Road` carries, so
//! that unpickling makes the same road again (the same steps on the same data give the
//! same numbers).
//!
//! A road read from a file carries the file's path, size and modification time, and how it
//! was read (in place or into memory, the tile cache): the file is read again, the same
//! way, where the road is unpickled (another process on the same machine, or a worker
//! sharing the file system), and a file that changed meanwhile is refused. A road read in
//! place thus pickles as a few hundred bytes, whatever its size. A road made from bytes
//! carries the bytes.

use ::opencrg_core as crg;
use ::opencrg_core::settings::Value;
use ::opencrg_core::{Compat, LoadOptions, ReadInPlace};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyTuple};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::UNIX_EPOCH;

/// Where a road's data came from.
#[derive(Clone)]
enum Origin {
    /// A file: its path, size and modification time (nanoseconds since 1970) when read.
    File { path: PathBuf, len: u64, modified: u128 },
    /// Bytes, and the name they were given.
    Bytes { data: Arc<Vec<u8>>, name: String },
    /// A road made by a tool: pickled as its bytes (KDBI), written when pickled.
    Made(Arc<crg::Road>),
}

/// A change made to a road after it was read.
#[derive(Clone)]
pub(crate) enum Step {
    Check,
    ApplyModifiers,
    SetModifier(u32, Value),
    RemoveModifier(u32),
    ClearModifiers,
    /// The global origin set: x, y, z, phi.
    SetGlobalOrigin([f64; 4]),
}

impl Step {
    /// Takes the step on `road`.
    pub(crate) fn apply(&self, road: &mut crg::Road) -> crg::Result<()> {
        match *self {
            Step::Check => return road.check(),
            Step::ApplyModifiers => road.apply_modifiers(),
            Step::SetModifier(id, value) => road.modifiers_mut().set_value(id, value)?,
            Step::RemoveModifier(id) => {
                road.modifiers_mut().remove(id);
            }
            Step::ClearModifiers => road.modifiers_mut().clear(),
            Step::SetGlobalOrigin([x, y, z, phi]) => road.set_global_origin(crg::georef::GlobalOrigin { x, y, z, phi }),
        }
        Ok(())
    }
}

/// Where a road came from, how it was read (its behaviour profile; for a file, in place or
/// not and the tile cache) and the changes made to it.
#[derive(Clone)]
pub(crate) struct Recipe {
    origin: Origin,
    load: LoadOptions,
    steps: Vec<Step>,
}

/// The size and modification time of a file.
fn stamp(path: &Path) -> std::io::Result<(u64, u128)> {
    let meta = std::fs::metadata(path)?;
    let modified = meta.modified()?.duration_since(UNIX_EPOCH).map(|d| d.as_nanos()).unwrap_or(0);
    Ok((meta.len(), modified))
}

impl Recipe {
    /// A road read from `path` with `load`: its absolute path and stamp (taken after the
    /// read), and whether it was read in place (it is read so again).
    pub(crate) fn file(path: &Path, load: LoadOptions, in_place: bool) -> Self {
        let path = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
        let (len, modified) = stamp(&path).unwrap_or((0, 0));
        let in_place = if in_place { ReadInPlace::Always } else { ReadInPlace::Never };
        Recipe {
            origin: Origin::File { path, len, modified },
            load: LoadOptions { in_place, ..load },
            steps: Vec::new(),
        }
    }

    /// A road made from `data` named `name`.
    pub(crate) fn bytes(data: Arc<Vec<u8>>, name: &str, compat: Compat) -> Self {
        let load = LoadOptions { compat, ..LoadOptions::default() };
        Recipe { origin: Origin::Bytes { data, name: name.to_string() }, load, steps: Vec::new() }
    }

    /// A road a tool made.
    pub(crate) fn made(road: Arc<crg::Road>) -> Self {
        let load = LoadOptions { compat: road.compat(), ..LoadOptions::default() };
        Recipe { origin: Origin::Made(road), load, steps: Vec::new() }
    }

    /// Notes a change.
    pub(crate) fn push(&mut self, step: Step) {
        self.steps.push(step);
    }

    /// The recipe as Python values: `(2, origin, compat, steps, in_place, cache)`, where
    /// origin is `("file", path, size, mtime_ns)` or `("bytes", data, name)`, each step a
    /// tuple `("check",)`, `("apply",)`, `("set", id, value)`, `("remove", id)` or
    /// `("clear",)`, `in_place` is `"always"`, `"never"` or `"auto"`, and `cache` the tile
    /// cache's bytes or `None`. (Version 1, without the last two, is read too.)
    pub(crate) fn to_py<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let origin = match &self.origin {
            Origin::File { path, len, modified } => {
                (("file", path.to_string_lossy().into_owned(), *len, *modified).into_pyobject(py)?).into_any()
            }
            Origin::Bytes { data, name } => {
                (("bytes", PyBytes::new(py, data), name.as_str()).into_pyobject(py)?).into_any()
            }
            Origin::Made(road) => {
                let mut data = Vec::new();
                crg::writer::write_to(road, &mut data, crg::DataFormat::Kdbi)?;
                (("bytes", PyBytes::new(py, &data), "<made>").into_pyobject(py)?).into_any()
            }
        };
        let steps = self
            .steps
            .iter()
            .map(|step| {
                Ok(match step {
                    Step::Check => ("check",).into_pyobject(py)?.into_any(),
                    Step::ApplyModifiers => ("apply",).into_pyobject(py)?.into_any(),
                    Step::SetModifier(id, Value::Int(v)) => ("set", *id, *v).into_pyobject(py)?.into_any(),
                    Step::SetModifier(id, Value::Double(v)) => ("set", *id, *v).into_pyobject(py)?.into_any(),
                    Step::RemoveModifier(id) => ("remove", *id).into_pyobject(py)?.into_any(),
                    Step::ClearModifiers => ("clear",).into_pyobject(py)?.into_any(),
                    Step::SetGlobalOrigin(o) => ("origin", o.to_vec()).into_pyobject(py)?.into_any(),
                })
            })
            .collect::<PyResult<Vec<_>>>()?;
        let in_place = match self.load.in_place {
            ReadInPlace::Always => "always",
            ReadInPlace::Never => "never",
            _ => "auto",
        };
        (2u32, origin, self.load.compat.to_string(), steps, in_place, self.load.tile_cache).into_pyobject(py)
    }

    /// The recipe from what [`Recipe::to_py`] gave.
    pub(crate) fn from_py(state: &Bound<'_, PyAny>) -> PyResult<Self> {
        let bad = |what: &str| crate::errors::request_error(format!("not a pickled opencrg.Road: {what}"));
        let version: u32 = state.get_item(0).and_then(|v| v.extract()).map_err(|_| bad("its state"))?;
        let (origin, compat, steps, in_place, tile_cache): (
            Bound<'_, PyAny>,
            String,
            Vec<Bound<'_, PyAny>>,
            String,
            Option<u64>,
        ) = match version {
            1 => {
                let (_, origin, compat, steps): (u32, _, _, _) = state.extract().map_err(|_| bad("its state"))?;
                (origin, compat, steps, "auto".into(), None)
            }
            2 => {
                let (_, origin, compat, steps, in_place, cache): (u32, _, _, _, _, _) =
                    state.extract().map_err(|_| bad("its state"))?;
                (origin, compat, steps, in_place, cache)
            }
            other => return Err(bad(&format!("state version {other}"))),
        };
        let compat: Compat =
            compat.parse().map_err(|e: crg::UnknownCompat| crate::errors::request_error(e.to_string()))?;
        let in_place = ReadInPlace::parse(&in_place).map_err(|e| bad(&e))?;
        let load = LoadOptions { compat, in_place, tile_cache, ..LoadOptions::default() };
        let kind: String = origin.get_item(0)?.extract()?;
        let origin = match kind.as_str() {
            "file" => {
                let (_, path, len, modified): (String, PathBuf, u64, u128) = origin.extract()?;
                Origin::File { path, len, modified }
            }
            "bytes" => {
                let (_, data, name): (String, Vec<u8>, String) = origin.extract()?;
                Origin::Bytes { data: Arc::new(data), name }
            }
            other => return Err(bad(&format!("origin '{other}'"))),
        };
        let steps = steps
            .iter()
            .map(|step| {
                let kind: String = step.get_item(0)?.extract()?;
                Ok(match kind.as_str() {
                    "check" => Step::Check,
                    "apply" => Step::ApplyModifiers,
                    "remove" => Step::RemoveModifier(step.get_item(1)?.extract()?),
                    "clear" => Step::ClearModifiers,
                    "origin" => Step::SetGlobalOrigin(step.get_item(1)?.extract()?),
                    "set" => {
                        let id: u32 = step.get_item(1)?.extract()?;
                        let value = step.get_item(2)?;
                        let value = if value.is_instance_of::<pyo3::types::PyFloat>() {
                            Value::Double(value.extract()?)
                        } else {
                            Value::Int(value.extract()?)
                        };
                        Step::SetModifier(id, value)
                    }
                    other => return Err(bad(&format!("step '{other}'"))),
                })
            })
            .collect::<PyResult<Vec<_>>>()?;
        Ok(Recipe { origin, load, steps })
    }

    /// Makes the road again: reads the data (refusing a file that changed since), then
    /// takes the same steps.
    pub(crate) fn make(&self, py: Python<'_>) -> PyResult<crg::Road> {
        let options = self.load;
        if let Origin::File { path, len, modified } = &self.origin {
            if stamp(path)? != (*len, *modified) {
                return Err(crate::errors::request_error(format!(
                    "{} changed since the road was pickled (size or modification time)",
                    path.display()
                )));
            }
        }
        py.detach(|| {
            let mut road = match &self.origin {
                Origin::File { path, .. } => crg::Road::load_with(path, options)?,
                Origin::Bytes { data, name } => crg::Road::from_bytes_with(data.to_vec(), name, options)?,
                Origin::Made(road) => crg::Road::clone(road),
            };
            for step in &self.steps {
                // A step that failed (a check) changes the road here as it changed it there.
                let _ = step.apply(&mut road);
            }
            Ok(road)
        })
        .map_err(crate::errors::to_py)
    }
}
