//! A body's section of `summary.json`: the generated model that ran and why, its energy
//! drift, where the run ended, and what the family and the scene add (the pendulum's measured
//! period and how far it moved when the run was refined; a stop condition and when it held).

use super::Report;
use crate::models::{ModelInfo, Operations};
use crate::output::summary::Named;
use serde::Serialize;
use std::collections::BTreeMap;

/// What a body's summary adds to the keys every scene's shares.
#[derive(Debug, Clone, Serialize)]
pub struct BodySection {
    /// The generated model that ran.
    pub variant: &'static str,
    /// Why that model.
    pub reason: String,
    /// Its operations per right-hand-side call.
    pub operations: Operations,
    /// The unpruned variant's, for comparison.
    pub full_operations: Operations,
    /// The largest relative change of the total energy over the rows, where the loads have a
    /// potential (`null` where they do not).
    pub energy_drift: Option<f64>,
    /// The end time, or the last row's time when the run stopped early.
    pub final_time: f64,
    /// The state at the end (or at the last row), by name.
    pub final_state: Named,
    /// What the family and the scene add, by name, written in the names' order: a family's
    /// measures (a pendulum's measured period) and how far they move when the run is refined
    /// (`half_step_difference` or `tolerance_difference`), a stop condition's `stop_when` and
    /// `stopped_at`.
    #[serde(flatten)]
    pub extra: BTreeMap<String, Extra>,
}

/// One entry a run adds to its section ([`BodySection::extra`]).
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
    Differences(BTreeMap<String, Option<f64>>),
}

impl BodySection {
    /// The section of a run of `info` (chosen for `reason`) that reported `report`, its state
    /// named by `state_names`.
    pub fn new(
        (info, reason): (&'static ModelInfo, String),
        report: &Report,
        state_names: &[String],
    ) -> Self {
        let final_state = (state_names.iter().cloned())
            .zip(report.final_state.iter().copied())
            .collect();
        BodySection {
            variant: info.name,
            reason,
            operations: info.operations,
            full_operations: info.full_variant().operations,
            energy_drift: report.energy_drift,
            final_time: report.final_time,
            final_state: Named(final_state),
            extra: BTreeMap::new(),
        }
    }
}
