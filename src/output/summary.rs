//! `summary.json`: what ran, why, what it cost, each run's figures and where it ended, for a
//! scene of any kind.
//!
//! One type, [`Summary`], is built by the library for every kind: the keys every scene shares
//! (its kind, file and title, the method with its settings and statistics, the wall time,
//! whether it was interrupted or failed, its warnings, a sweep case's values), each run's
//! figures with how far they moved when the run was refined ([`RunFigures`]) and the verdicts
//! judged on them ([`Verdict`]), and the kind's own section, flattened beside the shared keys:
//!
//! ```json
//! {"kind", "scene", "title",
//!  "integrator": {"method", "step" | "rtol", "atol", "steps", "rejected", "rhs_evals"},
//!  "wall_seconds", "interrupted", "error", "warnings", "case",
//!  …the kind's section}
//! ```
//!
//! The section is what the kind has always written there: a body's model (`variant`,
//! `reason`, `operations`), its energy drift, final state and measured figures (the
//! pendulum's `period_s`, with `half_step_difference` or `tolerance_difference`), its
//! `stop_when` and `stopped_at`; a ship's `model`, `linear` and `manoeuvre` (each manoeuvre's
//! figures and the IMO criteria); a vehicle's `model`, `kirchhoff`, `cruise` and `manoeuvre`;
//! with a stop condition, a ship's and a vehicle's `stop_when` and each manoeuvre's
//! `stopped_at`.
//! [`Summary::runs`] and [`Summary::verdicts`] give the same figures and verdicts in one shape
//! for every kind, for a library user (a sweep, a Monte Carlo) who should not parse each
//! kind's section; the file gives them once, in the section.
//!
//! A scene of any kind runs to its summary through one entry, its rows here dropped:
//!
//! ```
//! use eom::run::record::Discard;
//! use eom::scene::AnyScene;
//!
//! for file in ["scenes/pendulum.toml", "scenes/s175.toml", "scenes/remus100.toml"] {
//!     let scene = AnyScene::load(file.as_ref())?.into_kind();
//!     let summary = scene.run(file, &mut Discard)?.summary();
//!     assert_eq!(summary.kind, scene.kind()); // body, ship, vehicle
//!     for run in &summary.runs {
//!         for figure in &run.figures {
//!             // e.g. "turning_circle_35/port tactical_diameter_m = Some(…), refined: Some(…)"
//!             println!("{} {} = {:?}, refined: {:?}", run.run, figure.key, figure.value, figure.difference);
//!         }
//!     }
//!     assert!(!summary.runs.is_empty(), "{file}");
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! A run that stopped early still has its summary: `"interrupted": true` after Ctrl-C, or
//! `"error"` with the message of what stopped it.
//!
//! The file is written whole to a temporary name in the same folder and renamed over
//! `summary.json`, so a reader never sees half of one.

use crate::integrate::{AdaptiveOptions, Method, Stepper};
use crate::scene::sweep::TableCase;
use serde::Serialize;
use serde::ser::{SerializeMap, Serializer};
use std::collections::BTreeMap;
use std::path::Path;

/// `summary.json` of a scene of any kind, its kind's own section as `Section` (a JSON value
/// where the kind is not known: [`crate::kinds::Finished::summary`]).
#[derive(Debug, Clone, Serialize)]
pub struct Summary<Section = serde_json::Value> {
    /// The kind of scene, as the registry names it (`body`, `ship`, `vehicle`).
    pub kind: &'static str,
    /// The scene file, as given.
    pub scene: String,
    /// The scene's title.
    pub title: String,
    /// The method, its settings, and what it cost over every run.
    pub integrator: IntegratorSummary,
    /// Wall time of the scene's runs, s.
    pub wall_seconds: f64,
    /// Whether a signal (Ctrl-C, SIGTERM) ended the run early; what ran before it is here.
    pub interrupted: bool,
    /// Why the run stopped before its end, if it failed (`null` if it did not).
    pub error: Option<String>,
    /// What the run did not stop for but a reader should know.
    pub warnings: Vec<String>,
    /// A sweep case's number and the values it set.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub case: Option<CaseSummary>,
    /// Each run's figures, in the order run (in the file: in the kind's section).
    #[serde(skip)]
    pub runs: Vec<RunFigures>,
    /// The verdicts judged on the figures (a ship's IMO criteria; in the file: in the kind's
    /// section).
    #[serde(skip)]
    pub verdicts: Vec<Verdict>,
    /// What the kind adds, its keys beside the shared ones.
    #[serde(flatten)]
    pub section: Section,
}

impl<Section: Serialize> Summary<Section> {
    /// The summary with its section as a JSON value, for a caller that does not know the kind.
    pub fn into_json(self) -> Summary {
        let section = match serde_json::to_value(&self.section) {
            Ok(value @ serde_json::Value::Object(_)) => value,
            _ => serde_json::Value::Object(Default::default()),
        };
        Summary {
            kind: self.kind,
            scene: self.scene,
            title: self.title,
            integrator: self.integrator,
            wall_seconds: self.wall_seconds,
            interrupted: self.interrupted,
            error: self.error,
            warnings: self.warnings,
            case: self.case,
            runs: self.runs,
            verdicts: self.verdicts,
            section,
        }
    }

    /// `summary.json` as written, with a sweep case's number and values where it is one.
    pub fn file(&self, case: Option<&TableCase>) -> Vec<u8>
    where
        Section: Clone,
    {
        let mut summary = self.clone();
        summary.case = case.map(CaseSummary::of);
        serde_json::to_vec_pretty(&summary).unwrap_or_default()
    }
}

impl Summary {
    /// A figure of a run by the run's path and the figure's key, if the run gave it.
    pub fn figure(&self, run: &str, key: &str) -> Option<f64> {
        let run = self.runs.iter().find(|figures| figures.run == run)?;
        run.figures.iter().find(|f| f.key == key)?.value
    }
}

/// The method, its settings, and what it cost.
#[derive(Debug, Clone, Default, Serialize)]
pub struct IntegratorSummary {
    /// The method's name in scene files.
    pub method: &'static str,
    /// The step of a fixed-step method, s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub step: Option<f64>,
    /// The relative tolerance of an adaptive one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rtol: Option<f64>,
    /// Its absolute tolerance.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub atol: Option<f64>,
    /// Accepted steps over every run.
    pub steps: u64,
    /// Rejected steps over every run, where the kind counts them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rejected: Option<u64>,
    /// Right-hand-side evaluations over every run, where the kind counts them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rhs_evals: Option<u64>,
}

impl IntegratorSummary {
    /// `method` with its settings (a fixed step, or an adaptive method's tolerances), before
    /// any step is counted.
    pub fn settings(method: Method, step: Option<f64>, adaptive: Option<AdaptiveOptions>) -> Self {
        IntegratorSummary {
            method: method.name(),
            step: step.filter(|_| !method.is_adaptive()),
            rtol: adaptive.map(|o| o.rtol),
            atol: adaptive.map(|o| o.atol),
            ..IntegratorSummary::default()
        }
    }

    /// A run's method with its settings ([`settings`](Self::settings)).
    pub fn of(stepper: &Stepper) -> Self {
        Self::settings(stepper.method, stepper.step, stepper.adaptive)
    }
}

/// A sweep case: its number and the values it set, by key.
#[derive(Debug, Clone, Serialize)]
pub struct CaseSummary {
    /// The case's number, from 0.
    pub index: usize,
    /// Each swept key's value, as the scene gave it.
    pub values: BTreeMap<String, serde_json::Value>,
}

impl CaseSummary {
    /// The case's number and values.
    pub fn of(case: &TableCase) -> Self {
        CaseSummary {
            index: case.index,
            values: case.values_json(),
        }
    }
}

/// One run's figures (a body's one run, a manoeuvre or a side of one), each with how far it
/// moved when the run was refined.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunFigures {
    /// The run's path in the output (`turning_circle_35/port`); empty for a scene's one run.
    pub run: String,
    /// Each figure, in the kind's order.
    pub figures: Vec<Figure>,
    /// How the refined run was refined (`half the step`, `tolerances / 100`), where it was.
    pub refinement: Option<&'static str>,
    /// The largest difference over the run's figures, where the kind gives that rather than
    /// each figure's (a vehicle's manoeuvre).
    pub largest_difference: Option<f64>,
    /// What the run could not measure, and why.
    pub notes: Vec<String>,
}

/// A figure of a run: its key (its unit the key's suffix: `tactical_diameter_m`,
/// `period_s`), its value, and how far it moved when the run was refined.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Figure {
    /// The key, as the kind's section names it.
    pub key: String,
    /// Its value; `None` where the run did not give it (the run's notes say why).
    pub value: Option<f64>,
    /// |value − the refined run's|; `None` where the run was not refined, or the refined
    /// run did not give it.
    pub difference: Option<f64>,
}

/// A verdict judged on a scene's figures (an IMO criterion).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Verdict {
    /// Its name (`tactical_diameter`).
    pub name: String,
    /// The run whose figure it judges.
    pub run: String,
    /// Whether the scene meets it; `None` where it could not be judged.
    pub pass: Option<bool>,
}

/// Values by name, serialised as a JSON object in the given order.
#[derive(Debug, Clone, Default)]
pub struct Named(pub Vec<(String, f64)>);

impl Serialize for Named {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        for (key, value) in &self.0 {
            map.serialize_entry(key, value)?;
        }
        map.end()
    }
}

/// Writes `bytes` to a temporary file beside `path` and renames it over `path`.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let temporary = path.with_file_name(format!(".{name}.partial"));
    std::fs::write(&temporary, bytes)?;
    std::fs::rename(&temporary, path)
}
