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

use super::fins::Fins;
use super::manoeuvre::{ROW, VehicleManoeuvre, first_row};
use super::model::VehicleModel;
use super::table::VehicleTable;
use super::trim::{Held, Trim, TrimError, Trimmer};
use super::{InertiaAbout, VehicleError};
use crate::integrate::Stepper;
use crate::scene::check::Checker;
use crate::scene::stop::StopCondition;
use crate::scene::{Problem, SceneError};
use nalgebra::Matrix3;

pub use super::file::{
    AutopilotTable, BodyTable, CrossFlowTable, DepthTable, HeadingTable, HydrodynamicsTable,
    ManoeuvreTable, PropellerTable, VehicleSceneFile,
};

/// Gravity at the Earth's surface, m/s²: at the equator and at the poles (the normal gravity
/// of the WGS 84 ellipsoid), the range `body.weight / body.mass` may take.
pub(super) const GRAVITY: (f64, f64) = (9.780, 9.832);

/// Half a unit in the last significant digit of `x` as written: its shortest form that reads
/// back to the same number (30.48 → 0.005, 299 → 0.5).
pub(super) fn written_rounding(x: f64) -> f64 {
    let text = format!("{x:e}");
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let digits = mantissa.chars().filter(char::is_ascii_digit).count() as i32;
    let exponent: i32 = exponent.parse().unwrap_or(0);
    0.5 * 10f64.powi(exponent - (digits - 1))
}

/// The keys a manoeuvre's name is made from where the scene gives it none: its `kind`.
pub const NAMED_FROM: [&str; 1] = ["kind"];

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
            let names = manoeuvres.iter().map(|m| m.name.as_str());
            check.unique_manoeuvre(index, &manoeuvre.name, names)?;
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
