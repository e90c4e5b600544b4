//! FMI's state machine, the same in FMI 2 and FMI 3: where an instance is, and the one
//! table of which call is allowed in which state. The two versions' functions name these
//! calls (`lifecycle` moves an instance on); neither spells a state rule of its own.

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

    /// Why the call is refused in `state`, if it is; `subject` names the variable a get
    /// or set is of.
    pub fn refusal(self, state: State, subject: Option<&str>) -> Option<String> {
        if self.allowed_in(state) {
            return None;
        }
        let what = match subject {
            Some(name) => format!("{} {name}", self.what()),
            None => self.what().to_string(),
        };
        Some(format!("{what} is not allowed in the state {state:?}"))
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
