//! How much one request may make. Every tool that allocates by its parameters (the
//! nodes of a road being made, the vertices of a mesh, the pixels of a picture, the
//! window a filter reads per node) sizes what it would make here first, in floating
//! point so that no count can overflow, and is refused with [`Error::TooLarge`] naming
//! the request, the size it would need and the limit, before anything is allocated.
//! What passes is allocated fallibly ([`filled`]), so that memory the system still
//! refuses becomes an error too, never an abort.

use crate::base::error::{Error, Result};
use std::fmt;

/// The memory one request may take. By default ([`Budget::machine`]) a share of the
/// memory this process can still get; a caller who means a larger request gives the
/// limit itself ([`Budget::with_bytes`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Budget {
    bytes: u64,
    basis: Basis,
    raise: &'static str,
}

/// Where the limit comes from, for the refusal's text.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Basis {
    /// A share of this many bytes the machine said were available.
    Available(u64),
    /// The machine did not say; [`Budget::FALLBACK`].
    Unknown,
    /// The caller's own.
    Given,
}

/// The cost of a road being made: bytes per grid node (the values evaluated for it by
/// rows and by long sections, the road's grid) and per cross section (the reference line
/// as points, headings, slopes, banking and elevations, the frame road its nodes are
/// placed with and its search records, the finished road's line). Peak resident memory
/// of `opencrg resample` over 1.8 to 82 million nodes grew by 7.8 bytes a node and 151 a
/// cross section, of `opencrg generate` by 234 a cross section with its polyline
/// (`docs/limits.md`); these figures are rounded up by half.
const ROAD_NODE_BYTES: f64 = 12.0;
const ROAD_SECTION_BYTES: f64 = 240.0;

impl Budget {
    /// The share of the available memory a request may take by default.
    pub const SHARE: f64 = 0.5;
    /// The memory assumed available where the system does not say (4 GiB).
    pub const FALLBACK: u64 = 4 << 30;

    /// [`Budget::SHARE`] of the memory this process can still get: the least of the
    /// system's available memory, its control group's room and its address-space limit
    /// (where the platform tells them); [`Budget::FALLBACK`] where it tells none.
    pub fn machine() -> Budget {
        match crate::base::memory::available_bytes() {
            Some(b) => Budget { bytes: (b as f64 * Self::SHARE) as u64, basis: Basis::Available(b), raise: "" },
            None => Budget { bytes: (Self::FALLBACK as f64 * Self::SHARE) as u64, basis: Basis::Unknown, raise: "" },
        }
    }

    /// A limit of `bytes`, as the caller gives it.
    pub fn with_bytes(bytes: u64) -> Budget {
        Budget { bytes, basis: Basis::Given, raise: "" }
    }

    /// The same limit, its refusals saying how the user raises it (`"--max-memory"`).
    pub fn raised_with(self, how: &'static str) -> Budget {
        Budget { raise: how, ..self }
    }

    /// The limit in bytes.
    pub fn limit(&self) -> u64 {
        self.bytes
    }

    /// `count` things of `bytes_each` bytes, for `request` (the user's words: "--size
    /// 40000 px", "a median of 1001 x 1001 nodes"): the count when it is a finite
    /// number that fits, else a refusal naming the request, the count, the memory it
    /// would need and the limit.
    pub fn admit(&self, request: &dyn fmt::Display, count: f64, unit: &str, bytes_each: f64) -> Result<usize> {
        let bytes = count * bytes_each;
        if !(count >= 0.0) || !count.is_finite() || bytes > self.bytes as f64 || count > usize::MAX as f64 {
            return Err(Error::TooLarge(format!(
                "{request} would make {} {unit} ({}); {}",
                Count(count),
                Bytes(bytes),
                self.limit_text()
            )));
        }
        Ok(count as usize)
    }

    /// A road of `cross_sections` x `long_sections` nodes, with `extra` bytes per cross
    /// section for what its making keeps beside it (a polyline through its points): the
    /// two counts when the road fits.
    pub fn admit_road(
        &self,
        request: &dyn fmt::Display,
        cross_sections: f64,
        long_sections: f64,
        extra: f64,
    ) -> Result<(usize, usize)> {
        let nodes = cross_sections * long_sections;
        let bytes = nodes * ROAD_NODE_BYTES + cross_sections * (ROAD_SECTION_BYTES + extra);
        let fits = cross_sections.is_finite() && long_sections.is_finite() && bytes <= self.bytes as f64;
        if !fits {
            return Err(Error::TooLarge(format!(
                "{request} would make a road of {} cross sections x {} long sections ({} nodes, {}); {}",
                Count(cross_sections),
                Count(long_sections),
                Count(nodes),
                Bytes(bytes),
                self.limit_text()
            )));
        }
        Ok((cross_sections as usize, long_sections as usize))
    }

    /// "the limit is ..., half of the ... available (--max-memory raises it)".
    fn limit_text(&self) -> String {
        let share = if Self::SHARE == 0.5 { "half".to_string() } else { format!("{:.0} %", 100.0 * Self::SHARE) };
        let basis = match self.basis {
            Basis::Available(b) => format!(", {share} of the {} this process can still get", Bytes(b as f64)),
            Basis::Unknown => {
                format!(", {share} of the {} assumed where the system does not say", Bytes(Self::FALLBACK as f64))
            }
            Basis::Given => String::new(),
        };
        let raise = if self.raise.is_empty() { String::new() } else { format!(" ({} raises it)", self.raise) };
        format!("the limit is {}{basis}{raise}", Bytes(self.bytes as f64))
    }
}

impl Default for Budget {
    /// [`Budget::machine`].
    fn default() -> Budget {
        Budget::machine()
    }
}

/// A vector of `n` copies of `value`, or a refusal naming `what` when the system does
/// not give the memory.
pub fn filled<T: Clone>(n: usize, value: T, what: &str) -> Result<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(n).map_err(|_| refused_of::<T>(n, what))?;
    v.resize(n, value);
    Ok(v)
}

/// The refusal of `n` values of `T` for `what` the system did not give memory for.
pub fn refused_of<T>(n: usize, what: &str) -> Error {
    Error::TooLarge(format!(
        "{what}: the system refused the memory for {} values ({})",
        Count(n as f64),
        Bytes(n as f64 * std::mem::size_of::<T>() as f64)
    ))
}

/// A count as people read it: digits grouped by thousands up to 10^15, beyond that in
/// powers of ten.
struct Count(f64);

impl fmt::Display for Count {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if !x.is_finite() {
            return write!(f, "infinitely many");
        }
        if x >= 1e15 {
            return write!(f, "{x:.1e}");
        }
        let digits = format!("{:.0}", x.max(0.0).floor());
        let mut out = String::new();
        for (i, c) in digits.chars().enumerate() {
            if i > 0 && (digits.len() - i) % 3 == 0 {
                out.push(',');
            }
            out.push(c);
        }
        f.write_str(&out)
    }
}

/// Bytes in decimal units (kB, MB, GB, TB) to three figures.
pub(crate) struct Bytes(pub f64);

impl fmt::Display for Bytes {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if !x.is_finite() {
            return write!(f, "more memory than there is");
        }
        const UNITS: [(f64, &str); 5] = [(1e15, "PB"), (1e12, "TB"), (1e9, "GB"), (1e6, "MB"), (1e3, "kB")];
        if x >= 1e18 {
            return write!(f, "{:.1e} bytes", x);
        }
        for (scale, unit) in UNITS {
            if x >= scale {
                let v = x / scale;
                return if v >= 100.0 {
                    write!(f, "{v:.0} {unit}")
                } else if v >= 10.0 {
                    write!(f, "{v:.1} {unit}")
                } else {
                    write!(f, "{v:.2} {unit}")
                };
            }
        }
        write!(f, "{x:.0} bytes")
    }
}

/// A size the user writes: a number of bytes with an optional unit (k, M, G, T: powers
/// of 1000; Ki, Mi, Gi, Ti: of 1024; a trailing B allowed), as `--max-memory 8G` or
/// `max_memory="512MiB"`.
pub fn parse_bytes(text: &str) -> std::result::Result<u64, String> {
    let t = text.trim();
    let t = t.strip_suffix(['B', 'b']).unwrap_or(t);
    let number = t.trim_end_matches(|c: char| c.is_ascii_alphabetic());
    let unit = &t[number.len()..];
    let scale = match unit.to_ascii_lowercase().as_str() {
        "" => 1.0,
        "k" => 1e3,
        "m" => 1e6,
        "g" => 1e9,
        "t" => 1e12,
        "ki" => 1024.0,
        "mi" => 1024.0 * 1024.0,
        "gi" => 1024.0 * 1024.0 * 1024.0,
        "ti" => 1024.0 * 1024.0 * 1024.0 * 1024.0,
        _ => return Err(format!("'{text}': expected bytes, like 8G, 512M or 2GiB")),
    };
    let value: f64 = number.trim().parse().map_err(|_| format!("'{text}': expected bytes, like 8G, 512M or 2GiB"))?;
    let bytes = value * scale;
    if !(bytes >= 1.0) || bytes >= u64::MAX as f64 {
        return Err(format!("'{text}': a memory limit must be at least one byte and finite"));
    }
    Ok(bytes as u64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_and_bytes_read_as_people_write_them() {
        assert_eq!(Count(22_000_000_001.0).to_string(), "22,000,000,001");
        assert_eq!(Count(999.0).to_string(), "999");
        assert_eq!(Count(1e300).to_string(), "1.0e300");
        assert_eq!(Bytes(528e9).to_string(), "528 GB");
        assert_eq!(Bytes(1.5e6).to_string(), "1.50 MB");
        assert_eq!(Bytes(12.0).to_string(), "12 bytes");
    }

    #[test]
    fn sizes_parse_with_units() {
        assert_eq!(parse_bytes("8G"), Ok(8_000_000_000));
        assert_eq!(parse_bytes("512MiB"), Ok(512 << 20));
        assert_eq!(parse_bytes("2e9"), Ok(2_000_000_000));
        assert_eq!(parse_bytes(" 1.5 kB"), Ok(1500));
        assert!(parse_bytes("-1G").is_err());
        assert!(parse_bytes("lots").is_err());
        assert!(parse_bytes("inf").is_err());
        assert!(parse_bytes("0").is_err());
    }

    #[test]
    fn requests_beyond_the_limit_are_refused_with_the_numbers() {
        let b = Budget::with_bytes(1_000_000).raised_with("--max-memory");
        assert_eq!(b.admit(&"ten", 10.0, "pixels", 4.0).unwrap(), 10);
        let e = b.admit(&"--size 4000000000 px", 1.6e19, "pixels", 4.0).unwrap_err().to_string();
        assert!(e.contains("--size 4000000000 px would make 1.6e19 pixels"), "{e}");
        assert!(e.contains("the limit is 1.00 MB (--max-memory raises it)"), "{e}");
        assert!(b.admit(&"nan", f64::NAN, "x", 1.0).is_err());
        assert!(b.admit(&"inf", f64::INFINITY, "x", 0.0).is_err());
        let e = b.admit_road(&"u increment 1e-9 m", 1.2e11, 25.0, 0.0).unwrap_err().to_string();
        assert!(e.contains("120,000,000,000 cross sections x 25 long sections (3,000,000,000,000 nodes"), "{e}");
        assert_eq!(b.admit_road(&"small", 100.0, 5.0, 0.0).unwrap(), (100, 5));
    }

    #[test]
    fn the_machine_gives_a_positive_limit() {
        let b = Budget::machine();
        assert!(b.limit() > 0);
        let e = b.admit(&"everything", 1e30, "bytes", 1.0).unwrap_err().to_string();
        assert!(e.contains("the limit is"), "{e}");
    }

    #[test]
    fn refused_memory_is_an_error() {
        assert!(filled(usize::MAX / 2, 0u8, "test").is_err());
        assert_eq!(filled(3, 1.5f32, "test").unwrap(), vec![1.5; 3]);
    }
}
