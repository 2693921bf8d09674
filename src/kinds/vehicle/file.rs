//! A vehicle scene's tables as written, read by serde: every key by its path, none unknown.
//! [`super::scene`] checks them into a [`super::VehicleScene`].

use crate::scene::envelope::{FamilyTable, IntegratorTable, OutputTable, SteeringGearTable};
use serde::Deserialize;
use std::collections::BTreeMap;

/// The file as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VehicleSceneFile {
    /// What the scene is.
    pub title: String,
    /// `family = "vehicle"`.
    pub model: FamilyTable,
    /// The body.
    pub body: BodyTable,
    /// The hydrodynamic table.
    pub hydrodynamics: HydrodynamicsTable,
    /// The propeller at its setting.
    pub propeller: Option<PropellerTable>,
    /// The rudder's steering gear.
    #[serde(default)]
    pub rudder: SteeringGearTable,
    /// The stern planes' steering gear.
    #[serde(default)]
    pub stern_planes: SteeringGearTable,
    /// The method.
    pub integrator: IntegratorTable,
    /// The manoeuvres, each run from the cruise.
    #[serde(default)]
    pub manoeuvre: Vec<ManoeuvreTable>,
    /// Trajectory rows.
    #[serde(default)]
    pub output: OutputTable,
    /// The operating point of `eom linear`.
    pub linear: Option<crate::scene::envelope::LinearTable>,
    /// Values to sweep over (read by [`crate::scene::sweep`], which runs each case).
    pub sweep: Option<toml::Table>,
    /// A Monte Carlo's laws (read by [`crate::scene::uncertainty`], which runs each case).
    #[serde(default)]
    pub uncertainty: Option<crate::scene::uncertainty::UncertaintyTable>,
    /// The autopilots.
    pub autopilot: Option<AutopilotTable>,
}

/// `[autopilot]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AutopilotTable {
    /// T_s, s.
    pub sample_s: f64,
    /// The heading autopilot.
    pub heading: Option<HeadingTable>,
    /// The depth autopilot.
    pub depth: Option<DepthTable>,
}

/// `[autopilot.heading]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HeadingTable {
    /// k_p.
    pub kp: f64,
    /// k_i, 1/s.
    #[serde(default)]
    pub ki: f64,
    /// k_d, s.
    #[serde(default)]
    pub kd: f64,
}

/// `[autopilot.depth]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DepthTable {
    /// k_p, rad per m.
    pub kp: f64,
    /// k_i, rad per m s.
    #[serde(default)]
    pub ki: f64,
    /// θ_max, degrees.
    pub max_pitch_deg: f64,
    /// k_p,θ.
    pub kp_pitch: f64,
    /// k_i,θ, 1/s.
    #[serde(default)]
    pub ki_pitch: f64,
    /// k_d,θ, s.
    #[serde(default)]
    pub kd_pitch: f64,
}

/// `[body]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyTable {
    /// M, kg.
    pub mass: f64,
    /// W, N.
    pub weight: f64,
    /// B, N.
    pub buoyancy: f64,
    /// r_G from O, m.
    pub centre_of_gravity: [f64; 3],
    /// r_B from O, m.
    pub centre_of_buoyancy: [f64; 3],
    /// I_xx, I_yy, I_zz, kg m².
    pub inertia: [f64; 3],
    /// I_xy, I_yz, I_xz, kg m², the chapter's sign (−∫xy dm); zero when not given.
    pub products_of_inertia: Option<Vec<f64>>,
    /// `G` (the default) or `origin`: the point the tensor is about.
    pub inertia_about: Option<String>,
}

/// `[hydrodynamics]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HydrodynamicsTable {
    /// `prestero` or `fossen`.
    pub convention: String,
    /// `folded` or `derived`.
    pub added_mass_coriolis: String,
    /// `dimensional` (the default) or `prime`.
    pub units: Option<String>,
    /// ρ, kg/m³ (prime only).
    pub density: Option<f64>,
    /// L, m (prime only).
    pub length: Option<f64>,
    /// The added-mass entries by name.
    pub added_mass: BTreeMap<String, f64>,
    /// The force terms by name.
    pub coefficients: BTreeMap<String, f64>,
    /// The cross-flow drag in strips.
    pub cross_flow: Option<CrossFlowTable>,
}

/// `[hydrodynamics.cross_flow]`: the hull in strips ([`super::cross_flow`]).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CrossFlowTable {
    /// x_i, m.
    pub stations: Vec<f64>,
    /// Δx_i, m.
    pub lengths: Vec<f64>,
    /// H_i, m.
    pub heights: Vec<f64>,
    /// B_i, m.
    pub breadths: Vec<f64>,
    /// C_dy.
    pub sway_coefficient: f64,
    /// C_dz.
    pub heave_coefficient: f64,
    /// ρ, kg/m³: the prime system's by default.
    pub density: Option<f64>,
}

/// `[propeller]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PropellerTable {
    /// `constant` (the default: `thrust` and `torque`) or `healey_lienard` (a law in `rpm`).
    pub law: Option<String>,
    /// X_prop, N (constant).
    pub thrust: Option<f64>,
    /// K_prop, N m (constant).
    pub torque: Option<f64>,
    /// n, rpm (the law).
    pub rpm: Option<f64>,
    /// a in prop = a n/u, m/rad (the law).
    pub advance: Option<f64>,
    /// C_d0 (the law).
    pub drag_coefficient: Option<f64>,
    /// c in C_t = c L² prop|prop|/2 (the law).
    pub thrust_coefficient: Option<f64>,
}

/// `[[manoeuvre]]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ManoeuvreTable {
    /// The output folder's name.
    pub name: Option<String>,
    /// `fin_steps`, `autopilot`, `turning_circle` or `zigzag`.
    pub kind: String,
    /// When the commands step, s.
    pub times_s: Vec<f64>,
    /// The rudder's command from each time on, degrees.
    pub rudder_deg: Option<Vec<f64>>,
    /// The stern planes' command from each time on, degrees.
    pub stern_planes_deg: Option<Vec<f64>>,
    /// The heading the autopilot holds from each time on, degrees.
    pub heading_deg: Option<Vec<f64>>,
    /// The depth the autopilot holds from each time on, m.
    pub depth_m: Option<Vec<f64>>,
    /// A zig-zag's plane: `horizontal` (the rudder, on the heading) or `vertical` (the stern
    /// planes, on the pitch).
    pub plane: Option<String>,
    /// A zig-zag's fin angle, degrees.
    pub fin_deg: Option<f64>,
    /// A zig-zag's switch angle, degrees.
    pub switch_deg: Option<f64>,
    /// The end of the run, s.
    pub duration_s: f64,
}
