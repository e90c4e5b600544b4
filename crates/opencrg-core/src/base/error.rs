//! The one error type of the crate.

use std::borrow::Cow;
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

/// Everything that can go wrong, by the kind a caller acts on: a file missing, unreadable
/// or unwritable; a file whose content is wrong; a road refused by a check; a request too
/// large for the memory it may take; a value the request does not take.
#[derive(Debug)]
pub enum Error {
    /// A file that does not exist.
    NotFound {
        /// The file.
        path: PathBuf,
        /// The system's reason.
        source: std::io::Error,
    },
    /// A file that could not be read or written.
    Io {
        /// The file.
        path: PathBuf,
        /// Whether it was being written (else read).
        writing: bool,
        /// The system's reason.
        source: std::io::Error,
    },
    /// A file was read but its content is wrong.
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
    Check(String),
    /// A request that would take more memory than it may (the limit of a
    /// [`Budget`](crate::Budget)), or than the system gives.
    TooLarge(String),
    /// A value the request does not take: a parameter out of range (an increment, a
    /// width, a range outside the road), a setting refused, a point the evaluation refuses
    /// (outside the road with border mode none, NaN), a road or map without what the
    /// request needs (a projection, a channel, points that cover it).
    OutOfRange(Cow<'static, str>),
}

impl Error {
    /// The error of reading `path`: [`Error::NotFound`] for a file that does not exist,
    /// [`Error::Io`] otherwise.
    pub fn reading(path: &std::path::Path, source: std::io::Error) -> Self {
        if source.kind() == std::io::ErrorKind::NotFound {
            Error::NotFound { path: path.to_path_buf(), source }
        } else {
            Error::Io { path: path.to_path_buf(), writing: false, source }
        }
    }

    /// The error of writing `path`.
    pub fn writing(path: &std::path::Path, source: std::io::Error) -> Self {
        Error::Io { path: path.to_path_buf(), writing: true, source }
    }

    /// A value the request does not take, saying why.
    pub fn out_of_range(why: impl Into<Cow<'static, str>>) -> Self {
        Error::OutOfRange(why.into())
    }
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Error::NotFound { path, source } => write!(f, "{}: cannot read: {source}", path.display()),
            Error::Io { path, writing, source } => {
                write!(f, "{}: cannot {}: {source}", path.display(), if *writing { "write" } else { "read" })
            }
            Error::Format { path, location, field, message } => {
                write!(f, "{}{location}: {field}: {message}", path.display())
            }
            Error::Check(why) => write!(f, "check failed: {why}"),
            Error::TooLarge(why) => f.write_str(why),
            Error::OutOfRange(why) => f.write_str(why),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::NotFound { source, .. } | Error::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}

impl From<crate::base::settings::SettingError> for Error {
    fn from(e: crate::base::settings::SettingError) -> Self {
        Error::OutOfRange(e.to_string().into())
    }
}

impl From<Error> for std::io::Error {
    /// The error as an I/O error (for writers and readers that speak in those).
    fn from(e: Error) -> Self {
        let kind = match &e {
            Error::NotFound { source, .. } | Error::Io { source, .. } => source.kind(),
            _ => std::io::ErrorKind::Other,
        };
        std::io::Error::new(kind, e.to_string())
    }
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
