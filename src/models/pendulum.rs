//! How the compound pendulum (4.24) fills its emitted parameters: from a
//! [`PendulumParameters`], which has already checked them.

use super::generated::pendulum::Parameters;
use crate::PendulumParameters;

/// The emitted parameters of a validated pendulum.
pub(super) fn emitted(parameters: &PendulumParameters) -> Parameters {
    Parameters {
        i0: parameters.i0(),
        mass: parameters.mass(),
        g: parameters.g(),
        h: parameters.h(),
    }
}
