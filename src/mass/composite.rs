//! A body built from parts: solids and point masses placed in body axes, combined by the full
//! Steiner theorem (4.23), products of inertia included.
//!
//! The combination is done in two passes: first the mass and G of the whole, then each part's
//! tensor moved from its own G to the common G. Summing tensors about the body origin and
//! moving the total back to G would give the same number in exact arithmetic, but would lose
//! digits to cancellation when the parts sit far from the origin.

use super::error::{MassError, finite3};
use super::properties::MassProperties;
use super::steiner::steiner_shift;
use crate::InertiaTensor;
use crate::validate::positive;
use nalgebra::{Matrix3, Vector3};

/// One part already placed in body axes: its mass, its G and its tensor about its G (zero for a
/// point mass, which is why this is a plain matrix rather than an [`InertiaTensor`]).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Part {
    mass: f64,
    centre: Vector3<f64>,
    about_own_g: Matrix3<f64>,
}

/// A rigid body assembled from parts.
///
/// ```
/// use eom::mass::{Composite, solid_box};
/// use nalgebra::{Rotation3, Vector3};
/// // Two unit cubes of mass 1 side by side along x make a 2 × 1 × 1 box of mass 2.
/// let cube = solid_box(1.0, [1.0, 1.0, 1.0]).unwrap();
/// let mut body = Composite::new();
/// for x in [-0.5, 0.5] {
///     body.add(&cube.placed(&Vector3::new(x, 0.0, 0.0), &Rotation3::identity()).unwrap());
/// }
/// let whole = body.build().unwrap();
/// let expected = solid_box(2.0, [2.0, 1.0, 1.0]).unwrap();
/// assert!((whole.inertia().matrix() - expected.inertia().matrix()).norm() < 1e-12);
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Composite {
    parts: Vec<Part>,
}

impl Composite {
    /// An empty body.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a solid part, already placed in body axes (see [`MassProperties::placed`]).
    pub fn add(&mut self, part: &MassProperties) -> &mut Self {
        self.parts.push(Part {
            mass: part.mass(),
            centre: part.centre_of_gravity(),
            about_own_g: part.inertia().matrix(),
        });
        self
    }

    /// Adds a point mass at `position` in body axes; it has no moment about its own G.
    pub fn add_point(&mut self, mass: f64, position: Vector3<f64>) -> Result<&mut Self, MassError> {
        positive("mass", mass)?;
        finite3(["position[0]", "position[1]", "position[2]"], &position)?;
        self.parts.push(Part {
            mass,
            centre: position,
            about_own_g: Matrix3::zeros(),
        });
        Ok(self)
    }

    /// The number of parts added so far.
    pub fn len(&self) -> usize {
        self.parts.len()
    }

    /// Whether no part has been added.
    pub fn is_empty(&self) -> bool {
        self.parts.is_empty()
    }

    /// The mass properties of the whole: `M = Σ mᵢ`, `r_G = Σ mᵢ rᵢ / M` and
    /// `[I_G] = Σ ([Iᵢ] + mᵢ (|dᵢ|² 𝟙 − dᵢ dᵢᵀ))` with `dᵢ = rᵢ − r_G` (4.23).
    ///
    /// The total tensor is validated; a body of point masses on one line, for instance, has no
    /// moment about that line and is refused as not positive definite.
    pub fn build(&self) -> Result<MassProperties, MassError> {
        if self.parts.is_empty() {
            return Err(MassError::NoParts);
        }
        let mass: f64 = self.parts.iter().map(|p| p.mass).sum();
        let first_moment: Vector3<f64> = self.parts.iter().map(|p| p.centre * p.mass).sum();
        let centre = first_moment / mass;
        let about_g: Matrix3<f64> = self
            .parts
            .iter()
            .map(|p| p.about_own_g + steiner_shift(p.mass, &(p.centre - centre)))
            .sum();
        MassProperties::new(mass, centre, InertiaTensor::from_matrix(about_g)?)
    }
}
