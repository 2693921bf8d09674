//! What the planar models (4.39, 4.43, 4.46 with the track 4.44) check before they are built.

use crate::generic::ModelError;
use crate::generic::error::{check_finite, check_mass, check_positive};

/// M > 0 and I_zz > 0 (about G), returned as given.
pub(super) fn validate(mass: f64, izz: f64) -> Result<(f64, f64), ModelError> {
    Ok((check_mass(mass)?, check_positive("Izz", izz)?))
}

/// A finite x_G, the position of G ahead of midship (4.45).
pub(super) fn validate_x_g(x_g: f64) -> Result<f64, ModelError> {
    check_finite("x_G", x_g)
}
