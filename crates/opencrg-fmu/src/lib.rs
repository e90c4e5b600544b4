//! OpenCRG roads and OpenDRIVE maps with CRG surfaces as FMUs (Functional Mock-up
//! Units, FMI 2.0 and 3.0): what an FMU of a road holds and answers, apart from FMI's C
//! functions (the `opencrg-fmi` binary) and the packing into a zip (`opencrg fmu`).
//!
//! - [`variables`]: each wheel's inputs (x, y) and outputs (height, friction, normal,
//!   on the road; a map's s, t, road and lane; a CRG file's u, v, heading and
//!   curvature), the parameters, their value references.
//! - [`description`]: the model description.
//! - [`config`]: the file in `resources/` that tells the binary what to load.
//! - [`Terrain`] and [`Wheels`]: the road loaded, and the answers under each wheel.
//!
//! ```no_run
//! use opencrg_fmu::{Fmu, Quantity};
//! let fmu = Fmu::load("unpacked/resources".as_ref())?;
//! let mut wheels = fmu.wheels(&[])?;
//! wheels.set(0, Quantity::X, 10.0);
//! wheels.set(0, Quantity::Y, 0.5);
//! println!("z {}", wheels.real(0, Quantity::Z, 1.0));
//! # Ok::<(), opencrg_core::Error>(())
//! ```
#![warn(missing_docs)]

pub mod config;
pub mod description;
mod terrain;
pub mod variables;

pub use config::Config;
pub use description::{model_description, Fmi, Meta};
pub use terrain::{compat_named, Terrain, Wheels};
pub use variables::{Kind, Parameter, Quantity, Start, Type, Variable};

use opencrg_core::settings::Value;
use opencrg_core::{Compat, Error, Result};
use std::path::{Path, PathBuf};

/// An FMU's road, loaded from its `resources/` folder as its configuration says.
pub struct Fmu {
    /// What the resources hold.
    pub config: Config,
    /// The road, loaded.
    pub terrain: Terrain,
    resources: PathBuf,
    compat: Compat,
    /// The `roadFile` parameter: the CRG file read instead of the FMU's own road (empty:
    /// the FMU's own).
    road_file: String,
    /// Why the road named outside the FMU is missing (the FMU answers on a placeholder and
    /// refuses to initialize until `roadFile` names a road that loads).
    missing: Option<String>,
}

impl Fmu {
    /// Reads `resources/opencrg-fmu.txt` and loads the road it names (a CRG file in the
    /// current behaviour profile). Refused, with the file and the reason: a missing or
    /// damaged configuration, a road or CRG file that cannot be read or is refused (but a
    /// CRG file named outside the FMU that is not there: see [`Fmu::missing`]).
    pub fn load(resources: &Path) -> Result<Fmu> {
        let file = resources.join(config::FILE_NAME);
        let text = std::fs::read_to_string(&file).map_err(|e| Error::reading(&file, e))?;
        let config = Config::parse(&text, &file)?;
        let compat = Compat::default();
        let (terrain, missing) = match load_terrain(resources, &config, compat) {
            Ok(terrain) => (terrain, None),
            Err(e @ Error::NotFound { .. }) if config.outside => (Terrain::placeholder()?, Some(e.to_string())),
            Err(e) => return Err(e),
        };
        let road_file = road_file_start(&config);
        Ok(Fmu { config, terrain, resources: resources.to_path_buf(), compat, road_file, missing })
    }

    /// The behaviour profile the road was loaded with.
    pub fn compat(&self) -> Compat {
        self.compat
    }

    /// Loads a CRG file again in another behaviour profile (a map's files are read in
    /// the current one).
    pub fn set_compat(&mut self, compat: Compat) -> Result<()> {
        if compat != self.compat && self.config.kind == Kind::Crg && self.missing.is_none() {
            self.terrain = Terrain::load_crg(&self.road_path(), compat)?;
        }
        self.compat = compat;
        Ok(())
    }

    /// The `roadFile` parameter's value.
    pub fn road_file(&self) -> &str {
        &self.road_file
    }

    /// The `roadFile` parameter's start value: empty, or the path of a road left outside
    /// the FMU.
    pub fn road_file_start(&self) -> String {
        road_file_start(&self.config)
    }

    /// Reads the CRG file `file` instead of the FMU's road (empty: the FMU's own road
    /// again); refused, the road kept: a file that cannot be read or is refused.
    pub fn set_road_file(&mut self, file: &str) -> Result<()> {
        let file = file.trim();
        self.terrain = Terrain::load_crg(&self.path_of(file), self.compat)?;
        self.road_file = file.to_string();
        self.missing = None;
        Ok(())
    }

    /// Why the road named outside the FMU is missing, while it is.
    pub fn missing(&self) -> Option<&str> {
        self.missing.as_deref()
    }

    /// The CRG file read now.
    fn road_path(&self) -> PathBuf {
        self.path_of(&self.road_file)
    }

    /// The CRG file a `roadFile` value names (empty: the FMU's own road).
    fn path_of(&self, file: &str) -> PathBuf {
        if file.is_empty() {
            self.config.road_path(&self.resources)
        } else {
            PathBuf::from(file)
        }
    }

    /// A map's roads' OpenDRIVE ids in the file's order (none for a CRG file): what
    /// `wheel[i].road`'s values name.
    pub fn road_ids(&self) -> Vec<String> {
        match &self.terrain {
            Terrain::Map(surface) => surface.map().roads.iter().map(|r| r.id.clone()).collect(),
            Terrain::Crg(_) => Vec::new(),
        }
    }

    /// The model's variables (FMI 3's time first when `with_time`).
    pub fn variables(&self, with_time: bool) -> Vec<Variable> {
        let start = self.road_file_start();
        variables::variables(
            self.terrain.kind(),
            self.config.wheels,
            with_time,
            self.terrain.start_point(),
            |p| match p {
                variables::Parameter::RoadFile => variables::Start::String(start.clone()),
                p => self.terrain.parameter_start(p),
            },
        )
    }

    /// The wheels at their start point, a CRG file's contact points with the options
    /// `changed`.
    pub fn wheels(&self, changed: &[(u32, Value)]) -> Result<Wheels> {
        Wheels::new(&self.terrain, self.config.wheels as usize, self.terrain.start_point(), changed)
    }
}

/// The `roadFile` parameter's start value for `config`: empty, or the path of a road left
/// outside the FMU.
fn road_file_start(config: &Config) -> String {
    if config.outside {
        config.road.clone()
    } else {
        String::new()
    }
}

/// Loads the road `config` names under `resources`.
fn load_terrain(resources: &Path, config: &Config, compat: Compat) -> Result<Terrain> {
    let road = config.road_path(resources);
    match config.kind {
        Kind::Crg => Terrain::load_crg(&road, compat),
        Kind::Map => {
            let moved: Vec<(String, PathBuf)> =
                config.crg.iter().map(|(file, path)| (file.clone(), Config::resolve(resources, path))).collect();
            Terrain::load_map(&road, &moved)
        }
    }
}
