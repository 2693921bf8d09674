//! A ship scene run: every manoeuvre (each side of a two-sided one) with the scene's method,
//! its rows handed to the caller's [`Recorder`], run again refined for how far each figure
//! moves; the IMO criteria judged on them; the summary (`summary.json`'s types,
//! [`super::summary`]), the report as text, and a sweep case's line. What is written where,
//! and whether a run may go on, is the recorder's: this module opens no file.

use super::ShipError;
use super::Side;
use super::imo::{Criterion, Trial, criteria, possible};
use super::linear::LinearModel;
use super::manoeuvre::{Figures, ManoeuvreKind, ROW, run_until};
use super::scene::NAMED_FROM;
use super::side::{deciding_figure, worse};
use super::spiral::{Branch, Loop, SpiralCurve, SpiralPoint, Verdict};
use super::steady::SteadyTurns;
use super::summary::{
    CriterionSummary, LinearSummary, ManoeuvreSummary, Manoeuvres, ModelSummary, ShipSection,
    run_figures, verdict,
};
use super::{Manoeuvre, ShipModel, ShipScene};
use crate::output::drawing::{Curves, Drawing, Hull, Mark, PlaneManoeuvre, RunDrawings};
use crate::output::summary::{IntegratorSummary, RunFigures, Summary};
use crate::output::text::printable;
use crate::run::Row;
use crate::run::record::{Recorder, RunStart};
use crate::scene::sweep::{TableCase, manoeuvre_columns};
use crate::{Model, Short, fixed};
use std::fmt::Write;
use std::time::Instant;

/// A manoeuvre run with the scene's method, and the same refined (`Stepper::refined`: half
/// the step, or tolerances a hundred times tighter).
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The figures of the run with the scene's method.
    pub figures: Figures,
    /// The same, refined.
    pub refined: Figures,
    /// The steps the run took.
    pub steps: u64,
    /// Its evaluations of the right-hand side.
    pub rhs_evals: u64,
    /// Where the scene's stop condition ended the run with the scene's method, s.
    pub stopped_at: Option<f64>,
}

/// A manoeuvre's runs: one per side (`turning_circle_35/port/`, `…/starboard/`), or one of no
/// side or of the one side the scene names (`turning_circle_35/`).
pub type Runs = Vec<(Option<Side>, Outcome)>;

/// The side of a manoeuvre run to both that its summary, table and report show first: the
/// worse by the figure [`deciding_figure`] names.
pub fn worse_side(manoeuvre: &Manoeuvre, runs: &Runs) -> Option<Side> {
    let [(Some(Side::Port), port), (Some(Side::Starboard), starboard)] = runs.as_slice() else {
        return None;
    };
    let turning = matches!(manoeuvre.kind, ManoeuvreKind::TurningCircle { .. });
    let key = deciding_figure(turning);
    Some(worse(port.figures.get(key), starboard.figures.get(key)))
}

/// The outcome a manoeuvre's summary shows first: the worse side's, or its one run's.
pub fn shown<'a>(manoeuvre: &Manoeuvre, runs: &'a Runs) -> Option<&'a Outcome> {
    match worse_side(manoeuvre, runs) {
        Some(side) => runs.iter().find(|(s, _)| *s == Some(side)).map(|(_, o)| o),
        None => runs.first().map(|(_, o)| o),
    }
}

/// What a ship scene's run gave: its summary, each manoeuvre's runs (those finished before a
/// stop was asked), the IMO criteria judged on them, and whether a stop was asked.
#[derive(Debug, Clone)]
pub struct Finished<'a> {
    /// The scene that ran.
    pub scene: &'a ShipScene,
    /// `summary.json`.
    pub summary: Summary<ShipSection>,
    /// Each manoeuvre's runs, in the scene's order.
    pub outcomes: Vec<Runs>,
    /// The IMO criteria the runs allow.
    pub judged: Vec<Criterion>,
    /// Whether the recorder asked the run to stop before every manoeuvre had run.
    pub stopped: bool,
}

impl Finished<'_> {
    /// The report as the command prints it: each manoeuvre's figures (a column per side), the
    /// spirals, the IMO criteria.
    pub fn report(&self) -> String {
        report(self.scene, &self.outcomes, &self.judged).unwrap_or_default()
    }

    /// Each column of a ship sweep's table with its value in this run, in the table's order: each
    /// manoeuvre's figures (the worse side's, for one run to both), then each side's
    /// (`turn.port.tactical_diameter_m`), then each IMO criterion's value, verdict and sides; a
    /// manoeuvre's columns are named as [`manoeuvre_columns`] says.
    pub fn cells(&self, case: &TableCase) -> Vec<(String, String)> {
        let scene = self.scene;
        let text = |value: Option<f64>| value.map_or_else(String::new, |v| v.to_string());
        let mut cells = Vec::new();
        let names = manoeuvre_columns(
            case,
            scene.manoeuvres.iter().map(|m| m.name.as_str()),
            &NAMED_FROM,
        );
        for ((manoeuvre, runs), name) in scene.manoeuvres.iter().zip(&self.outcomes).zip(&names) {
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
            let criterion = self.judged.iter().find(|c| c.name == name);
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
}

/// Runs every manoeuvre of `scene` (`name` is its file, as the summary names it), each side
/// of a two-sided one, its rows to `recorder` under `manoeuvre` or `manoeuvre/side`; a run the
/// recorder stops ends the scene's run, keeping the ones before it (a side finished before it
/// too).
pub fn run_scene<'a>(
    scene: &'a ShipScene,
    name: &str,
    recorder: &mut dyn Recorder,
) -> Result<Finished<'a>, ShipError> {
    let started = Instant::now();
    let model = ShipModel::new(&scene.table)?;
    let linear = LinearModel::closed_form(&scene.table);
    let mut outcomes = Vec::new();
    let mut stopped = false;
    'manoeuvres: for manoeuvre in &scene.manoeuvres {
        let mut runs = Runs::new();
        let sided = manoeuvre.runs();
        for (side, one) in &sided {
            let path = match side {
                Some(side) if sided.len() > 1 => format!("{}/{}", manoeuvre.name, side.name()),
                _ => manoeuvre.name.clone(),
            };
            let outcome = match run_manoeuvre(scene, &model, one, (&path, recorder)) {
                Err(ShipError::Stopped { .. }) => {
                    stopped = true;
                    // A side finished before the signal is kept, as a manoeuvre is.
                    if !runs.is_empty() {
                        outcomes.push(runs);
                    }
                    break 'manoeuvres;
                }
                outcome => outcome.map_err(|e| e.in_manoeuvre(&manoeuvre.name))?,
            };
            let name = match side {
                Some(side) if sided.len() > 1 => format!("{} ({})", manoeuvre.name, side.name()),
                _ => manoeuvre.name.clone(),
            };
            let drawings = drawings(scene, (manoeuvre, &name), &path, &outcome.figures);
            (recorder.drawn(drawings)).map_err(|source| ShipError::Record {
                run: path.clone(),
                source,
            })?;
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
                summary.stopped_at = scene.stop.as_ref().map(|_| outcome.stopped_at);
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
    let stepper = &scene.stepper;
    let integrator = IntegratorSummary {
        steps: (outcomes.iter().flatten()).map(|(_, o)| o.steps).sum(),
        rhs_evals: Some((outcomes.iter().flatten()).map(|(_, o)| o.rhs_evals).sum()),
        ..IntegratorSummary::settings(stepper.method, stepper.step, stepper.adaptive)
    };
    let section = ShipSection {
        model: ModelSummary::new(scene, &model),
        linear: LinearSummary::new(scene, &model, &linear),
        manoeuvre: Manoeuvres {
            runs,
            imo: judged.iter().map(CriterionSummary::new).collect(),
        },
        stop_when: scene.stop.as_ref().map(|stop| stop.text.clone()),
    };
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
        runs: every_run_figures(scene, &outcomes),
        verdicts: judged.iter().map(verdict).collect(),
        section,
    };
    Ok(Finished {
        scene,
        summary,
        outcomes,
        judged,
        stopped,
    })
}

/// Each run's figures as every kind gives them, by its path (`turning_circle_35/port`).
fn every_run_figures(scene: &ShipScene, outcomes: &[Runs]) -> Vec<RunFigures> {
    let mut figures = Vec::new();
    for (manoeuvre, runs) in scene.manoeuvres.iter().zip(outcomes) {
        for (side, outcome) in runs {
            let path = match side {
                Some(side) if runs.len() > 1 => format!("{}/{}", manoeuvre.name, side.name()),
                _ => manoeuvre.name.clone(),
            };
            let both = (&outcome.figures, &outcome.refined);
            figures.push(run_figures(&path, &scene.stepper, both));
        }
    }
    figures
}

/// What a manoeuvre's run draws: the manoeuvre in the plane, the hull of the scene's length
/// (its beam assumed: a ship scene has no key for it), the view's readout the model's seven
/// states; and a spiral's r against δ.
fn drawings(
    scene: &ShipScene,
    (manoeuvre, name): (&Manoeuvre, &str),
    path: &str,
    figures: &Figures,
) -> RunDrawings {
    let title = format!("{} — {name}", scene.title);
    let mut drawings = Vec::new();
    if let Some(curve) = &figures.spiral {
        drawings.push(Drawing::Curves(spiral_curves(&title, curve)));
    }
    drawings.push(Drawing::PlaneManoeuvre(PlaneManoeuvre {
        title,
        execute_s: manoeuvre.execute,
        marks: Mark::all(&figures.marks),
        hull: Hull::of_length(scene.length),
        readout: ROW[..7].iter().map(|c| (*c).to_owned()).collect(),
    }));
    RunDrawings {
        path: path.to_owned(),
        drawings,
    }
}

/// A spiral's plot, in its manoeuvre's folder.
pub const SPIRAL_PLOT: &str = "spiral.svg";

/// `spiral.svg`: r against δ, each pass of a direct spiral a curve, a reverse spiral's one
/// in the order of r, and the steady turns traced by continuation.
fn spiral_curves(title: &str, curve: &SpiralCurve) -> Curves {
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
    let steady: Vec<(f64, f64)> = (curve.steady.iter())
        .flat_map(|s| &s.turns)
        .map(|t| (t.rudder.to_degrees(), t.r.to_degrees()))
        .collect();
    let curves = [
        ("first pass", pass(Branch::First)),
        ("back", pass(Branch::Back)),
        ("reverse spiral", pass(Branch::Reverse)),
        ("steady turns", steady),
    ];
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
    Curves {
        file: SPIRAL_PLOT.to_owned(),
        caption: format!("{title}: {verdict}"),
        x_desc: "rudder δ [deg]".to_owned(),
        y_desc: "yaw rate r [deg/s]".to_owned(),
        curves: (curves.into_iter())
            .filter(|(_, points)| !points.is_empty())
            .map(|(name, points)| (name.to_owned(), points))
            .collect(),
    }
}

/// Runs `manoeuvre` with the scene's method, its rows (t, [`ROW`], the rigid body's kinetic
/// energy) to `recorder` under `path`, and again refined, for how far each figure moves.
fn run_manoeuvre(
    scene: &ShipScene,
    model: &ShipModel,
    manoeuvre: &Manoeuvre,
    (path, recorder): (&str, &mut dyn Recorder),
) -> Result<Outcome, ShipError> {
    if recorder.stop_asked() {
        return Err(ShipError::Stopped { time: 0.0 });
    }
    let not_recorded = |source| ShipError::Record {
        run: path.to_owned(),
        source,
    };
    let names = ROW.map(str::to_owned);
    let expected_rows = (manoeuvre.duration / scene.every) as usize + 1;
    let start = RunStart {
        path,
        columns: &names,
        expected_rows,
        end_time: manoeuvre.duration,
        potential: false,
        energy_unit: crate::models::ENERGY_UNIT,
    };
    recorder.begin(start).map_err(not_recorded)?;
    let settings = (&scene.stepper, scene.every);
    let start = (scene.start(), scene.stop.as_ref());
    let keeps_rows = recorder.keeps_rows();
    let done = run_until(model, &scene.rudder, manoeuvre, start, settings, |sample| {
        if !keeps_rows {
            return !recorder.stop_asked();
        }
        let row = Row {
            t: sample.t,
            state: &sample.row(),
            kinetic_energy: model.kinetic_energy(&sample.model_state()),
            potential_energy: None,
        };
        recorder.row(&row)
    });
    // What the recorder could not keep comes first: the run stopped because of it.
    recorder.end().map_err(not_recorded)?;
    let done = done?;
    let refined = match recorder.refines() {
        true => {
            let refined = (&scene.stepper.refined(scene.every), scene.every);
            let refined = run_until(model, &scene.rudder, manoeuvre, start, refined, |_| {
                !recorder.stop_asked()
            })?;
            refined.figures
        }
        // No figure of its own: every difference is `None`.
        false => Figures::default(),
    };
    Ok(Outcome {
        figures: done.figures,
        refined,
        steps: done.steps,
        rhs_evals: done.rhs_evals,
        stopped_at: done.stopped_at,
    })
}

/// A figure as the report prints it: three decimals (no sign on a zero), or a dash where the
/// run gave none.
fn cell(value: Option<f64>) -> String {
    value.map_or_else(|| "—".to_owned(), |v| fixed(v, 3))
}

/// A manoeuvre's figures as the report prints them: a column per side for one run to both
/// (the worse side's marked), each note with its side.
fn manoeuvre_report(out: &mut String, manoeuvre: &Manoeuvre, runs: &Runs) -> std::fmt::Result {
    let worse = worse_side(manoeuvre, runs);
    match (runs.as_slice(), worse) {
        ([(_, port), (_, starboard)], Some(worse)) => {
            let mark = |side: Side| if side == worse { " (worse)" } else { "" };
            writeln!(
                out,
                "  {}:{:>31}{:>22}",
                manoeuvre.name,
                format!("port{}", mark(Side::Port)),
                format!("starboard{}", mark(Side::Starboard))
            )?;
            for ((key, p), (_, s)) in port.figures.values.iter().zip(&starboard.figures.values) {
                writeln!(out, "    {key:<28} {:>12} {:>21}", cell(*p), cell(*s))?;
            }
        }
        _ => {
            let side = runs.first().and_then(|(s, _)| *s);
            match side {
                Some(side) => writeln!(out, "  {} ({}):", manoeuvre.name, side.name())?,
                None => writeln!(out, "  {}:", manoeuvre.name)?,
            }
            for (_, outcome) in runs {
                for (key, value) in &outcome.figures.values {
                    writeln!(out, "    {key:<28} {:>12}", cell(*value))?;
                }
            }
        }
    }
    for (side, outcome) in runs {
        if let Some(curve) = &outcome.figures.spiral {
            spiral_report(out, curve)?;
        }
        let side = match side {
            Some(side) if runs.len() > 1 => format!(" ({})", side.name()),
            _ => String::new(),
        };
        for note in &outcome.figures.notes {
            writeln!(out, "    note{side}: {note}")?;
        }
    }
    Ok(())
}

/// A spiral's curve: its verdict, one line per angle (the two passes side by side for a
/// direct spiral; a point that did not settle marked `*`), then the loop from the settled
/// points beside the steady-turn curve's folds.
fn spiral_report(out: &mut String, curve: &SpiralCurve) -> std::fmt::Result {
    let verdict = curve.verdict();
    writeln!(
        out,
        "    course stable by the spiral        {}",
        match verdict {
            Verdict::NoLoop => "yes (no loop)",
            Verdict::Loop(_) => "NO (a loop)",
            Verdict::Undetermined(_) => "undetermined (see the note)",
        }
    )?;
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
    writeln!(
        out,
        "    settled: r within {}°/s over {} s (held at most {} s): {resolution}",
        Short(settle.tolerance.to_degrees()),
        Short(settle.window),
        Short(settle.max_hold),
    )?;
    let mark = |p: &SpiralPoint, text: String| match p.settled {
        true => format!("{text} "),
        false => format!("{text}*"),
    };
    let reverse = curve.points.iter().any(|p| p.branch == Branch::Reverse);
    if reverse {
        writeln!(
            out,
            "    {:>14} {:>14} {:>15}",
            "r_c [°/s]", "r [°/s]", "mean δ [°]"
        )?;
        for p in &curve.points {
            let target = p.target.map_or(f64::NAN, f64::to_degrees);
            let (r, d) = (p.yaw_rate.to_degrees(), p.rudder.to_degrees());
            writeln!(
                out,
                "    {:>14} {:>14} {:>15}",
                fixed(target, 4),
                fixed(r, 4),
                mark(p, fixed(d, 3))
            )?;
        }
    } else {
        writeln!(
            out,
            "    {:>10} {:>15} {:>15}",
            "δ [°]", "r first [°/s]", "r back [°/s]"
        )?;
        for first in curve.points.iter().filter(|p| p.branch == Branch::First) {
            let back = (curve.points.iter())
                .find(|p| p.branch == Branch::Back && p.rudder == first.rudder)
                .map(|p| mark(p, fixed(p.yaw_rate.to_degrees(), 4)));
            writeln!(
                out,
                "    {:>10} {:>15} {:>15}",
                fixed(first.rudder.to_degrees(), 2),
                mark(first, fixed(first.yaw_rate.to_degrees(), 4)),
                back.unwrap_or_else(|| "— ".to_owned())
            )?;
        }
    }
    if curve.points.iter().any(|p| !p.settled) {
        writeln!(out, "    * not settled: no figure rests on it")?;
    }
    if let Verdict::Loop(found) = verdict {
        loop_report(out, &found)?;
    }
    match &curve.steady {
        Ok(steady) => steady_report(out, steady)?,
        Err(why) => writeln!(out, "    steady turns: not traced ({why})")?,
    }
    Ok(())
}

/// The loop the settled points show: its ends, width and bounds, and the spiral's step.
fn loop_report(out: &mut String, found: &Loop) -> std::fmt::Result {
    let degrees = |x: f64| fixed(x.to_degrees(), 3);
    let most = found
        .most_width
        .map_or_else(String::new, |w| format!(", at most {}°", degrees(w)));
    let step = found
        .step
        .map_or_else(String::new, |s| format!(", rudder step {}°", degrees(s)));
    writeln!(
        out,
        "    loop from the settled points: δ from {}° to {}°, {}° wide (at least {}°{most}){step}",
        degrees(found.ends.0),
        degrees(found.ends.1),
        degrees(found.width),
        degrees(found.least_width()),
    )?;
    Ok(())
}

/// The steady-turn curve's folds and the loop between them, beside the spiral's.
fn steady_report(out: &mut String, steady: &SteadyTurns) -> std::fmt::Result {
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
    writeln!(
        out,
        "    steady turns ({} points, by continuation over {range}): {what}",
        steady.turns.len()
    )?;
    for (end, why) in ["low", "high"].iter().zip(&steady.ends) {
        if !steady.spans_range() {
            writeln!(out, "      the curve's {end} end: {why}")?;
        }
    }
    Ok(())
}

fn report(
    scene: &ShipScene,
    outcomes: &[Runs],
    judged: &[Criterion],
) -> Result<String, std::fmt::Error> {
    let mut text = String::new();
    let out = &mut text;
    writeln!(out, "{}", printable(&scene.title))?;
    for (manoeuvre, runs) in scene.manoeuvres.iter().zip(outcomes) {
        manoeuvre_report(out, manoeuvre, runs)?;
    }
    if !judged.is_empty() {
        writeln!(
            out,
            "  IMO MSC.137(76), L = {} m, L/V = {:.2} s:",
            scene.length,
            scene.length / scene.table.design_speed
        )?;
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
                (Some(value), Some(pass)) => writeln!(
                    out,
                    "    {:<24} {:>10} {:<3} ≤ {:>9.2}  {}  on {}{sides}",
                    c.name,
                    fixed(value, 2),
                    c.unit,
                    c.limit,
                    if pass { "pass" } else { "FAIL" },
                    c.manoeuvre
                ),
                _ => match &c.not_judged_because {
                    Some(why) => writeln!(out, "    {:<24} not judged: {why}", c.name),
                    None => writeln!(
                        out,
                        "    {:<24} not judged: {} did not give the figure (see its notes)\
                         {sides}",
                        c.name, c.manoeuvre
                    ),
                },
            }?;
        }
    }
    Ok(text)
}
