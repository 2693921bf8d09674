//! The tennis racket through the spatial 6-DOF models: the generated right-hand sides of
//! `eom::models` beside the generic nalgebra form `eom::generic::RigidBody`, so that the table
//! shows what the generator buys at equal accuracy.
//!
//! Layout. Each spatial model integrates its own whole state, `[u, v, w, p, q, r, x, y, z,
//! q0, q1, q2, q3]` (or `…, φ, θ, ψ`), through [`eom::models::Model::driven_by`] with no
//! loads, as a user runs it; the generic form integrates the same state through a closure.
//! The body starts at rest in translation (u = v = w = 0, x = y = z = 0), which no force
//! changes, and the end state is judged on its rotational part. So every spatial row pays the
//! model's full 6-DOF evaluation, translation included; and because their adaptive error
//! norms run over the same 13 (12) components, of which the translational six stay zero,
//! every spatial variant takes the same steps for the same tolerance (up to round-off). Those
//! zeros enter the root mean square of the error norm, so at one tolerance the spatial rows
//! take somewhat larger steps than the hand-written rows in the 7-state layout; compare them
//! with each other at equal tolerance, and with the hand-written rows at equal error.
//!
//! Full against pruned. The fair comparison is the same physical body: the racket in its
//! principal axes with the pruned model (`SpatialPrincipalQuaternion`, products known to be
//! zero), against the same racket described in body axes turned by a fixed rotation C, where
//! its tensor C^T diag(I₁, I₂, I₃) C has every product non-zero and needs the full model
//! (`SpatialFullQuaternion`). The state in turned axes is ω' = C^T ω, q' = q ⊗ c; the end state
//! is turned back before judging, so both are judged against the same exact solution. A full
//! model fed the principal tensor (products zero) is also run: same motion, cost only.

use eom::InertiaTensor;
use eom::generic::RigidBody;
use eom::reference::{ReferenceProblem, TennisRacket};
use nalgebra::{Matrix3, Quaternion, RealField, SVector, UnitQuaternion, Vector3};

/// The mass of the racket: it only enters the translation, which stays at rest.
pub const MASS: f64 = 1.0;

/// A spatial Euler-angle state `[u, v, w, p, q, r, x, y, z, φ, θ, ψ]` at rest in translation,
/// from `[p, q, r, φ, θ, ψ]`.
pub fn euler_state(y: &SVector<f64, 6>) -> SVector<f64, 12> {
    let mut state = SVector::<f64, 12>::zeros();
    state
        .fixed_rows_mut::<3>(3)
        .copy_from(&y.fixed_rows::<3>(0));
    state
        .fixed_rows_mut::<3>(9)
        .copy_from(&y.fixed_rows::<3>(3));
    state
}

/// `[p, q, r, φ, θ, ψ]` of a spatial Euler-angle state.
pub fn rotation_of_euler(state: &SVector<f64, 12>) -> SVector<f64, 6> {
    let mut y = SVector::<f64, 6>::zeros();
    y.fixed_rows_mut::<3>(0)
        .copy_from(&state.fixed_rows::<3>(3));
    y.fixed_rows_mut::<3>(3)
        .copy_from(&state.fixed_rows::<3>(9));
    y
}

/// The generic quaternion form, free of loads, as a system in the model's own state.
pub fn generic_quaternion<T: RealField + Copy>(
    body: RigidBody<T>,
) -> impl Fn(T, &SVector<T, 13>, &mut SVector<T, 13>) {
    move |_t, y, dy| *dy = body.rhs_quaternion(y, &Vector3::zeros(), &Vector3::zeros())
}

/// The generic Euler-angle form, free of loads, as a system in the model's own state.
pub fn generic_euler<T: RealField + Copy>(
    body: RigidBody<T>,
) -> impl Fn(T, &SVector<T, 12>, &mut SVector<T, 12>) {
    move |_t, y, dy| *dy = body.rhs_euler(y, &Vector3::zeros(), &Vector3::zeros())
}

/// The racket's tensor in its principal axes, diag(I₁, I₂, I₃).
pub fn principal_tensor(racket: &TennisRacket) -> InertiaTensor {
    let m = racket.body().moments;
    InertiaTensor::new(m.x, m.y, m.z, 0.0, 0.0, 0.0).expect("the racket's moments are physical")
}

/// The racket described in body axes turned by a fixed rotation C from its principal axes.
pub struct TurnedAxes {
    turn: UnitQuaternion<f64>,
    tensor: InertiaTensor,
}

impl TurnedAxes {
    /// The turn C of the body axes: a generic rotation, so that every product is non-zero.
    pub fn new(racket: &TennisRacket) -> Self {
        let turn = UnitQuaternion::from_euler_angles(0.4, -0.3, 0.7);
        let c = turn.to_rotation_matrix().into_inner();
        let tensor: Matrix3<f64> =
            c.transpose() * Matrix3::from_diagonal(&racket.body().moments) * c;
        let tensor = InertiaTensor::from_matrix(tensor).expect("a turned physical tensor");
        Self { turn, tensor }
    }

    /// The tensor C^T diag(I₁, I₂, I₃) C in the turned axes (every product non-zero).
    pub fn tensor(&self) -> &InertiaTensor {
        &self.tensor
    }

    /// The state `[ω', q']` in turned axes of a principal-axes state `[ω, q]`.
    pub fn to_turned(&self, y: &SVector<f64, 7>) -> SVector<f64, 7> {
        let w = self.turn.inverse() * Vector3::new(y[0], y[1], y[2]);
        let q = Quaternion::new(y[3], y[4], y[5], y[6]) * self.turn.quaternion();
        SVector::<f64, 7>::from([w.x, w.y, w.z, q.w, q.i, q.j, q.k])
    }

    /// The principal-axes state `[ω, q]` of a turned-axes state `[ω', q']`.
    pub fn to_principal(&self, y: &SVector<f64, 7>) -> SVector<f64, 7> {
        let w = self.turn * Vector3::new(y[0], y[1], y[2]);
        let q = Quaternion::new(y[3], y[4], y[5], y[6]) * self.turn.inverse().quaternion();
        SVector::<f64, 7>::from([w.x, w.y, w.z, q.w, q.i, q.j, q.k])
    }

    /// The turned start state of the racket.
    pub fn initial_state(&self, racket: &TennisRacket) -> SVector<f64, 7> {
        self.to_turned(&racket.initial_state())
    }
}
