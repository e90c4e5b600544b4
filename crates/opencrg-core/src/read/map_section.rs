//! The `$ROAD_CRG_MPRO` section resolved into a [`MapProjection`]: each keyword's
//! value checked where it stands (the error names file, line and keyword), names
//! quoted or not, the named ellipsoids and zones looked up.

use crate::base::error::{Error, Location, Result};
use crate::model::georef::{Datum, DatumKind, Ellipsoid, MapProjection, Projection};
use crate::read::syntax::parse_f64_prefix;
use std::path::Path;

/// One keyword of the section as read: lower-case key, value text, and where it stood.
pub(crate) struct MapEntry<'a> {
    pub key: &'a str,
    pub value: &'a str,
    pub path: &'a Path,
    pub line: usize,
}

/// The keywords of the section, lower case.
const KEYWORDS: [&str; 20] = [
    "gell_nm", "gell_a", "gell_b", "lell_nm", "lell_a", "lell_b", "tran_nm", "tran_ds", "tran_rx", "tran_ry",
    "tran_rz", "tran_tx", "tran_ty", "tran_tz", "proj_nm", "proj_f0", "proj_p0", "proj_l0", "proj_e0", "proj_n0",
];

/// Whether `key` (lower case) is a keyword of the section.
pub(crate) fn is_keyword(key: &str) -> bool {
    KEYWORDS.contains(&key)
}

/// A value without its quotes.
fn name_of(value: &str) -> &str {
    let v = value.trim();
    v.trim_matches(|c| c == '\'' || c == '"').trim()
}

/// What the section says, or `None` when it has no keyword at all.
pub(crate) fn resolve(entries: &[MapEntry]) -> Result<Option<MapProjection>> {
    if entries.is_empty() {
        return Ok(None);
    }
    let find = |key: &str| entries.iter().rev().find(|e| e.key == key);
    let fail = |e: &MapEntry, message: String| {
        Error::format(e.path, Location::Line(e.line), e.key.to_ascii_uppercase(), message)
    };
    let number = |key: &str, default: f64| -> Result<f64> {
        match find(key) {
            None => Ok(default),
            Some(e) => match parse_f64_prefix(e.value) {
                Some(v) if v.is_finite() => Ok(v),
                _ => Err(fail(e, format!("'{}' is not a finite number", e.value.trim()))),
            },
        }
    };
    let ellipsoid = |prefix: &str| -> Result<Ellipsoid> {
        let (nm, a_key, b_key) = (format!("{prefix}_nm"), format!("{prefix}_a"), format!("{prefix}_b"));
        let user = || -> Result<Ellipsoid> {
            let a = number(&a_key, 0.0)?;
            let b = number(&b_key, a)?;
            Ok(Ellipsoid { name: "USERDEFINED".into(), a, b })
        };
        // A user ellipsoid needs a positive semi-major axis and a semi-minor one no longer;
        // the error names the line that made it user-defined.
        let checked = |e: Ellipsoid, at: &MapEntry| -> Result<Ellipsoid> {
            if e.a > 0.0 && e.b > 0.0 && e.b <= e.a {
                Ok(e)
            } else if e.a <= 0.0 {
                Err(fail(
                    at,
                    format!("a user-defined ellipsoid needs its semi-major axis {}", a_key.to_ascii_uppercase()),
                ))
            } else {
                Err(fail(at, format!("semi-axes {} and {} do not make an ellipsoid", e.a, e.b)))
            }
        };
        match (find(&nm), find(&a_key)) {
            (Some(e), _) => {
                let name = name_of(e.value);
                if name.eq_ignore_ascii_case("USERDEFINED") {
                    checked(user()?, e)
                } else {
                    Ellipsoid::named(name).ok_or_else(|| fail(e, format!("unknown ellipsoid '{name}'")))
                }
            }
            (None, Some(a)) => checked(user()?, a),
            (None, None) => Ok(Ellipsoid::wgs84()),
        }
    };
    let global = ellipsoid("gell")?;
    let local = ellipsoid("lell")?;
    let kind = match find("tran_nm") {
        None => DatumKind::Nop,
        Some(e) => DatumKind::named(name_of(e.value))
            .ok_or_else(|| fail(e, format!("unknown transformation '{}' (NOP, HL7, HN7 or HS7)", name_of(e.value))))?,
    };
    let datum = Datum {
        kind,
        ds: number("tran_ds", 0.0)?,
        rotation: [number("tran_rx", 0.0)?, number("tran_ry", 0.0)?, number("tran_rz", 0.0)?],
        translation: [number("tran_tx", 0.0)?, number("tran_ty", 0.0)?, number("tran_tz", 0.0)?],
    };
    let user = [
        number("proj_f0", 1.0)?,
        number("proj_p0", 0.0)?,
        number("proj_l0", 0.0)?,
        number("proj_e0", 0.0)?,
        number("proj_n0", 0.0)?,
    ];
    let Some(e) = find("proj_nm") else {
        let first = &entries[0];
        return Err(fail(first, "the map projection section names no projection (PROJ_NM)".into()));
    };
    if user[0] <= 0.0 {
        if let Some(f0) = find("proj_f0") {
            return Err(fail(f0, "the scale on the central meridian must be positive".into()));
        }
    }
    let projection = Projection::named(name_of(e.value), user).map_err(|m| fail(e, m))?;
    Ok(Some(MapProjection { global, local, datum, projection }))
}
