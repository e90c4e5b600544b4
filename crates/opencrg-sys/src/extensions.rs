//! Extensions of the classic API (all named `crg...`, declared in their own section of
//! `crgBaseLib.h`): batch evaluation, surface normals, raw data access and writing.
//!
//! Pointers come from C: every one is checked for null and turned into a slice of the
//! length the caller gives, through the helpers of `ptr`.
#![allow(non_snake_case)] // the C API's parameter names

use crate::entry::{answer, answer_as, call_name};
use crate::ptr::{in_array as input, in_str, out, out_array as output};
use crate::{c_path, constants};
use opencrg_core::{ContactPoint, DataFormat};
use std::ffi::{c_char, c_int};

/// Runs a batch on a contact point: two inputs, `K` outputs of `n` values each.
fn batch<const K: usize>(
    name: fn() -> &'static str,
    cp_id: c_int,
    n: c_int,
    inputs: [*const f64; 2],
    outputs: [*mut f64; K],
    f: impl FnOnce(&mut ContactPoint, [&[f64]; 2], [&mut [f64]; K]) -> usize + Send,
) -> c_int {
    let Ok(n) = usize::try_from(n) else { return 0 };
    // SAFETY: the C caller gives `n` values behind every pointer (the functions' contract).
    let (Some(a), Some(b)) = (unsafe { input(inputs[0], n) }, unsafe { input(inputs[1], n) }) else { return 0 };
    // SAFETY: as above, for the outputs.
    let outs = outputs.map(|p| unsafe { output(p, n) });
    if outs.iter().any(Option::is_none) {
        return 0;
    }
    let outs = outs.map(Option::unwrap_or_default);
    answer_as(name, 0, |call| {
        call.on_cp(cp_id, |cp| c_int::try_from(f(cp, [a, b], outs)).unwrap_or(c_int::MAX)).unwrap_or(0)
    })
}

/// ======================================================================================
/// EXTENSIONS of this library, not in the reference library's API: batch evaluation
/// (crgEval...N), surface normals (crgEval...zn) and raw data access
/// (crgDataSetGetGrid..., crgDataSetGetRefLine).
/// ======================================================================================
///
/// Elevation of `n` points (`u[i]`, `v[i]`) into `z[i]`: the same answers as `crgEvaluv2z`
/// called on each point in order; NaN where that call fails. Returns how many succeeded.
///
/// # Safety
/// `u`, `v` and `z` point to `n` doubles each.
#[no_mangle]
pub unsafe extern "C" fn crgEvaluv2zN(cpId: c_int, n: c_int, u: *const f64, v: *const f64, z: *mut f64) -> c_int {
    batch(call_name!(), cpId, n, [u, v], [z], |cp, [u, v], [z]| cp.uv_to_z_many(u, v, z))
}

/// Elevation of `n` points (`x[i]`, `y[i]`), as `crgEvalxy2z` on each in order.
///
/// # Safety
/// `x`, `y` and `z` point to `n` doubles each.
#[no_mangle]
pub unsafe extern "C" fn crgEvalxy2zN(cpId: c_int, n: c_int, x: *const f64, y: *const f64, z: *mut f64) -> c_int {
    batch(call_name!(), cpId, n, [x, y], [z], |cp, [x, y], [z]| cp.xy_to_z_many(x, y, z))
}

/// x/y of `n` points (`u[i]`, `v[i]`), as `crgEvaluv2xy` on each in order.
///
/// # Safety
/// `u`, `v`, `x` and `y` point to `n` doubles each.
#[no_mangle]
pub unsafe extern "C" fn crgEvaluv2xyN(
    cpId: c_int,
    n: c_int,
    u: *const f64,
    v: *const f64,
    x: *mut f64,
    y: *mut f64,
) -> c_int {
    batch(call_name!(), cpId, n, [u, v], [x, y], |cp, [u, v], [x, y]| cp.uv_to_xy_many(u, v, x, y))
}

/// u/v of `n` points (`x[i]`, `y[i]`), as `crgEvalxy2uv` on each in order (the search
/// history carries from point to point).
///
/// # Safety
/// `x`, `y`, `u` and `v` point to `n` doubles each.
#[no_mangle]
pub unsafe extern "C" fn crgEvalxy2uvN(
    cpId: c_int,
    n: c_int,
    x: *const f64,
    y: *const f64,
    u: *mut f64,
    v: *mut f64,
) -> c_int {
    batch(call_name!(), cpId, n, [x, y], [u, v], |cp, [x, y], [u, v]| cp.xy_to_uv_many(x, y, u, v))
}

/// Heading and curvature of `n` points (`u[i]`, `v[i]`), as `crgEvaluv2pk` on each in order.
///
/// # Safety
/// `u`, `v`, `phi` and `curv` point to `n` doubles each.
#[no_mangle]
pub unsafe extern "C" fn crgEvaluv2pkN(
    cpId: c_int,
    n: c_int,
    u: *const f64,
    v: *const f64,
    phi: *mut f64,
    curv: *mut f64,
) -> c_int {
    batch(call_name!(), cpId, n, [u, v], [phi, curv], |cp, [u, v], [p, c]| cp.uv_to_pk_many(u, v, p, c))
}

/// Heading and curvature of `n` points (`x[i]`, `y[i]`), as `crgEvalxy2pk` on each in order.
///
/// # Safety
/// `x`, `y`, `phi` and `curv` point to `n` doubles each.
#[no_mangle]
pub unsafe extern "C" fn crgEvalxy2pkN(
    cpId: c_int,
    n: c_int,
    x: *const f64,
    y: *const f64,
    phi: *mut f64,
    curv: *mut f64,
) -> c_int {
    batch(call_name!(), cpId, n, [x, y], [phi, curv], |cp, [x, y], [p, c]| cp.xy_to_pk_many(x, y, p, c))
}

/// Writes an elevation and a normal through the pointers that are not NULL; 1, or 0
/// (and nothing written) when the evaluation failed.
fn put_normal(answer: opencrg_core::Result<(f64, [f64; 3])>, outs: [Option<&mut f64>; 4]) -> c_int {
    let Ok((value, [nx, ny, nz])) = answer else { return 0 };
    for (slot, v) in outs.into_iter().zip([value, nx, ny, nz]) {
        if let Some(slot) = slot {
            *slot = v;
        }
    }
    1
}

/// Elevation and the upward unit normal (nx, ny, nz in x/y/z) of the evaluated surface
/// at (u, v): the analytic gradient of the interpolation (grid, reference line z, slope,
/// banking, border modes, smoothing). On a cell edge, the gradient of the cell the
/// evaluation uses (towards larger u and v). Any pointer may be NULL. Returns 1, or 0
/// where `crgEvaluv2z` would fail.
///
/// # Safety
/// Non-null pointers point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvaluv2zn(
    cpId: c_int,
    u: f64,
    v: f64,
    z: *mut f64,
    nx: *mut f64,
    ny: *mut f64,
    nz: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let outs = unsafe { [out(z), out(nx), out(ny), out(nz)] };
    answer!(0, |call| call.on_cp(cpId, |cp| put_normal(cp.uv_to_normal(u, v), outs)).unwrap_or(0))
}

/// Elevation and normal at the point (x, y): those of `crgEvaluv2zn` at the (u, v) that
/// `crgEvalxy2uv` finds (the search history moves as with `crgEvalxy2uv`).
///
/// # Safety
/// Non-null pointers point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvalxy2zn(
    cpId: c_int,
    x: f64,
    y: f64,
    z: *mut f64,
    nx: *mut f64,
    ny: *mut f64,
    nz: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let outs = unsafe { [out(z), out(nx), out(ny), out(nz)] };
    answer!(0, |call| call.on_cp(cpId, |cp| put_normal(cp.xy_to_normal(x, y), outs)).unwrap_or(0))
}

/// The number of cross sections (u) and long sections (v) of the elevation grid.
/// Either pointer may be NULL. Returns 1, or 0 for an unknown data set.
///
/// # Safety
/// Non-null pointers point to an int each.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetGridSize(dataSetId: c_int, nU: *mut c_int, nV: *mut c_int) -> c_int {
    answer!(0, |call| call.road(dataSetId).map_or(0, |r| {
        let g = r.grid();
        for (p, value) in [(nU, g.nu), (nV, g.nv)] {
            // SAFETY: one int behind a non-null pointer (the contract).
            if let Some([slot]) = unsafe { output(p, 1) } {
                *slot = c_int::try_from(value).unwrap_or(c_int::MAX);
            }
        }
        1
    }))
}

/// The v position of every long section into v[0 .. nV). Returns 1, or 0 when `nV`
/// is not the grid's number of long sections, `v` is NULL or the data set unknown.
///
/// # Safety
/// `v` points to `nV` doubles.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetGridV(dataSetId: c_int, v: *mut f64, nV: c_int) -> c_int {
    answer!(0, |call| call.road(dataSetId).map_or(0, |r| {
        let g = r.grid();
        if usize::try_from(nV).ok() != Some(g.nv) {
            return 0;
        }
        // SAFETY: `nV` doubles behind `v` (the contract).
        let Some(out) = (unsafe { output(v, g.nv) }) else { return 0 };
        out.copy_from_slice(&g.v);
        1
    }))
}

/// The elevation grid into `z[i * nV + j]` (cross section i, long section j), NaN kept,
/// the road's z offset included: the surface evaluation adds the reference line z and
/// the banking to these values. Returns 1, or 0 when `nU` x `nV` is not the grid's size,
/// `z` is NULL or the data set unknown.
///
/// # Safety
/// `z` points to `nU * nV` floats.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetGridZ(dataSetId: c_int, z: *mut f32, nU: c_int, nV: c_int) -> c_int {
    answer!(0, |call| call.road(dataSetId).map_or(0, |r| {
        let g = r.grid();
        if usize::try_from(nU).ok() != Some(g.nu) || usize::try_from(nV).ok() != Some(g.nv) {
            return 0;
        }
        // SAFETY: `nU * nV` floats behind `z` (the contract).
        let Some(out) = (unsafe { output(z, g.nu * g.nv) }) else { return 0 };
        // Cross section by cross section, as the output holds them (a grid read in place
        // streams through from its file).
        let mut cross = out.chunks_exact_mut(g.nv);
        let read = g.rows(0..g.nu, |_, row| {
            if let Some(cross) = cross.next() {
                for (out, &value) in cross.iter_mut().zip(row) {
                    *out = if g.mean == 0.0 { value } else { (f64::from(value) + g.mean) as f32 };
                }
            }
            Ok::<(), opencrg_core::Error>(())
        });
        match read {
            Ok(()) => 1,
            Err(e) => {
                call.warn(&format!("{}: {e}", call.name()));
                0
            }
        }
    }))
}

/// The reference line at every cross section: u, x, y, heading (the heading channel's
/// value, or the start heading without one) and z (the reference line's elevation).
/// Any pointer may be NULL. Returns 1, or 0 when `nU` is not the number of cross
/// sections or the data set is unknown.
///
/// # Safety
/// Non-null pointers point to `nU` doubles each.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetRefLine(
    dataSetId: c_int,
    u: *mut f64,
    x: *mut f64,
    y: *mut f64,
    phi: *mut f64,
    z: *mut f64,
    nU: c_int,
) -> c_int {
    answer!(0, |call| call.road(dataSetId).map_or(0, |r| {
        let l = r.reference_line();
        let n = l.n;
        if usize::try_from(nU).ok() != Some(n) {
            return 0;
        }
        let value = |k: usize, i: usize| match k {
            0 => l.u_at(i),
            1 => l.x[i],
            2 => l.y[i],
            3 => l.heading_at(i),
            _ => l.z_at(i),
        };
        for (k, p) in [u, x, y, phi, z].into_iter().enumerate() {
            // SAFETY: `nU` doubles behind each non-null pointer (the contract).
            if let Some(out) = unsafe { output(p, n) } {
                for (i, o) in out.iter_mut().enumerate() {
                    *o = value(k, i);
                }
            }
        }
        1
    }))
}

/// ======================================================================================
/// WRITING: a data set saved as a CRG file (its data as it is now: modifiers applied
/// since loading are in the data).
/// ======================================================================================
///
/// Writes the data set to `filename` in `format` (`dCrgFormatLRFI`, `dCrgFormatLDFI`,
/// `dCrgFormatKRBI` or `dCrgFormatKDBI`): the header sections (comments, options,
/// modifiers, map data), the reference line and the grid. The file is written under a
/// temporary name and renamed: a failure leaves no partly written file. Returns 1 on
/// success, 0 (with a warning) for an unknown id or format, a null name or a write error.
///
/// # Safety
/// `filename` is null or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetWrite(dataSetId: c_int, filename: *const c_char, format: c_int) -> c_int {
    // SAFETY: the contract above.
    let filename = unsafe { in_str(filename) };
    answer!(0, |call| {
        let format = match format {
            constants::dCrgFormatLRFI => DataFormat::Lrfi,
            constants::dCrgFormatLDFI => DataFormat::Ldfi,
            constants::dCrgFormatKRBI => DataFormat::Krbi,
            constants::dCrgFormatKDBI => DataFormat::Kdbi,
            other => {
                call.warn(&format!("{}: unknown data format {other}", call.name()));
                return 0;
            }
        };
        let Some(filename) = filename else {
            call.warn(&format!("{}: no file name given", call.name()));
            return 0;
        };
        let path = c_path::path_of(filename);
        let Some(road) = call.road(dataSetId) else { return 0 };
        match opencrg_core::write(&road, &path, format) {
            Ok(()) => 1,
            Err(e) => {
                call.warn(&format!("{}: {e}", call.name()));
                0
            }
        }
    })
}
