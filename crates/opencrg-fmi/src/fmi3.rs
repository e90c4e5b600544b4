//! The FMI 3.0 functions, model exchange and co-simulation, with the types of the
//! standard's headers (`fmi3PlatformTypes.h`: `fmi3Boolean` is C's `bool`). Every
//! function of the standard is exported; those of capabilities the model description
//! does not claim (scheduled execution, FMU state, derivatives, clocks, configuration
//! mode, types the FMU has no variable of) refuse with a message.
#![allow(non_snake_case)]

use crate::abi;
use crate::guard::{guarded, on_instance, same_length, slice, slice_mut, text, this_export};
use crate::instance::{error, Interface, Refused};
use crate::log::{Fmi3Logger, Logger, Status};
use opencrg_fmu::variables::Type;
use opencrg_fmu::Fmi;
use std::ffi::{c_char, c_int, c_void};

/// `fmi3Instance`.
type Inst = *mut c_void;
/// `fmi3ValueReference`.
type Vr = u32;

/// `fmi3Dependent` of `fmi3DependencyKind`.
const DEPENDENT: c_int = 5;

/// The FMI version (`"3.0"`).
#[no_mangle]
pub extern "C" fn fmi3GetVersion() -> *const c_char {
    c"3.0".as_ptr()
}

/// Makes an instance of `interface`; null, with a message through `log` naming the file
/// and the reason, where the road cannot be loaded.
///
/// # Safety
/// The strings are null or NUL-terminated; `log` with `env` valid for the instance's life.
unsafe fn instantiate(
    name: &str,
    interface: Interface,
    token: *const c_char,
    resource_path: *const c_char,
    logging_on: bool,
    env: *mut c_void,
    log: Option<Fmi3Logger>,
) -> Inst {
    let logger = match log {
        Some(log) => Logger::Fmi3 { log, env },
        None => Logger::Silent,
    };
    // SAFETY: the caller's promise.
    let (token, path) = unsafe { (text(token), text(resource_path)) };
    let made = || Ok((interface, token, path.ok_or("no resourcePath given")?.into()));
    abi::instantiate(name, made, Fmi::V3, logger, logging_on)
}

/// Makes a model exchange instance.
///
/// # Safety
/// The strings are null or NUL-terminated; `log` with `env` valid for the instance's life.
#[no_mangle]
pub unsafe extern "C" fn fmi3InstantiateModelExchange(
    _instance_name: *const c_char,
    token: *const c_char,
    resource_path: *const c_char,
    _visible: bool,
    logging_on: bool,
    env: *mut c_void,
    log: Option<Fmi3Logger>,
) -> Inst {
    // SAFETY: the caller's promise.
    unsafe { instantiate(this_export!()(), Interface::ModelExchange, token, resource_path, logging_on, env, log) }
}

/// Makes a co-simulation instance (event mode and early return are not used).
///
/// # Safety
/// The strings are null or NUL-terminated; `log` with `env` valid for the instance's life.
#[no_mangle]
pub unsafe extern "C" fn fmi3InstantiateCoSimulation(
    _instance_name: *const c_char,
    token: *const c_char,
    resource_path: *const c_char,
    _visible: bool,
    logging_on: bool,
    _event_mode_used: bool,
    _early_return_allowed: bool,
    _required_intermediate: *const Vr,
    _n_required_intermediate: usize,
    env: *mut c_void,
    log: Option<Fmi3Logger>,
    _intermediate_update: *mut c_void,
) -> Inst {
    // SAFETY: the caller's promise.
    unsafe { instantiate(this_export!()(), Interface::CoSimulation, token, resource_path, logging_on, env, log) }
}

/// Not supported: scheduled execution (null, said through `log`).
///
/// # Safety
/// `log` with `env` is null or callable.
#[no_mangle]
pub unsafe extern "C" fn fmi3InstantiateScheduledExecution(
    _instance_name: *const c_char,
    _token: *const c_char,
    _resource_path: *const c_char,
    _visible: bool,
    _logging_on: bool,
    env: *mut c_void,
    log: Option<Fmi3Logger>,
    _clock_update: *mut c_void,
    _lock_preemption: *mut c_void,
    _unlock_preemption: *mut c_void,
) -> Inst {
    let name = this_export!()();
    guarded(std::ptr::null_mut(), || {
        if let Some(log) = log {
            let message = format!("{name}: scheduled execution is not supported (the model description says so)");
            Logger::Fmi3 { log, env }.say(Status::Error, &message);
        }
        std::ptr::null_mut()
    })
}

/// Frees an instance.
///
/// # Safety
/// `c` is null or an instance of this library, not used again.
#[no_mangle]
pub unsafe extern "C" fn fmi3FreeInstance(c: Inst) {
    // SAFETY: the caller's promise.
    unsafe { abi::free(c) }
}

/// Switches debug messages on or off (errors are always said).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi3SetDebugLogging(
    c: Inst,
    on: bool,
    _n: usize,
    _categories: *const *const c_char,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            i.logging_on = on;
            Ok(())
        })
    }
}

/// Enters initialization mode at the start time.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi3EnterInitializationMode(
    c: Inst,
    _tolerance_defined: bool,
    _tolerance: f64,
    start_time: f64,
    _stop_time_defined: bool,
    _stop_time: f64,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.enter_initialization(Some(start_time))) }
}

/// Leaves initialization mode: into event mode (model exchange) or step mode
/// (co-simulation, which has no event mode).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi3ExitInitializationMode(c: Inst) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.exit_initialization()) }
}

/// Model exchange: enters event mode (co-simulation has none).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi3EnterEventMode(c: Inst) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.enter_event_mode()) }
}

/// Ends the simulation.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi3Terminate(c: Inst) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.terminate()) }
}

/// Back to the state after instantiation, with the start values.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi3Reset(c: Inst) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.reset_all()) }
}

/// Reads Float64 variables: a wheel's answer computed where it moved since, the time,
/// real parameters.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values, `values`
/// `n_values`.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetFloat64(
    c: Inst,
    vr: *const Vr,
    nvr: usize,
    values: *mut f64,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            same_length(nvr, n_values)?;
            i.reals(slice(vr, nvr, "valueReferences")?, slice_mut(values, nvr, "values")?)
        })
    }
}

/// Sets Float64 variables: the wheels' x and y, the friction default, real options.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values, `values`
/// `n_values`.
#[no_mangle]
pub unsafe extern "C" fn fmi3SetFloat64(
    c: Inst,
    vr: *const Vr,
    nvr: usize,
    values: *const f64,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            same_length(nvr, n_values)?;
            i.set_reals(slice(vr, nvr, "valueReferences")?, slice(values, nvr, "values")?)
        })
    }
}

/// Reads Int32 variables (a map's road and lane, integer options).
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values, `values`
/// `n_values`.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetInt32(c: Inst, vr: *const Vr, nvr: usize, values: *mut i32, n_values: usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            same_length(nvr, n_values)?;
            let (vr, values) = (slice(vr, nvr, "valueReferences")?, slice_mut(values, nvr, "values")?);
            abi::integers(i, vr, values, Some(Type::Integer), |v| v)
        })
    }
}

/// Sets Int32 variables (integer options).
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values, `values`
/// `n_values`.
#[no_mangle]
pub unsafe extern "C" fn fmi3SetInt32(
    c: Inst,
    vr: *const Vr,
    nvr: usize,
    values: *const i32,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            same_length(nvr, n_values)?;
            abi::set_integers(i, slice(vr, nvr, "valueReferences")?, slice(values, nvr, "values")?, |v| v)
        })
    }
}

/// Reads Boolean variables (whether each wheel is on the road).
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values, `values`
/// `n_values`.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetBoolean(
    c: Inst,
    vr: *const Vr,
    nvr: usize,
    values: *mut bool,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            same_length(nvr, n_values)?;
            abi::booleans(i, slice(vr, nvr, "valueReferences")?, slice_mut(values, nvr, "values")?, |b| b)
        })
    }
}

/// Sets Boolean variables: there is none to set.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi3SetBoolean(
    c: Inst,
    vr: *const Vr,
    nvr: usize,
    _values: *const bool,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            same_length(nvr, n_values)?;
            abi::set_booleans(i, slice(vr, nvr, "valueReferences")?)
        })
    }
}

/// Reads String variables (the behaviour profile); valid until the instance's next call.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values, `values`
/// `n_values`.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetString(
    c: Inst,
    vr: *const Vr,
    nvr: usize,
    values: *mut *const c_char,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            same_length(nvr, n_values)?;
            abi::strings(i, slice(vr, nvr, "valueReferences")?, slice_mut(values, nvr, "values")?)
        })
    }
}

/// Sets String variables (the behaviour profile).
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values, `values`
/// `n_values` NUL-terminated strings.
#[no_mangle]
pub unsafe extern "C" fn fmi3SetString(
    c: Inst,
    vr: *const Vr,
    nvr: usize,
    values: *const *const c_char,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            same_length(nvr, n_values)?;
            abi::set_strings(i, slice(vr, nvr, "valueReferences")?, slice(values, nvr, "values")?)
        })
    }
}

/// Refuses value references of a type the FMU has no variable of (none for `nvr` = 0).
fn no_variable_of(ty: &str, vr: &[Vr]) -> Result<(), Refused> {
    match vr.first() {
        None => Ok(()),
        Some(r) => Err(error(format!("value reference {r}: this FMU has no {ty} variable"))),
    }
}

macro_rules! no_such_type {
    ($get:ident, $set:ident, $ty:ty, $name:literal) => {
        #[doc = concat!("Reads ", $name, " variables: there are none.")]
        ///
        /// # Safety
        /// `c` is null or a live instance of this library; `vr` holds `nvr` values.
        #[no_mangle]
        pub unsafe extern "C" fn $get(
            c: Inst,
            vr: *const Vr,
            nvr: usize,
            _values: *mut $ty,
            _n_values: usize,
        ) -> Status {
            // SAFETY: the caller's promise.
            unsafe { on_instance(this_export!(), c, |_| no_variable_of($name, slice(vr, nvr, "valueReferences")?)) }
        }

        #[doc = concat!("Sets ", $name, " variables: there are none.")]
        ///
        /// # Safety
        /// `c` is null or a live instance of this library; `vr` holds `nvr` values.
        #[no_mangle]
        pub unsafe extern "C" fn $set(
            c: Inst,
            vr: *const Vr,
            nvr: usize,
            _values: *const $ty,
            _n_values: usize,
        ) -> Status {
            // SAFETY: the caller's promise.
            unsafe { on_instance(this_export!(), c, |_| no_variable_of($name, slice(vr, nvr, "valueReferences")?)) }
        }
    };
}
no_such_type!(fmi3GetFloat32, fmi3SetFloat32, f32, "Float32");
no_such_type!(fmi3GetInt8, fmi3SetInt8, i8, "Int8");
no_such_type!(fmi3GetUInt8, fmi3SetUInt8, u8, "UInt8");
no_such_type!(fmi3GetInt16, fmi3SetInt16, i16, "Int16");
no_such_type!(fmi3GetUInt16, fmi3SetUInt16, u16, "UInt16");
no_such_type!(fmi3GetUInt32, fmi3SetUInt32, u32, "UInt32");
no_such_type!(fmi3GetUInt64, fmi3SetUInt64, u64, "UInt64");

/// Reads Int64 variables: a map's road, an enumeration.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values, `values`
/// `n_values`.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetInt64(c: Inst, vr: *const Vr, nvr: usize, values: *mut i64, n_values: usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            same_length(nvr, n_values)?;
            let (vr, values) = (slice(vr, nvr, "valueReferences")?, slice_mut(values, nvr, "values")?);
            abi::integers(i, vr, values, Some(Type::Enumeration), i64::from)
        })
    }
}

/// Sets Int64 variables: there is none to set.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi3SetInt64(c: Inst, vr: *const Vr, nvr: usize, _values: *const i64, _n: usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| no_variable_of("settable Int64", slice(vr, nvr, "valueReferences")?)) }
}

/// Reads Binary variables: there are none.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetBinary(
    c: Inst,
    vr: *const Vr,
    nvr: usize,
    _sizes: *mut usize,
    _values: *mut *const u8,
    _n_values: usize,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| no_variable_of("Binary", slice(vr, nvr, "valueReferences")?)) }
}

/// Sets Binary variables: there are none.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi3SetBinary(
    c: Inst,
    vr: *const Vr,
    nvr: usize,
    _sizes: *const usize,
    _values: *const *const u8,
    _n_values: usize,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| no_variable_of("Binary", slice(vr, nvr, "valueReferences")?)) }
}

/// Reads Clock variables: there are none.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetClock(c: Inst, vr: *const Vr, nvr: usize, _values: *mut bool) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| no_variable_of("Clock", slice(vr, nvr, "valueReferences")?)) }
}

/// Sets Clock variables: there are none.
///
/// # Safety
/// `c` is null or a live instance of this library; `vr` holds `nvr` values.
#[no_mangle]
pub unsafe extern "C" fn fmi3SetClock(c: Inst, vr: *const Vr, nvr: usize, _values: *const bool) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |_| no_variable_of("Clock", slice(vr, nvr, "valueReferences")?)) }
}

/// How many variables `vr` depends on: a wheel's outputs on its x and y, nothing else.
///
/// # Safety
/// `c` is null or a live instance of this library; `n` null or writable.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetNumberOfVariableDependencies(c: Inst, vr: Vr, n: *mut usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            slice_mut(n, 1, "nDependencies")?[0] = i.dependencies(vr)?.len();
            Ok(())
        })
    }
}

/// The variables `dependent` depends on (scalars: element index 0), all `fmi3Dependent`.
///
/// # Safety
/// `c` is null or a live instance of this library; the arrays hold `n` writable values.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetVariableDependencies(
    c: Inst,
    dependent: Vr,
    element_of_dependent: *mut usize,
    independents: *mut Vr,
    element_of_independents: *mut usize,
    kinds: *mut c_int,
    n: usize,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            let depends = i.dependencies(dependent)?;
            same_length(depends.len(), n)?;
            let (e_dep, ind) = (
                slice_mut(element_of_dependent, n, "elementIndicesOfDependent")?,
                slice_mut(independents, n, "independents")?,
            );
            let (e_ind, kinds) = (
                slice_mut(element_of_independents, n, "elementIndicesOfIndependents")?,
                slice_mut(kinds, n, "dependencyKinds")?,
            );
            for (k, &vr) in depends.iter().enumerate() {
                (e_dep[k], ind[k], e_ind[k], kinds[k]) = (0, vr, 0, DEPENDENT);
            }
            Ok(())
        })
    }
}

macro_rules! not_supported {
    ($name:ident ( $($arg:ident : $ty:ty),* ), $what:literal) => {
        #[doc = concat!("Not supported: ", $what, ".")]
        ///
        /// # Safety
        /// `c` is null or a live instance of this library.
        #[no_mangle]
        pub unsafe extern "C" fn $name(c: Inst, $($arg: $ty),*) -> Status {
            $(let _ = $arg;)*
            // SAFETY: the caller's promise.
            unsafe { on_instance(this_export!(), c, |_| abi::unsupported($what)) }
        }
    };
}
not_supported!(fmi3GetFMUState(state: *mut *mut c_void), "FMU states");
not_supported!(fmi3SetFMUState(state: *mut c_void), "FMU states");
not_supported!(fmi3FreeFMUState(state: *mut *mut c_void), "FMU states");
not_supported!(fmi3SerializedFMUStateSize(state: *mut c_void, size: *mut usize), "FMU states");
not_supported!(fmi3SerializeFMUState(state: *mut c_void, bytes: *mut u8, size: usize), "FMU states");
not_supported!(fmi3DeserializeFMUState(bytes: *const u8, size: usize, state: *mut *mut c_void), "FMU states");
not_supported!(
    fmi3GetDirectionalDerivative(unknowns: *const Vr, n_unknowns: usize, knowns: *const Vr, n_knowns: usize, seed: *const f64, n_seed: usize, sensitivity: *mut f64, n_sensitivity: usize),
    "directional derivatives"
);
not_supported!(
    fmi3GetAdjointDerivative(unknowns: *const Vr, n_unknowns: usize, knowns: *const Vr, n_knowns: usize, seed: *const f64, n_seed: usize, sensitivity: *mut f64, n_sensitivity: usize),
    "adjoint derivatives"
);
not_supported!(fmi3EnterConfigurationMode(), "configuration mode (there are no structural parameters)");
not_supported!(fmi3ExitConfigurationMode(), "configuration mode (there are no structural parameters)");
not_supported!(fmi3GetIntervalDecimal(vr: *const Vr, nvr: usize, intervals: *mut f64, qualifiers: *mut c_int), "clocks");
not_supported!(fmi3GetIntervalFraction(vr: *const Vr, nvr: usize, counters: *mut u64, resolutions: *mut u64, qualifiers: *mut c_int), "clocks");
not_supported!(fmi3GetShiftDecimal(vr: *const Vr, nvr: usize, shifts: *mut f64), "clocks");
not_supported!(fmi3GetShiftFraction(vr: *const Vr, nvr: usize, counters: *mut u64, resolutions: *mut u64), "clocks");
not_supported!(fmi3SetIntervalDecimal(vr: *const Vr, nvr: usize, intervals: *const f64), "clocks");
not_supported!(fmi3SetIntervalFraction(vr: *const Vr, nvr: usize, counters: *const u64, resolutions: *const u64), "clocks");
not_supported!(fmi3SetShiftDecimal(vr: *const Vr, nvr: usize, shifts: *const f64), "clocks");
not_supported!(fmi3SetShiftFraction(vr: *const Vr, nvr: usize, counters: *const u64, resolutions: *const u64), "clocks");
not_supported!(fmi3EvaluateDiscreteStates(), "evaluating discrete states");
not_supported!(fmi3GetOutputDerivatives(vr: *const Vr, nvr: usize, orders: *const i32, values: *mut f64, n_values: usize), "output derivatives");
not_supported!(fmi3ActivateModelPartition(clock: Vr, time: f64), "scheduled execution");

/// Model exchange: no discrete states to update, no event to come.
///
/// # Safety
/// `c` is null or a live instance of this library; the flags null or writable.
#[no_mangle]
pub unsafe extern "C" fn fmi3UpdateDiscreteStates(
    c: Inst,
    update_needed: *mut bool,
    terminate: *mut bool,
    nominals_changed: *mut bool,
    values_changed: *mut bool,
    next_time_defined: *mut bool,
    next_time: *mut f64,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            i.update_discrete_states()?;
            for (flag, what) in [
                (update_needed, "discreteStatesNeedUpdate"),
                (terminate, "terminateSimulation"),
                (nominals_changed, "nominalsOfContinuousStatesChanged"),
                (values_changed, "valuesOfContinuousStatesChanged"),
                (next_time_defined, "nextEventTimeDefined"),
            ] {
                slice_mut(flag, 1, what)?[0] = false;
            }
            slice_mut(next_time, 1, "nextEventTime")?[0] = 0.0;
            Ok(())
        })
    }
}

/// Model exchange: enters continuous-time mode.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi3EnterContinuousTimeMode(c: Inst) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.enter_continuous_time()) }
}

/// Model exchange: a step done; no event is needed.
///
/// # Safety
/// `c` is null or a live instance of this library; the flags null or writable.
#[no_mangle]
pub unsafe extern "C" fn fmi3CompletedIntegratorStep(
    c: Inst,
    _no_set_prior: bool,
    enter_event_mode: *mut bool,
    terminate: *mut bool,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            i.completed_integrator_step()?;
            slice_mut(enter_event_mode, 1, "enterEventMode")?[0] = false;
            slice_mut(terminate, 1, "terminateSimulation")?[0] = false;
            Ok(())
        })
    }
}

/// Model exchange: sets the time.
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi3SetTime(c: Inst, time: f64) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.set_model_time(time)) }
}

macro_rules! no_states_fn {
    ($name:ident, $ptr:ty, $what:literal) => {
        #[doc = concat!("Model exchange: ", $what, " (there are none; n must be 0).")]
        ///
        /// # Safety
        /// `c` is null or a live instance of this library.
        #[no_mangle]
        pub unsafe extern "C" fn $name(c: Inst, _values: $ptr, n: usize) -> Status {
            // SAFETY: the caller's promise.
            unsafe { on_instance(this_export!(), c, |_| abi::no_states(n)) }
        }
    };
}
no_states_fn!(fmi3SetContinuousStates, *const f64, "sets the continuous states");
no_states_fn!(fmi3GetContinuousStateDerivatives, *mut f64, "the states' derivatives");
no_states_fn!(fmi3GetContinuousStates, *mut f64, "the continuous states");
no_states_fn!(fmi3GetNominalsOfContinuousStates, *mut f64, "the states' nominal values");

/// Model exchange: there are no event indicators (n must be 0).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetEventIndicators(c: Inst, values: *mut f64, n: usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.event_indicators(slice_mut(values, n, "eventIndicators")?)) }
}

/// Model exchange: the number of event indicators, one per wheel.
///
/// # Safety
/// `c` is null or a live instance of this library; `n` null or writable.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetNumberOfEventIndicators(c: Inst, n: *mut usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            slice_mut(n, 1, "nEventIndicators")?[0] = i.event_indicator_count();
            Ok(())
        })
    }
}

/// Model exchange: the number of continuous states, 0.
///
/// # Safety
/// `c` is null or a live instance of this library; `n` null or writable.
#[no_mangle]
pub unsafe extern "C" fn fmi3GetNumberOfContinuousStates(c: Inst, n: *mut usize) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |_| {
            slice_mut(n, 1, "nContinuousStates")?[0] = 0;
            Ok(())
        })
    }
}

/// Co-simulation: step mode is where instances are after initialization (there is no
/// event mode to leave).
///
/// # Safety
/// `c` is null or a live instance of this library.
#[no_mangle]
pub unsafe extern "C" fn fmi3EnterStepMode(c: Inst) -> Status {
    // SAFETY: the caller's promise.
    unsafe { on_instance(this_export!(), c, |i| i.enter_step_mode()) }
}

/// Co-simulation: a step (the outputs follow the inputs; the time advances).
///
/// # Safety
/// `c` is null or a live instance of this library; the flags null or writable.
#[no_mangle]
pub unsafe extern "C" fn fmi3DoStep(
    c: Inst,
    current: f64,
    step: f64,
    _no_set_prior: bool,
    event_handling_needed: *mut bool,
    terminate: *mut bool,
    early_return: *mut bool,
    last_successful_time: *mut f64,
) -> Status {
    // SAFETY: the caller's promise.
    unsafe {
        on_instance(this_export!(), c, |i| {
            i.do_step(current, step)?;
            for (flag, what) in [
                (event_handling_needed, "eventHandlingNeeded"),
                (terminate, "terminateSimulation"),
                (early_return, "earlyReturn"),
            ] {
                slice_mut(flag, 1, what)?[0] = false;
            }
            slice_mut(last_successful_time, 1, "lastSuccessfulTime")?[0] = i.time();
            Ok(())
        })
    }
}
