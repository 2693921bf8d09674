//! Linearisation of a catalog scene: the operating point, the reduced state, A and B from
//! the proved Jacobians, the modes and the stability verdict.
//!
//! Why this shape: every catalog model emits ∂f/∂x and ∂f/∂u, proved equal to the exact
//! derivative of its equations ([`Model::state_jacobian`](crate::models::Model)), so A and B
//! are those programs evaluated at a point, not finite differences of `rhs`. What is left to
//! decide here is *which* point and *which* states:
//!
//! - [`plant`]: the model under the scene's loads, f(x) = rhs(x, loads(x) + u). The loads'
//!   own dependence on the state (damping, a weight turned by the attitude) enters A through
//!   ∂f/∂u · ∂loads/∂x; the loads are not emitted, so that factor is a central difference
//!   (~10⁻¹⁰ relative, from rounding, and exactly zero for a body under no loads).
//! - [`reduce`]: the states set aside. A steady motion may have states that grow along it
//!   (the position, the heading of a planar body, the attitude about a spin axis) while no
//!   other state depends on them; they are set aside and the rest, the reduced state, is
//!   linearised, so that A is constant along the motion.
//! - [`trim`]: Newton on the reduced state for the free variables a `[linear]` table names.
//! - [`modes`](mod@modes): eigenvalues and eigenvectors of A, each mode's period, damping, doubling or
//!   halving time, and its dominant states, its eigenvector read in comparable units (angles,
//!   rates by the mode's own time, velocities over the speed, lengths over a length scale).
//! - [`naming`]: each mode's name, by what moves in it.
//! - [`state_space`]: the result as control tools read it (A, B, C, D with the names and units
//!   of x, u and y, the point and what was set aside), for `linear.json` and `linear.mat`.
//! - [`report`]: the text and JSON reports of `eom linear` (report.txt, linear.json), for the
//!   command and the Python binding alike.

pub mod modes;
pub mod naming;
pub mod plant;
pub mod reduce;
pub mod report;
mod scene;
pub mod state_space;
pub mod trim;

pub use modes::{Mode, Naming, Reading, Stability, modes};
pub use plant::{Evaluation, LinearPlant};
pub use reduce::{SetAsideReason, set_aside, set_aside_why};
pub use scene::{LinearSpec, Linearisation, linearise, resolve, resolve_aliased, set_at};
pub use state_space::StateSpace;

use thiserror::Error;

/// Why a scene could not be linearised.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LinearError {
    /// Newton on the reduced state did not bring its rates to zero.
    #[error(
        "the trim did not converge: after {} on {variables}, d{state}/dt is still \
         {residual:.6e} (the largest of the reduced state's rates; tolerance {tolerance:.1e}). \
         The free variables may not be able to hold this point in equilibrium; name others \
         in linear.trim or start closer in linear.at",
        newton_steps(*iterations)
    )]
    NoConvergence {
        /// The steps taken.
        iterations: usize,
        /// The free variables, as the table names them.
        variables: String,
        /// The state entry whose rate is the largest left.
        state: String,
        /// Its rate.
        residual: f64,
        /// The tolerance it had to meet.
        tolerance: f64,
    },
    /// A value on the way was not finite (a state beyond the model's reach, θ at ±90° for
    /// Euler angles).
    #[error("the linear model at this point is not finite: {0}")]
    NotFinite(String),
    /// A name in `[linear]` that is neither a state entry nor an input of the model.
    #[error("`{0}` is neither a state entry nor an input of the model linearised")]
    Unknown(String),
    /// An output `linear.outputs` names that is not in the reduced state at the point.
    #[error(
        "linear.outputs[{index}]: `{name}` {why}; the outputs are entries of the reduced \
         state: {reduced}"
    )]
    Output {
        /// Its place in `linear.outputs`.
        index: usize,
        /// The name, as the table gives it.
        name: String,
        /// Why it is not an output.
        why: String,
        /// The reduced state's entries, which are.
        reduced: String,
    },
}

impl LinearError {
    /// Whether the scene asked for what cannot be (an output set aside), rather than the
    /// linearisation failing at its point.
    pub fn is_scene_error(&self) -> bool {
        matches!(self, LinearError::Output { .. })
    }
}

/// "1 Newton step", "2 Newton steps".
pub fn newton_steps(steps: usize) -> String {
    crate::counted(steps, "Newton step", "Newton steps")
}

/// The tolerance of an equilibrium: a rate below `EQUILIBRIUM_TOLERANCE · (1 + max|x|)`
/// counts as zero. Ten thousand times the round-off of a rate computed from states of that
/// size, far below any motion a scene means.
pub const EQUILIBRIUM_TOLERANCE: f64 = 1e-9;

/// The pitch beyond which Euler angles are not read, rad: 1° from ±90°, where ψ and φ lose
/// their meaning and tan θ in the kinematics grows past 57.
pub const EULER_PITCH_LIMIT: f64 = std::f64::consts::FRAC_PI_2 - std::f64::consts::PI / 180.0;

/// The scale a rate is compared with: one plus the largest state entry.
pub(crate) fn rate_scale(state: &[f64]) -> f64 {
    1.0 + state.iter().fold(0.0f64, |m, v| m.max(v.abs()))
}
