//! Uniform solids whose tensors the chapter works out (4.18, 4.20–4.21, exercise 4.1), and the
//! cylinders that a hull's parts are often made of.
//!
//! Every primitive is centred on its own G with its symmetry axes along its own axes, so its
//! tensor about G is diagonal; [`MassProperties::placed`] then puts it anywhere in a body.
//! Dimensions follow the chapter: a box and an ellipsoid are given by their overall length L
//! (along x), breadth B (along y) and depth D (along z), so that an ellipsoid has semi-axes
//! `a = L/2`, `b = B/2`, `c = D/2`. A cylinder's axis is its own x axis, as a hull's is.

use super::error::MassError;
use super::properties::MassProperties;
use crate::InertiaTensor;
use crate::validate::{non_negative, positive};
use nalgebra::Vector3;

fn centred(mass: f64, moments: [f64; 3]) -> Result<MassProperties, MassError> {
    let [ixx, iyy, izz] = moments;
    let inertia = InertiaTensor::new(ixx, iyy, izz, 0.0, 0.0, 0.0)?;
    MassProperties::new(mass, Vector3::zeros(), inertia)
}

/// A uniform sphere of radius R: `Ixx = Iyy = Izz = 2/5 M R²` (4.18).
///
/// ```
/// let ball = eom::mass::sphere(2.5, 2.0).unwrap();
/// assert!((ball.inertia().ixx() - 0.4 * 2.5 * 4.0).abs() < 1e-12);
/// ```
pub fn sphere(mass: f64, radius: f64) -> Result<MassProperties, MassError> {
    let mass = positive("mass", mass)?;
    let radius = positive("radius", radius)?;
    let moment = 0.4 * mass * radius * radius;
    centred(mass, [moment; 3])
}

/// A uniform box of length L, breadth B and depth D (`size = [L, B, D]`):
/// `Ixx = M (B² + D²)/12`, `Iyy = M (L² + D²)/12`, `Izz = M (L² + B²)/12` (4.20–4.21).
pub fn solid_box(mass: f64, size: [f64; 3]) -> Result<MassProperties, MassError> {
    let mass = positive("mass", mass)?;
    let [l, b, d] = dimensions(size)?;
    let m = mass / 12.0;
    centred(
        mass,
        [
            m * (b * b + d * d),
            m * (l * l + d * d),
            m * (l * l + b * b),
        ],
    )
}

/// A uniform ellipsoid of overall length L = 2a, breadth B = 2b and depth D = 2c
/// (`size = [L, B, D]`): `Ixx = M (b² + c²)/5`, `Iyy = M (c² + a²)/5`, `Izz = M (a² + b²)/5`
/// (exercise 4.1; the sphere of 4.18 when a = b = c).
pub fn ellipsoid(mass: f64, size: [f64; 3]) -> Result<MassProperties, MassError> {
    let mass = positive("mass", mass)?;
    let [a, b, c] = dimensions(size)?.map(|full| 0.5 * full);
    let m = mass / 5.0;
    centred(
        mass,
        [
            m * (b * b + c * c),
            m * (c * c + a * a),
            m * (a * a + b * b),
        ],
    )
}

/// A uniform solid cylinder of radius R and length L with its axis along x:
/// `Ixx = M R²/2`, `Iyy = Izz = M (3R² + L²)/12`.
pub fn solid_cylinder(mass: f64, radius: f64, length: f64) -> Result<MassProperties, MassError> {
    hollow_cylinder(mass, 0.0, radius, length)
}

/// A uniform thick-walled tube of inner radius r, outer radius R and length L with its axis
/// along x: `Ixx = M (R² + r²)/2`, `Iyy = Izz = M (3(R² + r²) + L²)/12`.
///
/// `r = 0` is the solid cylinder and `r = R` the thin shell (`Ixx = M R²`).
pub fn hollow_cylinder(
    mass: f64,
    inner_radius: f64,
    outer_radius: f64,
    length: f64,
) -> Result<MassProperties, MassError> {
    let mass = positive("mass", mass)?;
    let outer = positive("radius", outer_radius)?;
    let length = positive("length", length)?;
    let inner_radius = non_negative("inner_radius", inner_radius)?;
    if inner_radius > outer {
        return Err(MassError::InnerRadiusTooLarge {
            inner: inner_radius,
            outer,
        });
    }
    let squares = outer * outer + inner_radius * inner_radius;
    let transverse = mass * (3.0 * squares + length * length) / 12.0;
    centred(mass, [0.5 * mass * squares, transverse, transverse])
}

fn dimensions(size: [f64; 3]) -> Result<[f64; 3], MassError> {
    Ok([
        positive("size[0] (length L)", size[0])?,
        positive("size[1] (breadth B)", size[1])?,
        positive("size[2] (depth D)", size[2])?,
    ])
}
