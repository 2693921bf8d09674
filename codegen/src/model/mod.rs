//! The model specification: which family, which symmetry, which kinematics.
//!
//! Each [`Model`] is built from the *proved* derivations (never retyped): the implicit forms
//! are solved for the accelerations, the kinematics are appended, terms that the symmetry
//! makes zero are gone before emission, and every staged intermediate is checked to compose
//! back to the proved form.

pub mod aircraft;
pub mod earth;
mod families;
pub mod jacobian;
pub mod ship;
mod solve;
mod system;
pub mod vehicle;

pub use jacobian::{Entry, Jacobian};
pub use solve::{Solution, solve_diagonal, solve_linear};
pub use system::{BuildError, CoefficientName, Group, Parameter, Reciprocal, Stage, System};

/// Which products of inertia the body has.
///
/// This is the one definition: `eom`'s build script emits the runtime's copy of this enum
/// (and of [`Kinematics`]) from it, with the same variants, names and docs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Symmetry {
    /// All products of inertia (4.51).
    Full,
    /// Symmetric about the xz-plane: I_xy = I_yz = 0, I_xz free (ships, aircraft, AUVs).
    Xz,
    /// Principal axes: every product zero (4.52).
    Principal,
}

impl Symmetry {
    /// Every class, from the most general to the most pruned.
    pub const ALL: [Symmetry; 3] = [Symmetry::Full, Symmetry::Xz, Symmetry::Principal];

    /// The name in model names, scene files and on the command line: `full`, `xz`,
    /// `principal`.
    pub fn name(self) -> &'static str {
        match self {
            Symmetry::Full => "full",
            Symmetry::Xz => "xz",
            Symmetry::Principal => "principal",
        }
    }

    /// What the class means, for docs and help.
    pub fn doc(self) -> &'static str {
        match self {
            Symmetry::Full => "All products of inertia (4.51).",
            Symmetry::Xz => {
                "Symmetric about the xz-plane: I_xy = I_yz = 0, I_xz free (ships, aircraft, AUVs)."
            }
            Symmetry::Principal => "Principal axes: every product zero (4.52).",
        }
    }

    /// The products of inertia the class sets to zero, as the chapter names them.
    pub fn pruned(self) -> &'static [&'static str] {
        match self {
            Symmetry::Full => &[],
            Symmetry::Xz => &["Ixy", "Iyz"],
            Symmetry::Principal => &["Ixy", "Iyz", "Ixz"],
        }
    }
}

/// How the attitude is carried.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Kinematics {
    /// Euler angles (φ, θ, ψ): attitude by 4.60 (a spatial model's position by 4.57);
    /// singular at θ = ±90°.
    Euler,
    /// A unit quaternion (q0, q1, q2, q3), scalar first: q̇ = ½ q ⊗ (0, ω).
    Quaternion,
}

impl Kinematics {
    /// Both ways, Euler angles first.
    pub const ALL: [Kinematics; 2] = [Kinematics::Euler, Kinematics::Quaternion];

    /// The name in model names, scene files and on the command line: `euler`, `quaternion`.
    pub fn name(self) -> &'static str {
        match self {
            Kinematics::Euler => "euler",
            Kinematics::Quaternion => "quaternion",
        }
    }

    /// What it means, for docs and help.
    pub fn doc(self) -> &'static str {
        match self {
            Kinematics::Euler => {
                "Euler angles (φ, θ, ψ): attitude by 4.60 (a spatial model's position by 4.57); \
                 singular at θ = ±90°."
            }
            Kinematics::Quaternion => {
                "A quaternion (q0, q1, q2, q3), scalar first: q̇ = ½ q ⊗ (0, ω); no singularity."
            }
        }
    }
}

/// A model family: what a scene's `family` key names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Family {
    /// The compound pendulum.
    Pendulum,
    /// Planar, body axes at G.
    PlanarAtG,
    /// Planar, body axes at midship.
    PlanarMidship,
    /// Planar, space-fixed axes.
    PlanarSpaceFixed,
    /// Spatial 6-DOF.
    Spatial,
    /// The heavy top about a fixed point.
    Top,
}

impl Family {
    /// Every family, in catalog order.
    pub const ALL: [Family; 6] = [
        Family::Pendulum,
        Family::PlanarAtG,
        Family::PlanarMidship,
        Family::PlanarSpaceFixed,
        Family::Spatial,
        Family::Top,
    ];

    /// The name in scene files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Family::Pendulum => "pendulum",
            Family::PlanarAtG => "planar-g",
            Family::PlanarMidship => "planar-midship",
            Family::PlanarSpaceFixed => "planar-space",
            Family::Spatial => "spatial",
            Family::Top => "top",
        }
    }

    /// What it is, for docs and help.
    pub fn doc(self) -> &'static str {
        match self {
            Family::Pendulum => "Compound pendulum, 4.24.",
            Family::PlanarAtG => "Planar, body-fixed axes at G, 4.43 + 4.44.",
            Family::PlanarMidship => "Planar, body-fixed axes at midship, 4.46 + 4.44.",
            Family::PlanarSpaceFixed => "Planar, space-fixed axes, 4.39.",
            Family::Spatial => "Spatial 6-DOF, 4.49 + 4.51 with Euler angles or a quaternion.",
            Family::Top => {
                "Heavy top about a fixed point: Euler's equations about the pivot (4.50 with \
                 Steiner 4.23) under gravity."
            }
        }
    }
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
    /// The heavy top: a body turning about a fixed pivot under its weight (4.50 about the
    /// pivot with I_O by 4.23), state (p, q, r) and the attitude.
    Top {
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
        for symmetry in Symmetry::ALL {
            for kinematics in Kinematics::ALL {
                all.push(Model::Spatial {
                    symmetry,
                    kinematics,
                });
            }
        }
        for kinematics in Kinematics::ALL {
            all.push(Model::Top { kinematics });
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
            } => format!("spatial_{}_{}", symmetry.name(), kinematics.name()),
            Model::Top { kinematics } => format!("top_{}", kinematics.name()),
        }
    }

    /// The name of the model's type in `eom::models`: `Pendulum`, `SpatialXzQuaternion`, …
    pub fn type_name(&self) -> String {
        self.name()
            .split('_')
            .map(|word| {
                let mut chars = word.chars();
                chars
                    .next()
                    .map(|first| first.to_ascii_uppercase().to_string() + chars.as_str())
                    .unwrap_or_default()
            })
            .collect()
    }

    /// The family the model belongs to.
    pub fn family(&self) -> Family {
        match self {
            Model::Pendulum => Family::Pendulum,
            Model::PlanarAtG => Family::PlanarAtG,
            Model::PlanarMidship => Family::PlanarMidship,
            Model::PlanarSpaceFixed => Family::PlanarSpaceFixed,
            Model::Spatial { .. } => Family::Spatial,
            Model::Top { .. } => Family::Top,
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
                | Model::Top {
                    kinematics: Kinematics::Quaternion
                }
        )
    }

    /// How the model carries its attitude, if it has one in three dimensions.
    pub fn kinematics(&self) -> Option<Kinematics> {
        match *self {
            Model::Spatial { kinematics, .. } | Model::Top { kinematics } => Some(kinematics),
            _ => None,
        }
    }

    /// The strategies worth trying for this model.
    pub fn strategies(&self) -> &'static [Strategy] {
        match self {
            Model::Spatial { .. } => &Strategy::ALL,
            _ => &[Strategy::Expanded],
        }
    }

    /// The system to emit, built with one strategy.
    pub fn system(&self, strategy: Strategy) -> Result<System, BuildError> {
        match *self {
            Model::Pendulum => families::pendulum(),
            Model::PlanarAtG => families::planar_at_g(),
            Model::PlanarMidship => families::planar_midship(),
            Model::PlanarSpaceFixed => families::planar_space_fixed(),
            Model::Spatial {
                symmetry,
                kinematics,
            } => families::spatial(symmetry, kinematics, strategy),
            Model::Top { kinematics } => families::top(kinematics),
        }
    }
}
