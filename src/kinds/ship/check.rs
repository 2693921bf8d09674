//! A ship scene's own checks, methods of the checker every scene's tables are checked by
//! ([`Checker`]: its errors, its value checks, its method checks): the body and the table in
//! their units, the propulsion, and each `[[manoeuvre]]` by its kind, against what the ship
//! is (its linear model, its propulsion, its steering gear, its length). An MMG table's own
//! are `super::mmg`'s (its `check` module).

use super::ShipError;
use super::file::{BodyTable, EnvironmentTable, ManoeuvreTable, PropulsionTable, ShipSceneFile};
use super::linear::LinearModel;
use super::manoeuvre::{Manoeuvre, ManoeuvreKind};
use super::propulsion::Propulsion;
use super::scene::{
    CONTROLLER_TIME_S, MAX_HOLD_S, SETTLE_RUDDER_DEG, SETTLE_SPEED_M_S, SETTLE_TOLERANCE_DEG_S,
    SETTLE_WINDOW_S,
};
use super::side::Side;
use super::spiral::{ReverseSpiral, Settle, Spiral};
use super::table::{Current, GivenTable, RigidBodyTerms, ShipBody, ShipTable};
use super::{ShipForm, Units, YawInertia};
use crate::manoeuvring::steering::{Rudder, Series};
use crate::scene::check::Checker;
use crate::scene::{Problem, SceneError};

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
pub(super) struct Ship<'a> {
    pub(super) linear: &'a LinearModel,
    pub(super) propulsion: Option<&'a Propulsion>,
    pub(super) rudder: &'a Rudder,
    pub(super) length: f64,
}

/// A ship's own tables, checked by the checker of every scene ([`Checker`]: its errors, its
/// value checks, its method checks).
impl Checker<'_> {
    /// Exactly one of the keys given, among those of the table's units; the others refused.
    pub(super) fn one_of(
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

    pub(super) fn ship_body(
        &self,
        body: &BodyTable,
        units: Units,
    ) -> Result<(ShipBody, f64), SceneError> {
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

    pub(super) fn table(&self, file: &ShipSceneFile) -> Result<(ShipTable, f64), SceneError> {
        let hydro = &file.hydrodynamics;
        let form = self.word(
            "hydrodynamics.model",
            hydro.model.as_deref().unwrap_or("polynomial"),
            [(ShipForm::Polynomial, "polynomial"), (ShipForm::Mmg, "mmg")],
        )?;
        if form == ShipForm::Mmg {
            return self.mmg_table(file);
        }
        self.none_of(
            [
                ("particulars", hydro.particulars.is_some()),
                ("propeller_rate_rps", hydro.propeller_rate_rps.is_some()),
            ],
            "a key of an MMG table (model = \"mmg\"); a polynomial table's propeller is \
             [propulsion]",
        )?;
        let word = |key: &str, given: &Option<String>| {
            given.clone().ok_or_else(|| {
                self.error(
                    key,
                    Problem::Missing(format!("{key}, in a polynomial table")),
                )
            })
        };
        let units = self.word(
            "hydrodynamics.units",
            &word("hydrodynamics.units", &hydro.units)?,
            [(Units::Prime, "prime"), (Units::Dimensional, "dimensional")],
        )?;
        let rigid_body_terms = self.word(
            "hydrodynamics.rigid_body_terms",
            &word("hydrodynamics.rigid_body_terms", &hydro.rigid_body_terms)?,
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

    /// `[environment]`: a current of a speed (≥ 0) toward a direction, both given.
    pub(super) fn current(&self, table: &EnvironmentTable) -> Result<Option<Current>, SceneError> {
        let Some((speed, toward)) = self.speed_and_direction(
            ("environment.current_m_s", table.current_m_s),
            ("environment.current_toward_deg", table.current_toward_deg),
            [
                "the current's speed",
                "the direction the current flows toward",
                "it flows toward",
            ],
        )?
        else {
            return Ok(None);
        };
        let toward = self.finite("environment.current_toward_deg", toward)?;
        Ok(Some(Current {
            speed,
            toward: toward.to_radians(),
        }))
    }

    /// A speed and a direction given together (a current's, a wind's), or neither (`None`):
    /// the speed finite and not negative, the direction as written. `said` is what the speed
    /// is, what the direction is, and how the direction is read (`it flows toward`).
    pub(super) fn speed_and_direction(
        &self,
        (speed_key, speed): (&str, Option<f64>),
        (direction_key, direction): (&str, Option<f64>),
        [speed_is, direction_is, read]: [&str; 3],
    ) -> Result<Option<(f64, f64)>, SceneError> {
        let (speed, direction) = match (speed, direction) {
            (None, None) => return Ok(None),
            (Some(speed), Some(direction)) => (speed, direction),
            (Some(_), None) => {
                return Err(self.error(direction_key, Problem::Missing(direction_is.into())));
            }
            (None, Some(_)) => return Err(self.error(speed_key, Problem::Missing(speed_is.into()))),
        };
        let speed = self.finite(speed_key, speed)?;
        if speed < 0.0 {
            return Err(self.invalid(
                speed_key,
                format!("{speed} m/s: a speed is not negative (give the direction {read})"),
            ));
        }
        Ok(Some((speed, direction)))
    }

    /// `[propulsion]`, each number checked; the rate at the approach is solved by the table.
    pub(super) fn propulsion(&self, table: &PropulsionTable) -> Result<Propulsion, SceneError> {
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
    pub(super) fn within_gear(
        &self,
        key: &str,
        degrees: f64,
        rudder: &Rudder,
    ) -> Result<(), SceneError> {
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

    pub(super) fn manoeuvre(
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
                        "a crash stop needs a propulsion model to go astern: give [propulsion] (a \
                         polynomial table's; an MMG ship's propeller turns ahead only)",
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
    pub(super) fn spiral_angles(
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
    pub(super) fn spiral(
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
