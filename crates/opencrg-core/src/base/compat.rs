//! The behaviour profiles: which state of the reference library the answers follow.

use std::fmt;
use std::str::FromStr;

/// Which reference behaviour a road follows where ASAM's releases and its current code
/// give different answers.
///
/// Three answers differ: the heading returned by u/v to heading (current code: the
/// heading of the segment holding u; releases: that of the cross section before it),
/// the first point of a reference line integrated from its heading channel (current
/// code: the header's start x/y; releases: the origin, or the backward pass's point
/// when the end is given), and the reference point that a relocation uses when neither
/// `REFPOINT_V` nor `REFPOINT_V_FRACTION` is given (current code: v = 0, the reference
/// line; releases: the right border).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Compat {
    /// ASAM's current upstream code (the default).
    #[default]
    Upstream,
    /// The releases 2.0.1 and 1.2.0 (which answer alike).
    Release201,
}

impl Compat {
    /// The names [`Compat::from_str`] accepts, for messages.
    pub const ACCEPTED: &'static str = "2.0.1 or 1.2.0 (the releases), upstream or current (the default)";
}

/// A profile name that is not one of [`Compat::ACCEPTED`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownCompat(pub String);

impl fmt::Display for UnknownCompat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown compatibility profile '{}': accepted are {}", self.0, Compat::ACCEPTED)
    }
}

impl std::error::Error for UnknownCompat {}

impl FromStr for Compat {
    type Err = UnknownCompat;

    /// Reads a profile name: `2.0.1` or `1.2.0` for the releases, `upstream`, `current`
    /// or the empty string for the current code. Surrounding blanks are ignored.
    fn from_str(s: &str) -> Result<Self, UnknownCompat> {
        match s.trim() {
            "2.0.1" | "1.2.0" => Ok(Compat::Release201),
            "" | "upstream" | "current" => Ok(Compat::Upstream),
            other => Err(UnknownCompat(other.to_string())),
        }
    }
}

impl fmt::Display for Compat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Compat::Upstream => "upstream",
            Compat::Release201 => "2.0.1",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names() {
        assert_eq!("2.0.1".parse(), Ok(Compat::Release201));
        assert_eq!(" 1.2.0 ".parse(), Ok(Compat::Release201));
        assert_eq!("upstream".parse(), Ok(Compat::Upstream));
        assert_eq!("".parse(), Ok(Compat::Upstream));
        let e = "2.0".parse::<Compat>().unwrap_err();
        assert!(e.to_string().contains("'2.0'") && e.to_string().contains("1.2.0"), "{e}");
    }
}
