//! An aircraft's scene: its tables as written (`AircraftSceneFile`), and as checked
//! ([`AircraftScene`]: the model built, the trim found, the manoeuvres and the method).
//!
//! ```toml
//! title = "F-16 (Stevens, Lewis & Johnson, Appendix A)"
//!
//! [aircraft]
//! units = "us"                 # ft, slug, lbf, s; tables and controls in degrees
//! atmosphere = "stevens-lewis" # or "standard-1976"
//! aerodynamics = "stevens-lewis"
//!
//! [body]                       # mass, the tensor about G (the chapter's products), gravity
//! [geometry]                   # area, span, chord, xcg, xcg_reference (fractions of c̄)
//! [engine]                     # rotor_momentum, thrust tables in altitude and Mach
//! [aerodynamics.cx]            # … every table of the form, with its breakpoints
//! ```
//!
//! or, for an aircraft described by a textbook's stability derivatives
//! (`scenes/navion.toml`):
//!
//! ```toml
//! [aircraft]
//! aerodynamics = "derivatives"
//! [engine]                     # rotor_momentum, thrust (at full throttle), time_constant_s
//! [aerodynamics.derivatives]   # CL_0, CL_alpha, …, Cn_rudder, per radian
//! ```
//!
//! and in both:
//!
//! ```toml
//! [limits]                     # α over the tables, each surface's deflection
//! [trim]                       # speed, altitude, climb, turn or pull-up
//! [[manoeuvre]]                # kind, amount, start_s, width_s, duration_s
//! [integrator]
//! ```

use super::aero::{Aerodynamics, StevensLewisTables};
use super::atmosphere::Atmosphere;
use super::derivatives::Derivatives;
use super::engine::{ConstantThrust, Engine, Propulsion};
use super::manoeuvre::{AircraftManoeuvre, Manoeuvre, ROW};
use super::model::{AircraftModel, Airframe, CONTROLS, STATE};
use super::tables::{Breakpoints, Table1, Table2, TableError};
use super::trim::{Condition, Limits, Trim, trim};
use crate::InertiaTensor;
use crate::integrate::Stepper;
use crate::models::Kinematics;
use crate::scene::check::Checker;
use crate::scene::stop::StopCondition;
use crate::scene::{Problem, SceneError};

pub use super::file::{
    AerodynamicsTable, AircraftSceneFile, AircraftTable, Alpha, AlphaBeta, AlphaBetaAbs,
    AlphaElevator, BodyTable, DampingTable, EngineTable, GeometryTable, LimitsTable,
    ManoeuvreTable, TrimTable,
};

/// The form of an aircraft's aerodynamics, as `aircraft.aerodynamics` names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Form {
    StevensLewis,
    Derivatives,
}

/// A checked aircraft scene, ready to run.
#[derive(Debug, Clone)]
pub struct AircraftScene {
    /// What the scene is.
    pub title: String,
    /// The model.
    pub model: AircraftModel,
    /// How its runs carry the attitude (the rows are in Euler angles either way).
    pub kinematics: Kinematics,
    /// The unit system's name (`us`, `si`).
    pub units: &'static str,
    /// Where the tables and surfaces end.
    pub limits: Limits,
    /// The flight condition trimmed.
    pub condition: Condition,
    /// The trim every manoeuvre starts from.
    pub trim: Trim,
    /// The manoeuvres.
    pub manoeuvres: Vec<AircraftManoeuvre>,
    /// The method.
    pub stepper: Stepper,
    /// Rows' interval, s.
    pub every: f64,
    /// `integrator.stop_when`.
    pub stop: Option<StopCondition>,
    /// `[linear]`.
    pub linear: crate::linear::LinearSpec,
    /// The mass and the tensor about G, for the view.
    pub mass_properties: (f64, [[f64; 3]; 3]),
    /// What the trim rests on that is not data (a condition beyond the engine's tables), said
    /// with every run and linearisation.
    pub trim_warnings: Vec<String>,
    /// The wing's span and chord, for the view.
    pub span: f64,
    /// The mean aerodynamic chord.
    pub chord: f64,
    /// `geometry.length`, the fuselage's, for the view.
    pub length: Option<f64>,
}

/// The units of each state entry and control, by the unit system.
pub fn units(system: &str) -> [(&'static str, &'static str); 18] {
    let (length, speed) = if system == "si" {
        ("m", "m/s")
    } else {
        ("ft", "ft/s")
    };
    [
        ("vt", speed),
        ("alpha", "rad"),
        ("beta", "rad"),
        ("phi", "rad"),
        ("theta", "rad"),
        ("psi", "rad"),
        ("p", "rad/s"),
        ("q", "rad/s"),
        ("r", "rad/s"),
        ("north", length),
        ("east", length),
        ("altitude", length),
        ("power", "percent"),
        ("throttle", "0 to 1"),
        ("elevator", "deg"),
        ("aileron", "deg"),
        ("rudder", "deg"),
        ("load_factor", "g"),
    ]
}

impl AircraftScene {
    /// The columns of trajectory.csv after t, each with its unit in the scene's system
    /// (`vt[ft/s]`, `alpha[rad]`, `elevator[deg]`, `load_factor[g]`).
    pub fn labelled_columns(&self) -> Vec<String> {
        units(self.units)
            .iter()
            .map(|(name, unit)| crate::models::with_unit(name, unit))
            .collect()
    }

    /// The unit of the energies: `ft lbf` in US units, `J` in SI.
    pub fn energy_unit(&self) -> &'static str {
        match self.units {
            "si" => "J",
            _ => "ft lbf",
        }
    }

    /// Reads and checks aircraft scene text; `name` is how errors name it.
    pub fn parse(text: &str, name: &str) -> Result<Self, SceneError> {
        let file: AircraftSceneFile = crate::scene::read_as(text, name)?;
        Self::from_file(&file, name)
    }

    /// Checks the tables of an aircraft scene file, builds its model and trims it.
    pub fn from_file(file: &AircraftSceneFile, name: &str) -> Result<Self, SceneError> {
        let check = Checker { name };
        let units = check.word(
            "aircraft.units",
            &file.aircraft.units,
            [("us", "us"), ("si", "si")],
        )?;
        let atmosphere = match (file.aircraft.atmosphere.as_str(), units) {
            ("stevens-lewis", "us") => Atmosphere::StevensLewis,
            ("stevens-lewis", _) => {
                return Err(check.invalid(
                    "aircraft.atmosphere",
                    "`stevens-lewis` is in feet: it takes `units = \"us\"`",
                ));
            }
            ("standard-1976", "us") => Atmosphere::Standard1976Us,
            ("standard-1976", _) => Atmosphere::Standard1976Si,
            (other, _) => {
                return Err(check.invalid(
                    "aircraft.atmosphere",
                    format!("`{other}`: expected `stevens-lewis` or `standard-1976`"),
                ));
            }
        };
        let form = check.word(
            "aircraft.aerodynamics",
            &file.aircraft.aerodynamics,
            [
                (Form::StevensLewis, "stevens-lewis"),
                (Form::Derivatives, "derivatives"),
            ],
        )?;
        let kinematics = check.word(
            "aircraft.kinematics",
            file.aircraft.kinematics.as_deref().unwrap_or("euler"),
            [
                (Kinematics::Euler, "euler"),
                (Kinematics::Quaternion, "quaternion"),
            ],
        )?;
        let airframe = check.aircraft_airframe(file)?;
        let tensor = airframe.inertia.matrix();
        let mass_properties = (
            airframe.mass,
            std::array::from_fn(|r| std::array::from_fn(|c| tensor[(r, c)])),
        );
        let (span, chord) = (airframe.span, airframe.chord);
        let length = (file.geometry.length)
            .map(|length| check.positive("geometry.length", length))
            .transpose()?;
        let aerodynamics: Aerodynamics = match form {
            Form::StevensLewis => check.aircraft_aerodynamics(&file.aerodynamics)?.into(),
            Form::Derivatives => check.aircraft_derivatives(&file.aerodynamics)?.into(),
        };
        let engine = check.aircraft_engine(&file.engine)?;
        let model = AircraftModel::new(&airframe, aerodynamics, engine, atmosphere)
            .map_err(|e| check.invalid("body", e.to_string()))?;
        let limits = check.aircraft_limits(&file.limits)?;
        let condition = check.aircraft_condition(&file.trim)?;
        let trimmed =
            trim(&model, &condition, &limits).map_err(|e| check.invalid("trim", e.to_string()))?;
        let trim_warnings = trim_beyond_tables(&model, &trimmed);
        if file.manoeuvre.is_empty() {
            return Err(check.error(
                "manoeuvre",
                Problem::Missing("at least one [[manoeuvre]]".into()),
            ));
        }
        let mut manoeuvres: Vec<AircraftManoeuvre> = Vec::new();
        for (index, table) in file.manoeuvre.iter().enumerate() {
            let manoeuvre = check.aircraft_manoeuvre(index, table, &trimmed, &limits)?;
            let names = manoeuvres.iter().map(|m| m.name.as_str());
            check.unique_manoeuvre(index, &manoeuvre.name, names)?;
            manoeuvres.push(manoeuvre);
        }
        let longest = manoeuvres.iter().map(|m| m.duration).fold(0.0, f64::max);
        // p, q, r: symplectic Euler kicks the rates first.
        let (stepper, every) = check.stepping(
            (&file.integrator, &file.output),
            longest,
            ("an aircraft", 6..9),
        )?;
        let start = super::manoeuvre::row_at(&model, &trimmed.state, &trimmed.controls);
        let stop = check.stop_when(
            file.integrator.stop_when.as_deref(),
            &ROW,
            [(String::new(), start)],
        )?;
        let linear = check.linear(
            file.linear.as_ref(),
            "the aircraft",
            (&STATE, &CONTROLS, &[]),
        )?;
        if kinematics == Kinematics::Quaternion {
            // Derived and proved when the scene is read, as every model.
            model
                .in_quaternion()
                .map_err(|e| check.invalid("aircraft.kinematics", e.to_string()))?;
        }
        Ok(AircraftScene {
            title: file.title.clone(),
            model,
            kinematics,
            units,
            limits,
            condition,
            trim: trimmed,
            manoeuvres,
            stepper,
            every,
            stop,
            linear,
            mass_properties,
            trim_warnings,
            span,
            chord,
            length,
        })
    }

    /// The body as the view draws it: its mass and its tensor about G.
    pub fn solid(&self) -> crate::output::drawing::Solid {
        crate::output::drawing::Solid {
            mass: self.mass_properties.0,
            inertia_about_g: self.mass_properties.1,
        }
    }
}

impl Checker<'_> {
    fn aircraft_airframe(&self, file: &AircraftSceneFile) -> Result<Airframe, SceneError> {
        let body = &file.body;
        let geometry = &file.geometry;
        let mass = self.positive("body.mass", body.mass)?;
        let gravity = self.positive("body.gravity", body.gravity)?;
        let [ixx, iyy, izz] = body.inertia;
        for (i, x) in body.inertia.iter().enumerate() {
            self.positive(&format!("body.inertia[{i}]"), *x)?;
        }
        let (key, [ixy, iyz, ixz]) = self.aircraft_products(body)?;
        if ixy != 0.0 || iyz != 0.0 {
            return Err(self.invalid(
                key,
                "an aircraft is symmetric about its xz-plane: I_xy and I_yz must be 0",
            ));
        }
        let inertia = InertiaTensor::new(ixx, iyy, izz, ixy, iyz, ixz)
            .map_err(|e| self.invalid("body.inertia", e.to_string()))?;
        let chord = self.positive("geometry.chord", geometry.chord)?;
        let xcg = self.finite("geometry.xcg", geometry.xcg)?;
        let reference = self.finite("geometry.xcg_reference", geometry.xcg_reference)?;
        Ok(Airframe {
            mass,
            inertia,
            gravity,
            area: self.positive("geometry.area", geometry.area)?,
            span: self.positive("geometry.span", geometry.span)?,
            chord,
            reference_point: Airframe::reference_from_chord(chord, xcg, reference),
            rotor_momentum: self.finite("engine.rotor_momentum", file.engine.rotor_momentum)?,
        })
    }

    /// The tensor's off-diagonal entries I_xy, I_yz, I_xz and the key they were given by:
    /// `body.products_of_inertia` as they are, or `body.products_of_inertia_integrals`
    /// (∫xy dm, ∫yz dm, ∫xz dm) negated; never both.
    fn aircraft_products(&self, body: &BodyTable) -> Result<(&'static str, [f64; 3]), SceneError> {
        const ENTRIES: &str = "body.products_of_inertia";
        const INTEGRALS: &str = "body.products_of_inertia_integrals";
        match (body.products_of_inertia, body.products_of_inertia_integrals) {
            (Some(_), Some(_)) => Err(self.invalid(
                INTEGRALS,
                "the products are given twice: `body.products_of_inertia` (the tensor's \
                 entries, −∫xz dm) and `body.products_of_inertia_integrals` (∫xz dm); give one",
            )),
            (None, Some(integrals)) => {
                let [xy, yz, xz] = self.finite3(INTEGRALS, Some(integrals))?;
                // 0 − x, not −x: a product of 0 stays +0 (−0 would print as `-0e0`).
                Ok((INTEGRALS, [0.0 - xy, 0.0 - yz, 0.0 - xz]))
            }
            (entries, None) => Ok((ENTRIES, self.finite3(ENTRIES, entries)?)),
        }
    }

    fn aircraft_table_error(&self, key: &str, error: TableError) -> SceneError {
        self.invalid(key, error.to_string())
    }

    fn aircraft_points(
        &self,
        key: &str,
        axis: &str,
        points: &[f64],
    ) -> Result<Breakpoints, SceneError> {
        Breakpoints::new(key, axis, points.to_vec())
            .map_err(|e| self.aircraft_table_error(&format!("{key}.{axis}"), e))
    }

    fn aircraft_grid(
        &self,
        key: &str,
        (x_name, x): (&str, &[f64]),
        (y_name, y): (&str, &[f64]),
        values: &[Vec<f64>],
    ) -> Result<Table2, SceneError> {
        let (xs, ys) = (
            self.aircraft_points(key, x_name, x)?,
            self.aircraft_points(key, y_name, y)?,
        );
        Table2::new(key, xs, ys, values.to_vec())
            .map_err(|e| self.aircraft_table_error(&format!("{key}.values"), e))
    }

    fn aircraft_aerodynamics(
        &self,
        a: &AerodynamicsTable,
    ) -> Result<StevensLewisTables, SceneError> {
        if a.derivatives.is_some() {
            return Err(self.invalid(
                "aerodynamics.derivatives",
                "the derivatives' form is `aircraft.aerodynamics = \"derivatives\"`; this \
                 scene's tables are of the stevens-lewis form",
            ));
        }
        let in_elevator = |key: &str, t: &AlphaElevator| {
            self.aircraft_grid(
                key,
                ("alpha_deg", &t.alpha_deg),
                ("elevator_deg", &t.elevator_deg),
                &t.values,
            )
        };
        let in_beta_abs = |key: &str, t: &AlphaBetaAbs| {
            self.aircraft_grid(
                key,
                ("alpha_deg", &t.alpha_deg),
                ("beta_abs_deg", &t.beta_abs_deg),
                &t.values,
            )
        };
        let in_beta = |key: &str, t: &AlphaBeta| {
            self.aircraft_grid(
                key,
                ("alpha_deg", &t.alpha_deg),
                ("beta_deg", &t.beta_deg),
                &t.values,
            )
        };
        let one = |key: &str, alpha: &[f64], values: &[f64]| {
            let xs = self.aircraft_points(key, "alpha_deg", alpha)?;
            Table1::new(key, xs, values.to_vec()).map_err(|e| self.aircraft_table_error(key, e))
        };
        let d = self.aircraft_table("aerodynamics.damping", a.damping.as_ref())?;
        let damping = [
            ("CXq", &d.CXq),
            ("CYr", &d.CYr),
            ("CYp", &d.CYp),
            ("CZq", &d.CZq),
            ("Clr", &d.Clr),
            ("Clp", &d.Clp),
            ("Cmq", &d.Cmq),
            ("Cnr", &d.Cnr),
            ("Cnp", &d.Cnp),
        ];
        let mut tables = Vec::with_capacity(9);
        for (name, values) in damping {
            tables.push(one(
                &format!("aerodynamics.damping.{name}"),
                &d.alpha_deg,
                values,
            )?);
        }
        Ok(StevensLewisTables {
            cx: in_elevator(
                "aerodynamics.cx",
                self.aircraft_table("aerodynamics.cx", a.cx.as_ref())?,
            )?,
            cz: {
                let cz = self.aircraft_table("aerodynamics.cz", a.cz.as_ref())?;
                one("aerodynamics.cz", &cz.alpha_deg, &cz.values)?
            },
            cm: in_elevator(
                "aerodynamics.cm",
                self.aircraft_table("aerodynamics.cm", a.cm.as_ref())?,
            )?,
            cl: in_beta_abs(
                "aerodynamics.cl",
                self.aircraft_table("aerodynamics.cl", a.cl.as_ref())?,
            )?,
            cn: in_beta_abs(
                "aerodynamics.cn",
                self.aircraft_table("aerodynamics.cn", a.cn.as_ref())?,
            )?,
            dlda: in_beta(
                "aerodynamics.dlda",
                self.aircraft_table("aerodynamics.dlda", a.dlda.as_ref())?,
            )?,
            dldr: in_beta(
                "aerodynamics.dldr",
                self.aircraft_table("aerodynamics.dldr", a.dldr.as_ref())?,
            )?,
            dnda: in_beta(
                "aerodynamics.dnda",
                self.aircraft_table("aerodynamics.dnda", a.dnda.as_ref())?,
            )?,
            dndr: in_beta(
                "aerodynamics.dndr",
                self.aircraft_table("aerodynamics.dndr", a.dndr.as_ref())?,
            )?,
            damping: tables.try_into().expect("nine damping tables"),
        })
    }

    /// A table of the stevens-lewis form, which that form requires.
    fn aircraft_table<'a, T>(&self, key: &str, table: Option<&'a T>) -> Result<&'a T, SceneError> {
        table.ok_or_else(|| self.missing(key, "a table of the stevens-lewis form"))
    }

    /// The stability derivatives of `aircraft.aerodynamics = "derivatives"`, every term
    /// finite, and no table of the other form beside them.
    fn aircraft_derivatives(&self, a: &AerodynamicsTable) -> Result<Derivatives, SceneError> {
        let tables = [
            ("cx", a.cx.is_some()),
            ("cz", a.cz.is_some()),
            ("cm", a.cm.is_some()),
            ("cl", a.cl.is_some()),
            ("cn", a.cn.is_some()),
            ("dlda", a.dlda.is_some()),
            ("dldr", a.dldr.is_some()),
            ("dnda", a.dnda.is_some()),
            ("dndr", a.dndr.is_some()),
            ("damping", a.damping.is_some()),
        ];
        if let Some((name, _)) = tables.iter().find(|(_, given)| *given) {
            return Err(self.invalid(
                &format!("aerodynamics.{name}"),
                "a table of the stevens-lewis form, in a scene whose `aircraft.aerodynamics` \
                 is derivatives",
            ));
        }
        let derivatives = a.derivatives.ok_or_else(|| {
            self.missing(
                "aerodynamics.derivatives",
                "the stability derivatives of `aircraft.aerodynamics = \"derivatives\"`",
            )
        })?;
        for (name, value) in derivatives.terms() {
            self.finite(&format!("aerodynamics.derivatives.{name}"), value)?;
        }
        const KEY: &str = "aerodynamics.derivatives";
        let (lift_and_drag, body_axis) = (
            derivatives.lift_and_drag_terms(),
            derivatives.body_axis_terms(),
        );
        if let (Some(wind), Some(body)) = (lift_and_drag.first(), body_axis.first()) {
            return Err(self.invalid(
                &format!("{KEY}.{body}"),
                format!(
                    "a body-axis force term in a table that gives lift and drag ({wind}): a \
                     table gives its forces one way, CL_… and CD_… or CX_… and CZ_…"
                ),
            ));
        }
        if let Some((speed, mach)) = derivatives.speed_and_mach_of_one() {
            return Err(self.invalid(
                &format!("{KEY}.{mach}"),
                format!("a Mach derivative beside {speed}, the same slope per û: give one"),
            ));
        }
        self.reference_value(
            &format!("{KEY}.reference_speed"),
            derivatives.reference_speed,
            derivatives.has_speed_terms(),
            "u₀, the airspeed the speed and Mach derivatives (CL_u, CL_M, …) are taken about",
        )?;
        self.reference_value(
            &format!("{KEY}.reference_mach"),
            derivatives.reference_mach,
            !derivatives.mach_terms().is_empty(),
            "M₀, the Mach number the Mach derivatives (CL_M, CD_M, …) are taken about",
        )?;
        Ok(derivatives)
    }

    /// A table's reference condition (`what`): positive where the table has the terms that
    /// need it, absent where it has none.
    fn reference_value(
        &self,
        key: &str,
        value: f64,
        needed: bool,
        what: &str,
    ) -> Result<(), SceneError> {
        match (needed, value == 0.0) {
            (true, true) => Err(self.missing(key, what)),
            (true, false) => self.positive(key, value).map(|_| ()),
            (false, false) => {
                Err(self.invalid(key, format!("{what}, which the table does not give")))
            }
            (false, true) => Ok(()),
        }
    }

    /// Thrust tables, or a constant thrust: one of the two, whole.
    fn aircraft_engine(&self, e: &EngineTable) -> Result<Propulsion, SceneError> {
        let tables = [
            ("altitude", e.altitude.is_some()),
            ("mach", e.mach.is_some()),
            ("idle", e.idle.is_some()),
            ("military", e.military.is_some()),
            ("maximum", e.maximum.is_some()),
        ];
        if let Some(thrust) = e.thrust {
            if let Some((name, _)) = tables.iter().find(|(_, given)| *given) {
                return Err(self.invalid(
                    &format!("engine.{name}"),
                    "a thrust table beside `engine.thrust`: give the tables or a constant \
                     thrust, not both",
                ));
            }
            let time_constant = e.time_constant_s.ok_or_else(|| {
                self.missing(
                    "engine.time_constant_s",
                    "the power's lag of a constant thrust",
                )
            })?;
            return Ok(ConstantThrust {
                maximum: self.positive("engine.thrust", thrust)?,
                time_constant: self.positive("engine.time_constant_s", time_constant)?,
            }
            .into());
        }
        if e.time_constant_s.is_some() {
            return Err(self.invalid(
                "engine.time_constant_s",
                "the lag of a constant thrust, without `engine.thrust`",
            ));
        }
        let need = |key: &str, given: bool| {
            if given {
                Ok(())
            } else {
                Err(self.missing(
                    key,
                    "the thrust tables (altitude, mach, idle, military, maximum), or \
                     `engine.thrust` and `engine.time_constant_s`",
                ))
            }
        };
        for (name, given) in tables {
            need(&format!("engine.{name}"), given)?;
        }
        let (altitude, mach) = (e.altitude.as_deref(), e.mach.as_deref());
        let (altitude, mach) = (altitude.unwrap_or_default(), mach.unwrap_or_default());
        let table = |level: &str, values: &Option<Vec<Vec<f64>>>| {
            self.aircraft_grid(
                &format!("engine.{level}"),
                ("altitude", altitude),
                ("mach", mach),
                values.as_deref().unwrap_or_default(),
            )
        };
        Ok(Engine {
            idle: table("idle", &e.idle)?,
            military: table("military", &e.military)?,
            maximum: table("maximum", &e.maximum)?,
        }
        .into())
    }

    fn aircraft_limits(&self, l: &LimitsTable) -> Result<Limits, SceneError> {
        let [low, high] = l.alpha_deg;
        self.finite("limits.alpha_deg[0]", low)?;
        self.finite("limits.alpha_deg[1]", high)?;
        if low >= high {
            return Err(self.invalid("limits.alpha_deg", format!("{low} is not below {high}")));
        }
        Ok(Limits {
            alpha: (low.to_radians(), high.to_radians()),
            surfaces: [
                self.positive("limits.elevator_deg", l.elevator_deg)?,
                self.positive("limits.aileron_deg", l.aileron_deg)?,
                self.positive("limits.rudder_deg", l.rudder_deg)?,
            ],
        })
    }

    fn aircraft_condition(&self, t: &TrimTable) -> Result<Condition, SceneError> {
        let optional = |key: &str, value: Option<f64>| self.finite(key, value.unwrap_or(0.0));
        let condition = Condition {
            speed: self.positive("trim.speed", t.speed)?,
            altitude: self.finite("trim.altitude", t.altitude)?,
            climb_angle: optional("trim.climb_angle_rad", t.climb_angle_rad)?,
            turn_rate: optional("trim.turn_rate_rad_s", t.turn_rate_rad_s)?,
            pull_up_rate: optional("trim.pull_up_rate_rad_s", t.pull_up_rate_rad_s)?,
        };
        if condition.turn_rate != 0.0 && condition.pull_up_rate != 0.0 {
            return Err(self.invalid(
                "trim.pull_up_rate_rad_s",
                "a turn and a pull-up at once is not a steady condition: give one",
            ));
        }
        if condition.climb_angle.abs() >= std::f64::consts::FRAC_PI_2 {
            return Err(self.invalid("trim.climb_angle_rad", "must be within ±π/2"));
        }
        Ok(condition)
    }

    fn aircraft_manoeuvre(
        &self,
        index: usize,
        t: &ManoeuvreTable,
        trim: &Trim,
        limits: &Limits,
    ) -> Result<AircraftManoeuvre, SceneError> {
        let key = |k: &str| format!("manoeuvre[{index}].{k}");
        let kind = self.word(
            &key("kind"),
            &t.kind,
            [
                (Manoeuvre::ElevatorDoublet, "elevator_doublet"),
                (Manoeuvre::AileronStep, "aileron_step"),
                (Manoeuvre::RudderKick, "rudder_kick"),
                (Manoeuvre::ThrottleStep, "throttle_step"),
                (Manoeuvre::PullUp, "pull_up"),
            ],
        )?;
        let amount = self.finite(&key("amount"), t.amount)?;
        let start = self.checked(
            &key("start_s"),
            crate::validate::Requirement::NonNegative,
            t.start_s.unwrap_or(1.0),
        )?;
        let duration = self.positive(&key("duration_s"), t.duration_s)?;
        let width = match (kind.has_width(), t.width_s) {
            (true, Some(w)) => self.positive(&key("width_s"), w)?,
            (true, None) => 1.0,
            (false, Some(_)) => {
                return Err(self.invalid(&key("width_s"), format!("a {} has no width", t.kind)));
            }
            (false, None) => 0.0,
        };
        if start >= duration {
            return Err(self.invalid(
                &key("start_s"),
                format!("{start} is not before the run's end {duration}"),
            ));
        }
        let manoeuvre = AircraftManoeuvre {
            name: t.name.clone().unwrap_or_else(|| t.kind.clone()),
            kind,
            amount,
            start,
            width,
            duration,
        };
        // Every command the manoeuvre gives must be within the limits.
        for command in manoeuvre.commands(&trim.controls) {
            let [throttle, elevator, aileron, rudder] = command;
            if !(0.0..=1.0).contains(&throttle) {
                return Err(self.invalid(
                    &key("amount"),
                    format!("takes the throttle to {throttle}, beyond 0 to 1"),
                ));
            }
            for ((surface, value), limit) in ["elevator", "aileron", "rudder"]
                .iter()
                .zip([elevator, aileron, rudder])
                .zip(limits.surfaces)
            {
                if value.abs() > limit {
                    return Err(self.invalid(
                        &key("amount"),
                        format!(
                            "takes the {surface} to {}°, beyond its limit ±{}°",
                            crate::Short(value),
                            crate::Short(limit)
                        ),
                    ));
                }
            }
        }
        Ok(manoeuvre)
    }
}

/// The trim's condition where it lies beyond the engine's tables, as a warning.
fn trim_beyond_tables(model: &AircraftModel, trimmed: &Trim) -> Vec<String> {
    let (speed, altitude) = (trimmed.state[0], trimmed.state[11]);
    let beyond = model.beyond_engine_tables(speed, altitude);
    match beyond.is_empty() {
        true => Vec::new(),
        false => vec![format!(
            "the trim is at {}: its thrust is the tables' linear extension past their ends, \
             not data, and so is every run and linear model that starts from it",
            beyond.join(" and ")
        )],
    }
}
