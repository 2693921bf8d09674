//! The checker: a derived component equals its reference form exactly, or the build stops.
//!
//! Each [`Component`] pairs an expression computed from vector definitions with the book's
//! form as text. The text is parsed, the book's own definitions (4.13–4.14, ω = ψ̇k, …) are
//! substituted into it, and the difference must reduce to the empty sum. Anything left over is
//! reported term by term, with the equation number, so a wrong derivation or a wrong
//! transcription is found at once.

use crate::symbolic::{Expr, SymbolicError, parse};
use thiserror::Error;

/// A definition the book uses inside a reference form: `symbol := expression`.
pub type Definition = (String, Expr);

/// One scalar component of an equation: derived form against reference text.
#[derive(Debug, Clone)]
pub struct Component {
    /// What this component is (`"x"`, `"E[1,2]"`, `"I_xy"`).
    pub label: String,
    /// The form computed from the vector or matrix definitions.
    pub derived: Expr,
    /// The book's form, transcribed as Rust expression text.
    pub reference_text: String,
    /// Definitions substituted into the reference before comparing, in order.
    pub definitions: Vec<Definition>,
}

/// A numbered equation of the chapter with all its components.
#[derive(Debug, Clone)]
pub struct Equation {
    /// The chapter's number, e.g. `"4.51"`.
    pub number: &'static str,
    /// A one-line description.
    pub description: &'static str,
    /// The scalar components.
    pub components: Vec<Component>,
}

/// Why an equation was not proved.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum CheckError {
    /// The derived and the reference form differ; `residual` is derived − reference.
    #[error("equation ({number}), component {component}: derived − reference = {residual}")]
    Mismatch {
        /// The equation number.
        number: &'static str,
        /// The component label.
        component: String,
        /// The non-zero residual, in canonical form.
        residual: String,
    },
    /// The reference text could not be read or a definition could not be applied.
    #[error("equation ({number}), component {component}: {source}")]
    Reference {
        /// The equation number.
        number: &'static str,
        /// The component label.
        component: String,
        /// The underlying error.
        source: SymbolicError,
    },
    /// A derivation itself failed (an operation the engine cannot do).
    #[error("derivation of ({number}) failed: {source}")]
    Derivation {
        /// The equation number.
        number: &'static str,
        /// The underlying error.
        source: SymbolicError,
    },
}

impl Component {
    /// A component from its derived form, reference text and definitions.
    pub fn new(
        label: impl Into<String>,
        derived: Expr,
        reference_text: impl Into<String>,
        definitions: &[Definition],
    ) -> Self {
        Self {
            label: label.into(),
            derived,
            reference_text: reference_text.into(),
            definitions: definitions.to_vec(),
        }
    }

    /// The reference form, parsed, with the definitions substituted.
    pub fn reference(&self) -> Result<Expr, SymbolicError> {
        let mut reference = parse(&self.reference_text)?;
        for (symbol, replacement) in &self.definitions {
            reference = reference.subs(symbol, replacement)?;
        }
        Ok(reference)
    }

    /// derived − reference, in canonical form.
    pub fn residual(&self) -> Result<Expr, SymbolicError> {
        Ok(&self.derived - &self.reference()?)
    }
}

impl Equation {
    /// The total number of terms of the derived forms (a measure of the work proved).
    pub fn term_count(&self) -> usize {
        self.components.iter().map(|c| c.derived.term_count()).sum()
    }

    /// Proves every component, or names the first that fails.
    pub fn check(&self) -> Result<(), CheckError> {
        self.components
            .iter()
            .try_for_each(|c| self.check_component(c))
    }

    fn check_component(&self, component: &Component) -> Result<(), CheckError> {
        let residual = component
            .residual()
            .map_err(|source| CheckError::Reference {
                number: self.number,
                component: component.label.clone(),
                source,
            })?;
        if residual.is_zero() {
            Ok(())
        } else {
            Err(CheckError::Mismatch {
                number: self.number,
                component: component.label.clone(),
                residual: residual.to_string(),
            })
        }
    }
}

/// Parses `(symbol, text)` pairs into definitions.
pub fn definitions(pairs: &[(&str, &str)]) -> Result<Vec<Definition>, SymbolicError> {
    pairs
        .iter()
        .map(|(symbol, text)| Ok(((*symbol).to_owned(), parse(text)?)))
        .collect()
}

/// Derives every equation of the chapter and proves each against the book.
///
/// This is what `build.rs` of `eom` calls: an error stops the build.
///
/// ```
/// let equations = eom_codegen::check::check_all().unwrap();
/// assert!(equations.iter().any(|e| e.number == "4.51"));
/// ```
pub fn check_all() -> Result<Vec<Equation>, CheckError> {
    let equations = crate::derivation::all()?;
    equations.iter().try_for_each(Equation::check)?;
    Ok(equations)
}
