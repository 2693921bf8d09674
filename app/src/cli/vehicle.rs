//! Vehicle scenes: `eom run SCENE` for a scene with `[model] family = "vehicle"` and
//! `[hydrodynamics]`.
//!
//! Each `[[manoeuvre]]` runs from its trim ([`eom::kinds::vehicle::trim`]) into its own folder (`trajectory.csv`; as SVG the
//! track in plan, the profile, the attitude and the fins with their commands; `view.html`, the
//! run in 3-D), and
//! `summary.json` beside them holds the model that ran, the method, the folded table against
//! its added mass per coefficient, the cruise against its closed forms, and each manoeuvre's
//! figures with how far they move when the run is refined (the types of
//! `eom::kinds::vehicle::summary`). Ctrl-C ends the run at its next
//! step, keeping the manoeuvres finished before it.

use super::run::NUMBER_BYTES;
use super::run::{Interrupted, signal_received};
use super::sweep::{SweptCase, manoeuvre_columns};
use anyhow::{Context, Result};
use eom::kinds::vehicle::manoeuvre::{ROW, VehicleManoeuvre, run};
use eom::kinds::vehicle::scene::NAMED_FROM;
use eom::kinds::vehicle::summary::{
    CruiseSummary, KirchhoffRow, ManoeuvreSummary, ModelSummary, SetpointFigures, StepFigures,
    VehicleSummary, largest_difference, largest_setpoint_difference, trial_figures,
};
use eom::kinds::vehicle::trial::{Plane, TrialFigures, largest_trial_difference};
use eom::kinds::vehicle::{VehicleError, VehicleScene, format_folded};
use eom::output::summary::MethodSummary;
use eom::output::summary::write_atomically;
use eom::output::text::printable;
use eom::output::trajectory::{Columns, TrajectoryWriter, number_text};
use eom::run::{Row, Sink};
use eom::scene::sweep::TableCase;
use eom::{Model, fixed};
use eom::{Short, counted};
use eom_cli::plots::Mark;
use eom_cli::plots::vehicle::{VehiclePlot, write_vehicle_plots};
use std::collections::BTreeMap;
use std::path::Path;

/// Bytes per row of a vehicle's trajectory: twenty-two numbers.
const VEHICLE_ROW_BYTES: f64 = 22.0 * NUMBER_BYTES;

/// A manoeuvre run with the scene's method, and its figures refined.
struct Outcome {
    steps: Vec<StepFigures>,
    summary: ManoeuvreSummary,
}

/// What a vehicle scene's run gave: its summary (written into summary.json), each manoeuvre's
/// outcome, and the signal that ended it early, if one did.
pub struct VehicleRun {
    summary: VehicleSummary,
    outcomes: Vec<Outcome>,
    interrupted: Option<i32>,
}

/// Runs a vehicle scene, read and checked, into `out`, a folder already known to be writable,
/// and prints its figures.
pub fn execute(scene: &VehicleScene, out: &Path) -> Result<()> {
    let run = run_into(scene, out)?;
    print_report(scene, &run.summary, &run.outcomes, out);
    match run.interrupted {
        Some(signal) => Err(Interrupted {
            signal,
            kept: format!(
                "the {} finished before it, and summary.json, in {}",
                counted(run.outcomes.len(), "manoeuvre", "manoeuvres"),
                out.display()
            ),
        }
        .into()),
        None => Ok(()),
    }
}

/// Runs every manoeuvre of `scene` into its folder under `out` and writes summary.json.
fn run_into(scene: &VehicleScene, out: &Path) -> Result<VehicleRun> {
    let mut manoeuvres = BTreeMap::new();
    let mut outcomes = Vec::new();
    let mut interrupted = None;
    for manoeuvre in &scene.manoeuvres {
        let folder = out.join(&manoeuvre.name);
        std::fs::create_dir_all(&folder)
            .with_context(|| format!("creating {}", folder.display()))?;
        let outcome = match run_manoeuvre(scene, manoeuvre, &folder) {
            Err(error) if is_stopped(&error) => {
                interrupted = signal_received();
                break;
            }
            outcome => outcome.with_context(|| format!("manoeuvre {}", manoeuvre.name))?,
        };
        manoeuvres.insert(manoeuvre.name.clone(), outcome.summary.clone());
        outcomes.push(outcome);
    }
    let summary = VehicleSummary {
        title: scene.title.clone(),
        model: ModelSummary::new(scene),
        integrator: MethodSummary::new(&scene.stepper),
        kirchhoff: scene.model.folded().iter().map(KirchhoffRow::new).collect(),
        cruise: CruiseSummary::new(scene),
        manoeuvre: manoeuvres,
        interrupted: interrupted.is_some(),
    };
    let bytes = serde_json::to_vec_pretty(&serde_json::to_value(&summary)?)?;
    let path = out.join("summary.json");
    write_atomically(&path, &bytes).with_context(|| format!("writing {}", path.display()))?;
    Ok(VehicleRun {
        summary,
        outcomes,
        interrupted,
    })
}

impl SweptCase for VehicleScene {
    type Run = VehicleRun;

    fn folders(&self) -> Vec<String> {
        self.manoeuvres.iter().map(|m| m.name.clone()).collect()
    }

    fn trajectory_bytes(&self) -> f64 {
        let rows: f64 = (self.manoeuvres.iter())
            .map(|m| m.duration / self.every)
            .sum();
        rows * VEHICLE_ROW_BYTES
    }

    fn execute(&self, _name: &str, out: &Path) -> Result<()> {
        execute(self, out)
    }

    fn run_into(&self, _name: &str, out: &Path) -> Result<VehicleRun> {
        run_into(self, out)
    }

    /// Each manoeuvre's figures, `<manoeuvre>.<figure>`: a trial's (`turning_circle.
    /// tactical_diameter_m`), each autopilot's by what it holds (`turn_and_dive.heading.
    /// overshoot`), or, for fin steps, each step's end (`rudder_4.step_1.heading_deg`); then
    /// how far they moved when refined and the steps taken. A figure a trial gives as a list
    /// (a zig-zag's overshoot times) stays in summary.json.
    fn cells(&self, case: &TableCase, run: &VehicleRun) -> Vec<(String, String)> {
        let names = self.manoeuvres.iter().map(|m| m.name.as_str());
        let columns = manoeuvre_columns(case, names, &NAMED_FROM);
        let mut cells = Vec::new();
        for (manoeuvre, column) in self.manoeuvres.iter().zip(&columns) {
            let Some(summary) = run.summary.manoeuvre.get(&manoeuvre.name) else {
                continue;
            };
            let json = serde_json::to_value(summary).unwrap_or_default();
            let mut scalars = |prefix: String, value: &serde_json::Value| {
                for (key, value) in value.as_object().into_iter().flatten() {
                    if let Some(text) = scalar_text(value) {
                        cells.push((format!("{prefix}.{key}"), text));
                    }
                }
            };
            match (&json["trial"], json["autopilot"].as_array()) {
                (trial, _) if trial.is_object() => scalars(column.clone(), trial),
                (_, Some(autopilots)) => {
                    for autopilot in autopilots {
                        let what = autopilot["what"].as_str().unwrap_or("autopilot");
                        scalars(format!("{column}.{what}"), autopilot);
                    }
                }
                _ => {
                    let steps = json["steps"].as_array().into_iter().flatten();
                    for (index, step) in steps.enumerate() {
                        scalars(format!("{column}.step_{index}"), step);
                    }
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

/// Whether a run ended because a signal asked it to.
fn is_stopped(error: &anyhow::Error) -> bool {
    error
        .downcast_ref::<VehicleError>()
        .is_some_and(|e| matches!(e, VehicleError::Stopped { .. }))
}

/// Runs `manoeuvre` from its trim with the scene's method, its rows streamed to `folder/trajectory.csv`
/// (t, [`ROW`], the kinetic energy of the body and the fluid), then refined, and draws it.
fn run_manoeuvre(
    scene: &VehicleScene,
    manoeuvre: &VehicleManoeuvre,
    folder: &Path,
) -> Result<Outcome> {
    let path = folder.join("trajectory.csv");
    let names = ROW.map(str::to_owned);
    let expected_rows = (manoeuvre.duration / scene.every) as usize + 1;
    let mut writer = TrajectoryWriter::create(&path, &names, false, expected_rows)
        .with_context(|| format!("creating {}", path.display()))?;
    let model = &scene.model;
    let done = run(
        model,
        &scene.fins,
        manoeuvre,
        manoeuvre.trim.state,
        (&scene.stepper, scene.every),
        |sample| {
            let row = Row {
                t: sample.t,
                state: &sample.row(),
                kinetic_energy: model.kinetic_energy(&sample.state),
                potential_energy: None,
            };
            writer.row(&row) && signal_received().is_none()
        },
    );
    if let Some(error) = writer.take_error() {
        return Err(anyhow::Error::new(error).context(format!("writing {}", path.display())));
    }
    let done = done?;
    let columns = writer
        .finish()
        .with_context(|| format!("writing {}", path.display()))?;
    let refined = run(
        model,
        &scene.fins,
        manoeuvre,
        manoeuvre.trim.state,
        (&scene.stepper.refined(), scene.every),
        |_| signal_received().is_none(),
    )?;
    let steps = StepFigures::of(&done);
    let autopilot = SetpointFigures::of(&done);
    let trial = trial_figures(&done, manoeuvre);
    let trial_difference = match (&trial, trial_figures(&refined, manoeuvre)) {
        (Some(a), Some(b)) => largest_trial_difference(a, &b),
        _ => 0.0,
    };
    let refined_difference = largest_difference(&steps, &StepFigures::of(&refined))
        .max(largest_setpoint_difference(
            &autopilot,
            &SetpointFigures::of(&refined),
        ))
        .max(trial_difference);
    let summary = ManoeuvreSummary {
        steps: steps.clone(),
        autopilot,
        trial,
        refined_difference,
        refinement: scene.stepper.refinement(),
        steps_taken: done.steps,
    };
    let marks = match &summary.trial {
        Some(TrialFigures::TurningCircle(figures)) => figures.marks.as_slice(),
        _ => &[],
    };
    write_plots(folder, (scene, manoeuvre), &columns, marks)?;
    Ok(Outcome { steps, summary })
}

/// The track in plan with `marks` (what, [x, y]), the profile, the attitude and the fins, and
/// the run in 3-D.
fn write_plots(
    folder: &Path,
    (scene, manoeuvre): (&VehicleScene, &VehicleManoeuvre),
    columns: &Columns,
    marks: &[(String, [f64; 2])],
) -> Result<()> {
    // The columns in ROW's order.
    let column = |name: &str| -> &[f64] {
        let index = ROW.iter().position(|r| *r == name).unwrap_or(0);
        &columns.state[index]
    };
    let title = format!("{} — {}", scene.title, manoeuvre.name);
    let plot = VehiclePlot {
        title: &title,
        time: &columns.time,
        position: ["x", "y", "z"].map(column),
        attitude: ["phi", "theta", "psi"].map(column),
        fins: ["dr", "ds", "dr_command", "ds_command"].map(column),
        marks: &(marks.iter())
            .map(|(label, [x, y])| Mark {
                label: label.clone(),
                point: (*y, *x),
            })
            .collect::<Vec<_>>(),
    };
    write_vehicle_plots(folder, &plot)?;
    super::view::write_vehicle(folder, &title, &scene.table, columns)?;
    Ok(())
}

fn print_report(scene: &VehicleScene, summary: &VehicleSummary, outcomes: &[Outcome], out: &Path) {
    println!("{}", printable(&scene.title));
    let cruise = &summary.cruise;
    let closed = |x: Option<f64>, unit: &str| {
        x.map_or_else(String::new, |x| {
            format!(" (closed form {}{unit})", fixed(x, 4))
        })
    };
    println!(
        "  cruise: u = {} m/s{}, roll trim φ = {}°{}",
        fixed(cruise.speed_m_s, 4),
        closed(cruise.speed_closed_form_m_s, " m/s"),
        fixed(cruise.roll_deg, 4),
        closed(cruise.roll_closed_form_deg, "°")
    );
    if let Some(steps) = cruise.newton_steps {
        println!(
            "    trimmed in every state but the position and the heading ({}): θ = {}°, v = \
             {} m/s, w = {} m/s, ψ̇ = {} °/s, ż = {} m/s",
            counted(steps, "Newton step", "Newton steps"),
            fixed(cruise.pitch_deg, 3),
            fixed(cruise.sway_m_s, 4),
            fixed(cruise.heave_m_s, 4),
            fixed(cruise.heading_rate_deg_s, 4),
            fixed(cruise.depth_rate_m_s, 4)
        );
    }
    for (manoeuvre, outcome) in scene.manoeuvres.iter().zip(outcomes) {
        println!(
            "  {}: (refined: {:.1e})",
            manoeuvre.name, outcome.summary.refined_difference
        );
        println!(
            "    {:>6} {:>6} {:>7} {:>7} {:>10} {:>8} {:>8} {:>8} {:>8}",
            "from s", "to s", "δr °", "δs °", "r °/s", "U m/s", "φ °", "θ °", "z m"
        );
        for s in &outcome.steps {
            println!(
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
            );
        }
        print_autopilot(&outcome.summary.autopilot);
        if let Some(trial) = &outcome.summary.trial {
            print_trial(trial);
        }
    }
    if !scene.model.folded().is_empty() {
        println!("  the folded table against its added mass:");
        for line in format_folded(scene.model.folded()).lines() {
            println!("    {line}");
        }
    }
    println!("  written to {}", eom_cli::shell_path(out));
}

/// How the autopilots answered each change of what they hold.
fn print_autopilot(figures: &[SetpointFigures]) {
    if figures.is_empty() {
        return;
    }
    println!(
        "    {:<8} {:>6} {:>9} {:>9} {:>10} {:>12} {:>12}",
        "holds", "at s", "from", "to", "overshoot", "settles in s", "steady error"
    );
    for f in figures {
        let unit = if f.what == "heading" { "°" } else { " m" };
        let settles = f
            .settling_time_s
            .map_or_else(|| "not settled".to_owned(), |t| fixed(t, 1));
        println!(
            "    {:<8} {:>6} {:>8}{unit} {:>8}{unit} {:>9}{unit} {settles:>12} {:>11}{unit}",
            f.what,
            fixed(f.at_s, 1),
            fixed(f.from, 2),
            fixed(f.to, 2),
            fixed(f.overshoot, 3),
            fixed(f.steady_error, 4)
        );
    }
}

/// A trial's figures.
fn print_trial(trial: &TrialFigures) {
    let metres =
        |x: Option<f64>| x.map_or_else(|| "—".to_owned(), |x| format!("{} m", fixed(x, 2)));
    match trial {
        TrialFigures::TurningCircle(f) => {
            println!(
                "    turning circle at {}°: advance {}, transfer {}, tactical diameter {}, \
                 steady diameter {}",
                Short(f.rudder_deg),
                metres(f.advance_m),
                metres(f.transfer_m),
                metres(f.tactical_diameter_m),
                metres(f.steady_diameter_m)
            );
            println!(
                "      at the end: U = {} m/s, ψ̇ = {} °/s, φ = {}°, θ = {}°, depth change {} m",
                fixed(f.speed_m_s, 4),
                fixed(f.heading_rate_deg_s, 4),
                fixed(f.roll_deg, 3),
                fixed(f.pitch_deg, 3),
                fixed(f.depth_change_m, 3)
            );
            if let Some(why) = &f.not_steady_because {
                println!("      no steady figures: {why}");
            }
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
                Some(why) => println!("{label} no figures: {why}"),
                None => println!(
                    "{label} overshoots {} °, switches at {} s",
                    list(&f.overshoots_deg),
                    list(&f.switches_s)
                ),
            }
        }
    }
}
