//! What the heavy top (4.50 about the pivot with I_O by Steiner 4.23) checks before it is
//! built.

use super::Symmetry;
use super::spatial::check_symmetry;
use crate::InertiaTensor;
use crate::generic::ModelError;
use crate::validate::{finite, positive, require};

/// A validated top: the fields of both emitted `Parameters`.
pub(super) struct Body {
    pub mass: f64,
    pub ixx: f64,
    pub iyy: f64,
    pub izz: f64,
    pub h: f64,
    pub g: f64,
}

/// M > 0; a tensor about G in principal axes; h and g finite, of either sign (h < 0 puts G
/// below the pivot when the body z-axis points up, g < 0 turns the weight over); and the
/// moments about the pivot, I_xx + M h² and I_yy + M h², finite (I_zz is the tensor's own).
/// Those moments are then positive, as the tensor's are; their reciprocals are the emitted
/// coefficients.
pub(super) fn validate(
    mass: f64,
    inertia_at_g: &InertiaTensor,
    h: f64,
    g: f64,
) -> Result<Body, ModelError> {
    let mass = positive("mass", mass)?;
    check_symmetry(inertia_at_g, Symmetry::Principal)?;
    let h = finite("h", h)?;
    let g = finite("g", g)?;
    let shift = mass * h * h;
    let (ixx, iyy, izz) = (inertia_at_g.ixx(), inertia_at_g.iyy(), inertia_at_g.izz());
    for moment in [ixx + shift, iyy + shift] {
        require(
            moment.is_finite() && moment > 0.0,
            "h",
            h,
            "small enough that the moments about the pivot, I + M h² (4.23), are finite",
        )?;
    }
    Ok(Body {
        mass,
        ixx,
        iyy,
        izz,
        h,
        g,
    })
}
