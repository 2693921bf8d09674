//! What a vehicle scene's run reports, as data: the model that ran, the method, the folded
//! table against its added mass, the cruise, and each manoeuvre's figures, converged.

use super::FoldedComparison;
use super::VehicleScene;
use super::manoeuvre::{VehicleRun, euler_angles};
use crate::ship::summary::IntegratorSummary;
use serde::Serialize;
use std::collections::BTreeMap;

/// `summary.json` of a vehicle scene.
#[derive(Debug, Clone, Serialize)]
pub struct VehicleSummary {
    /// The scene's title.
    pub title: String,
    /// The model.
    pub model: ModelSummary,
    /// The method.
    pub integrator: IntegratorSummary,
    /// Per cross term of the added mass's Coriolis and centripetal terms: the table's value,
    /// what M_A implies, the difference (a folded table; empty for a derived one).
    pub kirchhoff: Vec<KirchhoffRow>,
    /// The cruise every manoeuvre starts from.
    pub cruise: CruiseSummary,
    /// Each manoeuvre by name.
    pub manoeuvre: BTreeMap<String, ManoeuvreSummary>,
    /// Whether the run was stopped (Ctrl-C) before every manoeuvre was run.
    pub interrupted: bool,
}

/// The model: the six equations about O with the table's terms.
#[derive(Debug, Clone, Serialize)]
pub struct ModelSummary {
    /// `vehicle`.
    pub family: &'static str,
    /// What it integrates.
    pub equations: &'static str,
    /// `prestero` or `fossen`.
    pub convention: &'static str,
    /// `folded` or `derived`.
    pub added_mass_coriolis: &'static str,
    /// The named force terms the model carries.
    pub terms: usize,
    /// What one right-hand side costs.
    pub operations: eom_kernel::Operations,
}

/// One cross term of Kirchhoff's terms.
#[derive(Debug, Clone, Serialize)]
pub struct KirchhoffRow {
    /// The load: X, Y, Z, K, M, N.
    pub load: String,
    /// The product of velocities.
    pub product: String,
    /// The table's coefficient of it, if it has one.
    pub coefficient: Option<String>,
    /// Its value in the table.
    pub printed: Option<f64>,
    /// What M_A implies for it.
    pub implied: f64,
    /// printed − implied.
    pub difference: Option<f64>,
}

impl KirchhoffRow {
    /// A row of the generator's comparison.
    pub fn new(row: &FoldedComparison) -> Self {
        KirchhoffRow {
            load: row.load.letter().to_string(),
            product: row.product.clone(),
            coefficient: row.name.clone(),
            printed: row.printed,
            implied: row.implied,
            difference: row.difference,
        }
    }
}

/// The cruise: surge and roll trimmed on the model, against their closed forms.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct CruiseSummary {
    /// u of the trim, m/s.
    pub speed_m_s: f64,
    /// √(X_prop / −X_u|u|) where the table has a u|u| term and a propeller, m/s.
    pub speed_closed_form_m_s: Option<f64>,
    /// φ of the trim, degrees.
    pub roll_deg: f64,
    /// asin(K_prop / (z_G W − z_B B)), degrees: the propeller's torque against the righting
    /// moment, where the table has no other roll term at the cruise.
    pub roll_closed_form_deg: Option<f64>,
}

/// The figures of one step of the commands, read where it ends.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct StepFigures {
    /// When the step's commands began, s.
    pub from_s: f64,
    /// When they ended, s.
    pub to_s: f64,
    /// The rudder's angle commanded (saturated), degrees.
    pub rudder_deg: f64,
    /// The stern planes', degrees.
    pub stern_planes_deg: f64,
    /// r at the end, degrees per second.
    pub yaw_rate_deg_s: f64,
    /// √(u² + v² + w²) at the end, m/s.
    pub speed_m_s: f64,
    /// φ at the end, degrees.
    pub roll_deg: f64,
    /// θ at the end, degrees.
    pub pitch_deg: f64,
    /// ψ at the end, degrees.
    pub heading_deg: f64,
    /// z at the end (down positive), m.
    pub depth_m: f64,
}

/// A manoeuvre's figures and how far they move when the run is refined.
#[derive(Debug, Clone, Serialize)]
pub struct ManoeuvreSummary {
    /// Each step of the commands, the first being the cruise before the first change.
    pub steps: Vec<StepFigures>,
    /// The largest |figure − figure of the refined run| over every step's figures (degrees,
    /// degrees per second, m/s and m alike).
    pub refined_difference: f64,
    /// How the refined run was refined: `half the step` or `tolerances / 100`.
    pub refinement: &'static str,
    /// Steps taken.
    pub steps_taken: u64,
}

impl StepFigures {
    /// The figures of each step of a run.
    pub fn of(run: &VehicleRun) -> Vec<Self> {
        let mut from = 0.0;
        run.ends
            .iter()
            .map(|end| {
                let [phi, theta, psi] = euler_angles(&end.state);
                let s = end.state;
                let figures = StepFigures {
                    from_s: from,
                    to_s: end.t,
                    rudder_deg: end.commands[0].to_degrees(),
                    stern_planes_deg: end.commands[1].to_degrees(),
                    yaw_rate_deg_s: s[5].to_degrees(),
                    speed_m_s: (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt(),
                    roll_deg: phi.to_degrees(),
                    pitch_deg: theta.to_degrees(),
                    heading_deg: psi.to_degrees(),
                    depth_m: s[8],
                };
                from = end.t;
                figures
            })
            .collect()
    }

    fn values(&self) -> [f64; 6] {
        [
            self.yaw_rate_deg_s,
            self.speed_m_s,
            self.roll_deg,
            self.pitch_deg,
            self.heading_deg,
            self.depth_m,
        ]
    }
}

/// The largest difference between two runs' figures, step by step (infinite where they do
/// not have the same steps).
pub fn largest_difference(a: &[StepFigures], b: &[StepFigures]) -> f64 {
    if a.len() != b.len() {
        return f64::INFINITY;
    }
    (a.iter().zip(b))
        .flat_map(|(x, y)| x.values().into_iter().zip(y.values()))
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

impl CruiseSummary {
    /// The trim `start` of `scene`'s model, against the closed forms.
    pub fn new(scene: &VehicleScene, start: &[f64; 15]) -> Self {
        let table = &scene.table;
        // The names of X's u|u| under the table's convention (Fossen's u², the same ahead),
        // and the prime system's ½ρL² of a force of two linear velocities.
        let names: &[&str] = match table.convention {
            super::Convention::Prestero => &["Xuu"],
            super::Convention::Fossen => &["Xu|u|", "Xuu"],
        };
        let drag = names.iter().find_map(|n| table.coefficients.get(*n));
        let scale = table
            .prime
            .map_or(1.0, |p| 0.5 * p.density * p.length.powi(2));
        let closed_speed = match (table.propeller, drag) {
            (Some(p), Some(&x)) if x < 0.0 && p.thrust >= 0.0 => {
                Some((p.thrust / (-x * scale)).sqrt())
            }
            _ => None,
        };
        let righting = table.centre_of_gravity[2] * table.weight
            - table.centre_of_buoyancy[2] * table.buoyancy;
        let closed_roll = table
            .propeller
            .filter(|p| righting > 0.0 && (p.torque / righting).abs() <= 1.0)
            .map(|p| (p.torque / righting).asin().to_degrees());
        CruiseSummary {
            speed_m_s: start[0],
            speed_closed_form_m_s: closed_speed,
            roll_deg: euler_angles(start)[0].to_degrees(),
            roll_closed_form_deg: closed_roll,
        }
    }
}

impl ModelSummary {
    /// The model of `scene`.
    pub fn new(scene: &VehicleScene) -> Self {
        ModelSummary {
            family: "vehicle",
            equations: "4.1 and 4.2 about the table's origin O with G at r_G (4.5, 4.23), the \
                        added mass on the left, Kirchhoff's terms (4.48, 4.50) folded or \
                        derived, the table's terms, the propeller, weight and buoyancy; the \
                        quaternion's kinematics",
            convention: scene.table.convention.name(),
            added_mass_coriolis: match scene.table.added_mass_coriolis {
                super::AddedMassCoriolis::Folded => "folded",
                super::AddedMassCoriolis::Derived => "derived",
            },
            terms: scene.model.terms(),
            operations: scene.model.operations(),
        }
    }
}
