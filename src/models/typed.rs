//! The typed models: one type per variant of the catalog, each built from validated
//! parameters and implementing [`Model`].
//!
//! The types are written by one macro over the catalog (`for_each_model!`); what differs
//! between families is only what `new` takes and checks. Each type's [`Model`] is that of the
//! coefficients it holds, which the emitter writes with the generated code; a typed model
//! adds only the guarantee that its parameters were validated.

use super::model::Model;
use super::{FromBody, generated, pendulum, planar, spatial, top};
use crate::InertiaTensor;
use crate::generic::ModelError;
use simba::simd::SimdRealField;

macro_rules! typed_models {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {$(
        #[doc = concat!(" ", $title)]
        ///
        #[doc = concat!(" State `", stringify!($n), "` entries ([`Model::STATE`]), inputs `", stringify!($m), "` ([`Model::INPUTS`]); the generated code is [`generated::", stringify!($module), "`].")]
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub struct $type<T> {
            coefficients: generated::$module::Coefficients<T>,
        }

        impl<T: SimdRealField + Copy> $type<T> {
            typed_models!(@new $module, $family $(($($option),+))?);

            /// The model of already validated parameters.
            fn from_parameters(parameters: &generated::$module::Parameters) -> Self {
                Self { coefficients: generated::$module::Coefficients::new(parameters) }
            }

            /// The coefficients the generated code reads, computed once from the parameters.
            pub fn coefficients(&self) -> &generated::$module::Coefficients<T> {
                &self.coefficients
            }
        }

        // The contract of the emitted coefficients, whose implementation the emitter writes.
        impl<T: SimdRealField + Copy> Model<T, $n, $m> for $type<T> {
            const NAME: &'static str = <generated::$module::Coefficients<T> as Model<T, $n, $m>>::NAME;
            const STATE: [&'static str; $n] = generated::$module::STATE;
            const INPUTS: [&'static str; $m] = generated::$module::INPUTS;
            const STATE_JACOBIAN: &'static [(usize, usize)] = &generated::$module::STATE_JACOBIAN;
            const INPUT_JACOBIAN: &'static [(usize, usize)] = &generated::$module::INPUT_JACOBIAN;

            #[inline(always)]
            fn rhs(&self, state: &[T; $n], input: &[T; $m]) -> [T; $n] {
                self.coefficients.rhs(state, input)
            }

            #[inline]
            fn kinetic_energy(&self, state: &[T; $n]) -> T {
                self.coefficients.kinetic_energy(state)
            }

            fn state_jacobian(&self, state: &[T; $n], input: &[T; $m]) -> [[T; $n]; $n] {
                self.coefficients.state_jacobian(state, input)
            }

            fn input_jacobian(&self, state: &[T; $n], input: &[T; $m]) -> [[T; $m]; $n] {
                self.coefficients.input_jacobian(state, input)
            }

            #[inline]
            fn potential_energy(&self, state: &[T; $n]) -> Option<T> {
                self.coefficients.potential_energy(state)
            }
        }
    )*};
    (@new $module:ident, Pendulum) => {
        /// The pendulum of `parameters`, already validated (see
        /// [`PendulumParameters::new`](crate::PendulumParameters::new)).
        pub fn new(parameters: &crate::PendulumParameters) -> Self {
            Self::from_parameters(&pendulum::emitted(parameters))
        }
    };
    (@new $module:ident, PlanarAtG) => {
        /// Validates M > 0 and I_zz > 0.
        pub fn new(mass: f64, izz: f64) -> Result<Self, ModelError> {
            let (mass, izz) = planar::validate(mass, izz)?;
            Ok(Self::from_parameters(&generated::$module::Parameters { mass, izz }))
        }
    };
    (@new $module:ident, PlanarSpaceFixed) => {
        typed_models!(@new $module, PlanarAtG);
    };
    (@new $module:ident, PlanarMidship) => {
        /// Validates M > 0, I_zz > 0 (about G) and a finite x_G (G ahead of midship).
        pub fn new(mass: f64, izz: f64, x_g: f64) -> Result<Self, ModelError> {
            let (mass, izz) = planar::validate(mass, izz)?;
            let x_g = planar::validate_x_g(x_g)?;
            Ok(Self::from_parameters(&generated::$module::Parameters { mass, izz, x_g }))
        }
    };
    (@new $module:ident, Spatial($symmetry:ident, $kinematics:ident)) => {
        /// Validates M > 0, an invertible tensor, and that the products of inertia this
        /// symmetry class prunes are zero (to [`PRODUCT_TOLERANCE`](super::PRODUCT_TOLERANCE)
        /// of the largest moment).
        pub fn new(mass: f64, inertia: &InertiaTensor) -> Result<Self, ModelError> {
            let mass = spatial::validate(mass, inertia, super::Symmetry::$symmetry)?;
            Ok(Self::from_parameters(&generated::$module::Parameters::from_body(mass, inertia)))
        }
    };
    (@new $module:ident, Top($kinematics:ident)) => {
        /// The top of a body of `mass` whose tensor about G, `inertia_at_g`, is in principal
        /// axes, hung on a pivot at distance `h` from G along the body z-axis (r_G = (0, 0, h)
        /// from the pivot; `h` of either sign), under gravity `g` along −Z in space axes.
        ///
        /// Validates M > 0, a principal tensor (products zero to
        /// [`PRODUCT_TOLERANCE`](super::PRODUCT_TOLERANCE) of the largest moment), h and g
        /// finite, and the moments about the pivot (4.23: I_xx + M h², I_yy + M h², I_zz)
        /// positive and finite.
        pub fn new(
            mass: f64,
            inertia_at_g: &InertiaTensor,
            h: f64,
            g: f64,
        ) -> Result<Self, ModelError> {
            let top::Body { mass, ixx, iyy, izz, h, g } = top::validate(mass, inertia_at_g, h, g)?;
            Ok(Self::from_parameters(&generated::$module::Parameters { mass, ixx, iyy, izz, h, g }))
        }
    };
}

for_each_model!(typed_models);
