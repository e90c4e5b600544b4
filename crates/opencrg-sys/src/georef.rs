//! Roads on the earth in C: the global origin (ASAM's development API:
//! `crgEvalxyz2enh`, `crgEvalenh2xyz`, `crgDataSetGetGlobalOrigin`,
//! `crgDataSetSetGlobalOrigin`) and geodetic coordinates through the road's map
//! projection (`crgEvalxyz2llh`, `crgEvalllh2xyz`, degrees). Every call returns 1 on
//! success and 0 for an unknown id, a null output or, for the geodetic ones, a road
//! without a map projection.
#![allow(non_snake_case)] // the C API's parameter names

use crate::entry::{answer, answer_as, call_name};
use crate::ptr::out;
use opencrg_core::georef::GlobalOrigin;
use opencrg_core::{ContactPoint, Earth};
use std::ffi::c_int;

thread_local! {
    /// The chain of the last map projection this thread converted with: building one
    /// reads its projection definitions (microseconds), a conversion takes far less.
    static LAST_EARTH: std::cell::RefCell<Option<Earth>> = const { std::cell::RefCell::new(None) };
}

/// `f` with the chain of the road's map projection (built again only when the projection
/// differs from the last one this thread used); `None` for a road without one.
fn with_earth<T>(road: &opencrg_core::Road, f: impl FnOnce(&Earth) -> Option<T>) -> Option<T> {
    let map = road.header().map.as_ref()?;
    LAST_EARTH.with(|cell| {
        let mut last = cell.borrow_mut();
        if last.as_ref().is_none_or(|e| e.map() != map) {
            *last = Some(Earth::new(map).ok()?);
        }
        f(last.as_ref()?)
    })
}

/// Runs `f` on a contact point's road and writes its triple: 1, or 0 when an output is
/// null, the id unknown or `f` gives nothing.
fn on_cp_road(
    name: fn() -> &'static str,
    cp_id: c_int,
    outs: (Option<&mut f64>, Option<&mut f64>, Option<&mut f64>),
    f: impl FnOnce(&opencrg_core::Road) -> Option<[f64; 3]> + Send,
) -> c_int {
    let (Some(a), Some(b), Some(c)) = outs else { return 0 };
    answer_as(name, 0, |call| match call.on_cp(cp_id, |cp: &mut ContactPoint| f(cp.road())) {
        Some(Some([x, y, z])) => {
            (*a, *b, *c) = (x, y, z);
            1
        }
        _ => 0,
    })
}

/// ======================================================================================
/// ROADS ON THE EARTH: the global origin (REFERENCE_LINE_OFFSET_*, the names and argument
/// orders of ASAM's development API) and, beyond it, geodetic coordinates through the
/// road's map projection ($ROAD_CRG_MPRO). Each returns 1 on success, 0 for an unknown
/// id, a null output or (crgEvalxyz2llh, crgEvalllh2xyz) a road without a projection.
/// ======================================================================================
///
/// East, north and height of the local point (x, y, z) of a contact point's road: the
/// point turned about the reference line's first point by the origin's heading, then
/// shifted by the origin.
///
/// # Safety
/// `e`, `n` and `h` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvalxyz2enh(
    cpId: c_int,
    x: f64,
    y: f64,
    z: f64,
    e: *mut f64,
    n: *mut f64,
    h: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let outs = unsafe { (out(e), out(n), out(h)) };
    on_cp_road(call_name!(), cpId, outs, |road| Some(road.xyz_to_enh(x, y, z)))
}

/// The local point (x, y, z) of a contact point's road at east, north and height.
///
/// # Safety
/// `x`, `y` and `z` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvalenh2xyz(
    cpId: c_int,
    e: f64,
    n: f64,
    h: f64,
    x: *mut f64,
    y: *mut f64,
    z: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let outs = unsafe { (out(x), out(y), out(z)) };
    on_cp_road(call_name!(), cpId, outs, |road| Some(road.enh_to_xyz(e, n, h)))
}

/// Latitude and longitude (degrees) and height on the global ellipsoid (WGS 84 unless
/// the road's map section names another) of the local point (x, y, z).
///
/// # Safety
/// `lat`, `lon` and `alt` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvalxyz2llh(
    cpId: c_int,
    x: f64,
    y: f64,
    z: f64,
    lat: *mut f64,
    lon: *mut f64,
    alt: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let outs = unsafe { (out(lat), out(lon), out(alt)) };
    on_cp_road(call_name!(), cpId, outs, |road| with_earth(road, |e| e.xyz_to_llh(road, [x, y, z]).ok()))
}

/// The local point (x, y, z) at latitude and longitude (degrees) and height on the
/// global ellipsoid.
///
/// # Safety
/// `x`, `y` and `z` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvalllh2xyz(
    cpId: c_int,
    lat: f64,
    lon: f64,
    alt: f64,
    x: *mut f64,
    y: *mut f64,
    z: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let outs = unsafe { (out(x), out(y), out(z)) };
    on_cp_road(call_name!(), cpId, outs, |road| Earth::of(road).and_then(|e| e.llh_to_xyz(road, [lat, lon, alt])).ok())
}

/// The global origin of a data set: offsets x, y, z (m) and heading phi (rad), as
/// `REFERENCE_LINE_OFFSET_*` gave them and modifiers that moved the road changed them.
///
/// # Safety
/// `x`, `y`, `z` and `phi` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetGlobalOrigin(
    dataSetId: c_int,
    x: *mut f64,
    y: *mut f64,
    z: *mut f64,
    phi: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let (Some(x), Some(y), Some(z), Some(phi)) = (unsafe { (out(x), out(y), out(z), out(phi)) }) else { return 0 };
    answer!(0, |call| {
        let Some(road) = call.road(dataSetId) else { return 0 };
        let o = road.global_origin();
        (*x, *y, *z, *phi) = (o.x, o.y, o.z, o.phi);
        1
    })
}

/// Sets the global origin of a data set. This moves the global frame, not the road:
/// x/y/z answers stay, east/north/height and geodetic answers change.
#[no_mangle]
pub extern "C" fn crgDataSetSetGlobalOrigin(dataSetId: c_int, x: f64, y: f64, z: f64, phi: f64) -> c_int {
    if ![x, y, z, phi].iter().all(|v| v.is_finite()) {
        return 0;
    }
    answer!(0, |call| call
        .change_road(dataSetId, |road| road.set_global_origin(GlobalOrigin { x, y, z, phi }))
        .map_or(0, |()| 1))
}
