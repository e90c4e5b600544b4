//! What the commands read: road files (their warnings said), the data formats' names,
//! pairs of numbers from stdin and the numbers printed back; and how a command fails (one
//! line for the user).

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

/// A file's name, for titles.
pub(crate) fn file_name(path: &Path) -> String {
    path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default()
}

/// A number as the point commands print it: the shortest text that reads back as the same
/// number, plainly where that is short (1e-5 to 1e16), in powers of ten otherwise (`1e300`,
/// not 301 digits); `nan` for NaN.
pub(crate) fn number(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x == 0.0 || !x.is_finite() || (1e-5..1e16).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

#[cfg(test)]
mod number_tests {
    use super::number;

    #[test]
    fn numbers_read_back_the_same_and_stay_short() {
        for x in [0.0, -0.0, 1.5, -120.25, 1e-5, 9.999e15, 1e16, 1e300, -2.5e-300, 5e-324, f64::MAX, f64::INFINITY] {
            let text = number(x);
            assert_eq!(text.parse::<f64>().unwrap().to_bits(), x.to_bits(), "{text}");
            assert!(text.len() <= 24, "{text}");
        }
        assert_eq!(number(1e300), "1e300");
        assert_eq!(number(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(number(f64::NAN), "nan");
    }
}
