//! Quantities and numbers as people read them.

/// A number a user gave, written back as people write it: in powers of ten when very
/// small or large (below 10^-4, from 10^6: `1e-9`, `3e9`), plainly otherwise.
pub struct Num(pub f64);

impl std::fmt::Display for Num {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        if x != 0.0 && x.is_finite() && !(1e-4..1e6).contains(&x.abs()) {
            write!(f, "{x:e}")
        } else {
            write!(f, "{x}")
        }
    }
}

/// A count and its noun, the noun in the plural unless the count is one (`1 wheel`,
/// `4 wheels`, `0 CRG files`); the plural adds an `s`.
pub struct Count<'a>(pub usize, pub &'a str);

impl std::fmt::Display for Count<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let Count(n, noun) = *self;
        write!(f, "{n} {noun}{}", if n == 1 { "" } else { "s" })
    }
}

/// A length in metres shown to the nanometre, as short as that allows: the sums and
/// differences that place grid nodes carry rounding in their last bits
/// (`-0.9999999999999999`), which says nothing about the road.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Metres(pub f64);

impl std::fmt::Display for Metres {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        let rounded = (x * 1e9).round() / 1e9;
        // Beyond 2^53 nm (9,000 km) there is nothing to round; NaN and infinities as they are.
        let shown = if rounded.is_finite() && x.abs() < 9e6 { rounded } else { x };
        // No "-0" for a length that rounds to zero.
        write!(f, "{}", if shown == 0.0 { 0.0 } else { shown })
    }
}

#[cfg(test)]
mod tests {
    use super::{Count, Metres};

    #[test]
    fn counts_take_the_plural_unless_one() {
        assert_eq!(Count(1, "wheel").to_string(), "1 wheel");
        assert_eq!(Count(0, "CRG file").to_string(), "0 CRG files");
        assert_eq!(Count(4, "road").to_string(), "4 roads");
    }

    #[test]
    fn lengths_are_shown_to_the_nanometre() {
        let shown = |x: f64| Metres(x).to_string();
        assert_eq!(shown(-0.9999999999999999), "-1");
        assert_eq!(shown(1.1999999999999997), "1.2");
        assert_eq!(shown(739.98), "739.98");
        assert_eq!(shown(-0.0), "0");
        assert_eq!(shown(1e-12), "0");
        assert_eq!(shown(0.000_000_5), "0.0000005");
        assert_eq!(shown(1.5e7 + 0.123_456_789_1), (1.5e7 + 0.123_456_789_1).to_string());
        assert_eq!(shown(f64::NAN), "NaN");
    }
}
