//! A scene of any kind, read by one entry: a catalog body's, whose model is a variant the
//! build generated, or one of a kind in the registry ([`crate::kinds::REGISTRY`]), whose model
//! its own table defines, derived and proved when the scene is read.
//!
//! Every kind is read by the same reader ([`super::read_as`]: TOML through serde, every table
//! closed, errors by key path), its method checked by the same checker (`integrator.method`,
//! `step`, `rtol`, `atol`, `max_steps`), its values by the same
//! [`Requirement`](crate::validate::Requirement)s, and a sweep of any kind makes its cases the
//! same way ([`super::sweep::shard_tables`]). Which kind a scene is, the registry says from
//! its tables, read here once: each kind recognises its own.

use super::{Problem, Scene, SceneError};
use crate::kinds::{self, Kind, Source};
use std::path::Path;
use toml::Table;

/// The table whose presence says that the scene defines its own model; a scene with it that
/// no registered kind reads needs the feature that builds such models.
const MODEL_TABLE: &str = "hydrodynamics";

/// A checked scene, of any kind.
#[derive(Debug)]
pub enum AnyScene {
    /// A catalog body under its loads.
    Catalog(Box<Scene>),
    /// A scene of a kind in [`kinds::REGISTRY`], whose own table defines its model.
    Kind(Box<dyn Kind>),
}

impl AnyScene {
    /// Reads and checks the scene file at `path` (a `body.file` is found relative to it).
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let name = super::error::display_name(path);
        let text = std::fs::read_to_string(path)
            .map_err(|e| SceneError::new(&name, "", Problem::Read(e)))?;
        let base = path.parent().unwrap_or(Path::new("."));
        Self::parse(&text, &name, base)
    }

    /// Reads and checks scene text; `name` is how errors name the file, `base` where a
    /// `body.file` is found.
    pub fn parse(text: &str, name: &str, base: &Path) -> Result<Self, SceneError> {
        let table: Table = text.parse().map_err(|e: toml::de::Error| {
            SceneError::new(name, "", Problem::Syntax(e.to_string()))
        })?;
        if let Some(kind) = kinds::recognise(&table) {
            return Ok(AnyScene::Kind((kind.read)(Source::Text(text), name, base)?));
        }
        refuse_unbuilt(&table, name)?;
        Ok(AnyScene::Catalog(Box::new(Scene::parse(text, name, base)?)))
    }

    /// Checks a scene's tables: one case of a sweep ([`super::sweep::TableCase`]).
    pub fn from_table(table: Table, name: &str, base: &Path) -> Result<Self, SceneError> {
        if let Some(kind) = kinds::recognise(&table) {
            return Ok(AnyScene::Kind((kind.read)(
                Source::Table(table),
                name,
                base,
            )?));
        }
        refuse_unbuilt(&table, name)?;
        let family = super::family_named(&table);
        let file = super::sweep::read_table(table, name)
            .map_err(|error| super::keys_of_the_family(error, family))?;
        Ok(AnyScene::Catalog(Box::new(Scene::from_file(
            &file, name, base,
        )?)))
    }

    /// The scene as a [`Kind`], whatever its kind: what the command runs, sweeps and
    /// reports (a catalog body is the kind `body`).
    pub fn into_kind(self) -> Box<dyn Kind> {
        match self {
            AnyScene::Catalog(scene) => scene,
            AnyScene::Kind(scene) => scene,
        }
    }

    /// The title.
    pub fn title(&self) -> &str {
        match self {
            AnyScene::Catalog(scene) => &scene.title,
            AnyScene::Kind(scene) => scene.title(),
        }
    }

    /// The scene as `T`, a kind's own scene type, if it is one.
    pub fn downcast<T: Kind + 'static>(self) -> Option<Box<T>> {
        match self {
            AnyScene::Kind(scene) => scene.into_any().downcast::<T>().ok(),
            AnyScene::Catalog(_) => None,
        }
    }

    /// The kind's name, as [`Kind::kind`] says it: `body` for a catalog body's, else the
    /// registry's (`ship`).
    pub fn kind(&self) -> &'static str {
        match self {
            AnyScene::Catalog(scene) => scene.kind(),
            AnyScene::Kind(scene) => scene.kind(),
        }
    }
}

/// A scene whose own table defines its model, read where no registered kind reads it: this
/// build has not the feature that builds such models.
fn refuse_unbuilt(table: &Table, name: &str) -> Result<(), SceneError> {
    match table.contains_key(MODEL_TABLE) {
        false => Ok(()),
        true => Err(SceneError::new(
            name,
            MODEL_TABLE,
            Problem::Invalid(
                "a scene whose table defines its model (a ship's 4.46, a vehicle's six \
                 equations) needs eom's feature `ship`, which builds it with the symbolic \
                 engine"
                    .into(),
            ),
        )),
    }
}
