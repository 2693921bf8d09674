//! The model contract: the one trait every emitted model implements, what acts on a model,
//! and the model under its loads.
//!
//! It lives here, beside the `sin_cos` the generated code already calls, because the emitter
//! writes each model's implementation of it into the generated file: a model emitted from a
//! user's own `build.rs` implements it as the catalog's models do, without its crate
//! depending on the whole `eom` library, and `eom` re-exports it at `eom::Model` and
//! `eom::models::{Model, Loads, Constant, Driven}`. What makes a [`Driven`] model an ODE
//! system for `eom`'s integrators (its `OdeSystem` implementation) is `eom`'s, since the
//! integrators are.
//!
//! A model knows its state layout, its inputs, its right-hand side, its kinetic energy (and,
//! in the weight's field, its potential energy) and the Jacobians of its right-hand side.
//! What acts on it is said separately, by [`Loads`]: constant inputs ([`Constant`]) or a
//! closure of time and state. [`Model::driven_by`] pairs the two into a [`Driven`] system.

use simba::simd::SimdRealField;

/// A model with `N` state entries and `M` inputs, over the scalar `T`.
///
/// The emitter implements it for every generated `Coefficients<T>`, delegating to the proved
/// functions of the same file; `eom`'s typed models (which validate their parameters) delegate
/// to those implementations, and `eom`'s generic nalgebra forms implement it too, so every
/// integrator and test takes either through one trait.
///
/// ```
/// use eom_kernel::{Constant, Loads, Model};
///
/// /// A harmonic oscillator, ẍ = −ω²x + u, written by hand.
/// struct Oscillator(f64);
///
/// impl Model<f64, 2, 1> for Oscillator {
///     const NAME: &'static str = "oscillator";
///     const STATE: [&'static str; 2] = ["x", "x_dot"];
///     const INPUTS: [&'static str; 1] = ["u"];
///     const STATE_JACOBIAN: &'static [(usize, usize)] = &[(0, 1), (1, 0)];
///     const INPUT_JACOBIAN: &'static [(usize, usize)] = &[(1, 0)];
///
///     fn rhs(&self, [x, v]: &[f64; 2], [u]: &[f64; 1]) -> [f64; 2] {
///         [*v, -self.0 * self.0 * x + u]
///     }
///     fn kinetic_energy(&self, [_, v]: &[f64; 2]) -> f64 {
///         0.5 * v * v
///     }
///     fn state_jacobian(&self, _: &[f64; 2], _: &[f64; 1]) -> [[f64; 2]; 2] {
///         eom_kernel::scatter(&[(0, 1), (1, 0)], [1.0, -self.0 * self.0])
///     }
///     fn input_jacobian(&self, _: &[f64; 2], _: &[f64; 1]) -> [[f64; 1]; 2] {
///         [[0.0], [1.0]]
///     }
/// }
///
/// let system = Oscillator(2.0).driven_by(Constant([1.0]));
/// let state = [0.5, 0.0];
/// let input = system.loads().at(0.0, &state);
/// assert_eq!(system.model().rhs(&state, &input), [0.0, -1.0]);
/// assert_eq!(Oscillator(2.0).potential_energy(&state), None);
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

    /// The model under `loads`: in `eom`, an `OdeSystem` every integrator accepts.
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

/// A model under its loads: the system an integrator advances ([`Model::driven_by`]).
#[derive(Debug, Clone, Copy)]
pub struct Driven<'a, Mo, L, const M: usize> {
    model: &'a Mo,
    loads: L,
}

impl<Mo, L, const M: usize> Driven<'_, Mo, L, M> {
    /// The model.
    #[inline(always)]
    pub fn model(&self) -> &Mo {
        self.model
    }

    /// The loads.
    #[inline(always)]
    pub fn loads(&self) -> &L {
        &self.loads
    }
}

/// The dense `R × C` matrix of an emitted Jacobian: `entries[i]` at `pattern[i]`, zero
/// elsewhere. Each emitted model's [`Model::state_jacobian`] and [`Model::input_jacobian`]
/// are this of the proved function that returns only the entries that do not vanish.
///
/// ```
/// let dense: [[f64; 2]; 2] = eom_kernel::scatter(&[(0, 1), (1, 0)], [1.0, -4.0]);
/// assert_eq!(dense, [[0.0, 1.0], [-4.0, 0.0]]);
/// ```
#[inline]
pub fn scatter<T: SimdRealField + Copy, const R: usize, const C: usize, const K: usize>(
    pattern: &[(usize, usize); K],
    entries: [T; K],
) -> [[T; C]; R] {
    let mut dense = [[T::zero(); C]; R];
    for (&(row, column), value) in pattern.iter().zip(entries) {
        dense[row][column] = value;
    }
    dense
}
