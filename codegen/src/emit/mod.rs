//! Emission: from a model to formatted, deterministic Rust source.
//!
//! For each model the emitter builds the system with every strategy the model allows, turns
//! each into a straight-line program ([`program`]), keeps the cheapest by operation count,
//! proves that it folds back to the system exactly ([`fold`]), and formats it.
//! The same model always gives the same bytes: nothing here iterates a hash map, reads the
//! clock or the environment. [`write_if_changed`] leaves a file untouched when its bytes are
//! already right, so Cargo does not rebuild for nothing.

mod build;
mod catalog;
pub mod fold;
pub mod program;
mod rust;
mod writer;

pub use program::{Operations, Program, identifier};
pub use rust::{F64Formula, f64_value};

use crate::model::{BuildError, Jacobian, Model, Strategy, System};
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why emission failed.
#[derive(Debug, Error)]
pub enum EmitError {
    /// The model could not be built or did not verify.
    #[error(transparent)]
    Model(#[from] BuildError),
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
    /// A one-line title.
    pub title: String,
    /// How many entries the state has.
    pub state_len: usize,
    /// How many inputs the model takes.
    pub inputs_len: usize,
    /// The fields of its `Parameters`, in order.
    pub parameters: Vec<String>,
    /// Whether it emits a `potential_energy` beside its `kinetic_energy`.
    pub potential_energy: bool,
    /// The strategy that gave the fewest operations.
    pub strategy: Strategy,
    /// The cost of one call.
    pub operations: Operations,
    /// The cost of one call of `state_jacobian` (∂f/∂x).
    pub state_jacobian_operations: Operations,
    /// The entries of ∂f/∂x that do not vanish identically, as (row, column).
    pub state_jacobian: Vec<(usize, usize)>,
    /// The entries of ∂f/∂u that do not vanish identically, as (row, column).
    pub input_jacobian: Vec<(usize, usize)>,
    /// The formatted source.
    pub source: String,
}

/// Generates one model's source, after proving that the program folds back to the system:
/// its right-hand side, its energies, and its Jacobians ∂f/∂x and ∂f/∂u against the exact
/// derivative of the system.
///
/// ```
/// use eom_codegen::emit::generate;
/// use eom_codegen::model::{Kinematics, Model, Symmetry};
/// let model = Model::Spatial { symmetry: Symmetry::Principal, kinematics: Kinematics::Euler };
/// let generated = generate(model).unwrap();
/// assert!(generated.source.contains("pub fn rhs<T: SimdRealField + Copy>"));
/// // One call for the three angles in `rhs`, one in `state_jacobian`.
/// assert_eq!(generated.source.matches("eom_kernel::sin_cos(").count(), 2);
/// assert_eq!(generated.operations.trig, 3); // one sin_cos per Euler angle
/// ```
pub fn generate(model: Model) -> Result<Generated, EmitError> {
    let mut best: Option<(Strategy, crate::model::System, Program, Operations)> = None;
    for &strategy in model.strategies() {
        let system = model.system(strategy)?;
        let program = Program::build(&system);
        let operations = program.operations(&program.rhs);
        let better = best
            .as_ref()
            .is_none_or(|(_, _, _, o)| operations.cost() < o.cost());
        if better {
            best = Some((strategy, system, program, operations));
        }
    }
    let (strategy, system, _, operations) = best.expect("every model has a strategy");
    // The strategy is chosen by the cost of `rhs` alone; the Jacobians are built after it in
    // the same arena, so the right-hand side's nodes and names are those it was chosen by.
    let jacobian = Jacobian::of(&system)?;
    let program = Program::build_with_jacobian(&system, &jacobian);
    fold::verify(&system, &program)?;
    let jacobians = program
        .jacobians
        .as_ref()
        .expect("built with its Jacobians");
    let state_jacobian_operations = program.operations(&jacobians.state);
    let (state_jacobian, input_jacobian) = (
        jacobians.state_pattern.clone(),
        jacobians.input_pattern.clone(),
    );
    let source = rust::source(&system, &program, &format!("{strategy:?}")).map_err(|source| {
        EmitError::Syntax {
            model: system.name.clone(),
            source,
        }
    })?;
    Ok(Generated {
        model,
        name: system.name,
        title: format!(
            "{} (equations {}).",
            system.title,
            system.equations.join(", ")
        ),
        state_len: system.state.len(),
        inputs_len: system.inputs.len(),
        parameters: system
            .parameters
            .iter()
            .map(|p| identifier(&p.symbol))
            .collect(),
        potential_energy: system.potential_energy.is_some(),
        strategy,
        operations,
        state_jacobian_operations,
        state_jacobian,
        input_jacobian,
        source,
    })
}

/// Builds a system that is not in the catalog (a ship of a scene's own hydrodynamic table)
/// into its program, and proves the program equal to the system, as [`generate`] does for
/// the catalog: what `eom` evaluates where the system is known only at run time.
pub fn prove(system: &System) -> Result<Program, EmitError> {
    let program = Program::build(system);
    fold::verify(system, &program)?;
    Ok(program)
}

/// As [`prove`], with the Jacobians ∂f/∂x and ∂f/∂u built in the same arena and folded back
/// against the exact derivative of the system ([`Jacobian::of`]) too: what a scene-defined
/// model evaluates, and what [`system_source`] writes.
pub fn prove_with_jacobians(system: &System) -> Result<Program, EmitError> {
    let jacobian = Jacobian::of(system)?;
    let program = Program::build_with_jacobian(system, &jacobian);
    fold::verify(system, &program)?;
    Ok(program)
}

/// The Rust source of a system that is not in the catalog, proved like a catalog model's: for
/// a user's `build.rs` that wants a ship of its own table compiled. The program is built with
/// its Jacobians ∂f/∂x and ∂f/∂u and folded back against the system and its exact derivative
/// before it is written, so the file implements the model contract (`eom_kernel::Model`) as
/// every catalog model's does.
///
/// ```
/// use eom_codegen::model::ship::{Force, ShipForm, ShipSpec, Term, Units, YawInertia, ship};
/// let spec = ShipSpec {
///     units: Units::Dimensional,
///     yaw_inertia: YawInertia::AboutG,
///     terms: vec![
///         Term { force: Force::Y, powers: [0, 1, 0, 0, 0] },
///         Term { force: Force::N, powers: [0, 0, 1, 0, 0] },
///     ],
///     propulsion: false,
///     form: ShipForm::Polynomial,
///     current: false,
///     applied: false,
/// };
/// let source = eom_codegen::emit::system_source(&ship("two_term_ship", &spec).unwrap()).unwrap();
/// assert!(source.contains("pub y_v: f64") && source.contains("pub n_r: f64"));
/// assert!(!source.contains("y_vvv"));
/// assert!(source.contains("impl<T: SimdRealField + Copy> eom_kernel::Model<T, 7, 1> for Coefficients<T>"));
/// ```
pub fn system_source(system: &System) -> Result<String, EmitError> {
    let program = prove_with_jacobians(system)?;
    rust::source(system, &program, "Expanded").map_err(|source| EmitError::Syntax {
        model: system.name.clone(),
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

/// Generates each model into `out_dir/<name>.rs` (the call for a user's `build.rs`).
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
    models
        .iter()
        .map(|&model| {
            let generated = generate(model)?;
            write_if_changed(
                &out_dir.join(format!("{}.rs", generated.name)),
                &generated.source,
            )?;
            Ok(generated)
        })
        .collect()
}

/// Generates each model into `out_dir/<name>.rs` and the catalog of them all into
/// `out_dir/catalog.rs` (the call `eom`'s own build script makes).
pub fn emit_with_catalog(out_dir: &Path, models: &[Model]) -> Result<Vec<Generated>, EmitError> {
    let generated = emit_into(out_dir, models)?;
    let source = catalog::source(&generated).map_err(|source| EmitError::Syntax {
        model: "catalog".into(),
        source,
    })?;
    write_if_changed(&out_dir.join("catalog.rs"), &source)?;
    Ok(generated)
}
