//! Spatial (6-DOF) motion of a rigid body about G, written with nalgebra: 4.49 for
//! translation, 4.50–4.51 for rotation, and the kinematics of either Euler angles (4.57,
//! 4.60) or a unit quaternion.
//!
//! This form knows nothing about symmetry: it carries the full tensor `[I]` for every body,
//! with its inverse computed once in [`RigidBody::new`]. Per call it does two cross
//! products, two 3×3 matrix–vector products and the attitude kinematics, with no allocation.
//! Whatever a specialised form gains over it (zero products pruned, coefficients such as
//! `I_zz − I_yy` hoisted, trigonometry shared) is the generator's doing.
//!
//! One cost is visible and deliberate: the Euler form takes `E` from nalgebra's
//! `Rotation3::from_euler_angles` (three `sin_cos`) and computes the `sin_cos` of `φ` and `θ`
//! again for 4.60, five in all where a fused hand-expansion of 4.57 would need three. Writing
//! out the expansion is exactly the symbolic work the generator is checked on, so the generic
//! form keeps nalgebra's rotation and stays independent of it.

use super::error::ModelError;
use super::kinematics::{body_to_space, euler_rates, quaternion_rate};
use super::state::{
    ATTITUDE, EulerState, POSITION, QuaternionState, RATES, VELOCITY, attitude_quaternion, rates,
    velocity,
};
use crate::InertiaTensor;
use crate::validate::positive;
use nalgebra::{Matrix3, RealField, UnitQuaternion, Vector3};

/// A rigid body for the spatial equations: mass, inertia tensor about G in body axes
/// (chapter convention, `H = [I] ω`) and its inverse.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidBody<T> {
    mass: T,
    inv_mass: T,
    inertia: Matrix3<T>,
    inverse_inertia: Matrix3<T>,
}

impl<T: RealField + Copy> RigidBody<T> {
    /// Validates the mass and inverts the (already validated) tensor once, in `f64`, before
    /// converting both to `T`.
    ///
    /// ```
    /// use eom::{InertiaTensor, generic::RigidBody};
    /// use nalgebra::Vector3;
    /// let tensor = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.0).unwrap();
    /// let body = RigidBody::<f64>::new(5.0, &tensor).unwrap();
    /// let h = body.angular_momentum(&Vector3::new(1.0, 1.0, 1.0));
    /// assert_eq!(h, Vector3::new(2.0, 3.0, 4.0)); // H = [I] ω (4.15)
    /// assert!(RigidBody::<f64>::new(f64::NAN, &tensor).is_err());
    /// ```
    pub fn new(mass: f64, inertia: &InertiaTensor) -> Result<Self, ModelError> {
        let mass = positive("mass", mass)?;
        let matrix = inertia.matrix();
        // A determinant that overflows gives a "successful" inverse of NaNs; refuse it too.
        let determinant = matrix.determinant();
        let inverse = matrix
            .try_inverse()
            .filter(|_| determinant.is_normal())
            .ok_or(ModelError::SingularInertia { determinant })?;
        Ok(Self {
            mass: nalgebra::convert(mass),
            inv_mass: nalgebra::convert(1.0 / mass),
            inertia: matrix.map(nalgebra::convert),
            inverse_inertia: inverse.map(nalgebra::convert),
        })
    }

    /// Validates a full matrix as an inertia tensor (4.12–4.14, see
    /// [`InertiaTensor::from_matrix`]) and then builds the body as [`new`](Self::new) does;
    /// an impossible tensor gives [`ModelError::Inertia`] naming the failed condition.
    pub fn from_matrix(mass: f64, inertia: Matrix3<f64>) -> Result<Self, ModelError> {
        positive("mass", mass)?;
        Self::new(mass, &InertiaTensor::from_matrix(inertia)?)
    }

    /// The body-fixed rate of the velocity of G, 4.47–4.49: `v̇ = F/M − ω × v`.
    #[inline]
    pub fn translational_acceleration(
        &self,
        velocity: &Vector3<T>,
        omega: &Vector3<T>,
        force: &Vector3<T>,
    ) -> Vector3<T> {
        force * self.inv_mass - omega.cross(velocity)
    }

    /// The body-fixed rate of the body rates, 4.50–4.51: `ω̇ = [I]⁻¹ (M − ω × [I] ω)`, with
    /// `moment` about G.
    #[inline]
    pub fn angular_acceleration(&self, omega: &Vector3<T>, moment: &Vector3<T>) -> Vector3<T> {
        let h = self.inertia * omega;
        self.inverse_inertia * (moment - omega.cross(&h))
    }

    /// The spatial form with Euler angles: the derivative of
    /// `[u, v, w, p, q, r, x, y, z, φ, θ, ψ]` under the body force `force` and the body moment
    /// `moment` about G.
    ///
    /// Accelerations by 4.49 and 4.51, position rate `E (u, v, w)` with
    /// `E = Rz(ψ) Ry(θ) Rx(φ)` (4.57), attitude rates by 4.60. Singular at `θ = ±90°` (see
    /// [`euler_rates`](super::euler_rates)); it never panics, but callers that may approach
    /// the singularity check the pitch with [`check_pitch`](super::check_pitch) or use
    /// [`rhs_quaternion`](Self::rhs_quaternion).
    #[inline]
    pub fn rhs_euler(
        &self,
        state: &EulerState<T>,
        force: &Vector3<T>,
        moment: &Vector3<T>,
    ) -> EulerState<T> {
        let (v, omega) = (velocity(state), rates(state));
        let (phi, theta, psi) = (state[ATTITUDE], state[ATTITUDE + 1], state[ATTITUDE + 2]);
        let mut out = EulerState::zeros();
        out.fixed_rows_mut::<3>(VELOCITY)
            .copy_from(&self.translational_acceleration(&v, &omega, force));
        out.fixed_rows_mut::<3>(RATES)
            .copy_from(&self.angular_acceleration(&omega, moment));
        out.fixed_rows_mut::<3>(POSITION)
            .copy_from(&(body_to_space(phi, theta, psi) * v));
        out.fixed_rows_mut::<3>(ATTITUDE)
            .copy_from(&euler_rates(phi, theta, &omega));
        out
    }

    /// The spatial form with a unit quaternion: the derivative of
    /// `[u, v, w, p, q, r, x, y, z, q0, q1, q2, q3]` (scalar first).
    ///
    /// Accelerations as in [`rhs_euler`](Self::rhs_euler); the position rate is `v` rotated by
    /// the stored quaternion *normalised* (so a quaternion that has drifted off unit length
    /// still rotates without stretching; it must not be zero), and `q̇ = ½ q ⊗ (0, ω)` with
    /// `q` as stored.
    #[inline]
    pub fn rhs_quaternion(
        &self,
        state: &QuaternionState<T>,
        force: &Vector3<T>,
        moment: &Vector3<T>,
    ) -> QuaternionState<T> {
        let (v, omega) = (velocity(state), rates(state));
        let q = attitude_quaternion(state);
        let q_dot = quaternion_rate(&q, &omega);
        let mut out = QuaternionState::zeros();
        out.fixed_rows_mut::<3>(VELOCITY)
            .copy_from(&self.translational_acceleration(&v, &omega, force));
        out.fixed_rows_mut::<3>(RATES)
            .copy_from(&self.angular_acceleration(&omega, moment));
        out.fixed_rows_mut::<3>(POSITION)
            .copy_from(&(UnitQuaternion::new_normalize(q) * v));
        out[ATTITUDE] = q_dot.w;
        out[ATTITUDE + 1] = q_dot.i;
        out[ATTITUDE + 2] = q_dot.j;
        out[ATTITUDE + 3] = q_dot.k;
        out
    }

    /// The angular momentum about G in body axes, `H = [I] ω` (4.15).
    #[inline]
    pub fn angular_momentum(&self, omega: &Vector3<T>) -> Vector3<T> {
        self.inertia * omega
    }

    /// The kinetic energy, 4.32: `T = ½ M v·v + ½ ωᵀ [I] ω` (by [`crate::energy::kinetic_energy`]).
    #[inline]
    pub fn kinetic_energy(&self, velocity: &Vector3<T>, omega: &Vector3<T>) -> T {
        crate::energy::kinetic_energy(self.mass, velocity, &self.inertia, omega)
    }

    /// The mass `M`.
    pub fn mass(&self) -> T {
        self.mass
    }

    /// The inertia tensor `[I]` about G (4.12).
    pub fn inertia(&self) -> Matrix3<T> {
        self.inertia
    }

    /// Its inverse `[I]⁻¹`, computed once.
    pub fn inverse_inertia(&self) -> Matrix3<T> {
        self.inverse_inertia
    }
}

impl RigidBody<f64> {
    /// The same body over another scalar (dual numbers, for its Jacobians).
    pub(super) fn cast<S: RealField + Copy>(&self) -> RigidBody<S> {
        RigidBody {
            mass: nalgebra::convert(self.mass),
            inv_mass: nalgebra::convert(self.inv_mass),
            inertia: self.inertia.map(nalgebra::convert),
            inverse_inertia: self.inverse_inertia.map(nalgebra::convert),
        }
    }
}
