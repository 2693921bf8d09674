//! A first-order system ready for emission: parameters, state, inputs, staged intermediates
//! and one output per state (its time derivative), all as canonical expressions.

use crate::symbolic::{Expr, SymbolicError};
use std::borrow::Cow;
use thiserror::Error;

/// Why a model could not be built or verified.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum BuildError {
    /// The symbolic engine could not perform a step.
    #[error("model {model}: {source}")]
    Symbolic {
        /// The model's name.
        model: String,
        /// The underlying error.
        source: SymbolicError,
    },
    /// A check on the solved or staged form failed: the emitted code would not be the proved
    /// equations.
    #[error("model {model}: {what} (residual {residual})")]
    Verification {
        /// The model's name.
        model: String,
        /// Which check failed.
        what: String,
        /// What was left over.
        residual: String,
    },
}

/// A parameter-level quantity that is not a polynomial: the reciprocal of a parameter
/// polynomial, computed once (the determinant of a mass matrix that is not diagonal).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Reciprocal {
    /// The symbol standing for `1 / of`.
    pub symbol: String,
    /// The parameter polynomial it inverts.
    pub of: Expr,
}

/// One scalar parameter, given by the user in f64.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Parameter {
    /// The symbol used in the equations (`Ixx`, `M`, `x_G`).
    pub symbol: Cow<'static, str>,
    /// What it is, for the generated doc comment.
    pub doc: Cow<'static, str>,
}

/// A named intermediate computed at every call, before the outputs.
pub type Stage = (String, Expr);

/// A run of outputs that come from one equation: the generated code puts `comment` above the
/// first of them.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Group {
    /// The index of the first output of the run.
    pub first: usize,
    /// What the outputs are and the equation they come from: `4.49: translation, body axes`.
    pub comment: String,
}

/// The system `d(state)/dt = outputs(parameters, state, inputs)`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct System {
    /// The model's name, a Rust identifier (`spatial_principal_euler`).
    pub name: String,
    /// A one-line title for docs.
    pub title: String,
    /// The chapter's equation numbers that this system implements.
    pub equations: Vec<&'static str>,
    /// Parameters in order.
    pub parameters: Vec<Parameter>,
    /// Reciprocals of parameter polynomials, computed once.
    pub reciprocals: Vec<Reciprocal>,
    /// State symbols in order.
    pub state: Vec<&'static str>,
    /// Input symbols (applied forces and moments) in order.
    pub inputs: Vec<&'static str>,
    /// Intermediates, each in terms of state, inputs and earlier stages.
    pub stages: Vec<Stage>,
    /// The derivative of each state symbol, in state order.
    pub outputs: Vec<Expr>,
    /// The outputs grouped by equation, in order.
    pub groups: Vec<Group>,
    /// The kinetic energy of the state, from the proved 4.32.
    pub kinetic_energy: Option<Expr>,
    /// The energy's formula in the model's own symbols, for the generated comment.
    pub energy_formula: Option<&'static str>,
    /// The potential energy of the state, for a model in a field (the weight of a body on a
    /// pivot), from the same vectors as the field's moment.
    pub potential_energy: Option<Expr>,
    /// The potential's formula in the model's own symbols, for the generated comment.
    pub potential_formula: Option<&'static str>,
    /// Names for parameter expressions that have one in the chapter (the entries of an
    /// inverse mass matrix or inertia tensor): a hoisted coefficient equal to one of them, up
    /// to sign, takes its name and description.
    pub coefficient_names: Vec<CoefficientName>,
}

/// A parameter expression with a name of its own (see [`System::coefficient_names`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CoefficientName {
    /// The value.
    pub value: Expr,
    /// The Rust identifier: `inv_inertia_xy`.
    pub name: String,
    /// What it is, for the doc comment: `([I]⁻¹)_xy`.
    pub description: String,
}

impl System {
    /// The outputs with every stage substituted back: what the staged program computes.
    pub fn expanded_outputs(&self) -> Result<Vec<Expr>, SymbolicError> {
        (0..self.outputs.len())
            .map(|i| self.expanded_output(i))
            .collect()
    }

    /// One output with every stage substituted back.
    pub fn expanded_output(&self, index: usize) -> Result<Expr, SymbolicError> {
        self.stages.iter().rev().try_fold(
            self.outputs[index].clone(),
            |output, (symbol, definition)| output.subs(symbol, definition),
        )
    }

    /// The system with symbols replaced in every stage and output (for checks at a point of a
    /// parametrisation, e.g. the quaternion of Euler angles, where |q| = 1 identically).
    pub fn substituted(&self, substitutions: &[(&str, Expr)]) -> Result<System, SymbolicError> {
        let mut system = self.clone();
        for (_, definition) in system.stages.iter_mut() {
            *definition = definition.subs_all(substitutions)?;
        }
        for output in system.outputs.iter_mut() {
            *output = output.subs_all(substitutions)?;
        }
        Ok(system)
    }

    /// True for a symbol that is a parameter or a reciprocal of parameters.
    pub fn is_parameter(&self, symbol: &str) -> bool {
        self.parameters.iter().any(|p| p.symbol == symbol)
            || self.reciprocals.iter().any(|r| r.symbol == symbol)
    }
}
