//! Scenes: what a body is, what acts on it, where it starts and how to integrate it, in one
//! TOML file, of any kind.
//!
//! Every scene is read by one reader, [`read_as`]: TOML through serde, every table closed to
//! unknown keys, so that a misspelt key is an error and not a silent default, and every error
//! naming the key by its path in the file (`integrator.step`) with what is wrong with it.
//! [`AnyScene`] is the one entry: it asks the registry ([`crate::kinds::REGISTRY`]) which
//! kind the scene's tables are, and that kind reads and checks them in its folder, its values
//! through the one set of checks (`check`: each value against its
//! [`Requirement`](crate::validate::Requirement), the method and its settings, the `[linear]`
//! table), the tables every scene with manoeuvres shares through [`envelope`].
//!
//! What every kind shares is here: a `[sweep]` of any scene ([`sweep`]), a Monte Carlo over
//! its values ([`uncertainty`]), a condition that
//! ends a run where it first holds ([`stop`]: `integrator.stop_when = "z > 10"`), the errors
//! ([`SceneError`]), and the key reference that docs/scenes.md and `eom new` are made from
//! ([`reference`](mod@reference)).
//!
//! Space axes are X north, Y east, Z down and body axes x forward, y to starboard, z down, as
//! in the chapter's ship dynamics; angles in a scene file are in degrees, rates in rad/s.

mod any;
pub(crate) mod check;
pub mod envelope;
mod error;
pub mod reference;
pub mod stop;
pub mod sweep;
pub mod uncertainty;

pub use any::AnyScene;
pub(crate) use error::display_name;
pub use error::{Problem, SceneError};
pub use stop::{Comparison, StopCondition};

/// The table whose presence says that a scene's own table defines its model (a ship's, a
/// vehicle's), derived and proved when the scene is read, rather than a variant the build
/// generated.
pub const DEFINED_MODEL_TABLE: &str = "hydrodynamics";

/// The integration methods a scene can name (defined with the integrators).
pub use crate::integrate::Method;

/// The default tolerances of an adaptive method when the scene gives none.
pub const DEFAULT_TOLERANCE: f64 = 1e-9;
/// The default limit on steps.
pub const DEFAULT_MAX_STEPS: usize = 1_000_000;
/// The most trajectory rows a scene may ask for (10⁸: a CSV of a few gigabytes at most).
pub const MAX_ROWS: usize = 100_000_000;
/// Trajectory rows a scene gets when it sets no `output.every`.
pub const DEFAULT_ROWS: f64 = 500.0;

/// Reads TOML text into any table type, each error named by its key path: the one reader of
/// scene files, of every kind.
pub fn read_as<T: serde::de::DeserializeOwned>(text: &str, name: &str) -> Result<T, SceneError> {
    let deserializer = toml::Deserializer::parse(text)
        .map_err(|e| SceneError::new(name, "", Problem::Syntax(e.to_string())))?;
    serde_path_to_error::deserialize(deserializer).map_err(|e| {
        let key = e.path().to_string();
        let key = if key == "." { String::new() } else { key };
        let message = e.into_inner().message().to_owned();
        let problem = if message.starts_with("missing field") {
            Problem::Missing(message)
        } else {
            Problem::Schema(message)
        };
        SceneError::new(name, &key, problem)
    })
}
