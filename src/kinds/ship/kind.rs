//! The ship as a kind of scene: recognised by its `[hydrodynamics]` (with any family but the
//! vehicle's), run through [`super::run`], linearised about its straight course with Nomoto's
//! models beside.

use super::keys;
use super::linear::{LinearModel, linearise_ship, nomoto_report};
use super::manoeuvre::ROW;
use super::manoeuvre::trajectory_columns;
use super::summary::LinearSummary;
use super::{ShipError, ShipModel, ShipScene};
use crate::kinds::{self, Columns, KindError, Linearised, Reference, Registered, Source};
use crate::scene::SceneError;
use crate::scene::reference::SceneFamily;
use std::path::Path;

/// The registry's entry.
pub const KIND: Registered = Registered {
    name: "ship",
    reference: Reference {
        heading: "Ship scenes",
        families: &[SceneFamily::Kind("ship")],
        doc: "A ship on its hydrodynamic table: planar-midship (4.46) with [hydrodynamics], \
              a rudder and the standard manoeuvres.",
        intro: "A scene with a `[hydrodynamics]` table is a ship scene: 4.46 at midship with \
                exactly the terms the table lists, derived and proved when the scene is read, \
                run through each `[[manoeuvre]]` from the same straight approach at U₀ \
                (`scenes/mariner.toml`, `scenes/esso_osaka.toml`; `eom new ship`).",
        keys: &[keys::KEYS, keys::environment::KEYS, keys::RUN_KEYS],
        notes: keys::NOTES,
        columns: Columns::Listed {
            said: "A ship writes one `trajectory.csv` per manoeuvre, with the rudder command \
                  after saturation and the distance run by midship",
            columns: trajectory_columns,
        },
    },
    recognises,
    family: Some("planar-midship"),
    reads_the_rest: false,
    read,
    example: "mariner.toml",
    swept_figures: crate::kinds::SweptFigures {
        names: &["*.tactical_diameter_m", "*.steady_turning_radius_m"],
        unit: "m",
    },
};

/// A ship's scene has `[hydrodynamics]` and `[model] family = "planar-midship"`.
fn recognises(table: &toml::Table) -> bool {
    table.contains_key("hydrodynamics") && kinds::family_of(table) == KIND.family
}

fn read(source: Source, name: &str, _base: &Path) -> Result<Box<dyn kinds::Kind>, SceneError> {
    let file = source.read(name)?;
    Ok(Box::new(ShipScene::from_file(&file, name)?))
}

impl From<ShipError> for KindError {
    fn from(error: ShipError) -> Self {
        let class = match error.cause() {
            ShipError::Invalid { .. } => KindError::Scene,
            ShipError::Run { .. } => KindError::Run,
            ShipError::Record { .. } => KindError::Output,
            ShipError::Build(_) | ShipError::In { .. } => KindError::Internal,
        };
        class(Box::new(error))
    }
}

impl kinds::Kind for ShipScene {
    fn folders(&self) -> Vec<String> {
        self.manoeuvres.iter().map(|m| m.name.clone()).collect()
    }

    /// Each side's rows of each manoeuvre, t and [`ROW`] with the kinetic energy.
    fn trajectory_numbers(&self) -> f64 {
        let rows: f64 = (self.manoeuvres.iter())
            .map(|m| m.duration / self.every * m.runs().len() as f64)
            .sum();
        rows * (ROW.len() + 2) as f64
    }

    fn linear(&self) -> Result<Linearised, KindError> {
        let model = ShipModel::new(&self.table)?;
        let linear = LinearModel::closed_form(&self.table);
        let linearisation = linearise_ship(self, &model)?;
        let json = match serde_json::to_value(LinearSummary::new(self, &model, &linear)) {
            Ok(serde_json::Value::Object(map)) => map,
            _ => serde_json::Map::new(),
        };
        Ok(Linearised {
            linearisation,
            text: nomoto_report(self, &model, &linear),
            json,
        })
    }

    /// The table's model, derived and proved again (as each run builds it).
    fn model(&self) -> Option<Result<Box<dyn crate::models::DynModel>, KindError>> {
        let model = ShipModel::new(&self.table).map_err(KindError::from);
        Some(model.map(|model| Box::new(crate::models::Erased(model)) as Box<_>))
    }

    /// Coefficients of the table (`hydrodynamics.coefficients.Yv`) set into the file as read.
    fn with_numbers(
        &self,
        name: &str,
        numbers: &[(&str, f64)],
    ) -> Option<Result<Box<dyn kinds::Kind>, SceneError>> {
        let scene = self.with_coefficients(name, numbers)?;
        Some(scene.map(|scene| Box::new(scene) as Box<dyn kinds::Kind>))
    }
}
