//! Ship scenes: `eom run SCENE` for a scene with `[hydrodynamics]`, and `eom linear SCENE`.
//!
//! `eom run` runs each `[[manoeuvre]]` from the same approach into its own folder
//! (`trajectory.csv`, `track.svg`, `heading.svg`, `view.html`) and writes `summary.json` beside them: the
//! model that ran, the linear model, each manoeuvre's figures under `"manoeuvre"` with how
//! much each moves when the run is refined (half the step, or tolerances a hundred times
//! tighter), and the IMO criteria under `"manoeuvre"."imo"` (the types of
//! `eom::ship::summary`).
//! Every file is written whole to a temporary name and renamed. Ctrl-C (or SIGTERM) ends the
//! run at its next step: the manoeuvres finished before it keep their folders, summary.json
//! says `"interrupted": true` and holds their figures, and the exit code is 128 + the signal.

use super::run::{Interrupted, signal_received};
use anyhow::{Context, Result};
use eom::Model;
use eom::output::summary::write_atomically;
use eom::output::text::printable;
use eom::output::trajectory::{Columns, TrajectoryWriter};
use eom::run::{Row, Sink};
use eom::scene::sweep::TableCase;
use eom::ship::imo::{Criterion, criteria};
use eom::ship::linear::{LinearModel, Nomoto, linearise};
use eom::ship::manoeuvre::{Figures, ROW, run, trajectory_columns};
use eom::ship::summary::{
    CriterionSummary, IntegratorSummary, LinearSummary, ManoeuvreSummary, Manoeuvres, ModelSummary,
    ShipSummary, nomoto_difference,
};
use eom::ship::{Manoeuvre, ShipError, ShipModel, ShipScene};
use eom_cli::plots::Mark;
use eom_cli::plots::ship::{Hull, ManoeuvrePlot, write_manoeuvre_plots};
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// A manoeuvre run with the scene's method, and the same refined (`Stepper::refined`: half
/// the step, or tolerances a hundred times tighter).
struct Outcome {
    /// The rows kept for the plots ([`ROW`]'s order).
    columns: Columns,
    figures: Figures,
    refined: Figures,
    steps: u64,
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
                "the {} manoeuvres finished before it, and summary.json, in {}",
                run.outcomes.len(),
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
    outcomes: Vec<Outcome>,
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
    for manoeuvre in &scene.manoeuvres {
        let folder = out.join(&manoeuvre.name);
        std::fs::create_dir_all(&folder)
            .with_context(|| format!("creating {}", folder.display()))?;
        let outcome = match run_manoeuvre(scene, &model, manoeuvre, &folder) {
            Err(error) if is_stopped(&error) => {
                interrupted = signal_received();
                break;
            }
            outcome => outcome.with_context(|| format!("manoeuvre {}", manoeuvre.name))?,
        };
        write_plots(&folder, scene, manoeuvre, &outcome)?;
        outcomes.push(outcome);
    }
    let runs: Vec<(&Manoeuvre, &Figures)> = scene
        .manoeuvres
        .iter()
        .zip(&outcomes)
        .map(|(m, o)| (m, &o.figures))
        .collect();
    let judged = criteria(scene.length, scene.table.design_speed, &runs);
    let runs = (scene.manoeuvres.iter().zip(&outcomes))
        .map(|(manoeuvre, outcome)| {
            let figures = (&outcome.figures, &outcome.refined);
            let summary = ManoeuvreSummary::new(manoeuvre, &scene.stepper, figures, outcome.steps);
            (manoeuvre.name.clone(), summary)
        })
        .collect();
    let summary = ShipSummary {
        scene: name.to_owned(),
        title: scene.title.clone(),
        model: ModelSummary::new(scene, &model),
        integrator: IntegratorSummary::new(&scene.stepper),
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

/// Runs every case of a ship sweep in parallel, each into the folder `folder_of` makes for
/// its index (`case-NNNN/`, made and found writable by the sweep's runner), and returns
/// the lines of its table: the case, the swept values, each manoeuvre's figures
/// (`turning_circle_35.tactical_diameter_m`), each IMO criterion's value and verdict
/// (`imo.tactical_diameter`, `imo.tactical_diameter.pass`), and the error of a case that
/// failed. A case that fails leaves the others running.
pub fn run_sweep(
    cases: &[(TableCase, ShipScene)],
    name: &str,
    folder_of: impl Fn(usize) -> Result<PathBuf> + Sync,
) -> (String, Vec<(usize, Option<String>)>) {
    let runs: Vec<Result<ShipRun>> = cases
        .par_iter()
        .map(|(case, scene)| {
            if signal_received().is_some() {
                anyhow::bail!("not run: the sweep was interrupted");
            }
            run_into(scene, name, &folder_of(case.index)?)
        })
        .collect();
    let failures = cases
        .iter()
        .zip(&runs)
        .map(|((case, _), run)| (case.index, run.as_ref().err().map(|e| format!("{e:#}"))))
        .collect();
    (sweep_table(cases, &runs), failures)
}

/// The columns of a ship sweep's table after the case and its values, from the first case
/// that ran (every case has the same manoeuvres and criteria).
fn sweep_columns(cases: &[(TableCase, ShipScene)], runs: &[Result<ShipRun>]) -> Vec<String> {
    let Some(((_, scene), run)) = cases
        .iter()
        .zip(runs)
        .find_map(|(case, run)| run.as_ref().ok().map(|run| (case, run)))
    else {
        return Vec::new();
    };
    let mut columns = Vec::new();
    for (manoeuvre, outcome) in scene.manoeuvres.iter().zip(&run.outcomes) {
        for (key, _) in &outcome.figures.values {
            columns.push(format!("{}.{key}", manoeuvre.name));
        }
    }
    for criterion in &run.judged {
        columns.push(format!("imo.{}", criterion.name));
        columns.push(format!("imo.{}.pass", criterion.name));
    }
    columns
}

/// The value of each of `columns` in `run`, empty where it gave none.
fn sweep_values(scene: &ShipScene, run: &ShipRun, columns: &[String]) -> Vec<String> {
    let mut values: BTreeMap<String, String> = BTreeMap::new();
    for (manoeuvre, outcome) in scene.manoeuvres.iter().zip(&run.outcomes) {
        for (key, value) in &outcome.figures.values {
            let text = value.map_or_else(String::new, |v| v.to_string());
            values.insert(format!("{}.{key}", manoeuvre.name), text);
        }
    }
    for criterion in &run.judged {
        let value = criterion.value.map_or_else(String::new, |v| v.to_string());
        let pass = criterion.pass().map_or_else(String::new, |p| p.to_string());
        values.insert(format!("imo.{}", criterion.name), value);
        values.insert(format!("imo.{}.pass", criterion.name), pass);
    }
    columns
        .iter()
        .map(|column| values.remove(column).unwrap_or_default())
        .collect()
}

/// `case, <swept keys…>, <figures and verdicts…>, error`, one line per case.
fn sweep_table(cases: &[(TableCase, ShipScene)], runs: &[Result<ShipRun>]) -> String {
    let Some((first, _)) = cases.first() else {
        return String::new();
    };
    let columns = sweep_columns(cases, runs);
    let mut header = vec!["case".to_owned()];
    header.extend(first.values.iter().map(|(k, _)| k.clone()));
    header.extend(columns.iter().cloned());
    header.push("error".into());
    let mut writer = csv::Writer::from_writer(Vec::new());
    let _ = writer.write_record(&header);
    for ((case, scene), run) in cases.iter().zip(runs) {
        let mut row = vec![case.index.to_string()];
        row.extend(case.values.iter().map(|(_, v)| v.to_string()));
        match run {
            Ok(run) => {
                row.extend(sweep_values(scene, run, &columns));
                row.push(String::new());
            }
            Err(error) => {
                row.extend(std::iter::repeat_n(String::new(), columns.len()));
                row.push(format!("{error:#}"));
            }
        }
        let _ = writer.write_record(&row);
    }
    String::from_utf8(writer.into_inner().unwrap_or_default()).unwrap_or_default()
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
    if let Some(error) = writer.error() {
        return Err(anyhow::anyhow!("writing {}: {error}", path.display()));
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
    let title = format!("{} — {}", scene.title, manoeuvre.name);
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
        // The scene gives no beam: the one view.html assumes.
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

fn print_report(scene: &ShipScene, outcomes: &[Outcome], judged: &[Criterion], out: &Path) {
    println!("{}", printable(&scene.title));
    for (manoeuvre, outcome) in scene.manoeuvres.iter().zip(outcomes) {
        println!("  {}:", manoeuvre.name);
        for (key, value) in &outcome.figures.values {
            match value {
                Some(v) => println!("    {key:<28} {v:>12.3}"),
                None => println!("    {key:<28} {:>12}", "—"),
            }
        }
        for note in &outcome.figures.notes {
            println!("    note: {note}");
        }
    }
    if !judged.is_empty() {
        println!(
            "  IMO MSC.137(76), L = {} m, L/V = {:.2} s:",
            scene.length,
            scene.length / scene.table.design_speed
        );
        for c in judged {
            match (c.value, c.pass()) {
                (Some(value), Some(pass)) => println!(
                    "    {:<24} {value:>10.2} {:<3} ≤ {:>9.2}  {}",
                    c.name,
                    c.unit,
                    c.limit,
                    if pass { "pass" } else { "FAIL" }
                ),
                _ => println!(
                    "    {:<24} not judged: {} did not give the figure (see its notes)",
                    c.name, c.manoeuvre
                ),
            }
        }
    }
    println!("  written to {}/", out.display());
}

/// Runs `eom linear` on a ship scene: Nomoto's models about the straight course.
pub fn linear(path: &Path, json: bool) -> Result<()> {
    let scene = ShipScene::load(path)?;
    let model = ShipModel::new(&scene.table)?;
    let linear = LinearModel::closed_form(&scene.table);
    if json {
        let report = LinearSummary::new(&scene, &model, &linear);
        println!("{}", String::from_utf8(sorted_json(&report)?)?);
        return Ok(());
    }
    let speed = scene.table.design_speed;
    println!(
        "{}: the linear model about the straight course at U₀ = {speed} m/s",
        printable(&scene.title)
    );
    let show = |what: &str, nomoto: Option<Nomoto>| match nomoto {
        Some(n) => println!(
            "  {what:<34} K = {:.6e} 1/s, T₁ = {:.6} s, T₂ = {:.6} s, T₃ = {:.6} s, T = {:.6} s",
            n.k, n.t1, n.t2, n.t3, n.t
        ),
        None => println!("  {what:<34} T₁ and T₂ are not real: no Nomoto form"),
    };
    show("Nomoto, closed form:", linear.nomoto());
    let (a, b) = linearise(&model, speed);
    show("Nomoto, linearised model:", Nomoto::from_state_space(a, b));
    if let Some(d) = nomoto_difference(linear.nomoto(), Nomoto::from_state_space(a, b)) {
        println!("  {:<34} {d:.1e}", "largest relative difference:");
    }
    let verdict = if linear.course_stable() {
        "stable"
    } else {
        "UNSTABLE"
    };
    match linear.stability_index() {
        Some(c) => println!(
            "  course stability: C′ = Y′v(N′r − m′x′G) − (Y′r − m′)N′v = {c:.6e}: {verdict}"
        ),
        None => println!(
            "  course stability: det N = {:.6e} (SI): {verdict}",
            linear.det_damping()
        ),
    }
    let pivot = linear.pivot_point();
    println!(
        "  pivot point: x_p = {pivot:.2} m ahead of midship ({:.3} L)",
        pivot / scene.length
    );
    Ok(())
}
