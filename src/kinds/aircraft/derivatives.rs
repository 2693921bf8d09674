//! The aerodynamic coefficients of an aircraft described by its stability derivatives, as
//! textbooks of flight dynamics give a light aircraft in one flight condition: each
//! coefficient a sum of terms linear in α, β, the non-dimensional rates and the surfaces.
//!
//! Lift and drag act in wind axes, so the body-axis coefficients the proved program reads are
//! rotated through α: C_X = C_L sin α − C_D cos α and C_Z = −C_L cos α − C_D sin α, with
//! C_L = C_L0 + C_Lα α + C_Lδe δe and C_D = C_D0 + C_Dα α; the pitch-rate lift C_Lq becomes
//! the program's damping terms C_Xq = C_Lq sin α and C_Zq = −C_Lq cos α. The side force and
//! the three moments are taken in the body axes of the scene, which a textbook's table puts
//! along the stability axes of its flight condition (α at trim near zero). Derivatives are
//! per radian, as textbooks give them; the surfaces enter in degrees, as everywhere in eom's
//! aircraft, converted exactly (π/180).
//!
//! C_mα̇, the pitching moment of the rate of change of α (the downwash lag at the tail), is
//! not a function of the state: the model adds C_mα̇ α̇ c̄/(2V) once α̇ is known
//! ([`super::model`]), since α̇ does not depend on C_m.

use super::aero::{Coefficient, Flow};
use serde::Deserialize;

/// Radians per degree, exactly as f64 rounds π/180.
const RADIANS_PER_DEGREE: f64 = std::f64::consts::PI / 180.0;

/// The stability derivatives, each per radian (the rates' through b/(2V) and c̄/(2V)); a term
/// a table does not give is 0. A scene's `[aerodynamics.derivatives]` names them by their
/// fields' names (`CL_alpha`); a name not among them is an error.
#[derive(Debug, Clone, Copy, PartialEq, Default, Deserialize)]
#[serde(default, deny_unknown_fields)]
#[allow(non_snake_case)]
pub struct Derivatives {
    /// Lift at α = 0 and the surfaces at 0.
    pub CL_0: f64,
    /// Lift per α.
    pub CL_alpha: f64,
    /// Lift per q c̄/(2V).
    pub CL_q: f64,
    /// Lift per elevator.
    pub CL_elevator: f64,
    /// Drag at α = 0.
    pub CD_0: f64,
    /// Drag per α.
    pub CD_alpha: f64,
    /// Pitching moment at α = 0 and the elevator at 0.
    pub Cm_0: f64,
    /// Pitching moment per α.
    pub Cm_alpha: f64,
    /// Pitching moment per α̇ c̄/(2V).
    pub Cm_alpha_dot: f64,
    /// Pitching moment per q c̄/(2V).
    pub Cm_q: f64,
    /// Pitching moment per elevator.
    pub Cm_elevator: f64,
    /// Side force per β.
    pub CY_beta: f64,
    /// Side force per p b/(2V).
    pub CY_p: f64,
    /// Side force per r b/(2V).
    pub CY_r: f64,
    /// Side force per aileron.
    pub CY_aileron: f64,
    /// Side force per rudder.
    pub CY_rudder: f64,
    /// Rolling moment per β.
    pub Cl_beta: f64,
    /// Rolling moment per p b/(2V).
    pub Cl_p: f64,
    /// Rolling moment per r b/(2V).
    pub Cl_r: f64,
    /// Rolling moment per aileron.
    pub Cl_aileron: f64,
    /// Rolling moment per rudder.
    pub Cl_rudder: f64,
    /// Yawing moment per β.
    pub Cn_beta: f64,
    /// Yawing moment per p b/(2V).
    pub Cn_p: f64,
    /// Yawing moment per r b/(2V).
    pub Cn_r: f64,
    /// Yawing moment per aileron.
    pub Cn_aileron: f64,
    /// Yawing moment per rudder.
    pub Cn_rudder: f64,
}

impl Derivatives {
    /// Every term by its key's name, in the order of the fields.
    pub fn terms(&self) -> [(&'static str, f64); 26] {
        [
            ("CL_0", self.CL_0),
            ("CL_alpha", self.CL_alpha),
            ("CL_q", self.CL_q),
            ("CL_elevator", self.CL_elevator),
            ("CD_0", self.CD_0),
            ("CD_alpha", self.CD_alpha),
            ("Cm_0", self.Cm_0),
            ("Cm_alpha", self.Cm_alpha),
            ("Cm_alpha_dot", self.Cm_alpha_dot),
            ("Cm_q", self.Cm_q),
            ("Cm_elevator", self.Cm_elevator),
            ("CY_beta", self.CY_beta),
            ("CY_p", self.CY_p),
            ("CY_r", self.CY_r),
            ("CY_aileron", self.CY_aileron),
            ("CY_rudder", self.CY_rudder),
            ("Cl_beta", self.Cl_beta),
            ("Cl_p", self.Cl_p),
            ("Cl_r", self.Cl_r),
            ("Cl_aileron", self.Cl_aileron),
            ("Cl_rudder", self.Cl_rudder),
            ("Cn_beta", self.Cn_beta),
            ("Cn_p", self.Cn_p),
            ("Cn_r", self.Cn_r),
            ("Cn_aileron", self.Cn_aileron),
            ("Cn_rudder", self.Cn_rudder),
        ]
    }

    /// The six static coefficients C_X, C_Y, C_Z, C_l, C_m, C_n and the nine damping
    /// derivatives (in the program's order `C_Xq`, `C_Yr`, `C_Yp`, `C_Zq`, `C_lr`, `C_lp`,
    /// `C_mq`, `C_nr`, `C_np`) at `flow`, each with its derivatives in α, β (per rad) and the
    /// surfaces (per deg).
    pub fn coefficients(&self, flow: &Flow) -> [Coefficient; 15] {
        let d = RADIANS_PER_DEGREE;
        let (alpha, beta) = (flow.alpha, flow.beta);
        let [elevator, aileron, rudder] = [flow.elevator, flow.aileron, flow.rudder].map(|s| s * d);
        let (sin, cos) = alpha.sin_cos();
        let lift = self.CL_0 + self.CL_alpha * alpha + self.CL_elevator * elevator;
        let drag = self.CD_0 + self.CD_alpha * alpha;
        let lift_by_elevator = self.CL_elevator * d;
        let linear = |by_beta: f64, by_aileron: f64, by_rudder: f64| Coefficient {
            value: by_beta * beta + by_aileron * aileron + by_rudder * rudder,
            by: [0.0, by_beta, 0.0, by_aileron * d, by_rudder * d],
        };
        let in_alpha = |value: f64, by_alpha: f64| Coefficient {
            value,
            by: [by_alpha, 0.0, 0.0, 0.0, 0.0],
        };
        let constant = |value: f64| in_alpha(value, 0.0);
        let mut out = [Coefficient::default(); 15];
        out[0] = Coefficient {
            value: lift * sin - drag * cos,
            by: [
                self.CL_alpha * sin + lift * cos - self.CD_alpha * cos + drag * sin,
                0.0,
                lift_by_elevator * sin,
                0.0,
                0.0,
            ],
        };
        out[1] = linear(self.CY_beta, self.CY_aileron, self.CY_rudder);
        out[2] = Coefficient {
            value: -lift * cos - drag * sin,
            by: [
                -self.CL_alpha * cos + lift * sin - self.CD_alpha * sin - drag * cos,
                0.0,
                -lift_by_elevator * cos,
                0.0,
                0.0,
            ],
        };
        out[3] = linear(self.Cl_beta, self.Cl_aileron, self.Cl_rudder);
        out[4] = Coefficient {
            value: self.Cm_0 + self.Cm_alpha * alpha + self.Cm_elevator * elevator,
            by: [self.Cm_alpha, 0.0, self.Cm_elevator * d, 0.0, 0.0],
        };
        out[5] = linear(self.Cn_beta, self.Cn_aileron, self.Cn_rudder);
        out[6] = in_alpha(self.CL_q * sin, self.CL_q * cos);
        out[7] = constant(self.CY_r);
        out[8] = constant(self.CY_p);
        out[9] = in_alpha(-self.CL_q * cos, self.CL_q * sin);
        out[10] = constant(self.Cl_r);
        out[11] = constant(self.Cl_p);
        out[12] = constant(self.Cm_q);
        out[13] = constant(self.Cn_r);
        out[14] = constant(self.Cn_p);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn navion_like() -> Derivatives {
        Derivatives {
            CL_0: 0.41,
            CL_alpha: 4.44,
            CL_q: 3.8,
            CL_elevator: 0.355,
            CD_0: 0.05,
            CD_alpha: 0.33,
            Cm_alpha: -0.683,
            Cm_elevator: -0.923,
            CY_beta: -0.564,
            CY_rudder: 0.157,
            Cl_beta: -0.074,
            Cl_aileron: -0.134,
            Cl_rudder: 0.0107,
            Cn_beta: 0.071,
            Cn_aileron: 0.0035,
            Cn_rudder: -0.072,
            ..Derivatives::default()
        }
    }

    /// Every derivative a coefficient reports against central differences of its value
    /// (steps 1e-6 rad and 1e-4 deg; the values are smooth, so the differences' truncation,
    /// of order h², and rounding, 1e-16/h, stay below 1e-9).
    #[test]
    fn each_coefficients_derivatives_are_its_slopes() {
        let table = navion_like();
        let at = Flow {
            alpha: 0.12,
            beta: -0.05,
            elevator: -3.0,
            aileron: 2.0,
            rudder: 1.5,
        };
        let base = table.coefficients(&at);
        let nudged = |k: usize, h: f64| {
            let mut f = at;
            match k {
                0 => f.alpha += h,
                1 => f.beta += h,
                2 => f.elevator += h,
                3 => f.aileron += h,
                _ => f.rudder += h,
            }
            table.coefficients(&f)
        };
        for k in 0..5 {
            let h = if k < 2 { 1e-6 } else { 1e-4 };
            let (up, down) = (nudged(k, h), nudged(k, -h));
            for c in 0..15 {
                let difference = (up[c].value - down[c].value) / (2.0 * h);
                assert!(
                    (difference - base[c].by[k]).abs() < 1e-9,
                    "coefficient {c} by argument {k}: {difference} against {}",
                    base[c].by[k]
                );
            }
        }
    }

    /// At α = 0 the body axes are the wind axes: C_X = −C_D, C_Z = −C_L.
    #[test]
    fn at_zero_alpha_the_forces_are_drag_and_lift() {
        let table = navion_like();
        let at = Flow {
            alpha: 0.0,
            beta: 0.0,
            elevator: 0.0,
            aileron: 0.0,
            rudder: 0.0,
        };
        let c = table.coefficients(&at);
        assert_eq!(c[0].value, -0.05);
        assert_eq!(c[2].value, -0.41);
        assert_eq!(c[9].value, -3.8);
    }
}
