//! The mass properties of one rigid body: its mass, its centre of gravity G and its inertia
//! tensor about G, checked once so that everything downstream can trust them.

use super::error::{MassError, finite3};
use super::gyration::{PrincipalAxes, radii_of_gyration};
use super::steiner::steiner;
use crate::InertiaTensor;
use crate::validate::positive;
use nalgebra::{Rotation3, Vector3};

/// Mass `M`, centre of gravity `r_G` (in body axes) and inertia tensor about G (chapter
/// convention, 4.12–4.14) of a rigid body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties {
    mass: f64,
    centre_of_gravity: Vector3<f64>,
    inertia: InertiaTensor,
}

impl MassProperties {
    /// Builds the properties, refusing a mass that is not positive and finite and a G that is
    /// not finite. The tensor is already valid, being an [`InertiaTensor`].
    ///
    /// ```
    /// use eom::{InertiaTensor, mass::MassProperties};
    /// use nalgebra::Vector3;
    /// let inertia = InertiaTensor::new(2.0, 2.0, 2.0, 0.0, 0.0, 0.0).unwrap();
    /// assert!(MassProperties::new(-1.0, Vector3::zeros(), inertia).is_err());
    /// ```
    pub fn new(
        mass: f64,
        centre_of_gravity: Vector3<f64>,
        inertia: InertiaTensor,
    ) -> Result<Self, MassError> {
        positive("mass", mass)?;
        finite3(["x_G", "y_G", "z_G"], &centre_of_gravity)?;
        Ok(Self {
            mass,
            centre_of_gravity,
            inertia,
        })
    }

    /// The mass `M`.
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// The centre of gravity `r_G = (x_G, y_G, z_G)` in body axes.
    pub fn centre_of_gravity(&self) -> Vector3<f64> {
        self.centre_of_gravity
    }

    /// The inertia tensor about G, in axes parallel to the body axes.
    pub fn inertia(&self) -> InertiaTensor {
        self.inertia
    }

    /// The inertia tensor about a point O of the body axes, by Steiner's theorem (4.23) with
    /// `r_G − r_O` as the position of G seen from O.
    ///
    /// ```
    /// use eom::mass::sphere;
    /// use nalgebra::Vector3;
    /// let ball = sphere(5.0, 1.0).unwrap(); // I_G = 2/5 · 5 · 1² = 2
    /// let about = ball.inertia_about(&Vector3::new(0.0, 0.0, 3.0)).unwrap();
    /// assert!((about.ixx() - (2.0 + 5.0 * 9.0)).abs() < 1e-12);
    /// ```
    pub fn inertia_about(&self, point: &Vector3<f64>) -> Result<InertiaTensor, MassError> {
        finite3(["x_O", "y_O", "z_O"], point)?;
        Ok(steiner(
            &self.inertia,
            self.mass,
            &(self.centre_of_gravity - point),
        )?)
    }

    /// The radii of gyration `(κ_xx, κ_yy, κ_zz)` about axes through G (4.16–4.17).
    pub fn radii_of_gyration(&self) -> Vector3<f64> {
        radii_of_gyration(&self.inertia, self.mass)
    }

    /// The principal moments and axes about G, with their radii of gyration.
    pub fn principal(&self) -> PrincipalAxes {
        PrincipalAxes::of(&self.inertia, self.mass)
    }

    /// The same body placed in other axes: a point `p` of the body's own axes goes to
    /// `offset + R p`. Then G goes to `offset + R r_G` and the tensor about G to `R [I] Rᵀ`.
    ///
    /// The rotation law holds for the chapter's tensor as it is: `[I] = tr(S) 𝟙 − S` with the
    /// second moments `S = ∫ r rᵀ dm`, and `S` becomes `R S Rᵀ` while its trace does not change,
    /// so the minus sign inside the products (4.14) needs no special care.
    pub fn placed(
        &self,
        offset: &Vector3<f64>,
        rotation: &Rotation3<f64>,
    ) -> Result<Self, MassError> {
        finite3(["offset[0]", "offset[1]", "offset[2]"], offset)?;
        let r = rotation.matrix();
        let inertia = InertiaTensor::from_matrix(r * self.inertia.matrix() * r.transpose())?;
        Self::new(self.mass, offset + r * self.centre_of_gravity, inertia)
    }
}

/// The rotation `E = Rz(ψ) Ry(θ) Rx(φ)` of 4.57 from roll φ, pitch θ and yaw ψ in degrees: it
/// turns a part's own axes into the body axes.
///
/// ```
/// use nalgebra::Vector3;
/// let e = eom::mass::rotation_from_degrees([0.0, 0.0, 90.0]).unwrap();
/// assert!((e * Vector3::x() - Vector3::y()).norm() < 1e-15); // yaw 90°: x turns into y
/// ```
pub fn rotation_from_degrees(roll_pitch_yaw: [f64; 3]) -> Result<Rotation3<f64>, MassError> {
    let [roll, pitch, yaw] = roll_pitch_yaw;
    finite3(["roll", "pitch", "yaw"], &Vector3::new(roll, pitch, yaw))?;
    Ok(Rotation3::from_euler_angles(
        roll.to_radians(),
        pitch.to_radians(),
        yaw.to_radians(),
    ))
}
