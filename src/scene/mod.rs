//! Scenes: a body, what acts on it, where it starts and how to integrate it, in one TOML file.
//!
//! A scene is read in two passes. [`file`](mod@file) reads the TOML into tables with serde,
//! every table closed to unknown keys, so that a misspelt key is an error and not a silent
//! default; then [`Scene::from_file`] checks each value for its family and builds what runs:
//! the smallest proved model the scene needs ([`select_spatial`]), the loads as inputs of that
//! model ([`SceneLoads`]), the initial state in the model's own layout, and the integrator.
//! Every error names the key by its path in the file (`integrator.step`) and says what is
//! wrong with it.
//!
//! Space axes are X north, Y east, Z down and body axes x forward, y to starboard, z down, as
//! in the chapter's ship dynamics; angles in a scene file are in degrees, rates in rad/s.

mod error;
pub mod file;
mod loads;
mod select;
pub mod sweep;

pub use error::{Problem, SceneError};
pub use loads::{PendulumLoads, PlanarLoads, SceneLoads, SpatialLoads, TopLoads, euler_angles};
pub use select::{Selection, select_spatial};

use crate::integrate::AdaptiveOptions;
use crate::models::{
    AnyModel, Family, Kinematics, ModelInfo, Pendulum, PlanarAtG, PlanarMidship, PlanarSpaceFixed,
    Symmetry, TopEuler, TopQuaternion,
};
use crate::{InertiaTensor, ParameterError, PendulumParameters};
use file::{GivenKeys, SceneFile};
use nalgebra::{Matrix3, UnitQuaternion};
use std::path::Path;

/// A scene, checked, ready to run.
#[derive(Debug, Clone)]
pub struct Scene {
    /// The title from the file.
    pub title: String,
    /// The model that runs, and why it was chosen.
    pub selection: Selection,
    /// The body's parameters.
    pub body: Body,
    /// The initial state, in the model's state layout.
    pub initial: Vec<f64>,
    /// What acts on the body.
    pub loads: SceneLoads,
    /// How to integrate.
    pub integrator: IntegratorSpec,
    /// Trajectory rows at t = k·every.
    pub every: f64,
}

/// A scene's body, by family.
#[derive(Debug, Clone)]
pub enum Body {
    /// The compound pendulum.
    Pendulum(PendulumParameters),
    /// A planar body: mass, I_zz about G, and G ahead of midship (midship family only).
    Planar {
        /// M.
        mass: f64,
        /// I_zz about G.
        izz: f64,
        /// x_G, for the midship family.
        x_g: Option<f64>,
    },
    /// A spatial body: mass and the tensor about G.
    Spatial {
        /// M.
        mass: f64,
        /// The tensor about G, body axes.
        inertia: InertiaTensor,
    },
    /// A heavy top: mass, the principal tensor about G, G at h along the body z-axis from
    /// the pivot, gravity g.
    Top {
        /// M.
        mass: f64,
        /// The tensor about G, principal axes.
        inertia: InertiaTensor,
        /// Pivot to G along the body z-axis.
        h: f64,
        /// Gravity, along −Z in the top's space axes.
        g: f64,
    },
}

/// The integration methods a scene can name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Explicit Euler, fixed step.
    Euler,
    /// Semi-implicit Euler, fixed step, velocities kicked first.
    SymplecticEuler,
    /// Classical Runge–Kutta, fixed step.
    Rk4,
    /// Dormand–Prince 5(4), adaptive.
    Dopri5,
    /// Dormand–Prince 8(5,3), adaptive.
    Dop853,
    /// The geometric rotation integrator, fixed step (free spatial bodies with a quaternion).
    LieMidpoint,
}

impl Method {
    /// Every method, by its name in scene files.
    pub const ALL: [(Method, &'static str); 6] = [
        (Method::Euler, "euler"),
        (Method::SymplecticEuler, "symplectic-euler"),
        (Method::Rk4, "rk4"),
        (Method::Dopri5, "dopri5"),
        (Method::Dop853, "dop853"),
        (Method::LieMidpoint, "lie-midpoint"),
    ];

    /// The name in scene files.
    pub fn name(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(m, _)| *m == self)
            .map(|(_, n)| *n)
            .expect("every method is listed")
    }

    /// Whether the step is chosen by a tolerance.
    pub fn is_adaptive(self) -> bool {
        matches!(self, Method::Dopri5 | Method::Dop853)
    }
}

/// How a scene is integrated: a method and its step or tolerances.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IntegratorSpec {
    /// The method.
    pub method: Method,
    /// The step of a fixed-step method.
    pub step: Option<f64>,
    /// The options of an adaptive method.
    pub adaptive: Option<AdaptiveOptions>,
    /// The run ends at t = end_time (it starts at 0).
    pub end_time: f64,
    /// The most steps a run may take.
    pub max_steps: usize,
}

/// The default tolerances of an adaptive method when the scene gives none.
pub const DEFAULT_TOLERANCE: f64 = 1e-9;
/// The default limit on steps.
pub const DEFAULT_MAX_STEPS: usize = 1_000_000;
/// The most trajectory rows a scene may ask for (10⁸: a CSV of a few gigabytes at most).
pub const MAX_ROWS: usize = 100_000_000;
/// Trajectory rows a scene gets when it sets no `output.every`.
pub const DEFAULT_ROWS: f64 = 500.0;

impl Scene {
    /// Reads and checks the scene file at `path` (a `body.file` is found relative to it).
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let name = error::display_name(path);
        let text = std::fs::read_to_string(path)
            .map_err(|e| SceneError::new(&name, "", Problem::Read(e)))?;
        let base = path.parent().unwrap_or(Path::new("."));
        Self::parse(&text, &name, base)
    }

    /// Reads and checks scene text; `name` is how errors name the file, `base` where a
    /// `body.file` is found.
    pub fn parse(text: &str, name: &str, base: &Path) -> Result<Self, SceneError> {
        Self::from_file(&read(text, name)?, name, base)
    }

    /// Checks the tables of a scene file.
    pub fn from_file(file: &SceneFile, name: &str, base: &Path) -> Result<Self, SceneError> {
        let check = Checker { name };
        let family = check.family(&file.model.family)?;
        check.keys_of_family(file, family)?;
        let body = check.body(file, family, base)?;
        let selection = check.selection(file, family, &body)?;
        let initial = check.initial(file, &selection)?;
        let loads = SceneLoads::from_table(&file.loads, &selection, &body)
            .map_err(|(key, problem)| SceneError::new(name, &key, problem))?;
        let integrator = check.integrator(file, &selection, &loads)?;
        let every = check.every(file, integrator.end_time)?;
        Ok(Scene {
            title: file.title.clone(),
            selection,
            body,
            initial,
            loads,
            integrator,
            every,
        })
    }

    /// The typed model the scene runs, over f64.
    pub fn model(&self) -> AnyModel {
        let info = self.selection.info;
        match (&self.body, info.family) {
            (Body::Pendulum(p), _) => Pendulum::new(p).into(),
            (Body::Planar { mass, izz, .. }, Family::PlanarAtG) => PlanarAtG::new(*mass, *izz)
                .expect("checked when the scene was read")
                .into(),
            (Body::Planar { mass, izz, x_g }, Family::PlanarMidship) => {
                PlanarMidship::new(*mass, *izz, x_g.unwrap_or(0.0))
                    .expect("checked when the scene was read")
                    .into()
            }
            (Body::Planar { mass, izz, .. }, _) => PlanarSpaceFixed::new(*mass, *izz)
                .expect("checked when the scene was read")
                .into(),
            (
                Body::Top {
                    mass,
                    inertia,
                    h,
                    g,
                },
                _,
            ) => top(info, *mass, inertia, *h, *g).expect("checked when the scene was read"),
            (Body::Spatial { mass, inertia }, _) => AnyModel::spatial(
                info.symmetry.expect("a spatial model has a symmetry class"),
                info.kinematics.expect("a spatial model has a kinematics"),
                *mass,
                inertia,
            )
            .expect("checked when the scene was read"),
        }
    }

    /// The state entries' names as the trajectory's columns: the model's layout, in
    /// identifiers (`x` for X).
    pub fn state_names(&self) -> Vec<String> {
        self.selection
            .info
            .state
            .iter()
            .map(|s| s.to_lowercase())
            .collect()
    }
}

/// The top of a catalog entry, as a model chosen at run time.
fn top(
    info: &ModelInfo,
    mass: f64,
    inertia: &InertiaTensor,
    h: f64,
    g: f64,
) -> Result<AnyModel, crate::generic::ModelError> {
    Ok(match info.kinematics {
        Some(Kinematics::Euler) => TopEuler::new(mass, inertia, h, g)?.into(),
        _ => TopQuaternion::new(mass, inertia, h, g)?.into(),
    })
}

/// Reads scene text into its tables: a syntax error, an unknown key or a wrong type names the
/// key's path.
pub fn read(text: &str, name: &str) -> Result<SceneFile, SceneError> {
    let deserializer = toml::Deserializer::parse(text)
        .map_err(|e| SceneError::new(name, "", Problem::Syntax(e.to_string())))?;
    serde_path_to_error::deserialize(deserializer).map_err(|e| {
        let key = e.path().to_string();
        let key = if key == "." { String::new() } else { key };
        let message = e.into_inner().message().to_owned();
        let problem = if message.starts_with("missing field") {
            Problem::Missing(message)
        } else {
            Problem::Schema(message)
        };
        SceneError::new(name, &key, problem)
    })
}

/// The checks of one scene file, each naming its key.
struct Checker<'a> {
    name: &'a str,
}

/// The keys a family reads in each table; any other key given is an error.
struct FamilyKeys {
    body: &'static [&'static str],
    initial: &'static [&'static str],
    loads: &'static [&'static str],
}

fn family_keys(family: Family) -> FamilyKeys {
    match family {
        Family::Pendulum => FamilyKeys {
            body: &["i0", "mass", "g", "h"],
            initial: &["theta_deg", "theta_dot"],
            loads: &["moment", "linear_damping", "quadratic_damping"],
        },
        Family::PlanarAtG | Family::PlanarSpaceFixed => FamilyKeys {
            body: &["mass", "izz"],
            initial: &["u", "v", "r", "x", "y", "psi_deg"],
            loads: PLANAR_LOADS,
        },
        Family::PlanarMidship => FamilyKeys {
            body: &["mass", "izz", "x_g"],
            initial: &["u", "v", "r", "x", "y", "psi_deg"],
            loads: PLANAR_LOADS,
        },
        Family::Top => FamilyKeys {
            body: &["mass", "inertia", "h", "g"],
            initial: &["rates", "attitude_deg"],
            loads: &["moment_body", "linear_damping", "quadratic_damping"],
        },
        Family::Spatial => FamilyKeys {
            body: &["mass", "inertia", "file"],
            initial: &["velocity", "rates", "position", "attitude_deg"],
            loads: &[
                "gravity",
                "buoyancy",
                "buoyancy_centre",
                "force_body",
                "force_space",
                "moment_body",
                "moment_space",
                "linear_damping",
                "quadratic_damping",
            ],
        },
    }
}

const PLANAR_LOADS: &[&str] = &[
    "force_body",
    "force_space",
    "moment",
    "linear_damping",
    "quadratic_damping",
];

impl Checker<'_> {
    fn error(&self, key: &str, problem: Problem) -> SceneError {
        SceneError::new(self.name, key, problem)
    }

    fn invalid(&self, key: &str, message: impl Into<String>) -> SceneError {
        self.error(key, Problem::Invalid(message.into()))
    }

    fn missing(&self, key: &str, why: &str) -> SceneError {
        self.error(key, Problem::Missing(why.to_owned()))
    }

    /// A value checked by the crate's parameter checks, the error naming its key.
    fn parameter(
        &self,
        key: &str,
        check: impl FnOnce() -> Result<f64, ParameterError>,
    ) -> Result<f64, SceneError> {
        check()
            .map_err(|e| self.invalid(key, format!("must be {}, got {}", e.requirement, e.value)))
    }

    fn family(&self, name: &str) -> Result<Family, SceneError> {
        Family::ALL
            .into_iter()
            .find(|f| f.name() == name)
            .ok_or_else(|| {
                let names: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
                self.invalid(
                    "model.family",
                    format!("unknown family `{name}`; one of {}", names.join(", ")),
                )
            })
    }

    /// Refuses a key that another family reads: it would be ignored, silently.
    fn keys_of_family(&self, file: &SceneFile, family: Family) -> Result<(), SceneError> {
        let keys = family_keys(family);
        let tables: [(&str, Vec<&str>, &[&str]); 3] = [
            ("body", file.body.given(), keys.body),
            ("initial", file.initial.given(), keys.initial),
            ("loads", file.loads.given(), keys.loads),
        ];
        for (table, given, allowed) in tables {
            if let Some(key) = given.iter().find(|k| !allowed.contains(k)) {
                return Err(self.error(
                    &format!("{table}.{key}"),
                    Problem::Schema(format!(
                        "not a key of a {} scene; its [{table}] takes {}",
                        family.name(),
                        allowed.join(", ")
                    )),
                ));
            }
        }
        let has_attitude = matches!(family, Family::Spatial | Family::Top);
        let misplaced = [
            (
                "model.symmetry",
                file.model.symmetry.is_some() && family != Family::Spatial,
            ),
            (
                "model.kinematics",
                file.model.kinematics.is_some() && !has_attitude,
            ),
        ];
        match misplaced.iter().find(|(_, misplaced)| *misplaced) {
            Some((key, _)) => Err(self.error(
                key,
                Problem::Schema(format!("a {} scene does not take it", family.name())),
            )),
            None => Ok(()),
        }
    }

    /// An error naming the first of `keys` that is given, where none may be.
    fn refuse_given(&self, keys: [(&str, bool); 2], why: &str) -> Result<(), SceneError> {
        match keys.iter().find(|(_, given)| *given) {
            Some((key, _)) => Err(self.invalid(key, why)),
            None => Ok(()),
        }
    }

    /// The tensor about G of `body.inertia`, a physical one.
    fn tensor(&self, rows: Option<[[f64; 3]; 3]>, what: &str) -> Result<InertiaTensor, SceneError> {
        let rows = rows.ok_or_else(|| self.missing("body.inertia", what))?;
        InertiaTensor::from_matrix(Matrix3::from_fn(|r, c| rows[r][c]))
            .map_err(|e| self.invalid("body.inertia", e.to_string()))
    }

    fn required(&self, key: &str, value: Option<f64>, what: &str) -> Result<f64, SceneError> {
        value.ok_or_else(|| self.missing(key, what))
    }

    fn body(&self, file: &SceneFile, family: Family, base: &Path) -> Result<Body, SceneError> {
        let b = &file.body;
        match family {
            Family::Pendulum => {
                let i0 = self.required("body.i0", b.i0, "I₀ about the pivot, kg m²")?;
                let mass = self.required("body.mass", b.mass, "the mass, kg")?;
                let g = self.required("body.g", b.g, "gravity, m/s²")?;
                let h = self.required("body.h", b.h, "the pivot-to-G distance, m")?;
                PendulumParameters::new(i0, mass, g, h)
                    .map(Body::Pendulum)
                    .map_err(|e| self.invalid(&format!("body.{}", e.field), e.to_string()))
            }
            Family::PlanarAtG | Family::PlanarMidship | Family::PlanarSpaceFixed => {
                let mass = self.required("body.mass", b.mass, "the mass, kg")?;
                let izz = self.required("body.izz", b.izz, "I_zz about G, kg m²")?;
                let mass =
                    self.parameter("body.mass", || crate::validate::positive("mass", mass))?;
                let izz = self.parameter("body.izz", || crate::validate::positive("izz", izz))?;
                let x_g = match family {
                    Family::PlanarMidship => {
                        let x_g = self.required("body.x_g", b.x_g, "G ahead of midship, m")?;
                        Some(self.parameter("body.x_g", || crate::validate::finite("x_g", x_g))?)
                    }
                    _ => None,
                };
                Ok(Body::Planar { mass, izz, x_g })
            }
            Family::Spatial => self.spatial_body(b, base),
            Family::Top => self.top_body(b),
        }
    }

    fn top_body(&self, b: &file::BodyTable) -> Result<Body, SceneError> {
        let mass = self.required("body.mass", b.mass, "the mass, kg")?;
        let inertia = self.tensor(b.inertia, "the principal tensor about G, kg m²")?;
        let h = self.required("body.h", b.h, "pivot to G along the body z-axis, m")?;
        let g = self.required("body.g", b.g, "gravity, m/s²")?;
        let info = ModelInfo::of_family(Family::Top)
            .next()
            .expect("the catalog has a top");
        top(info, mass, &inertia, h, g).map_err(|e| {
            let key = match &e {
                crate::generic::ModelError::Parameter(p) => format!("body.{}", p.field),
                _ => "body.inertia".to_owned(),
            };
            self.invalid(&key, e.to_string())
        })?;
        Ok(Body::Top {
            mass,
            inertia,
            h,
            g,
        })
    }

    fn spatial_body(&self, b: &file::BodyTable, base: &Path) -> Result<Body, SceneError> {
        if let Some(path) = &b.file {
            self.refuse_given(
                [
                    ("body.mass", b.mass.is_some()),
                    ("body.inertia", b.inertia.is_some()),
                ],
                "give either body.file or body.mass and body.inertia, not both",
            )?;
            let description = crate::mass::BodyFile::load(&base.join(path))
                .map_err(|e| self.error("body.file", Problem::BodyFile(Box::new(e))))?;
            let properties = description
                .mass_properties()
                .map_err(|e| self.error("body.file", Problem::BodyFile(Box::new(e))))?;
            return Ok(Body::Spatial {
                mass: properties.mass(),
                inertia: properties.inertia(),
            });
        }
        let mass = self.required("body.mass", b.mass, "the mass, kg (or body.file)")?;
        let mass = self.parameter("body.mass", || crate::validate::positive("mass", mass))?;
        let inertia = self.tensor(
            b.inertia,
            "the tensor about G, [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] (or body.file)",
        )?;
        Ok(Body::Spatial { mass, inertia })
    }

    fn selection(
        &self,
        file: &SceneFile,
        family: Family,
        body: &Body,
    ) -> Result<Selection, SceneError> {
        if family == Family::Top {
            let kinematics = self.kinematics(file)?;
            let info = ModelInfo::of_family(family)
                .find(|i| i.kinematics == Some(kinematics))
                .expect("the catalog has a top of each kinematics");
            return Ok(Selection {
                info,
                reason: format!(
                    "a top with {} kinematics, as the scene says",
                    kinematics.name()
                ),
            });
        }
        let Body::Spatial { mass, inertia } = body else {
            let info = ModelInfo::of_family(family)
                .next()
                .expect("every family has a model");
            return Ok(Selection::only(info));
        };
        let symmetry = match file.model.symmetry.as_deref() {
            None | Some("auto") => None,
            Some(name) => Some(self.named(
                "model.symmetry",
                name,
                Symmetry::ALL.map(|s| (s, s.name())),
                "auto",
            )?),
        };
        let kinematics = self.kinematics(file)?;
        let selection = select_spatial(inertia, symmetry, kinematics)
            .map_err(|message| self.invalid("model.symmetry", message))?;
        // The model checks more than a valid tensor promises (a determinant that f64 can
        // invert, 1e-110 kg m² on the diagonal is not): a scene accepted builds its model.
        let symmetry = selection
            .info
            .symmetry
            .expect("a spatial model has a symmetry class");
        AnyModel::spatial(symmetry, kinematics, *mass, inertia).map_err(|e| {
            let key = if file.body.file.is_some() {
                "body.file"
            } else {
                match e {
                    crate::generic::ModelError::Parameter(_) => "body.mass",
                    _ => "body.inertia",
                }
            };
            self.invalid(key, e.to_string())
        })?;
        Ok(selection)
    }

    /// `model.kinematics`, quaternion when the scene leaves it out.
    fn kinematics(&self, file: &SceneFile) -> Result<Kinematics, SceneError> {
        match file.model.kinematics.as_deref() {
            None => Ok(Kinematics::Quaternion),
            Some(name) => self.named(
                "model.kinematics",
                name,
                Kinematics::ALL.map(|k| (k, k.name())),
                "",
            ),
        }
    }

    /// One of `values` by its name, or an error listing the names.
    fn named<V: Copy, const K: usize>(
        &self,
        key: &str,
        name: &str,
        values: [(V, &'static str); K],
        extra: &str,
    ) -> Result<V, SceneError> {
        values
            .iter()
            .find(|(_, n)| *n == name)
            .map(|(v, _)| *v)
            .ok_or_else(|| {
                let mut names: Vec<&str> = values.iter().map(|(_, n)| *n).collect();
                if !extra.is_empty() {
                    names.insert(0, extra);
                }
                self.invalid(
                    key,
                    format!("unknown value `{name}`; one of {}", names.join(", ")),
                )
            })
    }

    fn finite(&self, key: &str, value: f64) -> Result<f64, SceneError> {
        if value.is_finite() {
            Ok(value)
        } else {
            Err(self.invalid(key, format!("must be finite, got {value}")))
        }
    }

    fn finite3(&self, key: &str, value: Option<[f64; 3]>) -> Result<[f64; 3], SceneError> {
        let v = value.unwrap_or([0.0; 3]);
        for (i, x) in v.iter().enumerate() {
            self.finite(&format!("{key}[{i}]"), *x)?;
        }
        Ok(v)
    }

    fn initial(&self, file: &SceneFile, selection: &Selection) -> Result<Vec<f64>, SceneError> {
        let i = &file.initial;
        let scalar =
            |key: &str, v: Option<f64>| self.finite(&format!("initial.{key}"), v.unwrap_or(0.0));
        Ok(match selection.info.family {
            Family::Pendulum => vec![
                scalar("theta_deg", i.theta_deg)?.to_radians(),
                scalar("theta_dot", i.theta_dot)?,
            ],
            Family::PlanarAtG | Family::PlanarMidship => vec![
                scalar("u", i.u)?,
                scalar("v", i.v)?,
                scalar("r", i.r)?,
                scalar("x", i.x)?,
                scalar("y", i.y)?,
                scalar("psi_deg", i.psi_deg)?.to_radians(),
            ],
            Family::PlanarSpaceFixed => {
                // The scene gives surge and sway in body axes, as for the other planar
                // families; the space-fixed state holds their space components.
                let (u, v) = (scalar("u", i.u)?, scalar("v", i.v)?);
                let psi = scalar("psi_deg", i.psi_deg)?.to_radians();
                let (s, c) = psi.sin_cos();
                vec![
                    scalar("x", i.x)?,
                    scalar("y", i.y)?,
                    psi,
                    u * c - v * s,
                    u * s + v * c,
                    scalar("r", i.r)?,
                ]
            }
            Family::Spatial => {
                let mut state = Vec::with_capacity(13);
                state.extend(self.finite3("initial.velocity", i.velocity)?);
                state.extend(self.finite3("initial.rates", i.rates)?);
                state.extend(self.finite3("initial.position", i.position)?);
                state.extend(self.attitude(i, selection)?);
                state
            }
            Family::Top => {
                let mut state = Vec::with_capacity(7);
                state.extend(self.finite3("initial.rates", i.rates)?);
                state.extend(self.attitude(i, selection)?);
                state
            }
        })
    }

    /// `initial.attitude_deg` as the model carries it: Euler angles or a quaternion.
    fn attitude(
        &self,
        i: &file::InitialTable,
        selection: &Selection,
    ) -> Result<Vec<f64>, SceneError> {
        let [roll, pitch, yaw] = self
            .finite3("initial.attitude_deg", i.attitude_deg)?
            .map(f64::to_radians);
        Ok(match selection.info.kinematics {
            Some(Kinematics::Euler) => vec![roll, pitch, yaw],
            _ => {
                let q = UnitQuaternion::from_euler_angles(roll, pitch, yaw);
                vec![q.w, q.i, q.j, q.k]
            }
        })
    }

    fn integrator(
        &self,
        file: &SceneFile,
        selection: &Selection,
        loads: &SceneLoads,
    ) -> Result<IntegratorSpec, SceneError> {
        let t = &file.integrator;
        let method = self.named("integrator.method", &t.method, Method::ALL, "")?;
        let end_time = self.finite("integrator.end_time", t.end_time)?;
        if end_time <= 0.0 {
            return Err(self.invalid(
                "integrator.end_time",
                format!("must be positive, got {end_time}"),
            ));
        }
        let max_steps = match t.max_steps {
            None => DEFAULT_MAX_STEPS,
            Some(0) => {
                return Err(self.invalid("integrator.max_steps", "must be at least 1, got 0"));
            }
            Some(n) => usize::try_from(n).unwrap_or(usize::MAX),
        };
        if method == Method::LieMidpoint {
            self.lie_midpoint_applies(selection, loads)?;
        }
        let (step, adaptive) = if method.is_adaptive() {
            if t.step.is_some() {
                return Err(self.invalid(
                    "integrator.step",
                    format!(
                        "{} chooses its own steps; give rtol and atol",
                        method.name()
                    ),
                ));
            }
            let rtol = self.tolerance("integrator.rtol", t.rtol)?;
            let atol = self.tolerance("integrator.atol", t.atol)?;
            let mut options = match method {
                Method::Dopri5 => AdaptiveOptions::dopri5(rtol, atol),
                _ => AdaptiveOptions::dop853(rtol, atol),
            };
            options.max_steps = max_steps;
            (None, Some(options))
        } else {
            self.refuse_given(
                [
                    ("integrator.rtol", t.rtol.is_some()),
                    ("integrator.atol", t.atol.is_some()),
                ],
                &format!("{} takes a fixed step; give integrator.step", method.name()),
            )?;
            let step = self.required("integrator.step", t.step, "the fixed step, s")?;
            let step = self.finite("integrator.step", step)?;
            if step <= 0.0 {
                return Err(
                    self.invalid("integrator.step", format!("must be positive, got {step}"))
                );
            }
            let steps = (end_time / step).ceil();
            if steps > max_steps as f64 {
                return Err(self.invalid(
                    "integrator.max_steps",
                    format!("the run needs {steps} steps of {step} s to reach {end_time} s, more than max_steps = {max_steps}"),
                ));
            }
            (Some(step), None)
        };
        Ok(IntegratorSpec {
            method,
            step,
            adaptive,
            end_time,
            max_steps,
        })
    }

    fn tolerance(&self, key: &str, value: Option<f64>) -> Result<f64, SceneError> {
        let value = self.finite(key, value.unwrap_or(DEFAULT_TOLERANCE))?;
        if value <= 0.0 {
            return Err(self.invalid(key, format!("must be positive, got {value}")));
        }
        Ok(value)
    }

    /// The geometric integrator turns a free body's attitude and rates (`RigidRotation`);
    /// the translation of a free body is then exact.
    fn lie_midpoint_applies(
        &self,
        selection: &Selection,
        loads: &SceneLoads,
    ) -> Result<(), SceneError> {
        let free_quaternion =
            selection.info.kinematics == Some(Kinematics::Quaternion) && loads.is_free();
        if free_quaternion {
            Ok(())
        } else {
            Err(self.invalid(
                "integrator.method",
                "lie-midpoint integrates the rotation of a free body: a spatial scene with quaternion kinematics and no loads",
            ))
        }
    }

    fn every(&self, file: &SceneFile, end_time: f64) -> Result<f64, SceneError> {
        let Some(every) = file.output.every else {
            // An end time within 500 of the smallest f64 would give rows 0 s apart.
            let every = end_time / DEFAULT_ROWS;
            return if every > 0.0 {
                Ok(every)
            } else {
                Err(self.invalid(
                    "integrator.end_time",
                    format!("{end_time} s is too short to divide into {DEFAULT_ROWS} rows"),
                ))
            };
        };
        let every = self.finite("output.every", every)?;
        if every <= 0.0 || every > end_time {
            return Err(self.invalid(
                "output.every",
                format!(
                    "must be positive and at most integrator.end_time = {end_time}, got {every}"
                ),
            ));
        }
        if end_time / every > MAX_ROWS as f64 {
            return Err(self.invalid(
                "output.every",
                format!(
                    "gives {:.0} rows over integrator.end_time = {end_time}, more than {MAX_ROWS}; a longer every keeps the file readable",
                    end_time / every
                ),
            ));
        }
        Ok(every)
    }
}
