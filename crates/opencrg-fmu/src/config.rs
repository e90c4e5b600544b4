//! The file in an FMU's `resources/` that tells its binary what to load: the road (a CRG
//! file or a map), how many wheels, the token that ties the resources to the model
//! description, and where a map's CRG files were put.
//!
//! ```text
//! # opencrg FMU resources: what the binary loads
//! token = {0d4b1c57-8a6e-2f90-41c3-77e2a9b0c1d5}
//! kind = map
//! road = road/town.xodr
//! wheels = 4
//! crg.1.file = ../surfaces/patch.crg
//! crg.1.path = crg/1/patch.crg
//! ```
//!
//! Paths are relative to `resources/`, with `/` between folders; `crg.N.file` is a CRG
//! record's `file` attribute as the map writes it, `crg.N.path` where the file now is. A
//! CRG file left outside the FMU (a road of gigabytes is not copied into a zip) is named
//! by `outside = yes` and its absolute path as `road`.

use crate::variables::{Kind, MAX_WHEELS};
use opencrg_core::{Error, Location};
use std::path::{Path, PathBuf};

/// The file's name in `resources/`.
pub const FILE_NAME: &str = "opencrg-fmu.txt";

/// What an FMU's resources hold.
#[derive(Debug, Clone, PartialEq)]
pub struct Config {
    /// The model description's `guid` (FMI 2) or `instantiationToken` (FMI 3).
    pub token: String,
    /// A CRG file or a map.
    pub kind: Kind,
    /// The road's file, relative to `resources/` (or its absolute path, when `outside`).
    pub road: String,
    /// Whether the road (a CRG file) lies outside the FMU, at the absolute path `road`.
    pub outside: bool,
    /// How many wheels.
    pub wheels: u32,
    /// A map's CRG files: each record's `file` attribute and where the file is,
    /// relative to `resources/`.
    pub crg: Vec<(String, String)>,
}

impl Config {
    /// The file's text.
    pub fn to_text(&self) -> String {
        let kind = match self.kind {
            Kind::Crg => "crg",
            Kind::Map => "map",
        };
        let mut text = format!(
            "# opencrg FMU resources: what the binary loads\ntoken = {}\nkind = {kind}\nroad = {}\nwheels = {}\n",
            self.token, self.road, self.wheels
        );
        if self.outside {
            text.push_str("outside = yes\n");
        }
        for (i, (file, path)) in self.crg.iter().enumerate() {
            text.push_str(&format!("crg.{}.file = {file}\ncrg.{}.path = {path}\n", i + 1, i + 1));
        }
        text
    }

    /// Reads the file's text, named `path` in messages; refused: a line or value it does
    /// not know, a missing key.
    pub fn parse(text: &str, path: &Path) -> Result<Config, Error> {
        Config::parse_text(text).map_err(|(line, message)| Error::Format {
            path: path.to_path_buf(),
            location: if line == 0 { Location::File } else { Location::Line(line) },
            field: "FMU resources".into(),
            message,
        })
    }

    /// [`Config::parse`]'s work: a refusal with its line (0: the file).
    fn parse_text(text: &str) -> Result<Config, (usize, String)> {
        let (mut token, mut kind, mut road, mut wheels, mut outside) = (None, None, None, None, false);
        let mut files: Vec<(Option<String>, Option<String>)> = Vec::new();
        for (n, line) in text.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let at = |what: &str| (n + 1, what.to_string());
            let (key, value) = line.split_once('=').ok_or_else(|| at("expected key = value"))?;
            let (key, value) = (key.trim(), value.trim().to_string());
            match key {
                "token" => token = Some(value),
                "kind" => {
                    kind = Some(match value.as_str() {
                        "crg" => Kind::Crg,
                        "map" => Kind::Map,
                        other => return Err(at(&format!("kind '{other}': crg or map"))),
                    })
                }
                "road" => road = Some(value),
                "outside" => {
                    outside = match value.as_str() {
                        "yes" => true,
                        "no" => false,
                        other => return Err(at(&format!("outside '{other}': yes or no"))),
                    }
                }
                "wheels" => {
                    let count = value.parse::<u32>().ok().filter(|w| (1..=MAX_WHEELS).contains(w));
                    wheels = Some(count.ok_or_else(|| at(&format!("wheels '{value}': 1 to {MAX_WHEELS}")))?);
                }
                _ => {
                    let mut parts = key.split('.');
                    let (Some("crg"), Some(index), Some(field), None) =
                        (parts.next(), parts.next(), parts.next(), parts.next())
                    else {
                        return Err(at(&format!("unknown key '{key}'")));
                    };
                    let index = index.parse::<usize>().ok().filter(|&i| i >= 1 && i <= files.len() + 1);
                    let index =
                        index.ok_or_else(|| at(&format!("'{key}': CRG files are numbered 1, 2, ... in turn")))?;
                    if index > files.len() {
                        files.push((None, None));
                    }
                    match field {
                        "file" => files[index - 1].0 = Some(value),
                        "path" => files[index - 1].1 = Some(value),
                        _ => return Err(at(&format!("unknown key '{key}'"))),
                    }
                }
            }
        }
        let missing = |key: &str| (0, format!("no '{key}' line"));
        let crg = files
            .into_iter()
            .enumerate()
            .map(|(i, pair)| match pair {
                (Some(file), Some(path)) => Ok((file, path)),
                _ => Err((0, format!("CRG file {} lacks its file or its path", i + 1))),
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Config {
            token: token.ok_or_else(|| missing("token"))?,
            kind: kind.ok_or_else(|| missing("kind"))?,
            road: road.ok_or_else(|| missing("road"))?,
            outside,
            wheels: wheels.ok_or_else(|| missing("wheels"))?,
            crg,
        })
    }

    /// Where the road's file is: under `resources`, or outside the FMU.
    pub fn road_path(&self, resources: &Path) -> PathBuf {
        if self.outside {
            PathBuf::from(&self.road)
        } else {
            Config::resolve(resources, &self.road)
        }
    }

    /// A path of the file, relative to `resources/`, under the folder `resources`.
    pub fn resolve(resources: &Path, relative: &str) -> PathBuf {
        relative.split('/').filter(|p| !p.is_empty()).fold(resources.to_path_buf(), |path, part| path.join(part))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_reads_back() {
        let config = Config {
            token: "{01234567-89ab-cdef-0123-456789abcdef}".into(),
            kind: Kind::Map,
            road: "road/town 1.xodr".into(),
            outside: false,
            wheels: 4,
            crg: vec![("../a b/c.crg".into(), "crg/1/c.crg".into()), ("d.crg".into(), "crg/2/d.crg".into())],
        };
        assert_eq!(Config::parse(&config.to_text(), Path::new("c.txt")).unwrap(), config);
        let outside =
            Config { kind: Kind::Crg, road: "/data/roads/track 1.crg".into(), outside: true, crg: vec![], ..config };
        let back = Config::parse(&outside.to_text(), Path::new("c.txt")).unwrap();
        assert_eq!(back, outside);
        assert_eq!(back.road_path(Path::new("/fmu/resources")), Path::new("/data/roads/track 1.crg"));
    }

    #[test]
    fn faults_are_named() {
        let good = "token = t\nkind = crg\nroad = r.crg\nwheels = 2\n";
        assert!(Config::parse(good, Path::new("c.txt")).is_ok());
        for (text, says) in [
            ("token = t\nkind = crg\nroad = r.crg\n", "c.txt: FMU resources: no 'wheels' line"),
            ("token = t\nkind = csv\nroad = r.crg\nwheels = 2\n", "c.txt:2: FMU resources: kind 'csv'"),
            ("token = t\nkind = crg\nroad = r.crg\nwheels = 0\n", "c.txt:4: FMU resources: wheels '0'"),
            (
                "token = t\nkind = map\nroad = r.xodr\nwheels = 2\ncrg.2.file = x\n",
                "c.txt:5: FMU resources: 'crg.2.file'",
            ),
            ("token = t\nkind = map\nroad = r.xodr\nwheels = 2\ncrg.1.file = x\n", "CRG file 1 lacks"),
            ("token = t\nkind = map\nroad = r.xodr\nwheels = 2\ncolour = red\n", "unknown key 'colour'"),
            ("token t\n", "c.txt:1: FMU resources: expected key = value"),
        ] {
            let e = Config::parse(text, Path::new("c.txt")).unwrap_err().to_string();
            assert!(e.contains(says), "{text:?}: {e}");
        }
    }

    #[test]
    fn paths_resolve_under_the_resources() {
        let p = Config::resolve(Path::new("/tmp/unpacked/resources"), "crg/1/x.crg");
        assert_eq!(p, Path::new("/tmp/unpacked/resources").join("crg").join("1").join("x.crg"));
    }
}
