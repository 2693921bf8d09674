//! A body's one run as the one runner ([`crate::run::scene`]) runs it: the figures its family
//! measures from its rows, its section of the summary, its report, its line in a sweep's table
//! and its drawing.

use super::summary::{BodySection, Extra};
use super::{Body, BodyScene, Report, run_reporting};
use crate::Short;
use crate::kind::KindError;
use crate::output::drawing::Drawing;
use crate::output::summary::{Figure, IntegratorSummary, RunFigures, Summary};
use crate::output::text::printable;
use crate::output::trajectory::number_text;
use crate::run::scene::{
    Closing, Counts, Failed, Ran, Rows, RunPlan, RunResult, SceneRuns, Setting,
};
use crate::run::{Row, Sink};
use crate::scene::sweep::TableCase;
use std::fmt::Write;

/// The pendulum's period, measured from its rows ([`crate::swing::measure_period`]).
const PERIOD: &str = "period_s";

/// What a body's run gives, as it ended: at its end time, at its stop condition, stopped by
/// the caller, or failed where it failed (the runner keeps why).
#[derive(Debug, Clone)]
pub struct BodyRun {
    /// What the run did, up to where it ended.
    pub report: Report,
    /// The rows the recorder took.
    pub rows: usize,
    /// The family's figures (the pendulum's period), each or why it is not given.
    pub measures: Vec<(&'static str, Result<f64, String>)>,
}

/// A body's run with the scene's method, its cost, and its figures refined.
pub type BodyOutcome = crate::run::scene::Outcome<BodyRun>;

/// How far each figure of `outcome` moved when the run was refined (`None` where the refined
/// run did not give it or did not finish), with why each is not given; empty where the run
/// gave no figure or was not refined.
fn refined_differences(
    scene: &BodyScene,
    outcome: &BodyOutcome,
) -> (Vec<(&'static str, Option<f64>)>, Vec<String>) {
    let Some(refinement) = &outcome.refinement else {
        return Default::default();
    };
    let key = scene.integrator.refinement_key();
    let mut warnings = Vec::new();
    let differences = (outcome.gave.measures.iter().enumerate())
        .filter_map(|(k, (name, value))| {
            let value = value.as_ref().ok()?;
            let difference = match refinement {
                Ok(refined) => match &refined.measures[k].1 {
                    Ok(refined) => Some((value - refined).abs()),
                    Err(why) => {
                        warnings.push(format!("{key} of {name} is not given: {why}"));
                        None
                    }
                },
                Err(error) => {
                    warnings.push(format!("{key} of {name} is not given: refined, {error}"));
                    None
                }
            };
            Some((*name, difference))
        })
        .collect();
    (differences, warnings)
}

/// The rows to the runner's, with what the family's figures are measured from.
struct Recording<'a, 'r> {
    rows: &'a mut Rows<'r>,
    /// Each row's time and first state entry, for a family that measures a figure from them.
    measured: Option<(Vec<f64>, Vec<f64>)>,
}

impl Sink for Recording<'_, '_> {
    fn row(&mut self, row: &Row) -> bool {
        let taken = self.rows.take(row);
        if taken && let Some(measured) = &mut self.measured {
            keep(measured, row);
        }
        taken
    }
}

/// Keeps a row's time and first state entry, what a family's figures are measured from.
fn keep((time, first): &mut (Vec<f64>, Vec<f64>), row: &Row) {
    time.push(row.t);
    first.push(row.state.first().copied().unwrap_or(f64::NAN));
}

/// The figures a family measures from its rows, by key.
fn measure_keys(scene: &BodyScene) -> &'static [&'static str] {
    match scene.body {
        Body::Pendulum(_) => &[PERIOD],
        _ => &[],
    }
}

/// Whether the trajectory has the potential and total energy: the model's own field or the
/// loads have a potential.
fn has_potential(scene: &BodyScene) -> bool {
    scene.selection.info.potential_energy || scene.loads.has_potential()
}

/// About how many numbers the trajectory holds: each row's time, state and energies.
pub(super) fn trajectory_numbers(scene: &BodyScene) -> f64 {
    let rows = scene.integrator.end_time / scene.every + 1.0;
    let energies = if has_potential(scene) { 3.0 } else { 1.0 };
    rows * (1.0 + scene.state_names().len() as f64 + energies)
}

impl SceneRuns for BodyScene {
    type Shared = ();
    type Gave = BodyRun;
    type Section = BodySection;

    fn kind_name(&self) -> &'static str {
        super::kind::NAME
    }

    fn scene_title(&self) -> &str {
        &self.title
    }

    fn integrator(&self) -> IntegratorSummary {
        let spec = &self.integrator;
        IntegratorSummary::settings(spec.method, spec.step, spec.adaptive)
    }

    fn prepare(&self) -> Result<(), KindError> {
        Ok(())
    }

    /// Its one run, at the top of the output.
    fn plans(&self, _: &()) -> Vec<RunPlan> {
        vec![RunPlan {
            path: String::new(),
            columns: self.state_names(),
            expected_rows: (self.integrator.end_time / self.every) as usize + 1,
            end_time: self.integrator.end_time,
            potential: has_potential(self),
            energy_unit: crate::models::ENERGY_UNIT,
        }]
    }

    /// The run with the scene's method, or refined; a run that fails keeps what it ran.
    fn run_one(
        &self,
        _: &(),
        _index: usize,
        setting: Setting,
        rows: &mut Rows,
    ) -> RunResult<BodyRun> {
        let refined;
        let scene = match setting {
            Setting::Scene => self,
            Setting::Refined => {
                let mut finer = self.clone();
                finer.integrator = self.integrator.refined(self.every);
                refined = finer;
                &refined
            }
        };
        let measuring = !measure_keys(scene).is_empty();
        let mut recording = Recording {
            rows,
            measured: measuring.then(Default::default),
        };
        let ran = run_reporting(scene, &mut recording);
        let measured = recording.measured;
        let report = ran.report;
        let counts = Counts {
            steps: report.steps as u64,
            rejected: Some(report.rejected as u64),
            rhs_evals: report.rhs_evals as u64,
        };
        let gave = BodyRun {
            report,
            rows: recording.rows.taken(),
            measures: measures(scene, measured.as_ref()),
        };
        let outcome = BodyOutcome::new(gave, counts);
        let error = match ran.error {
            None => return Ok(outcome),
            Some(error) => KindError::Run(Box::new(error)),
        };
        Err(Failed {
            error,
            kept: Some(outcome),
        })
    }

    /// A run that gave no figure is not refined.
    fn worth_refining(&self, gave: &BodyRun) -> bool {
        gave.measures.iter().any(|(_, value)| value.is_ok())
    }

    fn refined_warnings(&self, outcome: &BodyOutcome) -> Vec<String> {
        refined_differences(self, outcome).1
    }

    fn figures(&self, _: &RunPlan, outcome: &BodyOutcome) -> RunFigures {
        let (differences, _) = refined_differences(self, outcome);
        run_figures(self, &outcome.gave.measures, &differences)
    }

    fn drawings(&self, _: &(), _: usize, _: &BodyOutcome) -> Vec<Drawing> {
        super::drawing::drawings(self)
    }

    /// The model and where the run ended, its figures, how far they moved refined, and where
    /// a stop condition ended it.
    fn close(&self, ran: &Ran<'_, Self>) -> Closing<BodySection> {
        let selection = &self.selection;
        let Some(outcome) = ran.outcome(0) else {
            // Stopped before it began: the model alone.
            let section = BodySection::new(
                (selection.info, selection.reason.clone()),
                &Report::default(),
                &self.state_names(),
            );
            return Closing {
                section,
                verdicts: Vec::new(),
                warnings: Vec::new(),
            };
        };
        let report = &outcome.gave.report;
        let names = self.state_names();
        let mut section =
            BodySection::new((selection.info, selection.reason.clone()), report, &names);
        let mut warnings = report.warnings.clone();
        for (key, value) in &outcome.gave.measures {
            match value {
                Ok(value) => {
                    (section.extra).insert((*key).into(), Extra::Number(*value));
                }
                Err(why) => warnings.push(not_given(key, why)),
            }
        }
        let (differences, _) = refined_differences(self, outcome);
        if !differences.is_empty() {
            let differences = (differences.iter())
                .map(|(k, d)| ((*k).to_owned(), *d))
                .collect();
            let key = self.integrator.refinement_key();
            (section.extra).insert(key.into(), Extra::Differences(differences));
        }
        if let Some(condition) = &self.stop {
            section
                .extra
                .insert("stop_when".into(), Extra::Text(condition.text.clone()));
            (section.extra).insert("stopped_at".into(), Extra::Time(report.stopped_at));
        }
        Closing {
            section,
            verdicts: Vec::new(),
            warnings,
        }
    }

    fn report(&self, ran: &Ran<'_, Self>) -> String {
        (ran.outcome(0))
            .map(|outcome| report(self, outcome).unwrap_or_default())
            .unwrap_or_default()
    }

    fn cells(&self, ran: &Ran<'_, Self>, _: &TableCase) -> Vec<(String, String)> {
        let whole = ran.failures.is_empty() && !ran.stopped;
        cells(self, ran.outcome(0), whole)
    }

    fn kept(&self, ran: &Ran<'_, Self>) -> String {
        kept(self, ran.outcome(0), ran.stopped)
    }

    /// In the order of its section's fields (the section as a JSON value would sort them).
    fn summary_file(&self, summary: &Summary<BodySection>, case: Option<&TableCase>) -> Vec<u8> {
        summary.file(case)
    }
}

/// Why the measure `key` is not given, as the summary's warnings and the run's notes say it.
fn not_given(key: &str, why: &str) -> String {
    format!("{key} is not given: {why}")
}

/// The run's figures as every kind gives them: the family's measures, each with how far it
/// moved when the run was refined, and why a measure is not given.
fn run_figures(
    scene: &BodyScene,
    measures: &[(&'static str, Result<f64, String>)],
    refined: &[(&'static str, Option<f64>)],
) -> RunFigures {
    let difference = |key: &str| refined.iter().find(|(k, _)| *k == key)?.1;
    let figures = (measures.iter())
        .map(|(key, value)| Figure {
            key: (*key).to_owned(),
            value: value.as_ref().ok().copied(),
            difference: difference(key),
        })
        .collect();
    let notes = (measures.iter())
        .filter_map(|(key, value)| Some(not_given(key, value.as_ref().err()?)))
        .collect();
    RunFigures {
        run: String::new(),
        figures,
        refinement: (!refined.is_empty()).then(|| scene.integrator.method.refinement()),
        largest_difference: None,
        notes,
    }
}

/// The family's figures from the rows kept for them; where the run gives none (a pendulum
/// that swung less than twice), why.
fn measures(
    scene: &BodyScene,
    measured: Option<&(Vec<f64>, Vec<f64>)>,
) -> Vec<(&'static str, Result<f64, String>)> {
    let (time, first) = measured.map_or((&[][..], &[][..]), |(t, x)| (&t[..], &x[..]));
    (measure_keys(scene).iter())
        .map(|&key| {
            let value = match key {
                PERIOD => crate::swing::measure_period(time, first).map_err(|e| e.to_string()),
                _ => Err(format!("{key} is not a figure of this family")),
            };
            (key, value)
        })
        .collect()
}

/// The report as `eom run` prints it: the model and why, its cost against the full variant's,
/// the integration, the energy drift and where a stop condition ended it.
fn report(scene: &BodyScene, outcome: &BodyOutcome) -> Result<String, std::fmt::Error> {
    let info = scene.selection.info;
    let (ops, full) = (info.operations, info.full_variant().operations);
    let report = &outcome.gave.report;
    let mut text = String::new();
    let out = &mut text;
    let title = printable(&scene.title);
    writeln!(
        out,
        "{title}: ran {} ({})",
        info.name, scene.selection.reason
    )?;
    if full.arithmetic() != ops.arithmetic() {
        writeln!(
            out,
            "  {} arithmetic operations per call, against {} for {}",
            ops.arithmetic(),
            full.arithmetic(),
            info.full_variant().name
        )?;
    }
    writeln!(
        out,
        "  {}: {} steps ({} rejected), {} rhs calls, {:.3} s",
        scene.integrator.method.name(),
        report.steps,
        report.rejected,
        report.rhs_evals,
        report.wall_seconds
    )?;
    if let Some(drift) = report.energy_drift {
        writeln!(
            out,
            "  energy drift {drift:.2e} (largest |E − E₀| over the rows, relative to max(|E₀|, largest T))"
        )?;
    }
    let (differences, _) = refined_differences(scene, outcome);
    for ((key, value), (_, moved)) in outcome.gave.measures.iter().zip(&differences) {
        if let (Ok(value), Some(moved)) = (value, moved) {
            writeln!(
                out,
                "  {key} = {}, which {} moves by {moved:.1e}",
                Short(*value),
                scene.integrator.method.refinement()
            )?;
        }
    }
    if let (Some(t), Some(condition)) = (report.stopped_at, &scene.stop) {
        writeln!(
            out,
            "  stopped at t = {} s, where `{condition}` first held (summary.json: stopped_at, every digit)",
            Short(t)
        )?;
    }
    Ok(text)
}

/// The columns of a body's sweep's table after the case and its swept values, with this run's
/// values: `variant, steps, rhs_evals, wall_seconds, energy_drift, <the family's figures…>,
/// final_<state…>`; all but the variant empty where the run failed (`whole` false).
fn cells(scene: &BodyScene, outcome: Option<&BodyOutcome>, whole: bool) -> Vec<(String, String)> {
    let ran = whole && outcome.is_some();
    let value = |text: String| if ran { text } else { String::new() };
    let default = Report::default();
    let report = outcome.map_or(&default, |outcome| &outcome.gave.report);
    let measures = outcome.map_or(&[][..], |outcome| &outcome.gave.measures[..]);
    let mut cells = vec![
        ("variant".to_owned(), scene.selection.info.name.to_owned()),
        ("steps".into(), value(report.steps.to_string())),
        ("rhs_evals".into(), value(report.rhs_evals.to_string())),
        (
            "wall_seconds".into(),
            value(number_text(report.wall_seconds)),
        ),
    ];
    let drift = report.energy_drift.map_or_else(String::new, number_text);
    cells.push(("energy_drift".into(), value(drift)));
    for (key, measure) in measures {
        let text = measure
            .as_ref()
            .map_or_else(|_| String::new(), |v| number_text(*v));
        cells.push(((*key).to_owned(), value(text)));
    }
    for (k, name) in scene.state_names().iter().enumerate() {
        let x = report
            .final_state
            .get(k)
            .map_or_else(String::new, |x| number_text(*x));
        cells.push((format!("final_{name}"), value(x)));
    }
    cells
}

/// What the run kept when it ended early, in words.
fn kept(scene: &BodyScene, outcome: Option<&BodyOutcome>, stopped: bool) -> String {
    let (t, rows) = outcome.map_or((0.0, 0), |o| (o.gave.report.final_time, o.gave.rows));
    let end = scene.integrator.end_time;
    match (stopped, rows) {
        (true, _) => format!(
            "every row up to t = {} s of {} s in trajectory.csv, summary.json \
                 (\"interrupted\": true) and the plots",
            Short(t),
            Short(end)
        ),
        (false, 0) => "its summary.json (the run stopped at its start)".into(),
        (false, _) => format!(
            "its rows up to t = {} s (its last row before the failure), summary.json and \
             the plots",
            Short(t)
        ),
    }
}
