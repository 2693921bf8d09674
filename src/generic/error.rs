//! Why a parameter set is refused.
//!
//! Every generic model validates its `f64` parameters once, in its constructor, with the
//! crate's one set of checks ([`ParameterError`]), so that the right-hand sides never meet a
//! NaN mass or a negative moment of inertia and never need to check anything in the hot path.

use crate::{InertiaError, ParameterError};
use thiserror::Error;

/// Why a model cannot be built from the parameters given, or why a state is outside the
/// domain of a formulation.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ModelError {
    /// A scalar parameter breaks its requirement (its message names the parameter as the
    /// constructor's argument does: `"mass"`, `"izz"`, `"x_g"`, …).
    #[error(transparent)]
    Parameter(#[from] ParameterError),
    /// The inertia tensor is not that of a rigid body (its message names the failed check).
    #[error(transparent)]
    Inertia(#[from] InertiaError),
    /// A product of inertia that the model's symmetry class prunes is not zero: the pruned
    /// equations would silently be wrong for this body.
    #[error(
        "product of inertia {field} = {} must be zero for the {class} symmetry class",
        crate::Short(*value)
    )]
    SymmetryClass {
        /// The product, named as in the chapter (`"Ixy"`, `"Iyz"`, `"Ixz"`).
        field: &'static str,
        /// The value given.
        value: f64,
        /// The class that requires it to vanish.
        class: &'static str,
    },
    /// The inertia tensor passed validation but its inverse could not be formed in floating
    /// point (a determinant that underflows or overflows).
    #[error("inertia tensor cannot be inverted (determinant {determinant})")]
    SingularInertia {
        /// The determinant of `[I]`.
        determinant: f64,
    },
    /// The pitch is so close to ±90° that the Euler-angle rates of 4.60 (tan θ, sec θ) are
    /// meaningless: the attitude must be carried by a quaternion there.
    #[error(
        "Euler angles are singular: |cos θ| = {cos_theta:e} at pitch θ = {theta} rad is below {limit:e}"
    )]
    GimbalLock {
        /// The pitch angle θ.
        theta: f64,
        /// `|cos θ|`.
        cos_theta: f64,
        /// The smallest `|cos θ|` the caller accepts.
        limit: f64,
    },
}
