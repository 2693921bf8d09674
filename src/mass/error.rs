//! Why a mass property cannot be built: one enum for the primitives, the placement of parts and
//! their combination, so that every error names the quantity at fault.

use crate::validate::finite;
use crate::{InertiaError, ParameterError};
use thiserror::Error;

/// A mass, a dimension or a position that no rigid body can have.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MassError {
    /// A mass, a dimension, a coordinate or an angle is out of its range: not positive, not
    /// finite, or negative where zero is the least it may be (an inner radius).
    #[error(transparent)]
    Parameter(#[from] ParameterError),
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

/// Checks that every component of a vector is finite; `fields` names the components.
pub(crate) fn finite3(
    fields: [&'static str; 3],
    v: &nalgebra::Vector3<f64>,
) -> Result<(), MassError> {
    for (field, &value) in fields.iter().zip(v.iter()) {
        finite(field, value)?;
    }
    Ok(())
}
