//! What every scene is, whatever its kind: [`Kind`], what the command, a sweep, a Monte Carlo
//! and the Python module need of any scene, and what its run gives, [`Finished`]. The kinds
//! themselves, and the registry that lists them, are in [`crate::kinds`]; the one runner of
//! their runs is [`crate::run::scene`].

use crate::linear::Linearisation;
use crate::models::DynModel;
use crate::output::summary::{RunFigures, Summary, Verdict};
use crate::run::record::Recorder;
use crate::run::scene::SceneRuns;
use crate::run::tradeoff::Tradeoff;
use crate::scene::SceneError;
use crate::scene::sweep::TableCase;
use std::any::Any;

/// What every kind has by saying its runs ([`SceneRuns`]): its name and title, the scene's run
/// through the one runner ([`crate::run::scene::run`]), and the scene as its own type.
pub trait RunScene {
    /// The kind's name, as the registry lists it (`ship`, `vehicle`).
    fn kind(&self) -> &'static str;

    /// The scene's title.
    fn title(&self) -> &str;

    /// The scene as its own type, for a library user who knows the kind
    /// (`scene.as_any().downcast_ref::<S>()`, `S` the kind's scene type).
    fn as_any(&self) -> &dyn Any;

    /// The scene as its own type, owned ([`crate::scene::AnyScene::downcast`]).
    fn into_any(self: Box<Self>) -> Box<dyn Any>;

    /// Runs every run the scene asks for, in order, each one's rows to `recorder` (`name` is
    /// the scene's file, as the summary names it). A run the recorder stops ends the scene's,
    /// keeping the runs before it ([`Finished::stopped`]); a run that fails is kept as failed
    /// beside the runs that finished ([`Finished::failure`]). An error is the recorder's or
    /// the model's that could not be built.
    fn run(
        &self,
        name: &str,
        recorder: &mut dyn Recorder,
    ) -> Result<Box<dyn Finished + '_>, KindError>;
}

impl<K: SceneRuns + 'static> RunScene for K {
    fn kind(&self) -> &'static str {
        self.kind_name()
    }

    fn title(&self) -> &str {
        self.scene_title()
    }

    fn as_any(&self) -> &dyn Any {
        self
    }

    fn into_any(self: Box<Self>) -> Box<dyn Any> {
        self
    }

    fn run(
        &self,
        name: &str,
        recorder: &mut dyn Recorder,
    ) -> Result<Box<dyn Finished + '_>, KindError> {
        Ok(Box::new(crate::run::scene::run(self, name, recorder)?))
    }
}

/// What every scene is, whatever its kind: its title, the runs it asks for and what they
/// write, the run itself (rows to a [`Recorder`], figures into a [`Finished`]: [`RunScene`],
/// which every kind has by saying its runs to the one runner, [`SceneRuns`]), and its linear
/// plant. The command runs, sweeps, shards, guards and reports a scene through this alone.
pub trait Kind: RunScene + Send + Sync + std::fmt::Debug {
    /// The entries its run writes at the top of its output folder besides `summary.json`
    /// (each manoeuvre's folder), for the folder's claim.
    fn folders(&self) -> Vec<String>;

    /// About how many numbers its trajectories hold (rows × columns, every run), for the
    /// output-size guard.
    fn trajectory_numbers(&self) -> f64;

    /// The scene linearised at its operating point (`[linear]`, or its own: a ship's straight
    /// course, a vehicle's cruise), with what the kind adds to the report.
    fn linear(&self) -> Result<Linearised, KindError>;

    /// Its integrators compared over its run (`eom tradeoff`: every method over its steps or
    /// tolerances, each end state against a reference), for a kind whose scene is one run
    /// it can repeat; `None` for a kind that does not compare them.
    fn tradeoff(&self) -> Option<Result<Tradeoff, KindError>> {
        None
    }

    /// The model the scene runs, as it stands (no loads, schedules or steering gear): its
    /// names, `rhs` and proved Jacobians for any caller, sizes known at run time (a binding
    /// evaluating it over many states). `None` for a kind that does not give it.
    fn model(&self) -> Option<Result<Box<dyn DynModel>, KindError>> {
        None
    }

    /// The scene with each number at its key path (as `[sweep]` and `[uncertainty]` name
    /// them) set to its value, taken into the scene as read, without reading its tables again
    /// (a Monte Carlo's case); `None` where the kind does not, and the caller reads the
    /// tables with the numbers set in them. Either way the scene is the same, bit for bit.
    fn with_numbers(
        &self,
        _name: &str,
        _numbers: &[(&str, f64)],
    ) -> Option<Result<Box<dyn Kind>, SceneError>> {
        None
    }
}

/// What a scene's run gave: the summary, the report, a sweep case's line.
pub trait Finished: std::fmt::Debug {
    /// `summary.json` as the library builds it for every kind: the shared keys, each run's
    /// figures and the verdicts, and the kind's own section as a JSON value (its objects'
    /// keys sorted).
    fn summary(&self) -> Summary;

    /// Each run's figures and the verdicts, as [`Self::summary`] gives them, without building
    /// its JSON: what a Monte Carlo's case reads.
    fn figures(&self) -> (&[RunFigures], &[Verdict]);

    /// `summary.json` as written: [`Self::summary`], pretty-printed, with a sweep case's
    /// number and values under `"case"`. A kind whose section has an order of its own (a
    /// body's: its model, where it ended, then its figures) writes it in that order.
    fn summary_file(&self, case: Option<&TableCase>) -> Vec<u8> {
        self.summary().file(case)
    }

    /// The report as the command prints it (the folder it wrote aside).
    fn report(&self) -> String;

    /// Each column of a sweep's table after the case and its swept values, with its value
    /// in this run (empty where it gave none), in the table's order.
    fn cells(&self, case: &TableCase) -> Vec<(String, String)>;

    /// Whether the recorder stopped the run before every run the scene asks for had run.
    fn stopped(&self) -> bool;

    /// What a run that stopped early kept, in words (`the 2 manoeuvres finished before it,
    /// and summary.json`; `every row up to t = 3 s of 10 s in trajectory.csv, …`).
    fn kept(&self) -> String;

    /// Why the run failed where it failed, having kept what it ran (a body's run that came
    /// to gimbal lock: its rows, its drawings and a summary that gives the error); `None`
    /// for a run that did not fail. The command writes what was kept, then exits as for a
    /// failed run.
    fn failure(&self) -> Option<KindError> {
        None
    }

    /// What the run did not stop for but a reader should know (a fixed step past its
    /// accuracy bound), for the command to say beside the report; also in the summary.
    fn warnings(&self) -> Vec<String> {
        Vec::new()
    }
}

/// A scene's linearisation and what its kind adds to the report beside every scene's: text
/// after the text report, keys in the JSON report.
#[derive(Debug, Clone)]
pub struct Linearised {
    /// A, B, the modes, the verdict.
    pub linearisation: Linearisation,
    /// Lines after the text report (a ship's Nomoto models), empty for none.
    pub text: String,
    /// Keys added to the JSON report.
    pub json: serde_json::Map<String, serde_json::Value>,
}

impl Linearised {
    /// A linearisation that the kind adds nothing to.
    pub fn alone(linearisation: Linearisation) -> Self {
        Linearised {
            linearisation,
            text: String::new(),
            json: serde_json::Map::new(),
        }
    }
}

/// Why a scene of some kind could not be run or linearised, by what the command's exit code
/// says of it; each carries the kind's own error, whose message it gives.
#[derive(Debug, thiserror::Error)]
pub enum KindError {
    /// A value of the scene that cannot be used (exit 3).
    #[error(transparent)]
    Scene(Box<dyn std::error::Error + Send + Sync>),
    /// A run that cannot go on (exit 5).
    #[error(transparent)]
    Run(Box<dyn std::error::Error + Send + Sync>),
    /// A run its recorder stopped (Ctrl-C).
    #[error(transparent)]
    Stopped(Box<dyn std::error::Error + Send + Sync>),
    /// What a run gave could not be kept: a file not written (exit 4).
    #[error(transparent)]
    Output(Box<dyn std::error::Error + Send + Sync>),
    /// The model could not be built or proved (exit 1).
    #[error(transparent)]
    Internal(Box<dyn std::error::Error + Send + Sync>),
}

impl KindError {
    /// The message with every cause after it (`manoeuvre turn: at t = 3 s, …`), as the
    /// summary's `error` gives it.
    pub fn message(&self) -> String {
        let mut message = self.to_string();
        let mut cause = std::error::Error::source(self);
        while let Some(error) = cause {
            message = format!("{message}: {error}");
            cause = error.source();
        }
        message
    }

    /// An error of the same class whose message is `message` (a failure kept in a finished
    /// run, given again to each caller that asks).
    pub fn restated(&self, message: &str) -> KindError {
        let message: Box<dyn std::error::Error + Send + Sync> = message.into();
        match self {
            KindError::Scene(_) => KindError::Scene(message),
            KindError::Run(_) => KindError::Run(message),
            KindError::Stopped(_) => KindError::Stopped(message),
            KindError::Output(_) => KindError::Output(message),
            KindError::Internal(_) => KindError::Internal(message),
        }
    }
}

impl From<crate::linear::LinearError> for KindError {
    /// A point the scene names that cannot be used is the scene's; a trim that does not
    /// converge, the run's.
    fn from(error: crate::linear::LinearError) -> Self {
        match error.is_scene_error() {
            true => KindError::Scene(Box::new(error)),
            false => KindError::Run(Box::new(error)),
        }
    }
}
