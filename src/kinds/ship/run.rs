//! A ship scene's runs as the one runner ([`crate::run::scene`]) runs them: every manoeuvre,
//! each side of a two-sided one, from the same straight approach; the IMO criteria judged on
//! their figures; the ship's section of the summary (`summary.json`'s types,
//! [`super::summary`]), the report as text, and a sweep case's line. The runner does the
//! loop, the rows, the refined run and the summary's shared keys; this module opens no file.

use super::Side;
use super::environment::EnvironmentSummary;
use super::imo::{Criterion, Trial, criteria, possible};
use super::linear::LinearModel;
use super::manoeuvre::{Figures, ManoeuvreKind, ManoeuvreRun, ROW, run_until};
use super::scene::NAMED_FROM;
use super::side::{deciding_figure, worse};
use super::spiral::{Branch, Loop, SpiralCurve, SpiralPoint, Verdict};
use super::steady::SteadyTurns;
use super::summary::{
    CriterionSummary, LinearSummary, ManoeuvreSummary, Manoeuvres, ModelSummary, ShipSection,
    run_figures, verdict,
};
use super::{Manoeuvre, ShipModel, ShipScene};
use crate::kind::KindError;
use crate::output::drawing::{
    Coordinate, Curves, Drawing, Ground, Line, Mark, Orientation, Outline, Reading, Series, Shape,
    Track, Trail, View,
};
use crate::output::summary::{IntegratorSummary, RunFigures};
use crate::output::text::printable;
use crate::run::scene::{Closing, Counts, Ran, Rows, RunPlan, RunResult, SceneRuns, Setting};
use crate::scene::sweep::{TableCase, manoeuvre_columns};
use crate::{Model, Short, fixed};
use std::fmt::Write;

/// A manoeuvre run with the scene's method, its cost, and its figures refined
/// (`Stepper::refined`: half the step, or tolerances a hundred times tighter).
pub type Outcome = crate::run::scene::Outcome<ManoeuvreRun>;

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
    Some(worse(
        port.gave.figures.get(key),
        starboard.gave.figures.get(key),
    ))
}

/// The outcome a manoeuvre's summary shows first: the worse side's, or its one run's.
pub fn shown<'a>(manoeuvre: &Manoeuvre, runs: &'a Runs) -> Option<&'a Outcome> {
    match worse_side(manoeuvre, runs) {
        Some(side) => runs.iter().find(|(s, _)| *s == Some(side)).map(|(_, o)| o),
        None => runs.first().map(|(_, o)| o),
    }
}

/// What every run of a ship scene's run shares: the model, derived and proved, the linear
/// model about the straight course, and each run's manoeuvre (each side of a two-sided one)
/// in the order run.
#[derive(Debug)]
pub struct Shared {
    /// The table's model.
    pub model: ShipModel,
    /// The linear model about the straight course, in closed form.
    pub linear: LinearModel,
    /// Each run: its manoeuvre's index in the scene, its side, the manoeuvre as run to it.
    pub runs: Vec<(usize, Option<Side>, Manoeuvre)>,
}

/// Each manoeuvre's runs that finished, in the scene's order (empty for one that gave none).
fn grouped(ran: &Ran<'_, ShipScene>) -> Vec<Runs> {
    let mut grouped: Vec<Runs> = vec![Runs::new(); ran.scene.manoeuvres.len()];
    for (index, outcome) in &ran.outcomes {
        let (manoeuvre, side, _) = &ran.shared.runs[*index];
        grouped[*manoeuvre].push((*side, outcome.clone()));
    }
    grouped
}

/// The path of a manoeuvre's run under the output: `manoeuvre/side` for one of two sides.
fn path(manoeuvre: &Manoeuvre, side: Option<Side>, sides: usize) -> String {
    match side {
        Some(side) if sides > 1 => format!("{}/{}", manoeuvre.name, side.name()),
        _ => manoeuvre.name.clone(),
    }
}

impl SceneRuns for ShipScene {
    type Shared = Shared;
    type Gave = ManoeuvreRun;
    type Section = ShipSection;

    fn kind_name(&self) -> &'static str {
        super::KIND.name
    }

    fn scene_title(&self) -> &str {
        &self.title
    }

    fn integrator(&self) -> IntegratorSummary {
        IntegratorSummary::of(&self.stepper)
    }

    fn prepare(&self) -> Result<Shared, KindError> {
        let runs = (self.manoeuvres.iter().enumerate())
            .flat_map(|(index, manoeuvre)| {
                (manoeuvre.runs().into_iter()).map(move |(side, one)| (index, side, one))
            })
            .collect();
        Ok(Shared {
            model: ShipModel::new(&self.table)?,
            linear: LinearModel::closed_form(&self.table),
            runs,
        })
    }

    /// Each side's run of each manoeuvre: t, [`ROW`] and the rigid body's kinetic energy.
    fn plans(&self, shared: &Shared) -> Vec<RunPlan> {
        (shared.runs.iter())
            .map(|(index, side, one)| {
                let manoeuvre = &self.manoeuvres[*index];
                RunPlan {
                    path: path(manoeuvre, *side, manoeuvre.sides.len()),
                    columns: ROW.map(str::to_owned).to_vec(),
                    expected_rows: (one.duration / self.every) as usize + 1,
                    end_time: one.duration,
                    potential: false,
                    energy_unit: crate::models::ENERGY_UNIT,
                }
            })
            .collect()
    }

    fn run_one(
        &self,
        shared: &Shared,
        index: usize,
        setting: Setting,
        rows: &mut Rows,
    ) -> RunResult<ManoeuvreRun> {
        let (number, _, one) = &shared.runs[index];
        let stepper = setting.stepper(&self.stepper, self.every);
        let model = &shared.model;
        let start = (self.start(), self.stop.as_ref());
        // The figures are read from every accepted step and event, not from the rows: where
        // no row is kept and the method places its rows by dense output (its steps do not
        // depend on them), the run asks for none between its ends.
        let every = match rows.keeps() || !stepper.method.is_adaptive() {
            true => self.every,
            false => one.duration,
        };
        let done = run_until(
            model,
            &self.rudder,
            one,
            start,
            (&stepper, every),
            |sample| {
                let kinetic = || model.kinetic_energy(&sample.model_state());
                rows.take_built(sample.t, || (sample.row(), kinetic()))
            },
        );
        let manoeuvre = &self.manoeuvres[*number].name;
        let done = done.map_err(|e| KindError::from(e.in_manoeuvre(manoeuvre)))?;
        let counts = Counts {
            steps: done.steps,
            rejected: None,
            rhs_evals: done.rhs_evals,
        };
        Ok(Outcome::new(done, counts))
    }

    fn refined_warnings(&self, outcome: &Outcome) -> Vec<String> {
        (outcome.refined_failure().iter())
            .map(|error| {
                let refinement = self.stepper.refinement();
                format!("{refinement} of its figures is not given: refined, {error}")
            })
            .collect()
    }

    fn figures(&self, plan: &RunPlan, outcome: &Outcome) -> RunFigures {
        let not_refined = Figures::default();
        let refined = outcome.refined().map(|refined| &refined.figures);
        let both = (&outcome.gave.figures, refined.unwrap_or(&not_refined));
        let mut figures = run_figures(&plan.path, &self.stepper, both);
        figures.refinement = figures.refinement.filter(|_| outcome.refined().is_some());
        figures
    }

    fn drawings(&self, shared: &Shared, index: usize, outcome: &Outcome) -> Vec<Drawing> {
        let (number, side, _) = &shared.runs[index];
        let manoeuvre = &self.manoeuvres[*number];
        let name = match side {
            Some(side) if manoeuvre.sides.len() > 1 => {
                format!("{} ({})", manoeuvre.name, side.name())
            }
            _ => manoeuvre.name.clone(),
        };
        drawings(self, (manoeuvre, &name), &outcome.gave.figures)
    }

    fn close(&self, ran: &Ran<'_, Self>) -> Closing<ShipSection> {
        let outcomes = grouped(ran);
        let judged = judged(self, &outcomes);
        let runs = (self.manoeuvres.iter().zip(&outcomes))
            .filter(|(_, runs)| !runs.is_empty())
            .map(|(manoeuvre, runs)| {
                (
                    manoeuvre.name.clone(),
                    manoeuvre_summary(self, manoeuvre, runs),
                )
            })
            .collect();
        let model = &ran.shared.model;
        let section = ShipSection {
            model: ModelSummary::new(self, model),
            linear: LinearSummary::new(self, model, &ran.shared.linear),
            manoeuvre: Manoeuvres {
                runs,
                imo: judged.iter().map(CriterionSummary::new).collect(),
            },
            stop_when: self.stop.as_ref().map(|stop| stop.text.clone()),
        };
        Closing {
            section,
            verdicts: judged.iter().map(verdict).collect(),
            warnings: Vec::new(),
        }
    }

    /// Each manoeuvre's figures (a column per side), the spirals, the IMO criteria.
    fn report(&self, ran: &Ran<'_, Self>) -> String {
        let outcomes = grouped(ran);
        report(self, &outcomes, &judged(self, &outcomes)).unwrap_or_default()
    }

    fn cells(&self, ran: &Ran<'_, Self>, case: &TableCase) -> Vec<(String, String)> {
        let outcomes = grouped(ran);
        cells(self, (&outcomes, &judged(self, &outcomes)), case)
    }
}

/// The IMO criteria the finished runs allow.
fn judged(scene: &ShipScene, outcomes: &[Runs]) -> Vec<Criterion> {
    let trials: Vec<Trial> = (scene.manoeuvres.iter().zip(outcomes))
        .filter(|(_, runs)| !runs.is_empty())
        .map(|(m, runs)| (m, runs.iter().map(|(s, o)| (*s, &o.gave.figures)).collect()))
        .collect();
    criteria(scene, &trials)
}

/// A manoeuvre's summary: its one run's, or the worse side's with each side's beside, each
/// with the kind its side ran (the rudder's sign to that side).
fn manoeuvre_summary(scene: &ShipScene, manoeuvre: &Manoeuvre, runs: &Runs) -> ManoeuvreSummary {
    let sided = manoeuvre.runs();
    let summary_of = |(side, outcome): &(Option<Side>, Outcome)| {
        let manoeuvre = (sided.iter())
            .find(|(s, _)| s == side)
            .map_or(manoeuvre, |(_, run)| run);
        let not_refined = Figures::default();
        // No figure of its own where it was not refined: every difference `None`.
        let refined = outcome.refined().map(|refined| &refined.figures);
        let figures = (&outcome.gave.figures, refined.unwrap_or(&not_refined));
        let steps = outcome.gave.steps;
        let mut summary = ManoeuvreSummary::new(manoeuvre, &scene.stepper, figures, steps);
        summary.side = side.map(Side::name).or(summary.side);
        summary.stopped_at = scene.stop.as_ref().map(|_| outcome.gave.stopped_at);
        summary
    };
    match (worse_side(manoeuvre, runs), runs.as_slice()) {
        (Some(side), [port, starboard]) => {
            ManoeuvreSummary::both(summary_of(port), summary_of(starboard), side)
        }
        (_, runs) => summary_of(&runs[0]),
    }
}

/// Each column of a ship sweep's table with its value in this run, in the table's order: each
/// manoeuvre's figures (the worse side's, for one run to both), then each side's
/// (`turn.port.tactical_diameter_m`), then each IMO criterion's value, verdict and sides; a
/// manoeuvre's columns are named as [`manoeuvre_columns`] says.
fn cells(
    scene: &ShipScene,
    (outcomes, judged): (&[Runs], &[Criterion]),
    case: &TableCase,
) -> Vec<(String, String)> {
    let text = |value: Option<f64>| value.map_or_else(String::new, |v| v.to_string());
    let mut cells = Vec::new();
    let names = manoeuvre_columns(
        case,
        scene.manoeuvres.iter().map(|m| m.name.as_str()),
        &NAMED_FROM,
    );
    for ((manoeuvre, runs), name) in scene.manoeuvres.iter().zip(outcomes).zip(&names) {
        if let Some(outcome) = shown(manoeuvre, runs) {
            for (key, value) in &outcome.gave.figures.values {
                cells.push((format!("{name}.{key}"), text(*value)));
            }
        }
        for (side, outcome) in runs.iter().filter(|_| runs.len() > 1) {
            let side = side.map_or("", Side::name);
            for (key, value) in &outcome.gave.figures.values {
                cells.push((format!("{name}.{side}.{key}"), text(*value)));
            }
        }
    }
    // Every criterion the scene's kinds may give, judged in this case or not, so that the
    // columns do not depend on a swept angle (a turn at 20° is not judged; at 35° it is).
    for (name, sided) in possible(scene) {
        let criterion = judged.iter().find(|c| c.name == name);
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

/// What a manoeuvre's run draws: midship's track with the manoeuvre's points marked and the
/// hull's waterline along it, the heading change with the rudder and its command, the hull on
/// the water (the view's readout the model's seven states); and a spiral's r against δ. The
/// hull has the scene's length and a beam assumed (a ship scene has no key for it).
fn drawings(
    scene: &ShipScene,
    (manoeuvre, name): (&Manoeuvre, &str),
    figures: &Figures,
) -> Vec<Drawing> {
    let title = format!("{} — {name}", scene.title);
    let mut drawings = Vec::new();
    if let Some(curve) = &figures.spiral {
        drawings.push(Drawing::Curves(spiral_curves(&title, curve)));
    }
    let length = scene.length;
    let beam = length / Shape::ASSUMED_LENGTH_OVER_BEAM;
    let column = |name: &str, desc: &str| (name.to_owned(), desc.to_owned());
    drawings.push(Drawing::Track(Track {
        title: title.clone(),
        what: format!(
            "track, hull every 1/{HULLS} of the run (B = L/{} assumed)",
            crate::Short(length / beam)
        ),
        across: column("y", "east Y [m]"),
        up: column("x", "north X [m]"),
        marks: Mark::all(&figures.marks),
        outline: Some(Outline {
            length,
            beam,
            heading: "psi".into(),
            times: HULLS,
            label: "hull".into(),
        }),
    }));
    drawings.push(Drawing::Series(Series {
        file: "heading.svg".into(),
        title: title.clone(),
        what: "heading and rudder".into(),
        y_desc: "[deg]".into(),
        lines: vec![
            Line::new(
                "heading change ψ − ψ₀",
                "psi",
                Reading::DegreesSince {
                    from_s: manoeuvre.execute,
                },
            ),
            Line::new("rudder δ", "delta", Reading::Degrees),
            Line::new("command", "command", Reading::Degrees),
        ],
    }));
    let position = [
        Coordinate::Column("x".into()),
        Coordinate::Column("y".into()),
        Coordinate::Zero,
    ];
    let heading = Orientation::Heading("psi".into());
    drawings.push(Drawing::View(Box::new(View {
        readout: Some(ROW[..7].iter().map(|c| (*c).to_owned()).collect()),
        trail: Trail::Point([0.0; 3], "midship".into()),
        ground: Ground::Water,
        notes: vec![format!(
            "the hull of length L = {} m, and of beam B = L/{} = {} m, assumed: a ship scene \
             has no key for the beam (its table does not need one)",
            crate::Short(length),
            Shape::ASSUMED_LENGTH_OVER_BEAM,
            crate::Short(beam)
        )],
        ..View::moving(title, Shape::Waterline { length, beam }, position, heading)
    })));
    drawings
}

/// How many times the hull is drawn along the track, evenly by distance run, besides the start.
const HULLS: usize = 10;

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
            for ((key, p), (_, s)) in port
                .gave
                .figures
                .values
                .iter()
                .zip(&starboard.gave.figures.values)
            {
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
                for (key, value) in &outcome.gave.figures.values {
                    writeln!(out, "    {key:<28} {:>12}", cell(*value))?;
                }
            }
        }
    }
    for (side, outcome) in runs {
        if let Some(curve) = &outcome.gave.figures.spiral {
            spiral_report(out, curve)?;
        }
        let side = match side {
            Some(side) if runs.len() > 1 => format!(" ({})", side.name()),
            _ => String::new(),
        };
        for note in &outcome.gave.figures.notes {
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
    if let Some(environment) = EnvironmentSummary::of(&scene.table) {
        writeln!(out, "{}", environment.line())?;
    }
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
