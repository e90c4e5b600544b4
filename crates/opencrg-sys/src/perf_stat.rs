//! Performance statistics of contact points, declared in `crgBaseLibPrivate.h` as the
//! reference library's private header does: while active, every evaluation call of the
//! classic API (`crgEval...`) on a contact point is counted with the time it took;
//! printed through the message channel at NOTICE level.
//!
//! The evaluation calls pay one test for it ([`counted!`]): while no contact point's
//! statistics are active, they run as they would without; otherwise they take a cold
//! way of their own that times the call and adds it to the contact point's count.
#![allow(non_snake_case)] // the C API's parameter names

use crate::entry::{answer, Call};
use crate::{msg, registry};
use std::ffi::c_int;

/// Runs the body of an evaluation call on contact point `$cp`, counted by the
/// performance statistics when they are active. The body is written out twice: inline
/// for the common case, and inside the cold [`timed`], so that neither way calls the other.
macro_rules! counted {
    ($cp:expr, $body:block) => {
        if $crate::registry::counting() {
            $crate::perf_stat::timed($cp, move || $body)
        } else {
            $body
        }
    };
}
pub(crate) use counted;

/// Runs `call`, an evaluation on contact point `cp_id`, and counts it when that contact
/// point's statistics are active.
#[cold]
#[inline(never)]
pub(crate) fn timed(cp_id: c_int, call: impl FnOnce() -> c_int) -> c_int {
    let start = std::time::Instant::now();
    let r = call();
    let took = u64::try_from(start.elapsed().as_nanos()).unwrap_or(u64::MAX);
    registry::count_call(cp_id, took);
    r
}

/// Changes a contact point's statistics, warning about an unknown id.
fn change(call: &Call, cpId: c_int, f: impl FnOnce(&mut registry::PerfStat) + Send) -> Option<registry::PerfStat> {
    let found = registry::perf_stat(cpId, f);
    if found.is_none() {
        call.warn(&format!("{}: no contact point with id {cpId}", call.name()));
    }
    found
}

/// Starts counting the evaluation calls on a contact point and their time, from zero.
#[no_mangle]
pub extern "C" fn crgContactPointActivatePerfStat(cpId: c_int) {
    answer!((), |call| {
        let start = registry::PerfStat { active: true, ..Default::default() };
        change(call, cpId, |s| *s = start);
    })
}

/// Stops counting the calls on a contact point (what was counted is kept for printing).
#[no_mangle]
pub extern "C" fn crgContactPointDeActivatePerfStat(cpId: c_int) {
    answer!((), |call| {
        change(call, cpId, |s| s.active = false);
    })
}

/// Prints what was counted on a contact point: calls, their total, mean and longest time.
#[no_mangle]
pub extern "C" fn crgContactPointPrintPerfStat(cpId: c_int) {
    answer!((), |call| {
        let Some(s) = change(call, cpId, |_| {}) else { return };
        let mean = if s.calls > 0 { s.nanos as f64 / s.calls as f64 } else { 0.0 };
        let state = if s.active { "counting" } else { "not counting" };
        call.send(msg::NOTICE, &format!("performance statistics of contact point {cpId} ({state})"));
        call.send(msg::NOTICE, &format!("    calls counted:  {}", s.calls));
        call.send(msg::NOTICE, &format!("    time in all:    {:.6} s", s.nanos as f64 * 1e-9));
        call.send(msg::NOTICE, &format!("    time per call:  {mean:.1} ns (longest {} ns)", s.longest));
    })
}
