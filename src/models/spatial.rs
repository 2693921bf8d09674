//! The spatial 6-DOF models (4.49 with 4.51 and kinematics) from the generated code, one type
//! per symmetry class and kinematics.

use super::generated;
use super::scalar;
use crate::InertiaTensor;
use crate::generic::ModelError;
use crate::generic::error::check_mass;
use simba::simd::SimdRealField;

/// Which products of inertia a spatial model keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
pub enum Symmetry {
    /// All products (4.51).
    Full,
    /// Symmetric about the xz-plane: I_xy = I_yz = 0 (ships, aircraft, AUVs).
    Xz,
    /// Principal axes: all products zero (4.52).
    Principal,
}

impl Symmetry {
    fn pruned(self) -> &'static [&'static str] {
        match self {
            Symmetry::Full => &[],
            Symmetry::Xz => &["Ixy", "Iyz"],
            Symmetry::Principal => &["Ixy", "Iyz", "Ixz"],
        }
    }

    fn name(self) -> &'static str {
        match self {
            Symmetry::Full => "full",
            Symmetry::Xz => "xz",
            Symmetry::Principal => "principal",
        }
    }
}

/// A product that the class prunes must vanish. "Vanish" allows round-off of a computed tensor:
/// 1e-12 of the largest moment, far below any product that changes the motion measurably.
fn check_symmetry(inertia: &InertiaTensor, symmetry: Symmetry) -> Result<(), ModelError> {
    let scale = inertia.ixx().max(inertia.iyy()).max(inertia.izz());
    for &field in symmetry.pruned() {
        let value = match field {
            "Ixy" => inertia.ixy(),
            "Iyz" => inertia.iyz(),
            _ => inertia.izx(),
        };
        if value.abs() > 1e-12 * scale {
            return Err(ModelError::SymmetryClass {
                field,
                value,
                class: symmetry.name(),
            });
        }
    }
    Ok(())
}

/// The generated coefficients hold [I]⁻¹ through 1/det[I]: a determinant that underflows or
/// overflows in f64 would make them infinite or zero and every rate NaN or wrong, so it is
/// refused as the generic form refuses it.
fn check_invertible(inertia: &InertiaTensor) -> Result<(), ModelError> {
    let determinant = inertia.matrix().determinant();
    if determinant.is_normal() {
        Ok(())
    } else {
        Err(ModelError::SingularInertia { determinant })
    }
}

/// What every spatial variant keeps beside its coefficients: for the kinetic energy.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Body<T> {
    mass: T,
    inertia: [[T; 3]; 3],
}

impl<T: SimdRealField + Copy> Body<T> {
    fn new(mass: f64, inertia: &InertiaTensor) -> Self {
        let m = inertia.matrix();
        Self {
            mass: scalar(mass),
            inertia: std::array::from_fn(|r| std::array::from_fn(|c| scalar(m[(r, c)]))),
        }
    }

    /// T = ½M v·v + ½ωᵀ[I]ω (4.32), from the first six entries of the state.
    fn kinetic_energy(&self, state: &[T]) -> T {
        let (v, w) = (&state[0..3], &state[3..6]);
        let translation = self.mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        let rotation = (0..3)
            .map(|r| {
                w[r] * (self.inertia[r][0] * w[0]
                    + self.inertia[r][1] * w[1]
                    + self.inertia[r][2] * w[2])
            })
            .fold(T::zero(), |a, b| a + b);
        (translation + rotation) * scalar(0.5)
    }
}

/// An emitted spatial `Parameters` struct, filled from a mass and an inertia tensor.
///
/// Each symmetry class emits only the products it keeps, named as the chapter names them
/// (`ixy`, `iyz`, `ixz`, with the sign of 4.14). This is the one place that maps a tensor's
/// entries onto those fields; it is implemented for every emitted spatial module, so that code
/// calling an emitted module directly builds its parameters as the typed models do. It does
/// not validate: build the typed model (e.g. [`SpatialFullEuler::new`]) for that.
///
/// ```
/// use eom::InertiaTensor;
/// use eom::models::{FromBody, SpatialPrincipalEuler, generated::spatial_principal_euler};
///
/// let inertia = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.0).unwrap();
/// let typed = SpatialPrincipalEuler::<f64>::new(5.0, &inertia).unwrap();
/// // The emitted module, called directly with parameters from the same body.
/// let emitted = spatial_principal_euler::Parameters::from_body(5.0, &inertia);
/// let k = spatial_principal_euler::Coefficients::<f64>::new(&emitted);
/// let state = [1.0, 0.2, -0.1, 0.3, -0.2, 0.5, 0.0, 0.0, 0.0, 0.1, 0.2, 0.3];
/// let (force, moment) = ([10.0, -2.0, 1.0], [0.5, 0.2, -0.3]);
/// let input = [force[0], force[1], force[2], moment[0], moment[1], moment[2]];
/// let direct = spatial_principal_euler::rhs(&k, &state, &input);
/// assert_eq!(typed.rhs(&state, &force, &moment), direct);
/// ```
pub trait FromBody {
    /// The parameters of a body of `mass` and `inertia` (about G, body axes).
    fn from_body(mass: f64, inertia: &InertiaTensor) -> Self;
}

macro_rules! from_body {
    ($($($module:ident)::+ { $($field:ident: $value:ident),* };)*) => {$(
        impl FromBody for $($module)::+::Parameters {
            fn from_body(mass: f64, inertia: &InertiaTensor) -> Self {
                Self {
                    mass,
                    ixx: inertia.ixx(),
                    iyy: inertia.iyy(),
                    izz: inertia.izz(),
                    $($field: inertia.$value(),)*
                }
            }
        }
    )*};
}

from_body! {
    generated::spatial_full_euler { ixy: ixy, iyz: iyz, ixz: izx };
    generated::spatial_full_quaternion { ixy: ixy, iyz: iyz, ixz: izx };
    generated::spatial_xz_euler { ixz: izx };
    generated::spatial_xz_quaternion { ixz: izx };
    generated::spatial_principal_euler {};
    generated::spatial_principal_quaternion {};
}

macro_rules! spatial_model {
    ($name:ident, $module:ident, $symmetry:expr, $n:literal, $kinematics:literal) => {
        #[doc = concat!("Spatial 6-DOF motion, ", stringify!($symmetry), " inertia, ", $kinematics, ".")]
        ///
        /// Validates the mass and the symmetry class of the tensor, computes the generated
        /// coefficients once, then [`Self::rhs`] evaluates the generated right-hand side.
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub struct $name<T> {
            coefficients: generated::$module::Coefficients<T>,
            body: Body<T>,
        }

        impl<T: SimdRealField + Copy> $name<T> {
            /// Validates M > 0 and that the products this class prunes are zero.
            pub fn new(mass: f64, inertia: &InertiaTensor) -> Result<Self, ModelError> {
                let mass = check_mass(mass)?;
                check_symmetry(inertia, $symmetry)?;
                check_invertible(inertia)?;
                let parameters = generated::$module::Parameters::from_body(mass, inertia);
                let coefficients = generated::$module::Coefficients::new(&parameters);
                Ok(Self { coefficients, body: Body::new(mass, inertia) })
            }

            /// The time derivative of the state for a force and a moment about G, body axes.
            #[inline]
            pub fn rhs(&self, state: &[T; $n], force: &[T; 3], moment: &[T; 3]) -> [T; $n] {
                let input = [force[0], force[1], force[2], moment[0], moment[1], moment[2]];
                generated::$module::rhs(&self.coefficients, state, &input)
            }

            /// Kinetic energy ½Mv·v + ½ωᵀ\[I\]ω (4.32).
            pub fn kinetic_energy(&self, state: &[T; $n]) -> T {
                self.body.kinetic_energy(state)
            }
        }
    };
}

spatial_model!(
    SpatialFullEuler,
    spatial_full_euler,
    Symmetry::Full,
    12,
    "Euler angles"
);
spatial_model!(
    SpatialFullQuaternion,
    spatial_full_quaternion,
    Symmetry::Full,
    13,
    "unit quaternion"
);
spatial_model!(
    SpatialXzEuler,
    spatial_xz_euler,
    Symmetry::Xz,
    12,
    "Euler angles"
);
spatial_model!(
    SpatialXzQuaternion,
    spatial_xz_quaternion,
    Symmetry::Xz,
    13,
    "unit quaternion"
);
spatial_model!(
    SpatialPrincipalEuler,
    spatial_principal_euler,
    Symmetry::Principal,
    12,
    "Euler angles"
);
spatial_model!(
    SpatialPrincipalQuaternion,
    spatial_principal_quaternion,
    Symmetry::Principal,
    13,
    "unit quaternion"
);
