//! Numbers as tick labels (decades as powers of ten) and round lengths for scale bars.

/// A tick label: the number with at most six decimals, trailing zeros dropped, never
/// "-0" (steps of 1, 2 or 5 times a power of ten need no more digits than they have).
pub fn tick(v: f64) -> String {
    let text = format!("{v:.6}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    match text {
        "-0" | "" => "0".to_string(),
        t => t.to_string(),
    }
}

/// A power of ten as "10" with its exponent in superscript digits, or as a plain
/// number for 0.001 to 1000.
pub fn decade(v: f64) -> String {
    let exponent = v.log10().round() as i32;
    if (-3..=3).contains(&exponent) {
        return tick(10f64.powi(exponent));
    }
    let superscript: String = exponent
        .to_string()
        .chars()
        .map(|c| match c {
            '-' => '\u{207B}',
            '1' => '\u{00B9}',
            '2' => '\u{00B2}',
            '3' => '\u{00B3}',
            d => char::from_u32(0x2070 + d.to_digit(10).unwrap_or(0)).unwrap_or(d),
        })
        .collect();
    format!("10{superscript}")
}

/// A length of 1, 2 or 5 times a power of ten, at most `max`.
pub fn round_length(max: f64) -> f64 {
    let p = 10f64.powf(max.log10().floor());
    [5.0, 2.0, 1.0].into_iter().map(|k| k * p).find(|&l| l <= max).unwrap_or(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_labels_keep_the_digits_they_need() {
        assert_eq!(tick(0.30000000000000004), "0.3");
        assert_eq!(tick(-0.0000001), "0");
        assert_eq!(tick(-1.25), "-1.25");
        assert_eq!(tick(512340.0), "512340");
        assert_eq!(tick(0.002), "0.002");
    }

    #[test]
    fn decades_are_powers_of_ten() {
        assert_eq!(decade(0.01), "0.01");
        assert_eq!(decade(1.0), "1");
        assert_eq!(decade(1000.0), "1000");
        assert_eq!(decade(1e-6), "10\u{207B}\u{2076}");
        assert_eq!(decade(1e12), "10\u{00B9}\u{00B2}");
    }

    #[test]
    fn scale_bars_are_one_two_five() {
        assert_eq!(round_length(33.0), 20.0);
        assert_eq!(round_length(0.6), 0.5);
    }
}
