//! Comparing two clients' answers line by line, call by call.

/// Whether two printed numbers agree: both NaN, or within 1e-6 + 1e-9 |b| (the
/// conformance suite's rule: grid values are single precision in both libraries).
fn numbers_agree(a: f64, b: f64) -> bool {
    (a.is_nan() && b.is_nan()) || (a - b).abs() <= 1e-6 + 1e-9 * b.abs()
}

fn tokens_agree(a: &str, b: &str) -> bool {
    match (a.parse::<f64>(), b.parse::<f64>()) {
        (Ok(x), Ok(y)) => numbers_agree(x, y),
        _ => a == b,
    }
}

/// Whether the `index`-th part of two answer lines agrees. Part 0 is the command
/// and its arguments; every later part is a call whose first word is its return code.
/// The values of a call that returned 0 in both are not compared (the API leaves
/// them unspecified).
fn call_agrees(index: usize, a: &str, b: &str) -> bool {
    let (ta, tb): (Vec<&str>, Vec<&str>) = (a.split_whitespace().collect(), b.split_whitespace().collect());
    if ta.len() != tb.len() {
        return false;
    }
    if index > 0 && ta.first() == Some(&"0") && tb.first() == Some(&"0") {
        return true;
    }
    ta.iter().zip(&tb).all(|(x, y)| tokens_agree(x, y))
}

/// Whether two answer lines agree, call by call.
pub fn lines_agree(a: &str, b: &str) -> bool {
    let (ca, cb): (Vec<&str>, Vec<&str>) = (a.split('|').collect(), b.split('|').collect());
    ca.len() == cb.len() && ca.iter().zip(&cb).enumerate().all(|(k, (x, y))| call_agrees(k, x, y))
}

/// The names of the calls on a `q` answer line, in the order the client prints them
/// (an `xy` line holds the last three).
const CALLS: [&str; 6] = ["uv2xy", "uv2z", "uv2pk", "xy2uv", "xy2z", "xy2pk"];

/// The first call on a line that differs, named (`uv2z`, `xy2uv`, ... or the command).
pub fn first_differing_call(a: &str, b: &str) -> String {
    let command = a.split_whitespace().next().unwrap_or("?");
    let first_call = if command == "xy" { 3 } else { 0 };
    let k = a.split('|').zip(b.split('|')).enumerate().position(|(k, (x, y))| !call_agrees(k, x, y));
    match k {
        Some(k) if k > 0 => CALLS.get(first_call + k - 1).unwrap_or(&"?").to_string(),
        _ => command.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tolerance_and_return_codes() {
        assert!(lines_agree("q 1 2 | 1 0.5 nan", "q 1 2 | 1 0.5000000001 nan"));
        assert!(!lines_agree("q 1 2 | 1 0.5 0", "q 1 2 | 1 0.51 0"));
        assert!(!lines_agree("q 1 2 | 1 0.5", "q 1 2 | 0 0.5"));
        assert!(lines_agree("q 1 2 | 0 7", "q 1 2 | 0 8"), "values of refused calls are not compared");
        assert!(!lines_agree("q 1 2 | 1 nan", "q 1 2 | 1 0"));
        assert!(!lines_agree("load 1", "load 0"));
        assert_eq!(first_differing_call("q 0 0 | 1 1 1 | 1 5", "q 0 0 | 1 1 1 | 1 6"), "uv2z");
        assert_eq!(first_differing_call("xy 0 0 | 1 1 1 | 1 5", "xy 0 0 | 1 1 1 | 1 6"), "xy2z");
    }
}
