//! The one scene runner: what happens between "a scene" and "one run", for every kind.
//!
//! A kind says what its runs are ([`SceneRuns`]): their paths and columns, how one is run
//! with the scene's method or refined, what its figures are and how far they moved, what it
//! draws, and what its section of the summary, its report and a sweep's cells say of the runs
//! that finished. [`run`] does the rest once: the loop over the runs, the recorder (each run
//! begun, its rows, its end, its drawings), the stop a caller asks for, the refined run and
//! its differences, a run that fails (kept beside the runs that finished, the others still
//! run: every run of a scene starts from the scene's own start), and the one [`Summary`].
//! A Monte Carlo's case runs here too, through a recorder that keeps no rows
//! ([`Recorder::keeps_rows`]: its runs build none and draw nothing) and asks for no refined
//! run ([`Recorder::refines`]).
//!
//! ```
//! use eom::run::record::Discard;
//! use eom::scene::AnyScene;
//!
//! // Every kind runs through the one runner; a failed run keeps what finished.
//! let scene = AnyScene::load("scenes/navion.toml".as_ref())?.into_kind();
//! let finished = scene.run("navion.toml", &mut Discard)?;
//! assert!(finished.failure().is_none());
//! let (runs, _) = finished.figures();
//! // The aircraft's figures, each with how far it moved when the run was refined.
//! assert!(runs.iter().all(|run| run.refinement.is_some()));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::Row;
use super::record::{Recorder, RunStart};
use crate::integrate::Stepper;
use crate::kind::{Finished, KindError};
use crate::output::drawing::{Drawing, RunDrawings};
use crate::output::summary::{IntegratorSummary, RunFigures, Summary, Verdict};
use crate::scene::sweep::TableCase;
use serde::Serialize;
use std::time::Instant;

/// One run a scene asks for, as its kind says it before it runs.
#[derive(Debug, Clone, PartialEq)]
pub struct RunPlan {
    /// Its path under the output (`turning_circle_35/port`); empty for a scene's one run.
    pub path: String,
    /// The state columns of each row, after the time.
    pub columns: Vec<String>,
    /// About how many rows it gives.
    pub expected_rows: usize,
    /// The time it runs to, s.
    pub end_time: f64,
    /// Whether its rows carry a potential energy.
    pub potential: bool,
    /// The energies' unit.
    pub energy_unit: &'static str,
}

/// With what a run is integrated: the scene's method as written, or refined (half the step,
/// or tolerances a hundred times tighter) for how far its figures move.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Setting {
    /// The scene's method and settings.
    Scene,
    /// The same, refined.
    Refined,
}

impl Setting {
    /// The method a run steps with at this setting: `stepper` as the scene gave it, or
    /// refined ([`Stepper::refined`], `every` the rows' interval it keeps landing on).
    pub fn stepper(self, stepper: &Stepper, every: f64) -> Stepper {
        match self {
            Setting::Scene => stepper.clone(),
            Setting::Refined => stepper.refined(every),
        }
    }
}

/// Where a run's rows go: the caller's recorder, or, for a run whose rows nobody keeps (a
/// refined run, a Monte Carlo's case), nowhere but the check whether the caller asked to
/// stop.
pub struct Rows<'a> {
    recorder: &'a mut dyn Recorder,
    keeps: bool,
    taken: usize,
    ended_by_caller: bool,
}

impl<'a> Rows<'a> {
    fn new(recorder: &'a mut dyn Recorder, keeps: bool) -> Self {
        Rows {
            recorder,
            keeps,
            taken: 0,
            ended_by_caller: false,
        }
    }

    /// How a run through these rows ended: where the caller ended it (a row refused, a stop
    /// asked for), its failure is the caller's stop ([`KindError::Stopped`]), whatever the
    /// kind said of it; so no kind says a stop of its own.
    fn ended<O>(&self, done: Result<O, Failed<O>>) -> Result<O, Failed<O>> {
        match done {
            Err(Failed { error, kept }) if self.ended_by_caller => Err(Failed {
                error: match error {
                    KindError::Stopped(_) => error,
                    error => KindError::Stopped(Box::new(error)),
                },
                kept,
            }),
            done => done,
        }
    }

    /// Whether the rows are kept: a run whose rows are not need not build them.
    pub fn keeps(&self) -> bool {
        self.keeps
    }

    /// Whether the caller asked the run to stop; a run told so ends, and the runner counts
    /// how it ended as the caller's stop, whatever error the kind gives for it.
    pub fn stop_asked(&mut self) -> bool {
        let asked = self.recorder.stop_asked();
        self.ended_by_caller |= asked;
        asked
    }

    /// Takes one row; `false` ends the run (the recorder refused it, or a stop was asked),
    /// and the runner counts how it ended as the caller's stop.
    pub fn take(&mut self, row: &Row) -> bool {
        if !self.keeps {
            return !self.stop_asked();
        }
        let taken = self.recorder.row(row);
        self.taken += usize::from(taken);
        self.ended_by_caller |= !taken;
        taken
    }

    /// Takes the row at `t` that `row` builds (its state and kinetic energy; no potential),
    /// built only where the rows are kept; `false` ends the run, as [`take`](Self::take).
    pub fn take_built<const N: usize>(
        &mut self,
        t: f64,
        row: impl FnOnce() -> ([f64; N], f64),
    ) -> bool {
        if !self.keeps {
            return !self.stop_asked();
        }
        let (state, kinetic_energy) = row();
        self.take(&Row {
            t,
            state: &state,
            kinetic_energy,
            potential_energy: None,
        })
    }

    /// How many rows the recorder took.
    pub fn taken(&self) -> usize {
        self.taken
    }
}

impl super::Sink for Rows<'_> {
    fn row(&mut self, row: &Row) -> bool {
        self.take(row)
    }
}

/// A run that did not reach its end: why (a stop asked for is [`KindError::Stopped`]), and
/// what it gave up to there, where its kind keeps that (a body's rows, energy and end state).
#[derive(Debug)]
pub struct Failed<O> {
    /// Why it ended early.
    pub error: KindError,
    /// What it gave up to there, if anything is worth keeping.
    pub kept: Option<O>,
}

impl<O> From<KindError> for Failed<O> {
    fn from(error: KindError) -> Self {
        Failed { error, kept: None }
    }
}

/// What one run gave, for every kind: the kind's own result of the run with the scene's
/// method, what it cost, and the same run's result refined, where the runner refined it (a
/// kind's figures say how far they moved from it).
#[derive(Debug, Clone)]
pub struct Outcome<G> {
    /// What the kind's run gave: its figures, and what its drawings, report and cells read.
    pub gave: G,
    /// What the run cost.
    pub counts: Counts,
    /// The refined run: what it gave, or why it did not finish (the error's message with its
    /// causes); `None` where it was not run (a Monte Carlo's case, a run that gave no figure).
    pub refinement: Option<Result<G, String>>,
}

impl<G> Outcome<G> {
    /// What a run gave at `counts`, not refined (yet).
    pub fn new(gave: G, counts: Counts) -> Self {
        Outcome {
            gave,
            counts,
            refinement: None,
        }
    }

    /// What the refined run gave, where it ran and finished.
    pub fn refined(&self) -> Option<&G> {
        self.refinement.as_ref()?.as_ref().ok()
    }

    /// Why the refined run did not finish, where it ran and failed.
    pub fn refined_failure(&self) -> Option<&str> {
        self.refinement.as_ref()?.as_ref().err().map(String::as_str)
    }
}

/// How one run ended: what it gave, or why it failed and what it gave up to there.
pub type RunResult<G> = Result<Outcome<G>, Failed<Outcome<G>>>;

/// What an integration cost, summed over a scene's runs for its summary.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Counts {
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps, where the kind counts them.
    pub rejected: Option<u64>,
    /// Right-hand-side evaluations.
    pub rhs_evals: u64,
}

/// What a kind says of the runs that finished, once they have: its section of the summary,
/// the verdicts judged on them, and what a reader should know.
#[derive(Debug)]
pub struct Closing<Section> {
    /// The kind's section of `summary.json`.
    pub section: Section,
    /// The verdicts (a ship's IMO criteria).
    pub verdicts: Vec<Verdict>,
    /// Warnings beside the summary's.
    pub warnings: Vec<String>,
}

/// A kind's scene as the runner sees it: what its runs are, how each runs, and what is said
/// of them. Implemented by each kind's scene; [`crate::kind::Kind::run`] is [`run`] over it.
pub trait SceneRuns: Sync {
    /// What every run of one scene's run shares, made once before the first (a ship's
    /// model, derived and proved; nothing for a kind whose scene holds its model).
    type Shared;
    /// What one run of this kind gives: its figures, and what its drawings, report and cells
    /// read (the runner keeps it in an [`Outcome`], with its cost and its refined run's).
    type Gave;
    /// The kind's section of the summary.
    type Section: Serialize + Clone + std::fmt::Debug;

    /// The kind's name, as the registry lists it.
    fn kind_name(&self) -> &'static str;

    /// The scene's title.
    fn scene_title(&self) -> &str;

    /// The method and its settings, before any step is counted.
    fn integrator(&self) -> IntegratorSummary;

    /// What the runs share, made once.
    fn prepare(&self) -> Result<Self::Shared, KindError>;

    /// The runs the scene asks for, in order.
    fn plans(&self, shared: &Self::Shared) -> Vec<RunPlan>;

    /// Runs run `index` of [`Self::plans`] with `setting`, its rows to `rows`.
    fn run_one(
        &self,
        shared: &Self::Shared,
        index: usize,
        setting: Setting,
        rows: &mut Rows,
    ) -> RunResult<Self::Gave>;

    /// Whether a run that gave `gave` is worth running again refined (a body that gave no
    /// figure is not).
    fn worth_refining(&self, _gave: &Self::Gave) -> bool {
        true
    }

    /// What a reader should know of the refined run of `outcome`, once it ran: why it
    /// failed, or a figure it did not give.
    fn refined_warnings(&self, outcome: &Outcome<Self::Gave>) -> Vec<String>;

    /// The run's figures in the shape every kind gives them.
    fn figures(&self, plan: &RunPlan, outcome: &Outcome<Self::Gave>) -> RunFigures;

    /// What the run draws, once its figures are known.
    fn drawings(
        &self,
        shared: &Self::Shared,
        index: usize,
        outcome: &Outcome<Self::Gave>,
    ) -> Vec<Drawing>;

    /// The section, verdicts and warnings of the runs that finished.
    fn close(&self, ran: &Ran<'_, Self>) -> Closing<Self::Section>;

    /// The report as the command prints it.
    fn report(&self, ran: &Ran<'_, Self>) -> String;

    /// Each column of a sweep's table after the case and its swept values, with its value in
    /// this run, in the table's order.
    fn cells(&self, ran: &Ran<'_, Self>, case: &TableCase) -> Vec<(String, String)>;

    /// What a run that ended early kept, in words: the summary and the runs that finished.
    fn kept(&self, ran: &Ran<'_, Self>) -> String {
        let finished: Vec<&str> = (ran.outcomes.iter())
            .map(|(index, _)| ran.plans[*index].path.as_str())
            .collect();
        match finished.is_empty() {
            true => "summary.json (no run finished)".to_owned(),
            false => format!(
                "summary.json and the {} that finished ({})",
                crate::counted(finished.len(), "run", "runs"),
                finished.join(", ")
            ),
        }
    }

    /// `summary.json` as written: the section's objects' keys sorted, as a ship's and a
    /// vehicle's have always been written; a kind whose section has an order of its own (a
    /// body's) writes it in that order.
    fn summary_file(&self, summary: &Summary<Self::Section>, case: Option<&TableCase>) -> Vec<u8> {
        summary.clone().into_json().file(case)
    }
}

/// What a scene's runs gave: the shared part, each finished run's outcome by its index, and
/// how the scene's run ended.
pub struct Ran<'a, K: SceneRuns + ?Sized> {
    /// The scene.
    pub scene: &'a K,
    /// What the runs shared.
    pub shared: K::Shared,
    /// The plans of every run, in order.
    pub plans: Vec<RunPlan>,
    /// Each run that gave an outcome (finished, or failed keeping what it ran), by index.
    pub outcomes: Vec<(usize, Outcome<K::Gave>)>,
    /// Each run that failed, by index, with why.
    pub failures: Vec<(usize, KindError)>,
    /// Whether the caller stopped the runs.
    pub stopped: bool,
}

impl<K: SceneRuns + ?Sized> Ran<'_, K> {
    /// The outcome of run `index`, if it gave one.
    pub fn outcome(&self, index: usize) -> Option<&Outcome<K::Gave>> {
        (self.outcomes.iter()).find_map(|(i, outcome)| (*i == index).then_some(outcome))
    }

    /// Why run `index` failed, if it did.
    pub fn failure(&self, index: usize) -> Option<&KindError> {
        (self.failures.iter()).find_map(|(i, error)| (*i == index).then_some(error))
    }
}

/// What a scene's run gave, for every kind: the summary, and what the report, a sweep's cells
/// and the command read.
pub struct SceneFinished<'a, K: SceneRuns + ?Sized> {
    /// The runs and how they ended.
    pub ran: Ran<'a, K>,
    /// `summary.json`.
    pub summary: Summary<K::Section>,
}

impl<K: SceneRuns + ?Sized> std::fmt::Debug for SceneFinished<'_, K> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SceneFinished")
            .field("summary", &self.summary)
            .field("stopped", &self.ran.stopped)
            .finish_non_exhaustive()
    }
}

/// Runs every run `scene` asks for, in order, each one's rows to `recorder` (`name` is the
/// scene's file, as the summary names it): begun, its rows, ended, run again refined where
/// the recorder asks, drawn. A stop asked for ends the scene's run, keeping the runs before
/// it; a run that fails is kept as failed, and the runs after it still run. An error is the
/// recorder's (a file not written) or the preparation's (a model not built).
pub fn run<'a, K: SceneRuns + ?Sized>(
    scene: &'a K,
    name: &str,
    recorder: &mut dyn Recorder,
) -> Result<SceneFinished<'a, K>, KindError> {
    let started = Instant::now();
    let shared = scene.prepare()?;
    let plans = scene.plans(&shared);
    let mut ran = Ran {
        scene,
        shared,
        plans,
        outcomes: Vec::new(),
        failures: Vec::new(),
        stopped: false,
    };
    let mut warnings = Vec::new();
    let mut counts = Counts::default();
    for index in 0..ran.plans.len() {
        // A stop ends the scene's run: the runs after it are not run (neither among the
        // outcomes nor the failures).
        if ran.stopped || recorder.stop_asked() {
            ran.stopped = true;
            break;
        }
        let (outcome, failure, taken) = run_recorded(scene, &ran, index, recorder)?;
        let Some(mut outcome) = outcome else {
            record_failure(&mut ran, index, failure);
            continue;
        };
        add(&mut counts, outcome.counts);
        if failure.is_none() && recorder.refines() && scene.worth_refining(&outcome.gave) {
            let mut quiet = Rows::new(&mut *recorder, false);
            let refined = scene.run_one(&ran.shared, index, Setting::Refined, &mut quiet);
            match quiet.ended(refined) {
                Err(Failed {
                    error: KindError::Stopped(_),
                    ..
                }) => ran.stopped = true,
                refined => {
                    let refined = refined.map(|refined| refined.gave);
                    outcome.refinement = Some(refined.map_err(|failed| failed.error.message()));
                    warnings.extend(scene.refined_warnings(&outcome));
                }
            }
        }
        // A plot needs two rows; a run stopped at its start has at most one.
        if taken >= 2 {
            let drawings = scene.drawings(&ran.shared, index, &outcome);
            let path = ran.plans[index].path.clone();
            (recorder.drawn(RunDrawings { path, drawings })).map_err(KindError::Output)?;
        }
        ran.outcomes.push((index, outcome));
        record_failure(&mut ran, index, failure);
    }
    let closing = scene.close(&ran);
    let summary = summary(scene, &ran, (name, started), counts, closing, warnings);
    Ok(SceneFinished { ran, summary })
}

/// A failure into `ran`: a stop ends the scene's run; any other is the run's.
fn record_failure<K: SceneRuns + ?Sized>(
    ran: &mut Ran<'_, K>,
    index: usize,
    failure: Option<KindError>,
) {
    match failure {
        Some(KindError::Stopped(_)) => ran.stopped = true,
        Some(error) => ran.failures.push((index, error)),
        None => {}
    }
}

/// What a run with the scene's method gave: its outcome (or what it kept where it failed),
/// why it failed, and how many rows the recorder took.
type Recorded<G> = (Option<Outcome<G>>, Option<KindError>, usize);

/// Runs run `index` with the scene's method into the recorder: begun, its rows, ended. An
/// error is the recorder's alone.
fn run_recorded<K: SceneRuns + ?Sized>(
    scene: &K,
    ran: &Ran<'_, K>,
    index: usize,
    recorder: &mut dyn Recorder,
) -> Result<Recorded<K::Gave>, KindError> {
    let plan = &ran.plans[index];
    let keeps = recorder.keeps_rows();
    recorder
        .begin(RunStart {
            path: &plan.path,
            columns: &plan.columns,
            expected_rows: plan.expected_rows,
            end_time: plan.end_time,
            potential: plan.potential,
            energy_unit: plan.energy_unit,
        })
        .map_err(KindError::Output)?;
    let mut rows = Rows::new(&mut *recorder, keeps);
    let done = scene.run_one(&ran.shared, index, Setting::Scene, &mut rows);
    let done = rows.ended(done);
    let taken = rows.taken;
    // What the recorder could not keep comes first: the run stopped because of it.
    recorder.end().map_err(KindError::Output)?;
    Ok(match done {
        Ok(outcome) => (Some(outcome), None, taken),
        Err(Failed { error, kept }) => (kept, Some(error), taken),
    })
}

fn add(total: &mut Counts, counts: Counts) {
    total.steps += counts.steps;
    total.rhs_evals += counts.rhs_evals;
    total.rejected = match (total.rejected, counts.rejected) {
        (None, None) => None,
        (a, b) => Some(a.unwrap_or(0) + b.unwrap_or(0)),
    };
}

/// The one summary of a scene's run: the shared keys, each finished run's figures, the
/// kind's section and verdicts, the error of a run that failed.
fn summary<K: SceneRuns + ?Sized>(
    scene: &K,
    ran: &Ran<'_, K>,
    (name, started): (&str, Instant),
    counts: Counts,
    closing: Closing<K::Section>,
    refined_warnings: Vec<String>,
) -> Summary<K::Section> {
    let integrator = IntegratorSummary {
        steps: counts.steps,
        rejected: counts.rejected,
        rhs_evals: Some(counts.rhs_evals),
        ..scene.integrator()
    };
    let errors: Vec<String> = (ran.failures.iter())
        .map(|(_, error)| error.message())
        .collect();
    let mut warnings = closing.warnings;
    warnings.extend(refined_warnings);
    Summary {
        kind: scene.kind_name(),
        scene: name.to_owned(),
        title: scene.scene_title().to_owned(),
        integrator,
        wall_seconds: started.elapsed().as_secs_f64(),
        interrupted: ran.stopped,
        error: (!errors.is_empty()).then(|| errors.join("; ")),
        warnings,
        case: None,
        runs: (ran.outcomes.iter())
            .map(|(index, outcome)| scene.figures(&ran.plans[*index], outcome))
            .collect(),
        verdicts: closing.verdicts,
        section: closing.section,
    }
}

impl<K: SceneRuns + ?Sized> Finished for SceneFinished<'_, K> {
    fn summary(&self) -> Summary {
        self.summary.clone().into_json()
    }

    fn figures(&self) -> (&[RunFigures], &[Verdict]) {
        (&self.summary.runs, &self.summary.verdicts)
    }

    fn summary_file(&self, case: Option<&TableCase>) -> Vec<u8> {
        self.ran.scene.summary_file(&self.summary, case)
    }

    fn report(&self) -> String {
        self.ran.scene.report(&self.ran)
    }

    fn cells(&self, case: &TableCase) -> Vec<(String, String)> {
        self.ran.scene.cells(&self.ran, case)
    }

    fn stopped(&self) -> bool {
        self.ran.stopped
    }

    fn kept(&self) -> String {
        self.ran.scene.kept(&self.ran)
    }

    /// The failed runs' errors as the summary's `error` gives them (each, in order), of the
    /// first one's class.
    fn failure(&self) -> Option<KindError> {
        let (_, first) = self.ran.failures.first()?;
        Some(first.restated(self.summary.error.as_deref().unwrap_or_default()))
    }

    fn warnings(&self) -> Vec<String> {
        self.summary.warnings.clone()
    }
}
