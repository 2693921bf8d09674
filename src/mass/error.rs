//! Why a mass property cannot be built: one enum for the primitives, the placement of parts and
//! their combination, so that every error names the quantity at fault.

use crate::InertiaError;
use thiserror::Error;

/// A mass, a dimension or a position that no rigid body can have.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MassError {
    /// A mass or a dimension is zero, negative, NaN or infinite.
    #[error("{field} must be positive and finite, got {value}")]
    NotPositive {
        /// The quantity, e.g. `"mass"` or `"radius"`.
        field: &'static str,
        /// Its value.
        value: f64,
    },
    /// A quantity that may be zero (an inner radius) is negative or NaN.
    #[error("{field} must be zero or positive, got {value}")]
    Negative {
        /// The quantity, e.g. `"inner_radius"`.
        field: &'static str,
        /// Its value.
        value: f64,
    },
    /// A coordinate or an angle is NaN or infinite.
    #[error("{field} must be finite, got {value}")]
    NotFinite {
        /// The quantity, e.g. `"offset[2]"`.
        field: &'static str,
        /// Its value.
        value: f64,
    },
    /// A hollow cylinder whose bore is wider than the cylinder.
    #[error("inner radius {inner} exceeds the outer radius {outer}")]
    InnerRadiusTooLarge {
        /// The inner radius.
        inner: f64,
        /// The outer radius.
        outer: f64,
    },
    /// A composite body with no parts.
    #[error("a composite body needs at least one part")]
    NoParts,
    /// The tensor built is not that of a rigid body (for instance, point masses on one line have
    /// no moment about that line).
    #[error(transparent)]
    Inertia(#[from] InertiaError),
}

/// Checks that `value` is positive and finite, naming `field` if not.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<f64, MassError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(MassError::NotPositive { field, value })
    }
}

/// Checks that every component of a vector is finite; `fields` names the components.
pub(crate) fn finite3(
    fields: [&'static str; 3],
    v: &nalgebra::Vector3<f64>,
) -> Result<(), MassError> {
    for (field, &value) in fields.iter().zip(v.iter()) {
        if !value.is_finite() {
            return Err(MassError::NotFinite { field, value });
        }
    }
    Ok(())
}
