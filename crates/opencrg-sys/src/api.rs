//! The exported functions of the classic OpenCRG C API.
//!
//! Each function checks its pointers, looks up its id, calls the core crate and
//! turns the `Result` into the classic 1/0 (or id/-1) return; the whole body runs
//! inside [`guard`], so a panic becomes an error return.
#![allow(non_snake_case)] // the C API's parameter names

use crate::alloc;
use crate::c_path;
use crate::msg;
use crate::panic::guard;
use crate::perf_stat::counted;
use crate::profile;
use crate::ptr::{in_str, input, out};
use crate::registry;
use crate::report;
use opencrg_core::settings::{describe, name, Family, Kind, Value};
use opencrg_core::{ContactPoint, Road, Settings};
use std::ffi::{c_char, c_int, c_uint, c_void};
use std::sync::atomic::{AtomicBool, Ordering};

static SUPPRESS_NOT_FOUND: AtomicBool = AtomicBool::new(false);

#[cold]
#[inline(never)]
fn report_unknown(what: &str, func: &str, id: c_int) {
    msg::warn(&format!("{func}: invalid {what} id <{id}>"));
}

/// Runs `f` on a contact point; `None` (after a warning) for an unknown id. The
/// contact point is released before this returns, so the caller may send messages
/// (whose callback may call this library again).
#[inline(always)]
fn on_cp<T>(func: &str, id: c_int, f: impl FnOnce(&mut ContactPoint) -> T) -> Option<T> {
    let r = registry::with_cp(id, f);
    if r.is_none() {
        report_unknown("contact point", func, id);
    }
    r
}

/// Runs `f` on a data set's road, without holding the data set table (the road is
/// shared, not locked); `None` (after a warning) for an unknown id.
fn on_road<T>(func: &str, id: c_int, f: impl FnOnce(&Road) -> T) -> Option<T> {
    let Some(road) = registry::with_dataset(id, |d| d.road.clone()) else {
        report_unknown("data set", func, id);
        return None;
    };
    Some(f(&road))
}

/// Runs `f` on a data set's road to change it; `None` (after a warning) for an unknown id.
fn on_road_mut<T>(func: &str, id: c_int, f: impl FnOnce(&mut Road) -> T) -> Option<T> {
    let r = registry::modify_road(id, f);
    if r.is_none() {
        report_unknown("data set", func, id);
    }
    r
}

/// `on_cp` inside the panic guard, `on_error` for an unknown id. `f` must not send messages.
#[inline(always)]
pub(crate) fn cp_call<R: Copy>(func: &str, id: c_int, on_error: R, f: impl FnOnce(&mut ContactPoint) -> R) -> R {
    guard(func, on_error, || on_cp(func, id, f).unwrap_or(on_error))
}

/// `on_road` inside the panic guard, `on_error` for an unknown id.
pub(crate) fn road_read<R: Copy>(func: &str, id: c_int, on_error: R, f: impl FnOnce(&Road) -> R) -> R {
    guard(func, on_error, || on_road(func, id, f).unwrap_or(on_error))
}

/// `on_road_mut` inside the panic guard, `on_error` for an unknown id. `f` must not send messages.
pub(crate) fn road_write<R: Copy>(func: &str, id: c_int, on_error: R, f: impl FnOnce(&mut Road) -> R) -> R {
    guard(func, on_error, || on_road_mut(func, id, f).unwrap_or(on_error))
}

fn ok(r: opencrg_core::Result<()>, func: &str) -> c_int {
    match r {
        Ok(()) => 1,
        Err(e) => {
            msg::warn(&format!("{func}: {e}"));
            0
        }
    }
}

// ---------------------------------------------------------------- loading

/// Reads a CRG file; returns the data set id (> 0) or 0.
///
/// # Safety
/// `filename` is null or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn crgLoaderReadFile(filename: *const c_char) -> c_int {
    // SAFETY: the contract above.
    let filename = unsafe { in_str(filename) };
    guard("crgLoaderReadFile", 0, || {
        let Some(filename) = filename else {
            msg::fatal("crgLoaderReadFile: no file name given");
            return 0;
        };
        let path = c_path::path_of(filename);
        let compat = match profile::compat() {
            Ok(compat) => compat,
            Err(e) => {
                msg::fatal(&format!("crgLoaderReadFile: {e}; file <{}> not read", path.display()));
                return 0;
            }
        };
        // The statistics block costs a scan of the grid: only when it will be printed.
        let options = opencrg_core::LoadOptions { compat, report_statistics: msg::level() >= msg::NOTICE };
        match Road::load_with(&path, options) {
            Ok(mut road) => {
                // The file's WARN_MSGS counts the messages of its own loading, as the
                // reference applies it while reading the header.
                if let Some(n) = road.header().warn_msgs {
                    msg::set_max_warnings(n);
                }
                for w in road.warnings() {
                    msg::warn(w);
                }
                report::send("crgLoaderReadFile", road.take_events());
                let id = registry::add_dataset(road);
                msg::send(msg::NOTICE, &format!("crgLoaderReadFile: finished reading file <{}>", path.display()));
                id
            }
            Err(e) => {
                let not_found = matches!(&e, opencrg_core::Error::Io { source, .. } if source.kind() == std::io::ErrorKind::NotFound);
                if !(not_found && SUPPRESS_NOT_FOUND.load(Ordering::Relaxed)) {
                    msg::fatal(&format!("crgLoaderReadFile: {e}"));
                }
                0
            }
        }
    })
}

/// Suppresses the fatal message for files that do not exist.
#[no_mangle]
pub extern "C" fn crgLoaderSuppressFileNotFoundFatalMsg(suppress: bool) {
    SUPPRESS_NOT_FOUND.store(suppress, Ordering::Relaxed);
}

/// Checks a data set's options, modifiers and (when asked) curvature.
#[no_mangle]
pub extern "C" fn crgCheck(dataSetId: c_int) -> c_int {
    guard("crgCheck", 0, || {
        let Some((checked, events)) = on_road_mut("crgCheck", dataSetId, |r| (r.check(), r.take_events())) else {
            return 0;
        };
        report::send("crgCheck", events);
        if let Some(found) = on_road("crgCheck", dataSetId, opencrg_core::map_disagreements) {
            for sentence in found {
                msg::warn(&format!("crgCheck: {sentence}"));
            }
        }
        match checked {
            Ok(()) => 1,
            Err(e) => {
                msg::fatal(&format!("crgCheck: {e}"));
                0
            }
        }
    })
}

/// Releases a data set and its contact points.
#[no_mangle]
pub extern "C" fn crgDataSetRelease(dataSetId: c_int) -> c_int {
    guard("crgDataSetRelease", 0, || {
        let released = registry::release_dataset(dataSetId);
        if released {
            msg::send(msg::NOTICE, &format!("crgDataSetRelease: data set {dataSetId} released"));
        }
        c_int::from(released)
    })
}

/// Releases every data set.
#[no_mangle]
pub extern "C" fn crgMemRelease() {
    guard("crgMemRelease", (), || {
        for id in registry::dataset_ids() {
            registry::release_dataset(id);
        }
    })
}

/// The library's release text.
#[no_mangle]
pub extern "C" fn crgGetReleaseInfo() -> *const c_char {
    const INFO: &str = concat!("OpenCRG Rust library ", env!("CARGO_PKG_VERSION"), " (classic C API)\0");
    INFO.as_ptr().cast()
}

// ---------------------------------------------------------------- data set queries

/// Writes the pair `f` gives: 1, or 0 when an output is missing or `f` gives nothing.
fn two_out(a: Option<&mut f64>, b: Option<&mut f64>, f: impl FnOnce() -> Option<(f64, f64)>) -> c_int {
    let (Some(a), Some(b)) = (a, b) else { return 0 };
    match f() {
        Some((x, y)) => {
            (*a, *b) = (x, y);
            1
        }
        None => 0,
    }
}

/// u range of a data set.
///
/// # Safety
/// `uMin` and `uMax` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetURange(dataSetId: c_int, uMin: *mut f64, uMax: *mut f64) -> c_int {
    // SAFETY: the contract above.
    let (uMin, uMax) = unsafe { (out(uMin), out(uMax)) };
    guard("crgDataSetGetURange", 0, || two_out(uMin, uMax, || registry::with_dataset(dataSetId, |d| d.road.u_range())))
}

/// v range of a data set.
///
/// # Safety
/// `vMin` and `vMax` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetVRange(dataSetId: c_int, vMin: *mut f64, vMax: *mut f64) -> c_int {
    // SAFETY: the contract above.
    let (vMin, vMax) = unsafe { (out(vMin), out(vMax)) };
    guard("crgDataSetGetVRange", 0, || two_out(vMin, vMax, || registry::with_dataset(dataSetId, |d| d.road.v_range())))
}

/// u and v increments of a data set.
///
/// # Safety
/// `uInc` and `vInc` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetIncrements(dataSetId: c_int, uInc: *mut f64, vInc: *mut f64) -> c_int {
    // SAFETY: the contract above.
    let (uInc, vInc) = unsafe { (out(uInc), out(vInc)) };
    guard("crgDataSetGetIncrements", 0, || {
        two_out(uInc, vInc, || registry::with_dataset(dataSetId, |d| d.road.increments()))
    })
}

/// Whether the reference line can be closed, and over which u range.
///
/// # Safety
/// `uIsClosed` is null or points to an int; `uCloseMin` and `uCloseMax` are null or
/// point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetUtilityDataClosedTrack(
    dataSetId: c_int,
    uIsClosed: *mut c_int,
    uCloseMin: *mut f64,
    uCloseMax: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let outs = unsafe { (out(uIsClosed), out(uCloseMin), out(uCloseMax)) };
    guard("crgDataSetGetUtilityDataClosedTrack", 0, || {
        let (Some(is_closed), Some(close_min), Some(close_max)) = outs else { return 0 };
        match registry::with_dataset(dataSetId, |d| d.road.closed_track_report()) {
            Some((closed, a, b)) => {
                (*is_closed, *close_min, *close_max) = (c_int::from(closed), a, b);
                1
            }
            None => 0,
        }
    })
}

// ---------------------------------------------------------------- settings

/// Sets a modifier of a data set; 1, or 0 after a warning.
fn set_modifier(func: &str, id: c_int, option: c_uint, value: Value) -> c_int {
    guard(func, 0, || match on_road_mut(func, id, |r| r.modifiers_mut().set_value(option, value)) {
        Some(r) => ok(r, func),
        None => 0,
    })
}

/// Reads a setting as an integer: 1 when it is set, whatever its type (a double setting
/// reads as 0, as the reference's separate integer field does).
fn get_int(table: &Settings, id: c_uint, out: Option<&mut c_int>) -> c_int {
    match (table.get_int(id), out) {
        (Some(v), Some(out)) => {
            *out = v;
            1
        }
        _ => 0,
    }
}

/// Reads a setting as a double: 1 when it is set, whatever its type (an integer setting
/// reads as 0.0, as the reference's separate double field does).
fn get_double(table: &Settings, id: c_uint, out: Option<&mut f64>) -> c_int {
    match (table.get_double(id), out) {
        (Some(v), Some(out)) => {
            *out = v;
            1
        }
        _ => 0,
    }
}

/// Sets an integer modifier of a data set.
#[no_mangle]
pub extern "C" fn crgDataSetModifierSetInt(dataSetId: c_int, optionId: c_uint, optionValue: c_int) -> c_int {
    set_modifier("crgDataSetModifierSetInt", dataSetId, optionId, Value::Int(optionValue))
}

/// Sets a double modifier of a data set.
#[no_mangle]
pub extern "C" fn crgDataSetModifierSetDouble(dataSetId: c_int, optionId: c_uint, optionValue: f64) -> c_int {
    set_modifier("crgDataSetModifierSetDouble", dataSetId, optionId, Value::Double(optionValue))
}

/// Reads an integer modifier of a data set.
///
/// # Safety
/// `optionValue` is null or points to an int.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetModifierGetInt(
    dataSetId: c_int,
    optionId: c_uint,
    optionValue: *mut c_int,
) -> c_int {
    // SAFETY: the contract above.
    let optionValue = unsafe { out(optionValue) };
    road_read("crgDataSetModifierGetInt", dataSetId, 0, |r| get_int(r.modifiers(), optionId, optionValue))
}

/// Reads a double modifier of a data set.
///
/// # Safety
/// `optionValue` is null or points to a double.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetModifierGetDouble(
    dataSetId: c_int,
    optionId: c_uint,
    optionValue: *mut f64,
) -> c_int {
    // SAFETY: the contract above.
    let optionValue = unsafe { out(optionValue) };
    road_read("crgDataSetModifierGetDouble", dataSetId, 0, |r| get_double(r.modifiers(), optionId, optionValue))
}

/// Removes one modifier of a data set.
#[no_mangle]
pub extern "C" fn crgDataSetModifierRemove(dataSetId: c_int, modId: c_uint) -> c_int {
    road_write("crgDataSetModifierRemove", dataSetId, 0, |r| c_int::from(r.modifiers_mut().remove(modId)))
}

/// Removes every modifier of a data set.
#[no_mangle]
pub extern "C" fn crgDataSetModifierRemoveAll(dataSetId: c_int) -> c_int {
    road_write("crgDataSetModifierRemoveAll", dataSetId, 0, |r| {
        r.modifiers_mut().clear();
        1
    })
}

/// Restores the default modifiers of a data set.
#[no_mangle]
pub extern "C" fn crgDataSetModifierSetDefault(dataSetId: c_int) {
    road_write("crgDataSetModifierSetDefault", dataSetId, (), |r| r.modifiers_mut().reset_modifiers())
}

/// Restores the default options a data set gives its new contact points.
#[no_mangle]
pub extern "C" fn crgDataSetOptionSetDefault(dataSetId: c_int) {
    road_write("crgDataSetOptionSetDefault", dataSetId, (), |r| r.options_mut().reset_options())
}

/// Applies a data set's modifiers to its data.
#[no_mangle]
pub extern "C" fn crgDataSetModifiersApply(dataSetId: c_int) {
    guard("crgDataSetModifiersApply", (), || {
        let events = on_road_mut("crgDataSetModifiersApply", dataSetId, |r| {
            r.set_report_statistics(msg::level() >= msg::NOTICE);
            r.apply_modifiers();
            r.take_events()
        });
        report::send("crgDataSetModifiersApply", events.unwrap_or_default());
    })
}

fn print_settings(table: &Settings, label: &str) {
    msg::send(msg::NOTICE, &format!("crgOptionsPrint: {label}s set:"));
    let mut any = false;
    for (id, v) in table.iter() {
        any = true;
        let value = match v {
            Value::Int(i) => i.to_string(),
            Value::Double(d) => format!("{d:.4}"),
        };
        msg::send(msg::NOTICE, &format!("    {label:>8} = \"{}\"", name(id)));
        msg::send(msg::NOTICE, &format!("       value = {value}"));
    }
    if !any {
        msg::send(msg::NOTICE, &format!("    no {label}s set"));
    }
    msg::send(msg::NOTICE, "");
}

/// Prints a data set's modifiers.
#[no_mangle]
pub extern "C" fn crgDataSetModifiersPrint(dataSetId: c_int) {
    road_read("crgDataSetModifiersPrint", dataSetId, (), |r| print_settings(r.modifiers(), "modifier"))
}

// ---------------------------------------------------------------- printing

/// Prints the header values of a data set, one message a value (the reference's
/// figures in its order).
#[no_mangle]
pub extern "C" fn crgDataPrintHeader(dataSetId: c_int) {
    road_read("crgDataPrintHeader", dataSetId, (), |r| {
        let l = r.reference_line();
        let g = r.grid();
        for (k, v) in [
            ("first u", l.u_first),
            ("start x", l.x_first),
            ("start y", l.y_first),
            ("start heading", l.phi_first),
            ("last u", l.u_last),
            ("end x", l.x_last),
            ("end y", l.y_last),
            ("end heading", l.phi_last),
            ("u increment", l.u_inc),
            ("right v", g.v_first),
            ("left v", g.v_last),
            ("v increment", g.v_inc),
        ] {
            msg::send(msg::NOTICE, &format!("crgDataPrintHeader: {k:<13} = {v:10.4}"));
        }
    })
}

/// Prints the channels of a data set: the long sections' positions and columns, then
/// the reference line channels' columns (sizes at the DEBUG level).
#[no_mangle]
pub extern "C" fn crgDataPrintChannelInfo(dataSetId: c_int) {
    road_read("crgDataPrintChannelInfo", dataSetId, (), |r| {
        use opencrg_core::header::Channel;
        let h = r.header();
        let g = r.grid();
        let send = |level, text: String| msg::send(level, &text);
        send(msg::NOTICE, "crgDataPrintChannelInfo: the channels of the data set".into());
        send(msg::NOTICE, format!("    channels in a record     = {:4}", h.channels.len()));
        send(msg::NOTICE, format!("    long sections            = {:4}", g.nv));
        for (i, v) in g.v.iter().enumerate() {
            send(msg::NOTICE, format!("    long section {i:4} at v    = {v:.4}"));
        }
        // Columns of the long sections, in the road's (sorted) order.
        let mut columns: Vec<(f64, usize)> = h
            .channels
            .iter()
            .enumerate()
            .filter_map(|(col, c)| match *c {
                Channel::SectionAt(v) | Channel::SectionIndex(v) => Some((v, col)),
                _ => None,
            })
            .collect();
        columns.sort_by(|a, b| a.0.total_cmp(&b.0));
        send(msg::NOTICE, format!("    elevation channels       = {:4}", g.nv));
        for (i, (_, col)) in columns.iter().enumerate() {
            send(msg::NOTICE, format!("    elevation {i:4} in column = {col:4}"));
            send(msg::DEBUG, format!("    elevation {i:4} values    = {:4}", g.nu));
        }
        send(msg::NOTICE, "reference line channels:".into());
        let column = |wanted: Channel| h.channels.iter().position(|c| *c == wanted);
        for (label, channel, computed) in [
            ("x", Channel::RefX, true),
            ("y", Channel::RefY, true),
            ("u", Channel::RefU, false),
            ("heading", Channel::RefPhi, false),
            ("slope", Channel::RefSlope, false),
            ("banking", Channel::RefBank, false),
        ] {
            let col = column(channel);
            if let Some(col) = col {
                send(msg::NOTICE, format!("    {label:<8} in column      = {col}"));
            }
            if computed || col.is_some() {
                send(msg::DEBUG, format!("    {label:<8} values         = {}", g.nu));
            }
        }
        send(msg::NOTICE, "crgDataPrintChannelInfo: end of the channels".into());
    })
}

/// Prints a summary of the road: length, increment, cross sections, width and its
/// parts, every long section's position, their number.
#[no_mangle]
pub extern "C" fn crgDataPrintRoadInfo(dataSetId: c_int) {
    road_read("crgDataPrintRoadInfo", dataSetId, (), |r| {
        let (u0, u1) = r.u_range();
        let g = r.grid();
        let line = |text: String| msg::send(msg::NOTICE, &text);
        line("crgDataPrintRoadInfo: the road in figures".into());
        line(format!("        length [m]:                       {:10.4}", u1 - u0));
        line(format!("        distance of cross sections [m]:   {:10.4}", r.increments().0));
        line(format!("        cross sections:                   {:7}", g.nu));
        line(format!("        width [m]:                        {:10.4}", g.v_last - g.v_first));
        line(format!("        right of the reference line [m]:  {:10.4}", g.v_first.min(0.0)));
        line(format!("        left of the reference line [m]:   {:10.4}", g.v_last.max(0.0)));
        for v in &g.v {
            line(format!("        long section at v [m]:            {v:10.4}"));
        }
        line(format!("        long sections:                    {:7}", g.nv));
    })
}

// ---------------------------------------------------------------- messages and memory

/// Sets the message level.
#[no_mangle]
pub extern "C" fn crgMsgSetLevel(level: c_int) {
    msg::set_level(level);
}

/// Limits the number of messages printed (-1: no limit).
#[no_mangle]
pub extern "C" fn crgMsgSetMaxWarnMsgs(maxNo: c_int) {
    msg::set_max_warnings(maxNo);
}

/// Kept for compatibility; log messages are not limited separately.
#[no_mangle]
pub extern "C" fn crgMsgSetMaxLogMsgs(_maxNo: c_int) {}

/// Whether a message of this level would be printed.
#[no_mangle]
pub extern "C" fn crgMsgIsPrintable(level: c_int) -> c_int {
    c_int::from(msg::is_printable(level))
}

/// Sends messages to a callback instead of standard output (null restores printing).
#[no_mangle]
pub extern "C" fn crgMsgSetCallback(func: Option<unsafe extern "C" fn(level: c_int, message: *mut c_char) -> c_int>) {
    msg::set_callback(func);
}

/// Allocates zeroed memory through the library's allocator hook.
#[no_mangle]
pub extern "C" fn crgCalloc(nmemb: usize, size: usize) -> *mut c_void {
    alloc::calloc(nmemb, size)
}

/// Reallocates memory through the library's allocator hook.
///
/// # Safety
/// `ptr` is null or came from `crgCalloc` or `crgRealloc` and was not freed since.
#[no_mangle]
pub unsafe extern "C" fn crgRealloc(ptr: *mut c_void, size: usize) -> *mut c_void {
    // SAFETY: the contract above.
    unsafe { alloc::realloc(ptr, size) }
}

/// Frees memory through the library's allocator hook.
///
/// # Safety
/// `ptr` is null or came from `crgCalloc` or `crgRealloc` and was not freed since.
#[no_mangle]
pub unsafe extern "C" fn crgFree(ptr: *mut c_void) {
    // SAFETY: the contract above.
    unsafe { alloc::free(ptr) }
}

/// Installs the application's calloc (null restores the C library's).
#[no_mangle]
pub extern "C" fn crgCallocSetCallback(func: Option<unsafe extern "C" fn(nmemb: usize, size: usize) -> *mut c_void>) {
    alloc::set_calloc(func);
}

/// Installs the application's realloc (null restores the C library's).
#[no_mangle]
pub extern "C" fn crgReallocSetCallback(
    func: Option<unsafe extern "C" fn(ptr: *mut c_void, size: usize) -> *mut c_void>,
) {
    alloc::set_realloc(func);
}

/// Installs the application's free (null restores the C library's).
#[no_mangle]
pub extern "C" fn crgFreeSetCallback(func: Option<unsafe extern "C" fn(ptr: *mut c_void)>) {
    alloc::set_free(func);
}

/// 1 if the double is NaN (OpenCRG 1.2.0 API).
///
/// # Safety
/// `dValue` is null or points to a double.
#[no_mangle]
pub unsafe extern "C" fn crgIsNan(dValue: *mut f64) -> c_int {
    // SAFETY: the contract above.
    c_int::from(unsafe { input(dValue) }.is_some_and(|v| v.is_nan()))
}

/// 1 if the float is NaN (OpenCRG 1.2.0 API).
///
/// # Safety
/// `fValue` is null or points to a float.
#[no_mangle]
pub unsafe extern "C" fn crgIsNanf(fValue: *mut f32) -> c_int {
    // SAFETY: the contract above.
    c_int::from(unsafe { input(fValue) }.is_some_and(|v| v.is_nan()))
}

// ---------------------------------------------------------------- contact points

/// Creates a contact point on a data set; its id (>= 0) or -1.
#[no_mangle]
pub extern "C" fn crgContactPointCreate(dataSetId: c_int) -> c_int {
    guard("crgContactPointCreate", -1, || {
        let id = registry::create_cp(dataSetId);
        if id < 0 {
            msg::fatal(&format!("crgContactPointCreate: invalid data set id <{dataSetId}>"));
        }
        id
    })
}

/// Deletes a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointDelete(cpId: c_int) -> c_int {
    guard("crgContactPointDelete", 0, || c_int::from(registry::delete_cp(cpId)))
}

/// Deletes every contact point of a data set (-1: of every data set).
#[no_mangle]
pub extern "C" fn crgContactPointDeleteAll(dataSetId: c_int) {
    guard("crgContactPointDeleteAll", (), || registry::delete_cps_of((dataSetId != -1).then_some(dataSetId)))
}

fn option_kind_ok(id: c_uint, kind: Kind) -> bool {
    describe(id) == Some((Family::Option, kind))
}

/// Sets an integer option of a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointOptionSetInt(cpId: c_int, optionId: c_uint, optionValue: c_int) -> c_int {
    let func = "crgContactPointOptionSetInt";
    guard(func, 0, || match on_cp(func, cpId, |cp| cp.set_option_int(optionId, optionValue)) {
        Some(r) => ok(r, func),
        None => 0,
    })
}

/// Sets a double option of a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointOptionSetDouble(cpId: c_int, optionId: c_uint, optionValue: f64) -> c_int {
    let func = "crgContactPointOptionSetDouble";
    guard(func, 0, || {
        let kind_ok = option_kind_ok(optionId, Kind::Double);
        match on_cp(func, cpId, |cp| kind_ok.then(|| cp.set_option_double(optionId, optionValue))) {
            Some(Some(r)) => ok(r, func),
            Some(None) => {
                msg::warn(&format!("{func}: <{}> is not a double option", name(optionId)));
                0
            }
            None => 0,
        }
    })
}

/// Reads an integer option of a contact point.
///
/// # Safety
/// `optionValue` is null or points to an int.
#[no_mangle]
pub unsafe extern "C" fn crgContactPointOptionGetInt(cpId: c_int, optionId: c_uint, optionValue: *mut c_int) -> c_int {
    // SAFETY: the contract above.
    let optionValue = unsafe { out(optionValue) };
    cp_call("crgContactPointOptionGetInt", cpId, 0, |cp| get_int(cp.options(), optionId, optionValue))
}

/// Reads a double option of a contact point.
///
/// # Safety
/// `optionValue` is null or points to a double.
#[no_mangle]
pub unsafe extern "C" fn crgContactPointOptionGetDouble(cpId: c_int, optionId: c_uint, optionValue: *mut f64) -> c_int {
    // SAFETY: the contract above.
    let optionValue = unsafe { out(optionValue) };
    cp_call("crgContactPointOptionGetDouble", cpId, 0, |cp| get_double(cp.options(), optionId, optionValue))
}

/// Removes one option of a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointOptionRemove(cpId: c_int, optionId: c_uint) -> c_int {
    cp_call("crgContactPointOptionRemove", cpId, 0, |cp| c_int::from(cp.remove_option(optionId)))
}

/// Removes every option of a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointOptionRemoveAll(cpId: c_int) -> c_int {
    cp_call("crgContactPointOptionRemoveAll", cpId, 0, |cp| {
        cp.clear_options();
        1
    })
}

/// Prints the options of a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointOptionsPrint(cpId: c_int) {
    let func = "crgContactPointOptionsPrint";
    guard(func, (), || {
        if let Some(options) = on_cp(func, cpId, |cp| cp.options().clone()) {
            print_settings(&options, "option");
        }
    })
}

/// Restores the default options of a contact point.
#[no_mangle]
pub extern "C" fn crgContactPointSetDefaultOptions(cpId: c_int) {
    cp_call("crgContactPointSetDefaultOptions", cpId, (), |cp| cp.reset_options())
}

/// Sets the size of a contact point's search history.
#[no_mangle]
pub extern "C" fn crgContactPointSetHistory(cpId: c_int, histSize: c_int) -> c_int {
    cp_call("crgContactPointSetHistory", cpId, 0, |cp| match usize::try_from(histSize) {
        Ok(n) => match cp.set_history(n) {
            Ok(()) => 1,
            Err(e) => {
                msg::warn(&format!("crgContactPointSetHistory: {e}"));
                0
            }
        },
        Err(_) => 0,
    })
}

/// Sets the size of every contact point's search history.
#[no_mangle]
pub extern "C" fn crgContactPointSetHistoryForAllPoints(histSize: c_int) {
    guard("crgContactPointSetHistoryForAllPoints", (), || {
        if let Ok(n) = usize::try_from(histSize) {
            registry::update_all_cps(|cp| {
                if let Err(e) = cp.set_history(n) {
                    msg::warn(&format!("crgContactPointSetHistoryForAllPoints: {e}"));
                }
            });
        }
    })
}

// ---------------------------------------------------------------- evaluation

/// An evaluation giving two values: 1, or 0 (outputs untouched) when an output is
/// missing, the id unknown or the evaluation refused.
fn eval2(
    func: &str,
    cp_id: c_int,
    a: Option<&mut f64>,
    b: Option<&mut f64>,
    f: impl FnOnce(&mut ContactPoint) -> opencrg_core::Result<(f64, f64)>,
) -> c_int {
    two_out(a, b, || cp_call(func, cp_id, None, |cp| f(cp).ok()))
}

/// An evaluation giving one value: 1, or 0 when the output is missing or the id unknown,
/// or 0 with the output set to 0 when the evaluation is refused.
fn eval1(
    func: &str,
    cp_id: c_int,
    out: Option<&mut f64>,
    f: impl FnOnce(&mut ContactPoint) -> opencrg_core::Result<f64>,
) -> c_int {
    let Some(out) = out else { return 0 };
    cp_call(func, cp_id, 0, |cp| match f(cp) {
        Ok(z) => {
            *out = z;
            1
        }
        Err(_) => {
            *out = 0.0;
            0
        }
    })
}

/// x/y to u/v.
///
/// # Safety
/// `u` and `v` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvalxy2uv(cpId: c_int, x: f64, y: f64, u: *mut f64, v: *mut f64) -> c_int {
    counted!(cpId, {
        // SAFETY: the contract above.
        let (Some(u), Some(v)) = (unsafe { (out(u), out(v)) }) else { return 0 };
        // The common case first, as in `crgEvaluv2z`: the owner's way, the lean search.
        match registry::with_owned_cp_mut(cpId, |cp| cp.xy_to_uv_lean(x, y)) {
            Some(Some(found)) => {
                (*u, *v) = found;
                1
            }
            declined => xy2uv_general(cpId, declined.is_some(), x, y, u, v),
        }
    })
}

/// `crgEvalxy2uv` for every case but the common one; `declined`: the lean search was
/// tried and declined.
#[inline(never)]
fn xy2uv_general(cpId: c_int, declined: bool, x: f64, y: f64, u: &mut f64, v: &mut f64) -> c_int {
    eval2("crgEvalxy2uv", cpId, Some(u), Some(v), |cp| search_xy(cp, declined, x, y))
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

/// u/v to x/y.
///
/// # Safety
/// `x` and `y` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgEvaluv2xy(cpId: c_int, u: f64, v: f64, x: *mut f64, y: *mut f64) -> c_int {
    counted!(cpId, {
        // SAFETY: the contract above.
        let (x, y) = unsafe { (out(x), out(y)) };
        eval2("crgEvaluv2xy", cpId, x, y, |cp| cp.uv_to_xy(u, v))
    })
}

/// u/v to z.
///
/// # Safety
/// `z` is null or points to a double.
#[no_mangle]
pub unsafe extern "C" fn crgEvaluv2z(cpId: c_int, u: f64, v: f64, z: *mut f64) -> c_int {
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
        uv2z_general(cpId, u, v, z)
    })
}

/// `crgEvaluv2z` for every case but the common one (its own function, so that the
/// common case needs no stack frame).
#[inline(never)]
fn uv2z_general(cpId: c_int, u: f64, v: f64, z: &mut f64) -> c_int {
    eval1("crgEvaluv2z", cpId, Some(z), |cp| cp.uv_to_z(u, v))
}

/// x/y to z.
///
/// # Safety
/// `z` is null or points to a double.
#[no_mangle]
pub unsafe extern "C" fn crgEvalxy2z(cpId: c_int, x: f64, y: f64, z: *mut f64) -> c_int {
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
            Some(Some(Err((u, v)))) => eval1("crgEvalxy2z", cpId, Some(z), |cp| cp.z_of_found(u, v)),
            declined => xy2z_general(cpId, declined.is_some(), x, y, z),
        }
    })
}

/// `crgEvalxy2z` for every case but the common one (see `xy2uv_general`).
#[inline(never)]
fn xy2z_general(cpId: c_int, declined: bool, x: f64, y: f64, z: &mut f64) -> c_int {
    eval1("crgEvalxy2z", cpId, Some(z), |cp| {
        let (u, v) = search_xy(cp, declined, x, y)?;
        cp.z_of_found(u, v)
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
        eval2("crgEvaluv2pk", cpId, phi, curv, |cp| cp.uv_to_pk(u, v))
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
        eval2("crgEvalxy2pk", cpId, Some(phi), Some(curv), |cp| {
            let (u, v) = match found {
                Some(Some(found)) => found,
                declined => search_xy(cp, declined.is_some(), x, y)?,
            };
            cp.uv_to_pk(u, v)
        })
    })
}
