//! The behaviour profile of the C API, chosen by the `OPENCRG_COMPAT` environment
//! variable and read once, when a road is first loaded.

use opencrg_core::{Compat, UnknownCompat};
use std::sync::OnceLock;

/// The environment variable that chooses the profile.
const VARIABLE: &str = "OPENCRG_COMPAT";

static PROFILE: OnceLock<Result<Compat, UnknownCompat>> = OnceLock::new();

/// The profile roads are loaded with: the current upstream behaviour unless
/// `OPENCRG_COMPAT` names the releases; an error naming the accepted values when it
/// holds anything else (every load is then refused, rather than giving numbers of
/// the wrong profile).
pub(crate) fn from_environment() -> Result<Compat, String> {
    PROFILE
        .get_or_init(|| match std::env::var_os(VARIABLE) {
            None => Ok(Compat::default()),
            Some(value) => value.to_string_lossy().parse(),
        })
        .clone()
        .map_err(|e| format!("{VARIABLE}: {e}"))
}
