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
//! A jet's table adds what a light aircraft's leaves out (Etkin & Reid's, Nelson's,
//! Roskam's and Heffley & Jewell's common set): the speed derivatives C_Lu, C_Du, C_mu per
//! û = (V − u₀)/u₀ about the table's own speed u₀ (`reference_speed`, since the trim may be
//! flown elsewhere), the drag of the pitch rate and of the elevator (C_Dq, C_Dδe) and the
//! lift of α̇ (C_Lα̇).
//!
//! A source may give its forces in the body axes instead (Etkin's C_x, C_z along the
//! stability axes of its condition): the body-axis form, `CX_…` and `CZ_…`, whose terms are
//! added to C_X and C_Z as they are, not turned with α. A table gives its forces one way or
//! the other; C_m and the lateral set are the same in both. Its terms are the aerodynamic
//! force's: a source's total-force derivative that counts the thrust (Etkin's C_xu = −2 C_T0
//! − C_Du for a thrust constant with speed) gives the engine's share to the engine.
//!
//! A speed derivative may be given per Mach number instead (C_LM, as Heffley & Jewell give
//! C_DM): it enters as M₀ C_LM per û, M₀ the table's `reference_mach` (Etkin's C_Lu =
//! M ∂C_L/∂M), the speed of sound held at the condition's.
//!
//! C_mα̇ and C_Lα̇, the moment and lift of the rate of change of α (the downwash lag at the
//! tail), are not functions of the state: α̇ depends on the lift, so the model solves for it
//! ([`super::alpha_rate`]) and adds their terms once it is known.

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
    /// Lift per α̇ c̄/(2V).
    pub CL_alpha_dot: f64,
    /// Lift per û = (V − u₀)/u₀, u₀ the `reference_speed`.
    pub CL_u: f64,
    /// Drag per û.
    pub CD_u: f64,
    /// Pitching moment per û.
    pub Cm_u: f64,
    /// Drag per q c̄/(2V).
    pub CD_q: f64,
    /// Drag per elevator.
    pub CD_elevator: f64,
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
    /// u₀, the airspeed the table's speed derivatives are taken about (the scene's length
    /// unit per second); 0 when the table has none, and required when it has.
    pub reference_speed: f64,
    /// Lift per Mach number, taken as M₀ C_LM per û (Etkin's C_Lu = M ∂C_L/∂M, the sound
    /// speed held at the condition's).
    pub CL_M: f64,
    /// Drag per Mach number, as C_LM.
    pub CD_M: f64,
    /// Pitching moment per Mach number, as C_LM.
    pub Cm_M: f64,
    /// Body-axis force C_X per Mach number, as C_LM.
    pub CX_M: f64,
    /// Body-axis force C_Z per Mach number, as C_LM.
    pub CZ_M: f64,
    /// M₀, the Mach number the per-Mach derivatives are taken about; 0 when the table has
    /// none, and required when it has.
    pub reference_mach: f64,
    /// The aerodynamic force along body x (the condition's stability axes, not turned with
    /// α) at α = 0 and the surfaces at 0: the body-axis form of a table, which gives C_X and
    /// C_Z where the other gives lift and drag.
    pub CX_0: f64,
    /// C_X per α.
    pub CX_alpha: f64,
    /// C_X per α̇ c̄/(2V).
    pub CX_alpha_dot: f64,
    /// C_X per q c̄/(2V).
    pub CX_q: f64,
    /// C_X per û.
    pub CX_u: f64,
    /// C_X per elevator.
    pub CX_elevator: f64,
    /// The aerodynamic force along body z at α = 0 and the surfaces at 0.
    pub CZ_0: f64,
    /// C_Z per α.
    pub CZ_alpha: f64,
    /// C_Z per α̇ c̄/(2V).
    pub CZ_alpha_dot: f64,
    /// C_Z per q c̄/(2V).
    pub CZ_q: f64,
    /// C_Z per û.
    pub CZ_u: f64,
    /// C_Z per elevator.
    pub CZ_elevator: f64,
}

/// The slopes per û of the coefficients a speed or Mach derivative moves: each one's speed
/// derivative plus M₀ times its Mach derivative.
#[derive(Debug, Clone, Copy, PartialEq)]
struct PerSpeedRatio {
    lift: f64,
    drag: f64,
    moment: f64,
    along_x: f64,
    along_z: f64,
}

/// The increments of C_X, C_Z and C_m per unit α̇ (rad/s) at a flow, with their slopes in the
/// airspeed and α (α̇ held).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PerAlphaRate {
    /// ∂C_X/∂α̇, ∂C_Z/∂α̇, ∂C_m/∂α̇.
    pub per: [f64; 3],
    /// Their derivatives in V.
    pub by_speed: [f64; 3],
    /// Their derivatives in α.
    pub by_alpha: [f64; 3],
}

impl PerAlphaRate {
    /// Whether no coefficient has an α̇ term.
    pub fn is_zero(&self) -> bool {
        self.per == [0.0; 3]
    }
}

impl Derivatives {
    /// Every term by its key's name, in the order of the fields.
    pub fn terms(&self) -> [(&'static str, f64); 51] {
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
            ("CL_alpha_dot", self.CL_alpha_dot),
            ("CL_u", self.CL_u),
            ("CD_u", self.CD_u),
            ("Cm_u", self.Cm_u),
            ("CD_q", self.CD_q),
            ("CD_elevator", self.CD_elevator),
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
            ("reference_speed", self.reference_speed),
            ("CL_M", self.CL_M),
            ("CD_M", self.CD_M),
            ("Cm_M", self.Cm_M),
            ("CX_M", self.CX_M),
            ("CZ_M", self.CZ_M),
            ("reference_mach", self.reference_mach),
            ("CX_0", self.CX_0),
            ("CX_alpha", self.CX_alpha),
            ("CX_alpha_dot", self.CX_alpha_dot),
            ("CX_q", self.CX_q),
            ("CX_u", self.CX_u),
            ("CX_elevator", self.CX_elevator),
            ("CZ_0", self.CZ_0),
            ("CZ_alpha", self.CZ_alpha),
            ("CZ_alpha_dot", self.CZ_alpha_dot),
            ("CZ_q", self.CZ_q),
            ("CZ_u", self.CZ_u),
            ("CZ_elevator", self.CZ_elevator),
        ]
    }

    /// The terms of the lift-and-drag form, given (non-zero), by name.
    pub fn lift_and_drag_terms(&self) -> Vec<&'static str> {
        self.given(|name| name.starts_with("CL_") || name.starts_with("CD_"))
    }

    /// The terms of the body-axis form (C_X, C_Z), given, by name.
    pub fn body_axis_terms(&self) -> Vec<&'static str> {
        self.given(|name| name.starts_with("CX_") || name.starts_with("CZ_"))
    }

    /// The Mach derivatives given, by name.
    pub fn mach_terms(&self) -> Vec<&'static str> {
        self.given(|name| name.ends_with("_M"))
    }

    /// A coefficient given both per û and per Mach, as (the speed's term, the Mach's).
    pub fn speed_and_mach_of_one(&self) -> Option<(&'static str, &'static str)> {
        [
            ("CL_u", self.CL_u, "CL_M", self.CL_M),
            ("CD_u", self.CD_u, "CD_M", self.CD_M),
            ("Cm_u", self.Cm_u, "Cm_M", self.Cm_M),
            ("CX_u", self.CX_u, "CX_M", self.CX_M),
            ("CZ_u", self.CZ_u, "CZ_M", self.CZ_M),
        ]
        .into_iter()
        .find(|(_, per_speed, _, per_mach)| *per_speed != 0.0 && *per_mach != 0.0)
        .map(|(speed, _, mach, _)| (speed, mach))
    }

    /// The names of the terms `selected` that the table gives (non-zero).
    fn given(&self, selected: impl Fn(&str) -> bool) -> Vec<&'static str> {
        (self.terms().into_iter())
            .filter(|(name, value)| selected(name) && *value != 0.0)
            .map(|(name, _)| name)
            .collect()
    }

    /// Whether the table has a speed or Mach derivative (and so needs its
    /// `reference_speed`).
    pub fn has_speed_terms(&self) -> bool {
        let per_mach = [self.CL_M, self.CD_M, self.Cm_M, self.CX_M, self.CZ_M];
        [self.CL_u, self.CD_u, self.Cm_u, self.CX_u, self.CZ_u] != [0.0; 5] || per_mach != [0.0; 5]
    }

    /// The slopes per û: the speed derivatives, and M₀ times the Mach derivatives.
    fn per_speed_ratio(&self) -> PerSpeedRatio {
        let mach = self.reference_mach;
        PerSpeedRatio {
            lift: self.CL_u + mach * self.CL_M,
            drag: self.CD_u + mach * self.CD_M,
            moment: self.Cm_u + mach * self.Cm_M,
            along_x: self.CX_u + mach * self.CX_M,
            along_z: self.CZ_u + mach * self.CZ_M,
        }
    }

    /// û = (V − u₀)/u₀ at airspeed `speed` and its slope in V (0 and 0 for a table without
    /// speed derivatives, whose u₀ may be 0).
    fn speed_ratio(&self, speed: f64) -> (f64, f64) {
        if !self.has_speed_terms() {
            return (0.0, 0.0);
        }
        let u0 = self.reference_speed;
        ((speed - u0) / u0, 1.0 / u0)
    }

    /// The six static coefficients C_X, C_Y, C_Z, C_l, C_m, C_n and the nine damping
    /// derivatives (in the program's order `C_Xq`, `C_Yr`, `C_Yp`, `C_Zq`, `C_lr`, `C_lp`,
    /// `C_mq`, `C_nr`, `C_np`) at `flow`, each with its derivatives in α, β (per rad), the
    /// surfaces (per deg) and the airspeed.
    pub fn coefficients(&self, flow: &Flow) -> [Coefficient; 15] {
        let d = RADIANS_PER_DEGREE;
        let (alpha, beta) = (flow.alpha, flow.beta);
        let [elevator, aileron, rudder] = [flow.elevator, flow.aileron, flow.rudder].map(|s| s * d);
        let (sin, cos) = alpha.sin_cos();
        let (u, u_by_speed) = self.speed_ratio(flow.speed);
        let per_u = self.per_speed_ratio();
        let lift = self.CL_0 + self.CL_alpha * alpha + self.CL_elevator * elevator + per_u.lift * u;
        let drag = self.CD_0 + self.CD_alpha * alpha + self.CD_elevator * elevator + per_u.drag * u;
        let (lift_by_elevator, drag_by_elevator) = (self.CL_elevator * d, self.CD_elevator * d);
        let (lift_by_speed, drag_by_speed) = (per_u.lift * u_by_speed, per_u.drag * u_by_speed);
        // The body-axis form's terms, added as they are (0 for a table of lift and drag).
        let body_x =
            self.CX_0 + self.CX_alpha * alpha + self.CX_elevator * elevator + per_u.along_x * u;
        let body_z =
            self.CZ_0 + self.CZ_alpha * alpha + self.CZ_elevator * elevator + per_u.along_z * u;
        let linear = |by_beta: f64, by_aileron: f64, by_rudder: f64| Coefficient {
            value: by_beta * beta + by_aileron * aileron + by_rudder * rudder,
            by: [0.0, by_beta, 0.0, by_aileron * d, by_rudder * d, 0.0],
        };
        let in_alpha = |value: f64, by_alpha: f64| Coefficient {
            value,
            by: [by_alpha, 0.0, 0.0, 0.0, 0.0, 0.0],
        };
        let constant = |value: f64| in_alpha(value, 0.0);
        // C_X = C_L sin α − C_D cos α and C_Z = −C_L cos α − C_D sin α, of (lift, drag).
        let along_x = |l: f64, d: f64| l * sin - d * cos;
        let along_z = |l: f64, d: f64| -l * cos - d * sin;
        let mut out = [Coefficient::default(); 15];
        out[0] = Coefficient {
            value: along_x(lift, drag) + body_x,
            by: [
                along_x(self.CL_alpha, self.CD_alpha) - along_z(lift, drag) + self.CX_alpha,
                0.0,
                along_x(lift_by_elevator, drag_by_elevator) + self.CX_elevator * d,
                0.0,
                0.0,
                along_x(lift_by_speed, drag_by_speed) + per_u.along_x * u_by_speed,
            ],
        };
        out[1] = linear(self.CY_beta, self.CY_aileron, self.CY_rudder);
        out[2] = Coefficient {
            value: along_z(lift, drag) + body_z,
            by: [
                along_z(self.CL_alpha, self.CD_alpha) + along_x(lift, drag) + self.CZ_alpha,
                0.0,
                along_z(lift_by_elevator, drag_by_elevator) + self.CZ_elevator * d,
                0.0,
                0.0,
                along_z(lift_by_speed, drag_by_speed) + per_u.along_z * u_by_speed,
            ],
        };
        out[3] = linear(self.Cl_beta, self.Cl_aileron, self.Cl_rudder);
        out[4] = Coefficient {
            value: self.Cm_0
                + self.Cm_alpha * alpha
                + self.Cm_elevator * elevator
                + per_u.moment * u,
            by: [
                self.Cm_alpha,
                0.0,
                self.Cm_elevator * d,
                0.0,
                0.0,
                per_u.moment * u_by_speed,
            ],
        };
        out[5] = linear(self.Cn_beta, self.Cn_aileron, self.Cn_rudder);
        let (lift_q, drag_q) = (self.CL_q, self.CD_q);
        out[6] = in_alpha(
            along_x(lift_q, drag_q) + self.CX_q,
            -along_z(lift_q, drag_q),
        );
        out[7] = constant(self.CY_r);
        out[8] = constant(self.CY_p);
        out[9] = in_alpha(along_z(lift_q, drag_q) + self.CZ_q, along_x(lift_q, drag_q));
        out[10] = constant(self.Cl_r);
        out[11] = constant(self.Cl_p);
        out[12] = constant(self.Cm_q);
        out[13] = constant(self.Cn_r);
        out[14] = constant(self.Cn_p);
        out
    }

    /// The increments of C_X, C_Z, C_m per unit α̇ at `flow` for a chord `chord`: C_Lα̇ and
    /// C_mα̇ per α̇ c̄/(2V), the lift rotated into the body axes through α as C_Lq is, and the
    /// body-axis form's C_Xα̇ and C_Zα̇ as they are.
    pub fn per_alpha_rate(&self, flow: &Flow, chord: f64) -> PerAlphaRate {
        let scale = chord / (2.0 * flow.speed);
        let (sin, cos) = flow.alpha.sin_cos();
        let lift = self.CL_alpha_dot * scale;
        let per = [
            lift * sin + self.CX_alpha_dot * scale,
            -lift * cos + self.CZ_alpha_dot * scale,
            self.Cm_alpha_dot * scale,
        ];
        PerAlphaRate {
            per,
            by_speed: per.map(|k| -k / flow.speed),
            by_alpha: [lift * cos, lift * sin, 0.0],
        }
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

    /// The Navion's table with a jet's terms besides (speed, pitch-rate drag, elevator drag).
    fn with_jet_terms() -> Derivatives {
        Derivatives {
            CL_u: 0.106,
            CD_u: 0.022,
            Cm_u: 0.1043,
            CD_q: 0.3,
            CD_elevator: 0.05,
            reference_speed: 176.0,
            ..navion_like()
        }
    }

    /// The 747's table in the body-axis form (Etkin's C_x, C_z), with a Mach derivative.
    fn in_body_axes() -> Derivatives {
        Derivatives {
            CX_0: -0.043,
            CX_alpha: 0.2193,
            CX_alpha_dot: 0.1,
            CX_q: -0.2,
            CX_u: -0.022,
            CX_elevator: -3.818e-6,
            CZ_0: -0.654,
            CZ_alpha: -4.92,
            CZ_alpha_dot: 5.896,
            CZ_q: -5.921,
            CZ_M: -0.1325,
            CZ_elevator: -0.3648,
            Cm_alpha: -1.023,
            Cm_M: 0.13,
            reference_speed: 235.9,
            reference_mach: 0.8,
            ..navion_like()
        }
    }

    /// Every derivative a coefficient reports against central differences of its value
    /// (steps 1e-6 rad and 1e-4 deg; the values are smooth, so the differences' truncation,
    /// of order h², and rounding, 1e-16/h, stay below 1e-9), for a table of lift and drag
    /// and one in the body axes.
    #[test]
    fn each_coefficients_derivatives_are_its_slopes() {
        for table in [with_jet_terms(), in_body_axes()] {
            slopes_agree(&table);
        }
    }

    fn slopes_agree(table: &Derivatives) {
        let at = Flow {
            speed: 180.0,
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
                4 => f.rudder += h,
                _ => f.speed += h,
            }
            table.coefficients(&f)
        };
        for k in 0..6 {
            let h = [1e-6, 1e-6, 1e-4, 1e-4, 1e-4, 1e-4][k];
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

    /// The body-axis form's terms are C_X's and C_Z's as they are, at every α: the slopes
    /// in α and q, and per α̇ (c̄/(2V) each).
    #[test]
    fn body_axis_terms_are_not_turned_with_alpha() {
        let table = Derivatives {
            CL_0: 0.0,
            CL_alpha: 0.0,
            CL_q: 0.0,
            CL_elevator: 0.0,
            CD_0: 0.0,
            CD_alpha: 0.0,
            ..in_body_axes()
        };
        for alpha in [0.0, 0.3] {
            let at = Flow {
                speed: 235.9,
                alpha,
                beta: 0.0,
                elevator: 0.0,
                aileron: 0.0,
                rudder: 0.0,
            };
            let c = table.coefficients(&at);
            assert_eq!(c[0].value, -0.043 + 0.2193 * alpha);
            assert_eq!(c[2].by[0], -4.92);
            assert_eq!([c[6].value, c[9].value], [-0.2, -5.921]);
            let per = table.per_alpha_rate(&at, 8.324).per;
            let scale = 8.324 / (2.0 * 235.9);
            assert_eq!([per[0], per[1]], [0.1 * scale, 5.896 * scale]);
        }
    }

    /// The α̇ terms' slopes in V and α against central differences (steps 1e-4 ft/s and 1e-6
    /// rad; smooth, so within 1e-9), and at α = 0 the lift's term is all along −z.
    #[test]
    fn the_alpha_rate_terms_slopes_are_their_differences() {
        let table = Derivatives {
            CL_alpha_dot: 5.9,
            Cm_alpha_dot: -4.36,
            ..with_jet_terms()
        };
        let at = |speed: f64, alpha: f64| Flow {
            speed,
            alpha,
            beta: 0.0,
            elevator: 0.0,
            aileron: 0.0,
            rudder: 0.0,
        };
        let chord = 5.7;
        let base = table.per_alpha_rate(&at(180.0, 0.12), chord);
        for k in 0..3 {
            let by = |f: &dyn Fn(f64) -> Flow, h: f64| {
                let (up, down) = (
                    table.per_alpha_rate(&f(h), chord).per[k],
                    table.per_alpha_rate(&f(-h), chord).per[k],
                );
                (up - down) / (2.0 * h)
            };
            let by_speed = by(&|h| at(180.0 + h, 0.12), 1e-4);
            let by_alpha = by(&|h| at(180.0, 0.12 + h), 1e-6);
            assert!(
                (by_speed - base.by_speed[k]).abs() < 1e-9,
                "{k}: {by_speed}"
            );
            assert!(
                (by_alpha - base.by_alpha[k]).abs() < 1e-9,
                "{k}: {by_alpha}"
            );
        }
        let level = table.per_alpha_rate(&at(176.0, 0.0), chord);
        assert_eq!(level.per[0], 0.0);
        let scale = chord / (2.0 * 176.0);
        assert_eq!(level.per[1], -(5.9 * scale));
        assert_eq!(level.per[2], -4.36 * scale);
    }

    /// At α = 0 the body axes are the wind axes: C_X = −C_D, C_Z = −C_L.
    #[test]
    fn at_zero_alpha_the_forces_are_drag_and_lift() {
        let table = navion_like();
        let at = Flow {
            speed: 176.0,
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
