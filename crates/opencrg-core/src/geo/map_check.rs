//! The consistency of a road's WGS 84 start and end keywords with the rest of it.
//!
//! With a map projection, each given WGS 84 position is carried into the local frame and
//! must lie within `CHECK_PRO` of the reference line's start or end (x, y, z). Without
//! one, the geodesic distance between the WGS 84 start and end must match the x/y
//! distance between the reference line's ends within `CHECK_WGS`.

use super::earth::Earth;
use crate::model::road::Road;
use geographiclib_rs::{Geodesic, InverseGeodesic};

/// Where the WGS 84 keywords of `road` disagree with its reference line, one sentence
/// each naming both positions; empty when they agree or are not given.
pub fn map_disagreements(road: &Road) -> Vec<String> {
    let params = &road.header.road;
    let tolerances = road.header.map_tolerances;
    let l = &road.line;
    let ends = [(false, "start", [l.x_first, l.y_first, l.z_first]), (true, "end", [l.x_last, l.y_last, l.z_last])];
    let mut found = Vec::new();
    if road.header.map.is_some() {
        let earth = match Earth::of(road) {
            Ok(e) => e,
            Err(e) => return vec![format!("the map projection cannot be used: {e}")],
        };
        for (end, name, xyz) in ends {
            let Some(llh) = params.wgs84(end) else { continue };
            match earth.llh_to_xyz(road, llh) {
                Ok(p) => {
                    let d = (0..3).map(|i| (p[i] - xyz[i]).powi(2)).sum::<f64>().sqrt();
                    if d > tolerances.projected {
                        found.push(format!(
                            "the WGS 84 {name} (lat {:.9}, lon {:.9}, alt {:.3}) lies at x/y/z {:.4}/{:.4}/{:.4}, \
                             {d:.4} m from the reference line's {name} {:.4}/{:.4}/{:.4} (CHECK_PRO {})",
                            llh[0], llh[1], llh[2], p[0], p[1], p[2], xyz[0], xyz[1], xyz[2], tolerances.projected
                        ));
                    }
                }
                Err(e) => found.push(format!("the WGS 84 {name} cannot be projected: {e}")),
            }
        }
    } else if let (Some(a), Some(b)) = (params.wgs84(false), params.wgs84(true)) {
        let geodesic: f64 = Geodesic::wgs84().inverse(a[0], a[1], b[0], b[1]);
        let planar = (l.x_last - l.x_first).hypot(l.y_last - l.y_first);
        let eps = road.options.get_double(crate::base::settings::opt::CHECK_EPS).unwrap_or(1e-6);
        if (planar - geodesic).abs() > (eps * (planar + geodesic) / 2.0).max(tolerances.geodesic) {
            found.push(format!(
                "the WGS 84 start (lat {:.9}, lon {:.9}) and end (lat {:.9}, lon {:.9}) are {geodesic:.3} m apart, \
                 the reference line's start {:.4}/{:.4} and end {:.4}/{:.4} {planar:.3} m (CHECK_WGS {})",
                a[0], a[1], b[0], b[1], l.x_first, l.y_first, l.x_last, l.y_last, tolerances.geodesic
            ));
        }
    }
    found
}
