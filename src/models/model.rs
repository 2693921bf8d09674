//! The one trait every generated model implements, and how a model becomes an ODE system.
//!
//! A model knows its state layout, its inputs, its right-hand side and its kinetic energy (and,
//! in the weight's field, its potential energy).
//! What acts on it is said separately, by [`Loads`]: constant inputs ([`Constant`]) or a
//! closure of time and state. [`Model::driven_by`] pairs the two into a [`Driven`] system,
//! which is an [`OdeSystem`] every integrator of [`crate::integrate`] accepts, so no adapter
//! is written by hand.

use crate::integrate::{IntegrateError, OdeSystem};
use nalgebra::{RealField, SVector};
use simba::simd::SimdRealField;

/// A generated model with `N` state entries and `M` inputs, over the scalar `T`.
///
/// ```
/// use eom::InertiaTensor;
/// use eom::integrate::{AdaptiveOptions, Dop853, Integrator};
/// use eom::models::{Constant, Model, SpatialPrincipalQuaternion};
/// use nalgebra::SVector;
///
/// let inertia = InertiaTensor::new(2.0, 3.0, 4.5, 0.0, 0.0, 0.0).unwrap();
/// let body = SpatialPrincipalQuaternion::<f64>::new(1.0, &inertia).unwrap();
/// let mut state = [0.0; 13];
/// state[3..6].copy_from_slice(&[0.001, 6.0, 0.002]); // spinning about the middle axis
/// state[9] = 1.0; // the identity attitude
/// let start = SVector::from(state);
/// let free = body.driven_by(Constant::zero());
/// let mut method = Dop853::new(AdaptiveOptions::dop853(1e-10, 1e-10));
/// let end = method.integrate(&free, 0.0, start, 1.0).unwrap();
/// // Torque-free: the kinetic energy (4.32) is kept to the tolerance.
/// let energy = |y: &SVector<f64, 13>| body.kinetic_energy(&y.data.0[0]);
/// assert!((energy(&end) - energy(&start)).abs() < 1e-8 * energy(&start));
/// ```
pub trait Model<T: SimdRealField + Copy, const N: usize, const M: usize> {
    /// The generated module's name: `spatial_principal_quaternion`.
    const NAME: &'static str;
    /// What each state entry is, as the model names it.
    const STATE: [&'static str; N];
    /// What each input is.
    const INPUTS: [&'static str; M];

    /// The time derivative of `state` under the inputs `input`.
    fn rhs(&self, state: &[T; N], input: &[T; M]) -> [T; N];

    /// The kinetic energy of `state` (4.32), emitted from the proved form.
    fn kinetic_energy(&self, state: &[T; N]) -> T;

    /// Where ∂f/∂x has entries that do not vanish identically, as (row, column): row `i` is
    /// the rate of `STATE[i]`, column `j` the state entry `STATE[j]`.
    const STATE_JACOBIAN: &'static [(usize, usize)];
    /// Where ∂f/∂u has entries that do not vanish identically, as (row, column), the column
    /// indexing `INPUTS`.
    const INPUT_JACOBIAN: &'static [(usize, usize)];

    /// ∂f/∂x at `state` under `input`, row `i` the derivative of the rate of `STATE[i]`: the
    /// emitted Jacobian, proved equal to the exact derivative of the proved equations when
    /// it was generated, with the entries outside [`Model::STATE_JACOBIAN`] zero.
    fn state_jacobian(&self, state: &[T; N], input: &[T; M]) -> [[T; N]; N];

    /// ∂f/∂u at `state` under `input`, likewise ([`Model::INPUT_JACOBIAN`]).
    fn input_jacobian(&self, state: &[T; N], input: &[T; M]) -> [[T; M]; N];

    /// The potential energy of `state` in the weight's field, emitted from the proved form,
    /// for the models that have one: the pendulum (−Mgh cos θ, 4.35) and the top
    /// (Mgh cos of the tilt); both are Mg times the height of G above the pivot. `None` for the
    /// others, which move under their inputs alone.
    fn potential_energy(&self, state: &[T; N]) -> Option<T> {
        let _ = state;
        None
    }

    /// The model under `loads`, as an [`OdeSystem`] for the integrators.
    fn driven_by<L: Loads<T, N, M>>(&self, loads: L) -> Driven<'_, Self, L, M>
    where
        Self: Sized,
    {
        Driven { model: self, loads }
    }
}

/// What acts on a model: its inputs at a time and state.
///
/// Implemented by [`Constant`] and by every closure `Fn(T, &[T; N]) -> [T; M]`.
pub trait Loads<T, const N: usize, const M: usize> {
    /// The inputs at time `t` and state `state`.
    fn at(&self, t: T, state: &[T; N]) -> [T; M];
}

/// Inputs that do not change.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Constant<T, const M: usize>(pub [T; M]);

impl<T: SimdRealField + Copy, const M: usize> Constant<T, M> {
    /// No load at all: a free body, a pendulum without an applied moment.
    pub fn zero() -> Self {
        Self([T::zero(); M])
    }
}

impl<T: Copy, const N: usize, const M: usize> Loads<T, N, M> for Constant<T, M> {
    fn at(&self, _t: T, _state: &[T; N]) -> [T; M] {
        self.0
    }
}

impl<T, const N: usize, const M: usize, F> Loads<T, N, M> for F
where
    F: Fn(T, &[T; N]) -> [T; M],
{
    fn at(&self, t: T, state: &[T; N]) -> [T; M] {
        self(t, state)
    }
}

/// A model under its loads: the [`OdeSystem`] an integrator advances.
#[derive(Debug, Clone, Copy)]
pub struct Driven<'a, Mo, L, const M: usize> {
    model: &'a Mo,
    loads: L,
}

impl<Mo, L, const M: usize> Driven<'_, Mo, L, M> {
    /// The model.
    pub fn model(&self) -> &Mo {
        self.model
    }

    /// The loads.
    pub fn loads(&self) -> &L {
        &self.loads
    }
}

impl<T, const N: usize, const M: usize, Mo, L> OdeSystem<T, N> for Driven<'_, Mo, L, M>
where
    T: RealField + Copy,
    Mo: Model<T, N, M>,
    L: Loads<T, N, M>,
{
    /// Always inlined into the integrator's stages: left to the compiler, a model's `rhs` was
    /// called, its state and rates passed through memory, and a free body's 10⁶-step RK4 scene
    /// run took 1.40–1.42 of the bare calls' time instead of 0.95 (`cargo bench --bench driver`).
    #[inline(always)]
    fn rhs(&self, t: T, y: &SVector<T, N>, dy: &mut SVector<T, N>) {
        let state = &y.data.0[0];
        let input = self.loads.at(t, state);
        dy.data.0[0] = self.model.rhs(state, &input);
    }

    /// Names the first load input that is NaN or infinite at `(t, y)`. `rhs` checks nothing,
    /// so a run pays for this only when a step has failed and is replayed.
    fn explain_non_finite(&self, t: T, y: &SVector<T, N>) -> Option<IntegrateError> {
        let input = self.loads.at(t, &y.data.0[0]);
        let index = input.iter().position(|v| !v.is_finite())?;
        Some(IntegrateError::NonFiniteInput {
            index,
            name: Mo::INPUTS[index],
            value: input[index].to_subset().unwrap_or(f64::NAN),
            t: t.to_subset().unwrap_or(f64::NAN),
        })
    }
}
