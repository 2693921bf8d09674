//! What the planar models (4.39, 4.43, 4.46 with the track 4.44) check before they are built.

use crate::ParameterError;
use crate::validate::{finite, positive};

/// M > 0 and I_zz > 0 (about G), returned as given.
pub(super) fn validate(mass: f64, izz: f64) -> Result<(f64, f64), ParameterError> {
    Ok((positive("mass", mass)?, positive("izz", izz)?))
}

/// A finite x_G, the position of G ahead of midship (4.45).
pub(super) fn validate_x_g(x_g: f64) -> Result<f64, ParameterError> {
    finite("x_g", x_g)
}
