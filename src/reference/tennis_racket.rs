//! The tennis-racket (Dzhanibekov) flip: torque-free rotation of an asymmetric body,
//! I₁ < I₂ < I₃, started near the intermediate axis; body rates in closed form by Jacobi's
//! elliptic functions (Landau & Lifshitz, *Mechanics*, §37).
//!
//! With 2T = Σ Iᵢωᵢ² and H² = Σ Iᵢ²ωᵢ², in the case H² > 2TI₂:
//! - ω₁ = s₁A₁ cn τ, ω₂ = s₂A₂ sn τ, ω₃ = s₃A₃ dn τ, τ = λt + τ₀;
//! - A₁² = (2TI₃ − H²)/(I₁(I₃ − I₁)), A₂² = (2TI₃ − H²)/(I₂(I₃ − I₂)),
//!   A₃² = (H² − 2TI₁)/(I₃(I₃ − I₁));
//! - λ² = (I₃ − I₂)(H² − 2TI₁)/(I₁I₂I₃), m = (I₂ − I₁)(2TI₃ − H²)/((I₃ − I₂)(H² − 2TI₁)).
//!
//! Substituting into I₁ω̇₁ = (I₂ − I₃)ω₂ω₃ and its cyclic companions (with sn′ = cn dn,
//! cn′ = −sn dn, dn′ = −m sn cn) shows the magnitudes fit and the signs must satisfy
//! s₁ = s₂s₃. The problem starts at ω = (0, ω₂, ω₃) with ω₃ small: then H² − 2TI₂ =
//! I₃(I₃ − I₂)ω₃² > 0 (this case), and τ₀ = K(m) with s₂ = sign ω₂, s₃ = sign ω₃ reproduces
//! the start (sn K = 1, cn K = 0, dn K = √(1 − m)). ω₂ = s₂A₂ sn τ then changes sign every
//! 2K/λ: the flip. The differences 2TI₃ − H² = Σ Iᵢ(I₃ − Iᵢ)ωᵢ² and H² − 2TI₁ =
//! Σ Iᵢ(Iᵢ − I₁)ωᵢ² are formed term by term, without cancellation.
//!
//! The attitude needs an elliptic integral of the third kind for its angle about H; the exact
//! part used here is the direction of H: R(t) H_body(t) = H_space, fixed.

use nalgebra::{Quaternion, SVector, UnitQuaternion, Vector3};

use super::ReferenceProblem;
use super::torque_free::{PrincipalBody, energy, momentum};
use crate::ParameterError;
use crate::elliptic::{complete_k, jacobi};
use crate::validate::{non_zero, positive, require};

/// A torque-free asymmetric body near its intermediate axis; state `[p, q, r, q0, q1, q2, q3]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TennisRacket {
    body: PrincipalBody,
    omega0: Vector3<f64>,
    attitude0: UnitQuaternion<f64>,
    amplitude: Vector3<f64>,
    lambda: f64,
    m: f64,
    quarter: f64,
    h_space: Vector3<f64>,
}

impl TennisRacket {
    /// A body with principal moments `moments` (I₁ < I₂ < I₃) started with body rates
    /// (0, `omega2`, `omega3`) (both non-zero) and attitude `attitude0`.
    pub fn new(
        moments: Vector3<f64>,
        omega2: f64,
        omega3: f64,
        attitude0: UnitQuaternion<f64>,
    ) -> Result<Self, ParameterError> {
        let [i1, i2, i3] = [moments.x, moments.y, moments.z];
        positive("I1", i1)?;
        let ordered = i1 < i2 && i2 < i3 && i3.is_finite();
        require(
            ordered,
            "I2",
            i2,
            "between I₁ and I₃ (I₁ < I₂ < I₃, all finite)",
        )?;
        non_zero("omega2", omega2)?;
        non_zero("omega3", omega3)?;
        let omega0 = Vector3::new(0.0, omega2, omega3);
        let w2 = omega0.component_mul(&omega0);
        let above = i2 * (i3 - i2) * w2.y + i1 * (i3 - i1) * w2.x; // 2TI₃ − H²
        let below = i2 * (i2 - i1) * w2.y + i3 * (i3 - i1) * w2.z; // H² − 2TI₁
        let amplitude = Vector3::new(
            (above / (i1 * (i3 - i1))).sqrt(),
            (above / (i2 * (i3 - i2))).sqrt(),
            (below / (i3 * (i3 - i1))).sqrt(),
        );
        let m = (i2 - i1) * above / ((i3 - i2) * below);
        let quarter = complete_k(m).map_err(|_| ParameterError {
            field: "omega3",
            value: omega3,
            requirement: "far enough from the separatrix for K(m) in f64",
        })?;
        Ok(Self {
            body: PrincipalBody { moments },
            omega0,
            attitude0,
            amplitude,
            lambda: ((i3 - i2) * below / (i1 * i2 * i3)).sqrt(),
            m,
            quarter,
            h_space: attitude0 * moments.component_mul(&omega0),
        })
    }

    /// The right-hand side (4.52 with quaternion kinematics).
    pub fn body(&self) -> PrincipalBody {
        self.body
    }

    /// The elliptic parameter m of the motion (close to 1 near the separatrix).
    pub fn parameter(&self) -> f64 {
        self.m
    }

    /// The period of the body rates, 4K(m)/λ (two flips).
    pub fn period(&self) -> f64 {
        4.0 * self.quarter / self.lambda
    }

    /// The exact body rates at `t`.
    pub fn rates(&self, t: f64) -> Vector3<f64> {
        let j = jacobi(self.lambda * t + self.quarter, self.m).expect("m < 1 was checked");
        // dn from whichever identity avoids cancellation: 1 − m sn² when sn is small,
        // (1 − m) + m cn² when cn is small (near the intermediate axis, where m is near 1).
        let dn = if j.sn * j.sn < 0.5 {
            j.dn
        } else {
            ((1.0 - self.m) + self.m * j.cn * j.cn).sqrt()
        };
        let (s2, s3) = (self.omega0.y.signum(), self.omega0.z.signum());
        let a = &self.amplitude;
        Vector3::new(s2 * s3 * a.x * j.cn, s2 * a.y * j.sn, s3 * a.z * dn)
    }

    /// The angular momentum in space, R(t)H(t), fixed by the initial state.
    pub fn momentum_in_space(&self) -> Vector3<f64> {
        self.h_space
    }
}

impl ReferenceProblem<7> for TennisRacket {
    fn name(&self) -> &'static str {
        "tennis racket"
    }

    fn initial_state(&self) -> SVector<f64, 7> {
        let (w, q) = (self.omega0, self.attitude0);
        SVector::<f64, 7>::from([w.x, w.y, w.z, q.w, q.i, q.j, q.k])
    }

    /// One period of the body rates (two flips).
    fn t_end(&self) -> f64 {
        self.period()
    }

    /// max(|ω − ωₑₓ|/|ω₀|, angle between R(q)\[I\]ωₑₓ(t) and H in space, in radians).
    fn error(&self, t: f64, y: &SVector<f64, 7>) -> f64 {
        let exact = self.rates(t);
        let w = Vector3::new(y[0], y[1], y[2]);
        let rate_error = (w - exact).norm() / self.omega0.norm();
        let q = UnitQuaternion::from_quaternion(Quaternion::new(y[3], y[4], y[5], y[6]));
        let h = q * self.body.moments.component_mul(&exact);
        let direction_error = h.cross(&self.h_space).norm().atan2(h.dot(&self.h_space));
        rate_error.max(direction_error)
    }

    /// The kinetic energy T (4.32) and |H| (4.15).
    fn invariants(&self, y: &SVector<f64, 7>) -> Vec<f64> {
        let w = Vector3::new(y[0], y[1], y[2]);
        vec![
            energy(&self.body.moments, &w),
            momentum(&self.body.moments, &w),
        ]
    }
}
