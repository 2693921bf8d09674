//! Torque-free rotation of a rigid body in three forms of the same equations, for the
//! reference problems and the work–precision comparison.
//!
//! - [`PrincipalBody`]: Euler's equations in principal axes (4.52 with zero moment),
//!   I₁ṗ = (I₂ − I₃)qr and cyclically, with quaternion kinematics q̇ = ½ q ⊗ (0, ω);
//!   state `[p, q, r, q0, q1, q2, q3]` (scalar first). This is the "pruned" model: the products
//!   of inertia are known to vanish and their terms are gone.
//! - [`FullTensorBody`]: the general form 4.50–4.51 written with nalgebra,
//!   ω̇ = \[I\]⁻¹(−ω × \[I\]ω), same state — the "full" model, which keeps every product of inertia.
//! - [`EulerAngleBody`]: 4.52 with the Euler-angle kinematics 4.60, state
//!   `[p, q, r, φ, θ, ψ]`; singular at θ = ±90°.

use nalgebra::{Matrix3, Quaternion, RealField, SVector, Vector3};

use crate::integrate::{OdeSystem, RigidRotation};

/// Converts an `f64` parameter to the scalar type of a run.
fn lit<T: RealField>(x: f64) -> T {
    nalgebra::convert(x)
}

/// The kinetic energy of rotation T = ½ ωᵀ\[I\]ω (4.32) for principal moments: 4.32 of
/// [`crate::energy::kinetic_energy`] with G at rest.
pub fn energy(moments: &Vector3<f64>, omega: &Vector3<f64>) -> f64 {
    let inertia = Matrix3::from_diagonal(moments);
    crate::energy::kinetic_energy(0.0, &Vector3::zeros(), &inertia, omega)
}

/// The magnitude of the angular momentum |H| = |\[I\]ω| (4.15) for principal moments.
pub fn momentum(moments: &Vector3<f64>, omega: &Vector3<f64>) -> f64 {
    moments.component_mul(omega).norm()
}

/// q̇ = ½ q ⊗ (0, ω), the quaternion kinematics, for the scalar-first quaternion `q`.
fn quaternion_rate<T: RealField + Copy>(q: &Quaternion<T>, w: &Vector3<T>) -> Quaternion<T> {
    q * Quaternion::from_imag(*w) * lit::<T>(0.5)
}

/// Writes `[ω̇, q̇]` into `dy` from ω̇ and the state.
fn write_rates<T: RealField + Copy>(y: &SVector<T, 7>, w_dot: Vector3<T>, dy: &mut SVector<T, 7>) {
    let w = Vector3::new(y[0], y[1], y[2]);
    let q_dot = quaternion_rate(&Quaternion::new(y[3], y[4], y[5], y[6]), &w);
    *dy = SVector::<T, 7>::from([
        w_dot.x, w_dot.y, w_dot.z, q_dot.w, q_dot.i, q_dot.j, q_dot.k,
    ]);
}

/// Euler's torque-free equations in principal axes (4.52).
fn euler_equations<T: RealField + Copy>(i: &Vector3<f64>, w: &Vector3<T>) -> Vector3<T> {
    let (i1, i2, i3) = (lit::<T>(i.x), lit::<T>(i.y), lit::<T>(i.z));
    Vector3::new(
        (i2 - i3) * w.y * w.z / i1,
        (i3 - i1) * w.z * w.x / i2,
        (i1 - i2) * w.x * w.y / i3,
    )
}

/// A torque-free body in principal axes (4.52) with quaternion attitude.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrincipalBody {
    /// The principal moments (I₁, I₂, I₃).
    pub moments: Vector3<f64>,
}

impl<T: RealField + Copy> OdeSystem<T, 7> for PrincipalBody {
    fn rhs(&self, _t: T, y: &SVector<T, 7>, dy: &mut SVector<T, 7>) {
        let w = Vector3::new(y[0], y[1], y[2]);
        write_rates(y, euler_equations(&self.moments, &w), dy);
    }
}

impl<T: RealField + Copy> RigidRotation<T> for PrincipalBody {
    fn inertia(&self) -> Matrix3<T> {
        Matrix3::from_diagonal(&self.moments.map(lit::<T>))
    }
}

/// A torque-free body with a full inertia tensor (4.50–4.51), evaluated with nalgebra.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FullTensorBody {
    inertia: Matrix3<f64>,
    inverse: Matrix3<f64>,
}

impl FullTensorBody {
    /// The body with inertia tensor `inertia` (chapter convention, H = \[I\]ω), or `None` if it
    /// has no inverse.
    pub fn new(inertia: Matrix3<f64>) -> Option<Self> {
        Some(Self {
            inertia,
            inverse: inertia.try_inverse()?,
        })
    }
}

impl<T: RealField + Copy> OdeSystem<T, 7> for FullTensorBody {
    fn rhs(&self, _t: T, y: &SVector<T, 7>, dy: &mut SVector<T, 7>) {
        let w = Vector3::new(y[0], y[1], y[2]);
        let h = self.inertia.map(lit::<T>) * w;
        write_rates(y, self.inverse.map(lit::<T>) * (-w.cross(&h)), dy);
    }
}

impl<T: RealField + Copy> RigidRotation<T> for FullTensorBody {
    fn inertia(&self) -> Matrix3<T> {
        self.inertia.map(lit::<T>)
    }
}

/// A torque-free body in principal axes (4.52) with Euler-angle kinematics (4.60).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EulerAngleBody {
    /// The principal moments (I₁, I₂, I₃).
    pub moments: Vector3<f64>,
}

impl<T: RealField + Copy> OdeSystem<T, 6> for EulerAngleBody {
    fn rhs(&self, _t: T, y: &SVector<T, 6>, dy: &mut SVector<T, 6>) {
        let w = Vector3::new(y[0], y[1], y[2]);
        let w_dot = euler_equations(&self.moments, &w);
        let (sin_phi, cos_phi) = y[3].sin_cos();
        let (sin_theta, cos_theta) = y[4].sin_cos();
        let across = w.y * sin_phi + w.z * cos_phi;
        let phi_dot = w.x + across * sin_theta / cos_theta;
        let theta_dot = w.y * cos_phi - w.z * sin_phi;
        let psi_dot = across / cos_theta;
        *dy = SVector::<T, 6>::from([w_dot.x, w_dot.y, w_dot.z, phi_dot, theta_dot, psi_dot]);
    }
}
