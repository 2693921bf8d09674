//! The compound pendulum of 4.24, written directly: `I₀ θ̈ = −M g h sin θ + M_applied`.
//!
//! State `[θ, θ̇]` (conventions in [`PendulumParameters`]). The two parameter-only
//! coefficients, `M g h / I₀` and `1 / I₀`, are computed once in [`Pendulum::new`]; a call
//! costs one `sin` and a few multiplications.

use crate::PendulumParameters;
use crate::energy::{pendulum_kinetic_energy, pendulum_potential_energy};
use nalgebra::{RealField, SVector, Vector2};

/// A compound pendulum swinging about a fixed horizontal axis through the pivot O (4.24).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pendulum<T> {
    i0: T,
    mass: T,
    g: T,
    h: T,
    /// `M g h / I₀`, the square of the small-amplitude angular frequency (4.27).
    stiffness: T,
    /// `1 / I₀`.
    inv_i0: T,
}

impl<T: RealField + Copy> Pendulum<T> {
    /// The pendulum of `parameters`, already validated (see [`PendulumParameters::new`]).
    ///
    /// ```
    /// use eom::{PendulumParameters, generic::Pendulum};
    /// let parameters = PendulumParameters::new(2.0, 3.0, 9.81, 0.5).unwrap();
    /// let p = Pendulum::<f64>::new(&parameters);
    /// let rate = p.rhs(&nalgebra::Vector2::new(0.0, 1.0), 0.0);
    /// assert_eq!(rate, nalgebra::Vector2::new(1.0, 0.0));
    /// ```
    pub fn new(parameters: &PendulumParameters) -> Self {
        let (i0, mass, g, h) = (
            parameters.i0(),
            parameters.mass(),
            parameters.g(),
            parameters.h(),
        );
        Self {
            i0: nalgebra::convert(i0),
            mass: nalgebra::convert(mass),
            g: nalgebra::convert(g),
            h: nalgebra::convert(h),
            stiffness: nalgebra::convert(parameters.restoring_moment() / i0),
            inv_i0: nalgebra::convert(1.0 / i0),
        }
    }

    /// The time derivative of `[θ, θ̇]`: `[θ̇, −(M g h / I₀) sin θ + moment / I₀]` (4.24), with
    /// `moment` an applied moment about the pivot (positive in the sense of θ).
    #[inline]
    pub fn rhs(&self, state: &SVector<T, 2>, moment: T) -> SVector<T, 2> {
        let (theta, theta_dot) = (state[0], state[1]);
        Vector2::new(
            theta_dot,
            -self.stiffness * theta.sin() + moment * self.inv_i0,
        )
    }

    /// The energy `½ I₀ θ̇² + M g h (1 − cos θ)` of 4.34–4.35, constant without an applied
    /// moment (by [`pendulum_kinetic_energy`] and [`pendulum_potential_energy`]).
    ///
    /// ```
    /// use eom::{PendulumParameters, generic::Pendulum};
    /// let p = Pendulum::<f64>::new(&PendulumParameters::new(2.0, 3.0, 9.81, 0.5).unwrap());
    /// // At rest, level with the pivot: U = M g h; at the bottom moving at 1 rad/s: T = ½ I₀.
    /// let level = p.energy(&nalgebra::Vector2::new(std::f64::consts::FRAC_PI_2, 0.0));
    /// assert!((level - 3.0 * 9.81 * 0.5).abs() < 1e-14);
    /// assert_eq!(p.energy(&nalgebra::Vector2::new(0.0, 1.0)), 1.0);
    /// ```
    pub fn energy(&self, state: &SVector<T, 2>) -> T {
        pendulum_kinetic_energy(self.i0, state[1])
            + pendulum_potential_energy(self.mass, self.g, self.h, state[0])
    }

    /// The moment of inertia about the pivot, `I₀`.
    pub fn i0(&self) -> T {
        self.i0
    }

    /// The mass `M`.
    pub fn mass(&self) -> T {
        self.mass
    }

    /// The acceleration of gravity `g`.
    pub fn g(&self) -> T {
        self.g
    }

    /// The distance `h` from the pivot to G.
    pub fn h(&self) -> T {
        self.h
    }
}

impl Pendulum<f64> {
    /// The same pendulum over another scalar (dual numbers, for its Jacobians).
    pub(super) fn cast<S: RealField + Copy>(&self) -> Pendulum<S> {
        Pendulum {
            i0: nalgebra::convert(self.i0),
            mass: nalgebra::convert(self.mass),
            g: nalgebra::convert(self.g),
            h: nalgebra::convert(self.h),
            stiffness: nalgebra::convert(self.stiffness),
            inv_i0: nalgebra::convert(self.inv_i0),
        }
    }
}
