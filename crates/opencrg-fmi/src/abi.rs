//! What the FMI 2 and FMI 3 functions share beyond the state machine: making and freeing
//! an instance, the loops over value references for each C type, and the refusals of
//! what this FMU does not have. The two versions' files only translate their types and
//! names onto these.

use crate::guard::{guarded, text};
use crate::instance::{error, Instance, Interface, Refused};
use crate::log::{Logger, Status};
use opencrg_fmu::variables::Type;
use opencrg_fmu::Fmi;
use std::ffi::{c_char, c_void};
use std::path::PathBuf;

/// An instance on the heap for the importer, its road loaded from `resources`; null, with
/// a message through `logger` naming the export (`name`), the file and the reason, where
/// it cannot be made.
pub(crate) fn instantiate(
    name: &str,
    made: impl FnOnce() -> Result<(Interface, Option<String>, PathBuf), String>,
    fmi: Fmi,
    logger: Logger,
    logging_on: bool,
) -> *mut c_void {
    guarded(std::ptr::null_mut(), || {
        let instance = made().and_then(|(interface, token, resources)| {
            Instance::new(&token.unwrap_or_default(), &resources, interface, fmi, logger.clone())
        });
        match instance {
            Ok(mut instance) => {
                instance.logging_on = logging_on;
                Box::into_raw(Box::new(instance)).cast()
            }
            Err(message) => {
                logger.say(Status::Error, &format!("{name}: {message}"));
                std::ptr::null_mut()
            }
        }
    })
}

/// Frees an instance `instantiate` made.
///
/// # Safety
/// `c` is null or an instance of this library, not used again.
pub(crate) unsafe fn free(c: *mut c_void) {
    if !c.is_null() {
        // SAFETY: the caller's promise; a panic in a drop is caught.
        guarded((), || drop(unsafe { Box::from_raw(c.cast::<Instance>()) }));
    }
}

/// Integer variables into `out`, each converted by `to`: of FMI 3's type `ty` (Int32
/// for an Integer, Int64 for an Enumeration), or of either (`None`: FMI 2 reads both as
/// Integer).
pub(crate) fn integers<T>(
    i: &mut Instance,
    vrs: &[u32],
    out: &mut [T],
    ty: Option<Type>,
    to: impl Fn(i32) -> T,
) -> Result<(), Refused> {
    for (&vr, value) in vrs.iter().zip(out) {
        *value = to(match ty {
            Some(ty) => i.integer_of(vr, ty)?,
            None => i.integer(vr)?,
        });
    }
    Ok(())
}

/// Sets Integer variables.
pub(crate) fn set_integers<T: Copy>(
    i: &mut Instance,
    vrs: &[u32],
    values: &[T],
    from: impl Fn(T) -> i32,
) -> Result<(), Refused> {
    for (&vr, &value) in vrs.iter().zip(values) {
        i.set_integer(vr, from(value))?;
    }
    Ok(())
}

/// Boolean variables into `out`, each converted by `to`.
pub(crate) fn booleans<T>(i: &mut Instance, vrs: &[u32], out: &mut [T], to: impl Fn(bool) -> T) -> Result<(), Refused> {
    for (&vr, value) in vrs.iter().zip(out) {
        *value = to(i.boolean(vr)?);
    }
    Ok(())
}

/// Sets Boolean variables: refused for each (there is none to set).
pub(crate) fn set_booleans(i: &mut Instance, vrs: &[u32]) -> Result<(), Refused> {
    vrs.iter().try_for_each(|&vr| i.set_boolean(vr))
}

/// String variables into `out`, valid until the instance's next call.
pub(crate) fn strings(i: &mut Instance, vrs: &[u32], out: &mut [*const c_char]) -> Result<(), Refused> {
    for (s, value) in i.strings(vrs)?.iter().zip(out) {
        *value = s.as_ptr();
    }
    Ok(())
}

/// Sets String variables.
///
/// # Safety
/// Each of `values` is null or a NUL-terminated string that outlives the call.
pub(crate) unsafe fn set_strings(i: &mut Instance, vrs: &[u32], values: &[*const c_char]) -> Result<(), Refused> {
    for (&vr, &value) in vrs.iter().zip(values) {
        // SAFETY: the caller's promise.
        let value = unsafe { text(value) }.ok_or_else(|| error("a null string"))?;
        i.set_string(vr, &value)?;
    }
    Ok(())
}

/// A capability the model description does not claim.
pub(crate) fn unsupported(what: &str) -> Result<(), Refused> {
    Err(error(format!("{what} is not supported (the model description says so)")))
}

/// Refuses a state vector of a length other than 0 (there are no continuous states).
pub(crate) fn no_states(n: usize) -> Result<(), Refused> {
    if n == 0 {
        Ok(())
    } else {
        Err(error(format!("{n} continuous states asked for: this FMU has none")))
    }
}

/// Refuses derivatives of inputs or outputs, unless none are given or asked for.
pub(crate) fn no_derivatives(n: usize, what: &str) -> Result<(), Refused> {
    if n == 0 {
        Ok(())
    } else {
        unsupported(what)
    }
}
