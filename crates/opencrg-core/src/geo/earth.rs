//! The chain from a road's local x/y/z to geodetic coordinates and back:
//!
//! local x/y/z --global origin--> projected east/north/height (local ellipsoid)
//! --inverse transverse Mercator--> geodetic (local ellipsoid)
//! --earth-centred, datum transformation--> geodetic (global ellipsoid, WGS 84 by default).
//!
//! The earth-centred step is taken only where the ellipsoids differ or a transformation
//! is given; heights go through it too (so `NOP` between two different ellipsoids moves
//! heights as the specification's chain does). The projection and the conversions
//! between geodetic and earth-centred coordinates are `proj4rs`'s (its transverse
//! Mercator is Poder and Engsager's, as PROJ's); the Helmert transformations are
//! `helmert`'s.

use crate::base::error::{Error, Result};
use crate::model::georef::{DatumKind, Ellipsoid, MapProjection};
use crate::model::road::Road;
use proj4rs::proj::Proj;

/// A road's map projection, ready to convert points.
#[derive(Clone)]
pub struct Earth {
    map: MapProjection,
    projected: Proj,
    local: Proj,
    local_centred: Proj,
    global: Proj,
    global_centred: Proj,
    /// Whether the geodetic coordinates of both ellipsoids are the same (no datum step).
    direct: bool,
}

impl std::fmt::Debug for Earth {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Earth").field("map", &self.map).finish_non_exhaustive()
    }
}

fn geo_error(what: impl std::fmt::Display) -> Error {
    Error::out_of_range(what.to_string())
}

fn proj(definition: &str) -> Result<Proj> {
    Proj::from_proj_string(definition).map_err(|e| geo_error(format!("projection '{definition}': {e}")))
}

fn axes(e: &Ellipsoid) -> String {
    format!("+a={:?} +b={:?}", e.a, e.b)
}

impl Earth {
    /// The chain of a map projection.
    pub fn new(map: &MapProjection) -> Result<Earth> {
        let p = &map.projection;
        let local = &map.local;
        // proj4rs takes a sphere's transverse Mercator only in its classic form.
        let sphere = if local.a == local.b { " +approx" } else { "" };
        let projected = proj(&format!(
            "+proj=tmerc {} +lat_0={:?} +lon_0={:?} +k_0={:?} +x_0={:?} +y_0={:?} +units=m{sphere}",
            axes(local),
            p.lat0.to_degrees(),
            p.lon0.to_degrees(),
            p.scale,
            p.false_east,
            p.false_north
        ))?;
        let direct = map.datum.kind == DatumKind::Nop && map.local.a == map.global.a && map.local.b == map.global.b;
        Ok(Earth {
            map: map.clone(),
            projected,
            local: proj(&format!("+proj=longlat {}", axes(local)))?,
            local_centred: proj(&format!("+proj=geocent {} +units=m", axes(local)))?,
            global: proj(&format!("+proj=longlat {}", axes(&map.global)))?,
            global_centred: proj(&format!("+proj=geocent {} +units=m", axes(&map.global)))?,
            direct,
        })
    }

    /// The chain of a road's map projection; an error when it has none.
    pub fn of(road: &Road) -> Result<Earth> {
        match &road.header.map {
            Some(map) => Earth::new(map),
            None => Err(geo_error("the road has no map projection ($ROAD_CRG_MPRO)")),
        }
    }

    /// The map projection this chain converts with.
    pub fn map(&self) -> &MapProjection {
        &self.map
    }

    fn step(from: &Proj, to: &Proj, p: (f64, f64, f64)) -> Result<(f64, f64, f64)> {
        let mut q = p;
        proj4rs::transform::transform(from, to, &mut q).map_err(geo_error)?;
        if q.0.is_finite() && q.1.is_finite() && q.2.is_finite() {
            Ok(q)
        } else {
            Err(geo_error("the point lies where the projection has no answer"))
        }
    }

    /// Latitude and longitude (degrees) and height on the global ellipsoid of the
    /// projected point east, north, height.
    pub fn enh_to_llh(&self, enh: [f64; 3]) -> Result<[f64; 3]> {
        if !enh.iter().all(|v| v.is_finite()) {
            return Err(geo_error("east, north and height must be finite"));
        }
        let geodetic = Earth::step(&self.projected, &self.local, (enh[0], enh[1], enh[2]))?;
        let (lon, lat, h) = if self.direct {
            geodetic
        } else {
            let c = Earth::step(&self.local, &self.local_centred, geodetic)?;
            let g = super::helmert::local_to_global(&self.map.datum, [c.0, c.1, c.2]);
            Earth::step(&self.global_centred, &self.global, (g[0], g[1], g[2]))?
        };
        Ok([lat.to_degrees(), lon.to_degrees(), h])
    }

    /// East, north and height in the projection of the point at latitude and longitude
    /// (degrees) and height on the global ellipsoid.
    pub fn llh_to_enh(&self, llh: [f64; 3]) -> Result<[f64; 3]> {
        if !llh.iter().all(|v| v.is_finite()) || llh[0].abs() > 90.0 {
            return Err(geo_error("latitude must lie in -90..90 degrees, longitude and height be finite"));
        }
        let geodetic = (llh[1].to_radians(), llh[0].to_radians(), llh[2]);
        let local = if self.direct {
            geodetic
        } else {
            let g = Earth::step(&self.global, &self.global_centred, geodetic)?;
            let c = super::helmert::global_to_local(&self.map.datum, [g.0, g.1, g.2]);
            Earth::step(&self.local_centred, &self.local, (c[0], c[1], c[2]))?
        };
        let p = Earth::step(&self.local, &self.projected, local)?;
        Ok([p.0, p.1, p.2])
    }

    /// Latitude, longitude (degrees) and height on the global ellipsoid of the local
    /// point (x, y, z) of `road` (through its global origin).
    pub fn xyz_to_llh(&self, road: &Road, xyz: [f64; 3]) -> Result<[f64; 3]> {
        self.enh_to_llh(road.xyz_to_enh(xyz[0], xyz[1], xyz[2]))
    }

    /// The local point (x, y, z) of `road` at latitude, longitude (degrees) and height
    /// on the global ellipsoid.
    pub fn llh_to_xyz(&self, road: &Road, llh: [f64; 3]) -> Result<[f64; 3]> {
        let [e, n, h] = self.llh_to_enh(llh)?;
        Ok(road.enh_to_xyz(e, n, h))
    }
}
