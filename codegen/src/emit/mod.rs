//! Emission: from a model to formatted, deterministic Rust source.
//!
//! For each model the emitter builds the system with every strategy the model allows, turns
//! each into a straight-line program, keeps the cheapest by operation count, and formats it.
//! The same model always gives the same bytes: nothing here iterates a hash map, reads the
//! clock or the environment. [`write_if_changed`] leaves a file untouched when its bytes are
//! already right, so Cargo does not rebuild for nothing.

mod program;
mod rust;
mod trig;

pub use program::{Operations, Program, identifier};
pub use trig::Trig;

use crate::model::{Model, ModelError, Strategy};
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why emission failed.
#[derive(Debug, Error)]
pub enum EmitError {
    /// The model could not be built or did not verify.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// The generated tokens did not parse as a Rust file (a bug in the emitter).
    #[error("generated code for {model} is not valid Rust: {source}")]
    Syntax {
        /// The model's name.
        model: String,
        /// The parser's complaint.
        source: syn::Error,
    },
    /// Writing the file failed.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
}

/// One model's generated code.
#[derive(Debug, Clone)]
pub struct Generated {
    /// The model.
    pub model: Model,
    /// Its name (and the file stem).
    pub name: String,
    /// The strategy that gave the fewest operations.
    pub strategy: Strategy,
    /// The cost of one call.
    pub operations: Operations,
    /// The formatted source.
    pub source: String,
}

/// Generates one model's source.
///
/// ```
/// use eom_codegen::emit::generate;
/// use eom_codegen::model::{Kinematics, Model, Symmetry};
/// let model = Model::Spatial { symmetry: Symmetry::Principal, kinematics: Kinematics::Euler };
/// let generated = generate(model).unwrap();
/// assert!(generated.source.contains("pub fn rhs<T: SimdRealField + Copy>"));
/// assert_eq!(generated.operations.trig, 3); // one sin_cos per Euler angle
/// ```
pub fn generate(model: Model) -> Result<Generated, EmitError> {
    generate_with(model, Trig::Kernel)
}

/// Generates one model's source with the chosen sine and cosine ([`Trig::Kernel`] calls
/// `eom_kernel::sin_cos`; [`Trig::Std`] keeps the scalar's own `simd_sin_cos`, for a crate
/// that does not depend on `eom-kernel`).
///
/// ```
/// use eom_codegen::emit::{Trig, generate_with};
/// use eom_codegen::model::Model;
/// let kernel = generate_with(Model::Pendulum, Trig::Kernel).unwrap();
/// let std = generate_with(Model::Pendulum, Trig::Std).unwrap();
/// assert!(kernel.source.contains("= eom_kernel::sin_cos([theta]);"));
/// assert!(!kernel.source.contains("fn sin_cos")); // the kernel is in eom-kernel, not here
/// assert!(std.source.contains("theta.simd_sin_cos()"));
/// assert_eq!(kernel.operations, std.operations);
/// ```
pub fn generate_with(model: Model, trig: Trig) -> Result<Generated, EmitError> {
    let mut best: Option<(Strategy, crate::model::System, Program)> = None;
    for &strategy in model.strategies() {
        let system = model.system(strategy)?;
        let program = Program::build(&system);
        let better = best
            .as_ref()
            .is_none_or(|(_, _, p)| program.operations.cost() < p.operations.cost());
        if better {
            best = Some((strategy, system, program));
        }
    }
    let (strategy, system, program) = best.expect("every model has a strategy");
    let source =
        rust::source(&system, &program, &format!("{strategy:?}"), trig).map_err(|source| {
            EmitError::Syntax {
                model: system.name.clone(),
                source,
            }
        })?;
    Ok(Generated {
        model,
        name: system.name,
        strategy,
        operations: program.operations,
        source,
    })
}

/// Writes `contents` to `path` unless the file already holds exactly those bytes; returns
/// whether it wrote.
pub fn write_if_changed(path: &Path, contents: &str) -> Result<bool, EmitError> {
    if std::fs::read(path).is_ok_and(|old| old == contents.as_bytes()) {
        return Ok(false);
    }
    std::fs::write(path, contents).map_err(|source| EmitError::Io {
        path: path.to_owned(),
        source,
    })?;
    Ok(true)
}

/// Generates each model into `out_dir/<name>.rs` (the call for a user's `build.rs`). The crate
/// that includes a model with angles depends on `eom-kernel`, whose `sin_cos` its `rhs` calls.
///
/// ```no_run
/// // build.rs
/// use eom_codegen::model::{Kinematics, Model, Symmetry};
/// let out_dir = std::path::PathBuf::from(std::env::var("OUT_DIR").unwrap());
/// let model = Model::Spatial { symmetry: Symmetry::Xz, kinematics: Kinematics::Quaternion };
/// eom_codegen::emit::emit_into(&out_dir, &[model]).unwrap();
/// // then, in the crate: mod auv { include!(concat!(env!("OUT_DIR"), "/spatial_xz_quaternion.rs")); }
/// ```
pub fn emit_into(out_dir: &Path, models: &[Model]) -> Result<Vec<Generated>, EmitError> {
    emit_into_with(out_dir, models, Trig::Kernel)
}

/// [`emit_into`] with the chosen sine and cosine (see [`generate_with`]).
pub fn emit_into_with(
    out_dir: &Path,
    models: &[Model],
    trig: Trig,
) -> Result<Vec<Generated>, EmitError> {
    models
        .iter()
        .map(|&model| {
            let generated = generate_with(model, trig)?;
            write_if_changed(
                &out_dir.join(format!("{}.rs", generated.name)),
                &generated.source,
            )?;
            Ok(generated)
        })
        .collect()
}
