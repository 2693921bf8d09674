//! The aircraft as a kind of scene: recognised by its `[aircraft]` table, run through
//! [`super::run`], linearised at its trim.

use super::keys;
use super::linear::linearise_aircraft;
use super::manoeuvre::trajectory_columns;
use super::scene::AircraftScene;
use crate::kinds::{self, Columns, KindError, Linearised, Reference, Registered, Source};
use crate::scene::SceneError;
use crate::scene::reference::SceneFamily;
use std::path::Path;

/// The registry's entry.
pub const KIND: Registered = Registered {
    name: "aircraft",
    reference: Reference {
        heading: "Aircraft scenes",
        families: &[SceneFamily::Kind("aircraft")],
        doc: "An aircraft on its aerodynamic tables: six degrees of freedom about G in wind \
              axes, an engine with its lag, trimmed, then its manoeuvres.",
        intro: "A scene with an `[aircraft]` table is an aircraft scene: the rigid body about G \
                with I_xz and the engine's rotor, the wind-axis state (V, α, β), the \
                aerodynamic build-up from coefficient tables in α, β and the controls (or a \
                textbook's stability derivatives) times the dynamic pressure, flat-Earth \
                navigation and the power lag, derived and proved when the scene is read; \
                trimmed at `[trim]`, then each `[[manoeuvre]]` from the trim \
                (`scenes/f16.toml`, `scenes/navion.toml`; `eom new aircraft`; \
                docs/aircraft.md).",
        keys: keys::ALL,
        notes: keys::NOTES,
        columns: Columns::Listed {
            said: "An aircraft writes one per manoeuvre, the state in its scene's units \
                   (`summary.json` gives each column's under `units`), then the controls and \
                   the load factor",
            columns: trajectory_columns,
        },
    },
    recognises,
    family: None,
    reads_the_rest: false,
    read,
    example: "navion.toml",
    swept_figures: crate::kinds::SweptFigures {
        names: &["*.dutch_roll_period_s", "*.dutch_roll_period_linear_s"],
        unit: "s",
    },
};

/// An aircraft's scene has `[aircraft]`.
fn recognises(table: &toml::Table) -> bool {
    table.contains_key("aircraft")
}

fn read(source: Source, name: &str, _base: &Path) -> Result<Box<dyn kinds::Kind>, SceneError> {
    let file = source.read(name)?;
    Ok(Box::new(AircraftScene::from_file(&file, name)?))
}

impl kinds::Kind for AircraftScene {
    fn folders(&self) -> Vec<String> {
        self.manoeuvres.iter().map(|m| m.name.clone()).collect()
    }

    /// Each manoeuvre's rows, t, the row and the kinetic energy.
    fn trajectory_numbers(&self) -> f64 {
        let rows: f64 = (self.manoeuvres.iter())
            .map(|m| m.duration / self.every)
            .sum();
        rows * (super::manoeuvre::ROW.len() + 2) as f64
    }

    /// The linearisation at the trim, with what the trim rests on that is not data (a
    /// condition beyond the engine's tables) as warnings: lines of the text report and the
    /// JSON report's `warnings`.
    fn linear(&self) -> Result<Linearised, KindError> {
        let mut linearised = Linearised::alone(linearise_aircraft(self)?);
        for warning in &self.trim_warnings {
            linearised.text.push_str(&format!("warning: {warning}\n"));
        }
        if !self.trim_warnings.is_empty() {
            let warnings = self.trim_warnings.iter().cloned().map(Into::into).collect();
            (linearised.json).insert("warnings".into(), serde_json::Value::Array(warnings));
        }
        Ok(linearised)
    }

    /// The proved model with the scene's tables, engine and atmosphere, in the scene's units
    /// (controls: throttle 0–1, surfaces in degrees).
    fn model(&self) -> Option<Result<Box<dyn crate::models::DynModel>, KindError>> {
        Some(Ok(Box::new(crate::models::Erased(self.model.clone()))))
    }
}
