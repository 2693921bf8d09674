//! Reference problems: each carries its own right-hand side and its own exact solution,
//! written from the mathematics, so that the integrators are judged against answers that owe
//! nothing to an integrator.
//!
//! - [`LargeSwing`]: the compound pendulum 4.24 released from rest at a large angle, solved by
//!   Jacobi's sn and cn (period 4K(m)/ω₀);
//! - [`AxisymmetricTop`]: torque-free rotation of a symmetric body (4.52 with I₁ = I₂), steady
//!   precession in closed form, attitude included;
//! - [`TennisRacket`]: torque-free rotation near the intermediate axis (the Dzhanibekov flip),
//!   body rates by sn, cn, dn (Landau & Lifshitz, *Mechanics*, §37);
//! - [`PlanarTurn`]: 4.43–4.44 at constant yaw rate under a constant body-fixed force, a linear
//!   system whose velocities and track are known exactly.
//!
//! Each constructor refuses a parameter outside the range where its closed form holds with a
//! [`crate::ParameterError`] naming it.
//!
//! The torque-free bodies come in three forms of the same equations ([`torque_free`]): the
//! principal-axes form 4.52 with quaternion kinematics, the full-tensor form 4.51 with nalgebra,
//! and the principal-axes form with Euler-angle kinematics 4.60.

mod axisymmetric;
mod large_swing;
mod planar_turn;
mod tennis_racket;
pub mod torque_free;

pub use axisymmetric::AxisymmetricTop;
pub use large_swing::LargeSwing;
pub use planar_turn::PlanarTurn;
pub use tennis_racket::TennisRacket;

use nalgebra::{Quaternion, SVector, UnitQuaternion};

/// A problem with a known answer, in the state layout of its own right-hand side.
pub trait ReferenceProblem<const N: usize> {
    /// A short name for tables and plots.
    fn name(&self) -> &'static str;
    /// The state at t = 0 (the exact solution there).
    fn initial_state(&self) -> SVector<f64, N>;
    /// The natural horizon of the problem (one period, two flips, …).
    fn t_end(&self) -> f64;
    /// The error of `y` against the exact solution at `t`, in the measure the problem's
    /// documentation states (dimensionless, so that problems can share one plot).
    fn error(&self, t: f64, y: &SVector<f64, N>) -> f64;
    /// The quantities the exact flow conserves, evaluated at `y` (their drift is reported).
    fn invariants(&self, y: &SVector<f64, N>) -> Vec<f64>;
}

/// The angle (radians) of the rotation between two attitudes, 2 atan2(|δ⃗|, |δ₀|) with
/// δ = a⁻¹ ⊗ b — accurate for small angles, unlike 2 acos(δ₀). `b` is normalised first, so a
/// quaternion that drifted off the unit sphere is judged by the rotation it represents.
pub fn attitude_angle(a: &UnitQuaternion<f64>, b: &Quaternion<f64>) -> f64 {
    let delta = a.quaternion().conjugate() * b.normalize();
    2.0 * delta.vector().norm().atan2(delta.w.abs())
}
