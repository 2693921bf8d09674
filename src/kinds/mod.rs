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

pub use crate::kind::{Finished, Kind, KindError, Linearised, RunScene};
use crate::scene::SceneError;
use crate::scene::reference::{Key, SceneFamily};
use std::path::Path;

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
    /// Every key it reads, in the order a template writes them, a list a part of the scene
    /// (so that a kind of many keys keeps them in files of a readable size).
    pub keys: &'static [&'static [Key]],
    /// What its section says after the keys (its table's conventions); empty for nothing.
    pub notes: &'static str,
    /// What its trajectory.csv holds.
    pub columns: Columns,
}

impl Reference {
    /// Every key it reads, in the order a template writes them.
    pub fn keys(&self) -> impl Iterator<Item = &'static Key> {
        self.keys.iter().flat_map(|part| part.iter())
    }
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
    /// Whether a scene's tables are this kind's: each kind says what its own scenes have,
    /// not what another's lack.
    pub recognises: fn(&toml::Table) -> bool,
    /// The `model.family` its scenes name where another kind's scenes have the same tables
    /// (a ship's and a vehicle's both have `[hydrodynamics]`): what a scene with those tables
    /// and another family is told to name.
    pub family: Option<&'static str>,
    /// Whether it reads the scenes no other kind recognises (the catalog body's, whose
    /// checker says what such a scene lacks): it is asked after every other kind, so that a
    /// kind added to the registry is recognised wherever it stands in it.
    pub reads_the_rest: bool,
    /// Reads and checks the scene (`name` is how errors name the file, `base` where a file
    /// it names is found).
    pub read: Reader,
    /// Its example scene, under the repository's `scenes/`: what the tests run every kind by
    /// (each feature, the same way for every kind).
    pub example: &'static str,
    /// The figures a sweep over one key draws against it (`sweep.svg`, beside its table), all
    /// in one unit.
    pub swept_figures: SweptFigures,
}

/// The figures a sweep over one key draws against it, in one unit.
#[derive(Debug, Clone, Copy)]
pub struct SweptFigures {
    /// Each figure's column in the sweep's table: its name (`period_s`, a scene of one run),
    /// or `*.` and its name for every run's (`*.tactical_diameter_m`: the column
    /// `turn.port.tactical_diameter_m` and the like).
    pub names: &'static [&'static str],
    /// Their unit (`m`).
    pub unit: &'static str,
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
        // A scene with the ship's and the vehicle's table and another family, or none, is
        // neither's: each kind recognises its own scenes, not by what another's lack.
        let neither = [
            "[model]\nfamily = \"spatial\"\n[hydrodynamics]",
            "[hydrodynamics]",
        ];
        assert_eq!(neither.map(name), [None, None]);
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

    /// Whether `line` names the kind `other` by a path: `kinds::other`, `super::other` (a
    /// sibling kind, from a kind's `mod.rs`), `super::super::other`, or `other` in a group
    /// `kinds::{…}`.
    fn names_by_path(line: &str, other: &str) -> bool {
        let paths = [
            format!("kinds::{other}"),
            format!("super::{other}"),
            format!("super::super::{other}"),
        ];
        let word = |text: &str| {
            (text.split(|c: char| !(c.is_alphanumeric() || c == '_'))).any(|word| word == other)
        };
        let grouped = (line.split("kinds::{").skip(1))
            .any(|group| word(group.split('}').next().unwrap_or_default()));
        paths.iter().any(|path| {
            (line.match_indices(path.as_str())).any(|(at, _)| {
                let after = line[at + path.len()..].chars().next();
                !after.is_some_and(|c| c.is_alphanumeric() || c == '_')
            })
        }) || grouped
    }

    #[test]
    fn the_path_check_catches_each_way_of_naming_a_kind() {
        for line in [
            "use crate::kinds::ship::Side;",
            "use crate::kinds::{ship, vehicle};",
            "use super::ship::ShipScene;",
            "use super::super::ship;",
            "use crate::kinds::{body::BodyScene, ship};",
        ] {
            assert!(names_by_path(line, "ship"), "{line}");
        }
        for line in [
            "use super::shipping;",
            "use crate::kinds::{Kind, shipment};",
        ] {
            assert!(!names_by_path(line, "ship"), "{line}");
        }
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
                    let names = names_of(other);
                    for (number, line) in text.lines().enumerate() {
                        let typed = names[1..].iter().any(|name| contains_word(line, name));
                        if names_by_path(line, other) || typed {
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

    /// Whether `name` is in `line` as a word of its own (`ShipScene`, not `MyShipScene2`).
    fn contains_word(line: &str, name: &str) -> bool {
        (line.match_indices(name)).any(|(at, _)| {
            let word = |c: char| c.is_alphanumeric() || c == '_';
            let before = line[..at].chars().next_back();
            let after = line[at + name.len()..].chars().next();
            !before.is_some_and(word) && !after.is_some_and(word)
        })
    }

    /// The names by which a file names a kind of the registry: its module path, then its own
    /// types (`ShipScene`, `VehicleError`, `AircraftSection`, `ShipModel`).
    fn names_of(kind: &str) -> Vec<String> {
        let title: String = (kind.chars().next().into_iter())
            .flat_map(char::to_uppercase)
            .chain(kind.chars().skip(1))
            .collect();
        let mut names = vec![format!("kinds::{kind}")];
        names.extend(["Scene", "Error", "Section", "Model"].map(|what| format!("{title}{what}")));
        names
    }

    /// Where each line of the `.rs` files under `dirs` (folders or files) names one of
    /// `kinds`: by a path (`kinds::ship`, a group `kinds::{ship, …}`) or a type of its own.
    fn naming(root: &Path, dirs: &[&str], kinds: &[String]) -> Vec<String> {
        let mut found = Vec::new();
        for dir in dirs {
            let path = root.join(dir);
            let files = match path.is_dir() {
                true => sources(&path),
                false => vec![path],
            };
            for file in files {
                let text = std::fs::read_to_string(&file)
                    .unwrap_or_else(|e| panic!("{}: {e}", file.display()));
                for (number, line) in text.lines().enumerate() {
                    let named = kinds.iter().any(|kind| {
                        let names = names_of(kind);
                        let path = line.contains(&names[0]) || names_by_path_group(line, kind);
                        path || names[1..].iter().any(|name| contains_word(line, name))
                    });
                    if named {
                        found.push(format!("{}:{}: {line}", file.display(), number + 1));
                    }
                }
            }
        }
        found
    }

    /// Whether `line` names `kind` in a group `kinds::{…}`.
    fn names_by_path_group(line: &str, kind: &str) -> bool {
        names_by_path(line, kind) && line.contains("kinds::{")
    }

    #[test]
    fn the_shared_layers_and_the_application_name_no_kind() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let kinds = kinds(&root.join("src/kinds"));
        // Every layer below the kinds: what they share, the runner of their runs, and the
        // table of contents. (The fuzz targets still take each kind's scene by its type.)
        let shared = [
            "src/scene",
            "src/run",
            "src/output",
            "src/linear",
            "src/models",
            "src/integrate",
            "src/generic",
            "src/defined.rs",
            "src/defined",
            "src/manoeuvring",
            "src/kind.rs",
            "src/lib.rs",
            "python/src",
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
