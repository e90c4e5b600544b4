//! The drawing rules of the pictures: the colours of elevations and the ticks of axes,
//! one rule for the command's figures and the web page (the npm package exports them).

/// The colours of elevations, low to high: deep blue through green to yellow.
pub const ELEVATION_COLOURS: [[u8; 3]; 6] =
    [[48, 18, 59], [50, 101, 211], [27, 186, 161], [122, 221, 60], [233, 201, 40], [254, 247, 160]];

/// The colours of a figure's tracks (lines of several wheel tracks), in turn.
pub const TRACK_COLOURS: [[u8; 3]; 6] =
    [[30, 90, 200], [200, 60, 40], [40, 150, 60], [150, 60, 170], [220, 140, 20], [0, 0, 0]];

/// The grey of reference lines drawn under the data (the ISO 8608 class limits).
pub const REFERENCE_GREY: [u8; 3] = [150, 150, 150];

/// The colour of `t` in 0..1 (clamped) between the [`ELEVATION_COLOURS`] around it,
/// each channel rounded.
pub fn elevation_colour(t: f64) -> [u8; 3] {
    let stops = ELEVATION_COLOURS.len();
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) } * (stops - 1) as f64;
    let i = (t.floor() as usize).min(stops - 2);
    let f = t - i as f64;
    let (a, b) = (ELEVATION_COLOURS[i], ELEVATION_COLOURS[i + 1]);
    [0, 1, 2].map(|k| (f64::from(a[k]) + f * (f64::from(b[k]) - f64::from(a[k]))).round() as u8)
}

/// At most `at_most` ticks over [a, b], the multiples of the smallest round step (1, 2 or
/// 5 times a power of ten) that gives no more; none for an empty or infinite range.
pub fn ticks(a: f64, b: f64, at_most: usize) -> Vec<f64> {
    if !(a.is_finite() && b.is_finite() && b > a) || at_most == 0 {
        return Vec::new();
    }
    let mut power = 10f64.powf(((b - a) / at_most as f64).log10().floor());
    loop {
        for k in [1.0, 2.0, 5.0] {
            let step = k * power;
            let (first, last) = ((a / step).ceil(), (b / step).floor());
            if last - first + 1.0 <= at_most as f64 {
                return (first as i64..=last as i64).map(|n| n as f64 * step).collect();
            }
        }
        power *= 10.0;
    }
}

/// A tick label: the number with at most six decimals, trailing zeros dropped, never
/// "-0" (steps of 1, 2 or 5 times a power of ten need no more digits than they have).
pub fn tick_label(v: f64) -> String {
    let text = format!("{v:.6}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    match text {
        "-0" | "" => "0".to_string(),
        t => t.to_string(),
    }
}

/// A power of ten as "10" with its exponent in superscript digits, or as a plain
/// number for 0.001 to 1000.
pub fn decade_label(v: f64) -> String {
    let exponent = v.log10().round() as i32;
    if (-3..=3).contains(&exponent) {
        return tick_label(10f64.powi(exponent));
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_run_through_the_stops() {
        assert_eq!(elevation_colour(0.0), ELEVATION_COLOURS[0]);
        assert_eq!(elevation_colour(1.0), ELEVATION_COLOURS[5]);
        assert_eq!(elevation_colour(-3.0), ELEVATION_COLOURS[0]);
        assert_eq!(elevation_colour(0.1), [49, 60, 135]);
        assert_eq!(elevation_colour(f64::NAN), ELEVATION_COLOURS[0]);
    }

    #[test]
    fn ticks_take_the_smallest_round_step_that_fits() {
        assert_eq!(ticks(0.0, 10.0, 6), vec![0.0, 2.0, 4.0, 6.0, 8.0, 10.0]);
        assert_eq!(ticks(0.0, 10.0, 11), (0..=10).map(f64::from).collect::<Vec<_>>());
        assert_eq!(ticks(-0.3, 0.7, 5), vec![-0.2, 0.0, 0.2, 0.4, 0.6000000000000001]);
        assert_eq!(ticks(512_300.0, 512_345.0, 4), vec![512_300.0, 512_320.0, 512_340.0]);
        assert!(ticks(1.0, 1.0, 5).is_empty() && ticks(0.0, f64::INFINITY, 5).is_empty());
        for (a, b, n) in [(0.013, 0.27, 7), (-1e6, 3e6, 9), (3.0, 3.001, 2)] {
            let t = ticks(a, b, n);
            assert!(!t.is_empty() && t.len() <= n, "{a} {b} {n}: {t:?}");
            assert!(t.iter().all(|&v| v >= a && v <= b), "{t:?}");
        }
    }

    #[test]
    fn tick_labels_keep_the_digits_they_need() {
        assert_eq!(tick_label(0.30000000000000004), "0.3");
        assert_eq!(tick_label(-0.0000001), "0");
        assert_eq!(tick_label(-1.25), "-1.25");
        assert_eq!(tick_label(512340.0), "512340");
        assert_eq!(tick_label(0.002), "0.002");
    }

    #[test]
    fn decades_are_powers_of_ten() {
        assert_eq!(decade_label(0.01), "0.01");
        assert_eq!(decade_label(1.0), "1");
        assert_eq!(decade_label(1000.0), "1000");
        assert_eq!(decade_label(1e-6), "10\u{207B}\u{2076}");
        assert_eq!(decade_label(1e12), "10\u{00B9}\u{00B2}");
    }
}
