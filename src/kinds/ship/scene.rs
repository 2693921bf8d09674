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

use super::ShipError;
use super::linear::LinearModel;
use super::manoeuvre::{Manoeuvre, ManoeuvreKind};
use super::propulsion::Propulsion;
use super::side::Side;
use super::spiral::{ReverseSpiral, Settle, Spiral};
use super::table::{GivenTable, RigidBodyTerms, ShipBody, ShipTable};
use super::{Units, YawInertia};
use crate::integrate::Stepper;
use crate::manoeuvring::steering::{Rudder, Series};
use crate::scene::check::Checker;
use crate::scene::envelope::{FamilyTable, IntegratorTable, OutputTable, SteeringGearTable};
use crate::scene::stop::StopCondition;
use crate::scene::{Problem, SceneError};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::Path;

/// The file as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShipSceneFile {
    /// What the scene is.
    pub title: String,
    /// `family = "planar-midship"`.
    pub model: FamilyTable,
    /// The body.
    pub body: BodyTable,
    /// The hydrodynamic table.
    pub hydrodynamics: HydrodynamicsTable,
    /// The steering gear.
    #[serde(default)]
    pub rudder: SteeringGearTable,
    /// The propeller, its thrust law and the rudder in its slipstream (prime tables).
    pub propulsion: Option<PropulsionTable>,
    /// The step.
    pub integrator: IntegratorTable,
    /// The manoeuvres, each run from the same approach.
    #[serde(default)]
    pub manoeuvre: Vec<ManoeuvreTable>,
    /// Trajectory rows.
    #[serde(default)]
    pub output: OutputTable,
    /// Values to sweep over (read by [`crate::scene::sweep`], which runs each case).
    pub sweep: Option<toml::Table>,
    /// A Monte Carlo's laws (read by [`crate::scene::uncertainty`], which runs each case).
    #[serde(default)]
    pub uncertainty: Option<crate::scene::uncertainty::UncertaintyTable>,
    /// The operating point of `eom linear`.
    pub linear: Option<crate::scene::envelope::LinearTable>,
}

/// `[body]`: the keys of the table's units (`_prime` in the prime system), one of each.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyTable {
    /// L, m.
    pub length: Option<f64>,
    /// M, kg (dimensional).
    pub mass: Option<f64>,
    /// m′ = M/(½ρL³) (prime).
    pub mass_prime: Option<f64>,
    /// I_zz about G, kg m² (dimensional).
    pub izz: Option<f64>,
    /// I_O about midship, kg m² (dimensional).
    pub izz_midship: Option<f64>,
    /// I_zz′ about G, over ½ρL⁵ (prime).
    pub izz_prime: Option<f64>,
    /// I_O′ about midship, over ½ρL⁵ (prime).
    pub izz_midship_prime: Option<f64>,
    /// G ahead of midship, m (dimensional).
    pub x_g: Option<f64>,
    /// x_G′ = x_G/L (prime).
    pub x_g_prime: Option<f64>,
}

/// `[hydrodynamics]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HydrodynamicsTable {
    /// `prime` or `dimensional`.
    pub units: String,
    /// `folded` or `separate`.
    pub rigid_body_terms: String,
    /// ρ, kg/m³ (prime only).
    pub density: Option<f64>,
    /// U₀, m/s.
    pub design_speed: f64,
    /// The coefficients by name, as the table writes them.
    pub coefficients: BTreeMap<String, f64>,
}

/// `[propulsion]`: the propeller, its thrust law, and the rudder in its slipstream
/// ([`super::propulsion`]); every key required where the table is given (the checker names the
/// one missing).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PropulsionTable {
    /// d, m.
    pub diameter: Option<f64>,
    /// A_R, m².
    pub rudder_area: Option<f64>,
    /// w.
    pub wake_fraction: Option<f64>,
    /// K_T of the induced velocity.
    pub thrust_coefficient: Option<f64>,
    /// k.
    pub slipstream_factor: Option<f64>,
    /// x_R/L, the rudder ahead of midship (negative aft).
    pub rudder_position_prime: Option<f64>,
    /// [T′_uu, T′_un, T′_nn].
    pub thrust: Option<[f64; 3]>,
    /// C_R on the wetted surface.
    pub resistance: Option<f64>,
    /// S, m².
    pub wetted_surface: Option<f64>,
    /// The engine's rate limit, rev/s².
    pub max_rate_rps_s: Option<f64>,
}

/// `[[manoeuvre]]`: each kind reads its own keys and refuses the others.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ManoeuvreTable {
    /// The output folder's name.
    pub name: Option<String>,
    /// `turning_circle`, `zigzag`, `pull_out` or `rudder_series`.
    pub kind: String,
    /// The rudder angle, degrees (not for a series).
    pub rudder_deg: Option<f64>,
    /// A zig-zag's ψ_a, degrees.
    pub heading_deg: Option<f64>,
    /// When the rudder is put over, s (default 0).
    pub execute_s: Option<f64>,
    /// A pull-out's release, s.
    pub release_s: Option<f64>,
    /// The end of the run, s (a spiral's: the longest it may take, by default).
    pub duration_s: Option<f64>,
    /// A series' times, s.
    pub times_s: Option<Vec<f64>>,
    /// A series' angles, degrees.
    pub series_deg: Option<Vec<f64>>,
    /// `both` (default), `port` or `starboard`: the sides a turning circle or zig-zag runs to.
    pub side: Option<String>,
    /// A direct spiral's rudder angles, degrees, strictly monotonic.
    pub rudders_deg: Option<Vec<f64>>,
    /// A direct spiral's first angle, degrees (with `to_deg` and `step_deg`, in place of
    /// `rudders_deg`).
    pub from_deg: Option<f64>,
    /// A direct spiral's last angle of the first pass, degrees.
    pub to_deg: Option<f64>,
    /// A direct spiral's spacing of the angles from `from_deg` to `to_deg`, degrees.
    pub step_deg: Option<f64>,
    /// A reverse spiral's commanded yaw rates, degrees per second.
    pub yaw_rates_deg_s: Option<Vec<f64>>,
    /// A spiral's settling window, s.
    pub settle_window_s: Option<f64>,
    /// A spiral's settling tolerance on r over the window, degrees per second.
    pub settle_tolerance_deg_s: Option<f64>,
    /// The longest a spiral holds an angle, s.
    pub max_hold_s: Option<f64>,
    /// The reverse spiral's closed-loop yaw time constant, s.
    pub controller_time_s: Option<f64>,
    /// The reverse spiral's settling tolerance on the mean rudder from window to window,
    /// degrees.
    pub settle_rudder_deg: Option<f64>,
    /// A spiral's settling tolerance on the speed over the window, m/s.
    pub settle_speed_m_s: Option<f64>,
    /// A crash stop's full-astern propeller rate, rev/s (negative).
    pub astern_rps: Option<f64>,
}

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

/// The keys of `[[manoeuvre]]` that only some kinds read, with whether the table gives each.
fn kind_keys(table: &ManoeuvreTable) -> [(&'static str, bool); 19] {
    [
        ("rudder_deg", table.rudder_deg.is_some()),
        ("heading_deg", table.heading_deg.is_some()),
        ("release_s", table.release_s.is_some()),
        ("times_s", table.times_s.is_some()),
        ("series_deg", table.series_deg.is_some()),
        ("side", table.side.is_some()),
        ("rudders_deg", table.rudders_deg.is_some()),
        ("from_deg", table.from_deg.is_some()),
        ("to_deg", table.to_deg.is_some()),
        ("step_deg", table.step_deg.is_some()),
        ("yaw_rates_deg_s", table.yaw_rates_deg_s.is_some()),
        ("settle_window_s", table.settle_window_s.is_some()),
        (
            "settle_tolerance_deg_s",
            table.settle_tolerance_deg_s.is_some(),
        ),
        ("max_hold_s", table.max_hold_s.is_some()),
        ("controller_time_s", table.controller_time_s.is_some()),
        ("settle_rudder_deg", table.settle_rudder_deg.is_some()),
        ("settle_speed_m_s", table.settle_speed_m_s.is_some()),
        ("astern_rps", table.astern_rps.is_some()),
        ("duration_s", table.duration_s.is_some()),
    ]
}

/// The keys of [`kind_keys`] each kind reads.
fn keys_of(kind: &str) -> &'static [&'static str] {
    const SETTLE: [&str; 3] = ["settle_window_s", "settle_tolerance_deg_s", "max_hold_s"];
    match kind {
        "turning_circle" => &["rudder_deg", "side", "duration_s"],
        "zigzag" => &["rudder_deg", "heading_deg", "side", "duration_s"],
        "pull_out" => &["rudder_deg", "release_s", "duration_s"],
        "rudder_series" => &["times_s", "series_deg", "duration_s"],
        "spiral" => &[
            "rudders_deg",
            "from_deg",
            "to_deg",
            "step_deg",
            SETTLE[0],
            SETTLE[1],
            SETTLE[2],
            "settle_speed_m_s",
            "duration_s",
        ],
        "reverse_spiral" => &[
            "yaw_rates_deg_s",
            SETTLE[0],
            SETTLE[1],
            SETTLE[2],
            "controller_time_s",
            "settle_rudder_deg",
            "settle_speed_m_s",
            "duration_s",
        ],
        "crash_stop" => &["astern_rps", "duration_s"],
        _ => &[],
    }
}

/// What a manoeuvre's checks read of the ship: its linear model (which side δ turns it to,
/// the controller's gain, the time constant a spiral's settling allows), its propulsion
/// model, its steering gear and its length.
#[derive(Debug, Clone, Copy)]
struct Ship<'a> {
    linear: &'a LinearModel,
    propulsion: Option<&'a Propulsion>,
    rudder: &'a Rudder,
    length: f64,
}

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

/// A ship's own tables, checked by the checker of every scene ([`Checker`]: its errors, its
/// value checks, its method checks).
impl Checker<'_> {
    /// Exactly one of the keys given, among those of the table's units; the others refused.
    fn one_of(
        &self,
        given: &[(&str, Option<f64>)],
        wanted: &[&str],
    ) -> Result<(usize, f64), SceneError> {
        let present: Vec<(usize, &str, f64)> = given
            .iter()
            .enumerate()
            .filter_map(|(i, (k, v))| v.map(|v| (i, *k, v)))
            .collect();
        if let Some((_, key, _)) = present.iter().find(|(_, k, _)| !wanted.contains(k)) {
            return Err(self.invalid(
                &format!("body.{key}"),
                format!(
                    "not a key of this table's units; give one of {}",
                    wanted.join(", ")
                ),
            ));
        }
        match present.as_slice() {
            [(i, _, v)] => Ok((*i, *v)),
            [] => Err(self.error(
                "body",
                Problem::Missing(format!("one of {}", wanted.join(", "))),
            )),
            _ => Err(self.invalid(
                &format!("body.{}", present[1].1),
                format!("give only one of {}", wanted.join(", ")),
            )),
        }
    }

    fn ship_body(&self, body: &BodyTable, units: Units) -> Result<(ShipBody, f64), SceneError> {
        let length = self.positive(
            "body.length",
            body.length
                .ok_or_else(|| self.error("body.length", Problem::Missing("body.length".into())))?,
        )?;
        let prime = units == Units::Prime;
        let pick = |names: [&'static str; 2]| if prime { names[1] } else { names[0] };
        let masses = [("mass", body.mass), ("mass_prime", body.mass_prime)];
        let (_, mass) = self.one_of(&masses, &[pick(["mass", "mass_prime"])])?;
        let mass = self.positive(&format!("body.{}", pick(["mass", "mass_prime"])), mass)?;
        let inertias = [
            ("izz", body.izz),
            ("izz_midship", body.izz_midship),
            ("izz_prime", body.izz_prime),
            ("izz_midship_prime", body.izz_midship_prime),
        ];
        let wanted = if prime {
            ["izz_prime", "izz_midship_prime"]
        } else {
            ["izz", "izz_midship"]
        };
        let (index, inertia) = self.one_of(&inertias, &wanted)?;
        let inertia = self.positive(&format!("body.{}", inertias[index].0), inertia)?;
        let about = if index % 2 == 0 {
            YawInertia::AboutG
        } else {
            YawInertia::AboutMidship
        };
        let centres = [("x_g", body.x_g), ("x_g_prime", body.x_g_prime)];
        let (_, x_g) = self.one_of(&centres, &[pick(["x_g", "x_g_prime"])])?;
        let x_g = self.finite(&format!("body.{}", pick(["x_g", "x_g_prime"])), x_g)?;
        if about == YawInertia::AboutMidship && inertia <= mass * x_g * x_g {
            return Err(self.invalid(
                &format!("body.{}", inertias[index].0),
                format!(
                    "the yaw inertia about midship must exceed M x_G² = {:e}: the inertia \
                     about G, I_O − M x_G², would not be positive",
                    mass * x_g * x_g
                ),
            ));
        }
        let ship = ShipBody {
            mass,
            yaw_inertia: inertia,
            yaw_inertia_about: about,
            x_g,
        };
        Ok((ship, length))
    }

    fn table(&self, file: &ShipSceneFile) -> Result<(ShipTable, f64), SceneError> {
        let hydro = &file.hydrodynamics;
        let units = self.word(
            "hydrodynamics.units",
            &hydro.units,
            [(Units::Prime, "prime"), (Units::Dimensional, "dimensional")],
        )?;
        let rigid_body_terms = self.word(
            "hydrodynamics.rigid_body_terms",
            &hydro.rigid_body_terms,
            [
                (RigidBodyTerms::Folded, "folded"),
                (RigidBodyTerms::Separate, "separate"),
            ],
        )?;
        let density = match (units, hydro.density) {
            (Units::Prime, Some(rho)) => Some(self.positive("hydrodynamics.density", rho)?),
            (Units::Prime, None) => {
                return Err(self.error(
                    "hydrodynamics.density",
                    Problem::Missing("the prime system needs ρ".into()),
                ));
            }
            (Units::Dimensional, Some(_)) => {
                return Err(self.invalid(
                    "hydrodynamics.density",
                    "only the prime system uses ρ: a dimensional table would ignore it",
                ));
            }
            (Units::Dimensional, None) => None,
        };
        let design_speed = self.positive("hydrodynamics.design_speed", hydro.design_speed)?;
        let (body, length) = self.ship_body(&file.body, units)?;
        let given = GivenTable {
            units,
            body,
            density,
            length: (units == Units::Prime).then_some(length),
            design_speed,
            rigid_body_terms,
            coefficients: hydro.coefficients.clone(),
            propulsion: file
                .propulsion
                .as_ref()
                .map(|p| self.propulsion(p))
                .transpose()?,
        };
        let table = ShipTable::new(&given).map_err(|e| match e {
            ShipError::Invalid { key, reason } => self.invalid(&key, reason),
            other => self.invalid("hydrodynamics", other.to_string()),
        })?;
        Ok((table, length))
    }

    /// `[propulsion]`, each number checked; the rate at the approach is solved by the table.
    fn propulsion(&self, table: &PropulsionTable) -> Result<Propulsion, SceneError> {
        let key = |k: &str| format!("propulsion.{k}");
        let given = |k: &str, v: Option<f64>| {
            v.ok_or_else(|| self.error(&key(k), Problem::Missing(key(k))))
        };
        let positive = |k: &str, v: Option<f64>| self.positive(&key(k), given(k, v)?);
        let fraction = |k: &str, v: Option<f64>| {
            let v = self.finite(&key(k), given(k, v)?)?;
            if (0.0..1.0).contains(&v) {
                Ok(v)
            } else {
                Err(self.invalid(&key(k), "a fraction in [0, 1)"))
            }
        };
        let thrust = table
            .thrust
            .ok_or_else(|| self.error(&key("thrust"), Problem::Missing(key("thrust"))))?;
        for (i, value) in thrust.iter().enumerate() {
            self.finite(&format!("propulsion.thrust[{i}]"), *value)?;
        }
        let diameter = positive("diameter", table.diameter)?;
        let rudder_area = positive("rudder_area", table.rudder_area)?;
        let disk = std::f64::consts::PI * diameter * diameter / 4.0;
        if disk > rudder_area {
            return Err(self.invalid(
                &key("rudder_area"),
                format!(
                    "the rudder's area must hold the propeller's disk (π d²/4 = {disk} m²): c \
                     weighs the slipstream by the share of the rudder in it"
                ),
            ));
        }
        let position = given("rudder_position_prime", table.rudder_position_prime)?;
        Ok(Propulsion {
            diameter,
            rudder_area,
            wake_fraction: fraction("wake_fraction", table.wake_fraction)?,
            thrust_coefficient: positive("thrust_coefficient", table.thrust_coefficient)?,
            slipstream_factor: positive("slipstream_factor", table.slipstream_factor)?,
            rudder_position: self.finite(&key("rudder_position_prime"), position)?,
            thrust,
            resistance: positive("resistance", table.resistance)?,
            wetted_surface: positive("wetted_surface", table.wetted_surface)?,
            max_rate: positive("max_rate_rps_s", table.max_rate_rps_s)?,
            approach_rate: f64::NAN,
            approach_inflow: f64::NAN,
        })
    }

    /// A rudder command of `degrees` at `key` within the steering gear's reach: a command
    /// beyond `rudder.max_deg` would run at the limit while the manoeuvre is labelled and
    /// judged at the angle asked, so it is refused, naming both keys.
    fn within_gear(&self, key: &str, degrees: f64, rudder: &Rudder) -> Result<(), SceneError> {
        match rudder.max_angle.map(f64::to_degrees) {
            Some(max) if degrees.abs() > max * (1.0 + 1e-12) => Err(self.invalid(
                key,
                format!(
                    "{}° is beyond the steering gear's limit, rudder.max_deg = {}°: the \
                     rudder would stop at the limit while the run is named and judged at the \
                     angle asked; command at most {}°, or raise rudder.max_deg",
                    crate::Short(degrees),
                    crate::Short(max),
                    crate::Short(max)
                ),
            )),
            _ => Ok(()),
        }
    }

    fn manoeuvre(
        &self,
        index: usize,
        table: &ManoeuvreTable,
        ship: Ship,
    ) -> Result<Manoeuvre, SceneError> {
        let Ship {
            linear,
            propulsion,
            rudder,
            ..
        } = ship;
        let key = |k: &str| format!("manoeuvre[{index}].{k}");
        let required = |k: &str, v: Option<f64>| {
            v.ok_or_else(|| self.error(&key(k), Problem::Missing(key(k))))
        };
        let kinds = "turning_circle, zigzag, pull_out, rudder_series, spiral, reverse_spiral or \
                     crash_stop";
        if keys_of(&table.kind).is_empty() {
            return Err(self.invalid(&key("kind"), format!("`{}`: expected {kinds}", table.kind)));
        }
        if let Some((k, _)) = kind_keys(table)
            .into_iter()
            .find(|(k, given)| *given && !keys_of(&table.kind).contains(k))
        {
            return Err(self.invalid(&key(k), format!("not a key of a {} manoeuvre", table.kind)));
        }
        let rudder_angle = |v: Option<f64>| -> Result<f64, SceneError> {
            let degrees = self.finite(&key("rudder_deg"), required("rudder_deg", v)?)?;
            if degrees == 0.0 {
                return Err(self.invalid(&key("rudder_deg"), "a manoeuvre needs a rudder angle"));
            }
            self.within_gear(&key("rudder_deg"), degrees, rudder)?;
            Ok(degrees.to_radians())
        };
        let execute = self.finite(&key("execute_s"), table.execute_s.unwrap_or(0.0))?;
        if execute < 0.0 {
            return Err(self.invalid(&key("execute_s"), "the run starts at 0 s"));
        }
        let spiral = self.spiral(index, table, ship)?;
        let duration = match (table.duration_s, &spiral) {
            (Some(duration), _) => self.positive(&key("duration_s"), duration)?,
            (None, Some((_, longest))) => execute + longest,
            (None, None) => {
                return Err(self.error(&key("duration_s"), Problem::Missing(key("duration_s"))));
            }
        };
        if duration <= execute {
            return Err(self.invalid(&key("duration_s"), "the run must go on past the execute"));
        }
        let sides = match table.side.as_deref() {
            None | Some("both") => Side::BOTH.to_vec(),
            Some(name) => match Side::from_name(name) {
                Some(side) => vec![side],
                None => {
                    return Err(self.invalid(
                        &key("side"),
                        format!("`{name}`: expected `both`, `port` or `starboard`"),
                    ));
                }
            },
        };
        // The rudder's magnitude, put over to the first side (see `eom::kinds::ship::side`).
        let to_first_side = |rudder: f64| rudder.abs() * sides[0].rudder_sign(linear);
        let (kind, default_name) = match table.kind.as_str() {
            "turning_circle" => {
                let rudder = to_first_side(rudder_angle(table.rudder_deg)?);
                let name = format!("turning_circle_{}", table.rudder_deg.unwrap_or(0.0));
                (ManoeuvreKind::TurningCircle { rudder }, name)
            }
            "zigzag" => {
                let rudder = to_first_side(rudder_angle(table.rudder_deg)?);
                let heading = self.positive(
                    &key("heading_deg"),
                    required("heading_deg", table.heading_deg)?,
                )?;
                let name = format!(
                    "zigzag_{}_{}",
                    table.rudder_deg.unwrap_or(0.0).abs(),
                    heading
                );
                let heading = heading.to_radians();
                (ManoeuvreKind::ZigZag { rudder, heading }, name)
            }
            "pull_out" => {
                let rudder = rudder_angle(table.rudder_deg)?;
                let release =
                    self.finite(&key("release_s"), required("release_s", table.release_s)?)?;
                if release <= execute || release >= duration {
                    return Err(self.invalid(
                        &key("release_s"),
                        "the release must come after the execute and before the end",
                    ));
                }
                let name = format!("pull_out_{}", table.rudder_deg.unwrap_or(0.0));
                (ManoeuvreKind::PullOut { rudder, release }, name)
            }
            "rudder_series" => {
                let times = table
                    .times_s
                    .clone()
                    .ok_or_else(|| self.error(&key("times_s"), Problem::Missing(key("times_s"))))?;
                let degrees = table.series_deg.clone().ok_or_else(|| {
                    self.error(&key("series_deg"), Problem::Missing(key("series_deg")))
                })?;
                for (k, angle) in degrees.iter().enumerate() {
                    self.within_gear(&format!("{}[{k}]", key("series_deg")), *angle, rudder)?;
                }
                let angles = degrees.iter().map(|d| d.to_radians()).collect();
                let series = Series::new(times, angles).ok_or_else(|| {
                    self.invalid(
                        &key("times_s"),
                        "times_s and series_deg must be finite, of equal length, at least one, \
                         the times strictly increasing",
                    )
                })?;
                (ManoeuvreKind::Series(series), "rudder_series".to_owned())
            }
            "crash_stop" => {
                if propulsion.is_none() {
                    return Err(self.invalid(
                        &key("kind"),
                        "a crash stop needs a propulsion model to go astern: give [propulsion]",
                    ));
                }
                let astern = self.finite(
                    &key("astern_rps"),
                    required("astern_rps", table.astern_rps)?,
                )?;
                if astern >= 0.0 {
                    return Err(self.invalid(
                        &key("astern_rps"),
                        "full astern is a negative propeller rate",
                    ));
                }
                (ManoeuvreKind::CrashStop { astern }, "crash_stop".to_owned())
            }
            kind => match spiral {
                Some((kind, _)) => {
                    let name = match kind {
                        ManoeuvreKind::Spiral(_) => "spiral",
                        _ => "reverse_spiral",
                    };
                    (kind, name.to_owned())
                }
                None => {
                    return Err(self.invalid(&key("kind"), format!("`{kind}`: expected {kinds}")));
                }
            },
        };
        let turns = matches!(
            kind,
            ManoeuvreKind::TurningCircle { .. } | ManoeuvreKind::ZigZag { .. }
        );
        let name = table.name.clone().unwrap_or(default_name);
        let valid = !name.is_empty()
            && name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-' || c == '.')
            && name != "."
            && name != ".."
            && name != "imo";
        if !valid {
            return Err(self.invalid(
                &key("name"),
                format!("`{name}` must be a folder name: letters, digits, _ - . (and not `imo`)"),
            ));
        }
        Ok(Manoeuvre {
            name,
            kind,
            execute,
            duration,
            sides: if turns { sides } else { Vec::new() },
        })
    }

    /// A direct spiral's first pass, degrees: `rudders_deg` as given, or the angles from
    /// `from_deg` to `to_deg` every `step_deg` (exactly one of the two forms); `None` where
    /// neither is given.
    fn spiral_angles(
        &self,
        index: usize,
        table: &ManoeuvreTable,
    ) -> Result<Option<Vec<f64>>, SceneError> {
        let key = |k: &str| format!("manoeuvre[{index}].{k}");
        let range = [
            ("from_deg", table.from_deg),
            ("to_deg", table.to_deg),
            ("step_deg", table.step_deg),
        ];
        let given: Vec<&str> = range
            .iter()
            .filter(|(_, v)| v.is_some())
            .map(|(k, _)| *k)
            .collect();
        let both = "give the angles either as rudders_deg or as from_deg, to_deg and step_deg";
        match (&table.rudders_deg, given.len()) {
            (Some(_), 0) => return Ok(table.rudders_deg.clone()),
            (Some(_), _) => {
                return Err(self.invalid(&key(given[0]), format!("{both}, not both")));
            }
            (None, 0) => {
                return Err(self.error(
                    &key("rudders_deg"),
                    Problem::Missing(format!(
                        "{} (or {}, {} and {}): the spiral's setpoints",
                        key("rudders_deg"),
                        key("from_deg"),
                        key("to_deg"),
                        key("step_deg")
                    )),
                ));
            }
            (None, 3) => {}
            (None, _) => {
                let missing = range
                    .iter()
                    .find(|(_, v)| v.is_none())
                    .map_or("", |(k, _)| *k);
                return Err(self.error(
                    &key(missing),
                    Problem::Missing(format!("{}: {both}", key(missing))),
                ));
            }
        }
        let from = self.finite(&key("from_deg"), table.from_deg.unwrap_or(f64::NAN))?;
        let to = self.finite(&key("to_deg"), table.to_deg.unwrap_or(f64::NAN))?;
        let step = self.positive(&key("step_deg"), table.step_deg.unwrap_or(f64::NAN))?;
        let steps = (to - from).abs() / step;
        let whole = steps.round();
        if from == to || (steps - whole).abs() > 1e-9 * steps.max(1.0) || whole > 1000.0 {
            return Err(self.invalid(
                &key("step_deg"),
                format!(
                    "the angles from {from}° to {to}° must be a whole number of steps of \
                     {step}° (at least one, at most 1000)"
                ),
            ));
        }
        let sign = (to - from).signum();
        // Each angle from the first by a whole number of steps (no running sum), the last
        // the given `to_deg` itself.
        let count = whole as usize;
        let mut angles: Vec<f64> = (0..count).map(|k| from + sign * k as f64 * step).collect();
        angles.push(to);
        Ok(Some(angles))
    }

    /// A spiral's kind and the longest it may take (s), for the kinds `spiral` and
    /// `reverse_spiral`; `None` for the others.
    fn spiral(
        &self,
        index: usize,
        table: &ManoeuvreTable,
        ship: Ship,
    ) -> Result<Option<(ManoeuvreKind, f64)>, SceneError> {
        let Ship {
            linear,
            rudder,
            length,
            ..
        } = ship;
        let key = |k: &str| format!("manoeuvre[{index}].{k}");
        let (list_key, list) = match table.kind.as_str() {
            "spiral" => ("rudders_deg", self.spiral_angles(index, table)?),
            "reverse_spiral" => ("yaw_rates_deg_s", table.yaw_rates_deg_s.clone()),
            _ => return Ok(None),
        };
        let list = list.ok_or_else(|| {
            self.error(
                &key(list_key),
                Problem::Missing(format!("{}: the spiral's setpoints", key(list_key))),
            )
        })?;
        if list.len() < 2 || list.iter().any(|v| !v.is_finite()) {
            return Err(self.invalid(&key(list_key), "at least two finite values"));
        }
        if table.kind == "spiral" {
            // Each angle by the key that gave it: an entry of rudders_deg, or the range's ends
            // (the angles between lie between them).
            for (k, angle) in list.iter().enumerate() {
                let given = match (&table.rudders_deg, k) {
                    (Some(_), _) => format!("{}[{k}]", key("rudders_deg")),
                    (None, 0) => key("from_deg"),
                    (None, _) => key("to_deg"),
                };
                self.within_gear(&given, *angle, rudder)?;
            }
        }
        let settle = Settle {
            window: self.positive(
                &key("settle_window_s"),
                table.settle_window_s.unwrap_or(SETTLE_WINDOW_S),
            )?,
            tolerance: self
                .positive(
                    &key("settle_tolerance_deg_s"),
                    table
                        .settle_tolerance_deg_s
                        .unwrap_or(SETTLE_TOLERANCE_DEG_S),
                )?
                .to_radians(),
            max_hold: self.positive(&key("max_hold_s"), table.max_hold_s.unwrap_or(MAX_HOLD_S))?,
            rudder_tolerance: self
                .positive(
                    &key("settle_rudder_deg"),
                    table.settle_rudder_deg.unwrap_or(SETTLE_RUDDER_DEG),
                )?
                .to_radians(),
            speed_tolerance: self.positive(
                &key("settle_speed_m_s"),
                table.settle_speed_m_s.unwrap_or(SETTLE_SPEED_M_S),
            )?,
            time_constant: linear.slowest_time_constant(),
        };
        if settle.max_hold < settle.window {
            return Err(self.invalid(
                &key("max_hold_s"),
                "an angle is held at least one settling window",
            ));
        }
        let radians: Vec<f64> = list.iter().map(|v| v.to_radians()).collect();
        // Each setpoint is checked at the end of each window: it ends at the first check at or
        // past the longest hold.
        let per_setpoint = (settle.max_hold / settle.window).ceil() * settle.window;
        if table.kind == "spiral" {
            let rising = radians.windows(2).all(|w| w[1] > w[0]);
            let falling = radians.windows(2).all(|w| w[1] < w[0]);
            if !(rising || falling) {
                return Err(self.invalid(
                    &key("rudders_deg"),
                    "the angles of the first pass must be strictly monotonic, from one side to \
                     the other (the run comes back through them)",
                ));
            }
            let longest = (2 * radians.len() - 1) as f64 * per_setpoint;
            let spiral = Spiral {
                rudders: radians,
                settle,
                length,
            };
            return Ok(Some((ManoeuvreKind::Spiral(spiral), longest)));
        }
        let tau = self.positive(
            &key("controller_time_s"),
            table.controller_time_s.unwrap_or(CONTROLLER_TIME_S),
        )?;
        let (_, b) = linear.state_space();
        let gain = -1.0 / (b[1] * tau);
        if !gain.is_finite() {
            return Err(self.invalid(
                &key("kind"),
                "the table's rudder gives no yaw acceleration (B of the linear model is zero): \
                 no controller can steer it",
            ));
        }
        let longest = radians.len() as f64 * per_setpoint;
        let reverse = ReverseSpiral {
            yaw_rates: radians,
            settle,
            gain,
            length,
        };
        Ok(Some((ManoeuvreKind::ReverseSpiral(reverse), longest)))
    }
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
        let (table, length) = check.table(file)?;
        let rudder = check.steering_gear("rudder", &file.rudder)?;
        let linear = LinearModel::closed_form(&table);
        let table_propulsion = table.propulsion.as_ref();
        if file.manoeuvre.is_empty() {
            return Err(check.error(
                "manoeuvre",
                Problem::Missing("at least one [[manoeuvre]]".into()),
            ));
        }
        let mut manoeuvres: Vec<Manoeuvre> = Vec::new();
        for (index, table) in file.manoeuvre.iter().enumerate() {
            let ship = Ship {
                linear: &linear,
                propulsion: table_propulsion,
                rudder: &rudder,
                length,
            };
            let manoeuvre = check.manoeuvre(index, table, ship)?;
            if manoeuvres.iter().any(|m| m.name == manoeuvre.name) {
                return Err(check.invalid(
                    &format!("manoeuvre[{index}].name"),
                    format!("`{}` is taken by an earlier manoeuvre", manoeuvre.name),
                ));
            }
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
