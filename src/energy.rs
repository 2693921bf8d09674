//! Kinetic and potential energy (4.30–4.35): the check that every simulation can carry.
//!
//! Without dissipation `E = T + U` is constant (4.33), and with forces the rate of change of
//! the kinetic energy is their power. A model or an integrator that breaks either has a bug, so
//! these plain formulas are what the tests hold the generated code to.
//!
//! They are the crate's one runtime definition of each energy: the generic forms, the
//! reference problems and the torque-free bodies call them. (The generated models in
//! [`crate::models`] compute their own, to be emitted by the generator with the rest of the
//! model, and the tests hold those to these.) The kinetic and pendulum energies are generic over
//! the scalar `T: RealField + Copy`, as the generic forms are.

use nalgebra::{Matrix3, RealField, Vector3};

/// The kinetic energy of a rigid body, `T = ½ M v_G² + ½ ωᵀ [I_G] ω` (4.32), from the velocity
/// of G and the angular velocity, both in body axes, and the matrix of the tensor about G
/// ([`InertiaTensor::matrix`](crate::InertiaTensor::matrix)).
///
/// ```
/// use eom::{InertiaTensor, energy::kinetic_energy};
/// use nalgebra::Vector3;
/// let inertia = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.0).unwrap();
/// let (v, omega) = (Vector3::new(1.0, 0.0, 0.0), Vector3::new(0.0, 0.0, 2.0));
/// let t = kinetic_energy(5.0, &v, &inertia.matrix(), &omega);
/// assert_eq!(t, 0.5 * 5.0 * 1.0 + 0.5 * 4.0 * 4.0);
/// ```
pub fn kinetic_energy<T: RealField + Copy>(
    mass: T,
    velocity_g: &Vector3<T>,
    inertia: &Matrix3<T>,
    omega: &Vector3<T>,
) -> T {
    let half: T = nalgebra::convert(0.5);
    half * (mass * velocity_g.norm_squared() + omega.dot(&(inertia * omega)))
}

/// The potential energy of gravity, `U = −M g·r_G`, for a gravity vector `g` and G at `r_G`,
/// both in the same (space-fixed) axes; zero at the origin.
///
/// Writing it with the gravity vector leaves the choice of "up" to the caller: with z pointing
/// down, as ships' axes do, `g = (0, 0, g)` and `U = −M g z_G`.
pub fn gravity_potential_energy(mass: f64, gravity: &Vector3<f64>, centre: &Vector3<f64>) -> f64 {
    -mass * gravity.dot(centre)
}

/// The kinetic energy of a compound pendulum, `T = ½ I₀ θ̇²` (4.34), for the moment of inertia
/// about the pivot `i0` and the rate `θ̇`.
pub fn pendulum_kinetic_energy<T: RealField + Copy>(i0: T, rate: T) -> T {
    let half: T = nalgebra::convert(0.5);
    half * i0 * rate * rate
}

/// The potential energy of a compound pendulum, `U = M g h (1 − cos θ)` (4.34), zero at rest,
/// for the mass, gravity and pivot-to-G distance in the order of
/// [`PendulumParameters::new`](crate::PendulumParameters::new).
///
/// It is computed as `2 M g h sin²(θ/2)`, the same quantity without the cancellation of
/// `1 − cos θ` at small angles.
pub fn pendulum_potential_energy<T: RealField + Copy>(mass: T, g: T, h: T, angle: T) -> T {
    let half_angle: T = nalgebra::convert(0.5);
    let two: T = nalgebra::convert(2.0);
    let sine = (half_angle * angle).sin();
    two * mass * g * h * sine * sine
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mass::Composite;

    #[test]
    fn kinetic_energy_4_32_equals_the_sum_over_particles_4_30() {
        // T = ½ Σ m |v_G + ω × r|² over point masses (r from G) must equal 4.32 with the
        // tensor built from the same points: the cross term vanishes because Σ m r = 0.
        let points = [
            (1.0, Vector3::new(1.0, 2.0, 3.0)),
            (2.0, Vector3::new(-1.0, 0.5, 0.0)),
            (0.5, Vector3::new(0.0, -2.0, 1.0)),
            (3.0, Vector3::new(2.0, 1.0, -1.5)),
        ];
        let mut body = Composite::new();
        for &(m, r) in &points {
            body.add_point(m, r).unwrap();
        }
        let body = body.build().unwrap();
        let g = body.centre_of_gravity();
        let (v_g, omega) = (Vector3::new(0.3, -1.2, 0.7), Vector3::new(0.9, 0.4, -1.1));
        let particles: f64 = points
            .iter()
            .map(|&(m, r)| 0.5 * m * (v_g + omega.cross(&(r - g))).norm_squared())
            .sum();
        let formula = kinetic_energy(body.mass(), &v_g, &body.inertia().matrix(), &omega);
        // Relative 1e-14: two sums of a dozen terms of order ten.
        assert!((formula - particles).abs() < 1e-14 * particles);
    }

    #[test]
    fn gravity_potential_rises_against_gravity() {
        let g = Vector3::new(0.0, 0.0, 9.81); // z down, as in ships' axes
        let low = gravity_potential_energy(2.0, &g, &Vector3::new(0.0, 0.0, 1.0));
        let high = gravity_potential_energy(2.0, &g, &Vector3::new(0.0, 0.0, -1.0));
        assert_eq!(high - low, 2.0 * 9.81 * 2.0);
    }

    #[test]
    fn pendulum_potential_matches_4_34_as_written() {
        for angle in [0.1_f64, 1.0, 2.5, -3.0] {
            let direct = 3.0 * 9.81 * 0.4 * (1.0 - angle.cos());
            let computed = pendulum_potential_energy(3.0, 9.81, 0.4, angle);
            // The direct form loses the ulp of cos θ to cancellation: relative ε / (1 − cos θ),
            // 2e-14 at θ = 0.1; allow four of them.
            let tolerance = 4.0 * f64::EPSILON / (1.0 - angle.cos());
            assert!((computed - direct).abs() < tolerance * direct);
        }
        assert_eq!(pendulum_kinetic_energy(4.0, 0.5), 0.5);
        assert_eq!(pendulum_kinetic_energy(4.0_f32, 0.5), 0.5);
    }
}
