//! The compound pendulum at large amplitude (4.24): I₀θ̈ = −Mgh sin θ, released from rest at
//! θ₀.
//!
//! With ω₀² = Mgh/I₀, k = sin(θ₀/2) and m = k², the exact motion is
//! θ(t) = 2 asin(k sn(K − ω₀t | m)), θ̇(t) = −2kω₀ cn(K − ω₀t | m), K = K(m):
//! at t = 0, sn(K) = 1 and cn(K) = 0 give θ = θ₀, θ̇ = 0; the pendulum first swings towards
//! θ = 0, reached at t = K/ω₀. The period is 4K(m)/ω₀, which tends to 4.27's 2π/ω₀ as θ₀ → 0.
//! The energy ½I₀θ̇² + Mgh(1 − cos θ) (4.34–4.35) is conserved.

use nalgebra::{RealField, SVector};

use super::ReferenceProblem;
use crate::ParameterError;
use crate::elliptic::{complete_k, jacobi};
use crate::integrate::OdeSystem;
use crate::validate::positive;

/// A compound pendulum released from rest at a large angle; state `[θ, θ̇]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompoundPendulum {
    i0: f64,
    mgh: f64,
    theta0: f64,
    omega0: f64,
    k: f64,
    quarter: f64,
}

impl CompoundPendulum {
    /// A pendulum with moment of inertia `i0` about the pivot, mass `mass`, gravity `g`,
    /// pivot-to-G distance `h` (4.24), released from rest at `theta0` with 0 < θ₀ < π.
    pub fn new(i0: f64, mass: f64, g: f64, h: f64, theta0: f64) -> Result<Self, ParameterError> {
        let mgh = positive("mass", mass)? * positive("g", g)? * positive("h", h)?;
        let i0 = positive("i0", i0)?;
        if !(theta0 > 0.0 && theta0 < std::f64::consts::PI) {
            let requirement = "between 0 and π (the pendulum must swing, not go over the top)";
            return Err(ParameterError {
                field: "theta0",
                value: theta0,
                requirement,
            });
        }
        let k = (0.5 * theta0).sin();
        let quarter = complete_k(k * k).map_err(|_| ParameterError {
            field: "theta0",
            value: theta0,
            requirement: "far enough from π for K(m) in f64",
        })?;
        Ok(Self {
            i0,
            mgh,
            theta0,
            omega0: (mgh / i0).sqrt(),
            k,
            quarter,
        })
    }

    /// The period 4K(m)/ω₀.
    pub fn period(&self) -> f64 {
        4.0 * self.quarter / self.omega0
    }

    /// The small-amplitude natural frequency ω₀ = √(Mgh/I₀) (4.27).
    pub fn omega0(&self) -> f64 {
        self.omega0
    }

    /// The exact state `[θ, θ̇]` at time `t`.
    pub fn exact(&self, t: f64) -> SVector<f64, 2> {
        let m = self.k * self.k;
        let j = jacobi(self.quarter - self.omega0 * t, m).expect("m = sin²(θ₀/2) < 1 was checked");
        SVector::<f64, 2>::new(
            2.0 * (self.k * j.sn).asin(),
            -2.0 * self.k * self.omega0 * j.cn,
        )
    }

    /// The energy ½I₀θ̇² + Mgh(1 − cos θ) (4.34–4.35).
    pub fn energy(&self, y: &SVector<f64, 2>) -> f64 {
        0.5 * self.i0 * y[1] * y[1] + self.mgh * (1.0 - y[0].cos())
    }
}

impl<T: RealField + Copy> OdeSystem<T, 2> for CompoundPendulum {
    fn rhs(&self, _t: T, y: &SVector<T, 2>, dy: &mut SVector<T, 2>) {
        let w2: T = nalgebra::convert(self.omega0 * self.omega0);
        *dy = SVector::<T, 2>::new(y[1], -w2 * y[0].sin());
    }
}

impl ReferenceProblem<2> for CompoundPendulum {
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
