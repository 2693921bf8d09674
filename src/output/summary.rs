//! `summary.json`: what ran, why, what it cost and where it ended.
//!
//! ```json
//! {"scene", "title", "variant", "reason", "operations", "full_operations",
//!  "integrator": {"method", "steps", "rejected", "rhs_evals"}, "wall_seconds",
//!  "energy_drift", "final_time", "final_state": {name: value}, "interrupted", "error",
//!  "warnings", …what the family adds}
//! ```
//!
//! A scene with `integrator.stop_when` adds `"stop_when"` (the condition as written) and
//! `"stopped_at"` (the time it first held and ended the run, `null` if it never held);
//! `final_time` and `final_state` are then where it stopped.
//!
//! A family that measures figures from its rows (the pendulum's `period_s`) runs again refined
//! (half the step, or tolerances / 100) and says how far each moved, under
//! `"half_step_difference"` or `"tolerance_difference"`, as a ship's manoeuvre does.
//!
//! A run that stopped early still has its summary: `"interrupted": true` after Ctrl-C, or
//! `"error"` with the message of what stopped it; `final_time` and `final_state` are then its
//! last row's.
//!
//! The file is written whole to a temporary name in the same folder and renamed over
//! `summary.json`, so a reader never sees half of one.

use crate::integrate::Stepper;
use crate::models::{ModelInfo, Operations};
use crate::run::Report;
use serde::Serialize;
use serde::ser::{SerializeMap, Serializer};
use std::path::Path;

/// The summary of one run.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// The scene file.
    pub scene: String,
    /// The scene's title.
    pub title: String,
    /// The generated model that ran.
    pub variant: &'static str,
    /// Why that model.
    pub reason: String,
    /// Its operations per right-hand-side call.
    pub operations: Operations,
    /// The unpruned variant's, for comparison.
    pub full_operations: Operations,
    /// The integration.
    pub integrator: IntegratorSummary,
    /// Wall time of the run, s.
    pub wall_seconds: f64,
    /// The largest relative change of the total energy over the rows, where the loads have a
    /// potential (`null` where they do not).
    pub energy_drift: Option<f64>,
    /// The end time, or the last row's time when the run stopped early.
    pub final_time: f64,
    /// The state at the end (or at the last row), by name.
    pub final_state: Named,
    /// Whether the run was interrupted (Ctrl-C, SIGTERM) before its end time.
    pub interrupted: bool,
    /// Why the run stopped before its end time, if it failed (`null` if it did not).
    pub error: Option<String>,
    /// What the run did not stop for but a reader should know.
    pub warnings: Vec<String>,
    /// What the family and the scene add, by name, written in the names' order: a family's
    /// measures (a pendulum's measured period) and how far they move when the run is refined
    /// (`half_step_difference` or `tolerance_difference`), a sweep's `case`, a stop
    /// condition's `stop_when` and `stopped_at`.
    #[serde(flatten)]
    pub extra: std::collections::BTreeMap<String, Extra>,
}

/// One entry a run adds to its summary ([`Summary::extra`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Extra {
    /// A family's measure.
    Number(f64),
    /// A text: the stop condition as written.
    Text(String),
    /// A time that may not have come: when the stop condition held (`null` if it never did).
    Time(Option<f64>),
    /// How far each figure moved when the run was refined, by its key (`null` where the
    /// refined run gave none).
    Differences(std::collections::BTreeMap<String, Option<f64>>),
    /// The case of a sweep: its number and the values it set, by key.
    Case {
        /// The case's number, from 0.
        index: usize,
        /// Each swept key's value, as the scene gave it.
        values: std::collections::BTreeMap<String, serde_json::Value>,
    },
}

/// The integrator's part.
#[derive(Debug, Clone, Serialize)]
pub struct IntegratorSummary {
    /// The method's name in scene files.
    pub method: &'static str,
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Right-hand-side evaluations.
    pub rhs_evals: usize,
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

impl Summary {
    /// The summary of a run of `info` that reported `report`.
    pub fn new(
        scene: String,
        title: String,
        (info, reason): (&'static ModelInfo, String),
        method: &'static str,
        report: &Report,
        state_names: &[String],
    ) -> Self {
        Self {
            scene,
            title,
            variant: info.name,
            reason,
            operations: info.operations,
            full_operations: info.full_variant().operations,
            integrator: IntegratorSummary {
                method,
                steps: report.steps,
                rejected: report.rejected,
                rhs_evals: report.rhs_evals,
            },
            wall_seconds: report.wall_seconds,
            energy_drift: report.energy_drift,
            final_time: report.final_time,
            final_state: Named(
                state_names
                    .iter()
                    .cloned()
                    .zip(report.final_state.iter().copied())
                    .collect(),
            ),
            interrupted: false,
            error: None,
            warnings: report.warnings.clone(),
            extra: Default::default(),
        }
    }

    /// Writes the summary to `path` through a temporary file renamed over it.
    pub fn write(&self, path: &Path) -> std::io::Result<()> {
        let text = serde_json::to_string_pretty(self).map_err(std::io::Error::other)?;
        write_atomically(path, text.as_bytes())
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

/// The method and its settings, as a scene with manoeuvres ran each of them (a ship's, a
/// vehicle's): the step or the tolerances, where [`IntegratorSummary`] counts one run's steps.
#[derive(Debug, Clone, Serialize)]
pub struct MethodSummary {
    /// Its name in scene files.
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
}

impl MethodSummary {
    /// The method of `stepper` with the settings it ran with.
    pub fn new(stepper: &Stepper) -> Self {
        MethodSummary {
            method: stepper.method.name(),
            step: stepper.step,
            rtol: stepper.adaptive.map(|o| o.rtol),
            atol: stepper.adaptive.map(|o| o.atol),
        }
    }
}
