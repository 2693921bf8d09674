//! Steiner's theorem (the parallel-axis theorem, 4.23), with the products of inertia.
//!
//! A tensor about G and the same tensor about another point O differ by the tensor of the whole
//! mass concentrated at G. In the chapter's convention (products `Ixy = −∫xy dm`) that difference
//! is `M (|d|² 𝟙 − d dᵀ)` with `d = r_G` the position of G relative to O: its diagonal is
//! `M (y_G² + z_G²)`, … and its off-diagonal `−M x_G y_G`, …, exactly the terms of 4.23.

use crate::{InertiaError, InertiaTensor};
use nalgebra::{Matrix3, Vector3};

/// The matrix that Steiner's theorem (4.23) adds to a tensor about G to get the tensor about a
/// point O from which G lies at `r_g`: `M (|r_G|² 𝟙 − r_G r_Gᵀ)`.
///
/// It is also the tensor, about O, of a point mass `M` at `r_g`.
///
/// ```
/// use nalgebra::Vector3;
/// let shift = eom::mass::steiner_shift(2.0, &Vector3::new(1.0, 2.0, 0.0));
/// assert_eq!(shift[(2, 2)], 2.0 * (1.0 + 4.0)); // M (x_G² + y_G²)
/// assert_eq!(shift[(0, 1)], -2.0 * 1.0 * 2.0); // −M x_G y_G
/// ```
pub fn steiner_shift(mass: f64, r_g: &Vector3<f64>) -> Matrix3<f64> {
    (Matrix3::identity() * r_g.norm_squared() - r_g * r_g.transpose()) * mass
}

/// The tensor about O from the tensor about G (4.23): `[I_O] = [I_G] + M (|r_G|² 𝟙 − r_G r_Gᵀ)`.
///
/// The result passes through [`InertiaTensor::from_matrix`]; for a valid `[I_G]`, a positive
/// mass and a finite `r_g` it is always valid.
///
/// ```
/// use eom::{InertiaTensor, mass::steiner};
/// use nalgebra::Vector3;
/// let about_g = InertiaTensor::new(1.0, 1.0, 1.0, 0.0, 0.0, 0.0).unwrap();
/// let about_o = steiner(&about_g, 3.0, &Vector3::new(0.0, 0.0, 2.0)).unwrap();
/// assert_eq!(about_o.ixx(), 1.0 + 3.0 * 4.0);
/// assert_eq!(about_o.izz(), 1.0);
/// ```
pub fn steiner(
    about_g: &InertiaTensor,
    mass: f64,
    r_g: &Vector3<f64>,
) -> Result<InertiaTensor, InertiaError> {
    InertiaTensor::from_matrix(about_g.matrix() + steiner_shift(mass, r_g))
}

/// The tensor about G from the tensor about O (4.23 read backwards, as 4.29 does for the swing
/// test): `[I_G] = [I_O] − M (|r_G|² 𝟙 − r_G r_Gᵀ)`.
///
/// This can fail: a tensor about O that is too small for the given mass and G is refused with
/// the condition that fails.
pub fn steiner_to_g(
    about_o: &InertiaTensor,
    mass: f64,
    r_g: &Vector3<f64>,
) -> Result<InertiaTensor, InertiaError> {
    InertiaTensor::from_matrix(about_o.matrix() - steiner_shift(mass, r_g))
}
