//! Planar (manoeuvring) motion of a body with its origin at G: the body-fixed form 4.43 with
//! the track 4.44, and the space-fixed form 4.39.
//!
//! Both forms share the parameters `M` and `I_zz` (about G), so one [`PlanarBody`] serves
//! both; `1/M` and `1/I_zz` are computed once. The forms are kept apart because they integrate
//! different states, and because comparing them is one of the checks on both.

use super::error::ModelError;
use crate::validate::positive;
use nalgebra::{RealField, SVector, Vector3, Vector6};

/// A rigid body moving in the horizontal plane, origin of the body axes at G.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarBody<T> {
    mass: T,
    izz: T,
    inv_mass: T,
    inv_izz: T,
}

impl<T: RealField + Copy> PlanarBody<T> {
    /// Validates the mass `M > 0` and the yaw moment of inertia about G, `I_zz > 0`.
    ///
    /// ```
    /// use eom::generic::PlanarBody;
    /// let ship = PlanarBody::<f64>::new(2.0, 8.0).unwrap();
    /// // Pure yaw moment at rest: ṙ = M_z / I_zz and nothing else moves (4.43).
    /// let x = nalgebra::Vector6::zeros();
    /// let dx = ship.rhs_body_at_g(&x, &nalgebra::Vector3::new(0.0, 0.0, 4.0));
    /// assert_eq!(dx, nalgebra::Vector6::new(0.0, 0.0, 0.5, 0.0, 0.0, 0.0));
    /// ```
    pub fn new(mass: f64, izz: f64) -> Result<Self, ModelError> {
        let mass = positive("mass", mass)?;
        let izz = positive("izz", izz)?;
        Ok(Self {
            mass: nalgebra::convert(mass),
            izz: nalgebra::convert(izz),
            inv_mass: nalgebra::convert(1.0 / mass),
            inv_izz: nalgebra::convert(1.0 / izz),
        })
    }

    /// Body-fixed form at G, 4.43 with the track 4.44.
    ///
    /// State `[u, v, r, X, Y, ψ]`: surge and sway velocity of G in body axes, yaw rate, the
    /// track of G in space axes and the heading. `load = (F_x, F_y, M_z)` in body axes, the
    /// moment about G. Returns `[u̇, v̇, ṙ, Ẋ, Ẏ, ψ̇]` with
    /// `u̇ = F_x/M + v r`, `v̇ = F_y/M − u r`, `ṙ = M_z/I_zz`, `ψ̇ = r`.
    #[inline]
    pub fn rhs_body_at_g(&self, state: &SVector<T, 6>, load: &Vector3<T>) -> SVector<T, 6> {
        let (u, v, r, psi) = (state[0], state[1], state[2], state[5]);
        let (x_dot, y_dot) = track(u, v, psi);
        Vector6::new(
            load[0] * self.inv_mass + v * r,
            load[1] * self.inv_mass - u * r,
            load[2] * self.inv_izz,
            x_dot,
            y_dot,
            r,
        )
    }

    /// Space-fixed form, 4.36–4.39: `M Ẍ = F_X`, `M Ÿ = F_Y`, `I_zz ψ̈ = M_z`.
    ///
    /// State `[X, Y, ψ, Ẋ, Ẏ, ψ̇]` (position of G and heading, then their rates);
    /// `load = (F_X, F_Y, M_z)` in space axes. Returns `[Ẋ, Ẏ, ψ̇, Ẍ, Ÿ, ψ̈]`.
    #[inline]
    pub fn rhs_space_fixed(&self, state: &SVector<T, 6>, load: &Vector3<T>) -> SVector<T, 6> {
        Vector6::new(
            state[3],
            state[4],
            state[5],
            load[0] * self.inv_mass,
            load[1] * self.inv_mass,
            load[2] * self.inv_izz,
        )
    }

    /// The mass `M`.
    pub fn mass(&self) -> T {
        self.mass
    }

    /// The yaw moment of inertia about G, `I_zz`.
    pub fn izz(&self) -> T {
        self.izz
    }
}

impl PlanarBody<f64> {
    /// The same body over another scalar (dual numbers, for its Jacobians).
    pub(super) fn cast<S: RealField + Copy>(&self) -> PlanarBody<S> {
        PlanarBody {
            mass: nalgebra::convert(self.mass),
            izz: nalgebra::convert(self.izz),
            inv_mass: nalgebra::convert(self.inv_mass),
            inv_izz: nalgebra::convert(self.inv_izz),
        }
    }
}

/// A [`PlanarBody`] in the space-fixed form (4.39), as a model of its own: the body-fixed
/// form at G and this one integrate different states, so each has its own
/// [`Model`](crate::models::Model) implementation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarSpaceFixed<T>(pub PlanarBody<T>);

/// The track of the body origin, 4.44: `Ẋ = u cos ψ − v sin ψ`, `Ẏ = u sin ψ + v cos ψ`.
#[inline]
pub fn track<T: RealField + Copy>(u: T, v: T, psi: T) -> (T, T) {
    let (s, c) = psi.sin_cos();
    (u * c - v * s, u * s + v * c)
}
