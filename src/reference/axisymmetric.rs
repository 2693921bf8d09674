//! Torque-free rotation of an axisymmetric body, I₁ = I₂ ≠ I₃ (4.52 with zero moment): steady
//! precession, in closed form for the body rates and the attitude.
//!
//! Euler's equations give ṙ = 0, ṗ = −λq, q̇ = λp with λ = (I₃ − I₁) r / I₁, so the transverse
//! rate turns in the body at λ: p + iq = (p₀ + iq₀) e^{iλt}. Since ω = \[I\]⁻¹H = H/I₁ − λ e₃,
//! with H fixed in space, the attitude is a rotation about the fixed H at Ω = |H|/I₁ composed
//! with a rotation about the body axis e₃ at −λ: R(t) = Rot(ĥ, Ωt) R₀ Rot(e₃, −λt)
//! (differentiate: Ṙ = R (Ω R⁻¹ĥ − λ e₃)^ = R ω̂).

use nalgebra::{Quaternion, SVector, Unit, UnitQuaternion, Vector3};

use super::torque_free::{PrincipalBody, energy, momentum};
use super::{ReferenceProblem, attitude_angle};
use crate::ParameterError;
use crate::validate::positive;

/// A torque-free axisymmetric body; state `[p, q, r, q0, q1, q2, q3]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisymmetricTop {
    body: PrincipalBody,
    omega0: Vector3<f64>,
    attitude0: UnitQuaternion<f64>,
    lambda: f64,
    precession: f64,
    axis: Unit<Vector3<f64>>,
}

impl AxisymmetricTop {
    /// A body with transverse moment `i1` (= I₂), axial moment `i3`, initial body rates
    /// `omega0` and initial attitude `attitude0` (body to space).
    pub fn new(
        i1: f64,
        i3: f64,
        omega0: Vector3<f64>,
        attitude0: UnitQuaternion<f64>,
    ) -> Result<Self, ParameterError> {
        let moments = Vector3::new(positive("i1", i1)?, i1, positive("i3", i3)?);
        let h_body = moments.component_mul(&omega0);
        let axis = Unit::try_new(attitude0 * h_body, 1e-300).ok_or(ParameterError {
            field: "|omega0|",
            value: omega0.norm(),
            requirement: "large enough that the angular momentum has a direction",
        })?;
        Ok(Self {
            body: PrincipalBody { moments },
            omega0,
            attitude0,
            lambda: (i3 - i1) * omega0.z / i1,
            precession: h_body.norm() / i1,
            axis,
        })
    }

    /// The right-hand side (4.52 with quaternion kinematics).
    pub fn body(&self) -> PrincipalBody {
        self.body
    }

    /// The exact body rates at `t`.
    pub fn rates(&self, t: f64) -> Vector3<f64> {
        let (s, c) = (self.lambda * t).sin_cos();
        let w = &self.omega0;
        Vector3::new(w.x * c - w.y * s, w.x * s + w.y * c, w.z)
    }

    /// The exact attitude (body to space) at `t`.
    pub fn attitude(&self, t: f64) -> UnitQuaternion<f64> {
        let precession = UnitQuaternion::from_axis_angle(&self.axis, self.precession * t);
        let spin = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), -self.lambda * t);
        precession * self.attitude0 * spin
    }

    /// The exact state at `t`.
    pub fn exact(&self, t: f64) -> SVector<f64, 7> {
        let (w, q) = (self.rates(t), self.attitude(t));
        SVector::<f64, 7>::from([w.x, w.y, w.z, q.w, q.i, q.j, q.k])
    }
}

impl ReferenceProblem<7> for AxisymmetricTop {
    fn name(&self) -> &'static str {
        "axisymmetric"
    }

    fn initial_state(&self) -> SVector<f64, 7> {
        self.exact(0.0)
    }

    /// Two precession periods 2π/Ω.
    fn t_end(&self) -> f64 {
        2.0 * std::f64::consts::TAU / self.precession
    }

    /// max(|ω − ωₑₓ|/|ω₀|, attitude angle to the exact attitude in radians).
    fn error(&self, t: f64, y: &SVector<f64, 7>) -> f64 {
        let w = Vector3::new(y[0], y[1], y[2]);
        let rate_error = (w - self.rates(t)).norm() / self.omega0.norm();
        let q = Quaternion::new(y[3], y[4], y[5], y[6]);
        rate_error.max(attitude_angle(&self.attitude(t), &q))
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
