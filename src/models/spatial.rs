//! What the spatial models (4.49 with 4.51 and kinematics) check before they are built, and
//! how a body's tensor fills an emitted `Parameters`.

use super::Symmetry;
use super::generated;
use crate::InertiaTensor;
use crate::generic::ModelError;
use crate::validate::positive;

/// Validates a body for a spatial model of `symmetry`: M > 0, the products the class prunes
/// zero, and a tensor that can be inverted in f64. Returns the mass.
pub(super) fn validate(
    mass: f64,
    inertia: &InertiaTensor,
    symmetry: Symmetry,
) -> Result<f64, ModelError> {
    let mass = positive("mass", mass)?;
    check_symmetry(inertia, symmetry)?;
    check_invertible(inertia)?;
    Ok(mass)
}

/// The relative size below which a product of inertia counts as zero: 1e-12 of the largest
/// moment, which allows round-off of a computed tensor and is far below any product that
/// changes the motion measurably.
pub const PRODUCT_TOLERANCE: f64 = 1e-12;

/// A product that the class prunes must vanish, to [`PRODUCT_TOLERANCE`].
pub(super) fn check_symmetry(
    inertia: &InertiaTensor,
    symmetry: Symmetry,
) -> Result<(), ModelError> {
    let scale = inertia.ixx().max(inertia.iyy()).max(inertia.izz());
    for &field in symmetry.pruned() {
        let value = match field {
            "Ixy" => inertia.ixy(),
            "Iyz" => inertia.iyz(),
            _ => inertia.izx(),
        };
        if value.abs() > PRODUCT_TOLERANCE * scale {
            return Err(ModelError::SymmetryClass {
                field,
                value,
                class: symmetry.name(),
            });
        }
    }
    Ok(())
}

/// The generated coefficients hold [I]⁻¹ through 1/det[I]: a determinant that underflows or
/// overflows in f64 would make them infinite or zero and every rate NaN or wrong, so it is
/// refused as the generic form refuses it.
fn check_invertible(inertia: &InertiaTensor) -> Result<(), ModelError> {
    let determinant = inertia.matrix().determinant();
    if determinant.is_normal() {
        Ok(())
    } else {
        Err(ModelError::SingularInertia { determinant })
    }
}

/// An emitted spatial `Parameters` struct, filled from a mass and an inertia tensor.
///
/// Each symmetry class emits only the products it keeps, named as the chapter names them
/// (`ixy`, `iyz`, `ixz`, with the sign of 4.14). This is the one place that maps a tensor's
/// entries onto those fields. It does not validate: build the typed model (e.g.
/// [`SpatialFullEuler::new`](super::SpatialFullEuler::new)) for that.
///
/// ```
/// use eom::InertiaTensor;
/// use eom::models::{FromBody, Model, SpatialPrincipalEuler, generated};
///
/// let inertia = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.0).unwrap();
/// let typed = SpatialPrincipalEuler::<f64>::new(5.0, &inertia).unwrap();
/// let emitted = generated::spatial_principal_euler::Parameters::from_body(5.0, &inertia);
/// let k = generated::spatial_principal_euler::Coefficients::<f64>::new(&emitted);
/// let state = [1.0, 0.2, -0.1, 0.3, -0.2, 0.5, 0.0, 0.0, 0.0, 0.1, 0.2, 0.3];
/// let input = [10.0, -2.0, 1.0, 0.5, 0.2, -0.3];
/// let direct = generated::spatial_principal_euler::rhs(&k, &state, &input);
/// assert_eq!(typed.rhs(&state, &input), direct);
/// ```
pub trait FromBody {
    /// The parameters of a body of `mass` and `inertia` (about G, body axes).
    fn from_body(mass: f64, inertia: &InertiaTensor) -> Self;
}

/// `FromBody` for every spatial module of the catalog: each emitted field takes the tensor
/// entry of its name.
macro_rules! from_body {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {
        $(from_body!(@impl $module [$($parameter),*] $family $(($($option),+))?);)*
    };
    // Spatial models only: a top's parameters are more than a body (where G is, and gravity).
    (@impl $module:ident [$($parameter:ident),*] Spatial($symmetry:ident, $kinematics:ident)) => {
        impl FromBody for generated::$module::Parameters {
            fn from_body(mass: f64, inertia: &InertiaTensor) -> Self {
                Self { $($parameter: from_body!(@entry $parameter, mass, inertia),)* }
            }
        }
    };
    (@impl $module:ident [$($parameter:ident),*] $($other:tt)*) => {};
    (@entry mass, $mass:ident, $inertia:ident) => { $mass };
    (@entry ixx, $mass:ident, $inertia:ident) => { $inertia.ixx() };
    (@entry iyy, $mass:ident, $inertia:ident) => { $inertia.iyy() };
    (@entry izz, $mass:ident, $inertia:ident) => { $inertia.izz() };
    (@entry ixy, $mass:ident, $inertia:ident) => { $inertia.ixy() };
    (@entry iyz, $mass:ident, $inertia:ident) => { $inertia.iyz() };
    (@entry ixz, $mass:ident, $inertia:ident) => { $inertia.izx() };
}

for_each_model!(from_body);
