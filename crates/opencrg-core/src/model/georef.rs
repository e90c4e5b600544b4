//! Where a road lies on the earth, as data: the global origin of its local x/y/z frame
//! (`REFERENCE_LINE_OFFSET_*`) and the map projection of its `$ROAD_CRG_MPRO` section
//! (ellipsoids, datum transformation, transverse Mercator parameters). The named
//! ellipsoids and projection zones are resolved here; the projection arithmetic lives
//! in `geo`.

use crate::base::math;

/// The global origin: how the road's local x/y/z frame sits in the projected
/// east/north/height frame. A local point is turned about the reference line's first
/// point by `phi`, then shifted by (`x`, `y`, `z`).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct GlobalOrigin {
    /// `REFERENCE_LINE_OFFSET_X`, m.
    pub x: f64,
    /// `REFERENCE_LINE_OFFSET_Y`, m.
    pub y: f64,
    /// `REFERENCE_LINE_OFFSET_Z`, m.
    pub z: f64,
    /// `REFERENCE_LINE_OFFSET_PHI`, rad.
    pub phi: f64,
}

impl GlobalOrigin {
    /// East, north and height of the local point `p`, for a road whose reference line
    /// starts at `first` (local x, y).
    pub fn to_global(&self, first: (f64, f64), p: [f64; 3]) -> [f64; 3] {
        let (s, c) = math::sin_cos(self.phi);
        let (dx, dy) = (p[0] - first.0, p[1] - first.1);
        [first.0 + dx * c - dy * s + self.x, first.1 + dx * s + dy * c + self.y, p[2] + self.z]
    }

    /// The local point whose east, north and height are `q` (the inverse of
    /// [`GlobalOrigin::to_global`]).
    pub fn to_local(&self, first: (f64, f64), q: [f64; 3]) -> [f64; 3] {
        let (s, c) = math::sin_cos(self.phi);
        let (dx, dy) = (q[0] - self.x - first.0, q[1] - self.y - first.1);
        [first.0 + dx * c + dy * s, first.1 - dx * s + dy * c, q[2] - self.z]
    }

    /// The same origin for a road whose reference line now starts at `new_first` instead
    /// of `first` (the origin turns the road about its first point): every local point
    /// keeps its east, north and height.
    pub(crate) fn for_start(&self, first: (f64, f64), new_first: (f64, f64)) -> GlobalOrigin {
        let (s, c) = math::sin_cos(self.phi);
        let (dx, dy) = (first.0 - new_first.0, first.1 - new_first.1);
        GlobalOrigin { x: self.x + dx - (dx * c - dy * s), y: self.y + dy - (dx * s + dy * c), ..*self }
    }

    /// The origin after the road was moved rigidly: turned by `angle`, its first point
    /// carried from `first` to `moved_first`, its heights raised by `dz`. Every surface
    /// point keeps its east, north and height.
    pub(crate) fn after_move(&self, first: (f64, f64), moved_first: (f64, f64), angle: f64, dz: f64) -> GlobalOrigin {
        let p = self.phi - angle;
        GlobalOrigin {
            x: self.x + first.0 - moved_first.0,
            y: self.y + first.1 - moved_first.1,
            z: self.z - dz,
            phi: math::atan2(math::sin(p), math::cos(p)),
        }
    }
}

/// A rotational ellipsoid by its semi-axes.
#[derive(Debug, Clone, PartialEq)]
pub struct Ellipsoid {
    /// The name as the file gives it (upper case), `USERDEFINED` for given axes.
    pub name: String,
    /// Semi-major axis, m.
    pub a: f64,
    /// Semi-minor axis, m (equal to `a` for a sphere).
    pub b: f64,
}

/// The named ellipsoids of the specification: name, semi-major axis, and inverse
/// flattening (0 for a sphere) or, where the registry defines the ellipsoid by it,
/// the semi-minor axis (negative here to tell them apart). EPSG codes in brackets; the
/// DHDN variant of Bessel's is the one German state surveys use.
const NAMED_ELLIPSOIDS: [(&str, f64, f64); 16] = [
    ("WGS84", 6_378_137.0, 298.257_223_563),               // EPSG 7030
    ("AIRY1830", 6_377_563.396, 299.324_964_6),            // EPSG 7001
    ("AIRYMODIFIED1849", 6_377_340.189, 299.324_964_6),    // EPSG 7002
    ("BESSEL1841", 6_377_397.155, 299.152_812_8),          // EPSG 7004
    ("BESSELMODIFIED", 6_377_492.018, 299.152_812_8),      // EPSG 7005
    ("BESSELNAMIBIAGLM", 6_377_483.865, 299.152_812_8),    // EPSG 7046
    ("BESSELDHDN", 6_377_397.155, 299.152_815_4),          // DHDN
    ("CLARKE1866", 6_378_206.4, -6_356_583.8),             // EPSG 7008
    ("CLARKE1866AUTHALICSPHERE", 6_370_997.0, 0.0),        // EPSG 7052
    ("CLARKE1880IGN", 6_378_249.2, -6_356_515.0),          // EPSG 7011
    ("GRS1980", 6_378_137.0, 298.257_222_101),             // EPSG 7019
    ("GRS1980AUTHALICSPHERE", 6_371_007.0, 0.0),           // EPSG 7048
    ("INTERNATIONAL1924", 6_378_388.0, 297.0),             // EPSG 7022
    ("INTERNATIONAL1924AUTHALICSPHERE", 6_371_228.0, 0.0), // EPSG 7057
    ("KRASSOWSKY1940", 6_378_245.0, 298.3),                // EPSG 7024
    ("USERDEFINED", 0.0, 0.0),
];

impl Ellipsoid {
    /// WGS 84, the default global ellipsoid.
    pub fn wgs84() -> Ellipsoid {
        Ellipsoid::named("WGS84").expect("WGS84 is in the table")
    }

    /// The ellipsoid of a specification name (any case); `None` for an unknown name
    /// and for `USERDEFINED` (whose axes the file gives).
    pub fn named(name: &str) -> Option<Ellipsoid> {
        let upper = name.to_ascii_uppercase();
        let &(name, a, second) = NAMED_ELLIPSOIDS.iter().find(|e| e.0 == upper && e.0 != "USERDEFINED")?;
        let b = match second {
            s if s < 0.0 => -s,
            0.0 => a,
            rf => a * (1.0 - 1.0 / rf),
        };
        Some(Ellipsoid { name: name.to_string(), a, b })
    }
}

/// The datum transformation between the global and the local ellipsoid (`TRAN_*`; the
/// parameters take earth-centred coordinates of the global datum to the local one).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Datum {
    /// Which transformation.
    pub kind: DatumKind,
    /// Scale minus one.
    pub ds: f64,
    /// Rotations about x, y, z, rad.
    pub rotation: [f64; 3],
    /// Translation, m.
    pub translation: [f64; 3],
}

/// The datum transformation types of the specification.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum DatumKind {
    /// `NOP`: earth-centred coordinates are taken over unchanged.
    #[default]
    Nop,
    /// `HL7`: seven-parameter Helmert with the rotation linearised (exact inverse).
    Hl7,
    /// `HN7`: seven-parameter Helmert with the exact rotation (coordinate-frame convention).
    Hn7,
    /// `HS7`: the linearised rotation with the scale on its diagonal; the way back negates
    /// every parameter.
    Hs7,
}

impl DatumKind {
    /// The specification's name of the kind.
    pub fn name(self) -> &'static str {
        match self {
            DatumKind::Nop => "NOP",
            DatumKind::Hl7 => "HL7",
            DatumKind::Hn7 => "HN7",
            DatumKind::Hs7 => "HS7",
        }
    }

    /// The kind of a specification name (any case).
    pub fn named(name: &str) -> Option<DatumKind> {
        match name.to_ascii_uppercase().as_str() {
            "NOP" => Some(DatumKind::Nop),
            "HL7" => Some(DatumKind::Hl7),
            "HN7" => Some(DatumKind::Hn7),
            "HS7" => Some(DatumKind::Hs7),
            _ => None,
        }
    }
}

/// A transverse Mercator projection (`PROJ_*`, or what a named zone implies).
#[derive(Debug, Clone, PartialEq)]
pub struct Projection {
    /// The name as the file gives it (upper case).
    pub name: String,
    /// Scale on the central meridian (`PROJ_F0`).
    pub scale: f64,
    /// Latitude of origin, rad (`PROJ_P0`).
    pub lat0: f64,
    /// Longitude of the central meridian, rad (`PROJ_L0`).
    pub lon0: f64,
    /// False easting, m (`PROJ_E0`).
    pub false_east: f64,
    /// False northing, m (`PROJ_N0`).
    pub false_north: f64,
}

/// UTM band letters, south to north.
const UTM_BANDS: &str = "CDEFGHJKLMNPQRSTUVWX";
/// How many of them lie in the southern hemisphere (C to M).
const UTM_SOUTHERN_BANDS: usize = 10;

impl Projection {
    /// The projection of a `PROJ_NM` value (any case) with the `PROJ_*` values of the
    /// section for `TM` (`user`: scale, latitude and longitude of origin, false easting
    /// and northing); `Err` says what is wrong with the name.
    pub fn named(name: &str, user: [f64; 5]) -> Result<Projection, String> {
        let upper = name.to_ascii_uppercase();
        let (family, zone) = match upper.split_once('_') {
            Some((f, z)) => (f, Some(z)),
            None => (upper.as_str(), None),
        };
        let number = |z: Option<&str>, max: u32| -> Result<u32, String> {
            let z = z.ok_or_else(|| format!("'{upper}' lacks its zone number"))?;
            z.parse::<u32>().ok().filter(|&n| n <= max).ok_or_else(|| format!("'{z}' is no zone number of 0 to {max}"))
        };
        let deg = f64::to_radians;
        let (scale, lat0, lon0, false_east, false_north) = match family {
            "GK3" => {
                let n = number(zone, 119)?;
                (1.0, 0.0, deg(3.0 * f64::from(n)), 1e6 * f64::from(n) + 5e5, 0.0)
            }
            "GK6" => {
                let n = number(zone, 59)?;
                (1.0, 0.0, deg(6.0 * f64::from(n) - 3.0), 1e6 * f64::from(n) + 5e5, 0.0)
            }
            "UTM" => {
                let z = zone.ok_or_else(|| format!("'{upper}' lacks its zone and band, as in UTM_32U"))?;
                let band =
                    z.chars().last().filter(|c| c.is_ascii_alphabetic()).ok_or_else(|| {
                        format!("'{z}' ends in no band letter (C to X without I and O), as in UTM_32U")
                    })?;
                let position = UTM_BANDS
                    .find(band)
                    .ok_or_else(|| format!("band letter '{band}' does not exist (C to X without I and O)"))?;
                let n = z[..z.len() - 1]
                    .parse::<u32>()
                    .ok()
                    .filter(|n| (1..=60).contains(n))
                    .ok_or_else(|| format!("'{}' is no UTM zone number of 1 to 60", &z[..z.len() - 1]))?;
                let north = if position < UTM_SOUTHERN_BANDS { 1e7 } else { 0.0 };
                (0.9996, 0.0, deg(6.0 * f64::from(n) - 183.0), 5e5, north)
            }
            "TM" => {
                let lon0 = match zone {
                    Some(_) => deg(f64::from(number(zone, 359)?)),
                    None => user[2],
                };
                (user[0], user[1], lon0, user[3], user[4])
            }
            _ => return Err(format!("unknown projection '{name}' (GK3_n, GK6_n, UTM_nnB, TM_n or TM)")),
        };
        Ok(Projection { name: upper.clone(), scale, lat0, lon0, false_east, false_north })
    }
}

/// Everything the `$ROAD_CRG_MPRO` section says, resolved.
#[derive(Debug, Clone, PartialEq)]
pub struct MapProjection {
    /// The ellipsoid of the geodetic coordinates the road is placed in (`GELL_*`).
    pub global: Ellipsoid,
    /// The ellipsoid of the projection (`LELL_*`).
    pub local: Ellipsoid,
    /// The transformation between the global and the local ellipsoid's datum (`TRAN_*`).
    pub datum: Datum,
    /// The projection (`PROJ_*`).
    pub projection: Projection,
}

/// Tolerances of the map checks (options `CHECK_PRO` and `CHECK_WGS`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapTolerances {
    /// How far, m, the WGS 84 start and end may lie from the projected start and end.
    pub projected: f64,
    /// How much, m, the geodesic start-to-end distance may differ from the x/y one.
    pub geodesic: f64,
}

impl Default for MapTolerances {
    fn default() -> Self {
        MapTolerances { projected: 5e-3, geodesic: 10.0 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn origin_round_trip_and_move() {
        let o = GlobalOrigin { x: 690_000.0, y: 5_330_000.0, z: 500.0, phi: 0.3 };
        let first = (10.0, -4.0);
        let p = [17.0, 3.0, 1.5];
        let q = o.to_global(first, p);
        let back = o.to_local(first, q);
        assert!((0..3).all(|i| (back[i] - p[i]).abs() < 1e-9));
        // Move the road: turn by 0.5 about (2, 1), shift by (3, -7, 2).
        let (angle, c, t) = (0.5f64, (2.0, 1.0), (3.0, -7.0, 2.0));
        let mv = |x: f64, y: f64| {
            let (s, co) = math::sin_cos(angle);
            let (dx, dy) = (x - c.0, y - c.1);
            (c.0 + dx * co - dy * s + t.0, c.1 + dx * s + dy * co + t.1)
        };
        let moved_first = mv(first.0, first.1);
        let moved_p = mv(p[0], p[1]);
        let o2 = o.after_move(first, moved_first, angle, t.2);
        let q2 = o2.to_global(moved_first, [moved_p.0, moved_p.1, p[2] + t.2]);
        assert!((0..3).all(|i| (q2[i] - q[i]).abs() < 1e-6), "{q:?} {q2:?}");
    }

    #[test]
    fn named_zones() {
        let p = Projection::named("utm_32u", [1.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
        assert_eq!((p.scale, p.false_east, p.false_north), (0.9996, 5e5, 0.0));
        assert!((p.lon0.to_degrees() - 9.0).abs() < 1e-12);
        assert_eq!(Projection::named("UTM_33H", [0.0; 5]).unwrap().false_north, 1e7);
        assert!(Projection::named("UTM_32I", [0.0; 5]).unwrap_err().contains("band letter 'I'"));
        assert!(Projection::named("UTM_61U", [0.0; 5]).is_err());
        let gk = Projection::named("GK3_4", [0.0; 5]).unwrap();
        assert!((gk.lon0.to_degrees() - 12.0).abs() < 1e-12 && gk.false_east == 4_500_000.0);
        assert!(Projection::named("LAMBERT", [0.0; 5]).is_err());
        assert!(Ellipsoid::named("besseldhdn").is_some() && Ellipsoid::named("MARS").is_none());
        assert!(Ellipsoid::named("USERDEFINED").is_none());
    }
}
