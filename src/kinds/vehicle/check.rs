//! A vehicle scene's own checks, methods of every scene's [`Checker`]: the body, the table,
//! the propeller, the cross-flow, the fins, the autopilots, the trim, each `[[manoeuvre]]`.

use super::autopilot::{Autopilots, DepthGains, HeadingGains, Setpoints};
use super::cross_flow::CrossFlow;
use super::file::{
    AutopilotTable, BodyTable, CrossFlowTable, HydrodynamicsTable, ManoeuvreTable, PropellerTable,
    VehicleSceneFile,
};
use super::fins::{FinSteps, Fins};
use super::manoeuvre::VehicleManoeuvre;
use super::model::VehicleModel;
use super::propeller::PropellerLaw;
use super::scene::{GRAVITY, written_rounding};
use super::table::{PrimeScales, PropellerSetting, VehicleTable};
use super::trial::{Plane, Trial};
use super::trim::{Held, Trim, Trimmer};
use super::{AddedMassCoriolis, Convention, InertiaAbout};
use crate::scene::check::Checker;
use crate::scene::envelope::SteeringGearTable;
use crate::scene::{Problem, SceneError};
use crate::{InertiaTensor, Short, counted};
use nalgebra::Matrix3;

/// A vehicle's own tables, checked by the checker of every scene.
impl Checker<'_> {
    pub(super) fn vehicle_table(
        &self,
        file: &VehicleSceneFile,
    ) -> Result<VehicleTable, SceneError> {
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
    pub(super) fn mass_against_weight(&self, mass: f64, weight: f64) -> Result<(), SceneError> {
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
    pub(super) fn vehicle_inertia(
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
    pub(super) fn vehicle_propeller(
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
    pub(super) fn thrust(&self, thrust: f64) -> Result<f64, SceneError> {
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
    pub(super) fn cross_flow(
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
    pub(super) fn prime_scales(
        &self,
        hydro: &HydrodynamicsTable,
    ) -> Result<Option<PrimeScales>, SceneError> {
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
    pub(super) fn vehicle_manoeuvre(
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
    pub(super) fn held_trim(
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
    pub(super) fn within_stops(
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
    pub(super) fn zigzag(&self, index: usize, table: &ManoeuvreTable) -> Result<Trial, SceneError> {
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
    pub(super) fn listed(
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
    pub(super) fn setpoints(
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
    pub(super) fn autopilots(
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
