//! A vehicle scene run: every manoeuvre from its trim with the scene's method, its rows handed
//! to the caller's [`Recorder`], run again refined for how far each figure moves; the summary
//! (`summary.json`'s types, [`super::summary`]), the report as text, and a sweep case's line.
//! What is written where, and whether a run may go on, is the recorder's: this module opens no
//! file.

use super::manoeuvre::{ROW, VehicleManoeuvre, VehicleRun, run_until};
use super::scene::NAMED_FROM;
use super::summary::{
    CruiseSummary, KirchhoffRow, ManoeuvreSummary, ModelSummary, SetpointFigures, StepFigures,
    VehicleSection, largest_difference, largest_setpoint_difference, trial_figures,
};
use super::trial::{Plane, TrialFigures, largest_trial_difference};
use super::{VehicleError, VehicleScene, format_folded};
use crate::output::drawing::{Drawing, Mark, RunDrawings, SpaceManoeuvre};
use crate::output::summary::{Figure, IntegratorSummary, RunFigures, Summary};
use crate::output::text::printable;
use crate::output::trajectory::number_text;
use crate::run::Row;
use crate::run::record::{RecordError, Recorder, RunStart};
use crate::scene::stop::StopCondition;
use crate::scene::sweep::{TableCase, manoeuvre_columns};
use crate::{Model, Short, counted, fixed};
use std::collections::BTreeMap;
use std::fmt::Write;
use std::time::Instant;

/// A manoeuvre run with the scene's method, and its figures refined.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The figures of each stretch of constant commands.
    pub steps: Vec<StepFigures>,
    /// What summary.json says of it.
    pub summary: ManoeuvreSummary,
    /// Points to mark on its track: a turning circle's, (what, [x, y]).
    pub marks: Vec<(String, [f64; 2])>,
    /// Its evaluations of the right-hand side.
    pub rhs_evals: u64,
}

/// What a vehicle scene's run gave: its summary, each manoeuvre's outcome (those finished
/// before a stop was asked), and whether a stop was asked.
#[derive(Debug, Clone)]
pub struct Finished<'a> {
    /// The scene that ran.
    pub scene: &'a VehicleScene,
    /// `summary.json`.
    pub summary: Summary<VehicleSection>,
    /// Each manoeuvre run, in the scene's order.
    pub outcomes: Vec<Outcome>,
    /// Whether the recorder asked the run to stop before every manoeuvre had run.
    pub stopped: bool,
}

/// Runs every manoeuvre of `scene` (`name` is its file, as the summary names it), each from
/// its trim, its rows to `recorder` under the manoeuvre's name; a manoeuvre the recorder stops
/// ends the run, keeping the ones before it.
pub fn run_scene<'a>(
    scene: &'a VehicleScene,
    name: &str,
    recorder: &mut dyn Recorder,
) -> Result<Finished<'a>, VehicleError> {
    let started = Instant::now();
    let mut manoeuvres = BTreeMap::new();
    let mut outcomes = Vec::new();
    let mut stopped = false;
    for manoeuvre in &scene.manoeuvres {
        let outcome = match run_manoeuvre(scene, manoeuvre, recorder) {
            Err(VehicleError::Stopped { .. }) => {
                stopped = true;
                break;
            }
            outcome => outcome.map_err(|e| e.in_manoeuvre(&manoeuvre.name))?,
        };
        manoeuvres.insert(manoeuvre.name.clone(), outcome.summary.clone());
        outcomes.push(outcome);
    }
    let stepper = &scene.stepper;
    let integrator = IntegratorSummary {
        steps: outcomes.iter().map(|o| o.summary.steps_taken).sum(),
        rhs_evals: Some(outcomes.iter().map(|o| o.rhs_evals).sum()),
        ..IntegratorSummary::settings(stepper.method, stepper.step, stepper.adaptive)
    };
    let runs = (scene.manoeuvres.iter().zip(&outcomes))
        .map(|(manoeuvre, outcome)| run_figures(&manoeuvre.name, &outcome.summary))
        .collect();
    let summary = Summary {
        kind: super::KIND.name,
        scene: name.to_owned(),
        title: scene.title.clone(),
        integrator,
        wall_seconds: started.elapsed().as_secs_f64(),
        interrupted: stopped,
        error: None,
        warnings: Vec::new(),
        case: None,
        runs,
        verdicts: Vec::new(),
        section: VehicleSection {
            model: ModelSummary::new(scene),
            kirchhoff: scene.model.folded().iter().map(KirchhoffRow::new).collect(),
            cruise: CruiseSummary::new(scene),
            manoeuvre: manoeuvres,
            stop_when: scene.stop.as_ref().map(|stop| stop.text.clone()),
        },
    };
    Ok(Finished {
        scene,
        summary,
        outcomes,
        stopped,
    })
}

/// The error of a recorder that could not keep what a manoeuvre gave.
fn not_recorded(manoeuvre: &VehicleManoeuvre, error: RecordError) -> VehicleError {
    VehicleError::Record {
        run: manoeuvre.name.clone(),
        source: error,
    }
}

/// Runs `manoeuvre` from its trim with the scene's method, its rows (t, [`ROW`], the kinetic
/// energy of the body and the fluid) to `recorder`, then refined.
fn run_manoeuvre(
    scene: &VehicleScene,
    manoeuvre: &VehicleManoeuvre,
    recorder: &mut dyn Recorder,
) -> Result<Outcome, VehicleError> {
    if recorder.stop_asked() {
        return Err(VehicleError::Stopped { time: 0.0 });
    }
    let names = ROW.map(str::to_owned);
    let expected_rows = (manoeuvre.duration / scene.every) as usize + 1;
    let start = RunStart {
        path: &manoeuvre.name,
        columns: &names,
        expected_rows,
        end_time: manoeuvre.duration,
        potential: false,
        energy_unit: crate::models::ENERGY_UNIT,
    };
    recorder
        .begin(start)
        .map_err(|e| not_recorded(manoeuvre, e))?;
    let model = &scene.model;
    let start = (manoeuvre.trim.state, scene.stop.as_ref());
    let keeps_rows = recorder.keeps_rows();
    let done = run_until(
        model,
        &scene.fins,
        manoeuvre,
        start,
        (&scene.stepper, scene.every),
        |sample| {
            if !keeps_rows {
                return !recorder.stop_asked();
            }
            let row = Row {
                t: sample.t,
                state: &sample.row(),
                kinetic_energy: model.kinetic_energy(&sample.state),
                potential_energy: None,
            };
            recorder.row(&row)
        },
    );
    // What the recorder could not keep comes first: the run stopped because of it.
    recorder.end().map_err(|e| not_recorded(manoeuvre, e))?;
    let done = done?;
    let steps = StepFigures::of(&done);
    let autopilot = SetpointFigures::of(&done);
    let trial = trial_figures(&done, manoeuvre);
    // A Monte Carlo's case is not run again refined: what it reads is the cases' spread.
    let refined_difference = match recorder.refines() {
        true => {
            let settings = (&scene.stepper.refined(scene.every), scene.every);
            let refined = run_until(model, &scene.fins, manoeuvre, start, settings, |_| {
                !recorder.stop_asked()
            })?;
            Some(moved_when_refined(
                &refined,
                manoeuvre,
                &steps,
                &autopilot,
                trial.as_ref(),
            ))
        }
        false => None,
    };
    let marks = match &trial {
        Some(TrialFigures::TurningCircle(figures)) => figures.marks.clone(),
        _ => Vec::new(),
    };
    let drawings = RunDrawings {
        path: manoeuvre.name.clone(),
        drawings: vec![Drawing::SpaceManoeuvre(SpaceManoeuvre {
            title: format!("{} — {}", scene.title, manoeuvre.name),
            marks: Mark::all(&marks),
            solid: scene.solid(),
        })],
    };
    (recorder.drawn(drawings)).map_err(|e| not_recorded(manoeuvre, e))?;
    let notes = stop_notes(scene.stop.as_ref(), &done, trial.as_ref());
    let summary = ManoeuvreSummary {
        steps: steps.clone(),
        autopilot,
        trial,
        refined_difference,
        refinement: scene.stepper.refinement(),
        steps_taken: done.steps,
        stopped_at: scene.stop.as_ref().map(|_| done.stopped_at),
        notes,
    };
    Ok(Outcome {
        steps,
        summary,
        marks,
        rhs_evals: done.rhs_evals,
    })
}

/// The largest difference between the run's figures (`steps`, `autopilot`, `trial`) and
/// those of the same manoeuvre run `refined`.
fn moved_when_refined(
    refined: &VehicleRun,
    manoeuvre: &VehicleManoeuvre,
    steps: &[StepFigures],
    autopilot: &[SetpointFigures],
    trial: Option<&TrialFigures>,
) -> f64 {
    let trial_difference = match (trial, trial_figures(refined, manoeuvre)) {
        (Some(a), Some(b)) => largest_trial_difference(a, &b),
        _ => 0.0,
    };
    largest_difference(steps, &StepFigures::of(refined))
        .max(largest_setpoint_difference(
            autopilot,
            &SetpointFigures::of(refined),
        ))
        .max(trial_difference)
}

/// Where the stop condition ended `done`, and what it had not read by then: the figures of
/// the step of the commands it cut short (read at its end), an autopilot's answer to a change
/// within it, a trial's figures not given; none for a run it did not end.
fn stop_notes(
    stop: Option<&StopCondition>,
    done: &VehicleRun,
    trial: Option<&TrialFigures>,
) -> Vec<String> {
    let (Some(stop), Some(t)) = (stop, done.stopped_at) else {
        return Vec::new();
    };
    let from = done.ends.last().map_or(0.0, |end| end.t);
    let mut absent = vec![format!(
        "the step of the commands from {} s ended (its figures are read at its end)",
        Short(from)
    )];
    for (what, at) in SetpointFigures::cut_short(done) {
        absent.push(format!(
            "the {what} autopilot's answer to the change at {} s",
            Short(at)
        ));
    }
    match trial {
        Some(TrialFigures::TurningCircle(f)) => {
            let figures = [
                ("advance_m", f.advance_m),
                ("transfer_m", f.transfer_m),
                ("tactical_diameter_m", f.tactical_diameter_m),
                ("steady_diameter_m", f.steady_diameter_m),
                ("speed_m_s", f.speed_m_s),
                ("heading_rate_deg_s", f.heading_rate_deg_s),
                ("roll_deg", f.roll_deg),
                ("pitch_deg", f.pitch_deg),
                ("depth_change_m", f.depth_change_m),
            ];
            let keys: Vec<&str> = (figures.iter())
                .filter(|(_, value)| value.is_none())
                .map(|(key, _)| *key)
                .collect();
            absent.push(format!("the turning circle gave {}", keys.join(", ")));
        }
        Some(TrialFigures::ZigZag(_)) => {
            absent.push("a later switch or overshoot of the zig-zag".to_owned());
        }
        None => {}
    }
    vec![format!(
        "stopped at t = {t:.1} s where `{stop}` first held (integrator.stop_when), before: {}",
        absent.join("; ")
    )]
}

impl Finished<'_> {
    /// The report as the command prints it: the cruise, each manoeuvre's figures, the folded
    /// table against its added mass.
    pub fn report(&self) -> String {
        report(self.scene, &self.summary, &self.outcomes).unwrap_or_default()
    }

    /// Each manoeuvre's figures, `<manoeuvre>.<figure>`: a trial's (`turning_circle.
    /// tactical_diameter_m`), each autopilot's by what it holds (`turn_and_dive.heading.
    /// overshoot`), or, for fin steps, each step's end (`rudder_4.step_1.heading_deg`); then
    /// how far they moved when refined and the steps taken. A figure a trial gives as a list
    /// (a zig-zag's overshoot times) stays in summary.json.
    pub fn cells(&self, case: &TableCase) -> Vec<(String, String)> {
        let scene = self.scene;
        let names = scene.manoeuvres.iter().map(|m| m.name.as_str());
        let columns = manoeuvre_columns(case, names, &NAMED_FROM);
        let mut cells = Vec::new();
        for (manoeuvre, column) in scene.manoeuvres.iter().zip(&columns) {
            let Some(summary) = self.summary.section.manoeuvre.get(&manoeuvre.name) else {
                continue;
            };
            let json = serde_json::to_value(summary).unwrap_or_default();
            for (key, value) in manoeuvre_figures(&json) {
                if let Some(text) = scalar_text(value) {
                    cells.push((format!("{column}.{key}"), text));
                }
            }
            for key in ["refined_difference", "steps_taken"] {
                if let Some(text) = scalar_text(&json[key]) {
                    cells.push((format!("{column}.{key}"), text));
                }
            }
        }
        cells
    }
}

/// A manoeuvre's figures from its summary, by key: a trial's (`tactical_diameter_m`), each
/// autopilot's by what it holds (`heading.overshoot`), or, for fin steps, each step's end
/// (`step_1.heading_deg`).
fn manoeuvre_figures(json: &serde_json::Value) -> Vec<(String, &serde_json::Value)> {
    /// The entries of the object `value`, each key after `prefix`.
    fn entries<'j>(
        prefix: Option<&str>,
        value: &'j serde_json::Value,
    ) -> Vec<(String, &'j serde_json::Value)> {
        (value.as_object().into_iter().flatten())
            .map(|(key, value)| match prefix {
                Some(prefix) => (format!("{prefix}.{key}"), value),
                None => (key.clone(), value),
            })
            .collect()
    }
    match (&json["trial"], json["autopilot"].as_array()) {
        (trial, _) if trial.is_object() => entries(None, trial),
        (_, Some(autopilots)) => (autopilots.iter())
            .flat_map(|autopilot| {
                let what = autopilot["what"].as_str().unwrap_or("autopilot");
                entries(Some(what), autopilot)
            })
            .collect(),
        _ => (json["steps"].as_array().into_iter().flatten())
            .enumerate()
            .flat_map(|(index, step)| entries(Some(&format!("step_{index}")), step))
            .collect(),
    }
}

/// A manoeuvre's figures as every kind gives them: each number of [`manoeuvre_figures`] (or
/// `None` where it is not given), the largest difference the refined run showed over them.
fn run_figures(name: &str, summary: &ManoeuvreSummary) -> RunFigures {
    let json = serde_json::to_value(summary).unwrap_or_default();
    let figures = (manoeuvre_figures(&json).into_iter())
        .filter(|(_, value)| value.is_number() || value.is_null())
        .map(|(key, value)| Figure {
            key,
            value: value.as_f64(),
            difference: None,
        })
        .collect();
    RunFigures {
        run: name.to_owned(),
        figures,
        refinement: Some(summary.refinement),
        largest_difference: summary.refined_difference,
        notes: summary.notes.clone(),
    }
}

/// A figure as the sweep's table writes it: a number in its shortest round-trip form, a text
/// or a verdict as it is, an absent figure empty; `None` for a list or a table.
fn scalar_text(value: &serde_json::Value) -> Option<String> {
    match value {
        serde_json::Value::Number(n) => Some(n.as_f64().map_or_else(|| n.to_string(), number_text)),
        serde_json::Value::String(text) => Some(text.clone()),
        serde_json::Value::Bool(b) => Some(b.to_string()),
        serde_json::Value::Null => Some(String::new()),
        _ => None,
    }
}

fn report(
    scene: &VehicleScene,
    summary: &Summary<VehicleSection>,
    outcomes: &[Outcome],
) -> Result<String, std::fmt::Error> {
    let mut text = String::new();
    let out = &mut text;
    writeln!(out, "{}", printable(&scene.title))?;
    let cruise = &summary.section.cruise;
    let closed = |x: Option<f64>, unit: &str| {
        x.map_or_else(String::new, |x| {
            format!(" (closed form {}{unit})", fixed(x, 4))
        })
    };
    writeln!(
        out,
        "  cruise: u = {} m/s{}, roll trim φ = {}°{}",
        fixed(cruise.speed_m_s, 4),
        closed(cruise.speed_closed_form_m_s, " m/s"),
        fixed(cruise.roll_deg, 4),
        closed(cruise.roll_closed_form_deg, "°")
    )?;
    if let Some(steps) = cruise.newton_steps {
        writeln!(
            out,
            "    trimmed in every state but the position and the heading ({}): θ = {}°, v = \
             {} m/s, w = {} m/s, ψ̇ = {} °/s, ż = {} m/s",
            counted(steps, "Newton step", "Newton steps"),
            fixed(cruise.pitch_deg, 3),
            fixed(cruise.sway_m_s, 4),
            fixed(cruise.heave_m_s, 4),
            fixed(cruise.heading_rate_deg_s, 4),
            fixed(cruise.depth_rate_m_s, 4)
        )?;
    }
    for (manoeuvre, outcome) in scene.manoeuvres.iter().zip(outcomes) {
        match outcome.summary.refined_difference {
            Some(moved) => writeln!(out, "  {}: (refined: {moved:.1e})", manoeuvre.name)?,
            None => writeln!(out, "  {}: (not refined)", manoeuvre.name)?,
        }
        writeln!(
            out,
            "    {:>6} {:>6} {:>7} {:>7} {:>10} {:>8} {:>8} {:>8} {:>8}",
            "from s", "to s", "δr °", "δs °", "r °/s", "U m/s", "φ °", "θ °", "z m"
        )?;
        for s in &outcome.steps {
            writeln!(
                out,
                "    {:>6} {:>6} {:>7} {:>7} {:>10} {:>8} {:>8} {:>8} {:>8}",
                fixed(s.from_s, 1),
                fixed(s.to_s, 1),
                fixed(s.rudder_deg, 2),
                fixed(s.stern_planes_deg, 2),
                fixed(s.yaw_rate_deg_s, 4),
                fixed(s.speed_m_s, 4),
                fixed(s.roll_deg, 3),
                fixed(s.pitch_deg, 3),
                fixed(s.depth_m, 3)
            )?;
        }
        autopilot_report(out, &outcome.summary.autopilot)?;
        if let Some(trial) = &outcome.summary.trial {
            trial_report(out, trial)?;
        }
        for note in &outcome.summary.notes {
            writeln!(out, "    note: {note}")?;
        }
    }
    if !scene.model.folded().is_empty() {
        writeln!(out, "  the folded table against its added mass:")?;
        for line in format_folded(scene.model.folded()).lines() {
            writeln!(out, "    {line}")?;
        }
    }
    Ok(text)
}

/// How the autopilots answered each change of what they hold.
fn autopilot_report(out: &mut String, figures: &[SetpointFigures]) -> std::fmt::Result {
    if figures.is_empty() {
        return Ok(());
    }
    writeln!(
        out,
        "    {:<8} {:>6} {:>9} {:>9} {:>10} {:>12} {:>12}",
        "holds", "at s", "from", "to", "overshoot", "settles in s", "steady error"
    )?;
    for f in figures {
        let unit = if f.what == "heading" { "°" } else { " m" };
        let settles = f
            .settling_time_s
            .map_or_else(|| "not settled".to_owned(), |t| fixed(t, 1));
        writeln!(
            out,
            "    {:<8} {:>6} {:>8}{unit} {:>8}{unit} {:>9}{unit} {settles:>12} {:>11}{unit}",
            f.what,
            fixed(f.at_s, 1),
            fixed(f.from, 2),
            fixed(f.to, 2),
            fixed(f.overshoot, 3),
            fixed(f.steady_error, 4)
        )?;
    }
    Ok(())
}

/// A trial's figures.
fn trial_report(out: &mut String, trial: &TrialFigures) -> std::fmt::Result {
    let metres =
        |x: Option<f64>| x.map_or_else(|| "—".to_owned(), |x| format!("{} m", fixed(x, 2)));
    let number =
        |x: Option<f64>, digits: usize| x.map_or_else(|| "—".to_owned(), |x| fixed(x, digits));
    match trial {
        TrialFigures::TurningCircle(f) => {
            writeln!(
                out,
                "    turning circle at {}°: advance {}, transfer {}, tactical diameter {}, \
                 steady diameter {}",
                Short(f.rudder_deg),
                metres(f.advance_m),
                metres(f.transfer_m),
                metres(f.tactical_diameter_m),
                metres(f.steady_diameter_m)
            )?;
            writeln!(
                out,
                "      at the end: U = {} m/s, ψ̇ = {} °/s, φ = {}°, θ = {}°, depth change {} m",
                number(f.speed_m_s, 4),
                number(f.heading_rate_deg_s, 4),
                number(f.roll_deg, 3),
                number(f.pitch_deg, 3),
                number(f.depth_change_m, 3)
            )?;
            if let Some(why) = &f.not_steady_because {
                writeln!(out, "      no steady figures: {why}")?;
            }
            Ok(())
        }
        TrialFigures::ZigZag(f) => {
            let list = |v: &[f64]| {
                v.iter()
                    .map(|x| fixed(*x, 3))
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            let plane = match f.plane {
                Plane::Horizontal => "Horizontal",
                Plane::Vertical => "Vertical",
            };
            let label = format!(
                "    {plane} zig-zag {}°/{}°:",
                Short(f.fin_deg),
                Short(f.switch_deg)
            );
            match &f.no_figures_because {
                Some(why) => writeln!(out, "{label} no figures: {why}"),
                None => writeln!(
                    out,
                    "{label} overshoots {} °, switches at {} s",
                    list(&f.overshoots_deg),
                    list(&f.switches_s)
                ),
            }
        }
    }
}
