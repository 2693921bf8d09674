//! Ship scenes: `eom run SCENE` for a scene with `[hydrodynamics]`, and `eom linear SCENE`.
//!
//! `eom run` runs each `[[manoeuvre]]` from the same approach into its own folder
//! (`trajectory.csv`, `track.svg`, `heading.svg`, `view.html`) and writes `summary.json` beside them: the
//! model that ran, the linear model, each manoeuvre's figures under `"manoeuvre"` with how
//! much each moves when the run is refined (half the step, or tolerances a hundred times
//! tighter), and the IMO criteria under `"manoeuvre"."imo"` (the types of
//! `eom::kinds::ship::summary`).
//! Every file is written whole to a temporary name and renamed. Ctrl-C (or SIGTERM) ends the
//! run at its next step: the manoeuvres finished before it keep their folders, summary.json
//! says `"interrupted": true` and holds their figures, and the exit code is 128 + the signal.

use super::run::NUMBER_BYTES;
use super::run::{Interrupted, signal_received};
use super::sweep::{SweptCase, manoeuvre_columns};
use anyhow::{Context, Result};
use eom::Model;
use eom::kinds::ship::Side;
use eom::kinds::ship::imo::Trial;
use eom::kinds::ship::imo::{Criterion, criteria, possible};
use eom::kinds::ship::linear::{LinearModel, Nomoto, linearise, linearise_ship};
use eom::kinds::ship::manoeuvre::ManoeuvreKind;
use eom::kinds::ship::manoeuvre::{Figures, ROW, run, trajectory_columns};
use eom::kinds::ship::scene::NAMED_FROM;
use eom::kinds::ship::side::{deciding_figure, worse};
use eom::kinds::ship::spiral::{Branch, Loop, SpiralCurve, SpiralPoint, Verdict};
use eom::kinds::ship::steady::SteadyTurns;
use eom::kinds::ship::summary::{
    CriterionSummary, LinearSummary, ManoeuvreSummary, Manoeuvres, ModelSummary, ShipSummary,
    nomoto_difference,
};
use eom::kinds::ship::{Manoeuvre, ShipError, ShipModel, ShipScene};
use eom::output::summary::write_atomically;
use eom::output::text::printable;
use eom::output::trajectory::{Columns, TrajectoryWriter};
use eom::run::{Row, Sink};
use eom::scene::reference::{SceneFamily, keys_of};
use eom::scene::sweep::TableCase;
use eom::{Short, fixed};
use eom_cli::plots::Mark;
use eom_cli::plots::curves::{Curve, Curves, write_curves};
use eom_cli::plots::ship::{Hull, ManoeuvrePlot, write_manoeuvre_plots};

use std::path::Path;
use std::time::Instant;

/// Bytes per row of a ship's trajectory: ten numbers.
const SHIP_ROW_BYTES: f64 = 10.0 * NUMBER_BYTES;

/// A ship sweep's plot over a rudder angle, beside its table.
pub const SWEEP_PLOT: &str = "rudder_sweep.svg";

/// The figures [`write_sweep_plot`] draws against the rudder angle, with their names.
const SWEPT_FIGURES: [(&str, &str); 2] = [
    ("tactical_diameter_m", "tactical diameter"),
    ("steady_turning_radius_m", "steady turning radius"),
];

/// Whether a column of a sweep's table is a swept key (a key path of the scene: a key of an
/// entry of an array, `manoeuvre[0].rudder_deg`, or a key of one of its tables), not a figure
/// (`manoeuvre[0].tactical_diameter_m`, a manoeuvre's figure named by its position).
fn is_key_path(column: &str) -> bool {
    let tables = [
        "model.",
        "body.",
        "hydrodynamics.",
        "propulsion.",
        "rudder.",
        "integrator.",
        "output.",
    ];
    if let Some((array, rest)) = column.split_once('[') {
        // `manoeuvre[0].rudder_deg` is the reference's `manoeuvre[].rudder_deg`.
        let key = rest
            .split_once(']')
            .map(|(_, key)| format!("{array}[]{key}"));
        return key.is_some_and(|key| keys_of(SceneFamily::Ship).any(|k| k.path == key));
    }
    column == "title" || tables.iter().any(|t| column.starts_with(t))
}

/// `rudder_sweep.svg` in `dir`, from a ship sweep's table (`sweep.csv`'s text), when the sweep
/// varies one key and that key is a rudder angle (`….rudder_deg`): the tactical diameter and
/// the steady turning radius of each turning circle against it, each side's where a turn ran
/// to both. Draws nothing for any other sweep. The table alone decides, so that a whole run
/// and the merge of its shards draw the same plot.
pub fn write_sweep_plot(dir: &Path, table: &str) -> Result<()> {
    let mut reader = csv::Reader::from_reader(table.as_bytes());
    let Ok(header) = reader.headers().cloned() else {
        return Ok(());
    };
    let swept: Vec<&str> = header
        .iter()
        .skip(1)
        .take_while(|c| is_key_path(c))
        .collect();
    let [rudder] = swept.as_slice() else {
        return Ok(());
    };
    if !rudder.ends_with("rudder_deg") {
        return Ok(());
    }
    let rows: Vec<csv::StringRecord> = reader.records().filter_map(Result::ok).collect();
    let number = |row: &csv::StringRecord, i: usize| row.get(i)?.parse::<f64>().ok();
    let mut lines: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    for (i, column) in header.iter().enumerate() {
        let Some((key, what)) = SWEPT_FIGURES
            .iter()
            .find(|(k, _)| column.ends_with(&format!(".{k}")))
        else {
            continue;
        };
        let manoeuvre = &column[..column.len() - key.len() - 1];
        // A turn run to both sides: its sides' columns, not the worse side's.
        let sided = ["port", "starboard"].iter().any(|side| {
            header
                .iter()
                .any(|c| c == format!("{manoeuvre}.{side}.{key}"))
        });
        if sided {
            continue;
        }
        let mut points: Vec<(f64, f64)> = rows
            .iter()
            .filter_map(|row| Some((number(row, 1)?, number(row, i)?)))
            .collect();
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        lines.push((format!("{} {what}", manoeuvre.replace('.', " ")), points));
    }
    if lines.is_empty() {
        return Ok(());
    }
    let curves: Vec<Curve> = (lines.iter())
        .map(|(name, points)| Curve { name, points })
        .collect();
    let caption = format!("Turning circles against the rudder angle ({rudder})");
    let plot = Curves {
        caption: &caption,
        x_desc: "rudder angle [deg]",
        y_desc: "tactical diameter, steady turning radius [m]",
        curves: &curves,
    };
    write_curves(dir, SWEEP_PLOT, &plot)?;
    Ok(())
}

/// A spiral's plot, in its manoeuvre's folder.
pub const SPIRAL_PLOT: &str = "spiral.svg";

/// A manoeuvre run with the scene's method, and the same refined (`Stepper::refined`: half
/// the step, or tolerances a hundred times tighter).
struct Outcome {
    /// The rows kept for the plots ([`ROW`]'s order).
    columns: Columns,
    figures: Figures,
    refined: Figures,
    steps: u64,
}

/// A manoeuvre's runs: one per side (`turning_circle_35/port/`, `…/starboard/`), or one of no
/// side or of the one side the scene names (`turning_circle_35/`).
type Runs = Vec<(Option<Side>, Outcome)>;

/// The side of a manoeuvre run to both that its summary, table and report show first: the
/// worse by the figure [`deciding_figure`] names.
fn worse_side(manoeuvre: &Manoeuvre, runs: &Runs) -> Option<Side> {
    let [(Some(Side::Port), port), (Some(Side::Starboard), starboard)] = runs.as_slice() else {
        return None;
    };
    let turning = matches!(manoeuvre.kind, ManoeuvreKind::TurningCircle { .. });
    let key = deciding_figure(turning);
    Some(worse(port.figures.get(key), starboard.figures.get(key)))
}

/// The outcome a manoeuvre's summary shows first: the worse side's, or its one run's.
fn shown<'a>(manoeuvre: &Manoeuvre, runs: &'a Runs) -> Option<&'a Outcome> {
    match worse_side(manoeuvre, runs) {
        Some(side) => runs.iter().find(|(s, _)| *s == Some(side)).map(|(_, o)| o),
        None => runs.first().map(|(_, o)| o),
    }
}

/// A summary as pretty JSON with the keys of every object sorted (through
/// `serde_json::Value`, whose objects are sorted maps), as a ship's summary is written.
fn sorted_json(summary: &impl serde::Serialize) -> Result<Vec<u8>> {
    Ok(serde_json::to_vec_pretty(&serde_json::to_value(summary)?)?)
}

/// Runs a ship scene, read and checked, into `out`, a folder already known to be writable,
/// and prints its figures and verdicts.
pub fn execute(scene: &ShipScene, name: &str, out: &Path) -> Result<()> {
    let run = run_into(scene, name, out)?;
    print_report(scene, &run.outcomes, &run.judged, out);
    match run.interrupted {
        Some(signal) => Err(Interrupted {
            signal,
            kept: format!(
                "{} finished before it, and summary.json, in {}",
                match run.outcomes.len() {
                    1 => "the 1 manoeuvre".to_owned(),
                    n => format!("the {n} manoeuvres"),
                },
                out.display()
            ),
        }
        .into()),
        None => Ok(()),
    }
}

/// What a ship scene's run gave: each manoeuvre's outcome, the IMO criteria judged on them,
/// and the signal that ended it early, if one did.
pub struct ShipRun {
    outcomes: Vec<Runs>,
    judged: Vec<Criterion>,
    interrupted: Option<i32>,
}

/// Runs every manoeuvre of `scene` into its folder under `out` and writes summary.json.
fn run_into(scene: &ShipScene, name: &str, out: &Path) -> Result<ShipRun> {
    let started = Instant::now();
    let model = ShipModel::new(&scene.table)?;
    let linear = LinearModel::closed_form(&scene.table);
    let mut outcomes = Vec::new();
    let mut interrupted = None;
    'manoeuvres: for manoeuvre in &scene.manoeuvres {
        let mut runs = Runs::new();
        let sided = manoeuvre.runs();
        for (side, one) in &sided {
            let mut folder = out.join(&manoeuvre.name);
            if sided.len() > 1 {
                folder = folder.join(side.map_or("", Side::name));
            }
            std::fs::create_dir_all(&folder)
                .with_context(|| format!("creating {}", folder.display()))?;
            let outcome = match run_manoeuvre(scene, &model, one, &folder) {
                Err(error) if is_stopped(&error) => {
                    interrupted = signal_received();
                    // A side finished before the signal is kept, as a manoeuvre is.
                    if !runs.is_empty() {
                        outcomes.push(runs);
                    }
                    break 'manoeuvres;
                }
                outcome => outcome.with_context(|| format!("manoeuvre {}", manoeuvre.name))?,
            };
            let name = match side {
                Some(side) if sided.len() > 1 => format!("{} ({})", manoeuvre.name, side.name()),
                _ => manoeuvre.name.clone(),
            };
            write_plots(&folder, scene, &name, one, &outcome)?;
            runs.push((*side, outcome));
        }
        outcomes.push(runs);
    }
    let trials: Vec<Trial> = (scene.manoeuvres.iter().zip(&outcomes))
        .map(|(m, runs)| (m, runs.iter().map(|(s, o)| (*s, &o.figures)).collect()))
        .collect();
    let judged = criteria(scene, &trials);
    let runs = (scene.manoeuvres.iter().zip(&outcomes))
        .filter(|(_, runs)| !runs.is_empty())
        .map(|(manoeuvre, runs)| {
            let summary_of = |(side, outcome): &(Option<Side>, Outcome)| {
                let figures = (&outcome.figures, &outcome.refined);
                let mut summary =
                    ManoeuvreSummary::new(manoeuvre, &scene.stepper, figures, outcome.steps);
                summary.side = side.map(Side::name).or(summary.side);
                summary
            };
            let summary = match (worse_side(manoeuvre, runs), runs.as_slice()) {
                (Some(side), [port, starboard]) => {
                    ManoeuvreSummary::both(summary_of(port), summary_of(starboard), side)
                }
                (_, runs) => summary_of(&runs[0]),
            };
            (manoeuvre.name.clone(), summary)
        })
        .collect();
    let summary = ShipSummary {
        scene: name.to_owned(),
        title: scene.title.clone(),
        model: ModelSummary::new(scene, &model),
        integrator: eom::output::summary::MethodSummary::new(&scene.stepper),
        linear: LinearSummary::new(scene, &model, &linear),
        manoeuvre: Manoeuvres {
            runs,
            imo: judged.iter().map(CriterionSummary::new).collect(),
        },
        wall_seconds: started.elapsed().as_secs_f64(),
        interrupted: interrupted.is_some(),
    };
    let bytes = sorted_json(&summary)?;
    let path = out.join("summary.json");
    write_atomically(&path, &bytes).with_context(|| format!("writing {}", path.display()))?;
    Ok(ShipRun {
        outcomes,
        judged,
        interrupted,
    })
}

impl SweptCase for ShipScene {
    type Run = ShipRun;

    fn folders(&self) -> Vec<String> {
        self.manoeuvres.iter().map(|m| m.name.clone()).collect()
    }

    fn trajectory_bytes(&self) -> f64 {
        let rows: f64 = (self.manoeuvres.iter())
            .map(|m| m.duration / self.every * m.runs().len() as f64)
            .sum();
        rows * SHIP_ROW_BYTES
    }

    fn execute(&self, name: &str, out: &Path) -> Result<()> {
        execute(self, name, out)
    }

    fn run_into(&self, name: &str, out: &Path) -> Result<ShipRun> {
        run_into(self, name, out)
    }

    fn cells(&self, case: &TableCase, run: &ShipRun) -> Vec<(String, String)> {
        sweep_cells((case, self), run)
    }
}

/// Each column of a ship sweep's table with its value in `run`, in the table's order: each
/// manoeuvre's figures (the worse side's, for one run to both), then each side's
/// (`turn.port.tactical_diameter_m`), then each IMO criterion's value, verdict and sides; a
/// manoeuvre's columns are named as [`manoeuvre_columns`] says.
fn sweep_cells((case, scene): (&TableCase, &ShipScene), run: &ShipRun) -> Vec<(String, String)> {
    let text = |value: Option<f64>| value.map_or_else(String::new, |v| v.to_string());
    let mut cells = Vec::new();
    let names = manoeuvre_columns(
        case,
        scene.manoeuvres.iter().map(|m| m.name.as_str()),
        &NAMED_FROM,
    );
    for ((manoeuvre, runs), name) in scene.manoeuvres.iter().zip(&run.outcomes).zip(&names) {
        if let Some(outcome) = shown(manoeuvre, runs) {
            for (key, value) in &outcome.figures.values {
                cells.push((format!("{name}.{key}"), text(*value)));
            }
        }
        for (side, outcome) in runs.iter().filter(|_| runs.len() > 1) {
            let side = side.map_or("", Side::name);
            for (key, value) in &outcome.figures.values {
                cells.push((format!("{name}.{side}.{key}"), text(*value)));
            }
        }
    }
    // Every criterion the scene's kinds may give, judged in this case or not, so that the
    // columns do not depend on a swept angle (a turn at 20° is not judged; at 35° it is).
    for (name, sided) in possible(scene) {
        let criterion = run.judged.iter().find(|c| c.name == name);
        let value = criterion.and_then(|c| c.value);
        let pass = criterion.and_then(Criterion::pass);
        cells.push((format!("imo.{name}"), text(value)));
        cells.push((
            format!("imo.{name}.pass"),
            pass.map_or_else(String::new, |p| p.to_string()),
        ));
        for side in Side::BOTH.iter().filter(|_| sided) {
            let value = (criterion.iter().flat_map(|c| &c.sides))
                .find(|(s, _)| s == side)
                .and_then(|(_, v)| *v);
            cells.push((format!("imo.{name}.{}", side.name()), text(value)));
        }
    }
    cells
}

/// Whether a run ended because a signal asked it to.
fn is_stopped(error: &anyhow::Error) -> bool {
    error
        .downcast_ref::<ShipError>()
        .is_some_and(|e| matches!(e, ShipError::Stopped { .. }))
}

/// Runs `manoeuvre` with the scene's method, its rows streamed to `folder/trajectory.csv` by
/// the trajectory writer every run uses (t, [`ROW`], the rigid body's kinetic energy), and
/// again refined, for how far each figure moves.
fn run_manoeuvre(
    scene: &ShipScene,
    model: &ShipModel,
    manoeuvre: &Manoeuvre,
    folder: &Path,
) -> Result<Outcome> {
    let path = folder.join("trajectory.csv");
    let names = ROW.map(str::to_owned);
    let expected_rows = (manoeuvre.duration / scene.every) as usize + 1;
    let mut writer = TrajectoryWriter::create(&path, &names, false, expected_rows)
        .with_context(|| format!("creating {}", path.display()))?;
    let settings = (&scene.stepper, scene.every);
    let done = run(
        model,
        &scene.rudder,
        manoeuvre,
        scene.start(),
        settings,
        |sample| {
            let row = Row {
                t: sample.t,
                state: &sample.row(),
                kinetic_energy: model.kinetic_energy(&sample.model_state()),
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
    let refined = (&scene.stepper.refined(), scene.every);
    let refined = run(
        model,
        &scene.rudder,
        manoeuvre,
        scene.start(),
        refined,
        |_| signal_received().is_none(),
    )?;
    Ok(Outcome {
        columns,
        figures: done.figures,
        refined: refined.figures,
        steps: done.steps,
    })
}

fn write_plots(
    folder: &Path,
    scene: &ShipScene,
    name: &str,
    manoeuvre: &Manoeuvre,
    outcome: &Outcome,
) -> Result<()> {
    let columns = &outcome.columns;
    let time = &columns.time;
    // The columns in ROW's order.
    let [north, east, psi, rudder, command] = [3, 4, 5, 6, 7].map(|k| &columns.state[k]);
    let psi0 = (time.iter().zip(psi))
        .find(|(t, _)| **t >= manoeuvre.execute)
        .map_or(0.0, |(_, psi)| *psi);
    let degrees = |column: &[f64], from: f64| -> Vec<f64> {
        column.iter().map(|x| (x - from).to_degrees()).collect()
    };
    let heading = degrees(psi, psi0);
    let rudder = degrees(rudder, 0.0);
    let command = degrees(command, 0.0);
    let marks: Vec<Mark> = outcome
        .figures
        .marks
        .iter()
        .map(|(label, [x, y])| Mark {
            label: label.clone(),
            point: (*y, *x),
        })
        .collect();
    let title = format!("{} — {name}", scene.title);
    if let Some(curve) = &outcome.figures.spiral {
        write_spiral_plot(folder, &title, curve)?;
    }
    let plot = ManoeuvrePlot {
        title: &title,
        time,
        north,
        east,
        heading_change_deg: &heading,
        heading_rad: psi,
        rudder_deg: &rudder,
        command_deg: &command,
        marks: &marks,
        // A ship scene has no key for the beam: the one view.html assumes.
        hull: Hull {
            length: scene.length,
            beam: scene.length / super::view::ASSUMED_LENGTH_OVER_BEAM,
            beam_assumed: true,
        },
    };
    write_manoeuvre_plots(folder, &plot)?;
    let labels = trajectory_columns();
    let ship = super::view::ShipColumns {
        title: &title,
        length: scene.length,
        time,
        state: labels[1..8]
            .iter()
            .cloned()
            .zip(columns.state.iter().map(Vec::as_slice))
            .collect(),
    };
    super::view::write_ship(folder, ship)?;
    Ok(())
}

/// A figure as the report prints it: three decimals (no sign on a zero), or a dash where the
/// run gave none.
fn cell(value: Option<f64>) -> String {
    value.map_or_else(|| "—".to_owned(), |v| fixed(v, 3))
}

/// A manoeuvre's figures as the report prints them: a column per side for one run to both
/// (the worse side's marked), each note with its side.
fn print_manoeuvre(manoeuvre: &Manoeuvre, runs: &Runs) {
    let worse = worse_side(manoeuvre, runs);
    match (runs.as_slice(), worse) {
        ([(_, port), (_, starboard)], Some(worse)) => {
            let mark = |side: Side| if side == worse { " (worse)" } else { "" };
            println!(
                "  {}:{:>31}{:>22}",
                manoeuvre.name,
                format!("port{}", mark(Side::Port)),
                format!("starboard{}", mark(Side::Starboard))
            );
            for ((key, p), (_, s)) in port.figures.values.iter().zip(&starboard.figures.values) {
                println!("    {key:<28} {:>12} {:>21}", cell(*p), cell(*s));
            }
        }
        _ => {
            let side = runs.first().and_then(|(s, _)| *s);
            match side {
                Some(side) => println!("  {} ({}):", manoeuvre.name, side.name()),
                None => println!("  {}:", manoeuvre.name),
            }
            for (_, outcome) in runs {
                for (key, value) in &outcome.figures.values {
                    println!("    {key:<28} {:>12}", cell(*value));
                }
            }
        }
    }
    for (side, outcome) in runs {
        if let Some(curve) = &outcome.figures.spiral {
            print_spiral(curve);
        }
        let side = match side {
            Some(side) if runs.len() > 1 => format!(" ({})", side.name()),
            _ => String::new(),
        };
        for note in &outcome.figures.notes {
            println!("    note{side}: {note}");
        }
    }
}

/// A spiral's curve: its verdict, one line per angle (the two passes side by side for a
/// direct spiral; a point that did not settle marked `*`), then the loop from the settled
/// points beside the steady-turn curve's folds.
fn print_spiral(curve: &SpiralCurve) {
    let verdict = curve.verdict();
    println!(
        "    course stable by the spiral        {}",
        match verdict {
            Verdict::NoLoop => "yes (no loop)",
            Verdict::Loop(_) => "NO (a loop)",
            Verdict::Undetermined(_) => "undetermined (see the note)",
        }
    );
    let settle = curve.settle;
    let resolution = match settle.resolution().is_finite() {
        true => format!(
            "a settled r within ε = {}°/s of the steady one at T₁ = {} s",
            Short(settle.resolution().to_degrees()),
            Short(settle.time_constant)
        ),
        false => "no bound on a settled r's distance from the steady one (the linear model has \
                  a mode that neither grows nor decays)"
            .to_owned(),
    };
    println!(
        "    settled: r within {}°/s over {} s (held at most {} s): {resolution}",
        Short(settle.tolerance.to_degrees()),
        Short(settle.window),
        Short(settle.max_hold),
    );
    let mark = |p: &SpiralPoint, text: String| match p.settled {
        true => format!("{text} "),
        false => format!("{text}*"),
    };
    let reverse = curve.points.iter().any(|p| p.branch == Branch::Reverse);
    if reverse {
        println!(
            "    {:>14} {:>14} {:>15}",
            "r_c [°/s]", "r [°/s]", "mean δ [°]"
        );
        for p in &curve.points {
            let target = p.target.map_or(f64::NAN, f64::to_degrees);
            let (r, d) = (p.yaw_rate.to_degrees(), p.rudder.to_degrees());
            println!(
                "    {:>14} {:>14} {:>15}",
                fixed(target, 4),
                fixed(r, 4),
                mark(p, fixed(d, 3))
            );
        }
    } else {
        println!(
            "    {:>10} {:>15} {:>15}",
            "δ [°]", "r first [°/s]", "r back [°/s]"
        );
        for first in curve.points.iter().filter(|p| p.branch == Branch::First) {
            let back = (curve.points.iter())
                .find(|p| p.branch == Branch::Back && p.rudder == first.rudder)
                .map(|p| mark(p, fixed(p.yaw_rate.to_degrees(), 4)));
            println!(
                "    {:>10} {:>15} {:>15}",
                fixed(first.rudder.to_degrees(), 2),
                mark(first, fixed(first.yaw_rate.to_degrees(), 4)),
                back.unwrap_or_else(|| "— ".to_owned())
            );
        }
    }
    if curve.points.iter().any(|p| !p.settled) {
        println!("    * not settled: no figure rests on it");
    }
    if let Verdict::Loop(found) = verdict {
        print_loop(&found);
    }
    match &curve.steady {
        Ok(steady) => print_steady(steady),
        Err(why) => println!("    steady turns: not traced ({why})"),
    }
}

/// The loop the settled points show: its ends, width and bounds, and the spiral's step.
fn print_loop(found: &Loop) {
    let degrees = |x: f64| fixed(x.to_degrees(), 3);
    let most = found
        .most_width
        .map_or_else(String::new, |w| format!(", at most {}°", degrees(w)));
    let step = found
        .step
        .map_or_else(String::new, |s| format!(", rudder step {}°", degrees(s)));
    println!(
        "    loop from the settled points: δ from {}° to {}°, {}° wide (at least {}°{most}){step}",
        degrees(found.ends.0),
        degrees(found.ends.1),
        degrees(found.width),
        degrees(found.least_width()),
    );
}

/// The steady-turn curve's folds and the loop between them, beside the spiral's.
fn print_steady(steady: &SteadyTurns) {
    let (low, high) = steady.range;
    let range = format!(
        "δ from {}° to {}°",
        fixed(low.to_degrees(), 2),
        fixed(high.to_degrees(), 2)
    );
    let mut folds = steady.folds.clone();
    folds.sort_by(|a, b| a.rudder.total_cmp(&b.rudder));
    let folds: Vec<String> = (folds.iter())
        .map(|f| {
            format!(
                "δ = {}° (r = {}°/s)",
                fixed(f.rudder.to_degrees(), 4),
                fixed(f.r.to_degrees(), 4)
            )
        })
        .collect();
    let what = match (steady.folds.len(), steady.loop_width()) {
        (0, Some(_)) => "no fold: one steady turn at each δ".to_owned(),
        (0, None) => "no fold where it was traced".to_owned(),
        (_, Some(width)) => format!(
            "folds at {}: the loop {}° wide",
            folds.join(" and "),
            fixed(width.to_degrees(), 4)
        ),
        (_, None) => format!("one fold, at {}: the loop runs past the range", folds[0]),
    };
    println!(
        "    steady turns ({} points, by continuation over {range}): {what}",
        steady.turns.len()
    );
    for (end, why) in ["low", "high"].iter().zip(&steady.ends) {
        if !steady.spans_range() {
            println!("      the curve's {end} end: {why}");
        }
    }
}

/// `spiral.svg`: r against δ, each pass of a direct spiral a curve, a reverse spiral's one
/// in the order of r.
fn write_spiral_plot(folder: &Path, title: &str, curve: &SpiralCurve) -> Result<()> {
    let pass = |branch: Branch| -> Vec<(f64, f64)> {
        let mut points: Vec<(f64, f64)> = (curve.points.iter())
            .filter(|p| p.branch == branch)
            .map(|p| (p.rudder.to_degrees(), p.yaw_rate.to_degrees()))
            .collect();
        if branch == Branch::Reverse {
            points.sort_by(|a, b| a.1.total_cmp(&b.1));
        }
        points
    };
    let (first, back, reverse) = (
        pass(Branch::First),
        pass(Branch::Back),
        pass(Branch::Reverse),
    );
    let mut curves = Vec::new();
    if !first.is_empty() {
        curves.push(Curve {
            name: "first pass",
            points: &first,
        });
    }
    if !back.is_empty() {
        curves.push(Curve {
            name: "back",
            points: &back,
        });
    }
    if !reverse.is_empty() {
        curves.push(Curve {
            name: "reverse spiral",
            points: &reverse,
        });
    }
    let steady: Vec<(f64, f64)> = (curve.steady.iter())
        .flat_map(|s| &s.turns)
        .map(|t| (t.rudder.to_degrees(), t.r.to_degrees()))
        .collect();
    if !steady.is_empty() {
        curves.push(Curve {
            name: "steady turns",
            points: &steady,
        });
    }
    let verdict = match curve.verdict() {
        Verdict::NoLoop => "no loop (course-stable)".to_owned(),
        Verdict::Undetermined(_) => "loop undetermined (see the notes)".to_owned(),
        Verdict::Loop(l) => format!(
            "loop {:.2}° wide{}",
            l.width.to_degrees(),
            l.height
                .map_or(String::new(), |h| format!(" × {:.3}°/s", h.to_degrees()))
        ),
    };
    let caption = format!("{title}: {verdict}");
    let plot = Curves {
        caption: &caption,
        x_desc: "rudder δ [deg]",
        y_desc: "yaw rate r [deg/s]",
        curves: &curves,
    };
    write_curves(folder, SPIRAL_PLOT, &plot)?;
    Ok(())
}

fn print_report(scene: &ShipScene, outcomes: &[Runs], judged: &[Criterion], out: &Path) {
    println!("{}", printable(&scene.title));
    for (manoeuvre, runs) in scene.manoeuvres.iter().zip(outcomes) {
        print_manoeuvre(manoeuvre, runs);
    }
    if !judged.is_empty() {
        println!(
            "  IMO MSC.137(76), L = {} m, L/V = {:.2} s:",
            scene.length,
            scene.length / scene.table.design_speed
        );
        for c in judged {
            let sides: Vec<String> = (c.sides.iter())
                .map(|(side, v)| {
                    format!("{} {}", side.name(), v.map_or("—".into(), |v| fixed(v, 2)))
                })
                .collect();
            let sides = match sides.is_empty() {
                true => String::new(),
                false => format!(" ({})", sides.join(", ")),
            };
            match (c.value, c.pass()) {
                (Some(value), Some(pass)) => println!(
                    "    {:<24} {:>10} {:<3} ≤ {:>9.2}  {}  on {}{sides}",
                    c.name,
                    fixed(value, 2),
                    c.unit,
                    c.limit,
                    if pass { "pass" } else { "FAIL" },
                    c.manoeuvre
                ),
                _ => match &c.not_judged_because {
                    Some(why) => println!("    {:<24} not judged: {why}", c.name),
                    None => println!(
                        "    {:<24} not judged: {} did not give the figure (see its notes)\
                         {sides}",
                        c.name, c.manoeuvre
                    ),
                },
            }
        }
    }
    println!("  written to {}", eom_cli::shell_path(out));
}

/// Runs `eom linear` on a ship scene: Nomoto's models about the straight course.
pub fn linear(args: &super::linear::Args, scene: &ShipScene) -> Result<()> {
    let model = ShipModel::new(&scene.table)?;
    let linear = LinearModel::closed_form(&scene.table);
    let linearised = linearise_ship(scene, &model)?;
    let space = super::linear::state_space(args, &scene.title, &linearised);
    let mut text = super::linear::text_report(&scene.title, &linearised);
    text.push_str(&nomoto_report(scene, &model, &linear));
    // Every scene's report, with the ship's Nomoto block beside it.
    let mut report = super::linear::report(&space, &linearised)?;
    let nomoto = serde_json::to_value(LinearSummary::new(scene, &model, &linear))?;
    if let (Some(report), serde_json::Value::Object(nomoto)) = (report.as_object_mut(), nomoto) {
        report.extend(nomoto);
    }
    super::linear::write_out(args, (&space, &linearised), &text, &report)?;
    super::linear::show(args, &text, &report)
}

/// Nomoto's models, the course stability and the pivot point, as text.
fn nomoto_report(scene: &ShipScene, model: &ShipModel, linear: &LinearModel) -> String {
    use super::linear::line;
    let mut text = String::new();
    let speed = scene.table.design_speed;
    line(
        &mut text,
        format!(
            "{}: the linear model about the straight course at U₀ = {speed} m/s",
            printable(&scene.title)
        ),
    );
    let show = |text: &mut String, what: &str, nomoto: Option<Nomoto>| {
        let said = match nomoto {
            Some(n) => format!(
                "  {what:<34} K = {:.6e} 1/s, T₁ = {:.6} s, T₂ = {:.6} s, T₃ = {:.6} s, T = {:.6} s",
                n.k, n.t1, n.t2, n.t3, n.t
            ),
            None => format!("  {what:<34} T₁ and T₂ are not real: no Nomoto form"),
        };
        line(text, said);
    };
    show(&mut text, "Nomoto, closed form:", linear.nomoto());
    let (a, b) = linearise(model, speed);
    show(
        &mut text,
        "Nomoto, linearised model:",
        Nomoto::from_state_space(a, b),
    );
    if let Some(d) = nomoto_difference(linear.nomoto(), Nomoto::from_state_space(a, b)) {
        line(
            &mut text,
            format!("  {:<34} {d:.1e}", "largest relative difference:"),
        );
    }
    let verdict = if linear.course_stable() {
        "stable"
    } else {
        "UNSTABLE"
    };
    let stability = match linear.stability_index() {
        Some(c) => format!(
            "  course stability: C′ = Y′v(N′r − m′x′G) − (Y′r − m′)N′v = {c:.6e}: {verdict}"
        ),
        None => format!(
            "  course stability: det N = {:.6e} (SI): {verdict}",
            linear.det_damping()
        ),
    };
    line(&mut text, stability);
    let pivot = linear.pivot_point();
    line(
        &mut text,
        format!(
            "  pivot point: x_p = {pivot:.2} m ahead of midship ({:.3} L)",
            pivot / scene.length
        ),
    );
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_zero_is_printed_without_a_sign() {
        assert_eq!(fixed(-0.00001, 4), "0.0000");
        assert_eq!(fixed(-0.0, 3), "0.000");
        assert_eq!(fixed(-0.0001, 4), "-0.0001");
        assert_eq!(fixed(12.3456, 2), "12.35");
        assert_eq!(cell(Some(-0.0002)), "0.000");
    }

    /// A sweep's key columns are the scene's keys; a manoeuvre's figure named by its
    /// position is not one.
    #[test]
    fn a_figure_named_by_position_is_not_a_swept_key() {
        assert!(is_key_path("manoeuvre[0].rudder_deg"));
        assert!(is_key_path("manoeuvre[12].heading_deg"));
        assert!(is_key_path("hydrodynamics.coefficients.Yv"));
        assert!(!is_key_path("manoeuvre[0].tactical_diameter_m"));
        assert!(!is_key_path("manoeuvre[0].port.advance_90_m"));
        assert!(!is_key_path("imo.advance"));
    }
}
