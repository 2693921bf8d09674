//! Radii of gyration (4.16–4.17) and principal axes: the two ways to read an inertia tensor that
//! a naval architect compares across ships of different size.
//!
//! A radius of gyration `κ = √(I/M)` is the distance at which the whole mass would have the same
//! moment; it scales with the body, so `κ_xx / B` and `κ_yy / L` compare a model with its ship
//! (4.22). The principal axes are the axes in which the products of inertia vanish.

use crate::InertiaTensor;
use nalgebra::{Matrix3, Vector3};

/// The radius of gyration `κ = √(I / M)` of a moment `I` for a body of mass `M` (4.16–4.17).
///
/// Both arguments are expected positive (as they are in a [`crate::mass::MassProperties`]).
///
/// ```
/// // The uniform sphere (4.18–4.19): I = 2/5 M R², so κ = √(2/5) R ≈ 0.632 R.
/// let kappa = eom::mass::radius_of_gyration(0.4 * 3.0 * 2.0_f64.powi(2), 3.0);
/// assert!((kappa / 2.0 - 0.632).abs() < 5e-4);
/// ```
pub fn radius_of_gyration(moment: f64, mass: f64) -> f64 {
    (moment / mass).sqrt()
}

/// The radii of gyration `(κ_xx, κ_yy, κ_zz)` of a tensor's three moments (4.16–4.17).
pub fn radii_of_gyration(inertia: &InertiaTensor, mass: f64) -> Vector3<f64> {
    inertia
        .matrix()
        .diagonal()
        .map(|moment| radius_of_gyration(moment, mass))
}

/// Principal moments of inertia, their axes and their radii of gyration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrincipalAxes {
    /// The principal moments, ascending.
    pub moments: Vector3<f64>,
    /// The principal axes as the columns of a proper rotation (determinant +1), in body axes:
    /// `[I] = axes · diag(moments) · axesᵀ`.
    pub axes: Matrix3<f64>,
    /// The radius of gyration about each principal axis.
    pub radii: Vector3<f64>,
}

impl PrincipalAxes {
    /// The principal moments and axes of `inertia` (nalgebra's symmetric eigendecomposition),
    /// for a body of mass `mass`.
    ///
    /// Eigenvectors are defined up to sign; to make the output reproducible, the first two axes
    /// are turned so that their largest component is positive and the third is their cross
    /// product, so that the axes form a right-handed frame.
    pub fn of(inertia: &InertiaTensor, mass: f64) -> Self {
        let (moments, raw) = inertia.principal();
        let first = largest_component_positive(raw.column(0).into_owned());
        let second = largest_component_positive(raw.column(1).into_owned());
        let axes = Matrix3::from_columns(&[first, second, first.cross(&second)]);
        let radii = moments.map(|moment| radius_of_gyration(moment, mass));
        Self {
            moments,
            axes,
            radii,
        }
    }
}

fn largest_component_positive(axis: Vector3<f64>) -> Vector3<f64> {
    if axis[axis.iamax()] < 0.0 {
        -axis
    } else {
        axis
    }
}
