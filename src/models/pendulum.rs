//! The compound pendulum (4.24) from the generated code.

use super::generated::pendulum as generated;
use super::scalar;
use crate::PendulumParameters;
use simba::simd::SimdRealField;

/// The compound pendulum I₀θ̈ = −Mgh sin θ + M_O, state `[θ, θ̇]` (conventions in
/// [`PendulumParameters`]).
///
/// ```
/// use eom::{PendulumParameters, models::Pendulum};
/// let parameters = PendulumParameters::new(2.0, 1.0, 9.81, 0.5).unwrap();
/// let pendulum = Pendulum::<f64>::new(&parameters);
/// let rate = pendulum.rhs(&[0.1, 0.0], 0.0);
/// assert!((rate[1] + 9.81 * 0.5 * 0.1_f64.sin() / 2.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pendulum<T> {
    coefficients: generated::Coefficients<T>,
    i0: T,
}

impl<T: SimdRealField + Copy> Pendulum<T> {
    /// Computes the generated coefficients of `parameters`, already validated (see
    /// [`PendulumParameters::new`]).
    pub fn new(parameters: &PendulumParameters) -> Self {
        let emitted = generated::Parameters {
            i0: parameters.i0(),
            mass: parameters.mass(),
            g: parameters.g(),
            h: parameters.h(),
        };
        Self {
            coefficients: generated::Coefficients::new(&emitted),
            i0: scalar(emitted.i0),
        }
    }

    /// `[θ̇, θ̈]` for an applied moment `moment` about the pivot.
    #[inline]
    pub fn rhs(&self, state: &[T; 2], moment: T) -> [T; 2] {
        generated::rhs(&self.coefficients, state, &[moment])
    }

    /// Kinetic energy T = ½ I₀ θ̇² (4.34).
    pub fn kinetic_energy(&self, state: &[T; 2]) -> T {
        self.i0 * state[1] * state[1] * scalar(0.5)
    }
}
