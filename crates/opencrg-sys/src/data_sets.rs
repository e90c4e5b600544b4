//! What a data set holds (its ranges and increments, the closed-track data), its
//! modifiers, and the printouts of its header, channels and figures.
#![allow(non_snake_case)] // the C API's parameter names

use crate::entry::{answer, Call};
use crate::ptr::{out, put_pair};
use crate::{msg, registry, report};
use opencrg_core::settings::{name, Settings, Value};
use std::ffi::{c_int, c_uint};

/// u range of a data set.
///
/// # Safety
/// `uMin` and `uMax` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetURange(dataSetId: c_int, uMin: *mut f64, uMax: *mut f64) -> c_int {
    // SAFETY: the contract above.
    let (uMin, uMax) = unsafe { (out(uMin), out(uMax)) };
    answer!(0, |_| put_pair(uMin, uMax, || registry::with_dataset(dataSetId, |d| d.road.u_range())))
}

/// v range of a data set.
///
/// # Safety
/// `vMin` and `vMax` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetVRange(dataSetId: c_int, vMin: *mut f64, vMax: *mut f64) -> c_int {
    // SAFETY: the contract above.
    let (vMin, vMax) = unsafe { (out(vMin), out(vMax)) };
    answer!(0, |_| put_pair(vMin, vMax, || registry::with_dataset(dataSetId, |d| d.road.v_range())))
}

/// u and v increments of a data set.
///
/// # Safety
/// `uInc` and `vInc` are null or point to a double each.
#[no_mangle]
pub unsafe extern "C" fn crgDataSetGetIncrements(dataSetId: c_int, uInc: *mut f64, vInc: *mut f64) -> c_int {
    // SAFETY: the contract above.
    let (uInc, vInc) = unsafe { (out(uInc), out(vInc)) };
    answer!(0, |_| put_pair(uInc, vInc, || registry::with_dataset(dataSetId, |d| d.road.increments())))
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
    answer!(0, |_| {
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

// ---------------------------------------------------------------- modifiers

/// Sets a modifier of a data set; 1, or 0 after a warning.
fn set_modifier(call: &Call, id: c_int, option: c_uint, value: Value) -> c_int {
    match call.change_road(id, |r| r.modifiers_mut().set_value(option, value)) {
        Some(r) => call.done(r),
        None => 0,
    }
}

/// Reads a setting as an integer: 1 when it is set, whatever its type (a double setting
/// reads as 0, as the reference's separate integer field does).
pub(crate) fn get_int(table: &Settings, id: c_uint, out: Option<&mut c_int>) -> c_int {
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
pub(crate) fn get_double(table: &Settings, id: c_uint, out: Option<&mut f64>) -> c_int {
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
    answer!(0, |call| set_modifier(call, dataSetId, optionId, Value::Int(optionValue)))
}

/// Sets a double modifier of a data set.
#[no_mangle]
pub extern "C" fn crgDataSetModifierSetDouble(dataSetId: c_int, optionId: c_uint, optionValue: f64) -> c_int {
    answer!(0, |call| set_modifier(call, dataSetId, optionId, Value::Double(optionValue)))
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
    answer!(0, |call| call.road(dataSetId).map_or(0, |r| get_int(r.modifiers(), optionId, optionValue)))
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
    answer!(0, |call| call.road(dataSetId).map_or(0, |r| get_double(r.modifiers(), optionId, optionValue)))
}

/// Removes one modifier of a data set.
#[no_mangle]
pub extern "C" fn crgDataSetModifierRemove(dataSetId: c_int, modId: c_uint) -> c_int {
    answer!(0, |call| call.change_road(dataSetId, |r| c_int::from(r.modifiers_mut().remove(modId))).unwrap_or(0))
}

/// Removes every modifier of a data set.
#[no_mangle]
pub extern "C" fn crgDataSetModifierRemoveAll(dataSetId: c_int) -> c_int {
    answer!(0, |call| call.change_road(dataSetId, |r| r.modifiers_mut().clear()).map_or(0, |()| 1))
}

/// Restores the default modifiers of a data set.
#[no_mangle]
pub extern "C" fn crgDataSetModifierSetDefault(dataSetId: c_int) {
    answer!((), |call| {
        call.change_road(dataSetId, |r| r.modifiers_mut().reset_modifiers());
    })
}

/// Restores the default options a data set gives its new contact points.
#[no_mangle]
pub extern "C" fn crgDataSetOptionSetDefault(dataSetId: c_int) {
    answer!((), |call| {
        call.change_road(dataSetId, |r| r.options_mut().reset_options());
    })
}

/// Applies a data set's modifiers to its data.
#[no_mangle]
pub extern "C" fn crgDataSetModifiersApply(dataSetId: c_int) {
    answer!((), |call| {
        let statistics = msg::level() >= msg::NOTICE;
        let events = call.change_road(dataSetId, |r| {
            r.set_report_statistics(statistics);
            r.apply_modifiers();
            r.take_events()
        });
        report::send(call, events.unwrap_or_default());
    })
}

/// Prints a table of settings: each one's name and value (the options of a contact point,
/// the modifiers of a data set), headed as the printing call's.
pub(crate) fn print_settings(call: &Call, table: &Settings, label: &str) {
    call.notice(&format!("crgOptionsPrint: {label}s set:"));
    let mut any = false;
    for (id, v) in table.iter() {
        any = true;
        let value = match v {
            Value::Int(i) => i.to_string(),
            Value::Double(d) => format!("{d:.4}"),
        };
        call.notice(&format!("    {label:>8} = \"{}\"", name(id)));
        call.notice(&format!("       value = {value}"));
    }
    if !any {
        call.notice(&format!("    no {label}s set"));
    }
    call.notice("");
}

/// Prints a data set's modifiers.
#[no_mangle]
pub extern "C" fn crgDataSetModifiersPrint(dataSetId: c_int) {
    answer!((), |call| {
        if let Some(r) = call.road(dataSetId) {
            print_settings(call, r.modifiers(), "modifier");
        }
    })
}

// ---------------------------------------------------------------- printing

/// Prints the header values of a data set, one message a value (the reference's
/// figures in its order).
#[no_mangle]
pub extern "C" fn crgDataPrintHeader(dataSetId: c_int) {
    answer!((), |call| {
        let Some(r) = call.road(dataSetId) else { return };
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
            call.notice(&format!("{}: {k:<13} = {v:10.4}", call.name()));
        }
    })
}

/// Prints the channels of a data set: the long sections' positions and columns, then
/// the reference line channels' columns (sizes at the DEBUG level).
#[no_mangle]
pub extern "C" fn crgDataPrintChannelInfo(dataSetId: c_int) {
    answer!((), |call| {
        use opencrg_core::header::Channel;
        let Some(r) = call.road(dataSetId) else { return };
        let h = r.header();
        let g = r.grid();
        let send = |level, text: String| call.send(level, &text);
        send(msg::NOTICE, format!("{}: the channels of the data set", call.name()));
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
        send(msg::NOTICE, format!("{}: end of the channels", call.name()));
    })
}

/// Prints a summary of the road: length, increment, cross sections, width and its
/// parts, every long section's position, their number.
#[no_mangle]
pub extern "C" fn crgDataPrintRoadInfo(dataSetId: c_int) {
    answer!((), |call| {
        let Some(r) = call.road(dataSetId) else { return };
        let (u0, u1) = r.u_range();
        let g = r.grid();
        let line = |text: String| call.notice(&text);
        line(format!("{}: the road in figures", call.name()));
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
