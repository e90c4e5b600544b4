//! The calls that move an instance through FMI's state machine (`states` says where each
//! is allowed), the same for FMI 2 and FMI 3: initialization, events, steps, the end.

use crate::instance::{error, Instance, Interface, Refused};
use crate::states::{Call, State};

impl Instance {
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
