//! One FMU instance: its road and wheels, its parameters, the FMI state it is in, and
//! which call is allowed where. Shared by the FMI 2 and FMI 3 functions; nothing here
//! is global, so instances on different threads never meet.

use crate::log::{Logger, Status};
use crate::states::{Call, State};
use opencrg_core::settings::Value;
use opencrg_fmu::variables::{self, Parameter, Quantity, Start, Type};
use opencrg_fmu::{compat_named, Wheels};
use opencrg_fmu::{Fmi, Fmu, Kind};
use std::ffi::CString;
use std::path::Path;

/// Model exchange or co-simulation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interface {
    /// Model exchange: the importer integrates (there is nothing to integrate).
    ModelExchange,
    /// Co-simulation: the importer steps.
    CoSimulation,
}

/// A call not done: its status and why.
#[derive(Debug)]
pub struct Refused {
    /// Error, or Discard.
    pub status: Status,
    /// The reason, said through the logger.
    pub message: String,
}

/// Refuses with status Error.
pub fn error(message: impl ToString) -> Refused {
    Refused { status: Status::Error, message: message.to_string() }
}

/// A table by value reference of the wheel (0-based) and quantity each reference names,
/// for the references of one kind: the hot paths' decoding.
type Slots = Box<[Option<(u16, Quantity)>]>;

/// The wheel (0-based) and quantity the table `slots` gives reference `vr`, if any: the
/// hot paths' one lookup.
#[inline(always)]
fn slot_of(slots: &[Option<(u16, Quantity)>], vr: u32) -> Option<(usize, Quantity)> {
    let (wheel, q) = slots.get(vr as usize).copied().flatten()?;
    Some((usize::from(wheel), q))
}

/// The [`Slots`] of the wheel quantities of an FMU of `kind` with `wheels` wheels that
/// are `of_kind`.
fn slots(kind: Kind, wheels: u32, of_kind: impl Fn(Quantity) -> bool) -> Slots {
    let end = variables::wheel_vr(wheels + 1, Quantity::X);
    (0..end)
        .map(|vr| {
            let (wheel, q) = variables::wheel_of(kind, wheels, vr).filter(|&(_, q)| of_kind(q))?;
            Some((u16::try_from(wheel - 1).ok()?, q))
        })
        .collect()
}

/// The entry of [`Instance`]'s input table for a reference that names no input.
const NO_INPUT: u32 = u32::MAX;

/// The input table of an FMU of `kind` with `count` wheels: by value reference, the
/// input slot in `wheels` ([`Wheels::input_slot`]) of each x and y, [`NO_INPUT`]
/// elsewhere.
fn input_slots(kind: Kind, count: u32, wheels: &Wheels) -> Box<[u32]> {
    let slot = |vr| {
        let (wheel, q) = variables::wheel_of(kind, count, vr)?;
        u32::try_from(wheels.input_slot(wheel as usize - 1, q)?).ok()
    };
    (0..variables::wheel_vr(count + 1, Quantity::X)).map(|vr| slot(vr).unwrap_or(NO_INPUT)).collect()
}

/// Stores `values` into the wheels' input slots `inputs` gives their references `vrs`,
/// up to the first reference of no input; answers how many it stored. A loop of its own:
/// its arguments do not overlap, so the tables' places are read once.
#[inline(always)]
fn store_inputs(inputs: &[u32], wheels: &mut Wheels, vrs: &[u32], values: &[f64]) -> usize {
    for (k, (&vr, &value)) in vrs.iter().zip(values).enumerate() {
        let slot = inputs.get(vr as usize).map_or(NO_INPUT, |&slot| slot);
        if !wheels.set_slot(slot as usize, value) {
            return k;
        }
    }
    vrs.len()
}

/// A parameter's value.
#[derive(Debug, Clone, PartialEq)]
struct Parameters {
    friction_default: f64,
    compat: String,
    /// A CRG file's options, in `Parameter::all` order.
    options: Vec<(u32, Value)>,
}

/// One instance.
pub struct Instance {
    fmu: Fmu,
    kind: Kind,
    wheel_count: u32,
    /// By value reference: the wheel (0-based) and quantity of each Real wheel variable.
    reals: Slots,
    /// By value reference: the slot of each input (x, y) among the wheels'
    /// ([`Wheels::input_slot`]); [`NO_INPUT`] for the references of no input.
    inputs: Box<[u32]>,
    wheels: Wheels,
    interface: Interface,
    fmi: Fmi,
    /// Where in the state machine.
    pub state: State,
    time: f64,
    starts: Parameters,
    parameters: Parameters,
    logger: Logger,
    /// Whether debug messages are wanted (errors are always said).
    pub logging_on: bool,
    /// What the last string get handed out (valid until the next call).
    strings: Vec<CString>,
}

impl Instance {
    /// Loads the road the resources in `resources` hold; refused: a token that is not
    /// theirs, a road that cannot be loaded (the file and the reason named).
    pub fn new(
        token: &str,
        resources: &Path,
        interface: Interface,
        fmi: Fmi,
        logger: Logger,
    ) -> Result<Instance, String> {
        let fmu = Fmu::load(resources).map_err(|e| e.to_string())?;
        if token != fmu.config.token {
            return Err(format!(
                "the model description's token {token} is not that of the resources in {} ({})",
                resources.display(),
                fmu.config.token
            ));
        }
        let kind = fmu.config.kind;
        let starts = Parameters {
            friction_default: variables::FRICTION_DEFAULT,
            compat: variables::COMPAT_DEFAULT.into(),
            options: Parameter::all(kind)
                .into_iter()
                .filter_map(|p| match (p, fmu.terrain.parameter_start(p)) {
                    (Parameter::Option(id), Start::Integer(i)) => Some((id, Value::Int(i))),
                    (Parameter::Option(id), Start::Real(d)) => Some((id, Value::Double(d))),
                    _ => None,
                })
                .collect(),
        };
        let wheels = fmu.wheels(&[]).map_err(|e| e.to_string())?;
        let wheel_count = fmu.config.wheels;
        let reals = slots(kind, wheel_count, |q| q.ty() == Type::Real);
        let inputs = input_slots(kind, wheel_count, &wheels);
        Ok(Instance {
            fmu,
            kind,
            wheel_count,
            reals,
            inputs,
            wheels,
            interface,
            fmi,
            state: State::Instantiated,
            time: 0.0,
            parameters: starts.clone(),
            starts,
            logger,
            logging_on: false,
            strings: Vec::new(),
        })
    }

    /// Where its messages go.
    pub fn logger(&self) -> &Logger {
        &self.logger
    }

    /// Model exchange or co-simulation.
    pub fn interface(&self) -> Interface {
        self.interface
    }

    /// Refuses `call` in a state that does not allow it; `subject` names the variable a
    /// get or set is of.
    pub fn expect(&self, call: Call, subject: Option<&str>) -> Result<(), Refused> {
        match call.refusal(self.state, subject) {
            None => Ok(()),
            Some(why) => Err(error(why)),
        }
    }

    /// Why the road the FMU names outside itself cannot be read, if it cannot.
    pub fn road_missing(&self) -> Option<&str> {
        self.fmu.missing()
    }

    /// The variable's name, for messages.
    fn name_of(&self, vr: u32) -> String {
        if let Some((wheel, q)) = variables::wheel_of(self.kind, self.wheel_count, vr) {
            return format!("wheel[{wheel}].{}", q.name());
        }
        match Parameter::from_vr(self.kind, vr) {
            Some(p) => p.name(),
            None if vr == variables::TIME => "time".into(),
            None => format!("value reference {vr}"),
        }
    }

    fn not_a(&self, vr: u32, ty: &str) -> Refused {
        let what = self.name_of(vr);
        if what.starts_with("value reference") {
            error(format!("{what} is no variable of this FMU"))
        } else {
            error(format!("{what} (value reference {vr}) is not a {ty} variable"))
        }
    }

    /// The time (FMI 2's setup or FMI 3's initialization sets it, steps advance it).
    pub fn set_time(&mut self, time: f64) {
        self.time = time;
    }

    /// The current time.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Real variables into `out`: a wheel's input or output (computed where the wheel
    /// moved since), the time, a real parameter. The hot path decodes each reference
    /// by a table and reads the wheel's answer; anything else goes the cold way.
    #[inline(always)]
    pub fn reals(&mut self, vrs: &[u32], out: &mut [f64]) -> Result<(), Refused> {
        let mut read = 0;
        if Call::Get.allowed_in(self.state) {
            let friction = self.parameters.friction_default;
            let reals = &self.reals;
            read = self.wheels.read_reals(vrs, out, friction, |vr| slot_of(reals, vr));
            if read == vrs.len() {
                return Ok(());
            }
        }
        self.reals_otherwise(&vrs[read..], &mut out[read..])
    }

    /// [`Instance::reals`] from the first variable that is no wheel's Real, or in a state
    /// that allows no get.
    #[cold]
    #[inline(never)]
    fn reals_otherwise(&mut self, vrs: &[u32], out: &mut [f64]) -> Result<(), Refused> {
        for (&vr, value) in vrs.iter().zip(out) {
            *value = self.real_otherwise(vr)?;
        }
        Ok(())
    }

    /// [`Instance::reals`] off the hot path: parameters, the time, refusals.
    #[cold]
    #[inline(never)]
    fn real_otherwise(&mut self, vr: u32) -> Result<f64, Refused> {
        self.expect(Call::Get, Some(&self.name_of(vr)))?;
        if let Some((i, q)) = slot_of(&self.reals, vr) {
            return Ok(self.wheels.real(i, q, self.parameters.friction_default));
        }
        match Parameter::from_vr(self.kind, vr) {
            Some(Parameter::FrictionDefault) => Ok(self.parameters.friction_default),
            Some(Parameter::Option(id)) => match self.option(id) {
                Value::Double(d) => Ok(d),
                Value::Int(_) => Err(self.not_a(vr, "Real")),
            },
            _ if vr == variables::TIME && self.time_is_variable() => Ok(self.time),
            _ => Err(self.not_a(vr, "Real")),
        }
    }

    /// Sets Real variables: the wheels' x and y, the friction default, real options.
    /// The hot path stores each input in its place by a table; anything else goes the
    /// cold way.
    #[inline(always)]
    pub fn set_reals(&mut self, vrs: &[u32], values: &[f64]) -> Result<(), Refused> {
        let mut stored = 0;
        if Call::SetInput.allowed_in(self.state) {
            stored = store_inputs(&self.inputs, &mut self.wheels, vrs, values);
            if stored == vrs.len() {
                return Ok(());
            }
        }
        self.set_reals_otherwise(&vrs[stored..], &values[stored..])
    }

    /// [`Instance::set_reals`] from the first variable that is no wheel's input, or in a
    /// state that allows no input to be set.
    #[cold]
    #[inline(never)]
    fn set_reals_otherwise(&mut self, vrs: &[u32], values: &[f64]) -> Result<(), Refused> {
        let settable = Call::SetInput.allowed_in(self.state);
        for (&vr, &value) in vrs.iter().zip(values) {
            match self.wheel_input(vr) {
                Some((i, q)) if settable => self.wheels.set(i, q, value),
                _ => self.set_real_otherwise(vr, value)?,
            }
        }
        Ok(())
    }

    /// The wheel (0-based) and quantity of an input (x or y) `vr` names, if it does.
    fn wheel_input(&self, vr: u32) -> Option<(usize, Quantity)> {
        let (wheel, q) = variables::wheel_of(self.kind, self.wheel_count, vr).filter(|&(_, q)| q.is_input())?;
        Some((wheel as usize - 1, q))
    }

    /// [`Instance::set_reals`] off the hot path: parameters, refusals.
    #[cold]
    #[inline(never)]
    fn set_real_otherwise(&mut self, vr: u32, value: f64) -> Result<(), Refused> {
        if let Some((_, q)) = variables::wheel_of(self.kind, self.wheel_count, vr) {
            if q.is_input() {
                return self.expect(Call::SetInput, Some(&self.name_of(vr)));
            }
            return Err(error(format!("{} is an output: it cannot be set", self.name_of(vr))));
        }
        match Parameter::from_vr(self.kind, vr) {
            Some(p @ Parameter::FrictionDefault) => {
                self.expect(Call::SetTunable, Some(&p.name()))?;
                if !value.is_finite() {
                    return Err(error(format!("{} = {value}: a finite number is needed", p.name())));
                }
                self.parameters.friction_default = value;
                Ok(())
            }
            Some(p @ Parameter::Option(id)) if p.ty() == Type::Real => {
                self.expect(Call::SetFixed, Some(&p.name()))?;
                self.set_option(id, Value::Double(value))
            }
            _ => Err(self.not_a(vr, "Real")),
        }
    }

    /// An Integer variable.
    #[inline]
    pub fn integer(&mut self, vr: u32) -> Result<i32, Refused> {
        self.expect(Call::Get, Some(&self.name_of(vr)))?;
        if let Some((wheel, q)) = variables::wheel_of(self.kind, self.wheel_count, vr) {
            let i = wheel as usize - 1;
            match q {
                // Model exchange's continuous-time mode: as of the last event.
                Quantity::Road if self.state == State::ContinuousTime => return Ok(self.wheels.latched(i).1),
                Quantity::Lane if self.state == State::ContinuousTime => return Ok(self.wheels.latched(i).2),
                _ if matches!(q.ty(), Type::Integer | Type::Enumeration) => return Ok(self.wheels.integer(i, q)),
                _ => {}
            }
            return Err(self.not_a(vr, "Integer"));
        }
        match Parameter::from_vr(self.kind, vr) {
            Some(Parameter::Option(id)) => match self.option(id) {
                Value::Int(i) => Ok(i),
                Value::Double(_) => Err(self.not_a(vr, "Integer")),
            },
            _ => Err(self.not_a(vr, "Integer")),
        }
    }

    /// An integer variable of FMI 3's type for `ty` (Int32 for an Integer, Int64 for an
    /// Enumeration); refused for a variable of another type.
    pub fn integer_of(&mut self, vr: u32, ty: Type) -> Result<i32, Refused> {
        let is = match variables::wheel_of(self.kind, self.wheel_count, vr) {
            Some((_, q)) => q.ty(),
            None => Parameter::from_vr(self.kind, vr).map_or(Type::Real, |p| p.ty()),
        };
        if is != ty {
            return Err(self.not_a(vr, if ty == Type::Integer { "Int32" } else { "Int64 (Enumeration)" }));
        }
        self.integer(vr)
    }

    /// Sets an Integer variable.
    pub fn set_integer(&mut self, vr: u32, value: i32) -> Result<(), Refused> {
        match Parameter::from_vr(self.kind, vr) {
            Some(p @ Parameter::Option(id)) if p.ty() == Type::Integer => {
                self.expect(Call::SetFixed, Some(&p.name()))?;
                self.set_option(id, Value::Int(value))
            }
            _ => Err(self.not_a(vr, "settable Integer")),
        }
    }

    /// A Boolean variable.
    #[inline]
    pub fn boolean(&mut self, vr: u32) -> Result<bool, Refused> {
        self.expect(Call::Get, Some(&self.name_of(vr)))?;
        match variables::wheel_of(self.kind, self.wheel_count, vr) {
            // Model exchange's continuous-time mode: as of the last event.
            Some((wheel, Quantity::OnRoad)) if self.state == State::ContinuousTime => {
                Ok(self.wheels.latched(wheel as usize - 1).0)
            }
            Some((wheel, Quantity::OnRoad)) => Ok(self.wheels.on_road(wheel as usize - 1)),
            _ => Err(self.not_a(vr, "Boolean")),
        }
    }

    /// Sets a Boolean variable: there is none to set.
    pub fn set_boolean(&mut self, vr: u32) -> Result<(), Refused> {
        Err(self.not_a(vr, "settable Boolean"))
    }

    /// String variables, handed out as C strings valid until the next call.
    pub fn strings(&mut self, vrs: &[u32]) -> Result<&[CString], Refused> {
        self.strings.clear();
        for &vr in vrs {
            self.expect(Call::Get, Some(&self.name_of(vr)))?;
            match Parameter::from_vr(self.kind, vr) {
                Some(Parameter::Compat) => self.strings.push(crate::log::c_text(&self.parameters.compat)),
                Some(Parameter::RoadFile) => self.strings.push(crate::log::c_text(self.fmu.road_file())),
                _ => return Err(self.not_a(vr, "String")),
            }
        }
        Ok(&self.strings)
    }

    /// Sets a String variable.
    pub fn set_string(&mut self, vr: u32, value: &str) -> Result<(), Refused> {
        match Parameter::from_vr(self.kind, vr) {
            Some(p @ Parameter::Compat) => {
                self.expect(Call::SetFixed, Some(&p.name()))?;
                let compat = compat_named(value).map_err(error)?;
                let mut fmu_compat = self.parameters.clone();
                fmu_compat.compat = value.trim().to_string();
                self.fmu.set_compat(compat).map_err(error)?;
                self.parameters = fmu_compat;
                self.rebuild()
            }
            Some(p @ Parameter::RoadFile) => {
                self.expect(Call::SetFixed, Some(&p.name()))?;
                self.fmu.set_road_file(value).map_err(error)?;
                self.take_road_starts();
                self.rebuild()
            }
            _ => Err(self.not_a(vr, "String")),
        }
    }

    /// Whether the time is a variable (FMI 3's; FMI 2 lists none, and its value
    /// reference 0 is unknown there).
    fn time_is_variable(&self) -> bool {
        self.fmi == Fmi::V3
    }

    fn option(&self, id: u32) -> Value {
        self.parameters.options.iter().find(|o| o.0 == id).map_or(Value::Int(0), |o| o.1)
    }

    /// Sets an option's value and makes the wheels anew; the value refused (and the
    /// old one kept) where the C API refuses it.
    fn set_option(&mut self, id: u32, value: Value) -> Result<(), Refused> {
        let old = self.parameters.clone();
        if let Some(slot) = self.parameters.options.iter_mut().find(|o| o.0 == id) {
            slot.1 = value;
        }
        self.rebuild().inspect_err(|_| self.parameters = old)
    }

    /// The wheels anew with the options that differ from their start values, where
    /// they were.
    fn rebuild(&mut self) -> Result<(), Refused> {
        let changed: Vec<(u32, Value)> =
            self.parameters.options.iter().copied().filter(|o| !self.starts.options.contains(o)).collect();
        let mut wheels = self.fmu.wheels(&changed).map_err(error)?;
        for i in 0..wheels.len() {
            for q in [Quantity::X, Quantity::Y] {
                wheels.set(i, q, self.wheels.real(i, q, 0.0));
            }
        }
        self.wheels = wheels;
        Ok(())
    }

    /// The options' start values anew from the road now read (its file's options), each
    /// option set since kept.
    fn take_road_starts(&mut self) {
        for (k, start) in self.starts.options.iter_mut().enumerate() {
            let now = match self.fmu.terrain.parameter_start(Parameter::Option(start.0)) {
                Start::Integer(i) => Value::Int(i),
                Start::Real(d) => Value::Double(d),
                _ => continue,
            };
            if let Some(set) = self.parameters.options.get_mut(k).filter(|o| o.1 == start.1) {
                set.1 = now;
            }
            start.1 = now;
        }
    }

    /// Back to the state after instantiation: start values, time 0.
    pub fn reset(&mut self) -> Result<(), Refused> {
        if self.parameters.compat != self.starts.compat {
            let compat = compat_named(&self.starts.compat).map_err(error)?;
            self.fmu.set_compat(compat).map_err(error)?;
        }
        let start = self.fmu.road_file_start();
        if self.fmu.road_file() != start {
            self.fmu.set_road_file(&start).map_err(error)?;
            self.take_road_starts();
        }
        self.parameters = self.starts.clone();
        self.wheels = self.fmu.wheels(&[]).map_err(error)?;
        self.time = 0.0;
        self.state = State::Instantiated;
        Ok(())
    }

    /// Model exchange: the wheels' discrete outputs (on the road, road, lane) as they are
    /// now become those the continuous-time mode answers, until the next event.
    pub fn latch_discrete(&mut self) {
        self.wheels.latch();
    }

    /// How many event indicators: one per wheel.
    pub fn event_indicator_count(&self) -> usize {
        self.wheels.len()
    }

    /// Model exchange: each wheel's event indicator into `out` (one per wheel).
    pub fn indicators(&mut self, out: &mut [f64]) -> Result<(), Refused> {
        if out.len() != self.wheels.len() {
            return Err(error(format!("{} event indicators asked for: this FMU has {}", out.len(), self.wheels.len())));
        }
        for (i, value) in out.iter_mut().enumerate() {
            *value = self.wheels.real(i, Quantity::EventIndicator, 0.0);
        }
        Ok(())
    }

    /// Which variables output `vr` depends on (FMI 3): its wheel's x and y.
    pub fn dependencies(&self, vr: u32) -> Result<Vec<u32>, Refused> {
        match variables::wheel_of(self.kind, self.wheel_count, vr) {
            Some((wheel, q)) if !q.is_input() => {
                Ok(vec![variables::wheel_vr(wheel, Quantity::X), variables::wheel_vr(wheel, Quantity::Y)])
            }
            Some(_) => Ok(Vec::new()),
            None => match Parameter::from_vr(self.kind, vr) {
                Some(_) => Ok(Vec::new()),
                None if vr == variables::TIME && self.time_is_variable() => Ok(Vec::new()),
                None => Err(self.not_a(vr, "known")),
            },
        }
    }
}
