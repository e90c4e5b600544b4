//! Round lengths for scale bars (tick labels and the ticks themselves are the toolkit's
//! drawing rules, `opencrg_tools::drawing`, which the web page shares).

/// A length of 1, 2 or 5 times a power of ten, at most `max`.
pub fn round_length(max: f64) -> f64 {
    let p = 10f64.powf(max.log10().floor());
    [5.0, 2.0, 1.0].into_iter().map(|k| k * p).find(|&l| l <= max).unwrap_or(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_bars_are_one_two_five() {
        assert_eq!(round_length(33.0), 20.0);
        assert_eq!(round_length(0.6), 0.5);
    }
}
