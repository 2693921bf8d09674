//! A body's one run: its rows to the recorder, the figures its family measures from them, its
//! summary, its report, its line in a sweep's table and its drawing.

use super::summary::{BodySection, Extra};
use super::{Body, BodyScene, Report, RunError, SceneLoads, run_reporting};
use crate::Short;
use crate::kinds::KindError;
use crate::output::drawing::{BodyShape, Drawing, RigidBody, RunDrawings};
use crate::output::summary::{Figure, IntegratorSummary, RunFigures, Summary};
use crate::output::text::printable;
use crate::output::trajectory::number_text;
use crate::run::record::{Recorder, RunStart};
use crate::run::{Row, Sink};
use std::fmt::Write;

/// The pendulum's period, measured from its rows ([`crate::swing::measure_period`]).
const PERIOD: &str = "period_s";

/// A body's run as it ended: at its end time, at its stop condition, stopped by the recorder,
/// or failed where it failed.
#[derive(Debug)]
pub struct BodyRun<'a> {
    scene: &'a BodyScene,
    /// What the run did, up to where it ended.
    pub report: Report,
    /// Why it ended before its end time, where it failed.
    pub error: Option<RunError>,
    /// Whether the recorder stopped it (Ctrl-C) before its end time, or while its refined
    /// run checked its figures.
    pub stopped: bool,
    /// The rows the recorder took.
    pub rows: usize,
    /// The family's figures (the pendulum's period), each or why it is not given.
    pub measures: Vec<(&'static str, Result<f64, String>)>,
    /// How far each figure moved when the run was refined (`None` where the refined run gave
    /// none); empty where the run gave no figure, or did not end as it should.
    pub refined: Vec<(&'static str, Option<f64>)>,
    /// `summary.json`.
    pub summary: Summary<BodySection>,
}

/// The rows to the recorder, counted, with what the family's figures are measured from.
struct Recording<'a> {
    recorder: &'a mut dyn Recorder,
    rows: usize,
    /// Each row's time and first state entry, for a family that measures a figure from them.
    measured: Option<(Vec<f64>, Vec<f64>)>,
}

impl Sink for Recording<'_> {
    fn row(&mut self, row: &Row) -> bool {
        let taken = self.recorder.row(row);
        if taken {
            self.rows += 1;
            if let Some(measured) = &mut self.measured {
                keep(measured, row);
            }
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

/// Runs `scene` (`name`, its file as the summary names it), its rows to `recorder` under the
/// top of the output, then its drawing where it gave two rows or more. A failure of the run
/// is kept in what it returns; an error is the recorder's alone.
pub(super) fn run_body<'a>(
    scene: &'a BodyScene,
    name: &str,
    recorder: &mut dyn Recorder,
) -> Result<BodyRun<'a>, KindError> {
    let names = scene.state_names();
    let start = RunStart {
        path: "",
        columns: &names,
        expected_rows: (scene.integrator.end_time / scene.every) as usize + 1,
        end_time: scene.integrator.end_time,
        potential: has_potential(scene),
        energy_unit: crate::models::ENERGY_UNIT,
    };
    recorder.begin(start).map_err(KindError::Output)?;
    let mut recording = Recording {
        recorder,
        rows: 0,
        measured: (!measure_keys(scene).is_empty()).then(Default::default),
    };
    let ran = run_reporting(scene, &mut recording);
    let Recording {
        recorder,
        rows,
        measured,
    } = recording;
    // A row the recorder could not keep is its error, before anything the run says.
    recorder.end().map_err(KindError::Output)?;
    let mut stopped = matches!(ran.error, Some(RunError::Stopped { .. }));
    let error = ran.error.filter(|_| !stopped);
    let measures = measures(scene, measured.as_ref());
    let mut summary = summary_of(scene, name, &ran.report, &names);
    summary.error = error.as_ref().map(RunError::to_string);
    for (key, value) in &measures {
        match value {
            Ok(value) => {
                (summary.section.extra).insert((*key).into(), Extra::Number(*value));
            }
            Err(why) => summary.warnings.push(not_given(key, why)),
        }
    }
    let refined = match (&error, stopped) {
        (None, false) => refined_differences(scene, &measures, &|| recorder.stop_asked()),
        _ => Refined::default(),
    };
    // A stop asked during the refined run stops the scene's run as one during its rows does.
    stopped |= refined.stopped;
    summary.interrupted = stopped;
    summary.warnings.extend(refined.warnings);
    let refined = refined.differences;
    if !refined.is_empty() {
        let differences = (refined.iter())
            .map(|(k, d)| ((*k).to_owned(), *d))
            .collect();
        let key = scene.integrator.refinement_key();
        (summary.section.extra).insert(key.into(), Extra::Differences(differences));
    }
    summary.runs = vec![run_figures(scene, &measures, &refined)];
    if let Some(condition) = &scene.stop {
        let extra = &mut summary.section.extra;
        extra.insert("stop_when".into(), Extra::Text(condition.text.clone()));
        extra.insert("stopped_at".into(), Extra::Time(ran.report.stopped_at));
    }
    // A plot needs two rows; a run stopped at its start has at most one.
    if rows >= 2 {
        let drawings = RunDrawings {
            path: String::new(),
            drawings: vec![Drawing::RigidBody(drawing(scene))],
        };
        recorder.drawn(drawings).map_err(KindError::Output)?;
    }
    Ok(BodyRun {
        scene,
        report: ran.report,
        error,
        stopped,
        rows,
        measures,
        refined,
        summary,
    })
}

/// The summary of a run of `scene` (`name`, its file) that reported `report`, before its
/// figures: the settings and statistics, the model and where the run ended.
fn summary_of(
    scene: &BodyScene,
    name: &str,
    report: &Report,
    names: &[String],
) -> Summary<BodySection> {
    let spec = &scene.integrator;
    let integrator = IntegratorSummary {
        steps: report.steps as u64,
        rejected: Some(report.rejected as u64),
        rhs_evals: Some(report.rhs_evals as u64),
        ..IntegratorSummary::settings(spec.method, spec.step, spec.adaptive)
    };
    let selection = &scene.selection;
    Summary {
        kind: super::kind::NAME,
        scene: name.to_owned(),
        title: scene.title.clone(),
        integrator,
        wall_seconds: report.wall_seconds,
        interrupted: false,
        error: None,
        warnings: report.warnings.clone(),
        case: None,
        runs: Vec::new(),
        verdicts: Vec::new(),
        section: BodySection::new((selection.info, selection.reason.clone()), report, names),
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

/// The rows of a refined run, kept for the figures alone; the run ends when the caller asks
/// (Ctrl-C).
struct Kept<'a> {
    measured: (Vec<f64>, Vec<f64>),
    stop_asked: &'a dyn Fn() -> bool,
}

impl Sink for Kept<'_> {
    fn row(&mut self, row: &Row) -> bool {
        keep(&mut self.measured, row);
        !(self.stop_asked)()
    }
}

/// What refining a run gave: how far each figure moved, by key (`None` where the refined run
/// gave none), a warning for each such, and whether the caller stopped it.
#[derive(Default)]
struct Refined {
    differences: Vec<(&'static str, Option<f64>)>,
    warnings: Vec<String>,
    stopped: bool,
}

/// How far each figure given moves when the scene runs again refined
/// ([`super::IntegratorSpec::refined`]). Nothing where the run gave no figure.
fn refined_differences(
    scene: &BodyScene,
    measures: &[(&'static str, Result<f64, String>)],
    stop_asked: &dyn Fn() -> bool,
) -> Refined {
    if !measures.iter().any(|(_, value)| value.is_ok()) {
        return Refined::default();
    }
    let mut finer = scene.clone();
    finer.integrator = scene.integrator.refined(scene.every);
    let mut kept = Kept {
        measured: Default::default(),
        stop_asked,
    };
    let ran = run_reporting(&finer, &mut kept);
    if let Some(RunError::Stopped { .. }) = ran.error {
        return Refined {
            stopped: true,
            ..Refined::default()
        };
    }
    let refined_measures = self::measures(&finer, Some(&kept.measured));
    let key = scene.integrator.refinement_key();
    let mut warnings = Vec::new();
    let differences = (measures.iter().zip(refined_measures))
        .filter_map(|((name, value), (_, refined))| {
            let value = value.as_ref().ok()?;
            let difference = match (&ran.error, refined) {
                (None, Ok(refined)) => Some((value - refined).abs()),
                (Some(error), _) => {
                    warnings.push(format!("{key} of {name} is not given: refined, {error}"));
                    None
                }
                (None, Err(why)) => {
                    warnings.push(format!("{key} of {name} is not given: {why}"));
                    None
                }
            };
            Some((*name, difference))
        })
        .collect();
    Refined {
        differences,
        warnings,
        stopped: false,
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

/// What the plots and the view draw of the body.
fn drawing(scene: &BodyScene) -> RigidBody {
    let rows = |m: nalgebra::Matrix3<f64>| [0, 1, 2].map(|r| [m[(r, 0)], m[(r, 1)], m[(r, 2)]]);
    let shape = match &scene.body {
        Body::Spatial { mass, inertia } => BodyShape::Spatial {
            mass: *mass,
            inertia: rows(inertia.matrix()),
            in_water: in_water(&scene.loads),
            free_of_moments: scene.loads.is_free() || scene.loads.uniform_gravity_only().is_some(),
        },
        Body::Top {
            mass, inertia, h, ..
        } => BodyShape::Top {
            mass: *mass,
            inertia: rows(inertia.matrix()),
            h: *h,
        },
        Body::Pendulum(p) => BodyShape::Pendulum {
            h: p.h(),
            i0: p.i0(),
            mass: p.mass(),
        },
        Body::Planar { mass, izz, .. } => BodyShape::Planar {
            mass: *mass,
            izz: *izz,
        },
    };
    RigidBody {
        title: scene.title.clone(),
        family: scene.selection.info.family,
        kinematics: scene.selection.info.kinematics,
        shape,
        initial: scene.initial.clone(),
        conserves_energy: scene.loads.potential_energy(&scene.initial).is_some(),
    }
}

/// Whether water acts on a spatial body: buoyancy, or any damping.
fn in_water(loads: &SceneLoads) -> bool {
    match loads {
        SceneLoads::Spatial(l) => {
            l.buoyancy != 0.0 || l.linear.iter().chain(&l.quadratic).any(|c| *c != 0.0)
        }
        _ => false,
    }
}

impl BodyRun<'_> {
    /// The report as `eom run` prints it: the model and why, its cost against the full
    /// variant's, the integration, the energy drift and where a stop condition ended it.
    pub fn report(&self) -> String {
        self.write_report().unwrap_or_default()
    }

    fn write_report(&self) -> Result<String, std::fmt::Error> {
        let scene = self.scene;
        let info = scene.selection.info;
        let (ops, full) = (info.operations, info.full_variant().operations);
        let report = &self.report;
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
        for ((key, value), (_, moved)) in self.measures.iter().zip(&self.refined) {
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

    /// The columns of a body's sweep's table after the case and its swept values, with this
    /// run's values: `variant, steps, rhs_evals, wall_seconds, energy_drift, <the family's
    /// figures…>, final_<state…>`; all but the variant empty where the run failed.
    pub fn cells(&self) -> Vec<(String, String)> {
        let scene = self.scene;
        let ran = self.error.is_none() && !self.stopped;
        let value = |text: String| if ran { text } else { String::new() };
        let report = &self.report;
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
        for (key, measure) in &self.measures {
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
    pub fn kept(&self) -> String {
        let (t, end) = (self.report.final_time, self.scene.integrator.end_time);
        match (self.stopped, self.rows) {
            (true, _) => format!(
                "every row up to t = {} s of {} s in trajectory.csv, summary.json \
                 (\"interrupted\": true) and the plots",
                Short(t),
                Short(end)
            ),
            (false, 0) => "its summary.json (the run stopped at its start)".into(),
            (false, _) => format!(
                "its rows up to t = {} s, summary.json and the plots",
                Short(t)
            ),
        }
    }
}
