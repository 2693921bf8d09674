//! A scene of any kind, read by one entry: the registry ([`crate::kinds::REGISTRY`]) says from
//! its tables, read here once, which kind it is (each kind recognises its own), and that kind
//! reads and checks it.
//!
//! Every kind is read by the same reader ([`super::read_as`]: TOML through serde, every table
//! closed, errors by key path), its method checked by the same checker (`integrator.method`,
//! `step`, `rtol`, `atol`, `max_steps`), its values by the same
//! [`Requirement`](crate::validate::Requirement)s, and a sweep of any kind makes its cases the
//! same way ([`super::sweep::shard_tables`]).

use super::{DEFINED_MODEL_TABLE, Problem, SceneError};
use crate::kinds::{self, Kind, Source};
use std::path::Path;
use toml::Table;

/// A checked scene, of any kind: what the command runs, sweeps and reports.
#[derive(Debug)]
pub struct AnyScene(Box<dyn Kind>);

impl AnyScene {
    /// Reads and checks the scene file at `path` (a file it names, such as a `body.file`, is
    /// found relative to it).
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let name = super::display_name(path);
        let text = std::fs::read_to_string(path)
            .map_err(|e| SceneError::new(&name, "", Problem::Read(e)))?;
        let base = path.parent().unwrap_or(Path::new("."));
        Self::parse(&text, &name, base)
    }

    /// Reads and checks scene text; `name` is how errors name the file, `base` where a file
    /// it names is found.
    pub fn parse(text: &str, name: &str, base: &Path) -> Result<Self, SceneError> {
        let table: Table = text.parse().map_err(|e: toml::de::Error| {
            SceneError::new(name, "", Problem::Syntax(e.to_string()))
        })?;
        let kind = recognise(&table, name)?;
        Ok(AnyScene((kind.read)(Source::Text(text), name, base)?))
    }

    /// Checks a scene's tables: one case of a sweep ([`super::sweep::TableCase`]).
    pub fn from_table(table: Table, name: &str, base: &Path) -> Result<Self, SceneError> {
        let kind = recognise(&table, name)?;
        Ok(AnyScene((kind.read)(Source::Table(table), name, base)?))
    }

    /// The scene as a [`Kind`], whatever its kind.
    pub fn into_kind(self) -> Box<dyn Kind> {
        self.0
    }

    /// The scene as a [`Kind`], borrowed.
    pub fn as_kind(&self) -> &dyn Kind {
        self.0.as_ref()
    }

    /// The title.
    pub fn title(&self) -> &str {
        self.0.title()
    }

    /// The scene as `T`, a kind's own scene type, if it is one.
    pub fn downcast<T: Kind + 'static>(self) -> Option<Box<T>> {
        self.0.into_any().downcast::<T>().ok()
    }

    /// The kind's name, as the registry lists it (`body`, `ship`).
    pub fn kind(&self) -> &'static str {
        self.0.kind()
    }
}

/// The registered kind whose tables `table` are. A scene whose own table defines its model
/// and that no registered kind reads names a family none of them reads (each kind that reads
/// such scenes is said with its family), or, where none is registered, needs the feature that
/// builds such models.
fn recognise(table: &Table, name: &str) -> Result<&'static kinds::Registered, SceneError> {
    kinds::recognise(table).ok_or_else(|| {
        let families: Vec<String> = (kinds::REGISTRY.iter())
            .filter_map(|kind| Some(format!("{}'s `{}`", kind.name, kind.family?)))
            .collect();
        if families.is_empty() {
            return SceneError::new(
                name,
                DEFINED_MODEL_TABLE,
                Problem::Invalid(
                    "a scene whose table defines its model (a ship's 4.46, a vehicle's six \
                     equations) needs eom's feature `ship`, which builds it with the symbolic \
                     engine"
                        .into(),
                ),
            );
        }
        let read = format!(
            "a scene with [{DEFINED_MODEL_TABLE}] names the family of the kind that reads it: {}",
            families.join(" or ")
        );
        match kinds::family_of(table) {
            Some(family) => SceneError::new(
                name,
                "model.family",
                Problem::Invalid(format!("`{family}`: {read}")),
            ),
            None => SceneError::new(name, "model.family", Problem::Missing(read)),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scene with `[hydrodynamics]` that names another family, or none, is told which
    /// family each kind that reads such scenes names (or, without them, which feature
    /// builds them), at `model.family`.
    #[test]
    fn a_table_no_kind_reads_is_told_the_families_that_are_read() {
        for (text, said) in [
            (
                "[model]\nfamily = \"spatial\"\n[hydrodynamics]\n",
                "`spatial`: ",
            ),
            ("[hydrodynamics]\n", "missing"),
        ] {
            let error = AnyScene::parse(text, "scene.toml", Path::new("."))
                .err()
                .unwrap()
                .to_string();
            if cfg!(feature = "ship") {
                assert!(
                    error.contains("model.family") && error.contains(said),
                    "{error}"
                );
                assert!(error.contains("ship's `planar-midship`"), "{error}");
                assert!(error.contains("vehicle's `vehicle`"), "{error}");
            } else {
                assert!(error.contains("feature `ship`"), "{error}");
            }
        }
    }
}
