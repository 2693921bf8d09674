//! An aircraft scene's run: each manoeuvre from the trim, its rows to the recorder, its
//! figures, the Dutch roll read from a rudder kick beside the linear model's, and the typed
//! summary.

use super::linear::linearise_aircraft;
use super::manoeuvre::{self, AircraftRun, ROW, RunError, dutch_roll};
use super::scene::{AircraftScene, units};
use crate::kinds::KindError;
use crate::output::drawing::{Curves, Drawing, Flight, RunDrawings};
use crate::output::summary::{Figure, IntegratorSummary, Named, RunFigures, Summary};
use crate::output::trajectory::number_text;
use crate::run::Row;
use crate::run::record::{Recorder, RunStart};
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

/// What a run of the scene gave.
#[derive(Debug)]
pub struct Finished<'a> {
    /// The scene.
    pub scene: &'a AircraftScene,
    /// The summary.
    pub summary: Summary<AircraftSection>,
    /// Whether the recorder stopped it.
    pub stopped: bool,
    /// How many manoeuvres ran.
    pub ran: usize,
}

/// The Dutch roll of the linear model at the trim: (period s, damping ratio).
fn linear_dutch_roll(scene: &AircraftScene) -> Option<(f64, f64)> {
    let linear = linearise_aircraft(scene).ok()?;
    let mode = linear.modes.iter().find(|m| m.name == Some("Dutch roll"))?;
    Some((mode.period_s?, mode.damping_ratio?))
}

fn figures(scene: &AircraftScene, run: &AircraftRun, kick: bool) -> (Named, Vec<String>) {
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
        if let Some((period, damping)) = linear_dutch_roll(scene) {
            figures.push(("dutch_roll_period_linear_s".into(), period));
            figures.push(("dutch_roll_damping_linear".into(), damping));
        }
    }
    (Named(figures), notes)
}

/// Runs every manoeuvre of `scene` from its trim, each one's rows to `recorder`.
pub fn run_scene<'a>(
    scene: &'a AircraftScene,
    name: &str,
    recorder: &mut dyn Recorder,
) -> Result<Finished<'a>, KindError> {
    let started = std::time::Instant::now();
    let columns = scene.labelled_columns();
    let mut section = AircraftSection {
        units: units(scene.units).into_iter().collect(),
        trim: trim_summary(scene),
        manoeuvre: BTreeMap::new(),
        stop_when: scene.stop.as_ref().map(|s| s.text.clone()),
    };
    let (mut steps, mut evals, mut runs, mut stopped) = (0, 0, Vec::new(), false);
    for manoeuvre in &scene.manoeuvres {
        if recorder.stop_asked() {
            stopped = true;
            break;
        }
        let expected = (manoeuvre.duration / scene.every).ceil() as usize + 1;
        recorder
            .begin(RunStart {
                path: &manoeuvre.name,
                columns: &columns,
                expected_rows: expected,
                end_time: manoeuvre.duration,
                potential: false,
                energy_unit: scene.energy_unit(),
            })
            .map_err(KindError::Output)?;
        let mut curves: Vec<(f64, [f64; 18])> = Vec::new();
        let stride = (expected / 2000).max(1);
        let mut count = 0usize;
        let done = manoeuvre::run(
            &scene.model,
            scene.kinematics,
            manoeuvre,
            (&scene.trim.state, &scene.trim.controls),
            (&scene.stepper, scene.every),
            scene.stop.as_ref(),
            |sample| {
                if count.is_multiple_of(stride) {
                    curves.push((sample.t, sample.row));
                }
                count += 1;
                recorder.row(&Row {
                    t: sample.t,
                    state: &sample.row,
                    kinetic_energy: sample.kinetic,
                    potential_energy: None,
                })
            },
        );
        let done = match done {
            Ok(done) => done,
            Err(RunError::Stopped { .. }) => {
                recorder.end().map_err(KindError::Output)?;
                stopped = true;
                break;
            }
            Err(error) => {
                let message = format!("manoeuvre {}: {error}", manoeuvre.name);
                return Err(KindError::Run(message.into()));
            }
        };
        recorder.end().map_err(KindError::Output)?;
        recorder
            .drawn(drawings(scene, &manoeuvre.name, &curves))
            .map_err(KindError::Output)?;
        steps += done.steps;
        evals += done.rhs_evals;
        let kick = manoeuvre.kind == manoeuvre::Manoeuvre::RudderKick;
        let (named, mut notes) = figures(scene, &done, kick);
        if let Some(t) = done.stopped_at {
            notes.push(format!(
                "stopped at t = {t} s where `{}` first held (integrator.stop_when): the figures \
                 are of the run up to there",
                section.stop_when.as_deref().unwrap_or_default()
            ));
        }
        runs.push(RunFigures {
            run: manoeuvre.name.clone(),
            figures: (named.0.iter())
                .map(|(key, value)| Figure {
                    key: key.clone(),
                    value: Some(*value),
                    difference: None,
                })
                .collect(),
            refinement: None,
            largest_difference: None,
            notes: notes.clone(),
        });
        section.manoeuvre.insert(
            manoeuvre.name.clone(),
            ManoeuvreSummary {
                figures: named,
                notes,
                steps_taken: done.steps,
                stopped_at: done.stopped_at,
            },
        );
    }
    let stepper = &scene.stepper;
    let summary = Summary {
        kind: super::kind::KIND.name,
        scene: name.to_owned(),
        title: scene.title.clone(),
        integrator: IntegratorSummary {
            steps,
            rhs_evals: Some(evals),
            ..IntegratorSummary::settings(stepper.method, stepper.step, stepper.adaptive)
        },
        wall_seconds: started.elapsed().as_secs_f64(),
        interrupted: stopped,
        error: None,
        warnings: Vec::new(),
        case: None,
        runs,
        verdicts: Vec::new(),
        section,
    };
    let ran = summary.runs.len();
    Ok(Finished {
        scene,
        summary,
        stopped,
        ran,
    })
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
fn drawings(scene: &AircraftScene, path: &str, rows: &[(f64, [f64; 18])]) -> RunDrawings {
    let curve = |name: &str, column: usize, scale: f64| {
        let points = rows
            .iter()
            .map(|(t, row)| (*t, row[column] * scale))
            .collect();
        (name.to_owned(), points)
    };
    let degrees = 180.0 / std::f64::consts::PI;
    let column = |name: &str| ROW.iter().position(|c| *c == name).unwrap_or(0);
    RunDrawings {
        path: path.to_owned(),
        drawings: vec![
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
            Drawing::Flight(Flight {
                title: format!("{}: {path}", scene.title),
                solid: scene.solid(),
                span: scene.span,
                chord: scene.chord,
                length_unit: units(scene.units)[9].1,
            }),
            Drawing::Curves(Curves {
                file: "load_factor.svg".into(),
                caption: format!("{}: {path}, load factor", scene.title),
                x_desc: "t (s)".into(),
                y_desc: "n_z (g)".into(),
                curves: vec![curve("n_z", column("load_factor"), 1.0)],
            }),
        ],
    }
}

impl Finished<'_> {
    /// The report as the command prints it.
    pub fn report(&self) -> String {
        let mut out = String::new();
        let scene = self.scene;
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
        for (name, m) in &self.summary.section.manoeuvre {
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
    pub fn cells(&self, _case: &TableCase) -> Vec<(String, String)> {
        let mut cells = Vec::new();
        for manoeuvre in &self.scene.manoeuvres {
            let Some(m) = self.summary.section.manoeuvre.get(&manoeuvre.name) else {
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
}
