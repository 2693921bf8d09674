//! Why a scene cannot run: every error names the file and the key, by its path in the file
//! (`integrator.step`), and says what is wrong with it.

use crate::mass::BodyFileError;
use std::path::PathBuf;
use thiserror::Error;

/// A scene that cannot be read or run as written.
#[derive(Debug, Error)]
#[error("{file}: {}{problem}", key_prefix(.key))]
pub struct SceneError {
    /// The scene file (or `<scene>` for text given directly).
    pub file: String,
    /// The key's path in the file, `integrator.step`; empty for the file as a whole.
    pub key: String,
    /// What is wrong.
    pub problem: Problem,
}

fn key_prefix(key: &str) -> String {
    if key.is_empty() {
        String::new()
    } else {
        format!("`{key}`: ")
    }
}

/// What is wrong with a scene, by class: the command line maps each class to its own exit
/// code.
#[derive(Debug, Error)]
pub enum Problem {
    /// The file cannot be read.
    #[error("cannot read it: {0}")]
    Read(#[source] std::io::Error),
    /// The file is not TOML.
    #[error("not valid TOML: {0}")]
    Syntax(String),
    /// A key the scene format does not have, or a value of the wrong type.
    #[error("{0}")]
    Schema(String),
    /// A key the scene needs is absent.
    #[error("missing: {0}")]
    Missing(String),
    /// A value out of its range, or keys that contradict each other.
    #[error("{0}")]
    Invalid(String),
    /// The body file named by `body.file` cannot be used.
    #[error(transparent)]
    BodyFile(Box<BodyFileError>),
}

impl SceneError {
    /// An error about `key` of `file`.
    pub fn new(file: &str, key: &str, problem: Problem) -> Self {
        Self {
            file: file.to_owned(),
            key: key.to_owned(),
            problem,
        }
    }
}

/// The scene file's display name.
pub(crate) fn display_name(path: &std::path::Path) -> String {
    PathBuf::from(path).display().to_string()
}
