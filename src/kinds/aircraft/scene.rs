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
//! [limits]                     # α over the tables, each surface's deflection
//! [trim]                       # speed, altitude, climb, turn or pull-up
//! [[manoeuvre]]                # kind, amount, start_s, width_s, duration_s
//! [integrator]
//! ```

use super::aero::StevensLewisTables;
use super::atmosphere::Atmosphere;
use super::engine::Engine;
use super::manoeuvre::{AircraftManoeuvre, Manoeuvre, ROW};
use super::model::{AircraftModel, Airframe, CONTROLS, STATE};
use super::tables::{Breakpoints, Table1, Table2, TableError};
use super::trim::{Condition, Limits, Trim, trim};
use crate::InertiaTensor;
use crate::integrate::Stepper;
use crate::scene::check::Checker;
use crate::scene::envelope::{IntegratorTable, LinearTable, OutputTable};
use crate::scene::stop::StopCondition;
use crate::scene::{Problem, SceneError};
use serde::Deserialize;

/// The file as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AircraftSceneFile {
    /// What the scene is.
    pub title: String,
    /// The units, the atmosphere and the form of the aerodynamic tables.
    pub aircraft: AircraftTable,
    /// Mass, inertia, gravity.
    pub body: BodyTable,
    /// Wing area, span, chord, and where G and the tables' reference lie.
    pub geometry: GeometryTable,
    /// Thrust tables and the rotor.
    pub engine: EngineTable,
    /// The aerodynamic tables.
    pub aerodynamics: AerodynamicsTable,
    /// Where the tables and the surfaces end.
    pub limits: LimitsTable,
    /// The steady flight every manoeuvre starts from.
    pub trim: TrimTable,
    /// The method.
    pub integrator: IntegratorTable,
    /// The manoeuvres, each from the trim.
    #[serde(default)]
    pub manoeuvre: Vec<ManoeuvreTable>,
    /// Trajectory rows.
    #[serde(default)]
    pub output: OutputTable,
    /// The operating point of `eom linear` (by default the trim).
    pub linear: Option<LinearTable>,
    /// Values to sweep over (read by [`crate::scene::sweep`]).
    pub sweep: Option<toml::Table>,
}

/// `[aircraft]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AircraftTable {
    /// `us` (ft, slug, lbf) or `si` (m, kg, N); seconds, and degrees for the tables' angles
    /// and the surfaces, in both.
    pub units: String,
    /// `stevens-lewis` (its `adc`, in `us` units) or `standard-1976`.
    pub atmosphere: String,
    /// The form of the tables: `stevens-lewis`.
    pub aerodynamics: String,
}

/// `[body]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyTable {
    /// Mass.
    pub mass: f64,
    /// I_xx, I_yy, I_zz about G.
    pub inertia: [f64; 3],
    /// I_xy, I_yz, I_xz about G, the tensor's off-diagonal entries (the chapter's sign:
    /// −∫xz dm; Stevens & Lewis's J_xz = +982 slug ft² is −982 here).
    pub products_of_inertia: Option<[f64; 3]>,
    /// Gravity.
    pub gravity: f64,
}

/// `[geometry]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GeometryTable {
    /// Wing reference area S.
    pub area: f64,
    /// Span b.
    pub span: f64,
    /// Mean aerodynamic chord c̄.
    pub chord: f64,
    /// G, as a fraction of c̄ aft of its leading edge.
    pub xcg: f64,
    /// Where the moment tables are given, likewise.
    pub xcg_reference: f64,
}

/// `[engine]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EngineTable {
    /// The rotor's angular momentum along body x.
    pub rotor_momentum: f64,
    /// The thrust tables' altitudes.
    pub altitude: Vec<f64>,
    /// Their Mach numbers.
    pub mach: Vec<f64>,
    /// Thrust at idle, `[altitude][mach]`.
    pub idle: Vec<Vec<f64>>,
    /// At military power.
    pub military: Vec<Vec<f64>>,
    /// At maximum power.
    pub maximum: Vec<Vec<f64>>,
}

/// A table in α and the elevator.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AlphaElevator {
    /// α's breakpoints, deg.
    pub alpha_deg: Vec<f64>,
    /// The elevator's, deg.
    pub elevator_deg: Vec<f64>,
    /// `[α][elevator]`.
    pub values: Vec<Vec<f64>>,
}

/// A table in α and |β|.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AlphaBetaAbs {
    /// α's breakpoints, deg.
    pub alpha_deg: Vec<f64>,
    /// |β|'s, deg.
    pub beta_abs_deg: Vec<f64>,
    /// `[α][|β|]`.
    pub values: Vec<Vec<f64>>,
}

/// A table in α and β.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AlphaBeta {
    /// α's breakpoints, deg.
    pub alpha_deg: Vec<f64>,
    /// β's, deg.
    pub beta_deg: Vec<f64>,
    /// `[α][β]`.
    pub values: Vec<Vec<f64>>,
}

/// A table in α.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Alpha {
    /// α's breakpoints, deg.
    pub alpha_deg: Vec<f64>,
    /// The values.
    pub values: Vec<f64>,
}

/// The damping derivatives, each in α.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
#[allow(non_snake_case)]
pub struct DampingTable {
    /// α's breakpoints, deg.
    pub alpha_deg: Vec<f64>,
    /// C_Xq.
    pub CXq: Vec<f64>,
    /// C_Yr.
    pub CYr: Vec<f64>,
    /// C_Yp.
    pub CYp: Vec<f64>,
    /// C_Zq.
    pub CZq: Vec<f64>,
    /// C_lr.
    pub Clr: Vec<f64>,
    /// C_lp.
    pub Clp: Vec<f64>,
    /// C_mq.
    pub Cmq: Vec<f64>,
    /// C_nr.
    pub Cnr: Vec<f64>,
    /// C_np.
    pub Cnp: Vec<f64>,
}

/// `[aerodynamics]`: the tables of the Stevens & Lewis form.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AerodynamicsTable {
    /// C_x(α, δ_e).
    pub cx: AlphaElevator,
    /// C_z(α).
    pub cz: Alpha,
    /// C_m(α, δ_e).
    pub cm: AlphaElevator,
    /// C_l(α, |β|).
    pub cl: AlphaBetaAbs,
    /// C_n(α, |β|).
    pub cn: AlphaBetaAbs,
    /// ΔC_l per δ_a/20.
    pub dlda: AlphaBeta,
    /// ΔC_l per δ_r/30.
    pub dldr: AlphaBeta,
    /// ΔC_n per δ_a/20.
    pub dnda: AlphaBeta,
    /// ΔC_n per δ_r/30.
    pub dndr: AlphaBeta,
    /// The damping derivatives.
    pub damping: DampingTable,
}

/// `[limits]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LimitsTable {
    /// α's range with data, deg.
    pub alpha_deg: [f64; 2],
    /// The elevator's deflection limit, ± deg.
    pub elevator_deg: f64,
    /// The aileron's.
    pub aileron_deg: f64,
    /// The rudder's.
    pub rudder_deg: f64,
}

/// `[trim]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrimTable {
    /// True airspeed.
    pub speed: f64,
    /// Altitude.
    pub altitude: f64,
    /// Flight-path angle γ, rad.
    pub climb_angle_rad: Option<f64>,
    /// Turn rate ψ̇ of a coordinated turn, rad/s.
    pub turn_rate_rad_s: Option<f64>,
    /// Pitch rate of a pull-up, rad/s.
    pub pull_up_rate_rad_s: Option<f64>,
}

/// `[[manoeuvre]]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ManoeuvreTable {
    /// `elevator_doublet`, `aileron_step`, `rudder_kick`, `throttle_step`, `pull_up`.
    pub kind: String,
    /// Its folder's name; `kind` where absent.
    pub name: Option<String>,
    /// The deflection from the trim, deg (a throttle step's change of throttle, 0 to 1).
    pub amount: f64,
    /// When it starts, s.
    pub start_s: Option<f64>,
    /// A doublet's half and a kick's pulse, s.
    pub width_s: Option<f64>,
    /// How long the run lasts, s.
    pub duration_s: f64,
}

/// A checked aircraft scene, ready to run.
#[derive(Debug, Clone)]
pub struct AircraftScene {
    /// What the scene is.
    pub title: String,
    /// The model.
    pub model: AircraftModel,
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
    /// The wing's span and chord, for the view.
    pub span: f64,
    /// The mean aerodynamic chord.
    pub chord: f64,
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
        check.word(
            "aircraft.aerodynamics",
            &file.aircraft.aerodynamics,
            [((), "stevens-lewis")],
        )?;
        let airframe = check.aircraft_airframe(file)?;
        let tensor = airframe.inertia.matrix();
        let mass_properties = (
            airframe.mass,
            std::array::from_fn(|r| std::array::from_fn(|c| tensor[(r, c)])),
        );
        let (span, chord) = (airframe.span, airframe.chord);
        let tables = check.aircraft_aerodynamics(&file.aerodynamics)?;
        let engine = check.aircraft_engine(&file.engine)?;
        let model = AircraftModel::new(&airframe, tables, engine, atmosphere)
            .map_err(|e| check.invalid("body", e.to_string()))?;
        let limits = check.aircraft_limits(&file.limits)?;
        let condition = check.aircraft_condition(&file.trim)?;
        let trimmed =
            trim(&model, &condition, &limits).map_err(|e| check.invalid("trim", e.to_string()))?;
        if file.manoeuvre.is_empty() {
            return Err(check.error(
                "manoeuvre",
                Problem::Missing("at least one [[manoeuvre]]".into()),
            ));
        }
        let mut manoeuvres: Vec<AircraftManoeuvre> = Vec::new();
        for (index, table) in file.manoeuvre.iter().enumerate() {
            let manoeuvre = check.aircraft_manoeuvre(index, table, &trimmed, &limits)?;
            if manoeuvres.iter().any(|m| m.name == manoeuvre.name) {
                return Err(check.invalid(
                    &format!("manoeuvre[{index}].name"),
                    format!("`{}` is taken by an earlier manoeuvre", manoeuvre.name),
                ));
            }
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
        Ok(AircraftScene {
            title: file.title.clone(),
            model,
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
            span,
            chord,
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
        let [ixy, iyz, ixz] = self.finite3("body.products_of_inertia", body.products_of_inertia)?;
        if ixy != 0.0 || iyz != 0.0 {
            return Err(self.invalid(
                "body.products_of_inertia",
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
        let d = &a.damping;
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
            cx: in_elevator("aerodynamics.cx", &a.cx)?,
            cz: one("aerodynamics.cz", &a.cz.alpha_deg, &a.cz.values)?,
            cm: in_elevator("aerodynamics.cm", &a.cm)?,
            cl: in_beta_abs("aerodynamics.cl", &a.cl)?,
            cn: in_beta_abs("aerodynamics.cn", &a.cn)?,
            dlda: in_beta("aerodynamics.dlda", &a.dlda)?,
            dldr: in_beta("aerodynamics.dldr", &a.dldr)?,
            dnda: in_beta("aerodynamics.dnda", &a.dnda)?,
            dndr: in_beta("aerodynamics.dndr", &a.dndr)?,
            damping: tables.try_into().expect("nine damping tables"),
        })
    }

    fn aircraft_engine(&self, e: &EngineTable) -> Result<Engine, SceneError> {
        let table = |level: &str, values: &[Vec<f64>]| {
            self.aircraft_grid(
                &format!("engine.{level}"),
                ("altitude", &e.altitude),
                ("mach", &e.mach),
                values,
            )
        };
        Ok(Engine {
            idle: table("idle", &e.idle)?,
            military: table("military", &e.military)?,
            maximum: table("maximum", &e.maximum)?,
        })
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
                        format!("takes the {surface} to {value}°, beyond its limit ±{limit}°"),
                    ));
                }
            }
        }
        Ok(manoeuvre)
    }
}
