//! The one check on scalar inputs: a number that must be finite, positive, not negative or
//! non-zero ([`Requirement`]), and the errors that say which and why.
//!
//! Every constructor that takes physical numbers — the models, the generic forms, the
//! reference problems, the mass properties, the inertia tensor, the swing test — checks
//! them here, once, so that what runs afterwards never meets a NaN mass or a negative moment
//! of inertia. The scene readers (catalog scenes, ship scenes, loads, time tables) check their
//! values with the same [`Requirement`]s and wrap the [`Violation`] in an error that names the
//! key, so that every refusal reads the same way: the key or field as the caller named it,
//! what it must be, and what it was.

use crate::Short;
use thiserror::Error;

/// A scalar input outside its domain: `field` must be `requirement`, and was `value`.
///
/// The errors of the models and the generic forms ([`crate::generic::ModelError`]), of the
/// mass properties ([`crate::mass::MassError`]), of the swing test ([`crate::swing::SwingError`])
/// and of the inertia tensor ([`crate::InertiaError`]) wrap it beside their own variants; the
/// reference problems return it as it is.
///
/// ```
/// use eom::generic::{ModelError, PlanarBody};
/// let err = PlanarBody::<f64>::new(-1.0, 2.0).unwrap_err();
/// assert!(matches!(err, ModelError::Parameter(ref e) if e.field == "mass"));
/// assert_eq!(err.to_string(), "mass must be positive and finite, got -1");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("{field} must be {requirement}, got {}", Short(*value))]
pub struct ParameterError {
    /// The input, named as the caller names it: the argument or field name (`"mass"`, `"i0"`,
    /// `"izz"`, `"pivot_to_cg"`), or a component (`"offset[2]"`, `"Ixy"`).
    pub field: &'static str,
    /// The value given.
    pub value: f64,
    /// What it must be, in words (`"positive and finite"`).
    pub requirement: &'static str,
}

/// What a number must be.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Requirement {
    /// Finite, of either sign.
    Finite,
    /// Finite and strictly positive.
    Positive,
    /// Finite and not negative (zero is allowed).
    NonNegative,
    /// Finite and not zero.
    NonZero,
}

impl Requirement {
    /// The requirement in words, as every message writes it.
    pub fn words(self) -> &'static str {
        match self {
            Requirement::Finite => "finite",
            Requirement::Positive => "positive and finite",
            Requirement::NonNegative => "finite and not negative",
            Requirement::NonZero => "non-zero and finite",
        }
    }

    /// Whether `value` meets it.
    pub fn holds(self, value: f64) -> bool {
        value.is_finite()
            && match self {
                Requirement::Finite => true,
                Requirement::Positive => value > 0.0,
                Requirement::NonNegative => value >= 0.0,
                Requirement::NonZero => value != 0.0,
            }
    }

    /// `value` if it meets the requirement, else what it failed.
    ///
    /// ```
    /// use eom::validate::Requirement;
    /// assert_eq!(Requirement::Positive.check(2.0), Ok(2.0));
    /// let refused = Requirement::Positive.check(-0.5).unwrap_err();
    /// assert_eq!(refused.to_string(), "must be positive and finite, got -0.5");
    /// ```
    pub fn check(self, value: f64) -> Result<f64, Violation> {
        match self.holds(value) {
            true => Ok(value),
            false => Err(Violation {
                requirement: self,
                value,
            }),
        }
    }

    /// Every entry of `values` checked; the error gives the index of the first that fails.
    pub fn check_all<const K: usize>(
        self,
        values: [f64; K],
    ) -> Result<[f64; K], (usize, Violation)> {
        for (i, value) in values.iter().enumerate() {
            self.check(*value).map_err(|violation| (i, violation))?;
        }
        Ok(values)
    }
}

/// A number that does not meet its [`Requirement`], before the caller names it: `must be
/// positive and finite, got -0.5`.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("must be {}, got {}", requirement.words(), Short(*value))]
pub struct Violation {
    /// What the number must be.
    pub requirement: Requirement,
    /// What it was.
    pub value: f64,
}

impl Violation {
    /// The violation as a [`ParameterError`] of `field`.
    pub fn of(self, field: &'static str) -> ParameterError {
        ParameterError {
            field,
            value: self.value,
            requirement: self.requirement.words(),
        }
    }
}

/// Returns `value` if it is finite and strictly positive.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<f64, ParameterError> {
    Requirement::Positive.check(value).map_err(|v| v.of(field))
}

/// Returns `value` if it is finite and not negative (zero is allowed).
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<f64, ParameterError> {
    Requirement::NonNegative
        .check(value)
        .map_err(|v| v.of(field))
}

/// Returns `value` if it is finite (of either sign).
pub(crate) fn finite(field: &'static str, value: f64) -> Result<f64, ParameterError> {
    Requirement::Finite.check(value).map_err(|v| v.of(field))
}

/// Returns `value` if it is finite and not zero (of either sign).
pub(crate) fn non_zero(field: &'static str, value: f64) -> Result<f64, ParameterError> {
    Requirement::NonZero.check(value).map_err(|v| v.of(field))
}

/// Returns `value` if `holds`, else the error naming `field` and `requirement`.
pub(crate) fn require(
    holds: bool,
    field: &'static str,
    value: f64,
    requirement: &'static str,
) -> Result<f64, ParameterError> {
    if holds {
        Ok(value)
    } else {
        Err(ParameterError {
            field,
            value,
            requirement,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_check_refuses_exactly_its_complement() {
        let values = [
            f64::NAN,
            f64::NEG_INFINITY,
            -1.0,
            -0.0,
            0.0,
            1e-300,
            2.0,
            f64::INFINITY,
        ];
        for value in values {
            let finite_value = value.is_finite();
            assert_eq!(positive("x", value).is_ok(), finite_value && value > 0.0);
            assert_eq!(
                non_negative("x", value).is_ok(),
                finite_value && value >= 0.0
            );
            assert_eq!(finite("x", value).is_ok(), finite_value);
            assert_eq!(non_zero("x", value).is_ok(), finite_value && value != 0.0);
        }
    }

    #[test]
    fn the_error_names_the_field_the_value_and_the_requirement() {
        let err = non_negative("h", -0.5).unwrap_err();
        assert_eq!(
            err,
            ParameterError {
                field: "h",
                value: -0.5,
                requirement: "finite and not negative"
            }
        );
        assert_eq!(
            err.to_string(),
            "h must be finite and not negative, got -0.5"
        );
        assert_eq!(positive("mass", 2.5), Ok(2.5));
    }
}
