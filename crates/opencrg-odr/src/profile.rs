//! Road properties along s written as cubic polynomials: elevation, superelevation, lane
//! offset, lane widths and borders.

/// One record: from `s` on, the value is `a + b ds + c ds^2 + d ds^3` with `ds = s - self.s`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cubic {
    /// Where the record starts (s, or the offset from its lane section's start).
    pub s: f64,
    /// The value at `s`.
    pub a: f64,
    /// The slope at `s`.
    pub b: f64,
    /// The quadratic term.
    pub c: f64,
    /// The cubic term.
    pub d: f64,
}

impl Cubic {
    /// The value `ds` after the record's start.
    pub fn value(&self, ds: f64) -> f64 {
        self.a + ds * (self.b + ds * (self.c + ds * self.d))
    }

    /// The derivative `ds` after the record's start.
    pub fn slope(&self, ds: f64) -> f64 {
        self.b + ds * (2.0 * self.c + ds * 3.0 * self.d)
    }
}

/// Records sorted by where they start; at any s the last record starting at or before it
/// holds (before the first record, the first one extended backwards; without records, 0).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Profile {
    records: Vec<Cubic>,
}

impl Profile {
    /// The profile of `records`, in any order (records starting at the same s keep their
    /// order: the later one holds).
    pub fn new(mut records: Vec<Cubic>) -> Profile {
        records.sort_by(|a, b| a.s.total_cmp(&b.s));
        Profile { records }
    }

    /// The records, sorted by s.
    pub fn records(&self) -> &[Cubic] {
        &self.records
    }

    /// Whether there is no record (the value is 0 everywhere).
    pub fn is_empty(&self) -> bool {
        self.records.is_empty()
    }

    /// The record holding at `s`.
    fn record(&self, s: f64) -> Option<&Cubic> {
        let after = self.records.partition_point(|r| r.s <= s);
        self.records.get(after.saturating_sub(1))
    }

    /// The record holding at `s` as a cubic of its own: a record's value is the profile's
    /// there; the zero polynomial where there is no record.
    pub(crate) fn cubic_at(&self, s: f64) -> Cubic {
        self.record(s).copied().unwrap_or(Cubic { s: 0.0, a: 0.0, b: 0.0, c: 0.0, d: 0.0 })
    }

    /// Where its records start.
    pub(crate) fn starts(&self) -> impl Iterator<Item = f64> + '_ {
        self.records.iter().map(|r| r.s)
    }

    /// The value at `s`.
    pub fn at(&self, s: f64) -> f64 {
        self.record(s).map_or(0.0, |r| r.value(s - r.s))
    }

    /// The derivative at `s`.
    pub fn slope_at(&self, s: f64) -> f64 {
        self.record(s).map_or(0.0, |r| r.slope(s - r.s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_last_record_at_or_before_s_holds() {
        let p = Profile::new(vec![
            Cubic { s: 10.0, a: 5.0, b: 0.0, c: 0.0, d: 0.0 },
            Cubic { s: 0.0, a: 1.0, b: 2.0, c: 0.5, d: 0.1 },
        ]);
        assert_eq!(p.at(2.0), 1.0 + 4.0 + 2.0 + 0.8);
        assert_eq!(p.slope_at(2.0), 2.0 + 2.0 + 1.2);
        assert_eq!(p.at(10.0), 5.0);
        assert!((p.at(-1.0) - (1.0 - 2.0 + 0.5 - 0.1)).abs() < 1e-15);
        assert_eq!(Profile::default().at(3.0), 0.0);
    }
}
