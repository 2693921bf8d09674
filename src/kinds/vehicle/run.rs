//! A vehicle scene's runs as the one runner ([`crate::run::scene`]) runs them: every
//! manoeuvre from its trim; the vehicle's section of the summary (`summary.json`'s types,
//! [`super::summary`]), the report as text, and a sweep case's line. The runner does the loop,
//! the rows, the refined run and the summary's shared keys; this module opens no file.

use super::manoeuvre::{ROW, VehicleManoeuvre, VehicleRun, run_until};
use super::scene::NAMED_FROM;
use super::summary::{
    CruiseSummary, KirchhoffRow, ManoeuvreSummary, ModelSummary, SetpointFigures, StepFigures,
    VehicleSection, largest_difference, largest_setpoint_difference, trial_figures,
};
use super::trial::{Plane, TrialFigures, largest_trial_difference};
use super::{VehicleScene, format_folded};
use crate::kind::KindError;
use crate::output::drawing::{
    Attitude, Coordinate, Drawing, Ground, Line, Mark, Orientation, Profile, Reading, Series,
    Shape, Track, Trail, View,
};
use crate::output::summary::{Figure, IntegratorSummary, RunFigures};
use crate::output::text::printable;
use crate::output::trajectory::number_text;
use crate::run::scene::{Closing, Counts, Ran, Rows, RunPlan, RunResult, SceneRuns, Setting};
use crate::scene::stop::StopCondition;
use crate::scene::sweep::{TableCase, manoeuvre_columns};
use crate::{Model, Short, counted, fixed};
use std::fmt::Write;

/// What a manoeuvre's run gives: each stretch's figures, the summary that says them, the
/// points its track marks.
#[derive(Debug, Clone)]
pub struct ManoeuvreFigures {
    /// The figures of each stretch of constant commands.
    pub steps: Vec<StepFigures>,
    /// What summary.json says of it, but how far it moved refined ([`summary`] adds that).
    pub summary: ManoeuvreSummary,
    /// Points to mark on its track: a turning circle's, (what, [x, y]).
    pub marks: Vec<(String, [f64; 2])>,
}

/// A manoeuvre run with the scene's method, its cost, and its figures refined.
pub type Outcome = crate::run::scene::Outcome<ManoeuvreFigures>;

/// What summary.json says of a manoeuvre's run: its summary, with the largest difference of
/// its figures from the refined run's where that finished.
pub fn summary(outcome: &Outcome) -> ManoeuvreSummary {
    ManoeuvreSummary {
        refined_difference: refined_difference(outcome),
        ..outcome.gave.summary.clone()
    }
}

/// The largest difference of a manoeuvre's figures from the refined run's, where that
/// finished.
fn refined_difference(outcome: &Outcome) -> Option<f64> {
    let refined = outcome.refined()?;
    Some(moved_when_refined(&outcome.gave.summary, &refined.summary))
}

impl SceneRuns for VehicleScene {
    type Shared = ();
    type Gave = ManoeuvreFigures;
    type Section = VehicleSection;

    fn kind_name(&self) -> &'static str {
        super::KIND.name
    }

    fn scene_title(&self) -> &str {
        &self.title
    }

    fn integrator(&self) -> IntegratorSummary {
        IntegratorSummary::of(&self.stepper)
    }

    fn prepare(&self) -> Result<(), KindError> {
        Ok(())
    }

    /// Each manoeuvre's run from its trim: t, [`ROW`] and the kinetic energy of the body and
    /// the fluid.
    fn plans(&self, _: &()) -> Vec<RunPlan> {
        (self.manoeuvres.iter())
            .map(|manoeuvre| RunPlan {
                path: manoeuvre.name.clone(),
                columns: ROW.map(str::to_owned).to_vec(),
                expected_rows: (manoeuvre.duration / self.every) as usize + 1,
                end_time: manoeuvre.duration,
                potential: false,
                energy_unit: crate::models::ENERGY_UNIT,
            })
            .collect()
    }

    fn run_one(
        &self,
        _: &(),
        index: usize,
        setting: Setting,
        rows: &mut Rows,
    ) -> RunResult<ManoeuvreFigures> {
        let manoeuvre = &self.manoeuvres[index];
        let stepper = setting.stepper(&self.stepper, self.every);
        let model = &self.model;
        let start = (manoeuvre.trim.state, self.stop.as_ref());
        let settings = (&stepper, self.every);
        let done = run_until(model, &self.fins, manoeuvre, start, settings, |sample| {
            let kinetic = || model.kinetic_energy(&sample.state);
            rows.take_built(sample.t, || (sample.row(), kinetic()))
        });
        let done = done.map_err(|e| KindError::from(e.in_manoeuvre(&manoeuvre.name)))?;
        Ok(outcome(self, manoeuvre, &done))
    }

    fn refined_warnings(&self, outcome: &Outcome) -> Vec<String> {
        (outcome.refined_failure().iter())
            .map(|error| format!("refined_difference is not given: refined, {error}"))
            .collect()
    }

    fn figures(&self, plan: &RunPlan, outcome: &Outcome) -> RunFigures {
        run_figures(
            &plan.path,
            &outcome.gave.summary,
            refined_difference(outcome),
        )
    }

    fn drawings(&self, _: &(), index: usize, outcome: &Outcome) -> Vec<Drawing> {
        drawings(
            self,
            format!("{} — {}", self.title, self.manoeuvres[index].name),
            Mark::all(&outcome.gave.marks),
        )
    }

    fn close(&self, ran: &Ran<'_, Self>) -> Closing<VehicleSection> {
        let manoeuvre = (ran.outcomes.iter())
            .map(|(index, o)| (self.manoeuvres[*index].name.clone(), summary(o)))
            .collect();
        let section = VehicleSection {
            model: ModelSummary::new(self),
            kirchhoff: self.model.folded().iter().map(KirchhoffRow::new).collect(),
            cruise: CruiseSummary::new(self),
            manoeuvre,
            stop_when: self.stop.as_ref().map(|stop| stop.text.clone()),
        };
        Closing {
            section,
            verdicts: Vec::new(),
            warnings: Vec::new(),
        }
    }

    /// The cruise, each manoeuvre's figures, the folded table against its added mass.
    fn report(&self, ran: &Ran<'_, Self>) -> String {
        let outcomes: Vec<(&VehicleManoeuvre, &Outcome)> = (ran.outcomes.iter())
            .map(|(index, outcome)| (&self.manoeuvres[*index], outcome))
            .collect();
        report(self, &CruiseSummary::new(self), &outcomes).unwrap_or_default()
    }

    /// Each manoeuvre's figures, `<manoeuvre>.<figure>`: a trial's (`turning_circle.
    /// tactical_diameter_m`), each autopilot's by what it holds (`turn_and_dive.heading.
    /// overshoot`), or, for fin steps, each step's end (`rudder_4.step_1.heading_deg`); then
    /// how far they moved when refined and the steps taken. A figure a trial gives as a list
    /// (a zig-zag's overshoot times) stays in summary.json.
    fn cells(&self, ran: &Ran<'_, Self>, case: &TableCase) -> Vec<(String, String)> {
        let names = self.manoeuvres.iter().map(|m| m.name.as_str());
        let columns = manoeuvre_columns(case, names, &NAMED_FROM);
        let mut cells = Vec::new();
        for (index, column) in columns.iter().enumerate() {
            let Some(outcome) = ran.outcome(index) else {
                continue;
            };
            let json = serde_json::to_value(summary(outcome)).unwrap_or_default();
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

/// What a manoeuvre's run gave, and what it cost.
fn outcome(scene: &VehicleScene, manoeuvre: &VehicleManoeuvre, done: &VehicleRun) -> Outcome {
    let steps = StepFigures::of(done);
    let trial = trial_figures(done, manoeuvre);
    let marks = match &trial {
        Some(TrialFigures::TurningCircle(figures)) => figures.marks.clone(),
        _ => Vec::new(),
    };
    let notes = stop_notes(scene.stop.as_ref(), done, trial.as_ref());
    let summary = ManoeuvreSummary {
        steps: steps.clone(),
        autopilot: SetpointFigures::of(done),
        trial,
        // Said by [`summary`], from the refined run where it ran.
        refined_difference: None,
        refinement: scene.stepper.refinement(),
        steps_taken: done.steps,
        stopped_at: scene.stop.as_ref().map(|_| done.stopped_at),
        notes,
    };
    let counts = Counts {
        steps: done.steps,
        rejected: None,
        rhs_evals: done.rhs_evals,
    };
    Outcome::new(
        ManoeuvreFigures {
            steps,
            summary,
            marks,
        },
        counts,
    )
}

/// The largest difference between a run's figures (its steps, autopilots and trial) and those
/// of the same manoeuvre run refined.
fn moved_when_refined(summary: &ManoeuvreSummary, refined: &ManoeuvreSummary) -> f64 {
    let trial_difference = match (&summary.trial, &refined.trial) {
        (Some(a), Some(b)) => largest_trial_difference(a, b),
        _ => 0.0,
    };
    largest_difference(&summary.steps, &refined.steps)
        .max(largest_setpoint_difference(
            &summary.autopilot,
            &refined.autopilot,
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
/// `None` where it is not given), the largest difference the refined run showed over them
/// (`largest_difference`, where it ran).
fn run_figures(
    name: &str,
    summary: &ManoeuvreSummary,
    largest_difference: Option<f64>,
) -> RunFigures {
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
        refinement: largest_difference.map(|_| summary.refinement),
        largest_difference,
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
    cruise: &CruiseSummary,
    outcomes: &[(&VehicleManoeuvre, &Outcome)],
) -> Result<String, std::fmt::Error> {
    let mut text = String::new();
    let out = &mut text;
    writeln!(out, "{}", printable(&scene.title))?;
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
    for (manoeuvre, outcome) in outcomes {
        match summary(outcome).refined_difference {
            Some(moved) => writeln!(out, "  {}: (refined: {moved:.1e})", manoeuvre.name)?,
            None => writeln!(out, "  {}: (not refined)", manoeuvre.name)?,
        }
        writeln!(
            out,
            "    {:>6} {:>6} {:>7} {:>7} {:>10} {:>8} {:>8} {:>8} {:>8}",
            "from s", "to s", "δr °", "δs °", "r °/s", "U m/s", "φ °", "θ °", "z m"
        )?;
        for s in &outcome.gave.steps {
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
        autopilot_report(out, &outcome.gave.summary.autopilot)?;
        if let Some(trial) = &outcome.gave.summary.trial {
            trial_report(out, trial)?;
        }
        for note in &outcome.gave.summary.notes {
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

/// What a manoeuvre's run draws: the track in plan with its marks, the profile, the attitude,
/// the fins with their commands, and the solid of the body's mass and principal moments
/// moving through the water about the table's origin O (G's offset from it, 2 cm for REMUS,
/// not drawn), every column in its readout.
fn drawings(scene: &VehicleScene, title: String, marks: Vec<Mark>) -> Vec<Drawing> {
    let column = |name: &str| name.to_owned();
    let [x, y, z] = ["x", "y", "z"].map(column);
    let angles = ["phi", "theta", "psi"].map(column);
    let fin = |label: &str, name: &str| Line::new(label, name, Reading::Degrees);
    vec![
        Drawing::Track(Track {
            title: title.clone(),
            what: "track in plan".into(),
            across: (y.clone(), "east Y [m]".into()),
            up: (x.clone(), "north X [m]".into()),
            marks,
            outline: None,
        }),
        Drawing::Profile(Profile {
            title: title.clone(),
            position: [x.clone(), y.clone(), z.clone()],
            when_level: true,
        }),
        Drawing::Attitude(Attitude {
            title: title.clone(),
            orientation: Orientation::EulerAngles(angles),
        }),
        Drawing::Series(Series {
            file: "fins.svg".into(),
            title: title.clone(),
            what: "fins and their commands".into(),
            y_desc: "[deg]".into(),
            lines: vec![
                fin("rudder δr", "dr"),
                fin("stern planes δs", "ds"),
                fin("rudder command", "dr_command"),
                fin("stern planes command", "ds_command"),
            ],
        }),
        Drawing::View(Box::new(View {
            trail: Trail::Point([0.0; 3], "the table's origin O".into()),
            ground: Ground::Water,
            ..View::moving(
                title,
                Shape::Cylinder(scene.solid()),
                [x, y, z].map(Coordinate::Column),
                Orientation::Quaternion(["q0", "q1", "q2", "q3"].map(column)),
            )
        })),
    ]
}
