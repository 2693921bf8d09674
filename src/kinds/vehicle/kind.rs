//! The vehicle as a kind of scene: recognised by its `[hydrodynamics]` with
//! `family = "vehicle"`, run through [`super::run`], linearised at its cruise through the
//! table's Euler-angle twin.

use super::keys;
use super::linear::linearise_vehicle;
use super::manoeuvre::ROW;
use super::manoeuvre::trajectory_columns;
use super::{VehicleError, VehicleScene};
use crate::kinds::{self, Columns, KindError, Linearised, Reference, Registered, Source};
use crate::scene::SceneError;
use crate::scene::reference::SceneFamily;
use std::path::Path;

/// The registry's entry.
pub const KIND: Registered = Registered {
    name: "vehicle",
    reference: Reference {
        heading: "Vehicle scenes",
        families: &[SceneFamily::Kind("vehicle")],
        doc: "An underwater vehicle on its hydrodynamic table: six degrees of freedom about \
              the table's origin with [hydrodynamics], a propeller, fins and their steps.",
        intro: "A scene with `[model] family = \"vehicle\"` and a `[hydrodynamics]` table is a \
                vehicle scene: the six equations about the table's origin O with G at r_G, the \
                added mass, Kirchhoff's terms folded or derived, exactly the terms the table \
                lists, the propeller and the hydrostatics, derived and proved when the scene is \
                read, run through each `[[manoeuvre]]` from the cruise \
                (`scenes/remus100.toml`; `eom new vehicle`; docs/vehicles.md).",
        keys: &[keys::KEYS],
        notes: "",
        columns: Columns::Listed {
            said: "A vehicle writes one per manoeuvre, with the fins' commands after saturation and \
                  the Euler angles of its quaternion",
            columns: trajectory_columns,
        },
    },
    recognises,
    family: Some("vehicle"),
    reads_the_rest: false,
    read,
    example: "remus100.toml",
    swept_figures: crate::kinds::SweptFigures {
        names: &["*.tactical_diameter_m", "*.steady_diameter_m"],
        unit: "m",
    },
};

/// A vehicle's scene has `[hydrodynamics]` and `[model] family = "vehicle"`.
fn recognises(table: &toml::Table) -> bool {
    table.contains_key("hydrodynamics") && kinds::family_of(table) == KIND.family
}

fn read(source: Source, name: &str, _base: &Path) -> Result<Box<dyn kinds::Kind>, SceneError> {
    let file = source.read(name)?;
    Ok(Box::new(VehicleScene::from_file(&file, name)?))
}

impl From<VehicleError> for KindError {
    fn from(error: VehicleError) -> Self {
        let class = match error.cause() {
            VehicleError::Invalid { .. } | VehicleError::Table(_) => KindError::Scene,
            VehicleError::Linear(linear) if linear.is_scene_error() => KindError::Scene,
            VehicleError::Run { .. } | VehicleError::Linear(_) => KindError::Run,
            VehicleError::Record { .. } => KindError::Output,
            VehicleError::Prove(_) | VehicleError::In { .. } => KindError::Internal,
        };
        class(Box::new(error))
    }
}

impl kinds::Kind for VehicleScene {
    fn folders(&self) -> Vec<String> {
        self.manoeuvres.iter().map(|m| m.name.clone()).collect()
    }

    /// Each manoeuvre's rows, t and [`ROW`] with the kinetic energy.
    fn trajectory_numbers(&self) -> f64 {
        let rows: f64 = (self.manoeuvres.iter())
            .map(|m| m.duration / self.every)
            .sum();
        rows * (ROW.len() + 2) as f64
    }

    fn linear(&self) -> Result<Linearised, KindError> {
        Ok(Linearised::alone(linearise_vehicle(self)?))
    }

    /// The table's proved model, as the scene built it.
    fn model(&self) -> Option<Result<Box<dyn crate::models::DynModel>, KindError>> {
        Some(Ok(Box::new(crate::models::Erased(self.model.clone()))))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A vehicle's run that cannot go on is a run's error, whichever manoeuvre it is said of;
    /// a value it refuses, the scene's; one stopped by its recorder, a stop; and the message
    /// is the vehicle's own.
    #[test]
    fn a_vehicles_errors_are_classed_by_what_failed() {
        let run = VehicleError::Run {
            time: 1.0,
            reason: "the state component u is not finite".into(),
        };
        let error = KindError::from(run.in_manoeuvre("turn"));
        assert!(matches!(error, KindError::Run(_)), "{error:?}");
        assert_eq!(error.to_string(), "manoeuvre turn");
        let invalid = VehicleError::Invalid {
            key: "propeller.thrust".into(),
            reason: "astern".into(),
        };
        let error = KindError::from(invalid.in_manoeuvre("turn"));
        assert!(matches!(error, KindError::Scene(_)), "{error:?}");
    }
}
