//! What the compound pendulum (4.24) checks before it is built.

use super::generated::pendulum::Parameters;
use crate::generic::ModelError;
use crate::generic::error::{
    check_finite, check_mass, check_non_negative, check_positive, check_steiner,
};

/// I₀ > 0 (about the pivot), M > 0, g finite, h ≥ 0 and I₀ ≥ M h² (4.29).
pub(super) fn validate(i0: f64, mass: f64, g: f64, h: f64) -> Result<Parameters, ModelError> {
    let parameters = Parameters {
        i0: check_positive("I0", i0)?,
        mass: check_mass(mass)?,
        g: check_finite("g", g)?,
        h: check_non_negative("h", h)?,
    };
    check_steiner(i0, mass, h)?;
    Ok(parameters)
}
