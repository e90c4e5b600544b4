//! The one error type of the crate.

use std::path::PathBuf;

/// Where in a file something went wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Location {
    /// The file as a whole.
    File,
    /// A header line (1-based).
    Line(usize),
    /// A data record (1-based, one record per cross section) and, when known, a channel (1-based).
    Record {
        /// The record number.
        record: usize,
        /// The channel number, if the problem is in one channel.
        channel: Option<usize>,
    },
}

impl std::fmt::Display for Location {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Location::File => Ok(()),
            Location::Line(l) => write!(f, ":{l}"),
            Location::Record { record, channel: None } => write!(f, ": data record {record}"),
            Location::Record { record, channel: Some(c) } => write!(f, ": data record {record}, channel {c}"),
        }
    }
}

/// Everything that can go wrong in this crate.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A file could not be opened or read.
    #[error("{path}: cannot read: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The system's reason.
        source: std::io::Error,
    },
    /// A file was read but its content is wrong.
    #[error("{path}{location}: {field}: {message}")]
    Format {
        /// The file.
        path: PathBuf,
        /// Where in the file.
        location: Location,
        /// The header field, section or channel concerned.
        field: String,
        /// What is wrong.
        message: String,
    },
    /// A road was refused by a check.
    #[error("check failed: {0}")]
    Check(String),
    /// A setting was refused.
    #[error(transparent)]
    Setting(#[from] crate::base::settings::SettingError),
    /// An evaluation was refused (outside the data with border mode none, or a NaN input).
    #[error("evaluation refused: {0}")]
    Eval(&'static str),
    /// An analysis was refused (a track outside the road, a profile too short for it).
    #[error("{0}")]
    Analysis(String),
    /// A position on the earth could not be computed (a road without a map projection,
    /// a point the projection cannot take).
    #[error("{0}")]
    Geo(String),
    /// A tool refused what it was asked (a range outside the road, points that do not
    /// cover it, roads that cannot be joined).
    #[error("{0}")]
    Request(String),
    /// A file could not be written.
    #[error("{path}: cannot write: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// The system's reason.
        source: std::io::Error,
    },
}

/// Shorthand for results of this crate.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// A format error at a place in a file.
    pub fn format(
        path: &std::path::Path,
        location: Location,
        field: impl Into<String>,
        message: impl Into<String>,
    ) -> Self {
        Error::Format { path: path.to_path_buf(), location, field: field.into(), message: message.into() }
    }
}
