//! The aerodynamic coefficients of an aircraft described as Stevens & Lewis describe the
//! F-16: tables in the angle of attack, the sideslip and the elevator, increments per unit of
//! aileron and rudder, and nine damping derivatives in the angle of attack, combined by the
//! source's build-up formulas. The angles enter the tables in degrees (α and β converted with
//! the source's 57.29578), the controls in degrees.
//!
//! What is computed here is what the proved program reads as its inputs: the six static
//! coefficients and the nine damping derivatives, each with its derivatives in α, β (per
//! radian) and the three surfaces (per degree); the program forms the totals with the
//! non-dimensional rates, the dynamic pressure and the moment transfer.

use super::derivatives::{Derivatives, PerAlphaRate};
use super::tables::{Lookup2, Table1, Table2};

/// Degrees per radian as the source's code converts α and β before its lookups.
pub const DEGREES_PER_RADIAN: f64 = 57.29578;

/// The derivatives a coefficient can have, in this order: α, β (rad), elevator, aileron,
/// rudder (deg), airspeed.
pub const ARGUMENTS: [&str; 6] = ["alpha", "beta", "elevator", "aileron", "rudder", "speed"];

/// The tables of the Stevens & Lewis form.
#[derive(Debug, Clone, PartialEq)]
pub struct StevensLewisTables {
    /// C_x(α, δ_e).
    pub cx: Table2,
    /// C_z(α) at zero sideslip and elevator.
    pub cz: Table1,
    /// C_m(α, δ_e) at the reference centre of gravity.
    pub cm: Table2,
    /// C_l(α, |β|), odd in β.
    pub cl: Table2,
    /// C_n(α, |β|), odd in β.
    pub cn: Table2,
    /// ΔC_l per unit aileron (δ_a/20), in (α, β).
    pub dlda: Table2,
    /// ΔC_l per unit rudder (δ_r/30), in (α, β).
    pub dldr: Table2,
    /// ΔC_n per unit aileron, in (α, β).
    pub dnda: Table2,
    /// ΔC_n per unit rudder, in (α, β).
    pub dndr: Table2,
    /// The damping derivatives in α, in the program's order (`C_Xq`, `C_Yr`, `C_Yp`, `C_Zq`,
    /// `C_lr`, `C_lp`, `C_mq`, `C_nr`, `C_np`).
    pub damping: [Table1; 9],
}

/// How an aircraft's aerodynamics is described: the tables of the Stevens & Lewis form, or a
/// textbook's stability derivatives.
#[derive(Debug, Clone, PartialEq)]
pub enum Aerodynamics {
    /// Tables in α, β and the controls (boxed: a kilobyte of tables).
    StevensLewis(Box<StevensLewisTables>),
    /// Terms linear in α, β, the rates and the surfaces (boxed: 33 numbers).
    Derivatives(Box<Derivatives>),
}

impl From<StevensLewisTables> for Aerodynamics {
    fn from(tables: StevensLewisTables) -> Self {
        Aerodynamics::StevensLewis(Box::new(tables))
    }
}

impl From<Derivatives> for Aerodynamics {
    fn from(derivatives: Derivatives) -> Self {
        Aerodynamics::Derivatives(Box::new(derivatives))
    }
}

impl Aerodynamics {
    /// The six static coefficients and the nine damping derivatives at `flow`.
    pub fn coefficients(&self, flow: &Flow) -> [Coefficient; 15] {
        match self {
            Aerodynamics::StevensLewis(tables) => tables.coefficients(flow),
            Aerodynamics::Derivatives(derivatives) => derivatives.coefficients(flow),
        }
    }

    /// The increments of C_X, C_Z, C_m per unit α̇ at `flow` for a chord `chord` (none for
    /// the tables, which have no α̇ terms).
    pub fn per_alpha_rate(&self, flow: &Flow, chord: f64) -> PerAlphaRate {
        match self {
            Aerodynamics::StevensLewis(_) => PerAlphaRate::default(),
            Aerodynamics::Derivatives(derivatives) => derivatives.per_alpha_rate(flow, chord),
        }
    }
}

/// A coefficient and its derivatives in [`ARGUMENTS`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Coefficient {
    /// Its value.
    pub value: f64,
    /// ∂/∂α, ∂/∂β (per rad), ∂/∂δ_e, ∂/∂δ_a, ∂/∂δ_r (per deg), ∂/∂V.
    pub by: [f64; 6],
}

/// The angles and controls a lookup reads: α, β in radians, the surfaces in degrees, and the
/// airspeed (which the tables do not read, and a table of derivatives reads through its speed
/// derivatives and its α̇ terms).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Flow {
    /// Airspeed (the scene's length unit per second).
    pub speed: f64,
    /// Angle of attack (rad).
    pub alpha: f64,
    /// Sideslip (rad).
    pub beta: f64,
    /// Elevator (deg).
    pub elevator: f64,
    /// Aileron (deg).
    pub aileron: f64,
    /// Rudder (deg).
    pub rudder: f64,
}

impl StevensLewisTables {
    /// The six static coefficients C_X, C_Y, C_Z, C_l, C_m, C_n and the nine damping
    /// derivatives at `flow`, each with its derivatives.
    pub fn coefficients(&self, flow: &Flow) -> [Coefficient; 15] {
        let deg = DEGREES_PER_RADIAN;
        let (alpha, beta) = (flow.alpha * deg, flow.beta * deg);
        let (aileron, rudder) = (flow.aileron / 20.0, flow.rudder / 30.0);
        let mut out = [Coefficient::default(); 15];
        out[0] = in_alpha_and_elevator(self.cx.at(alpha, flow.elevator));
        out[1] = Coefficient {
            value: -0.02 * beta + 0.021 * aileron + 0.086 * rudder,
            by: [0.0, -0.02 * deg, 0.0, 0.021 / 20.0, 0.086 / 30.0, 0.0],
        };
        let cz = self.cz.at(alpha);
        let sideslip = 1.0 - (beta / 57.3).powi(2);
        out[2] = Coefficient {
            value: cz.value * sideslip - 0.19 * (flow.elevator / 25.0),
            by: [
                cz.slope * deg * sideslip,
                cz.value * (-2.0 * beta / (57.3 * 57.3)) * deg,
                -0.19 / 25.0,
                0.0,
                0.0,
                0.0,
            ],
        };
        out[3] = self.lateral(
            &self.cl, &self.dlda, &self.dldr, alpha, beta, aileron, rudder,
        );
        out[4] = in_alpha_and_elevator(self.cm.at(alpha, flow.elevator));
        out[5] = self.lateral(
            &self.cn, &self.dnda, &self.dndr, alpha, beta, aileron, rudder,
        );
        for (slot, table) in out[6..].iter_mut().zip(&self.damping) {
            let d = table.at(alpha);
            *slot = Coefficient {
                value: d.value,
                by: [d.slope * deg, 0.0, 0.0, 0.0, 0.0, 0.0],
            };
        }
        out
    }

    /// sign(β)·base(α, |β|) + aileron·by_aileron(α, β) + rudder·by_rudder(α, β), the angles in
    /// degrees and the surfaces normalised (δ_a/20, δ_r/30).
    #[allow(clippy::too_many_arguments)]
    fn lateral(
        &self,
        base: &Table2,
        by_aileron: &Table2,
        by_rudder: &Table2,
        alpha: f64,
        beta: f64,
        aileron: f64,
        rudder: f64,
    ) -> Coefficient {
        let deg = DEGREES_PER_RADIAN;
        let sign = if beta < 0.0 { -1.0 } else { 1.0 };
        let b = base.at(alpha, beta.abs());
        let a = by_aileron.at(alpha, beta);
        let r = by_rudder.at(alpha, beta);
        Coefficient {
            value: sign * b.value + a.value * aileron + r.value * rudder,
            by: [
                (sign * b.by_x + a.by_x * aileron + r.by_x * rudder) * deg,
                (b.by_y + a.by_y * aileron + r.by_y * rudder) * deg,
                0.0,
                a.value / 20.0,
                r.value / 30.0,
                0.0,
            ],
        }
    }
}

/// A table in (α in degrees, elevator) as a coefficient.
fn in_alpha_and_elevator(at: Lookup2) -> Coefficient {
    Coefficient {
        value: at.value,
        by: [at.by_x * DEGREES_PER_RADIAN, 0.0, at.by_y, 0.0, 0.0, 0.0],
    }
}
