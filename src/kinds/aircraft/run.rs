//! An aircraft scene's runs as the one runner ([`crate::run::scene`]) runs them: each
//! manoeuvre from the trim, its figures (each with how far it moved when run refined), the
//! Dutch roll read from a rudder kick beside the linear model's, and the typed section of the
//! summary.

use super::linear::linearise_aircraft;
use super::manoeuvre::{self, AircraftRun, Manoeuvre, ROW, dutch_roll};
use super::scene::{AircraftScene, units};
use crate::kind::KindError;
use crate::output::drawing::{Airframe, Coordinate, Curves, Drawing, Orientation, Shape, View};
use crate::output::summary::{Figure, IntegratorSummary, Named, RunFigures};
use crate::output::trajectory::number_text;
use crate::run::scene::{Closing, Counts, Ran, Rows, RunPlan, RunResult, SceneRuns, Setting};
use crate::scene::sweep::TableCase;
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write;

/// The trim, as summary.json gives it.
#[derive(Debug, Clone, Serialize)]
pub struct TrimSummary {
    /// Every state entry and control at the trim, by name (the units under `units`).
    pub state: Named,
    /// The controls.
    pub controls: Named,
    /// The largest of |V̇|, |α̇|, |β̇|, |ṗ|, |q̇|, |ṙ| left.
    pub residual: f64,
}

/// A manoeuvre's figures.
#[derive(Debug, Clone, Serialize)]
pub struct ManoeuvreSummary {
    /// The figures by key (unit as suffix).
    pub figures: Named,
    /// How far each figure moved when the run was refined with half the step (a fixed-step
    /// method), `null` where the refined run did not give it; absent where the run was not
    /// refined (a Monte Carlo's case).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub half_step_difference: Option<BTreeMap<String, Option<f64>>>,
    /// The same with tolerances a hundred times tighter (an adaptive method).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tolerance_difference: Option<BTreeMap<String, Option<f64>>>,
    /// What could not be read, and why.
    pub notes: Vec<String>,
    /// Accepted steps.
    pub steps_taken: u64,
    /// Where the stop condition ended it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stopped_at: Option<f64>,
}

/// The aircraft's section of summary.json.
#[derive(Debug, Clone, Serialize)]
pub struct AircraftSection {
    /// Each column's unit.
    pub units: BTreeMap<&'static str, &'static str>,
    /// The trim.
    pub trim: TrimSummary,
    /// Each manoeuvre's figures, by name.
    pub manoeuvre: BTreeMap<String, ManoeuvreSummary>,
    /// `integrator.stop_when`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stop_when: Option<String>,
}

/// The Dutch roll of the linear model at the trim: (period s, damping ratio).
fn linear_dutch_roll(scene: &AircraftScene) -> Option<(f64, f64)> {
    let linear = linearise_aircraft(scene).ok()?;
    let mode = linear.modes.iter().find(|m| m.name == Some("Dutch roll"))?;
    Some((mode.period_s?, mode.damping_ratio?))
}

/// A manoeuvre's figures, and what could not be read; a rudder kick's Dutch roll beside the
/// linear model's (`linear`).
fn figures(
    scene: &AircraftScene,
    run: &AircraftRun,
    (kick, linear): (bool, Option<(f64, f64)>),
) -> (Named, Vec<String>) {
    let m = &run.measured;
    let mut figures = vec![
        ("peak_load_factor_g".to_owned(), m.load_factor.0),
        ("least_load_factor_g".to_owned(), m.load_factor.1),
        (
            "alpha_excursion_deg".to_owned(),
            m.excursions[0].to_degrees(),
        ),
        (
            "sideslip_excursion_deg".to_owned(),
            m.excursions[1].to_degrees(),
        ),
        (
            "roll_rate_peak_deg_s".to_owned(),
            m.excursions[2].to_degrees(),
        ),
        ("final_speed".to_owned(), run.end[0]),
        (
            "altitude_change".to_owned(),
            run.end[11] - scene.trim.state[11],
        ),
    ];
    let mut notes = Vec::new();
    let (low, high) = scene.limits.alpha;
    let (least, largest) = m.alpha_extremes;
    if least < low || largest > high {
        notes.push(format!(
            "α went from {:.2}° to {:.2}°, beyond the range the aerodynamics holds \
             ({:.1}° to {:.1}°, `limits.alpha_deg`): the rows there are the tables' linear \
             extension past their ends, not data, and the figures read on them are no better",
            least.to_degrees(),
            largest.to_degrees(),
            low.to_degrees(),
            high.to_degrees()
        ));
    }
    if kick {
        match dutch_roll(&m.yaw_peaks, &m.yaw_troughs) {
            Some((period, damping)) => {
                figures.push(("dutch_roll_period_s".into(), period));
                figures.push(("dutch_roll_damping".into(), damping));
            }
            None => notes.push(
                "the yaw rate swung fewer than three times after the kick: no Dutch roll read"
                    .into(),
            ),
        }
        if let Some((period, damping)) = linear {
            figures.push(("dutch_roll_period_linear_s".into(), period));
            figures.push(("dutch_roll_damping_linear".into(), damping));
        }
    }
    (Named(figures), notes)
}

/// What a manoeuvre's run gives: its summary, and the rows its plots draw (every few, at
/// most about 2000; none where its rows are not kept).
#[derive(Debug, Clone)]
pub struct ManoeuvreFigures {
    /// What summary.json says of it, but how far it moved refined ([`summary`] adds that).
    pub summary: ManoeuvreSummary,
    curves: Vec<(f64, [f64; 18])>,
}

/// A manoeuvre run with the scene's method, its cost, and its figures refined.
pub type Outcome = crate::run::scene::Outcome<ManoeuvreFigures>;

/// What summary.json says of a manoeuvre's run: its summary, with each figure's difference
/// from the refined run's, by key, where that finished (under `tolerance_difference` for an
/// adaptive method, `half_step_difference` for a fixed step).
pub fn summary(scene: &AircraftScene, outcome: &Outcome) -> ManoeuvreSummary {
    let mut summary = outcome.gave.summary.clone();
    let differences = refined_differences(outcome);
    match scene.stepper.method.is_adaptive() {
        true => summary.tolerance_difference = differences,
        false => summary.half_step_difference = differences,
    }
    summary
}

/// Each figure's difference from the refined run's, by key (`None` for a figure the refined
/// run did not give), where the refined run finished.
fn refined_differences(outcome: &Outcome) -> Option<BTreeMap<String, Option<f64>>> {
    let refined = &outcome.refined()?.summary.figures;
    let differences = (outcome.gave.summary.figures.0.iter())
        .map(|(key, value)| {
            let moved = (refined.0.iter()).find(|(k, _)| k == key);
            let difference = moved.map(|(_, refined)| (value - refined).abs());
            (key.clone(), difference)
        })
        .collect();
    Some(differences)
}

impl SceneRuns for AircraftScene {
    /// The linear model's Dutch roll at the trim, where a manoeuvre is a rudder kick.
    type Shared = Option<(f64, f64)>;
    type Gave = ManoeuvreFigures;
    type Section = AircraftSection;

    fn kind_name(&self) -> &'static str {
        super::kind::KIND.name
    }

    fn scene_title(&self) -> &str {
        &self.title
    }

    fn integrator(&self) -> IntegratorSummary {
        IntegratorSummary::of(&self.stepper)
    }

    fn prepare(&self) -> Result<Option<(f64, f64)>, KindError> {
        let kicks = (self.manoeuvres.iter()).any(|m| m.kind == Manoeuvre::RudderKick);
        Ok(kicks.then(|| linear_dutch_roll(self)).flatten())
    }

    /// Each manoeuvre's run from the trim: t, the row in the scene's units, the kinetic
    /// energy.
    fn plans(&self, _: &Option<(f64, f64)>) -> Vec<RunPlan> {
        let columns = self.labelled_columns();
        (self.manoeuvres.iter())
            .map(|manoeuvre| RunPlan {
                path: manoeuvre.name.clone(),
                columns: columns.clone(),
                expected_rows: (manoeuvre.duration / self.every).ceil() as usize + 1,
                end_time: manoeuvre.duration,
                potential: false,
                energy_unit: self.energy_unit(),
            })
            .collect()
    }

    fn run_one(
        &self,
        linear: &Option<(f64, f64)>,
        index: usize,
        setting: Setting,
        rows: &mut Rows,
    ) -> RunResult<ManoeuvreFigures> {
        let manoeuvre = &self.manoeuvres[index];
        let stepper = setting.stepper(&self.stepper, self.every);
        let mut curves: Vec<(f64, [f64; 18])> = Vec::new();
        let stride = ((manoeuvre.duration / self.every).ceil() as usize / 2000).max(1);
        let mut count = 0usize;
        let done = manoeuvre::run(
            &self.model,
            self.kinematics,
            manoeuvre,
            (&self.trim.state, &self.trim.controls),
            (&stepper, self.every),
            self.stop.as_ref(),
            |sample| {
                // The plots' curves, of the rows kept alone.
                if rows.keeps() && count.is_multiple_of(stride) {
                    curves.push((sample.t, sample.row));
                }
                count += 1;
                rows.take_built(sample.t, || (sample.row, sample.kinetic))
            },
        );
        let done = done.map_err(|error| {
            KindError::Run(format!("manoeuvre {}: {error}", manoeuvre.name).into())
        })?;
        let kick = manoeuvre.kind == Manoeuvre::RudderKick;
        let (named, mut notes) = figures(self, &done, (kick, *linear));
        if let Some(t) = done.stopped_at {
            notes.push(format!(
                "stopped at t = {} s where `{}` first held (integrator.stop_when): the figures \
                 are of the run up to there",
                crate::Short(t),
                self.stop.as_ref().map_or("", |s| s.text.as_str())
            ));
        }
        let summary = ManoeuvreSummary {
            figures: named,
            half_step_difference: None,
            tolerance_difference: None,
            notes,
            steps_taken: done.steps,
            stopped_at: done.stopped_at,
        };
        let counts = Counts {
            steps: done.steps,
            rejected: None,
            rhs_evals: done.rhs_evals,
        };
        Ok(Outcome::new(ManoeuvreFigures { summary, curves }, counts))
    }

    fn refined_warnings(&self, outcome: &Outcome) -> Vec<String> {
        let key = match self.stepper.method.is_adaptive() {
            true => "tolerance_difference",
            false => "half_step_difference",
        };
        (outcome.refined_failure().iter())
            .map(|error| format!("{key} is not given: refined, {error}"))
            .collect()
    }

    fn figures(&self, plan: &RunPlan, outcome: &Outcome) -> RunFigures {
        // The differences alone, rather than the summary that says them (a Monte Carlo's
        // case reads its figures here, and needs no copy of its summary).
        let m = &outcome.gave.summary;
        let differences = refined_differences(outcome);
        let differences = differences.as_ref();
        RunFigures {
            run: plan.path.clone(),
            figures: (m.figures.0.iter())
                .map(|(key, value)| Figure {
                    key: key.clone(),
                    value: Some(*value),
                    difference: differences.and_then(|d| d.get(key).copied().flatten()),
                })
                .collect(),
            refinement: differences.map(|_| self.stepper.refinement()),
            largest_difference: None,
            notes: m.notes.clone(),
        }
    }

    fn drawings(&self, _: &Option<(f64, f64)>, index: usize, outcome: &Outcome) -> Vec<Drawing> {
        drawings(self, &self.manoeuvres[index].name, &outcome.gave.curves)
    }

    fn close(&self, ran: &Ran<'_, Self>) -> Closing<AircraftSection> {
        let section = AircraftSection {
            units: units(self.units).into_iter().collect(),
            trim: trim_summary(self),
            manoeuvre: (ran.outcomes.iter())
                .map(|(index, o)| (self.manoeuvres[*index].name.clone(), summary(self, o)))
                .collect(),
            stop_when: self.stop.as_ref().map(|s| s.text.clone()),
        };
        Closing {
            section,
            verdicts: Vec::new(),
            warnings: self.trim_warnings.clone(),
        }
    }

    fn report(&self, ran: &Ran<'_, Self>) -> String {
        report(self, ran)
    }

    fn cells(&self, ran: &Ran<'_, Self>, _case: &TableCase) -> Vec<(String, String)> {
        cells(self, ran)
    }
}

fn trim_summary(scene: &AircraftScene) -> TrimSummary {
    let state = (super::STATE.iter())
        .zip(scene.trim.state)
        .map(|(n, v)| (n.to_string(), v))
        .collect();
    let controls = (super::CONTROLS.iter())
        .zip(scene.trim.controls)
        .map(|(n, v)| (n.to_string(), v))
        .collect();
    TrimSummary {
        state: Named(state),
        controls: Named(controls),
        residual: scene.trim.residual,
    }
}

/// The run's plots: the angles and the load factor against time.
fn drawings(scene: &AircraftScene, path: &str, rows: &[(f64, [f64; 18])]) -> Vec<Drawing> {
    let curve = |name: &str, column: usize, scale: f64| {
        let points = rows
            .iter()
            .map(|(t, row)| (*t, row[column] * scale))
            .collect();
        (name.to_owned(), points)
    };
    let degrees = 180.0 / std::f64::consts::PI;
    let column = |name: &str| ROW.iter().position(|c| *c == name).unwrap_or(0);
    vec![
        Drawing::Curves(Curves {
            file: "angles.svg".into(),
            caption: format!("{}: {path}, angles", scene.title),
            x_desc: "t (s)".into(),
            y_desc: "angle (deg)".into(),
            curves: ["alpha", "beta", "phi", "theta"]
                .iter()
                .map(|n| curve(n, column(n), degrees))
                .collect(),
        }),
        Drawing::Curves(Curves {
            file: "rates.svg".into(),
            caption: format!("{}: {path}, body rates", scene.title),
            x_desc: "t (s)".into(),
            y_desc: "rate (deg/s)".into(),
            curves: ["p", "q", "r"]
                .iter()
                .map(|n| curve(n, column(n), degrees))
                .collect(),
        }),
        Drawing::View(Box::new(view(scene, format!("{}: {path}", scene.title)))),
        Drawing::Curves(Curves {
            file: "load_factor.svg".into(),
            caption: format!("{}: {path}, load factor", scene.title),
            x_desc: "t (s)".into(),
            y_desc: "n_z (g)".into(),
            curves: vec![curve("n_z", column("load_factor"), 1.0)],
        }),
    ]
}

/// The fuselage's length over its diameter, as the view draws an aircraft: a transport's and
/// a fighter's fineness ratio to within a factor of two.
const FUSELAGE_FINENESS: f64 = 10.0;

/// The view of a flight: the aircraft from the scene's geometry (a fuselage of its length
/// along body x, a tenth as thick, wings of its span and chord, a tailplane and a fin; without
/// the scene's length, as long as the span) over the ground (z = 0 at altitude 0), turned by
/// the rows' Euler angles, every column in its readout.
fn view(scene: &AircraftScene, title: String) -> View {
    let (length, said) = match scene.length {
        Some(length) => (length, "`geometry.length`"),
        None => (
            scene.span,
            "the span, the scene giving no `geometry.length`",
        ),
    };
    let unit = units(scene.units)[9].1;
    let column = |name: &str, unit: &str| format!("{name}[{unit}]");
    let airframe = Shape::Aircraft(Airframe {
        length,
        diameter: length / FUSELAGE_FINENESS,
        span: scene.span,
        chord: scene.chord,
        unit,
    });
    let position = [
        Coordinate::Column(column("north", unit)),
        Coordinate::Column(column("east", unit)),
        Coordinate::Negated(column("altitude", unit)),
    ];
    let attitude = Orientation::EulerAngles(["phi", "theta", "psi"].map(|a| column(a, "rad")));
    View {
        notes: vec![format!(
            "drawn from the scene's geometry: the fuselage {} {unit} long ({said}) and a tenth \
             of that across, the wings of span {} {unit} and chord {} {unit}, the tailplane a \
             third of the span",
            crate::Short(length),
            crate::Short(scene.span),
            crate::Short(scene.chord),
        )],
        ..View::moving(title, airframe, position, attitude)
    }
}

/// The inertia tensor about G that the model uses, as the report echoes it: its rows, whose
/// off-diagonal entries are −∫xz dm (a scene that gave the integrals ∫xz dm, as Etkin and
/// Nelson print them, sees here the sign they took).
fn inertia_line(scene: &AircraftScene) -> String {
    let unit = if scene.units == "si" {
        "kg m²"
    } else {
        "slug ft²"
    };
    let rows: Vec<String> = (scene.mass_properties.1.iter())
        .map(|row| {
            let entries: Vec<String> = row.iter().map(|x| format!("{x:e}")).collect();
            format!("[{}]", entries.join(", "))
        })
        .collect();
    format!(
        "inertia about G, the tensor eom uses ({unit}; off-diagonal entries −∫xz dm): [{}]",
        rows.join(", ")
    )
}

/// The report as the command prints it: the trim, then each manoeuvre's figures and notes.
fn report(scene: &AircraftScene, ran: &Ran<'_, AircraftScene>) -> String {
    let mut out = String::new();
    let t = &scene.trim;
    let _ = writeln!(out, "{}", crate::output::text::printable(&scene.title));
    let _ = writeln!(
        out,
        "  trim: V = {} {}, α = {:.4}°, θ = {:.4}°, φ = {:.4}°, throttle {:.4}, elevator \
             {:.4}°, aileron {:.4}°, rudder {:.4}° (residual {:.1e})",
        t.state[0],
        units(scene.units)[0].1,
        t.state[1].to_degrees(),
        t.state[4].to_degrees(),
        t.state[3].to_degrees(),
        t.controls[0],
        t.controls[1],
        t.controls[2],
        t.controls[3],
        t.residual
    );
    let _ = writeln!(out, "  {}", inertia_line(scene));
    for (index, outcome) in &ran.outcomes {
        let (name, m) = (&scene.manoeuvres[*index].name, &outcome.gave.summary);
        let figures: Vec<String> = (m.figures.0.iter())
            .map(|(k, v)| format!("{k} {}", crate::Short(*v)))
            .collect();
        let _ = writeln!(out, "  {name}: {}", figures.join(", "));
        for note in &m.notes {
            let _ = writeln!(out, "    note: {note}");
        }
    }
    out
}

/// Each manoeuvre's figures, `<manoeuvre>.<figure>`, then its steps.
fn cells(scene: &AircraftScene, ran: &Ran<'_, AircraftScene>) -> Vec<(String, String)> {
    let mut cells = Vec::new();
    for (index, manoeuvre) in scene.manoeuvres.iter().enumerate() {
        let Some(m) = ran.outcome(index).map(|outcome| &outcome.gave.summary) else {
            continue;
        };
        for (key, value) in &m.figures.0 {
            cells.push((format!("{}.{key}", manoeuvre.name), number_text(*value)));
        }
        cells.push((
            format!("{}.steps_taken", manoeuvre.name),
            m.steps_taken.to_string(),
        ));
    }
    cells
}
