//! The planar models (4.39, 4.43, 4.46 with the track 4.44) from the generated code.

use super::generated::{planar_at_g, planar_midship, planar_space_fixed};
use super::scalar;
use crate::generic::ModelError;
use crate::validate::{finite, positive};
use simba::simd::SimdRealField;

/// Planar motion in body axes at G (4.43, 4.44): state `[u, v, r, X, Y, ψ]`, inputs
/// `[F_x, F_y, M_z]` in body axes about G.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarAtG<T> {
    coefficients: planar_at_g::Coefficients<T>,
    mass: T,
    izz: T,
}

impl<T: SimdRealField + Copy> PlanarAtG<T> {
    /// Validates M > 0 and I_zz > 0.
    pub fn new(mass: f64, izz: f64) -> Result<Self, ModelError> {
        let parameters = planar_at_g::Parameters {
            mass: positive("mass", mass)?,
            izz: positive("izz", izz)?,
        };
        Ok(Self {
            coefficients: planar_at_g::Coefficients::new(&parameters),
            mass: scalar(mass),
            izz: scalar(izz),
        })
    }

    /// The time derivative of the state.
    #[inline]
    pub fn rhs(&self, state: &[T; 6], load: &[T; 3]) -> [T; 6] {
        planar_at_g::rhs(&self.coefficients, state, load)
    }

    /// Kinetic energy ½M(u² + v²) + ½I_zz r² (4.32 in the plane).
    pub fn kinetic_energy(&self, state: &[T; 6]) -> T {
        let [u, v, r, ..] = *state;
        (self.mass * (u * u + v * v) + self.izz * r * r) * scalar(0.5)
    }
}

/// Planar motion in body axes at midship, G at (x_G, 0, 0) (4.45, 4.46, 4.44): state
/// `[u, v, r, X, Y, ψ]` of the midship origin, inputs `[X, Y, N]` in body axes about midship.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarMidship<T> {
    coefficients: planar_midship::Coefficients<T>,
    mass: T,
    izz: T,
    x_g: T,
}

impl<T: SimdRealField + Copy> PlanarMidship<T> {
    /// Validates M > 0, I_zz > 0 (about G) and a finite x_G.
    pub fn new(mass: f64, izz: f64, x_g: f64) -> Result<Self, ModelError> {
        let parameters = planar_midship::Parameters {
            mass: positive("mass", mass)?,
            izz: positive("izz", izz)?,
            x_g: finite("x_g", x_g)?,
        };
        let coefficients = planar_midship::Coefficients::new(&parameters);
        Ok(Self {
            coefficients,
            mass: scalar(mass),
            izz: scalar(izz),
            x_g: scalar(x_g),
        })
    }

    /// The time derivative of the state.
    #[inline]
    pub fn rhs(&self, state: &[T; 6], load: &[T; 3]) -> [T; 6] {
        planar_midship::rhs(&self.coefficients, state, load)
    }

    /// Kinetic energy ½M(u² + v_G²) + ½I_zz r², with v_G = v + x_G r (4.45).
    pub fn kinetic_energy(&self, state: &[T; 6]) -> T {
        let [u, v, r, ..] = *state;
        let v_g = v + self.x_g * r;
        (self.mass * (u * u + v_g * v_g) + self.izz * r * r) * scalar(0.5)
    }
}

/// Planar motion in space-fixed axes (4.39): state `[X, Y, ψ, Ẋ, Ẏ, ψ̇]`, inputs
/// `[F_X, F_Y, M_z]` in space axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarSpaceFixed<T> {
    coefficients: planar_space_fixed::Coefficients<T>,
    mass: T,
    izz: T,
}

impl<T: SimdRealField + Copy> PlanarSpaceFixed<T> {
    /// Validates M > 0 and I_zz > 0.
    pub fn new(mass: f64, izz: f64) -> Result<Self, ModelError> {
        let parameters = planar_space_fixed::Parameters {
            mass: positive("mass", mass)?,
            izz: positive("izz", izz)?,
        };
        let coefficients = planar_space_fixed::Coefficients::new(&parameters);
        Ok(Self {
            coefficients,
            mass: scalar(mass),
            izz: scalar(izz),
        })
    }

    /// The time derivative of the state.
    #[inline]
    pub fn rhs(&self, state: &[T; 6], load: &[T; 3]) -> [T; 6] {
        planar_space_fixed::rhs(&self.coefficients, state, load)
    }

    /// Kinetic energy ½M(Ẋ² + Ẏ²) + ½I_zz ψ̇².
    pub fn kinetic_energy(&self, state: &[T; 6]) -> T {
        let [_, _, _, x_dot, y_dot, psi_dot] = *state;
        (self.mass * (x_dot * x_dot + y_dot * y_dot) + self.izz * psi_dot * psi_dot) * scalar(0.5)
    }
}
