//! The compound pendulum (4.24) from the generated code.

use super::generated::pendulum as generated;
use super::scalar;
use crate::generic::ModelError;
use crate::generic::error::check_steiner;
use crate::validate::{finite, non_negative, positive};
use simba::simd::SimdRealField;

/// The compound pendulum I₀θ̈ = −Mgh sin θ + M_O, state `[θ, θ̇]`.
///
/// ```
/// use eom::models::Pendulum;
/// let pendulum = Pendulum::<f64>::new(2.0, 1.0, 9.81, 0.5).unwrap();
/// let rate = pendulum.rhs(&[0.1, 0.0], 0.0);
/// assert!((rate[1] + 9.81 * 0.5 * 0.1_f64.sin() / 2.0).abs() < 1e-15);
/// assert!(Pendulum::<f64>::new(-2.0, 1.0, 9.81, 0.5).is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pendulum<T> {
    coefficients: generated::Coefficients<T>,
    i0: T,
}

impl<T: SimdRealField + Copy> Pendulum<T> {
    /// Validates I₀ > 0 (about the pivot), M > 0, g finite, h ≥ 0 and I₀ ≥ M h² (4.29).
    pub fn new(i0: f64, mass: f64, g: f64, h: f64) -> Result<Self, ModelError> {
        let parameters = generated::Parameters {
            i0: positive("i0", i0)?,
            mass: positive("mass", mass)?,
            g: finite("g", g)?,
            h: non_negative("h", h)?,
        };
        check_steiner(i0, mass, h)?;
        Ok(Self {
            coefficients: generated::Coefficients::new(&parameters),
            i0: scalar(i0),
        })
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
