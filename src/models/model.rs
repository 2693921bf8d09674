//! How a model becomes an ODE system: [`Driven`], a model under its loads, is an
//! [`OdeSystem`] every integrator of [`crate::integrate`] accepts, so no adapter is written by
//! hand.
//!
//! The contract itself ([`Model`], [`Loads`], [`Constant`], [`Driven`]) is `eom-kernel`'s,
//! re-exported here: the emitter writes each generated model's implementation of it into the
//! generated file, so a model emitted from a user's own `build.rs` implements it too, without
//! depending on this library. This implementation is eom's because the integrators are.
//!
//! ```
//! use eom::InertiaTensor;
//! use eom::integrate::{AdaptiveOptions, Dop853, Integrator};
//! use eom::models::{Constant, Model, SpatialPrincipalQuaternion};
//! use nalgebra::SVector;
//!
//! let inertia = InertiaTensor::new(2.0, 3.0, 4.5, 0.0, 0.0, 0.0).unwrap();
//! let body = SpatialPrincipalQuaternion::<f64>::new(1.0, &inertia).unwrap();
//! let mut state = [0.0; 13];
//! state[3..6].copy_from_slice(&[0.001, 6.0, 0.002]); // spinning about the middle axis
//! state[9] = 1.0; // the identity attitude
//! let start = SVector::from(state);
//! let free = body.driven_by(Constant::zero());
//! let mut method = Dop853::new(AdaptiveOptions::dop853(1e-10, 1e-10));
//! let end = method.integrate(&free, 0.0, start, 1.0).unwrap();
//! // Torque-free: the kinetic energy (4.32) is kept to the tolerance.
//! let energy = |y: &SVector<f64, 13>| body.kinetic_energy(&y.data.0[0]);
//! assert!((energy(&end) - energy(&start)).abs() < 1e-8 * energy(&start));
//! ```

use crate::integrate::{IntegrateError, OdeSystem};
pub use eom_kernel::{Constant, Driven, Loads, Model};
use nalgebra::{RealField, SVector};

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
        let input = self.loads().at(t, state);
        dy.data.0[0] = self.model().rhs(state, &input);
    }

    /// Names the first load input that is NaN or infinite at `(t, y)`. `rhs` checks nothing,
    /// so a run pays for this only when a step has failed and is replayed.
    fn explain_non_finite(&self, t: T, y: &SVector<T, N>) -> Option<IntegrateError> {
        let input = self.loads().at(t, &y.data.0[0]);
        let index = input.iter().position(|v| !v.is_finite())?;
        Some(IntegrateError::NonFiniteInput {
            index,
            name: Mo::INPUTS[index],
            value: input[index].to_subset().unwrap_or(f64::NAN),
            t: t.to_subset().unwrap_or(f64::NAN),
        })
    }
}
