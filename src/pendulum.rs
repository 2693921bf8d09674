//! The compound pendulum's parameters (4.24–4.29), validated once and shared by every pendulum
//! in the crate.
//!
//! A rigid body swings about a fixed horizontal axis through the pivot O, with G at distance
//! `h` from O: `I₀ θ̈ = −M g h sin θ + M_O` (4.24), with `I₀` the moment of inertia about the
//! pivot, `M` the mass, `g` gravity and `M_O` an applied moment about the pivot.
//!
//! One [`PendulumParameters`] feeds each pendulum role: the generic form
//! ([`crate::generic::Pendulum`]), the generated model ([`crate::models::Pendulum`]), the exact
//! large-amplitude solution ([`crate::reference::LargeSwing`]) and the swing test's model of a
//! body on the rig ([`crate::swing::SwungBody`]).
//!
//! # Conventions
//!
//! The state is `[θ, θ̇]`: θ is the angle of OG from the downward vertical, positive in the
//! sense of the applied moment, so θ = 0 is the stable rest position when `g > 0`. Every
//! motion with a known answer starts **released from rest at θ = θ₀ at t = 0**: it first
//! swings towards θ = 0 (θ̇ < 0 for 0 < θ₀ < π), passes it at a quarter period and comes to
//! rest at −θ₀ at half a period.

use crate::ParameterError;
use crate::validate::{finite, non_negative, positive, require};

/// Relative slack in the check `I₀ ≥ M h²`: a simple pendulum has `I₀ = M h²` exactly, and
/// the product computed by the caller may exceed `I₀` by a few ulps.
const STEINER_SLACK: f64 = 1e-12;

/// The parameters of a compound pendulum (4.24): `I₀` about the pivot, `M`, `g` and `h`.
///
/// Validated once, in [`new`](Self::new): `I₀ > 0`, `M > 0`, `g` finite (of either sign:
/// `g ≤ 0` is a pendulum balanced above its pivot or without weight, which the equations of
/// motion handle but which has no period), `h ≥ 0`, and `I₀ ≥ M h²` (4.29: the moment about G,
/// `I_G = I₀ − M h²`, cannot be negative; a simple pendulum has `I₀ = M h²` exactly and is
/// accepted). Errors name the argument: `"i0"`, `"mass"`, `"g"`, `"h"`.
///
/// ```
/// use eom::PendulumParameters;
/// let p = PendulumParameters::new(2.0, 3.0, 9.81, 0.5).unwrap();
/// assert_eq!((p.i0(), p.mass(), p.g(), p.h()), (2.0, 3.0, 9.81, 0.5));
/// // ω₀ = √(M g h / I₀) (4.27)
/// assert_eq!(p.natural_frequency().unwrap(), (3.0 * 9.81 * 0.5 / 2.0_f64).sqrt());
/// // I₀ = 0.5 < M h² = 0.75: I_G would be negative.
/// let err = PendulumParameters::new(0.5, 3.0, 9.81, 0.5).unwrap_err();
/// assert_eq!(err.field, "i0");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PendulumParameters {
    i0: f64,
    mass: f64,
    g: f64,
    h: f64,
}

impl PendulumParameters {
    /// Validates the moment of inertia about the pivot `i0`, the mass `mass`, gravity `g` and
    /// the pivot-to-G distance `h`, in the order of 4.24 (`I₀ θ̈ = −M g h sin θ`).
    pub fn new(i0: f64, mass: f64, g: f64, h: f64) -> Result<Self, ParameterError> {
        let i0 = positive("i0", i0)?;
        let mass = positive("mass", mass)?;
        let g = finite("g", g)?;
        let h = non_negative("h", h)?;
        require(
            i0 >= mass * h * h * (1.0 - STEINER_SLACK),
            "i0",
            i0,
            "at least mass · h² (4.29: I_G = I₀ − M h² cannot be negative)",
        )?;
        Ok(Self { i0, mass, g, h })
    }

    /// The pendulum of a body with radius of gyration `kappa_g` about G (`κ_G > 0`), hung at
    /// distance `h` from G: `I₀ = M (κ_G² + h²)` (4.29). Otherwise as [`new`](Self::new).
    ///
    /// ```
    /// let p = eom::PendulumParameters::from_gyradius(0.25, 20.0, 9.81, 0.12).unwrap();
    /// assert!((p.i0() - 20.0 * (0.25_f64.powi(2) + 0.12_f64.powi(2))).abs() < 1e-15);
    /// ```
    pub fn from_gyradius(kappa_g: f64, mass: f64, g: f64, h: f64) -> Result<Self, ParameterError> {
        let kappa_g = positive("kappa_g", kappa_g)?;
        let mass = positive("mass", mass)?;
        let h = non_negative("h", h)?;
        Self::new(mass * (kappa_g * kappa_g + h * h), mass, g, h)
    }

    /// The moment of inertia about the pivot, `I₀`.
    pub fn i0(&self) -> f64 {
        self.i0
    }

    /// The mass `M`.
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// The acceleration of gravity `g`.
    pub fn g(&self) -> f64 {
        self.g
    }

    /// The distance `h` from the pivot to G.
    pub fn h(&self) -> f64 {
        self.h
    }

    /// `M g h`, the restoring moment per unit of `sin θ` (4.24).
    pub fn restoring_moment(&self) -> f64 {
        self.mass * self.g * self.h
    }

    /// The small-amplitude angular frequency `ω₀ = √(M g h / I₀)` (4.27).
    ///
    /// A pendulum swings, and has a frequency, only if `g > 0` and `h > 0`; otherwise the
    /// error names whichever of `"g"` and `"h"` is not positive.
    pub fn natural_frequency(&self) -> Result<f64, ParameterError> {
        let swings = "positive for the pendulum to swing";
        require(self.g > 0.0, "g", self.g, swings)?;
        require(self.h > 0.0, "h", self.h, swings)?;
        Ok((self.restoring_moment() / self.i0).sqrt())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_parameter_is_named_when_refused() {
        let field = |r: Result<PendulumParameters, ParameterError>| r.unwrap_err().field;
        assert_eq!(field(PendulumParameters::new(-1.0, 1.0, 9.8, 0.5)), "i0");
        assert_eq!(
            field(PendulumParameters::new(1.0, f64::INFINITY, 9.8, 0.5)),
            "mass"
        );
        assert_eq!(field(PendulumParameters::new(1.0, 1.0, f64::NAN, 0.5)), "g");
        assert_eq!(field(PendulumParameters::new(1.0, 1.0, 9.8, -0.5)), "h");
        // I₀ = 1 < M h² = 4: the moment about G would be negative (4.29).
        assert_eq!(field(PendulumParameters::new(1.0, 1.0, 9.8, 2.0)), "i0");
        assert_eq!(
            field(PendulumParameters::from_gyradius(0.0, 1.0, 9.8, 2.0)),
            "kappa_g"
        );
    }

    #[test]
    fn a_simple_pendulum_and_a_weightless_one_are_valid_but_only_one_swings() {
        // I₀ = M h² exactly, computed in floating point.
        let simple = PendulumParameters::new(0.3 * 0.7 * 0.7, 0.3, 9.8, 0.7).unwrap();
        assert!((simple.natural_frequency().unwrap() - (9.8_f64 / 0.7).sqrt()).abs() < 1e-14);
        let weightless = PendulumParameters::new(1.0, 1.0, 0.0, 0.5).unwrap();
        assert_eq!(weightless.natural_frequency().unwrap_err().field, "g");
        let balanced = PendulumParameters::new(1.0, 1.0, 9.8, 0.0).unwrap();
        assert_eq!(balanced.natural_frequency().unwrap_err().field, "h");
    }
}
