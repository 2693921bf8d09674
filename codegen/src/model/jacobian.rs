//! The Jacobians ∂f/∂x and ∂f/∂u of a proved system, by exact differentiation.
//!
//! Linearising a model about an operating point needs the derivative of its right-hand side.
//! Taking it here, of the proved system, makes it exact and lets the emitted Jacobian be
//! proved like `rhs`: folded back and compared with these expressions term by term. Every
//! output is a polynomial in the atoms (symbols, sin and cos of angles, with integer powers),
//! so [`Expr::diff`] differentiates it exactly (d sin θ = cos θ dθ, d cos⁻¹θ = sin θ cos⁻²θ dθ).
//!
//! The one value that is not such a polynomial is a stage whose reciprocal a later value takes
//! (|q|² of the quaternion track, inverted as 1/|q|²): it is kept as a symbol, *opaque*, as
//! the fold-back proof keeps it, and the chain rule carries its derivative,
//! d(1/s)/dx = −s⁻² ds/dx with ds/dx from its own definition. Every other stage is
//! substituted back first, so the derivative is that of the proved equations, not of one way
//! of staging them.

use super::system::{BuildError, System};
use crate::symbolic::{Atom, Expr, SymbolicError};

/// One entry of a Jacobian that does not vanish identically.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Entry {
    /// The row: the index of the state whose rate is differentiated.
    pub row: usize,
    /// The column: the index of the state (or input) it is differentiated by.
    pub column: usize,
    /// The derivative, in parameters, state, inputs and the opaque stages.
    pub value: Expr,
}

/// ∂f/∂x and ∂f/∂u of a system, their non-zero entries in row-major order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Jacobian {
    /// The entries of ∂f/∂x.
    pub state: Vec<Entry>,
    /// The entries of ∂f/∂u.
    pub input: Vec<Entry>,
    /// The stages kept as symbols (see the module doc).
    pub opaque: Vec<String>,
}

impl Jacobian {
    /// Differentiates the outputs of `system` by every state entry and every input.
    ///
    /// ```
    /// use eom_codegen::model::{Jacobian, Model};
    /// let system = Model::Pendulum.system(eom_codegen::model::Strategy::Expanded).unwrap();
    /// let jacobian = Jacobian::of(&system).unwrap();
    /// // θ̇ by θ̇, θ̈ by θ (−Mgh cos θ / I₀); θ̈ by M_O (1/I₀).
    /// let pattern: Vec<_> = jacobian.state.iter().map(|e| (e.row, e.column)).collect();
    /// assert_eq!(pattern, [(0, 1), (1, 0)]);
    /// assert_eq!(jacobian.input.len(), 1);
    /// ```
    pub fn of(system: &System) -> Result<Jacobian, BuildError> {
        let symbolic = |source: SymbolicError| BuildError::Symbolic {
            model: system.name.clone(),
            source,
        };
        let opaque = opaque_stages(system);
        let definitions: Vec<(String, Expr)> = system
            .stages
            .iter()
            .filter(|(name, _)| opaque.contains(name))
            .map(|(name, value)| Ok((name.clone(), expand(system, value, &opaque)?)))
            .collect::<Result<_, SymbolicError>>()
            .map_err(symbolic)?;
        let outputs: Vec<Expr> = system
            .outputs
            .iter()
            .map(|output| expand(system, output, &opaque))
            .collect::<Result<_, _>>()
            .map_err(symbolic)?;
        Ok(Jacobian {
            state: entries(&outputs, &system.state, &definitions),
            input: entries(&outputs, &system.inputs, &definitions),
            opaque,
        })
    }
}

/// The non-zero ∂output/∂variable, row-major.
fn entries(outputs: &[Expr], variables: &[&str], opaque: &[(String, Expr)]) -> Vec<Entry> {
    let mut found = Vec::new();
    for (row, output) in outputs.iter().enumerate() {
        for (column, variable) in variables.iter().enumerate() {
            let value = total_derivative(output, variable, opaque);
            if !value.is_zero() {
                found.push(Entry { row, column, value });
            }
        }
    }
    found
}

/// d value / d symbol, through the opaque stages by the chain rule.
fn total_derivative(value: &Expr, symbol: &str, opaque: &[(String, Expr)]) -> Expr {
    let mut derivative = value.diff(symbol);
    for (name, definition) in opaque {
        let through = value.diff(name);
        if !through.is_zero() {
            derivative = derivative + through * total_derivative(definition, symbol, opaque);
        }
    }
    derivative
}

/// The stages whose reciprocal a later stage or an output takes: they stay symbols.
pub fn opaque_stages(system: &System) -> Vec<String> {
    let values = system
        .stages
        .iter()
        .map(|(_, value)| value)
        .chain(&system.outputs);
    let mut opaque: Vec<String> = Vec::new();
    for value in values {
        for (monomial, _) in value.terms() {
            for (atom, power) in monomial.factors() {
                if let Atom::Symbol(name) = atom
                    && power < 0
                    && system.stages.iter().any(|(stage, _)| stage == name)
                    && !opaque.contains(name)
                {
                    opaque.push(name.clone());
                }
            }
        }
    }
    opaque
}

/// A value with every stage but the opaque ones substituted back.
pub fn expand(system: &System, value: &Expr, opaque: &[String]) -> Result<Expr, SymbolicError> {
    system
        .stages
        .iter()
        .rev()
        .filter(|(name, _)| !opaque.contains(name))
        .try_fold(value.clone(), |value, (name, definition)| {
            value.subs(name, definition)
        })
}
