//! Kinetic and potential energy (4.30–4.35): the check that every simulation can carry.
//!
//! Without dissipation `E = T + U` is constant (4.33), and with forces the rate of change of
//! the kinetic energy is their power. A model or an integrator that breaks either has a bug, so
//! these plain formulas are what the tests hold the generated code to.

use crate::InertiaTensor;
use nalgebra::Vector3;

/// The kinetic energy of a rigid body, `T = ½ M v_G² + ½ ωᵀ [I_G] ω` (4.32), from the velocity
/// of G and the angular velocity, both in body axes, and the tensor about G.
///
/// ```
/// use eom::{InertiaTensor, energy::kinetic_energy};
/// use nalgebra::Vector3;
/// let inertia = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.0).unwrap();
/// let t = kinetic_energy(5.0, &Vector3::new(1.0, 0.0, 0.0), &inertia, &Vector3::new(0.0, 0.0, 2.0));
/// assert_eq!(t, 0.5 * 5.0 * 1.0 + 0.5 * 4.0 * 4.0);
/// ```
pub fn kinetic_energy(
    mass: f64,
    velocity_g: &Vector3<f64>,
    inertia: &InertiaTensor,
    omega: &Vector3<f64>,
) -> f64 {
    0.5 * mass * velocity_g.norm_squared() + 0.5 * omega.dot(&(inertia.matrix() * omega))
}

/// The potential energy of gravity, `U = −M g·r_G`, for a gravity vector `g` and G at `r_G`,
/// both in the same (space-fixed) axes; zero at the origin.
///
/// Writing it with the gravity vector leaves the choice of "up" to the caller: with z pointing
/// down, as ships' axes do, `g = (0, 0, g)` and `U = −M g z_G`.
pub fn gravity_potential_energy(mass: f64, gravity: &Vector3<f64>, centre: &Vector3<f64>) -> f64 {
    -mass * gravity.dot(centre)
}

/// The kinetic energy of a compound pendulum, `T = ½ I₀ θ̇²` (4.34).
pub fn pendulum_kinetic_energy(inertia_pivot: f64, rate: f64) -> f64 {
    0.5 * inertia_pivot * rate * rate
}

/// The potential energy of a compound pendulum, `U = M g h (1 − cos θ)` (4.34), zero at rest.
///
/// It is computed as `2 M g h sin²(θ/2)`, the same quantity without the cancellation of
/// `1 − cos θ` at small angles.
pub fn pendulum_potential_energy(mass: f64, gravity: f64, pivot_to_cg: f64, angle: f64) -> f64 {
    let half = (0.5 * angle).sin();
    2.0 * mass * gravity * pivot_to_cg * half * half
}
