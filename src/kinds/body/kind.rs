//! The catalog body as a [`Kind`]: one run at the top of the output, linearised at its
//! initial state (or its `[linear]` point).

use super::BodyScene;
use super::keys::{self, ALL};
use super::run::trajectory_numbers;
use crate::kinds::{Columns, Kind, KindError, Linearised, Reference, Registered, Source};
use crate::run::tradeoff::Tradeoff;
use crate::scene::SceneError;
use std::path::Path;

/// The kind's name.
pub const NAME: &str = "body";

/// The registry's entry.
pub const KIND: Registered = Registered {
    name: NAME,
    reference: Reference {
        doc: "A body of the catalog's families (the pendulum, a planar body, a spatial body, \
              the heavy top) under its loads, its model a variant the build generated and \
              proved.",
        heading: "Catalog scenes",
        intro: keys::INTRO,
        families: ALL,
        keys: keys::EVERY_KEY,
        notes: keys::NOTES,
        columns: Columns::Written(keys::columns),
    },
    recognises,
    family: None,
    reads_the_rest: true,
    read,
    example: "pendulum.toml",
    swept_figures: crate::kinds::SweptFigures {
        names: &["period_s"],
        unit: "s",
    },
};

/// A catalog body's scene is every scene that no other kind recognises and whose own table does
/// not define its model: its checker says what a scene that is no kind's lacks
/// (`model.family`, its body, …).
fn recognises(table: &toml::Table) -> bool {
    !table.contains_key(crate::scene::DEFINED_MODEL_TABLE)
}

fn read(source: Source, name: &str, base: &Path) -> Result<Box<dyn Kind>, SceneError> {
    let scene = match source {
        Source::Text(text) => BodyScene::parse(text, name, base)?,
        Source::Table(table) => BodyScene::from_table(table, name, base)?,
    };
    Ok(Box::new(scene))
}

impl Kind for BodyScene {
    /// Its one run's trajectory, at the top of the output (its drawings beside it).
    fn folders(&self) -> Vec<String> {
        vec!["trajectory.csv".to_owned()]
    }

    fn trajectory_numbers(&self) -> f64 {
        trajectory_numbers(self)
    }

    fn linear(&self) -> Result<Linearised, KindError> {
        Ok(Linearised::alone(super::linear::linearise_scene(self)?))
    }

    /// The catalog variant the scene selected, under its parameters.
    fn model(&self) -> Option<Result<Box<dyn crate::models::DynModel>, KindError>> {
        Some(Ok(Box::new(BodyScene::model(self))))
    }

    fn tradeoff(&self) -> Option<Result<Tradeoff, KindError>> {
        let compared = super::tradeoff::tradeoff(self);
        Some(compared.map_err(|error| KindError::Run(Box::new(error))))
    }
}
