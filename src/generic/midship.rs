//! Planar motion with the body origin at midship and G at `(x_G, 0, 0)`: 4.46 with the track
//! 4.44.
//!
//! Moving the origin off G couples sway and yaw through the mass matrix
//! `[[M, M x_G], [M x_G, I_zz + M x_G²]]` acting on `(v̇, ṙ)`. Its determinant is `M I_zz`,
//! positive for every valid body, so it is inverted once, in [`PlanarMidship::new`], and a
//! call solves for the accelerations with one 2×2 product.

use super::error::ModelError;
use super::planar::track;
use crate::ParameterError;
use crate::validate::{finite, positive};
use nalgebra::{Matrix2, RealField, SVector, Vector2, Vector3, Vector6};

/// A rigid body in planar motion, body axes at midship, G on the x axis at `x_G`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarMidship<T> {
    mass: T,
    /// The yaw moment of inertia about G.
    izz: T,
    x_g: T,
    inv_mass: T,
    /// `M x_G`, the first moment of mass about midship.
    mass_x_g: T,
    /// The inverse of the sway–yaw mass matrix of 4.46.
    inverse_mass_matrix: Matrix2<T>,
}

impl<T: RealField + Copy> PlanarMidship<T> {
    /// Validates `M > 0`, the yaw moment of inertia about G, `I_zz > 0`, and `x_G` finite,
    /// then inverts the sway–yaw mass matrix once.
    ///
    /// ```
    /// use eom::generic::PlanarMidship;
    /// assert!(PlanarMidship::<f64>::new(1.0, 2.0, -0.3).is_ok());
    /// assert!(PlanarMidship::<f64>::new(1.0, 2.0, f64::NAN).is_err());
    /// ```
    pub fn new(mass: f64, izz: f64, x_g: f64) -> Result<Self, ModelError> {
        let mass = positive("mass", mass)?;
        let izz = positive("izz", izz)?;
        let x_g = finite("x_g", x_g)?;
        let mass_matrix = Matrix2::new(mass, mass * x_g, mass * x_g, izz + mass * x_g * x_g);
        let Some(inverse) = mass_matrix.try_inverse() else {
            return Err(ModelError::Parameter(ParameterError {
                field: "x_g",
                value: x_g,
                requirement: "small enough that the sway–yaw mass matrix can be inverted",
            }));
        };
        Ok(Self {
            mass: nalgebra::convert(mass),
            izz: nalgebra::convert(izz),
            x_g: nalgebra::convert(x_g),
            inv_mass: nalgebra::convert(1.0 / mass),
            mass_x_g: nalgebra::convert(mass * x_g),
            inverse_mass_matrix: inverse.map(nalgebra::convert),
        })
    }

    /// Body-fixed form at midship, 4.46 with the track 4.44.
    ///
    /// State `[u, v, r, X, Y, ψ]`: velocity of the midship origin in body axes, yaw rate, the
    /// midship origin's track and the heading. `load = (X, Y, N)` in body axes, `N` about
    /// midship. Returns `[u̇, v̇, ṙ, Ẋ, Ẏ, ψ̇]` from
    /// `M(u̇ − v r − x_G r²) = X`, `M(v̇ + u r + x_G ṙ) = Y`,
    /// `(I_zz + M x_G²) ṙ + M x_G (v̇ + u r) = N`.
    #[inline]
    pub fn rhs_body_at_midship(&self, state: &SVector<T, 6>, load: &Vector3<T>) -> SVector<T, 6> {
        let (u, v, r, psi) = (state[0], state[1], state[2], state[5]);
        let u_dot = load[0] * self.inv_mass + v * r + self.x_g * r * r;
        let ur = u * r;
        let bias = Vector2::new(load[1] - self.mass * ur, load[2] - self.mass_x_g * ur);
        let sway_yaw = self.inverse_mass_matrix * bias;
        let (x_dot, y_dot) = track(u, v, psi);
        Vector6::new(u_dot, sway_yaw[0], sway_yaw[1], x_dot, y_dot, r)
    }

    /// The mass `M`.
    pub fn mass(&self) -> T {
        self.mass
    }

    /// The position of G along the body x axis, `x_G`.
    pub fn x_g(&self) -> T {
        self.x_g
    }

    /// The yaw moment of inertia about G, `I_zz`.
    pub fn izz(&self) -> T {
        self.izz
    }
}

impl PlanarMidship<f64> {
    /// The same body over another scalar (dual numbers, for its Jacobians).
    pub(super) fn cast<S: RealField + Copy>(&self) -> PlanarMidship<S> {
        PlanarMidship {
            mass: nalgebra::convert(self.mass),
            izz: nalgebra::convert(self.izz),
            x_g: nalgebra::convert(self.x_g),
            inv_mass: nalgebra::convert(self.inv_mass),
            mass_x_g: nalgebra::convert(self.mass_x_g),
            inverse_mass_matrix: self.inverse_mass_matrix.map(nalgebra::convert),
        }
    }
}
