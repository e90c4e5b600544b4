//! What the commands read: road files (their warnings said), the data formats' names,
//! and pairs of numbers from stdin; and how a command fails (one line for the user).

use clap::ValueEnum;
use opencrg_core::{DataFormat, Road};
use std::io::BufRead;
use std::path::Path;

/// An error for the user: one line.
pub(crate) type Failure = String;

/// Reads a road file, its warnings on stderr.
pub(crate) fn load(path: &Path) -> Result<Road, Failure> {
    let road = Road::load(path).map_err(|e| e.to_string())?;
    for w in road.warnings() {
        eprintln!("opencrg: warning: {w}");
    }
    Ok(road)
}

/// Calls `each` with the two numbers of every line of stdin (blank lines and `#`
/// comments skipped; numbers split by blanks or commas); refused: a line that is not two
/// numbers, named by its number.
pub(crate) fn stdin_pairs(mut each: impl FnMut(f64, f64) -> Result<(), Failure>) -> Result<(), Failure> {
    for (k, line) in std::io::stdin().lock().lines().enumerate() {
        let line = line.map_err(|e| format!("stdin: {e}"))?;
        let text = line.trim();
        if text.is_empty() || text.starts_with('#') {
            continue;
        }
        let bad = || format!("stdin:{}: '{text}' is not two numbers", k + 1);
        let values: Vec<f64> = text
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|s| !s.is_empty())
            .map(str::parse)
            .collect::<Result<_, _>>()
            .map_err(|_| bad())?;
        let [a, b] = values[..] else { return Err(bad()) };
        each(a, b)?;
    }
    Ok(())
}

/// The data formats, named as in files and the specification.
#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum Format {
    #[value(name = "KRBI")]
    Krbi,
    #[value(name = "KDBI")]
    Kdbi,
    #[value(name = "LRFI")]
    Lrfi,
    #[value(name = "LDFI")]
    Ldfi,
}

impl From<Format> for DataFormat {
    fn from(f: Format) -> DataFormat {
        match f {
            Format::Krbi => DataFormat::Krbi,
            Format::Kdbi => DataFormat::Kdbi,
            Format::Lrfi => DataFormat::Lrfi,
            Format::Ldfi => DataFormat::Ldfi,
        }
    }
}
