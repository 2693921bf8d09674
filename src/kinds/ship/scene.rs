//! The ship scene: a planar-midship scene with a `[hydrodynamics]` table, a `[rudder]` and
//! the `[[manoeuvre]]`s to run.
//!
//! ```toml
//! title = "…"
//!
//! [model]
//! family = "planar-midship"
//!
//! [body]                       # in the table's units
//! length = 160.93              # L, m (always: the IMO criteria are in ship lengths)
//! mass_prime = 0.00798         # or mass (kg) for a dimensional table
//! izz_midship_prime = 0.000392 # or izz_prime (about G); dimensional: izz (about G) or izz_midship
//! x_g_prime = -0.023           # or x_g (m)
//!
//! [hydrodynamics]
//! units = "prime"              # or "dimensional"
//! rigid_body_terms = "folded"  # or "separate" (see eom::kinds::ship::table)
//! density = 1025.0             # ρ, kg/m³ (prime only)
//! design_speed = 7.7175        # U₀, m/s: the approach speed, and the surge perturbation's reference
//!
//! [hydrodynamics.coefficients] # the terms to model, and only those
//! Xudot = -0.00042
//! Yv = -0.0116
//! # …
//!
//! [propulsion]                 # optional, prime tables: the propeller and the thrust law
//! diameter = 9.1               # d, m
//! rudder_area = 119.817        # A_R, m²
//! wake_fraction = 0.2          # w
//! thrust_coefficient = 0.59    # K_T of the induced velocity
//! slipstream_factor = 0.95     # k
//! rudder_position_prime = -0.5 # x_R/L
//! thrust = [-0.962e-5, -0.446e-5, 0.0309e-5] # T′_uu, T′_un, T′_nn
//! resistance = 0.00226         # C_R on the wetted surface
//! wetted_surface = 26319.8     # S, m²
//! max_rate_rps_s = 0.0167      # the engine's rate limit
//!
//! [rudder]                     # every key optional
//! max_deg = 40.0               # δ_max
//! max_rate_deg_s = 5.0         # δ̇_max (needs the lag)
//! time_constant_s = 1.0        # the first-order lag
//!
//! [integrator]
//! method = "rk4"               # any method but lie-midpoint; events located on its solution
//! step = 0.1                   # s
//! # stop_when = "u < 1"        # ends each manoeuvre where it first holds (t, a row's names)
//!
//! [[manoeuvre]]
//! kind = "turning_circle"      # turning_circle, zigzag, pull_out, rudder_series, spiral, …
//! rudder_deg = 35.0
//! duration_s = 1200.0
//! # name = "turning_circle_35" # the output folder; made from the kind and angles if absent
//! # execute_s = 0.0            # when the rudder is put over
//! # heading_deg = 10.0         # zigzag: ψ_a
//! # release_s = 300.0          # pull_out: rudder back to zero
//! # times_s = [0, 10, 20]      # rudder_series: the command's times and angles
//! # series_deg = [0, 10, -10]
//! # side = "both"              # turning_circle, zigzag: both (default), port or starboard
//! # astern_rps = -0.64         # crash_stop: the full-astern propeller rate
//!
//! [[manoeuvre]]
//! kind = "spiral"              # Dieudonné's direct spiral; "reverse_spiral": Bech's
//! rudders_deg = [10, 5, 0, -5, -10] # the first pass; the run comes back through them
//! # from_deg = 10.0            # or the first pass as from_deg, to_deg every step_deg
//! # to_deg = -10.0
//! # step_deg = 5.0
//! # yaw_rates_deg_s = [0.2, 0, -0.2] # reverse_spiral: the commanded yaw rates
//! # settle_window_s = 100.0    # r settled: within settle_tolerance_deg_s over the window
//! # settle_tolerance_deg_s = 0.001
//! # max_hold_s = 2000.0        # the longest an angle is held
//! # settle_rudder_deg = 0.01   # reverse_spiral: the mean rudder settled, window to window
//! # settle_speed_m_s = 0.001   # the speed settled: within it over the window
//! # controller_time_s = 20.0   # reverse_spiral: the controller's closed-loop τ
//! ```
//!
//! Every run starts on a straight course at U₀, midship at the origin, heading north, rudder
//! amidships. Every key is checked and an error names it by its path in the file.

use super::linear::LinearModel;
use super::manoeuvre::Manoeuvre;
use super::manoeuvre::ManoeuvreKind::{ReverseSpiral, Spiral};
use super::table::ShipTable;
use crate::integrate::Stepper;
use crate::manoeuvring::steering::Rudder;
use crate::scene::check::Checker;
use crate::scene::stop::StopCondition;
use crate::scene::{Problem, SceneError};
use std::path::Path;

use super::check::Ship;
pub use super::file::{
    BodyTable, HydrodynamicsTable, ManoeuvreTable, PropulsionTable, ShipSceneFile,
};

/// The keys of `[[manoeuvre]]` a manoeuvre's name is made from where the scene gives none
/// (`turning_circle_35`, `zigzag_10_10`).
pub const NAMED_FROM: [&str; 3] = ["kind", "rudder_deg", "heading_deg"];

/// A spiral's settling window by default, s.
pub const SETTLE_WINDOW_S: f64 = 100.0;
/// A spiral's settling tolerance by default, degrees per second.
pub const SETTLE_TOLERANCE_DEG_S: f64 = 0.001;
/// The longest a spiral holds an angle by default, s.
pub const MAX_HOLD_S: f64 = 2000.0;
/// The reverse spiral's settling tolerance on the mean rudder by default, degrees.
pub const SETTLE_RUDDER_DEG: f64 = 0.01;
/// A spiral's settling tolerance on the speed by default, m/s.
pub const SETTLE_SPEED_M_S: f64 = 0.001;
/// The reverse spiral's closed-loop yaw time constant by default, s.
pub const CONTROLLER_TIME_S: f64 = 20.0;

/// A ship scene, checked, ready to run.
#[derive(Debug, Clone)]
pub struct ShipScene {
    /// The title.
    pub title: String,
    /// L, m.
    pub length: f64,
    /// The table, rigid-body terms separate.
    pub table: ShipTable,
    /// The steering gear.
    pub rudder: Rudder,
    /// The method and its settings ([`segment`](crate::integrate::Stepper)).
    pub stepper: Stepper,
    /// A trajectory row at t = k·every, s.
    pub every: f64,
    /// The manoeuvres.
    pub manoeuvres: Vec<Manoeuvre>,
    /// The operating point of `eom linear` (`[linear]`), by default the approach.
    pub linear: crate::linear::LinearSpec,
    /// `integrator.stop_when`: the condition on a manoeuvre's row (t and
    /// [`ROW`](super::manoeuvre::ROW)'s names) that ends each run where it first holds.
    pub stop: Option<StopCondition>,
    /// The file it was read from, without its `[sweep]` and `[uncertainty]`: what another
    /// case's numbers are set into ([`ShipScene::with_coefficients`]).
    file: std::sync::Arc<ShipSceneFile>,
}

impl ShipScene {
    /// Reads and checks a ship scene file.
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path)
            .map_err(|e| SceneError::new(&name, "", Problem::Read(e)))?;
        Self::parse(&text, &name)
    }

    /// Reads and checks ship scene text; `name` is how errors name it.
    pub fn parse(text: &str, name: &str) -> Result<Self, SceneError> {
        let file: ShipSceneFile = crate::scene::read_as(text, name)?;
        Self::from_file(&file, name)
    }

    /// Checks the tables of a ship scene file.
    pub fn from_file(file: &ShipSceneFile, name: &str) -> Result<Self, SceneError> {
        let kept = ShipSceneFile {
            sweep: None,
            uncertainty: None,
            ..file.clone()
        };
        Self::checked(kept, name)
    }

    /// Checks the tables of `owned`, a file without `[sweep]` and `[uncertainty]`, and keeps it.
    fn checked(owned: ShipSceneFile, name: &str) -> Result<Self, SceneError> {
        let file = &owned;
        let check = Checker { name };
        if file.model.family != "planar-midship" {
            return Err(check.invalid(
                "model.family",
                format!(
                    "`{}`: a scene with [hydrodynamics] runs 4.46 at midship, family \
                     `planar-midship`",
                    file.model.family
                ),
            ));
        }
        let (mut table, length) = check.table(file)?;
        if let Some(windage) = &file.windage {
            table.windage = Some(check.windage(windage)?);
        }
        if let Some(environment) = &file.environment {
            table.current = check.current(environment)?;
            table.wind = check.wind(environment, table.windage.is_some())?;
        }
        let rudder = check.steering_gear("rudder", &file.rudder)?;
        let linear = LinearModel::closed_form(&table);
        let table_propulsion = table.propulsion.as_ref();
        if file.manoeuvre.is_empty() {
            return Err(check.error(
                "manoeuvre",
                Problem::Missing("at least one [[manoeuvre]]".into()),
            ));
        }
        // The air moving over the water (a wind, or a current under a windage): the wind's
        // loads turn with the heading, and no turn is steady.
        let windy =
            (table.ship_wind()).is_some_and(|air| air.wind.speed > 0.0 || air.current != [0.0; 2]);
        let mut manoeuvres: Vec<Manoeuvre> = Vec::new();
        for (index, table) in file.manoeuvre.iter().enumerate() {
            let ship = Ship {
                linear: &linear,
                propulsion: table_propulsion,
                rudder: &rudder,
                length,
            };
            let manoeuvre = check.manoeuvre(index, table, ship)?;
            if windy && matches!(manoeuvre.kind, Spiral(_) | ReverseSpiral(_)) {
                return Err(check.invalid(
                    &format!("manoeuvre[{index}].kind"),
                    "a spiral holds the rudder until the turn is steady, and where the air moves \
                     over the water (a wind, or a current under a [windage]) no turn is: the \
                     wind's loads turn with the heading. Run it in still air",
                ));
            }
            let names = manoeuvres.iter().map(|m| m.name.as_str());
            check.unique_manoeuvre(index, &manoeuvre.name, names)?;
            manoeuvres.push(manoeuvre);
        }
        let longest = manoeuvres.iter().map(|m| m.duration).fold(0.0, f64::max);
        // u, v, r: symplectic Euler kicks the velocities first.
        let (stepper, every) =
            check.stepping((&file.integrator, &file.output), longest, ("a ship", 0..3))?;
        // Every manoeuvre starts from the approach, its rudder and command amidships, midship
        // at the origin, no distance run.
        let approach = ShipScene::approach_row(table.design_speed);
        let starts = [(String::new(), approach)];
        let stop = check.stop_when(
            file.integrator.stop_when.as_deref(),
            &super::manoeuvre::ROW,
            starts,
        )?;
        let state = &super::model::STATE;
        let linear = check.linear(
            file.linear.as_ref(),
            "the ship",
            (&state[..6], &state[6..], &super::linear::ALIASES),
        )?;
        Ok(ShipScene {
            title: file.title.clone(),
            length,
            table,
            rudder,
            stepper,
            every,
            manoeuvres,
            linear,
            stop,
            file: std::sync::Arc::new(owned),
        })
    }

    /// The scene with each coefficient its key names (`hydrodynamics.coefficients.Yv`) set to
    /// its value, read from the file as written with those values in it, as the scene read
    /// again from its text would be, without reading the text; `None` where a key names
    /// something else, or a coefficient the table does not have.
    pub fn with_coefficients(
        &self,
        name: &str,
        numbers: &[(&str, f64)],
    ) -> Option<Result<ShipScene, SceneError>> {
        let mut file = (*self.file).clone();
        for (key, value) in numbers {
            let term = key.strip_prefix("hydrodynamics.coefficients.")?;
            *file.hydrodynamics.coefficients.get_mut(term)? = *value;
        }
        Some(ShipScene::checked(file, name))
    }

    /// The row (in [`ROW`](super::manoeuvre::ROW)'s order) of the approach at `speed`, where
    /// every manoeuvre starts.
    fn approach_row(speed: f64) -> [f64; 9] {
        [speed, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    }

    /// The approach: straight ahead at U₀, at the origin, heading north, rudder amidships.
    pub fn start(&self) -> [f64; 7] {
        [self.table.design_speed, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    }
}
