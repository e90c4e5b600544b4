//! The evaluation calls on a contact point: u/v to x/y, z, heading and curvature; x/y to
//! u/v, z, heading and curvature. Each first tries the common case the owner's way (the
//! calling thread owns the contact point; the core's lean paths: no lock, no call, no
//! panic guard), then the general way inside the guard; each is counted by the
//! performance statistics while they are active (`counted!`).
#![allow(non_snake_case)] // the C API's parameter names

use crate::entry::{answer_as, call_name};
use crate::perf_stat::counted;
use crate::ptr::{out, put_pair};
use crate::registry;
use opencrg_core::ContactPoint;
use std::ffi::c_int;

/// An evaluation giving two values: 1, or 0 (outputs untouched) when an output is
/// missing, the id unknown or the evaluation refused.
fn eval2(
    name: fn() -> &'static str,
    cp_id: c_int,
    a: Option<&mut f64>,
    b: Option<&mut f64>,
    f: impl FnOnce(&mut ContactPoint) -> opencrg_core::Result<(f64, f64)> + Send,
) -> c_int {
    let answered = put_pair(a, b, || answer_as(name, None, |call| call.on_cp(cp_id, |cp| f(cp).ok()).flatten()));
    if answered == 0 {
        tell_fault(name, cp_id);
    }
    answered
}

/// After a refusal: when the contact point's road is read in place and its file was cut
/// short or changed, a warning naming the file (the reference's refusals are silent;
/// this one has a cause the caller must hear of).
#[cold]
#[inline(never)]
fn tell_fault(name: fn() -> &'static str, cp_id: c_int) {
    answer_as(name, (), |call| {
        if let Some(Some(text)) = call.on_cp(cp_id, |cp| cp.road().grid().fault().map(|e| e.to_string())) {
            call.warn(&format!("{}: {text}", call.name()));
        }
    });
}

/// An evaluation giving one value: 1, or 0 when the output is missing or the id unknown,
/// or 0 with the output set to 0 when the evaluation is refused.
fn eval1(
    name: fn() -> &'static str,
    cp_id: c_int,
    out: Option<&mut f64>,
    f: impl FnOnce(&mut ContactPoint) -> opencrg_core::Result<f64> + Send,
) -> c_int {
    let Some(out) = out else { return 0 };
    let answered = answer_as(name, 0, |call| {
        call.on_cp(cp_id, |cp| match f(cp) {
            Ok(z) => {
                *out = z;
                1
            }
            Err(_) => {
                *out = 0.0;
                0
            }
        })
        .unwrap_or(0)
    });
    if answered == 0 {
        tell_fault(name, cp_id);
    }
    answered
}

/// The x/y search of the general way: without a second try of the lean search where it
/// just declined.
fn search_xy(cp: &mut ContactPoint, declined: bool, x: f64, y: f64) -> opencrg_core::Result<(f64, f64)> {
    if declined {
        cp.xy_to_uv_general(x, y)
    } else {
        cp.xy_to_uv(x, y)
    }
}

/// x/y to u/v.
///
/// # Safety
/// `u` and `v` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvalxy2uv(cpId: c_int, x: f64, y: f64, u: *mut f64, v: *mut f64) -> c_int {
    /// Every case but the common one; `declined`: the lean search was tried and declined.
    #[inline(never)]
    fn general(cpId: c_int, declined: bool, x: f64, y: f64, u: &mut f64, v: &mut f64) -> c_int {
        eval2(call_name!(), cpId, Some(u), Some(v), |cp| search_xy(cp, declined, x, y))
    }
    counted!(cpId, {
        // SAFETY: the contract above.
        let (Some(u), Some(v)) = (unsafe { (out(u), out(v)) }) else { return 0 };
        // The common case first, as in `crgEvaluv2z`: the owner's way, the lean search.
        match registry::with_owned_cp_mut(cpId, |cp| cp.xy_to_uv_lean(x, y)) {
            Some(Some(found)) => {
                (*u, *v) = found;
                1
            }
            declined => general(cpId, declined.is_some(), x, y, u, v),
        }
    })
}

/// u/v to x/y.
///
/// # Safety
/// `x` and `y` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvaluv2xy(cpId: c_int, u: f64, v: f64, x: *mut f64, y: *mut f64) -> c_int {
    counted!(cpId, {
        // SAFETY: the contract above.
        let (x, y) = unsafe { (out(x), out(y)) };
        eval2(call_name!(), cpId, x, y, |cp| cp.uv_to_xy(u, v))
    })
}

/// u/v to z.
///
/// # Safety
/// `z` is null or points to a double.
#[no_mangle]
pub unsafe extern "C" fn crgEvaluv2z(cpId: c_int, u: f64, v: f64, z: *mut f64) -> c_int {
    /// Every case but the common one (a function of its own, so that the common case needs
    /// no stack frame): first that of a road read in place (the owner's way too: the
    /// core's lean path over the tiles at hand), then the general way.
    #[inline(never)]
    fn general(cpId: c_int, u: f64, v: f64, z: &mut f64) -> c_int {
        if let Some(Some(value)) = registry::with_owned_cp_mut(cpId, |cp| cp.uv_to_z_placed(u, v)) {
            *z = value;
            return 1;
        }
        eval1(call_name!(), cpId, Some(z), |cp| cp.uv_to_z(u, v))
    }
    counted!(cpId, {
        // SAFETY: the contract above.
        let Some(z) = (unsafe { out(z) }) else { return 0 };
        // The common case first: the calling thread owns the contact point and (u, v) is
        // inside the road. Nothing in it can panic, so it needs no guard, and it makes no
        // call, which keeps it short; everything else takes the general way below.
        if let Some(Some(value)) = registry::with_owned_cp_mut(cpId, |cp| cp.uv_to_z_plain(u, v)) {
            *z = value;
            return 1;
        }
        general(cpId, u, v, z)
    })
}

/// x/y to z.
///
/// # Safety
/// `z` is null or points to a double.
#[no_mangle]
pub unsafe extern "C" fn crgEvalxy2z(cpId: c_int, x: f64, y: f64, z: *mut f64) -> c_int {
    /// Every case but the common one (see `crgEvalxy2uv`).
    #[inline(never)]
    fn general(cpId: c_int, declined: bool, x: f64, y: f64, z: &mut f64) -> c_int {
        eval1(call_name!(), cpId, Some(z), |cp| {
            let (u, v) = search_xy(cp, declined, x, y)?;
            cp.z_of_found(u, v)
        })
    }
    /// The elevation at the (u, v) a lean search found where the common case of a grid in
    /// memory does not apply: that of a road read in place the owner's way, else the
    /// general way.
    #[inline(never)]
    fn found(cpId: c_int, u: f64, v: f64, z: &mut f64) -> c_int {
        if let Some(Some(value)) = registry::with_owned_cp_mut(cpId, |cp| cp.uv_to_z_placed(u, v)) {
            *z = value;
            return 1;
        }
        eval1(call_name!(), cpId, Some(z), |cp| cp.z_of_found(u, v))
    }
    counted!(cpId, {
        // SAFETY: the contract above.
        let Some(z) = (unsafe { out(z) }) else { return 0 };
        // The common case first (see `crgEvalxy2uv`); a search done the lean way whose
        // elevation needs the general way continues from the (u, v) it found.
        match registry::with_owned_cp_mut(cpId, |cp| {
            let (u, v) = cp.xy_to_uv_lean(x, y)?;
            Some(cp.uv_to_z_plain(u, v).ok_or((u, v)))
        }) {
            Some(Some(Ok(value))) => {
                *z = value;
                1
            }
            Some(Some(Err((u, v)))) => found(cpId, u, v, z),
            declined => general(cpId, declined.is_some(), x, y, z),
        }
    })
}

/// u/v to heading and curvature.
///
/// # Safety
/// `phi` and `curv` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvaluv2pk(cpId: c_int, u: f64, v: f64, phi: *mut f64, curv: *mut f64) -> c_int {
    counted!(cpId, {
        // SAFETY: the contract above.
        let (phi, curv) = unsafe { (out(phi), out(curv)) };
        eval2(call_name!(), cpId, phi, curv, |cp| cp.uv_to_pk(u, v))
    })
}

/// x/y to heading and curvature.
///
/// # Safety
/// `phi` and `curv` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvalxy2pk(cpId: c_int, x: f64, y: f64, phi: *mut f64, curv: *mut f64) -> c_int {
    counted!(cpId, {
        // SAFETY: the contract above.
        let (Some(phi), Some(curv)) = (unsafe { (out(phi), out(curv)) }) else { return 0 };
        // The search the lean way where it applies (see `crgEvalxy2uv`), then heading and
        // curvature at what it found, inside the guard.
        let found = registry::with_owned_cp_mut(cpId, |cp| cp.xy_to_uv_lean(x, y));
        eval2(call_name!(), cpId, Some(phi), Some(curv), |cp| {
            let (u, v) = match found {
                Some(Some(found)) => found,
                declined => search_xy(cp, declined.is_some(), x, y)?,
            };
            cp.uv_to_pk(u, v)
        })
    })
}
