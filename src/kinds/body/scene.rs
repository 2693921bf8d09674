//! A catalog body's scene: the body, what acts on it, where it starts and how to integrate
//! it, checked, with the model it selects.
//!
//! It is read in two passes. [`file`](super::file) reads the TOML into tables with serde
//! ([`crate::scene::read_as`]), every table closed to unknown keys; then
//! [`BodyScene::from_file`] checks each value for its family and builds what runs: the
//! smallest proved model the scene needs ([`select_spatial`](super::select_spatial)), the
//! loads as inputs of that model ([`SceneLoads`]), the initial state in the model's own
//! layout, and the integrator. A load may change with time, as a [`table`](super::table) of
//! (t, value) that the run is cut at.

use super::file::SceneFile;
use super::{SceneLoads, Selection};
use crate::integrate::AdaptiveOptions;
use crate::models::{AnyModel, Family, Pendulum, PlanarAtG, PlanarMidship, PlanarSpaceFixed};
use crate::scene::check::Checker;
use crate::scene::{Method, Problem, SceneError, StopCondition, read_as};
use crate::{InertiaTensor, PendulumParameters};
use std::path::Path;

/// A catalog body's scene, checked, ready to run.
#[derive(Debug, Clone)]
pub struct BodyScene {
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
    /// The condition that ends the run where it first holds, if the scene gives one.
    pub stop: Option<StopCondition>,
    /// Where `eom linear` linearises: the `[linear]` table, checked.
    pub linear: crate::linear::LinearSpec,
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

/// Tolerances looser than this warn: the run's numbers may be wrong in the third digit.
pub const LOOSE_TOLERANCE: f64 = 1e-3;

impl IntegratorSpec {
    /// The same method made finer, to check a figure's convergence: half the step, or
    /// tolerances a hundred times tighter (as every kind refines its runs,
    /// [`crate::integrate::Stepper::refined`]): the step halved is the one taken
    /// between rows `every` apart ([`crate::integrate::half_the_step`]).
    pub fn refined(&self, every: f64) -> Self {
        IntegratorSpec {
            step: (self.step).map(|h| crate::integrate::half_the_step(h, every)),
            adaptive: self.adaptive.map(AdaptiveOptions::tightened),
            ..*self
        }
    }

    /// The summary's key for how far a figure moves in the refined run:
    /// `half_step_difference` or `tolerance_difference`, as a ship's manoeuvre says it.
    pub fn refinement_key(&self) -> &'static str {
        match self.method.is_adaptive() {
            true => "tolerance_difference",
            false => "half_step_difference",
        }
    }

    /// What the run should say about its own settings: a relative tolerance looser than
    /// [`LOOSE_TOLERANCE`] (rtol = 10 drifts a free body's energy by a third). The absolute
    /// tolerance is in the state's own units, so no one bound fits it.
    pub fn warnings(&self) -> Vec<String> {
        self.adaptive
            .iter()
            .map(|options| options.rtol)
            .filter(|rtol| *rtol > LOOSE_TOLERANCE)
            .map(|rtol| {
                format!(
                    "integrator.rtol = {rtol:e} is looser than {LOOSE_TOLERANCE:e}: the run's \
                     numbers may be wrong from the third digit"
                )
            })
            .collect()
    }
}

impl BodyScene {
    /// Reads and checks the scene file at `path` (a `body.file` is found relative to it).
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let name = crate::scene::display_name(path);
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

    /// Checks a scene's tables: one case of a sweep ([`crate::scene::sweep::TableCase`]).
    pub fn from_table(table: toml::Table, name: &str, base: &Path) -> Result<Self, SceneError> {
        let family = family_named(&table);
        let file = crate::scene::sweep::read_table(table, name)
            .map_err(|error| keys_of_the_family(error, family))?;
        Self::from_file(&file, name, base)
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
        let integrator = check.integrator(file, &loads)?;
        let every = check.every(file, integrator.end_time)?;
        let stop = check.stop(file, &selection, &initial)?;
        let info = selection.info;
        let linear = check.linear(
            file.linear.as_ref(),
            info.name,
            (info.state, info.inputs, &[]),
        )?;
        Ok(BodyScene {
            title: file.title.clone(),
            selection,
            body,
            initial,
            loads,
            integrator,
            every,
            stop,
            linear,
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
            ) => AnyModel::top(
                info.kinematics.expect("a top has a kinematics"),
                *mass,
                inertia,
                *h,
                *g,
            )
            .expect("checked when the scene was read"),
            (Body::Spatial { mass, inertia }, _) => AnyModel::spatial(
                info.symmetry.expect("a spatial model has a symmetry class"),
                info.kinematics.expect("a spatial model has a kinematics"),
                *mass,
                inertia,
            )
            .expect("checked when the scene was read"),
        }
    }

    /// The state entries' names as the trajectory's columns name them (before their units):
    /// the model's layout, in identifiers (`x` for X).
    pub fn state_names(&self) -> Vec<String> {
        self.selection
            .info
            .state
            .iter()
            .map(|s| s.to_lowercase())
            .collect()
    }
}

/// Reads scene text into its tables: a syntax error, an unknown key or a wrong type names the
/// key's path.
pub fn read(text: &str, name: &str) -> Result<SceneFile, SceneError> {
    read_as(text, name).map_err(|error| {
        let family = toml::from_str::<toml::Table>(text)
            .ok()
            .and_then(|t| family_named(&t));
        keys_of_the_family(error, family)
    })
}

/// The catalog family a scene's table names in `model.family`, if it names one.
pub(crate) fn family_named(table: &toml::Table) -> Option<Family> {
    let name = table.get("model")?.get("family")?.as_str()?;
    Family::ALL.into_iter().find(|f| f.name() == name)
}

/// An unknown key in a catalog scene's `[body]`, `[initial]`, `[loads]` or `[model]`, told
/// with the keys the scene's own family takes there rather than every family's (serde lists
/// the union of the table's fields).
pub(crate) fn keys_of_the_family(mut error: SceneError, family: Option<Family>) -> SceneError {
    let Problem::Schema(message) = &error.problem else {
        return error;
    };
    let Some((table, key)) = error.key.split_once('.') else {
        return error;
    };
    if let (Some(family), true) = (family, message.starts_with("unknown field")) {
        let allowed = crate::scene::reference::table_keys(family, table);
        if !allowed.is_empty() {
            error.problem = Problem::Schema(format!(
                "unknown field `{key}`; a {} scene's [{table}] takes {}",
                family.name(),
                allowed.join(", ")
            ));
        }
    }
    error
}
