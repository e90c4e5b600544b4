//! OpenDRIVE maps with CRG surfaces in C (`crgOdr.h`): a map loaded once (its roads
//! indexed, its CRG files read), a probe per wheel or thread, the ground at world x/y and
//! the world point of road coordinates. Ids as in the classic API: maps > 0, probes >= 0;
//! calls return 1 on success and 0 otherwise (an unknown id, a null output, a point off
//! every road). Probes live in a table of slots like the contact points ([`Slots`]): a
//! thread evaluating its own probe takes no lock, others take the probe's own; queries
//! allocate nothing and make no system call.
#![allow(non_snake_case)] // the C API's parameter names

use crate::c_path;
use crate::entry::answer;
use crate::lock::lock;
use crate::ptr::{in_str, out};
use crate::slots::Slots;
use opencrg_odr::{Probe, Surface};
use std::ffi::{c_char, c_int};
use std::sync::{Arc, Mutex};

/// The loaded maps (index + 1 is the id).
static MAPS: Mutex<Vec<Option<Arc<Surface>>>> = Mutex::new(Vec::new());

/// The probes, by id, with the map each was made on.
static PROBES: Slots<Probe> = Slots::new();

fn map(id: c_int) -> Option<Arc<Surface>> {
    let index = usize::try_from(id).ok()?.checked_sub(1)?;
    lock(&MAPS).get(index)?.clone()
}

/// ======================================================================================
/// OPENDRIVE MAPS: loading, probes, the ground at world x/y. Declared in crgOdr.h.
/// ======================================================================================
///
/// Reads an OpenDRIVE map (.xodr), indexes its roads and reads the CRG files its
/// `<surface><CRG>` records name (relative to the map's folder); returns the map's id
/// (> 0), or 0 with a message naming the file, line and element.
///
/// # Safety
/// `filename` is null or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn crgOdrMapLoad(filename: *const c_char) -> c_int {
    // SAFETY: the contract above.
    let filename = unsafe { in_str(filename) };
    answer!(0, |call| {
        let Some(filename) = filename else {
            call.fatal(&format!("{}: no file name given", call.name()));
            return 0;
        };
        match Surface::load(c_path::path_of(filename)) {
            Ok(surface) => {
                let mut maps = lock(&MAPS);
                maps.push(Some(Arc::new(surface)));
                c_int::try_from(maps.len()).unwrap_or(0)
            }
            Err(e) => {
                call.fatal(&format!("{}: {e}", call.name()));
                0
            }
        }
    })
}

/// Releases a map and its probes; 1, or 0 for an unknown id.
#[no_mangle]
pub extern "C" fn crgOdrMapRelease(mapId: c_int) -> c_int {
    answer!(0, |_| {
        let released = {
            let mut maps = lock(&MAPS);
            let index = usize::try_from(mapId).ok().and_then(|i| i.checked_sub(1));
            index.and_then(|i| maps.get_mut(i)).and_then(Option::take).is_some()
        };
        if released {
            PROBES.delete_of(Some(mapId), |_| {});
        }
        c_int::from(released)
    })
}

/// The number of roads of a map (the road indexes of the other calls count from 0 in the
/// file's order), or -1 for an unknown id.
#[no_mangle]
pub extern "C" fn crgOdrMapGetRoadCount(mapId: c_int) -> c_int {
    answer!(-1, |_| { map(mapId).map_or(-1, |m| c_int::try_from(m.map().roads.len()).unwrap_or(c_int::MAX)) })
}

/// Makes a probe on a map: one per wheel or thread, it keeps where its wheel was; returns
/// its id (>= 0), or -1 for an unknown map.
#[no_mangle]
pub extern "C" fn crgOdrProbeCreate(mapId: c_int) -> c_int {
    answer!(-1, |_| {
        let Some(surface) = map(mapId) else { return -1 };
        PROBES.create(mapId, surface.probe())
    })
}

/// Releases a probe; 1, or 0 for an unknown id.
#[no_mangle]
pub extern "C" fn crgOdrProbeRelease(probeId: c_int) -> c_int {
    answer!(0, |_| c_int::from(PROBES.delete(probeId).is_some()))
}

/// The ground at the world point (x, y): the surface's height with the CRG records laid
/// on (NaN in a hole of a CRG grid), the friction coefficient (NaN where neither a
/// record nor the lane's material gives one), the road's index, the lane's id, s and t.
/// Returns 1, or 0 off every road, for an unknown probe or a null output (the outputs
/// then unchanged).
///
/// # Safety
/// Each output is null or points to a writable value of its type.
#[no_mangle]
pub unsafe extern "C" fn crgOdrEvalxy(
    probeId: c_int,
    x: f64,
    y: f64,
    z: *mut f64,
    friction: *mut f64,
    road: *mut c_int,
    lane: *mut c_int,
    s: *mut f64,
    t: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let outs = unsafe { (out(z), out(friction), out(road), out(lane), out(s), out(t)) };
    answer!(0, |_| {
        let (Some(z), Some(friction), Some(road), Some(lane), Some(s), Some(t)) = outs else { return 0 };
        let Some(Some(g)) = PROBES.with_mut(probeId, |p| p.ground(x, y)) else { return 0 };
        (*z, *friction, *s, *t) = (g.z, g.friction, g.s, g.t);
        (*road, *lane) = (c_int::try_from(g.road).unwrap_or(-1), g.lane);
        1
    })
}

/// The upward unit normal of the surface at the world point (x, y), CRG records laid on.
/// Returns 1, or 0 off every road, where a height around it is NaN, for an unknown probe
/// or a null output.
///
/// # Safety
/// Each output is null or points to a writable double.
#[no_mangle]
pub unsafe extern "C" fn crgOdrEvalxy2normal(
    probeId: c_int,
    x: f64,
    y: f64,
    nx: *mut f64,
    ny: *mut f64,
    nz: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let outs = unsafe { (out(nx), out(ny), out(nz)) };
    answer!(0, |_| {
        let (Some(nx), Some(ny), Some(nz)) = outs else { return 0 };
        let Some(Some([a, b, c])) = PROBES.with_mut(probeId, |p| p.normal(x, y)) else { return 0 };
        (*nx, *ny, *nz) = (a, b, c);
        1
    })
}

/// The world point of the surface at (s, t) of the road with this index, CRG records
/// laid on. Returns 1, or 0 for an unknown probe or road, a point the road cannot place or
/// a null output.
///
/// # Safety
/// Each output is null or points to a writable double.
#[no_mangle]
pub unsafe extern "C" fn crgOdrEvalst2xyz(
    probeId: c_int,
    road: c_int,
    s: f64,
    t: f64,
    x: *mut f64,
    y: *mut f64,
    z: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let outs = unsafe { (out(x), out(y), out(z)) };
    answer!(0, |_| {
        let (Some(x), Some(y), Some(z)) = outs else { return 0 };
        let Ok(road) = usize::try_from(road) else { return 0 };
        let Some(Some((px, py, g))) = PROBES.with_mut(probeId, |p| p.ground_st(road, s, t)) else { return 0 };
        (*x, *y, *z) = (px, py, g.z);
        1
    })
}
