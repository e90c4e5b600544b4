//! How rough a road is along wheel tracks: the IRI ([`crate::iri`]) over the whole track
//! and per segment, and the ISO 8608 density and class ([`crate::psd`]).
//!
//! A track is the longitudinal profile at one v, sampled along u at the grid's
//! increment through the library's own evaluation (a [`ContactPoint`] with default
//! options). Where the road has no elevation (NaN in the data), the profile is cut: the
//! IRI averages over the runs long enough for it (each started afresh), the density over
//! the longest run, and the metres left out are reported.

use crate::analysis::iri;
use crate::analysis::psd::{self, Spectrum};
use opencrg_core::units::Num;
use opencrg_core::ContactPoint;
use opencrg_core::Road;
use opencrg_core::{Error, Result};
use std::sync::Arc;

/// The wheel tracks analysed when none are named: v = -0.85, 0 and 0.85 m.
pub const DEFAULT_TRACKS: [f64; 3] = [-0.85, 0.0, 0.85];
/// The default segment length of the IRI, in m (as road authorities report it).
pub const DEFAULT_SEGMENT: f64 = 100.0;

/// The IRI over one segment of a track.
#[derive(Debug, Clone, PartialEq)]
pub struct Segment {
    /// Where the segment starts, in u (m).
    pub u_start: f64,
    /// Where it ends, in u (m).
    pub u_end: f64,
    /// Its IRI in m/km; `None` where no part of it could be driven (no data).
    pub iri: Option<f64>,
}

/// The roughness of one track.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    /// The track's v (m).
    pub v: f64,
    /// The IRI of the whole track, in m/km.
    pub iri: f64,
    /// The IRI segment by segment.
    pub segments: Vec<Segment>,
    /// The displacement density and its ISO 8608 fit.
    pub psd: Spectrum,
    /// Metres of the track without elevation (left out of both).
    pub skipped: f64,
}

/// The profile at `v`: samples `du` apart from `u_first` to `u_last` (NaN where the road
/// has no elevation).
pub fn profile(road: &Arc<Road>, v: f64) -> Result<Vec<f64>> {
    let (u_first, u_last) = road.u_range();
    let (v_right, v_left) = road.v_range();
    if !(v >= v_right && v <= v_left) {
        return Err(Error::out_of_range(format!(
            "track at v = {} m lies outside the road, whose long sections span v = {v_right} to {v_left} m",
            Num(v)
        )));
    }
    let du = road.increments().0;
    let n = ((u_last - u_first) / du + 1e-9).floor() as usize + 1;
    let cp = ContactPoint::new(Arc::clone(road));
    Ok((0..n).map(|i| cp.uv_to_z(u_first + i as f64 * du, v).unwrap_or(f64::NAN)).collect())
}

/// The runs of finite values of `z`, as index ranges.
fn finite_runs(z: &[f64]) -> Vec<std::ops::Range<usize>> {
    let mut runs = Vec::new();
    let mut start = None;
    for (i, value) in z.iter().enumerate() {
        match (value.is_finite(), start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                runs.push(s..i);
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        runs.push(s..z.len());
    }
    runs
}

/// The roughness of the road along the tracks at `tracks` (v in m), the IRI also per
/// `segment` metres of u. Refused: a track outside the road, a road too short for the
/// IRI's initial 11 m or the density's bands, a track without any run long enough.
pub fn roughness(road: &Arc<Road>, tracks: &[f64], segment: f64) -> Result<Vec<Track>> {
    let (u_first, u_last) = road.u_range();
    let du = road.increments().0;
    if !(segment > 0.0 && segment.is_finite()) || segment < du {
        return Err(Error::out_of_range(format!(
            "segment length {} m; it must be a positive number of at least the road's u increment ({du} m)",
            Num(segment)
        )));
    }
    tracks
        .iter()
        .map(|&v| {
            let z = profile(road, v)?;
            let runs = finite_runs(&z);
            let skipped = du * (z.len() - runs.iter().map(|r| r.len()).sum::<usize>()) as f64;
            let longest = runs.iter().max_by_key(|r| r.len()).cloned().unwrap_or(0..0);
            let too_short = |what: &str, e: Error| {
                Error::out_of_range(format!(
                    "track at v = {v} m: {what}; the longest run with elevations is {:.2} m of {:.2} m ({e})",
                    du * longest.len().saturating_sub(1) as f64,
                    u_last - u_first
                ))
            };
            // Each run long enough is driven on its own; the IRI averages all their steps.
            let driven: Vec<(usize, iri::Response)> =
                runs.iter().filter_map(|r| iri::response(&z[r.clone()], du).ok().map(|resp| (r.start, resp))).collect();
            if driven.is_empty() {
                let e = iri::response(&z[longest.clone()], du).err().unwrap_or(Error::out_of_range("no data"));
                return Err(too_short("no run of elevations long enough for the IRI", e));
            }
            let steps: usize = driven.iter().map(|(_, r)| r.rectified.len()).sum();
            let total: f64 = driven.iter().flat_map(|(_, r)| &r.rectified).sum();
            let runs: Vec<(f64, &iri::Response)> = driven.iter().map(|(start, r)| (*start as f64 * du, r)).collect();
            let segments = iri::segment_iris(&runs, u_last - u_first, segment)?
                .into_iter()
                .enumerate()
                .map(|(k, iri)| Segment {
                    u_start: u_first + k as f64 * segment,
                    u_end: (u_first + (k + 1) as f64 * segment).min(u_last),
                    iri,
                })
                .collect();
            let psd = psd::spectrum(&z[longest.clone()], du).map_err(|e| too_short("too short for the density", e))?;
            Ok(Track { v, iri: 1000.0 * total / steps as f64, segments, psd, skipped })
        })
        .collect()
}
