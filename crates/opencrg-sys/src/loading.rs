//! Loading, checking and releasing data sets; the library's release text.
#![allow(non_snake_case)] // the C API's parameter names

use crate::entry::answer;
use crate::ptr::in_str;
use crate::{c_path, compat, msg, registry, report};
use opencrg_core::Road;
use std::ffi::{c_char, c_int};
use std::sync::atomic::{AtomicBool, Ordering};

static SUPPRESS_NOT_FOUND: AtomicBool = AtomicBool::new(false);

/// Reads a CRG file; returns the data set id (> 0) or 0.
///
/// # Safety
/// `filename` is null or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn crgLoaderReadFile(filename: *const c_char) -> c_int {
    // SAFETY: the contract above.
    let filename = unsafe { in_str(filename) };
    answer!(0, |call| {
        let Some(filename) = filename else {
            call.fatal(&format!("{}: no file name given", call.name()));
            return 0;
        };
        let path = c_path::path_of(filename);
        let compat = match compat::from_environment() {
            Ok(compat) => compat,
            Err(e) => {
                call.fatal(&format!("{}: {e}; file <{}> not read", call.name(), path.display()));
                return 0;
            }
        };
        // The statistics block costs a scan of the grid: only when it will be printed.
        let options = opencrg_core::LoadOptions {
            compat,
            report_statistics: msg::level() >= msg::NOTICE,
            ..opencrg_core::LoadOptions::default()
        };
        match Road::load_with(&path, options) {
            Ok(mut road) => {
                // The file's WARN_MSGS counts the messages of its own loading, as the
                // reference applies it while reading the header.
                if let Some(n) = road.header().warn_msgs {
                    msg::set_max_warnings(n);
                }
                for w in road.warnings() {
                    call.warn(w);
                }
                report::send(call, road.take_events());
                let id = registry::add_dataset(road);
                call.notice(&format!("{}: finished reading file <{}>", call.name(), path.display()));
                id
            }
            Err(e) => {
                let not_found = matches!(&e, opencrg_core::Error::NotFound { .. });
                if !(not_found && SUPPRESS_NOT_FOUND.load(Ordering::Relaxed)) {
                    call.fatal(&format!("{}: {e}", call.name()));
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
    answer!(0, |call| {
        let Some((checked, events)) = call.change_road(dataSetId, |r| (r.check(), r.take_events())) else {
            return 0;
        };
        report::send(call, events);
        if let Some(road) = call.road(dataSetId) {
            for sentence in opencrg_core::map_disagreements(&road) {
                call.warn(&format!("{}: {sentence}", call.name()));
            }
        }
        match checked {
            Ok(()) => 1,
            Err(e) => {
                call.fatal(&format!("{}: {e}", call.name()));
                0
            }
        }
    })
}

/// Releases a data set and its contact points.
#[no_mangle]
pub extern "C" fn crgDataSetRelease(dataSetId: c_int) -> c_int {
    answer!(0, |call| {
        let released = registry::release_dataset(dataSetId);
        if released {
            call.notice(&format!("{}: data set {dataSetId} released", call.name()));
        }
        c_int::from(released)
    })
}

/// Releases every data set.
#[no_mangle]
pub extern "C" fn crgMemRelease() {
    answer!((), |_| {
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
