//! FMI's state machine, the same in FMI 2 and FMI 3: where an instance is, the one table
//! of which call is allowed in which state, and the calls that move an instance on. The
//! two versions' functions name these calls; neither spells a state rule of its own.

use crate::instance::{error, Instance, Interface, Refused};

/// Where an instance is in FMI's state machine.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum State {
    /// After instantiation (or reset).
    Instantiated,
    /// Between entering and leaving initialization.
    Initialization,
    /// Model exchange: event mode.
    Event,
    /// Model exchange: continuous-time mode.
    ContinuousTime,
    /// Co-simulation: between steps.
    Step,
    /// After terminate.
    Terminated,
    /// After a panic: only freeing is left.
    Broken,
}

/// A call, by what it does to or asks of the state machine.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Call {
    /// FMI 2's setup of the experiment (its start time).
    SetupExperiment,
    /// Entering initialization mode.
    EnterInitialization,
    /// Leaving initialization mode.
    ExitInitialization,
    /// Model exchange: entering event mode.
    EnterEventMode,
    /// Model exchange: updating the discrete states (the outputs that change at events).
    UpdateDiscreteStates,
    /// Model exchange: entering continuous-time mode.
    EnterContinuousTime,
    /// Model exchange: an integrator step completed.
    CompletedIntegratorStep,
    /// Model exchange: setting the time.
    SetTime,
    /// Model exchange: reading the event indicators.
    GetEventIndicators,
    /// Co-simulation: entering step mode.
    EnterStepMode,
    /// Co-simulation: a step.
    DoStep,
    /// Terminating.
    Terminate,
    /// Resetting to the state after instantiation.
    Reset,
    /// Reading a variable.
    Get,
    /// Setting an input.
    SetInput,
    /// Setting a fixed parameter.
    SetFixed,
    /// Setting a tunable parameter.
    SetTunable,
}

use State::{ContinuousTime, Event, Initialization, Instantiated, Step, Terminated};

/// Each call: the states it is allowed in and what it is, for messages.
const TABLE: [(Call, &[State], &str); 17] = [
    (Call::SetupExperiment, &[Instantiated], "setting up the experiment"),
    (Call::EnterInitialization, &[Instantiated], "entering initialization mode"),
    (Call::ExitInitialization, &[Initialization], "leaving initialization mode"),
    (Call::EnterEventMode, &[Event, ContinuousTime], "entering event mode"),
    (Call::UpdateDiscreteStates, &[Event], "updating discrete states"),
    (Call::EnterContinuousTime, &[Event], "entering continuous-time mode"),
    (Call::CompletedIntegratorStep, &[ContinuousTime], "completing an integrator step"),
    (Call::SetTime, &[Event, ContinuousTime], "setting the time"),
    (Call::GetEventIndicators, &[Initialization, Event, ContinuousTime, Terminated], "reading the event indicators"),
    (Call::EnterStepMode, &[Step], "entering step mode (this FMU has no event mode)"),
    (Call::DoStep, &[Step], "a step"),
    (Call::Terminate, &[Event, ContinuousTime, Step], "terminating"),
    (Call::Reset, &[Instantiated, Initialization, Event, ContinuousTime, Step, Terminated], "resetting"),
    (Call::Get, &[Initialization, Event, ContinuousTime, Step, Terminated], "reading"),
    (Call::SetInput, &[Instantiated, Initialization, Event, ContinuousTime, Step], "setting the input"),
    (Call::SetFixed, &[Instantiated, Initialization], "setting the fixed parameter"),
    (Call::SetTunable, &[Instantiated, Initialization, Event, Step], "setting the tunable parameter"),
];

/// Each call's states as a bit set (bit `state as u8`), from [`TABLE`].
const MASKS: [u8; 17] = {
    let mut masks = [0u8; 17];
    let mut k = 0;
    while k < TABLE.len() {
        let (call, states, _) = TABLE[k];
        let mut s = 0;
        while s < states.len() {
            masks[call as usize] |= 1 << states[s] as u8;
            s += 1;
        }
        k += 1;
    }
    masks
};

impl Call {
    /// Whether the call is allowed in `state`.
    #[inline(always)]
    pub fn allowed_in(self, state: State) -> bool {
        MASKS[self as usize] >> state as u8 & 1 == 1
    }

    /// What the call is, for messages.
    fn what(self) -> &'static str {
        TABLE[self as usize].2
    }
}

impl Instance {
    /// Refuses `call` in a state that does not allow it; `subject` names the variable a
    /// get or set is of.
    pub fn expect(&self, call: Call, subject: Option<&str>) -> Result<(), Refused> {
        if call.allowed_in(self.state) {
            return Ok(());
        }
        let what = match subject {
            Some(name) => format!("{} {name}", call.what()),
            None => call.what().to_string(),
        };
        Err(error(format!("{what} is not allowed in the state {:?}", self.state)))
    }

    /// Makes `call` where it is allowed and moves to `next`.
    fn go(&mut self, call: Call, next: State) -> Result<(), Refused> {
        self.expect(call, None)?;
        self.state = next;
        Ok(())
    }

    /// FMI 2's setup: the start time.
    pub fn setup_experiment(&mut self, start_time: f64) -> Result<(), Refused> {
        self.expect(Call::SetupExperiment, None)?;
        self.set_time(start_time);
        Ok(())
    }

    /// Enters initialization mode: refused while the road the FMU names outside itself
    /// is missing (`roadFile` must name one first); FMI 3 gives the start time here.
    pub fn enter_initialization(&mut self, start_time: Option<f64>) -> Result<(), Refused> {
        self.expect(Call::EnterInitialization, None)?;
        if let Some(why) = self.road_missing() {
            return Err(error(format!("{why}: set the parameter roadFile to the road's CRG file")));
        }
        if let Some(t) = start_time {
            self.set_time(t);
        }
        self.state = State::Initialization;
        Ok(())
    }

    /// Leaves initialization mode: into event mode (model exchange) or step mode
    /// (co-simulation, which has no event mode here).
    pub fn exit_initialization(&mut self) -> Result<(), Refused> {
        let next = match self.interface() {
            Interface::ModelExchange => State::Event,
            Interface::CoSimulation => State::Step,
        };
        self.go(Call::ExitInitialization, next)?;
        self.latch_discrete();
        Ok(())
    }

    /// Model exchange: enters event mode.
    pub fn enter_event_mode(&mut self) -> Result<(), Refused> {
        self.go(Call::EnterEventMode, State::Event)
    }

    /// Model exchange: the discrete outputs (on the road, road, lane) take the wheels'
    /// present values; no further event is asked for.
    pub fn update_discrete_states(&mut self) -> Result<(), Refused> {
        self.expect(Call::UpdateDiscreteStates, None)?;
        self.latch_discrete();
        Ok(())
    }

    /// Model exchange: enters continuous-time mode.
    pub fn enter_continuous_time(&mut self) -> Result<(), Refused> {
        self.go(Call::EnterContinuousTime, State::ContinuousTime)?;
        self.latch_discrete();
        Ok(())
    }

    /// Model exchange: an integrator step done (no step event is asked for).
    pub fn completed_integrator_step(&mut self) -> Result<(), Refused> {
        self.expect(Call::CompletedIntegratorStep, None)
    }

    /// Model exchange: sets the time.
    pub fn set_model_time(&mut self, time: f64) -> Result<(), Refused> {
        self.expect(Call::SetTime, None)?;
        self.set_time(time);
        Ok(())
    }

    /// Model exchange: the event indicators into `out`, one per wheel: 1 while its
    /// on the road, road and lane are those of the last event, -1 once one differs.
    pub fn event_indicators(&mut self, out: &mut [f64]) -> Result<(), Refused> {
        self.expect(Call::GetEventIndicators, None)?;
        self.indicators(out)
    }

    /// Co-simulation: step mode, where an instance is after initialization.
    pub fn enter_step_mode(&mut self) -> Result<(), Refused> {
        self.expect(Call::EnterStepMode, None)
    }

    /// Co-simulation: a step of `step` from `current` (the outputs follow the inputs).
    pub fn do_step(&mut self, current: f64, step: f64) -> Result<(), Refused> {
        self.expect(Call::DoStep, None)?;
        if !(step >= 0.0) {
            return Err(error(format!("communicationStepSize {step}: must not be negative")));
        }
        self.set_time(current + step);
        Ok(())
    }

    /// Ends the simulation.
    pub fn terminate(&mut self) -> Result<(), Refused> {
        self.go(Call::Terminate, State::Terminated)
    }

    /// Back to the state after instantiation, with the start values.
    pub fn reset_all(&mut self) -> Result<(), Refused> {
        self.expect(Call::Reset, None)?;
        self.reset()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_lists_every_call_once_in_order() {
        for (k, (call, states, _)) in TABLE.iter().enumerate() {
            assert_eq!(*call as usize, k, "{call:?}");
            for s in [Instantiated, Initialization, Event, ContinuousTime, Step, Terminated, State::Broken] {
                assert_eq!(call.allowed_in(s), states.contains(&s), "{call:?} in {s:?}");
            }
        }
    }
}
