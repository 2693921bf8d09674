//! The vehicle scene: `[model] family = "vehicle"` with a `[hydrodynamics]` table, the body,
//! the propeller, the fins and the `[[manoeuvre]]`s to run.
//!
//! ```toml
//! title = "…"
//!
//! [model]
//! family = "vehicle"                 # six degrees of freedom about the table's origin O
//!
//! [body]                             # SI, body axes at O (x forward, y starboard, z down)
//! mass = 30.48                       # M, kg
//! weight = 299.0                     # W, N
//! buoyancy = 299.0                   # B, N
//! centre_of_gravity = [0, 0, 0.0196] # r_G from O, m
//! centre_of_buoyancy = [0, 0, 0]     # r_B from O, m
//! inertia = [0.177, 3.45, 3.45]      # I_xx, I_yy, I_zz, kg m²
//! # products_of_inertia = [0, 0, 0]  # I_xy, I_yz, I_xz (4.14: −∫xy dm); zero by default
//! # inertia_about = "origin"         # "G" (the default) or the table's origin O
//!
//! [hydrodynamics]
//! convention = "prestero"            # or "fossen": how the names are read
//! added_mass_coriolis = "folded"     # or "derived": eom adds Kirchhoff's terms
//! # units = "prime"                  # or "dimensional" (the default): the prime system, with
//! # density = 1025.0                 #   ρ, kg/m³, and
//! # length = 5.3                     #   L, m (prime only), U = u
//!
//! [hydrodynamics.added_mass]         # Xudot, Yvdot, Yrdot, …
//! [hydrodynamics.coefficients]       # the terms to model, and only those; controls dr, ds
//! # [hydrodynamics.cross_flow]       # optional: the cross-flow drag of the hull in strips
//! # stations = [-0.6, 0.0, 0.6]      # x_i from O, m
//! # lengths = [0.6, 0.6, 0.6]        # Δx_i, m
//! # heights = [0.19, 0.19, 0.19]     # H_i, m (the sway flow's)
//! # breadths = [0.19, 0.19, 0.19]    # B_i, m (the heave flow's)
//! # sway_coefficient = 0.5           # C_dy
//! # heave_coefficient = 0.6          # C_dz
//! # density = 1025.0                 # ρ, kg/m³ (the prime system's by default)
//!
//! [propeller]                        # constant thrust and torque at the setting
//! thrust = 3.86                      # X_prop, N
//! torque = -0.543                    # K_prop, N m
//! # law = "healey_lienard"           # or the NPS AUV II's law in its rate (prime tables):
//! # rpm = 1300.0                     #   n, and prop = advance n/u, thrust ½ρL²C_d0(a n)²,
//! # advance = 0.012                  #   ε of C_t = c L² prop|prop|/2 for the terms in `n`
//! # drag_coefficient = 0.00385       #   C_d0
//! # thrust_coefficient = 0.008       #   c
//!
//! [rudder]                           # and [stern_planes]: every key optional
//! max_deg = 13.6
//! max_rate_deg_s = 20.0              # needs the lag
//! time_constant_s = 0.1
//!
//! [integrator]
//! method = "rk4"
//! step = 0.01
//! # stop_when = "z > 20"             # ends each manoeuvre where it first holds (t, a row's names)
//!
//! [autopilot]                        # optional: the autopilots, sampled every sample_s
//! sample_s = 0.1
//! [autopilot.heading]                # PID on ψ to the rudder; gains positive
//! kp = 1.0                           # rad of rudder per rad of heading error
//! ki = 0.0                           # 1/s
//! kd = 0.5                           # s
//! [autopilot.depth]                  # depth to pitch (kp, ki, max_pitch_deg) to the planes
//! kp = 0.2                           # rad of pitch per m of depth error
//! ki = 0.0                           # rad per m s
//! max_pitch_deg = 20.0
//! kp_pitch = 1.0                     # rad of planes per rad of pitch error
//! ki_pitch = 0.0                     # 1/s
//! kd_pitch = 0.5                     # s
//!
//! [[manoeuvre]]
//! kind = "fin_steps"                 # the commands step at times_s
//! times_s = [10, 40, 70]
//! rudder_deg = [4, -4, 0]
//! stern_planes_deg = [0, 0, 0]       # optional: zero
//! duration_s = 80
//!
//! [[manoeuvre]]
//! kind = "autopilot"                 # the autopilots hold what is commanded from times_s on
//! times_s = [5]
//! heading_deg = [30]                 # needs [autopilot.heading]
//! depth_m = [5]                      # needs [autopilot.depth]
//! duration_s = 80
//! ```
//!
//! Every run starts from the trim at the propeller's setting ([`super::trim`]): at the origin,
//! heading north, fins at zero, u and the roll angle φ trimmed so that u̇ = ṗ = 0 (Newton on
//! the proved model and its proved Jacobian), and where that is not a steady motion (W ≠ B, G
//! and the centre of buoyancy not on one vertical) the whole state but the position and the
//! heading; a scene without a trim ahead is refused. Every key is checked and an error names
//! it by its path.

use super::autopilot::{Autopilots, DepthGains, HeadingGains, Setpoints};
use super::cross_flow::CrossFlow;
use super::fins::{FinSteps, Fins};
use super::manoeuvre::{ROW, VehicleManoeuvre, first_row};
use super::model::VehicleModel;
use super::propeller::PropellerLaw;
use super::table::{PrimeScales, PropellerSetting, VehicleTable};
use super::trial::{Plane, Trial};
use super::trim::{Held, Trim, TrimError, Trimmer};
use super::{AddedMassCoriolis, Convention, InertiaAbout, VehicleError};
use crate::integrate::Stepper;
use crate::scene::check::Checker;
use crate::scene::envelope::{FamilyTable, IntegratorTable, OutputTable, SteeringGearTable};
use crate::scene::stop::StopCondition;
use crate::scene::{Problem, SceneError};
use crate::{InertiaTensor, Short, counted};
use nalgebra::Matrix3;
use serde::Deserialize;
use std::collections::BTreeMap;

/// Gravity at the Earth's surface, m/s²: at the equator and at the poles (the normal gravity
/// of the WGS 84 ellipsoid), the range `body.weight / body.mass` may take.
const GRAVITY: (f64, f64) = (9.780, 9.832);

/// Half a unit in the last significant digit of `x` as written: its shortest form that reads
/// back to the same number (30.48 → 0.005, 299 → 0.5).
fn written_rounding(x: f64) -> f64 {
    let text = format!("{x:e}");
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let digits = mantissa.chars().filter(char::is_ascii_digit).count() as i32;
    let exponent: i32 = exponent.parse().unwrap_or(0);
    0.5 * 10f64.powi(exponent - (digits - 1))
}

/// The keys a manoeuvre's name is made from where the scene gives it none: its `kind`.
pub const NAMED_FROM: [&str; 1] = ["kind"];

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

/// A vehicle scene, checked, its model built and proved, ready to run.
#[derive(Debug, Clone)]
pub struct VehicleScene {
    /// The title.
    pub title: String,
    /// The table.
    pub table: VehicleTable,
    /// The model of the table.
    pub model: VehicleModel,
    /// The fins' steering gears.
    pub fins: Fins,
    /// The method.
    pub stepper: Stepper,
    /// A trajectory row at t = k·every, s.
    pub every: f64,
    /// The manoeuvres.
    pub manoeuvres: Vec<VehicleManoeuvre>,
    /// The operating point of `eom linear` (`[linear]`), by default the trim.
    pub linear: crate::linear::LinearSpec,
    /// The steady motion every manoeuvre starts from.
    pub trim: Trim,
    /// `integrator.stop_when`: the condition on a manoeuvre's row (t and [`ROW`]'s names)
    /// that ends each run where it first holds.
    pub stop: Option<StopCondition>,
}

impl Checker<'_> {
    fn vehicle_table(&self, file: &VehicleSceneFile) -> Result<VehicleTable, SceneError> {
        let body = &file.body;
        let vector = |key: &str, v: [f64; 3]| -> Result<[f64; 3], SceneError> {
            for (i, x) in v.iter().enumerate() {
                self.finite(&format!("body.{key}[{i}]"), *x)?;
            }
            Ok(v)
        };
        let mass = self.positive("body.mass", body.mass)?;
        let centre_of_gravity = vector("centre_of_gravity", body.centre_of_gravity)?;
        let (inertia, inertia_about) = self.vehicle_inertia(body, mass, centre_of_gravity)?;
        let hydro = &file.hydrodynamics;
        let convention = self.word(
            "hydrodynamics.convention",
            &hydro.convention,
            [
                (Convention::Prestero, "prestero"),
                (Convention::Fossen, "fossen"),
            ],
        )?;
        let added_mass_coriolis = self.word(
            "hydrodynamics.added_mass_coriolis",
            &hydro.added_mass_coriolis,
            [
                (AddedMassCoriolis::Folded, "folded"),
                (AddedMassCoriolis::Derived, "derived"),
            ],
        )?;
        for (table, entries) in [
            ("added_mass", &hydro.added_mass),
            ("coefficients", &hydro.coefficients),
        ] {
            for (name, value) in entries {
                self.finite(&format!("hydrodynamics.{table}.{name}"), *value)?;
                if table == "coefficients" && name.ends_with("dot") {
                    return Err(self.invalid(
                        &format!("hydrodynamics.coefficients.{name}"),
                        "an added-mass entry: give it in [hydrodynamics.added_mass]",
                    ));
                }
            }
        }
        let prime = self.prime_scales(hydro)?;
        let Some(propeller) = file.propeller.as_ref() else {
            return Err(self.error(
                "propeller",
                Problem::Missing(
                    "[propeller]: every manoeuvre starts from the cruise its thrust makes".into(),
                ),
            ));
        };
        let propeller = self.vehicle_propeller(propeller, prime)?;
        let weight = self.positive("body.weight", body.weight)?;
        self.mass_against_weight(mass, weight)?;
        Ok(VehicleTable {
            mass,
            weight,
            buoyancy: self.positive("body.buoyancy", body.buoyancy)?,
            centre_of_gravity,
            centre_of_buoyancy: vector("centre_of_buoyancy", body.centre_of_buoyancy)?,
            inertia,
            inertia_about,
            convention,
            added_mass_coriolis,
            added_mass: hydro.added_mass.clone(),
            coefficients: hydro.coefficients.clone(),
            propeller: Some(propeller),
            prime,
            cross_flow: (hydro.cross_flow.as_ref())
                .map(|c| self.cross_flow(c, prime))
                .transpose()?,
        })
    }

    /// `body.mass` against `body.weight`: W/M is gravity at the Earth's surface, 9.780 m/s² at
    /// the equator to 9.832 at the poles, to the rounding of the two numbers as written (half
    /// a unit in the last significant digit of each). A mass that contradicts its weight (a
    /// payload added to one and not the other) would make every motion wrong by their ratio.
    fn mass_against_weight(&self, mass: f64, weight: f64) -> Result<(), SceneError> {
        let (m, w) = (written_rounding(mass), written_rounding(weight));
        let (lowest, highest) = (
            (weight - w) / (mass + m),
            (weight + w) / (mass - m).max(0.0),
        );
        if highest >= GRAVITY.0 && lowest <= GRAVITY.1 {
            return Ok(());
        }
        Err(self.invalid(
            "body.mass",
            format!(
                "{} kg contradicts `body.weight` = {} N: W/M = {} m/s², where gravity at the \
                 Earth's surface is {} to {} m/s² (M = W/g is {} kg at g = 9.81 m/s²)",
                Short(mass),
                Short(weight),
                Short(weight / mass),
                GRAVITY.0,
                GRAVITY.1,
                Short(weight / 9.81)
            ),
        ))
    }

    /// `body.inertia` and `body.products_of_inertia` as a tensor and the point it is about
    /// (`body.inertia_about`): a physical
    /// tensor (symmetric, positive definite, each moment at most the sum of the other two),
    /// and about O one whose tensor about G, less M(|r_G|²1 − r_G r_Gᵀ) by 4.23, is physical
    /// too.
    fn vehicle_inertia(
        &self,
        body: &BodyTable,
        mass: f64,
        r_g: [f64; 3],
    ) -> Result<([[f64; 3]; 3], InertiaAbout), SceneError> {
        let mut tensor = [[0.0; 3]; 3];
        for (i, x) in body.inertia.iter().enumerate() {
            tensor[i][i] = self.positive(&format!("body.inertia[{i}]"), *x)?;
        }
        let key = "body.products_of_inertia";
        if let Some(products) = &body.products_of_inertia {
            if products.len() != 3 {
                return Err(self.invalid(
                    key,
                    format!(
                        "give three products [Ixy, Iyz, Ixz], not {}",
                        products.len()
                    ),
                ));
            }
            for ((i, x), (r, c)) in products.iter().enumerate().zip([(0, 1), (1, 2), (0, 2)]) {
                tensor[r][c] = self.finite(&format!("{key}[{i}]"), *x)?;
                tensor[c][r] = tensor[r][c];
            }
        }
        let about = match &body.inertia_about {
            Some(word) => self.word(
                "body.inertia_about",
                word,
                [
                    (InertiaAbout::Gravity, "G"),
                    (InertiaAbout::Origin, "origin"),
                ],
            )?,
            None => InertiaAbout::Gravity,
        };
        let physical = |m: [[f64; 3]; 3], what: &str| {
            InertiaTensor::from_matrix(Matrix3::from_fn(|r, c| m[r][c]))
                .map(|_| ())
                .map_err(|e| self.invalid("body.inertia", format!("{what}{e}")))
        };
        physical(tensor, "")?;
        if about == InertiaAbout::Origin {
            let squared: f64 = r_g.iter().map(|x| x * x).sum();
            let mut about_g = tensor;
            for (r, row) in about_g.iter_mut().enumerate() {
                for (c, entry) in row.iter_mut().enumerate() {
                    let identity = if r == c { squared } else { 0.0 };
                    *entry -= mass * (identity - r_g[r] * r_g[c]);
                }
            }
            physical(
                about_g,
                "about G (4.23, the tensor about O less M(|r_G|²1 − r_G r_Gᵀ)): ",
            )?;
        }
        Ok((tensor, about))
    }

    /// `[propeller]`: constant thrust and torque, or the law in the propeller's rate (in the
    /// prime system, whose ρ and L it reads), each refusing the other's keys.
    fn vehicle_propeller(
        &self,
        p: &PropellerTable,
        prime: Option<PrimeScales>,
    ) -> Result<PropellerSetting, SceneError> {
        let law = match &p.law {
            Some(word) => self.word(
                "propeller.law",
                word,
                [(false, "constant"), (true, "healey_lienard")],
            )?,
            None => false,
        };
        let given = |key: &str, value: Option<f64>| match value {
            Some(x) => Ok(x),
            None => Err(self.error(
                &format!("propeller.{key}"),
                Problem::Missing(format!(
                    "the law `{}` needs it",
                    if law { "healey_lienard" } else { "constant" }
                )),
            )),
        };
        let refused = |key: &str, value: Option<f64>, why: &str| match value {
            Some(_) => Err(self.invalid(&format!("propeller.{key}"), why)),
            None => Ok(()),
        };
        if !law {
            for (key, value) in [
                ("rpm", p.rpm),
                ("advance", p.advance),
                ("drag_coefficient", p.drag_coefficient),
                ("thrust_coefficient", p.thrust_coefficient),
            ] {
                refused(
                    key,
                    value,
                    "only a law reads it: give propeller.law = \"healey_lienard\"",
                )?;
            }
            return Ok(PropellerSetting {
                thrust: self.thrust(given("thrust", p.thrust)?)?,
                torque: self.finite("propeller.torque", given("torque", p.torque)?)?,
                law: None,
            });
        }
        refused(
            "thrust",
            p.thrust,
            "the law gives the thrust: ½ρL²C_d0(a n)²",
        )?;
        let Some(scales) = prime else {
            return Err(self.invalid(
                "propeller.law",
                "the law is in the prime system: give hydrodynamics.units = \"prime\"",
            ));
        };
        let positive = |key: &str, value: Option<f64>| {
            self.positive(&format!("propeller.{key}"), given(key, value)?)
        };
        let law = PropellerLaw {
            rpm: positive("rpm", p.rpm)?,
            advance: positive("advance", p.advance)?,
            drag_coefficient: positive("drag_coefficient", p.drag_coefficient)?,
            thrust_coefficient: positive("thrust_coefficient", p.thrust_coefficient)?,
            density: scales.density,
            length: scales.length,
        };
        Ok(PropellerSetting {
            thrust: law.thrust(),
            torque: self.finite("propeller.torque", p.torque.unwrap_or(0.0))?,
            law: Some(law),
        })
    }

    /// `propeller.thrust`, positive: every manoeuvre starts from the cruise it makes ahead. At
    /// zero the vehicle lies at rest, where its fins act on nothing; a negative thrust drives
    /// it astern, outside a table identified going ahead.
    fn thrust(&self, thrust: f64) -> Result<f64, SceneError> {
        let key = "propeller.thrust";
        let thrust = self.finite(key, thrust)?;
        if thrust > 0.0 {
            return Ok(thrust);
        }
        Err(self.invalid(
            key,
            if thrust == 0.0 {
                "zero thrust: every manoeuvre starts from the cruise the thrust makes, and \
                 without one the vehicle lies at rest, where its fins turn it not at all"
            } else {
                "a negative thrust drives the vehicle astern, outside a table identified going \
                 ahead: give the thrust ahead, positive"
            },
        ))
    }

    /// `[hydrodynamics.cross_flow]`: strips of one length each (the stations' count), finite
    /// stations, positive lengths, heights, breadths, coefficients and ρ (the prime system's
    /// unless given).
    fn cross_flow(
        &self,
        table: &CrossFlowTable,
        prime: Option<PrimeScales>,
    ) -> Result<CrossFlow, SceneError> {
        let key = |k: &str| format!("hydrodynamics.cross_flow.{k}");
        let count = table.stations.len();
        if count == 0 {
            return Err(self.invalid(&key("stations"), "give at least one strip"));
        }
        let strips = |k: &str, values: &[f64], positive: bool| -> Result<Vec<f64>, SceneError> {
            if values.len() != count {
                return Err(self.invalid(
                    &key(k),
                    format!(
                        "{}, one per strip: stations has {count}",
                        counted(values.len(), "entry", "entries")
                    ),
                ));
            }
            (values.iter().enumerate())
                .map(|(i, x)| match positive {
                    true => self.positive(&format!("{}[{i}]", key(k)), *x),
                    false => self.finite(&format!("{}[{i}]", key(k)), *x),
                })
                .collect()
        };
        let density = match (table.density, prime) {
            (Some(rho), _) => self.positive(&key("density"), rho)?,
            (None, Some(scales)) => scales.density,
            (None, None) => {
                return Err(self.error(
                    &key("density"),
                    Problem::Missing("a dimensional table has no ρ of its own".into()),
                ));
            }
        };
        Ok(CrossFlow {
            stations: strips("stations", &table.stations, false)?,
            lengths: strips("lengths", &table.lengths, true)?,
            heights: strips("heights", &table.heights, true)?,
            breadths: strips("breadths", &table.breadths, true)?,
            sway_coefficient: self.positive(&key("sway_coefficient"), table.sway_coefficient)?,
            heave_coefficient: self.positive(&key("heave_coefficient"), table.heave_coefficient)?,
            density,
        })
    }

    /// The prime system's ρ and L where `hydrodynamics.units` is `prime` (each then
    /// required), none in SI (where each is refused).
    fn prime_scales(&self, hydro: &HydrodynamicsTable) -> Result<Option<PrimeScales>, SceneError> {
        let prime = match &hydro.units {
            Some(units) => self.word(
                "hydrodynamics.units",
                units,
                [(true, "prime"), (false, "dimensional")],
            )?,
            None => false,
        };
        let scale = |key: &str, value: Option<f64>, what: &str| match (prime, value) {
            (true, Some(x)) => self.positive(key, x).map(Some),
            (true, None) => Err(self.error(
                key,
                Problem::Missing(format!("the prime system needs {what}")),
            )),
            (false, Some(_)) => Err(self.invalid(
                key,
                format!("only the prime system uses {what}: a dimensional table would ignore it"),
            )),
            (false, None) => Ok(None),
        };
        let density = scale("hydrodynamics.density", hydro.density, "ρ")?;
        let length = scale("hydrodynamics.length", hydro.length, "L")?;
        Ok(density
            .zip(length)
            .map(|(density, length)| PrimeScales { density, length }))
    }

    /// Manoeuvre `index`, from `trim` (the scene's; one held by its autopilots is set by
    /// [`Checker::held_trim`]).
    fn vehicle_manoeuvre(
        &self,
        index: usize,
        table: &ManoeuvreTable,
        autopilots: Option<&Autopilots>,
        trim: Trim,
    ) -> Result<VehicleManoeuvre, SceneError> {
        let key = |k: &str| format!("manoeuvre[{index}].{k}");
        let duration = self.positive(&key("duration_s"), table.duration_s)?;
        let n = table.times_s.len();
        let listed = |k: &str, given: &Option<Vec<f64>>| self.listed(&key(k), given, n);
        let angles = |k: &str, given: &Option<Vec<f64>>| -> Result<Vec<f64>, SceneError> {
            let degrees = listed(k, given)?.unwrap_or_else(|| vec![0.0; n]);
            Ok(degrees.iter().map(|d| d.to_radians()).collect())
        };
        let zigzag_keys = [
            ("plane", table.plane.is_some()),
            ("fin_deg", table.fin_deg.is_some()),
            ("switch_deg", table.switch_deg.is_some()),
        ];
        if table.kind != "zigzag"
            && let Some((k, _)) = zigzag_keys.iter().find(|(_, given)| *given)
        {
            return Err(self.invalid(&key(k), "only a zigzag manoeuvre takes it"));
        }
        let (rudder, stern, autopilot, trial) = match table.kind.as_str() {
            kind @ ("fin_steps" | "turning_circle") => {
                let circle = kind == "turning_circle";
                // A turning circle may hold its depth: the depth autopilot works the planes.
                for (k, given, allowed) in [
                    ("heading_deg", table.heading_deg.is_some(), false),
                    ("depth_m", table.depth_m.is_some(), circle),
                ] {
                    if given && !allowed {
                        return Err(self.invalid(
                            &key(k),
                            format!(
                                "a {kind} manoeuvre commands the fins; kind = \"autopilot\" \
                                 commands headings and depths"
                            ),
                        ));
                    }
                }
                let trial = circle.then(|| Trial::TurningCircle {
                    execute: table.times_s.first().copied().unwrap_or(0.0),
                });
                if circle
                    && (table.rudder_deg.is_none() || table.stern_planes_deg.is_some() || n != 1)
                {
                    return Err(self.invalid(
                        &key("rudder_deg"),
                        "a turning circle holds one rudder angle from one time: times_s = [t], \
                         rudder_deg = [δ]",
                    ));
                }
                if table.rudder_deg.is_none() && table.stern_planes_deg.is_none() {
                    return Err(self.error(
                        &key("rudder_deg"),
                        Problem::Missing("rudder_deg or stern_planes_deg".into()),
                    ));
                }
                let rudder = angles("rudder_deg", &table.rudder_deg)?;
                let stern = angles("stern_planes_deg", &table.stern_planes_deg)?;
                let setpoints = (table.depth_m.is_some())
                    .then(|| self.setpoints(index, table, autopilots))
                    .transpose()?;
                (rudder, stern, setpoints, trial)
            }
            "autopilot" => {
                let setpoints = self.setpoints(index, table, autopilots)?;
                let rudder = angles("rudder_deg", &table.rudder_deg)?;
                let stern = angles("stern_planes_deg", &table.stern_planes_deg)?;
                (rudder, stern, Some(setpoints), None)
            }
            "zigzag" => {
                let trial = self.zigzag(index, table)?;
                let held = table.heading_deg.is_some() || table.depth_m.is_some();
                let setpoints = held
                    .then(|| self.setpoints(index, table, autopilots))
                    .transpose()?;
                (vec![0.0; n], vec![0.0; n], setpoints, Some(trial))
            }
            other => {
                return Err(self.invalid(
                    &key("kind"),
                    format!("`{other}`: expected fin_steps, autopilot, turning_circle or zigzag"),
                ));
            }
        };
        let pairs = rudder.into_iter().zip(stern).map(|(r, s)| [r, s]).collect();
        let steps = FinSteps::new(table.times_s.clone(), pairs).ok_or_else(|| {
            self.invalid(
                &key("times_s"),
                "the times and angles must be finite, at least one, the times strictly \
                 increasing",
            )
        })?;
        if table.times_s[0] < 0.0 || table.times_s[0] >= duration {
            return Err(self.invalid(&key("times_s"), "the first step must fall within the run"));
        }
        let name = (table.name.clone()).unwrap_or_else(|| table.kind.clone());
        let valid = !name.is_empty()
            && name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-' || c == '.')
            && name != "."
            && name != "..";
        if !valid {
            return Err(self.invalid(
                &key("name"),
                format!("`{name}` must be a folder name: letters, digits, _ - ."),
            ));
        }
        Ok(VehicleManoeuvre {
            name,
            steps,
            autopilot,
            trial,
            duration,
            trim,
        })
    }

    /// The trim of manoeuvre `index`, whose autopilots hold `held` from its start: the fins
    /// they work at their trim within their stops, and the pitch within the depth
    /// autopilot's `max_pitch_deg`, since the autopilots could not hold it beyond.
    fn held_trim(
        &self,
        index: usize,
        trimmer: &mut Trimmer<'_>,
        held: Held,
        fins: &Fins,
        file: &VehicleSceneFile,
    ) -> Result<Trim, SceneError> {
        let asking = if held.depth { "depth_m" } else { "heading_deg" };
        let key = format!("manoeuvre[{index}].{asking}");
        let trim = trimmer
            .trim(held)
            .map_err(|e| self.invalid(&key, e.to_string()))?;
        let beyond = |angle: f64, limit: Option<f64>| limit.is_some_and(|max| angle.abs() > max);
        let gears = [
            (
                held.heading,
                "rudder",
                fins.rudder.max_angle,
                trim.state[13],
            ),
            (
                held.depth,
                "stern_planes",
                fins.stern_planes.max_angle,
                trim.state[14],
            ),
        ];
        for (holds, fin, stop, angle) in gears {
            if holds && beyond(angle, stop) {
                return Err(self.invalid(
                    &key,
                    format!(
                        "the steady motion its autopilots hold from the start needs the {} at \
                         {}°, beyond `{fin}.max_deg` = {}°",
                        fin.replace('_', " "),
                        Short(angle.to_degrees()),
                        Short(stop.unwrap_or(0.0).to_degrees())
                    ),
                ));
            }
        }
        let pitch = crate::kinds::vehicle::manoeuvre::euler_angles(&trim.state)[1];
        let max_pitch = (file.autopilot.as_ref())
            .and_then(|a| a.depth.as_ref())
            .map(|d| d.max_pitch_deg);
        if let Some(max) = max_pitch.filter(|max| held.depth && pitch.to_degrees().abs() > *max) {
            return Err(self.invalid(
                &key,
                format!(
                    "the steady motion with the depth held pitches {}°, beyond \
                     `autopilot.depth.max_pitch_deg` = {}°, which the autopilot cannot command",
                    Short(pitch.to_degrees()),
                    Short(max)
                ),
            ));
        }
        Ok(trim)
    }

    /// The fins' commands of manoeuvre `index` within their stops (`rudder.max_deg`,
    /// `stern_planes.max_deg`): a fin commanded beyond its stop would run at the stop while the
    /// manoeuvre is labelled and judged at the angle asked for. A zig-zag's `fin_deg` is its
    /// plane's fin's command.
    fn within_stops(
        &self,
        index: usize,
        table: &ManoeuvreTable,
        rudder: &SteeringGearTable,
        stern_planes: &SteeringGearTable,
    ) -> Result<(), SceneError> {
        let key = |k: &str| format!("manoeuvre[{index}].{k}");
        let vertical = table.plane.as_deref() == Some("vertical");
        let zigzag_fin = if vertical { "stern_planes" } else { "rudder" };
        let fins = [("rudder", rudder), ("stern_planes", stern_planes)];
        for (fin, gear) in fins {
            let Some(stop) = gear.max_deg else { continue };
            let mut commands: Vec<(String, f64)> = Vec::new();
            let steps = if fin == "rudder" {
                &table.rudder_deg
            } else {
                &table.stern_planes_deg
            };
            for (i, angle) in steps.iter().flatten().enumerate() {
                commands.push((key(&format!("{fin}_deg[{i}]")), *angle));
            }
            if let Some(angle) = table.fin_deg.filter(|_| fin == zigzag_fin) {
                commands.push((key("fin_deg"), angle));
            }
            if let Some((command, angle)) = commands.iter().find(|(_, a)| a.abs() > stop) {
                return Err(self.invalid(
                    command,
                    format!(
                        "{}° is beyond the {}'s stop `{fin}.max_deg` = {}°: the fin would run \
                         at {}° while the manoeuvre is labelled and judged at {}°",
                        Short(*angle),
                        fin.replace('_', " "),
                        Short(stop),
                        Short(stop.copysign(*angle)),
                        Short(*angle)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// A zig-zag: its plane, fin and switch angles, its execute at times_s[0]; the fin it
    /// switches is not also an autopilot's.
    fn zigzag(&self, index: usize, table: &ManoeuvreTable) -> Result<Trial, SceneError> {
        let key = |k: &str| format!("manoeuvre[{index}].{k}");
        let plane = self.word(
            &key("plane"),
            table.plane.as_deref().unwrap_or("horizontal"),
            [
                (Plane::Horizontal, "horizontal"),
                (Plane::Vertical, "vertical"),
            ],
        )?;
        let angle = |k: &str, value: Option<f64>, below: f64| -> Result<f64, SceneError> {
            let value = value.ok_or_else(|| self.error(&key(k), Problem::Missing(k.into())))?;
            let value = self.positive(&key(k), value)?;
            if value >= below {
                return Err(self.invalid(&key(k), format!("must be below {below}°")));
            }
            Ok(value.to_radians())
        };
        let fin = angle("fin_deg", table.fin_deg, 90.0)?;
        let switch = angle("switch_deg", table.switch_deg, 90.0)?;
        for (fin_key, given, in_plane) in [
            ("rudder_deg", table.rudder_deg.is_some(), true),
            ("stern_planes_deg", table.stern_planes_deg.is_some(), true),
            (
                "heading_deg",
                table.heading_deg.is_some(),
                plane == Plane::Horizontal,
            ),
            ("depth_m", table.depth_m.is_some(), plane == Plane::Vertical),
        ] {
            if given && in_plane {
                return Err(self.invalid(
                    &key(fin_key),
                    "a zigzag commands its fin itself; only the other plane's autopilot may \
                     hold a setpoint (heading_deg in a vertical zigzag, depth_m in a \
                     horizontal one)",
                ));
            }
        }
        if table.times_s.len() != 1 {
            return Err(self.invalid(&key("times_s"), "a zigzag has one execute: times_s = [t]"));
        }
        Ok(Trial::ZigZag {
            plane,
            fin,
            switch,
            execute: table.times_s[0],
        })
    }

    /// A list of `n` finite values, one per time, if given.
    fn listed(
        &self,
        key: &str,
        given: &Option<Vec<f64>>,
        n: usize,
    ) -> Result<Option<Vec<f64>>, SceneError> {
        let Some(values) = given else {
            return Ok(None);
        };
        if values.len() != n {
            let given = counted(values.len(), "value", "values");
            let times = counted(n, "time", "times");
            return Err(self.invalid(key, format!("{given} for {times}")));
        }
        for (i, v) in values.iter().enumerate() {
            self.finite(&format!("{key}[{i}]"), *v)?;
        }
        Ok(Some(values.clone()))
    }

    /// An autopilot manoeuvre's setpoints, each list needing its autopilot, with the scene's
    /// autopilots.
    fn setpoints(
        &self,
        index: usize,
        table: &ManoeuvreTable,
        autopilots: Option<&Autopilots>,
    ) -> Result<(Autopilots, Setpoints), SceneError> {
        let key = |k: &str| format!("manoeuvre[{index}].{k}");
        let listed =
            |k: &str, given: &Option<Vec<f64>>| self.listed(&key(k), given, table.times_s.len());
        let heading = listed("heading_deg", &table.heading_deg)?;
        let depth = listed("depth_m", &table.depth_m)?;
        for (fin, given, held, by) in [
            ("rudder_deg", &table.rudder_deg, &heading, "heading_deg"),
            (
                "stern_planes_deg",
                &table.stern_planes_deg,
                &depth,
                "depth_m",
            ),
        ] {
            if given.is_some() && held.is_some() {
                return Err(self.invalid(
                    &key(fin),
                    format!("the autopilot holding {by} commands this fin: give one or the other"),
                ));
            }
        }
        if heading.is_none() && depth.is_none() {
            return Err(self.error(
                &key("heading_deg"),
                Problem::Missing("heading_deg or depth_m".into()),
            ));
        }
        let on = |k: &str, needed: bool, has: bool, which: &str| {
            if needed && !has {
                Err(self.error(
                    &key(k),
                    Problem::Missing(format!("[autopilot.{which}] to hold it")),
                ))
            } else {
                Ok(())
            }
        };
        let (has_heading, has_depth) =
            autopilots.map_or((false, false), |a| (a.heading.is_some(), a.depth.is_some()));
        on("heading_deg", heading.is_some(), has_heading, "heading")?;
        on("depth_m", depth.is_some(), has_depth, "depth")?;
        let setpoints = Setpoints {
            times: table.times_s.clone(),
            heading_deg: heading,
            depth,
        };
        match autopilots {
            Some(autopilots) => Ok((*autopilots, setpoints)),
            None => Err(self.error(&key("heading_deg"), Problem::Missing("[autopilot]".into()))),
        }
    }

    /// `[autopilot]`: the gains, positive, and each fin's sense on `model` at its trim `start`.
    fn autopilots(
        &self,
        table: &AutopilotTable,
        model: &VehicleModel,
        start: &[f64; 15],
    ) -> Result<Autopilots, SceneError> {
        let sample = self.positive("autopilot.sample_s", table.sample_s)?;
        let gain = |key: &str, value: f64| -> Result<f64, SceneError> {
            self.finite(key, value)?;
            if value < 0.0 {
                return Err(self.invalid(
                    key,
                    "gains are positive: the fin's sense comes from the vehicle's own \
                     Jacobian (see docs/vehicles.md)",
                ));
            }
            Ok(value)
        };
        let heading = table
            .heading
            .as_ref()
            .map(|h| -> Result<HeadingGains, SceneError> {
                Ok(HeadingGains {
                    kp: gain("autopilot.heading.kp", h.kp)?,
                    ki: gain("autopilot.heading.ki", h.ki)?,
                    kd: gain("autopilot.heading.kd", h.kd)?,
                })
            })
            .transpose()?;
        let depth = table
            .depth
            .as_ref()
            .map(|d| -> Result<DepthGains, SceneError> {
                let max = self.positive("autopilot.depth.max_pitch_deg", d.max_pitch_deg)?;
                if max >= 90.0 {
                    return Err(self.invalid("autopilot.depth.max_pitch_deg", "must be below 90°"));
                }
                Ok(DepthGains {
                    kp: gain("autopilot.depth.kp", d.kp)?,
                    ki: gain("autopilot.depth.ki", d.ki)?,
                    max_pitch: max.to_radians(),
                    kp_pitch: gain("autopilot.depth.kp_pitch", d.kp_pitch)?,
                    ki_pitch: gain("autopilot.depth.ki_pitch", d.ki_pitch)?,
                    kd_pitch: gain("autopilot.depth.kd_pitch", d.kd_pitch)?,
                })
            })
            .transpose()?;
        Autopilots::new(model, start, sample, (heading, depth))
            .map_err(|e| self.invalid(&e.key(), e.to_string()))
    }
}

impl VehicleScene {
    /// The body as the view draws it: its mass and its inertia tensor about G, as the table
    /// gives it or from the one about O by 4.23 turned round, I_G = I_O − M(|r_G|² E −
    /// r_G r_Gᵀ).
    pub fn solid(&self) -> crate::output::drawing::Solid {
        let table = &self.table;
        let given = Matrix3::from_fn(|r, c| table.inertia[r][c]);
        let about_g = match table.inertia_about {
            InertiaAbout::Gravity => given,
            InertiaAbout::Origin => {
                let r = nalgebra::Vector3::from(table.centre_of_gravity);
                given - (Matrix3::identity() * r.norm_squared() - r * r.transpose()) * table.mass
            }
        };
        crate::output::drawing::Solid {
            mass: table.mass,
            inertia_about_g: about_g.transpose().into(),
        }
    }

    /// Reads and checks vehicle scene text; `name` is how errors name it.
    pub fn parse(text: &str, name: &str) -> Result<Self, SceneError> {
        let file: VehicleSceneFile = crate::scene::read_as(text, name)?;
        Self::from_file(&file, name)
    }

    /// Checks the tables of a vehicle scene file and builds its model.
    pub fn from_file(file: &VehicleSceneFile, name: &str) -> Result<Self, SceneError> {
        let check = Checker { name };
        if file.model.family != "vehicle" {
            return Err(check.invalid(
                "model.family",
                format!("`{}`: expected `vehicle`", file.model.family),
            ));
        }
        let table = check.vehicle_table(file)?;
        let model =
            VehicleModel::new(&table).map_err(|e| check.invalid(&e.key(), e.to_string()))?;
        let fins = Fins {
            rudder: check.steering_gear("rudder", &file.rudder)?,
            stern_planes: check.steering_gear("stern_planes", &file.stern_planes)?,
        };
        if file.manoeuvre.is_empty() {
            return Err(check.error(
                "manoeuvre",
                Problem::Missing("at least one [[manoeuvre]]".into()),
            ));
        }
        let refused = |e: TrimError| check.invalid(e.key(), e.to_string());
        let mut trimmer = Trimmer::new(&table, &model).map_err(refused)?;
        let trim = trimmer.trim(Held::default()).map_err(refused)?;
        let autopilots = (file.autopilot.as_ref())
            .map(|table| check.autopilots(table, &model, &trim.state))
            .transpose()?;
        let mut manoeuvres: Vec<VehicleManoeuvre> = Vec::new();
        for (index, table) in file.manoeuvre.iter().enumerate() {
            let mut manoeuvre = check.vehicle_manoeuvre(index, table, autopilots.as_ref(), trim)?;
            check.within_stops(index, table, &file.rudder, &file.stern_planes)?;
            let held = manoeuvre.held();
            if held != Held::default() {
                manoeuvre.trim = check.held_trim(index, &mut trimmer, held, &fins, file)?;
            }
            if manoeuvres.iter().any(|m| m.name == manoeuvre.name) {
                return Err(check.invalid(
                    &format!("manoeuvre[{index}].name"),
                    format!("`{}` is taken by an earlier manoeuvre", manoeuvre.name),
                ));
            }
            manoeuvres.push(manoeuvre);
        }
        let longest = manoeuvres.iter().map(|m| m.duration).fold(0.0, f64::max);
        // ν: symplectic Euler kicks the velocities first.
        let (stepper, every) = check.stepping(
            (&file.integrator, &file.output),
            longest,
            ("a vehicle", 0..6),
        )?;
        // Each manoeuvre's first row, from its own trim (made only for a condition to check).
        let starts = manoeuvres.iter().map(|m| {
            let row = first_row(&fins, m, m.trim.state).row();
            (format!(" of manoeuvre `{}`", m.name), row)
        });
        let stop = check.stop_when(file.integrator.stop_when.as_deref(), &ROW, starts)?;
        let (names, body) = (&super::model::EULER_STATE, super::linear::BODY);
        let linear = check.linear(
            file.linear.as_ref(),
            "the vehicle (in Euler angles)",
            (&names[..body], &names[body..], &super::linear::ALIASES),
        )?;
        Ok(VehicleScene {
            title: file.title.clone(),
            table,
            model,
            fins,
            stepper,
            every,
            manoeuvres,
            linear,
            trim,
            stop,
        })
    }

    /// The trim every run starts from (see the module docs): found when the scene was read,
    /// which refuses a scene without one.
    pub fn start(&self) -> Result<[f64; 15], VehicleError> {
        Ok(self.trim.state)
    }
}
