//! The kinds of scene: what a scene is, beyond the envelope every scene shares.
//!
//! A catalog body's scene selects a variant the build generated; a ship's and a vehicle's
//! define their model by their own table, derived and proved when the scene is read. Each of
//! these lives in its folder here, with its tables, keys, manoeuvres and figures, implements
//! [`Kind`] (what the command and a library user need of any scene: its runs, its rows, its
//! summary, its report, its drawings, its linear plant), and has one line in [`REGISTRY`], the
//! only list of them. None imports another: what two kinds share is in the layers below them
//! ([`crate::models`]: the catalog, an attitude's Euler angles; [`crate::manoeuvring`]: the
//! steering gear, the course; [`crate::scene::envelope`]: the tables every scene with
//! manoeuvres writes; [`crate::output::summary`]: the one summary every kind builds;
//! [`crate::output::drawing`]: what a run draws; [`crate::run::record`]: where its rows go).
//! A test below holds that.
//!
//! A scene of any kind is loaded through one entry, says which kind it is, and runs to its
//! summary without the command; here the Mariner's manoeuvres, with a recorder that counts
//! each run's rows:
//!
//! ```
//! use eom::output::drawing::RunDrawings;
//! use eom::run::Row;
//! use eom::run::record::{RecordError, Recorder, RunStart};
//! use eom::scene::AnyScene;
//!
//! /// How many rows each run gave, by its path (`turning_circle_35/port`).
//! #[derive(Default)]
//! struct Counted(Vec<(String, usize)>);
//!
//! impl Recorder for Counted {
//!     fn begin(&mut self, run: RunStart) -> Result<(), RecordError> {
//!         self.0.push((run.path.to_owned(), 0));
//!         Ok(())
//!     }
//!     fn row(&mut self, _: &Row) -> bool {
//!         self.0.last_mut().map(|(_, rows)| *rows += 1);
//!         true // false would stop the run here
//!     }
//!     fn end(&mut self) -> Result<(), RecordError> {
//!         Ok(())
//!     }
//!     fn drawn(&mut self, _: RunDrawings) -> Result<(), RecordError> {
//!         Ok(())
//!     }
//!     fn stop_asked(&self) -> bool {
//!         false
//!     }
//! }
//!
//! let mariner = AnyScene::load("scenes/mariner.toml".as_ref())?.into_kind();
//! assert_eq!(mariner.kind(), "ship");
//! let mut counted = Counted::default();
//! let finished = mariner.run("mariner.toml", &mut counted)?;
//! assert_eq!(counted.0[0], ("turning_circle_35/port".to_owned(), 1504)); // a row a second
//! // summary.json as the command writes it: the turn's worse side, and the IMO verdicts.
//! let summary = finished.summary();
//! let turn = &summary.section["manoeuvre"]["turning_circle_35"];
//! assert!((turn["tactical_diameter_m"].as_f64().unwrap() - 1178.27).abs() < 0.01);
//! assert_eq!(summary.section["manoeuvre"]["imo"][0]["criterion"], "advance");
//! assert_eq!(summary.section["manoeuvre"]["imo"][0]["pass"], true);
//! // The same figures and verdicts in the shape every kind gives them.
//! let diameter = summary.figure("turning_circle_35/port", "tactical_diameter_m");
//! assert!((diameter.unwrap() - 1178.27).abs() < 0.01);
//! assert_eq!(summary.verdicts[0].name, "advance");
//! assert_eq!(summary.verdicts[0].pass, Some(true));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#[cfg(feature = "ship")]
pub mod aircraft;
pub mod body;
#[cfg(feature = "ship")]
pub mod ship;
#[cfg(feature = "ship")]
pub mod vehicle;

use crate::linear::Linearisation;
use crate::models::DynModel;
use crate::output::summary::{RunFigures, Summary, Verdict};
use crate::run::record::Recorder;
use crate::run::tradeoff::Tradeoff;
use crate::scene::SceneError;
use crate::scene::reference::{Key, SceneFamily};
use crate::scene::sweep::TableCase;
use std::any::Any;
use std::path::Path;

/// What every scene is, whatever its kind: its title, the runs it asks for and what they
/// write, the run itself (rows to a [`Recorder`], figures into a [`Finished`]), and its linear
/// plant. The command runs, sweeps, shards, guards and reports a scene through this alone.
pub trait Kind: Send + Sync + std::fmt::Debug {
    /// The kind's name, as the registry lists it (`ship`, `vehicle`).
    fn kind(&self) -> &'static str;

    /// The scene's title.
    fn title(&self) -> &str;

    /// The entries its run writes at the top of its output folder besides `summary.json`
    /// (each manoeuvre's folder), for the folder's claim.
    fn folders(&self) -> Vec<String>;

    /// About how many numbers its trajectories hold (rows × columns, every run), for the
    /// output-size guard.
    fn trajectory_numbers(&self) -> f64;

    /// Runs every run the scene asks for, in order, each one's rows to `recorder` (`name` is
    /// the scene's file, as the summary names it). A run the recorder stops ends the scene's,
    /// keeping the runs before it: [`Finished::stopped`] says so.
    fn run(
        &self,
        name: &str,
        recorder: &mut dyn Recorder,
    ) -> Result<Box<dyn Finished + '_>, KindError>;

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

    /// The scene as its own type, for a library user who knows the kind
    /// (`scene.as_any().downcast_ref::<ShipScene>()`).
    fn as_any(&self) -> &dyn Any;

    /// The scene as its own type, owned ([`crate::scene::AnyScene::downcast`]).
    fn into_any(self: Box<Self>) -> Box<dyn Any>;
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

/// Where a kind's tables are read from: a scene's text, or one case of a sweep (its tables).
pub enum Source<'a> {
    /// The scene file's text.
    Text(&'a str),
    /// A sweep case's tables.
    Table(toml::Table),
}

impl Source<'_> {
    /// The tables read as `T`, every error naming its key.
    pub fn read<T: serde::de::DeserializeOwned>(self, name: &str) -> Result<T, SceneError> {
        match self {
            Source::Text(text) => crate::scene::read_as(text, name),
            Source::Table(table) => crate::scene::sweep::read_table(table, name),
        }
    }
}

/// How a kind reads and checks a scene: from its tables, the name errors give the file, the
/// folder a file it names is found in.
pub type Reader = fn(Source, &str, &Path) -> Result<Box<dyn Kind>, SceneError>;

/// What the scene reference (docs/scenes.md, `eom new`) says of a kind.
pub struct Reference {
    /// What a scene of it is, in one line (`eom new`'s help, the template's first lines).
    pub doc: &'static str,
    /// Its section's title in docs/scenes.md (`Ship scenes`).
    pub heading: &'static str,
    /// Its section's first paragraph in docs/scenes.md.
    pub intro: &'static str,
    /// The families `eom new` makes a template of (a ship's one; a catalog body's six), in
    /// order; its keys say which of them reads each.
    pub families: &'static [SceneFamily],
    /// Every key it reads, in the order a template writes them.
    pub keys: &'static [Key],
    /// What its section says after the keys (its table's conventions); empty for nothing.
    pub notes: &'static str,
    /// What its trajectory.csv holds.
    pub columns: Columns,
}

/// What a kind's trajectory.csv holds, as the reference page says it.
pub enum Columns {
    /// One list of columns for every scene of the kind: the sentence that says what the file
    /// is (`A ship writes one …`), which the columns end.
    Listed {
        /// The sentence, without its end.
        said: &'static str,
        /// The columns.
        columns: fn() -> Vec<String>,
    },
    /// Columns that differ by the scene's model, written by the kind (a table of layouts).
    Written(fn() -> String),
}

/// A kind of scene as the registry lists it: its name, how its tables are recognised, how
/// they are read and checked, and what the reference says of it.
pub struct Registered {
    /// The kind's name (`ship`).
    pub name: &'static str,
    /// What the scene reference says of it.
    pub reference: Reference,
    /// Whether a scene's tables are this kind's.
    pub recognises: fn(&toml::Table) -> bool,
    /// Whether it reads the scenes no other kind recognises (the catalog body's, whose
    /// checker says what such a scene lacks): it is asked after every other kind, so that a
    /// kind added to the registry is recognised wherever it stands in it.
    pub reads_the_rest: bool,
    /// Reads and checks the scene (`name` is how errors name the file, `base` where a file
    /// it names is found).
    pub read: Reader,
}

/// The kinds of scene: the only list of them, in the order the reference lists them. A scene
/// is the first kind's that recognises its tables, the kind that reads the rest asked last.
pub const REGISTRY: &[Registered] = &[
    body::KIND,
    #[cfg(feature = "ship")]
    ship::KIND,
    #[cfg(feature = "ship")]
    vehicle::KIND,
    #[cfg(feature = "ship")]
    aircraft::KIND,
];

/// What a scene of manoeuvres kept when it stopped early: the `count` it finished, or began
/// and kept a part of, and its summary.
pub(crate) fn manoeuvres_kept(count: usize) -> String {
    format!(
        "the {} finished before it, and summary.json",
        crate::counted(count, "manoeuvre", "manoeuvres")
    )
}

/// The registered kind whose tables `table` are, if one is: the first kind's that recognises
/// them, the kind that reads the rest asked last.
pub fn recognise(table: &toml::Table) -> Option<&'static Registered> {
    let asked = |rest: bool| {
        (REGISTRY.iter()).find(move |kind| kind.reads_the_rest == rest && (kind.recognises)(table))
    };
    asked(false).or_else(|| asked(true))
}

/// The registered kind of this name.
pub fn named(name: &str) -> Option<&'static Registered> {
    REGISTRY.iter().find(|kind| kind.name == name)
}

/// The family a scene's `[model]` names, if it names one.
pub fn family_of(table: &toml::Table) -> Option<&str> {
    table.get("model")?.get("family")?.as_str()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(text: &str) -> toml::Table {
        text.parse().unwrap()
    }

    /// One kind reads what no other recognises, and it is asked last: a kind listed before
    /// it in the registry is still recognised.
    #[test]
    fn each_scene_is_its_own_kind_s_and_the_rest_the_reader_of_the_rest_s() {
        let rest: Vec<&str> = (REGISTRY.iter())
            .filter(|kind| kind.reads_the_rest)
            .map(|kind| kind.name)
            .collect();
        assert_eq!(rest, ["body"]);
        let name = |text: &str| recognise(&table(text)).map(|kind| kind.name);
        assert_eq!(name("[model]\nfamily = \"pendulum\""), Some("body"));
        assert_eq!(name("[model]\nfamily = \"aircraft\""), Some("body"));
        assert_eq!(name(""), Some("body"));
        let hull = "[model]\nfamily = \"planar-midship\"\n[hydrodynamics]";
        let vehicle = "[model]\nfamily = \"vehicle\"\n[hydrodynamics]";
        match cfg!(feature = "ship") {
            true => {
                assert_eq!(name(hull), Some("ship"));
                assert_eq!(name(vehicle), Some("vehicle"));
            }
            // Without the kinds that build such models, none reads them: `AnyScene` says
            // which feature would.
            false => assert_eq!((name(hull), name(vehicle)), (None, None)),
        }
    }
}

#[cfg(test)]
mod tidy {
    //! The map's rules about kinds, held by reading the sources, as a linter would: a rule
    //! written only in ARCHITECTURE.md is broken by the next change that does not read it.

    use std::path::{Path, PathBuf};

    /// Every `.rs` file under `dir`, sorted.
    fn sources(dir: &Path) -> Vec<PathBuf> {
        let mut found = Vec::new();
        let mut stack = vec![dir.to_owned()];
        while let Some(dir) = stack.pop() {
            let entries = std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{dir:?}: {e}"));
            for entry in entries.flatten() {
                let path = entry.path();
                if path.is_dir() {
                    stack.push(path);
                } else if path.extension().is_some_and(|e| e == "rs") {
                    found.push(path);
                }
            }
        }
        found.sort();
        found
    }

    /// The kinds: the folders under `src/kinds/`.
    fn kinds(root: &Path) -> Vec<String> {
        let mut kinds: Vec<String> = std::fs::read_dir(root)
            .unwrap_or_else(|e| panic!("{root:?}: {e}"))
            .flatten()
            .filter(|entry| entry.path().is_dir())
            .map(|entry| entry.file_name().to_string_lossy().into_owned())
            .collect();
        kinds.sort();
        kinds
    }

    #[test]
    fn no_kind_imports_another() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/kinds");
        let kinds = kinds(&root);
        assert!(kinds.len() >= 2, "the kinds' folders: {kinds:?}");
        let mut found = Vec::new();
        for kind in &kinds {
            for file in sources(&root.join(kind)) {
                let text = std::fs::read_to_string(&file).unwrap_or_default();
                for other in kinds.iter().filter(|other| *other != kind) {
                    let paths = [format!("kinds::{other}"), format!("super::super::{other}")];
                    for (number, line) in text.lines().enumerate() {
                        if paths.iter().any(|path| line.contains(path.as_str())) {
                            found.push(format!("{}:{}: {line}", file.display(), number + 1));
                        }
                    }
                }
            }
        }
        assert!(
            found.is_empty(),
            "a kind names another; move what they share into a shared layer:\n{}",
            found.join("\n")
        );
    }

    /// The names by which a file names a kind of the registry: its module path, and its own
    /// types (`ShipScene`, `VehicleError`).
    fn names_of(kind: &str) -> Vec<String> {
        let title: String = (kind.chars().next().into_iter())
            .flat_map(char::to_uppercase)
            .chain(kind.chars().skip(1))
            .collect();
        vec![
            format!("kinds::{kind}"),
            format!("{title}Scene"),
            format!("{title}Error"),
        ]
    }

    /// Where each line of the `.rs` files under `dirs` names one of `kinds`.
    fn naming(root: &Path, dirs: &[&str], kinds: &[String]) -> Vec<String> {
        let mut found = Vec::new();
        for dir in dirs {
            for file in sources(&root.join(dir)) {
                let text = std::fs::read_to_string(&file).unwrap_or_default();
                for (number, line) in text.lines().enumerate() {
                    let names = kinds.iter().flat_map(|kind| names_of(kind));
                    if names.into_iter().any(|name| line.contains(&name)) {
                        found.push(format!("{}:{}: {line}", file.display(), number + 1));
                    }
                }
            }
        }
        found
    }

    #[test]
    fn the_shared_layers_and_the_application_name_no_kind() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let kinds = kinds(&root.join("src/kinds"));
        let shared = [
            "src/scene",
            "src/run",
            "src/output",
            "src/linear",
            "src/models",
        ];
        let found = naming(root, &shared, &kinds);
        assert!(
            found.is_empty(),
            "a shared layer names a kind; let the kind say it through the registry:\n{}",
            found.join("\n")
        );
        let found = naming(root, &["app/src"], &kinds);
        assert!(
            found.is_empty(),
            "the application names a kind; let the kind say it through `Kind`:\n{}",
            found.join("\n")
        );
    }
}
