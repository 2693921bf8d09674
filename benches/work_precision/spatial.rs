//! The tennis racket through the spatial 6-DOF models: the generated right-hand sides of
//! `eom::models` beside the generic nalgebra form `eom::generic::RigidBody`, so that the table
//! shows what the generator buys at equal accuracy.
//!
//! Layout. Each spatial model is integrated in the reference problem's own layout,
//! `[p, q, r, q0, q1, q2, q3]` (or `[p, q, r, φ, θ, ψ]` for Euler angles): the adapter places
//! the rates and the attitude in the model's 13-state (12-state) vector with the body at rest
//! in translation (u = v = w = 0, x = y = z = 0), no force and no moment, calls the model's
//! whole `rhs`, and takes back the rotational rates. Translation then stays exactly zero, so
//! nothing is lost; and because the integrated state is the reference problem's, the error norm
//! of the adaptive methods sees the same components as for the hand-written forms (zeros in
//! the 13-state would dilute its root mean square and loosen the tolerance). Every variant in
//! the same layout and axes therefore takes the same steps for the same tolerance (up to
//! round-off), and its errors and RHS evaluations compare directly with the hand-written rows;
//! in turned axes the rates have other components, so the steps differ by a few per cent.
//! The time of a run includes the
//! model's full 6-DOF evaluation (translation included, as a user of the model pays it) and
//! the adapter's copies, which are the same for the generated and the generic forms. "Full"
//! is enforced, not assumed: the optimiser inlines the forms into the integrator (the generic
//! one is built of small functions, the generated `rhs` is marked always-inline), and an
//! inlined form whose translation outputs are discarded would have them removed as dead code,
//! the generic position rate (a square root and a division) included. So the zero inputs are
//! hidden from the optimiser and every output is kept (see [`at_rest`]).
//!
//! Full against pruned. The fair comparison is the same physical body: the racket in its
//! principal axes with the pruned model (`SpatialPrincipalQuaternion`, products known to be
//! zero), against the same racket described in body axes turned by a fixed rotation C, where
//! its tensor C^T diag(I₁, I₂, I₃) C has every product non-zero and needs the full model
//! (`SpatialFullQuaternion`). The state in turned axes is ω' = C^T ω, q' = q ⊗ c; the end state
//! is turned back before judging, so both are judged against the same exact solution. A full
//! model fed the principal tensor (products zero) is also run: same motion, cost only.

use std::hint::black_box;

use eom::InertiaTensor;
use eom::generic::RigidBody;
use eom::reference::{ReferenceProblem, TennisRacket};
use nalgebra::{Matrix3, Quaternion, RealField, SVector, UnitQuaternion, Vector3};

/// The mass of the racket: it only enters the translation, which stays at rest.
pub const MASS: f64 = 1.0;

/// The whole right-hand side of a spatial model: the derivative of an `N`-state under a body
/// force and a moment about G, as arrays.
pub trait SpatialRhs<T, const N: usize>: Fn(&[T; N], &[T; 3], &[T; 3]) -> [T; N] {}

impl<T, const N: usize, F: Fn(&[T; N], &[T; 3], &[T; 3]) -> [T; N]> SpatialRhs<T, N> for F {}

/// One call of a spatial model at rest in translation, under no force and no moment, with
/// every output kept, so that every form pays its full 6-DOF evaluation alike: a form the
/// compiler inlines would otherwise drop the translation outputs the layout discards (and fold
/// the known zeros), while a form it calls out of line computes them all. The zero passes
/// through [`black_box`] once per call, and so do the translation outputs, which are only
/// stored: the rotational outputs go on to the integrator without a round trip through memory.
fn at_rest<T: RealField + Copy, const N: usize>(
    rhs: &impl SpatialRhs<T, N>,
    rates: [T; 3],
    attitude: &[T],
) -> [T; N] {
    let z = black_box(T::zero());
    let mut state = [z; N];
    state[3..6].copy_from_slice(&rates);
    state[9..].copy_from_slice(attitude);
    let d = rhs(&state, &[z; 3], &[z; 3]);
    black_box([d[0], d[1], d[2], d[6], d[7], d[8]]);
    d
}

/// A spatial quaternion right-hand side (`[u, v, w, p, q, r, x, y, z, q0, q1, q2, q3]`) seen
/// in the layout `[p, q, r, q0, q1, q2, q3]`, translation at rest (see [`at_rest`]).
pub fn quaternion<T: RealField + Copy>(
    rhs: impl SpatialRhs<T, 13>,
) -> impl Fn(T, &SVector<T, 7>, &mut SVector<T, 7>) {
    move |_t, y, dy| {
        let d = at_rest(&rhs, [y[0], y[1], y[2]], &[y[3], y[4], y[5], y[6]]);
        *dy = SVector::<T, 7>::from([d[3], d[4], d[5], d[9], d[10], d[11], d[12]]);
    }
}

/// A spatial Euler-angle right-hand side (`[u, v, w, p, q, r, x, y, z, φ, θ, ψ]`) seen in the
/// layout `[p, q, r, φ, θ, ψ]`, translation at rest (see [`at_rest`]).
pub fn euler<T: RealField + Copy>(
    rhs: impl SpatialRhs<T, 12>,
) -> impl Fn(T, &SVector<T, 6>, &mut SVector<T, 6>) {
    move |_t, y, dy| {
        let d = at_rest(&rhs, [y[0], y[1], y[2]], &[y[3], y[4], y[5]]);
        *dy = SVector::<T, 6>::from([d[3], d[4], d[5], d[9], d[10], d[11]]);
    }
}

/// The generic quaternion form as a function of arrays.
pub fn generic_quaternion<T: RealField + Copy>(body: RigidBody<T>) -> impl SpatialRhs<T, 13> {
    move |s, f, m| {
        let (f, m) = (Vector3::from(*f), Vector3::from(*m));
        body.rhs_quaternion(&SVector::from(*s), &f, &m).into()
    }
}

/// The generic Euler-angle form as a function of arrays.
pub fn generic_euler<T: RealField + Copy>(body: RigidBody<T>) -> impl SpatialRhs<T, 12> {
    move |s, f, m| {
        let (f, m) = (Vector3::from(*f), Vector3::from(*m));
        body.rhs_euler(&SVector::from(*s), &f, &m).into()
    }
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
