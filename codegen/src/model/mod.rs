//! The model specification: which family, which symmetry, which kinematics.
//!
//! Each [`Model`] is built from the *proved* derivations (never retyped): the implicit forms
//! are solved for the accelerations, the kinematics are appended, terms that the symmetry
//! makes zero are gone before emission, and every staged intermediate is checked to compose
//! back to the proved form.

mod families;
mod solve;
mod system;

pub use solve::{Solution, solve_linear};
pub use system::{CoefficientName, Group, ModelError, Parameter, Reciprocal, Stage, System};

/// Which products of inertia the body has.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Symmetry {
    /// All products of inertia (4.51).
    Full,
    /// Symmetric about the xz-plane: I_xy = I_yz = 0, I_xz free (ships, aircraft, AUVs).
    Xz,
    /// Principal axes: every product zero (4.52).
    Principal,
}

/// How the attitude is carried.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Kinematics {
    /// Euler angles (φ, θ, ψ): position by 4.57, attitude by 4.60; singular at θ = ±90°.
    Euler,
    /// A unit quaternion (q0, q1, q2, q3), scalar first: q̇ = ½ q ⊗ (0, ω).
    Quaternion,
}

/// How the rotational accelerations of a spatial model are computed; the emitter builds each
/// and keeps the one with the fewest operations.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Strategy {
    /// Every acceleration expanded into monomials of the rates, coefficients hoisted.
    Expanded,
    /// The bias terms (ω×\[I\]ω − M) staged, then multiplied by the inverse inertia.
    StagedBias,
    /// H = \[I\]ω staged, then ω×H − M, then the inverse inertia.
    StagedMomentum,
}

impl Strategy {
    /// All strategies, in the order ties are broken.
    pub const ALL: [Strategy; 3] = [
        Strategy::Expanded,
        Strategy::StagedBias,
        Strategy::StagedMomentum,
    ];
}

/// A model family and its options.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Model {
    /// Compound pendulum (4.24), state (θ, θ̇).
    Pendulum,
    /// Planar, body-fixed at G (4.43 with the track 4.44), state (u, v, r, X, Y, ψ).
    PlanarAtG,
    /// Planar, body-fixed at midship with G at (x_G, 0, 0) (4.46 with 4.44).
    PlanarMidship,
    /// Planar, space-fixed (4.39), state (X, Y, ψ, Ẋ, Ẏ, ψ̇).
    PlanarSpaceFixed,
    /// Spatial 6-DOF (4.49 with 4.51 and kinematics).
    Spatial {
        /// Which products of inertia are present.
        symmetry: Symmetry,
        /// How the attitude is carried.
        kinematics: Kinematics,
    },
}

impl Model {
    /// Every variant `eom` ships, in a fixed order.
    pub fn all() -> Vec<Model> {
        let mut all = vec![
            Model::Pendulum,
            Model::PlanarAtG,
            Model::PlanarMidship,
            Model::PlanarSpaceFixed,
        ];
        for symmetry in [Symmetry::Full, Symmetry::Xz, Symmetry::Principal] {
            for kinematics in [Kinematics::Euler, Kinematics::Quaternion] {
                all.push(Model::Spatial {
                    symmetry,
                    kinematics,
                });
            }
        }
        all
    }

    /// The model's name, a Rust identifier: `pendulum`, `spatial_xz_quaternion`, …
    pub fn name(&self) -> String {
        match self {
            Model::Pendulum => "pendulum".into(),
            Model::PlanarAtG => "planar_at_g".into(),
            Model::PlanarMidship => "planar_midship".into(),
            Model::PlanarSpaceFixed => "planar_space_fixed".into(),
            Model::Spatial {
                symmetry,
                kinematics,
            } => {
                let s = match symmetry {
                    Symmetry::Full => "full",
                    Symmetry::Xz => "xz",
                    Symmetry::Principal => "principal",
                };
                let k = match kinematics {
                    Kinematics::Euler => "euler",
                    Kinematics::Quaternion => "quaternion",
                };
                format!("spatial_{s}_{k}")
            }
        }
    }

    /// Whether the model's state holds angles, so that its right-hand side takes their sine
    /// and cosine: the pendulum, the body-fixed planar models and the Euler-angle variants.
    pub fn has_angles(&self) -> bool {
        !matches!(
            self,
            Model::PlanarSpaceFixed
                | Model::Spatial {
                    kinematics: Kinematics::Quaternion,
                    ..
                }
        )
    }

    /// The strategies worth trying for this model.
    pub fn strategies(&self) -> &'static [Strategy] {
        match self {
            Model::Spatial { .. } => &Strategy::ALL,
            _ => &[Strategy::Expanded],
        }
    }

    /// The system to emit, built with one strategy.
    pub fn system(&self, strategy: Strategy) -> Result<System, ModelError> {
        match *self {
            Model::Pendulum => families::pendulum(),
            Model::PlanarAtG => families::planar_at_g(),
            Model::PlanarMidship => families::planar_midship(),
            Model::PlanarSpaceFixed => families::planar_space_fixed(),
            Model::Spatial {
                symmetry,
                kinematics,
            } => families::spatial(symmetry, kinematics, strategy),
        }
    }
}
