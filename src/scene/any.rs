//! A scene of any kind, read by one entry: a catalog body's, whose model is a variant the
//! build generated, or one whose model the scene's own table defines (a ship's 4.46 on its
//! hydrodynamic table, or a vehicle's six equations about its table's origin, derived and
//! proved when the scene is read).
//!
//! Both kinds are read by the same reader ([`super::read_as`]: TOML through serde, every table
//! closed, errors by key path), their method checked by the same checker
//! (`integrator.method`, `step`, `rtol`, `atol`, `max_steps`), their values by the same
//! [`Requirement`](crate::validate::Requirement)s, and a sweep of either makes its cases the
//! same way ([`super::sweep::shard_tables`]). What tells them apart is a fact of the scene,
//! read here once: a table that defines the model.

use super::{Problem, Scene, SceneError};
use std::path::Path;
use toml::Table;

/// The table whose presence says that the scene defines its own model: a ship's 4.46 terms
/// or a vehicle's six equations.
const MODEL_TABLE: &str = "hydrodynamics";

/// The family that says a scene with [`MODEL_TABLE`] is a vehicle's (a ship's otherwise).
const VEHICLE_FAMILY: &str = "vehicle";

/// Whether a scene's tables say it is a vehicle's: `model.family = "vehicle"`.
fn is_vehicle(table: &Table) -> bool {
    (table.get("model").and_then(|m| m.get("family"))).and_then(|f| f.as_str())
        == Some(VEHICLE_FAMILY)
}

/// A checked scene, of either kind.
#[derive(Debug, Clone)]
pub enum AnyScene {
    /// A catalog body under its loads.
    Catalog(Box<Scene>),
    /// A ship on its own hydrodynamic table, with its manoeuvres.
    #[cfg(feature = "ship")]
    Ship(Box<crate::kinds::ship::ShipScene>),
    /// An underwater vehicle on its own hydrodynamic table, with its manoeuvres.
    #[cfg(feature = "ship")]
    Vehicle(Box<crate::kinds::vehicle::VehicleScene>),
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
        if table.contains_key(MODEL_TABLE) && is_vehicle(&table) {
            return Self::vehicle(|| super::read_as(text, name), name);
        }
        if table.contains_key(MODEL_TABLE) {
            return Self::defined_by_table(|| super::read_as(text, name), name);
        }
        Ok(AnyScene::Catalog(Box::new(Scene::parse(text, name, base)?)))
    }

    /// Checks a scene's tables: one case of a sweep ([`super::sweep::TableCase`]).
    pub fn from_table(table: Table, name: &str, base: &Path) -> Result<Self, SceneError> {
        if table.contains_key(MODEL_TABLE) && is_vehicle(&table) {
            return Self::vehicle(|| super::sweep::read_table(table, name), name);
        }
        if table.contains_key(MODEL_TABLE) {
            return Self::defined_by_table(|| super::sweep::read_table(table, name), name);
        }
        let family = super::family_named(&table);
        let file = super::sweep::read_table(table, name)
            .map_err(|error| super::keys_of_the_family(error, family))?;
        Ok(AnyScene::Catalog(Box::new(Scene::from_file(
            &file, name, base,
        )?)))
    }

    /// The scene whose tables `read` reads, with a model its own table defines.
    #[cfg(feature = "ship")]
    fn defined_by_table(
        read: impl FnOnce() -> Result<crate::kinds::ship::scene::ShipSceneFile, SceneError>,
        name: &str,
    ) -> Result<Self, SceneError> {
        let scene = crate::kinds::ship::ShipScene::from_file(&read()?, name)?;
        Ok(AnyScene::Ship(Box::new(scene)))
    }

    /// The vehicle scene whose tables `read` reads.
    #[cfg(feature = "ship")]
    fn vehicle(
        read: impl FnOnce() -> Result<crate::kinds::vehicle::scene::VehicleSceneFile, SceneError>,
        name: &str,
    ) -> Result<Self, SceneError> {
        let scene = crate::kinds::vehicle::VehicleScene::from_file(&read()?, name)?;
        Ok(AnyScene::Vehicle(Box::new(scene)))
    }

    /// Without the feature `ship` the tables are not read (the reader's type is only named,
    /// so that the callers' generic readers have one).
    #[cfg(not(feature = "ship"))]
    fn vehicle(
        read: impl FnOnce() -> Result<Table, SceneError>,
        name: &str,
    ) -> Result<Self, SceneError> {
        Self::defined_by_table(read, name)
    }

    #[cfg(not(feature = "ship"))]
    fn defined_by_table(
        _read: impl FnOnce() -> Result<Table, SceneError>,
        name: &str,
    ) -> Result<Self, SceneError> {
        Err(SceneError::new(
            name,
            MODEL_TABLE,
            Problem::Invalid(
                "a scene whose table defines its model (a ship's 4.46, a vehicle's six \
                 equations) needs eom's feature `ship`, which builds it with the symbolic \
                 engine"
                    .into(),
            ),
        ))
    }

    /// The title.
    pub fn title(&self) -> &str {
        match self {
            AnyScene::Catalog(scene) => &scene.title,
            #[cfg(feature = "ship")]
            AnyScene::Ship(scene) => &scene.title,
            #[cfg(feature = "ship")]
            AnyScene::Vehicle(scene) => &scene.title,
        }
    }
}
