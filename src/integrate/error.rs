//! Why an integration stopped: each variant names the culprit (the parameter, the time, the
//! state component), so that a failed run can be diagnosed from its message alone.

use crate::Short;
use thiserror::Error;

/// An integration that could not be carried out or could not be finished.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum IntegrateError {
    /// A step size (`h`, `h_min`, `h_max`, `h0`) is zero, negative, NaN or infinite.
    #[error("step size {name} = {} must be positive and finite", Short(*value))]
    InvalidStep {
        /// The parameter, e.g. `"h"`.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A tolerance is negative, NaN or infinite, or both tolerances are zero.
    #[error(
        "tolerance {name} = {value} must be finite and non-negative, and rtol, atol not both zero"
    )]
    InvalidTolerance {
        /// `"rtol"` or `"atol"`.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// The relative tolerance is below what the precision can meet: below ten rounding units
    /// of the scalar type ([`min_rtol`](crate::integrate::min_rtol)), where the error estimate
    /// is rounding noise and the method would take ever more steps for no accuracy.
    #[error(
        "tolerance rtol = {rtol:e} is below what {precision} can meet: at least {min:e} (ten \
         rounding units), or 0 for a purely absolute tolerance"
    )]
    ToleranceBelowPrecision {
        /// The relative tolerance asked for.
        rtol: f64,
        /// The smallest one this precision accepts.
        min: f64,
        /// The scalar type, e.g. `"f32"`.
        precision: &'static str,
    },
    /// A parameter of the step-size controller (`beta`, `safety`, `fac_min`, `fac_max`) is out
    /// of its range.
    #[error("step-size controller parameter {name} = {} must lie in {range}", Short(*value))]
    InvalidController {
        /// The parameter, e.g. `"safety"`.
        name: &'static str,
        /// Its value.
        value: f64,
        /// The range it must lie in, e.g. `"(0, 1]"`.
        range: &'static str,
    },
    /// The integration interval is not finite or runs backwards.
    #[error("integration interval [{}, {}] must be finite with t_end ≥ t0", Short(*t0), Short(*t_end))]
    InvalidInterval {
        /// The start time.
        t0: f64,
        /// The end time.
        t_end: f64,
    },
    /// The step-size controller asked for a step below the minimum (the problem is stiff,
    /// singular, or the tolerance is below what the precision can deliver).
    #[error("step size {} fell below the minimum {} at t = {}", Short(*h), Short(*h_min), Short(*t))]
    StepSizeTooSmall {
        /// The time reached.
        t: f64,
        /// The step the controller asked for.
        h: f64,
        /// The minimum step allowed.
        h_min: f64,
    },
    /// The maximum number of steps (accepted plus rejected) was reached before `t_end`.
    #[error("maximum number of steps {max_steps} exceeded at t = {}", Short(*t))]
    MaxStepsExceeded {
        /// The time reached.
        t: f64,
        /// The limit.
        max_steps: usize,
    },
    /// A state component became NaN or infinite (the right-hand side produced it).
    #[error("state component {component} is not finite at t = {}", Short(*t))]
    NonFiniteState {
        /// The index of the first non-finite component.
        component: usize,
        /// The time at which it appeared.
        t: f64,
    },
    /// An input the system computes from time and state (a load a [`Loads`](crate::Loads)
    /// closure returns) is NaN or infinite at a finite state: the culprit is the input, not
    /// the state component it would poison next.
    #[error("load input {name} is {value} at t = {}, at a finite state", Short(*t))]
    NonFiniteInput {
        /// The input's index in the model's input layout.
        index: usize,
        /// The input's name in the model's input layout, e.g. `"M_y"`.
        name: &'static str,
        /// Its value (NaN or ±∞).
        value: f64,
        /// The time of the right-hand-side evaluation that received it.
        t: f64,
    },
    /// The model has no rates at a finite state and finite inputs: the state is outside the
    /// model's domain (an MMG ship going astern, say), and the model says why.
    #[error("the model has no rates at t = {}: {reason}", Short(*t))]
    OutsideModel {
        /// Why, in the model's words.
        reason: String,
        /// The time of the right-hand-side evaluation.
        t: f64,
    },
    /// Dense output was asked for a number of times that differs from the room given for it.
    #[error("{times} output times but room for {slots} states")]
    OutputLength {
        /// The number of output times.
        times: usize,
        /// The number of output slots.
        slots: usize,
    },
    /// The run's observer asked it to stop (an output could not be written, or the user
    /// interrupted the run).
    #[error("the run was stopped by its observer at t = {}", Short(*t))]
    Stopped {
        /// The time reached.
        t: f64,
    },
    /// A method was given without a setting it needs: a fixed step, or an adaptive method's
    /// tolerances.
    #[error("the method needs its {what}")]
    MissingSetting {
        /// What is missing.
        what: &'static str,
    },
    /// A method that integrates one kind of system only (the Lie midpoint method: a free
    /// body's rotation) was given another.
    #[error("{method} integrates a free body's rotation alone, not this system")]
    NotApplicable {
        /// The method's name in scene files.
        method: &'static str,
    },
    /// The inertia tensor given to a rotation integrator has no finite inverse.
    #[error("inertia tensor is singular: [I]⁻¹ (for ω = [I]⁻¹H) does not exist")]
    SingularInertia,
    /// The implicit equation of a step did not converge (the step is too large for the
    /// angular velocity: the fixed-point iteration contracts only while h·|ω| is small).
    #[error("implicit step did not converge in {iterations} iterations at t = {}", Short(*t))]
    NotConverged {
        /// The time at the start of the step.
        t: f64,
        /// The iterations spent.
        iterations: usize,
    },
}

impl IntegrateError {
    /// The time the integration reached, for the errors that happen on the way.
    pub fn time(&self) -> Option<f64> {
        match self {
            IntegrateError::StepSizeTooSmall { t, .. }
            | IntegrateError::MaxStepsExceeded { t, .. }
            | IntegrateError::NonFiniteState { t, .. }
            | IntegrateError::NonFiniteInput { t, .. }
            | IntegrateError::OutsideModel { t, .. }
            | IntegrateError::Stopped { t }
            | IntegrateError::NotConverged { t, .. } => Some(*t),
            _ => None,
        }
    }

    /// What went wrong, without the time: for a run's error that says the time itself
    /// ([`IntegrateError::time`]) once.
    pub fn without_time(&self) -> String {
        match self {
            IntegrateError::StepSizeTooSmall { h, h_min, .. } => format!(
                "the step size {} fell below the minimum {}",
                Short(*h),
                Short(*h_min)
            ),
            IntegrateError::MaxStepsExceeded { max_steps, .. } => format!(
                "{max_steps} steps taken (accepted and rejected), the most \
                 `integrator.max_steps` allows, before the end"
            ),
            IntegrateError::NonFiniteState { component, .. } => {
                format!("state component {component} is not finite")
            }
            IntegrateError::NonFiniteInput { name, value, .. } => {
                format!("load input {name} is {value}, at a finite state")
            }
            IntegrateError::OutsideModel { reason, .. } => {
                format!("the model has no rates: {reason}")
            }
            IntegrateError::Stopped { .. } => "the run was stopped by its observer".to_owned(),
            IntegrateError::NotConverged { iterations, .. } => {
                format!("the implicit step did not converge in {iterations} iterations")
            }
            other => other.to_string(),
        }
    }
}
