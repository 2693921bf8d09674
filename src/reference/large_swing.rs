//! The compound pendulum at large amplitude (4.24): `I₀ θ̈ = −M g h sin θ`, released from rest
//! at θ₀ at t = 0, solved exactly by Jacobi's elliptic functions.
//!
//! With `ω₀² = M g h / I₀`, `k = sin(θ₀/2)`, `m = k²`, `K = K(m)` and `u = ω₀ t + K`:
//! `sin(θ/2) = k sn(u | m)` and `θ̇ = 2 k ω₀ cn(u | m)`.
//!
//! At t = 0, sn(K) = 1 and cn(K) = 0 give θ = θ₀ and θ̇ = 0. Since cn < 0 on K < u < 3K, the
//! pendulum first swings towards θ = 0, passes it at t = K/ω₀ (sn(2K) = 0) and comes to rest
//! at −θ₀ at t = 2K/ω₀. The period is 4K(m)/ω₀, which tends to 4.27's 2π/ω₀ as θ₀ → 0.
//!
//! Differentiating, `½ cos(θ/2) θ̇ = k ω₀ cn dn` with `cos(θ/2) = √(1 − k² sn²) = dn`, which
//! gives θ̇; then `½ I₀ θ̇² + M g h (1 − cos θ) = 2 M g h k² (cn² + sn²) = M g h (1 − cos θ₀)`,
//! the energy integral 4.35 with `I₀ ω₀² = M g h`.

use nalgebra::{RealField, SVector};

use super::ReferenceProblem;
use crate::elliptic::{complete_k, jacobi};
use crate::energy::{pendulum_kinetic_energy, pendulum_potential_energy};
use crate::integrate::OdeSystem;
use crate::validate::require;
use crate::{ParameterError, PendulumParameters};

/// The exact motion of a compound pendulum released from rest at θ₀ (conventions in
/// [`PendulumParameters`]); state `[θ, θ̇]`.
///
/// ```
/// use eom::{PendulumParameters, reference::LargeSwing};
/// let parameters = PendulumParameters::new(2.0, 3.0, 9.81, 0.5).unwrap();
/// let swing = LargeSwing::new(&parameters, 2.0).unwrap();
/// // At rest at θ₀ when released; a quarter period later at the bottom, moving towards −θ₀.
/// let start = swing.exact(0.0);
/// assert!((start[0] - 2.0).abs() < 1e-7 && start[1].abs() < 1e-12);
/// let bottom = swing.exact(0.25 * swing.period());
/// assert!(bottom[0].abs() < 1e-12 && bottom[1] < 0.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LargeSwing {
    parameters: PendulumParameters,
    theta0: f64,
    omega0: f64,
    k: f64,
    m: f64,
    quarter: f64,
}

impl LargeSwing {
    /// The pendulum of `parameters` released from rest at `theta0` (radians) at t = 0.
    ///
    /// The pendulum must swing: `g > 0` and `h > 0` (see
    /// [`PendulumParameters::natural_frequency`]) and `0 ≤ θ₀ < π` (at π it would balance on
    /// top, and beyond it go over the top).
    pub fn new(parameters: &PendulumParameters, theta0: f64) -> Result<Self, ParameterError> {
        let omega0 = parameters.natural_frequency()?;
        let swings = "at least 0 and below π (the pendulum must swing, not go over the top)";
        let theta0 = require(
            (0.0..std::f64::consts::PI).contains(&theta0),
            "theta0",
            theta0,
            swings,
        )?;
        let k = (0.5 * theta0).sin();
        let m = k * k;
        let quarter = complete_k(m).map_err(|_| ParameterError {
            field: "theta0",
            value: theta0,
            requirement: "far enough below π for K(m) in f64",
        })?;
        Ok(Self {
            parameters: *parameters,
            theta0,
            omega0,
            k,
            m,
            quarter,
        })
    }

    /// The parameters the pendulum was built from.
    pub fn parameters(&self) -> &PendulumParameters {
        &self.parameters
    }

    /// The release angle θ₀, in radians.
    pub fn theta0(&self) -> f64 {
        self.theta0
    }

    /// The small-amplitude natural frequency ω₀ = √(Mgh/I₀) (4.27).
    pub fn omega0(&self) -> f64 {
        self.omega0
    }

    /// The period 4K(m)/ω₀.
    pub fn period(&self) -> f64 {
        4.0 * self.quarter / self.omega0
    }

    /// The exact state `[θ, θ̇]` at time `t`.
    pub fn exact(&self, t: f64) -> SVector<f64, 2> {
        // m = sin²(θ₀/2) with 0 ≤ θ₀ < π, checked in `new`, so 0 ≤ m < 1 and jacobi cannot fail.
        let j = jacobi(self.omega0 * t + self.quarter, self.m).expect("0 ≤ m < 1 checked in new");
        SVector::<f64, 2>::new(
            2.0 * (self.k * j.sn).asin(),
            2.0 * self.k * self.omega0 * j.cn,
        )
    }

    /// The energy ½I₀θ̇² + Mgh(1 − cos θ) (4.34–4.35).
    pub fn energy(&self, y: &SVector<f64, 2>) -> f64 {
        let p = &self.parameters;
        pendulum_kinetic_energy(p.i0(), y[1])
            + pendulum_potential_energy(p.mass(), p.g(), p.h(), y[0])
    }
}

impl<T: RealField + Copy> OdeSystem<T, 2> for LargeSwing {
    fn rhs(&self, _t: T, y: &SVector<T, 2>, dy: &mut SVector<T, 2>) {
        let w2: T = nalgebra::convert(self.omega0 * self.omega0);
        *dy = SVector::<T, 2>::new(y[1], -w2 * y[0].sin());
    }
}

impl ReferenceProblem<2> for LargeSwing {
    fn name(&self) -> &'static str {
        "pendulum"
    }

    fn initial_state(&self) -> SVector<f64, 2> {
        SVector::<f64, 2>::new(self.theta0, 0.0)
    }

    /// One period.
    fn t_end(&self) -> f64 {
        self.period()
    }

    /// max(|θ − θₑₓ|, |θ̇ − θ̇ₑₓ|/ω₀), in radians.
    fn error(&self, t: f64, y: &SVector<f64, 2>) -> f64 {
        let e = self.exact(t);
        (y[0] - e[0]).abs().max((y[1] - e[1]).abs() / self.omega0)
    }

    fn invariants(&self, y: &SVector<f64, 2>) -> Vec<f64> {
        vec![self.energy(y)]
    }
}
