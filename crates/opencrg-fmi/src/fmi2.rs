//! The FMI 2.0 functions, model exchange and co-simulation, with the types of the
//! standard's headers (`fmi2TypesPlatform.h`: `fmi2Boolean` and `fmi2Integer` are C
//! ints). Each answers through [`on_instance`]; functions of capabilities the model
//! description does not claim (FMU state, directional derivatives, asynchronous steps)
//! refuse with a message.
#![allow(non_snake_case)]

use crate::abi;
use crate::guard::{on_instance, slice, slice_mut, text, this_export};
use crate::instance::Interface;
use crate::log::{Fmi2Logger, Logger, Status};
use opencrg_fmu::Fmi;
use std::ffi::{c_char, c_int, c_uint, c_void};

/// `fmi2Component`.
type Component = *mut c_void;
/// `fmi2ValueReference`.
type Vr = c_uint;
/// `fmi2Boolean`.
type Boolean = c_int;

/// `fmi2CallbackFunctions`.
#[repr(C)]
pub struct CallbackFunctions {
    logger: Option<Fmi2Logger>,
    allocate_memory: Option<unsafe extern "C" fn(usize, usize) -> *mut c_void>,
    free_memory: Option<unsafe extern "C" fn(*mut c_void)>,
    step_finished: Option<unsafe extern "C" fn(*mut c_void, c_int)>,
    component_environment: *mut c_void,
}

/// `fmi2EventInfo`.
#[repr(C)]
pub struct EventInfo {
    new_discrete_states_needed: Boolean,
    terminate_simulation: Boolean,
    nominals_of_continuous_states_changed: Boolean,
    values_of_continuous_states_changed: Boolean,
    next_event_time_defined: Boolean,
    next_event_time: f64,
}

/// The platform types (`"default"`).
#[no_mangle]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    c"default".as_ptr()
}

/// The FMI version (`"2.0"`).
#[no_mangle]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    c"2.0".as_ptr()
}

/// Makes an instance: loads the road its resources hold. Null, with a message through
/// `functions`' logger naming the file and the reason, where it cannot.
///
/// # Safety
/// The strings are null or NUL-terminated; `functions` is null or valid for the
/// instance's life.
#[no_mangle]
pub unsafe extern "C" fn fmi2Instantiate(
    instance_name: *const c_char,
    fmu_type: c_int,
    guid: *const c_char,
    resource_location: *const c_char,
    functions: *const CallbackFunctions,
    _visible: Boolean,
    logging_on: Boolean,
) -> Component {
    // SAFETY: the caller's promise.
    let (instance_name, guid, location) = unsafe { (text(instance_name), text(guid), text(resource_location)) };
    // SAFETY: the caller's promise.
    let logger = match unsafe { functions.as_ref() } {
        Some(CallbackFunctions { logger: Some(log), component_environment, .. }) => Logger::Fmi2 {
            log: *log,
            env: *component_environment,
            name: crate::log::c_text(&instance_name.unwrap_or_default()),
        },
        _ => Logger::Silent,
    };
    let made = || {
        let interface = match fmu_type {
            0 => Interface::ModelExchange,
            1 => Interface::CoSimulation,
            other => return Err(format!("fmuType {other}: 0 (model exchange) or 1 (co-simulation)")),
        };
        let location = location.ok_or("no fmuResourceLocation given")?;
        let resources = crate::uri::file_path(&location)
            .ok_or_else(|| format!("fmuResourceLocation '{location}' is not a file: URI of this machine"))?;
        Ok((interface, guid, resources))
    };
    abi::instantiate(this_export!()(), made, Fmi::V2, logger, logging_on != 0)
}

/// Frees an instance.
///
/// # Safety
/// `c` is null or an instance of this library, not used again.
#[no_mangle]
pub unsafe extern "C" fn fmi2FreeInstance(c: Component) {
    // SAFETY: the caller's promise.
    unsafe { abi::free(c) }
}

/// Switches debug messages on or off (errors are always said).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: Component,
    on: Boolean,
    _n: usize,
    _categories: *const *const c_char,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            i.logging_on = on != 0;
            Ok(())
        })
    }
}

/// Sets the start time (the tolerance and stop time are not needed).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: Component,
    _tolerance_defined: Boolean,
    _tolerance: f64,
    start_time: f64,
    _stop_time_defined: Boolean,
    _stop_time: f64,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.setup_experiment(start_time)) }
}

/// Enters initialization mode.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: Component) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.enter_initialization(None)) }
}

/// Leaves initialization mode: into event mode (model exchange) or stepping
/// (co-simulation).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: Component) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.exit_initialization()) }
}

/// Ends the simulation.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2Terminate(c: Component) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.terminate()) }
}

/// Back to the state after instantiation, with the start values.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2Reset(c: Component) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.reset_all()) }
}

/// Reads Real variables: a wheel's answer computed where it moved since.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` and `value` hold `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetReal(c: Component, vr: *const Vr, nvr: usize, value: *mut f64) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.reals(slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?)) }
}

/// Reads Integer variables (a map's road and lane, integer options).
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` and `value` hold `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetInteger(c: Component, vr: *const Vr, nvr: usize, value: *mut c_int) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            abi::integers(i, slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?, None, |v| v)
        })
    }
}

/// Reads Boolean variables (whether each wheel is on the road).
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` and `value` hold `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetBoolean(c: Component, vr: *const Vr, nvr: usize, value: *mut Boolean) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            abi::booleans(i, slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?, Boolean::from)
        })
    }
}

/// Reads String variables (the behaviour profile); the strings stay valid until the
/// instance's next call.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` and `value` hold `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetString(c: Component, vr: *const Vr, nvr: usize, value: *mut *const c_char) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| abi::strings(i, slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?))
    }
}

/// Sets Real variables: the wheels' x and y, the friction default, real options.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` and `value` hold `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetReal(c: Component, vr: *const Vr, nvr: usize, value: *const f64) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.set_reals(slice(vr, nvr, "vr")?, slice(value, nvr, "value")?)) }
}

/// Sets Integer variables (integer options).
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` and `value` hold `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetInteger(c: Component, vr: *const Vr, nvr: usize, value: *const c_int) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            abi::set_integers(i, slice(vr, nvr, "vr")?, slice(value, nvr, "value")?, |v| v)
        })
    }
}

/// Sets Boolean variables: there is none to set.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetBoolean(c: Component, vr: *const Vr, nvr: usize, _value: *const Boolean) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| abi::set_booleans(i, slice(vr, nvr, "vr")?)) }
}

/// Sets String variables (the behaviour profile).
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` and `value` hold `nvr` values,
/// the strings NUL-terminated.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetString(c: Component, vr: *const Vr, nvr: usize, value: *const *const c_char) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| abi::set_strings(i, slice(vr, nvr, "vr")?, slice(value, nvr, "value")?))
    }
}

/// Not supported: FMU states.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetFMUstate(c: Component, _state: *mut *mut c_void) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::unsupported("getting the FMU state")) }
}

/// Not supported: FMU states.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetFMUstate(c: Component, _state: *mut c_void) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::unsupported("setting the FMU state")) }
}

/// Not supported: FMU states.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2FreeFMUstate(c: Component, _state: *mut *mut c_void) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::unsupported("freeing an FMU state")) }
}

/// Not supported: FMU states.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(c: Component, _state: *mut c_void, _size: *mut usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::unsupported("serializing the FMU state")) }
}

/// Not supported: FMU states.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: Component,
    _state: *mut c_void,
    _bytes: *mut u8,
    _size: usize,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::unsupported("serializing the FMU state")) }
}

/// Not supported: FMU states.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: Component,
    _bytes: *const u8,
    _size: usize,
    _state: *mut *mut c_void,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::unsupported("deserializing an FMU state")) }
}

/// Not supported: directional derivatives.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
    c: Component,
    _unknowns: *const Vr,
    _n_unknowns: usize,
    _knowns: *const Vr,
    _n_knowns: usize,
    _dv_known: *const f64,
    _dv_unknown: *mut f64,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::unsupported("directional derivatives")) }
}

/// Model exchange: enters event mode.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2EnterEventMode(c: Component) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.enter_event_mode()) }
}

/// Model exchange: no discrete states to update, no event to come.
///
/// # Safety
/// `c` is null or a live instance of this library; `info` null or writable.
#[no_mangle]
pub unsafe extern "C" fn fmi2NewDiscreteStates(c: Component, info: *mut EventInfo) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            i.update_discrete_states()?;
            let info = slice_mut(info, 1, "eventInfo")?;
            info[0] = EventInfo {
                new_discrete_states_needed: 0,
                terminate_simulation: 0,
                nominals_of_continuous_states_changed: 0,
                values_of_continuous_states_changed: 0,
                next_event_time_defined: 0,
                next_event_time: 0.0,
            };
            Ok(())
        })
    }
}

/// Model exchange: enters continuous-time mode.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2EnterContinuousTimeMode(c: Component) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.enter_continuous_time()) }
}

/// Model exchange: a step done; no event is needed.
///
/// # Safety
/// `c` is null or a live instance of this library; the flags null or writable.
#[no_mangle]
pub unsafe extern "C" fn fmi2CompletedIntegratorStep(
    c: Component,
    _no_set_prior: Boolean,
    enter_event_mode: *mut Boolean,
    terminate: *mut Boolean,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            i.completed_integrator_step()?;
            slice_mut(enter_event_mode, 1, "enterEventMode")?[0] = 0;
            slice_mut(terminate, 1, "terminateSimulation")?[0] = 0;
            Ok(())
        })
    }
}

/// Model exchange: sets the time.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetTime(c: Component, time: f64) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.set_model_time(time)) }
}

/// Model exchange: there are no states (n must be 0).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetContinuousStates(c: Component, _x: *const f64, n: usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::no_states(n)) }
}

/// Model exchange: there are no states (n must be 0).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetDerivatives(c: Component, _dx: *mut f64, n: usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::no_states(n)) }
}

/// Model exchange: there are no event indicators (n must be 0).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetEventIndicators(c: Component, z: *mut f64, n: usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.event_indicators(slice_mut(z, n, "eventIndicators")?)) }
}

/// Model exchange: there are no states (n must be 0).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetContinuousStates(c: Component, _x: *mut f64, n: usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::no_states(n)) }
}

/// Model exchange: there are no states (n must be 0).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetNominalsOfContinuousStates(c: Component, _x: *mut f64, n: usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::no_states(n)) }
}

/// Co-simulation: input derivatives are not used (order 0 only).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
    c: Component,
    _vr: *const Vr,
    nvr: usize,
    _order: *const c_int,
    _value: *const f64,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::no_derivatives(nvr, "input derivatives")) }
}

/// Co-simulation: output derivatives are not given (maxOutputDerivativeOrder 0).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: Component,
    _vr: *const Vr,
    nvr: usize,
    _order: *const c_int,
    _value: *mut f64,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::no_derivatives(nvr, "output derivatives")) }
}

/// Co-simulation: a step (the outputs follow the inputs; the time advances).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2DoStep(c: Component, current: f64, step: f64, _no_set_prior: Boolean) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.do_step(current, step)) }
}

/// Co-simulation: steps are never asynchronous, so there is nothing to cancel.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi2CancelStep(c: Component) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| abi::unsupported("cancelling a step (steps end before they return)")) }
}

macro_rules! status_query {
    ($name:ident, $ty:ty) => {
        /// Co-simulation: not supported (steps are never asynchronous).
        ///
        /// # Safety
        /// `c` is null or a live instance of this library.
        #[no_mangle]
        pub unsafe extern "C" fn $name(c: Component, _kind: c_int, _value: *mut $ty) -> Status {
            // SAFETY: the caller's promise.
            unsafe {
                on_instance(this_export!(), c, |_| abi::unsupported("status queries (steps are never asynchronous)"))
            }
        }
    };
}
status_query!(fmi2GetStatus, c_int);
status_query!(fmi2GetRealStatus, f64);
status_query!(fmi2GetIntegerStatus, c_int);
status_query!(fmi2GetBooleanStatus, Boolean);
status_query!(fmi2GetStringStatus, *const c_char);
