//! A model chosen at run time: one enum over every typed model of the catalog, in f64.
//!
//! A scene or a command line names its model by family, symmetry and kinematics; [`AnyModel`]
//! holds whichever typed model that is, and [`AnyModel::visit`] hands it back to generic code
//! with its state and input sizes known at compile time, so that what runs is the generated
//! `rhs`, inlined, not a call through a pointer.

use super::model::Model;
use super::*;

/// Generic code that runs on whichever model an [`AnyModel`] holds.
pub trait Visitor {
    /// What the visit returns.
    type Output;

    /// Runs on the model.
    fn visit<Mo: Model<f64, N, M>, const N: usize, const M: usize>(
        self,
        model: &Mo,
    ) -> Self::Output;
}

macro_rules! any_model {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {
        /// Every typed model of the catalog over `f64`, one variant each.
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub enum AnyModel {
            $(
                #[doc = concat!(" ", $title)]
                $type($type<f64>),
            )*
        }

        $(
            impl From<$type<f64>> for AnyModel {
                fn from(model: $type<f64>) -> Self {
                    AnyModel::$type(model)
                }
            }
        )*

        impl AnyModel {
            /// Runs `visitor` on the model held.
            pub fn visit<V: Visitor>(&self, visitor: V) -> V::Output {
                match self {
                    $(AnyModel::$type(model) => visitor.visit(model),)*
                }
            }

            /// The catalog's entry for the model held.
            pub fn info(&self) -> &'static ModelInfo {
                let name = match self {
                    $(AnyModel::$type(_) => stringify!($module),)*
                };
                ModelInfo::find(name).expect("every typed model is in the catalog")
            }

            /// The spatial model of a symmetry class and kinematics for a body.
            pub fn spatial(
                symmetry: Symmetry,
                kinematics: Kinematics,
                mass: f64,
                inertia: &crate::InertiaTensor,
            ) -> Result<Self, crate::generic::ModelError> {
                $(any_model!(
                    @spatial $type, symmetry, kinematics, mass, inertia,
                    $family $(($($option),+))?
                );)*
                unreachable!("the catalog has every spatial variant")
            }

            /// The top of a body of `mass` with the principal tensor `inertia_at_g` about G, G
            /// at distance `h` from the pivot along the body z-axis, under gravity `g`, with
            /// the attitude carried by `kinematics` (see
            /// [`TopEuler::new`](super::TopEuler::new)).
            pub fn top(
                kinematics: Kinematics,
                mass: f64,
                inertia_at_g: &crate::InertiaTensor,
                h: f64,
                g: f64,
            ) -> Result<Self, crate::generic::ModelError> {
                $(any_model!(
                    @top $type, kinematics, mass, inertia_at_g, h, g, $family $(($($option),+))?
                );)*
                unreachable!("the catalog has a top of every kinematics")
            }
        }
    };
    (@spatial $type:ident, $symmetry:ident, $kinematics:ident, $mass:ident, $inertia:ident,
        Spatial($class:ident, $attitude:ident)) => {
        if $symmetry == Symmetry::$class && $kinematics == Kinematics::$attitude {
            return Ok($type::new($mass, $inertia)?.into());
        }
    };
    (@spatial $($other:tt)*) => {};
    (@top $type:ident, $kinematics:ident, $mass:ident, $inertia:ident, $h:ident, $g:ident,
        Top($attitude:ident)) => {
        if $kinematics == Kinematics::$attitude {
            return Ok($type::new($mass, $inertia, $h, $g)?.into());
        }
    };
    (@top $($other:tt)*) => {};
}

for_each_model!(any_model);

/// A layout mismatch: a state or an input of the wrong length for the model.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{model} takes {expected} {what}, not {given}")]
pub struct LayoutError {
    /// The model.
    pub model: &'static str,
    /// `"state entries"` or `"inputs"`.
    pub what: &'static str,
    /// What the model takes.
    pub expected: usize,
    /// What was given.
    pub given: usize,
}

impl AnyModel {
    /// The time derivative of a state given as a slice, under inputs given as a slice.
    pub fn rhs(&self, state: &[f64], input: &[f64]) -> Result<Vec<f64>, LayoutError> {
        struct Rhs<'a>(&'a [f64], &'a [f64]);
        impl Visitor for Rhs<'_> {
            type Output = Result<Vec<f64>, LayoutError>;
            fn visit<Mo: Model<f64, N, M>, const N: usize, const M: usize>(
                self,
                model: &Mo,
            ) -> Self::Output {
                let state: [f64; N] = fixed(Mo::NAME, "state entries", self.0)?;
                let input: [f64; M] = fixed(Mo::NAME, "inputs", self.1)?;
                Ok(model.rhs(&state, &input).to_vec())
            }
        }
        self.visit(Rhs(state, input))
    }

    /// The kinetic energy (4.32) of a state given as a slice.
    pub fn kinetic_energy(&self, state: &[f64]) -> Result<f64, LayoutError> {
        struct Energy<'a>(&'a [f64]);
        impl Visitor for Energy<'_> {
            type Output = Result<f64, LayoutError>;
            fn visit<Mo: Model<f64, N, M>, const N: usize, const M: usize>(
                self,
                model: &Mo,
            ) -> Self::Output {
                let state: [f64; N] = fixed(Mo::NAME, "state entries", self.0)?;
                Ok(model.kinetic_energy(&state))
            }
        }
        self.visit(Energy(state))
    }

    /// The potential energy of a state given as a slice, for a model that has one (the
    /// pendulum, the top; see [`Model::potential_energy`]).
    pub fn potential_energy(&self, state: &[f64]) -> Result<Option<f64>, LayoutError> {
        struct Potential<'a>(&'a [f64]);
        impl Visitor for Potential<'_> {
            type Output = Result<Option<f64>, LayoutError>;
            fn visit<Mo: Model<f64, N, M>, const N: usize, const M: usize>(
                self,
                model: &Mo,
            ) -> Self::Output {
                let state: [f64; N] = fixed(Mo::NAME, "state entries", self.0)?;
                Ok(model.potential_energy(&state))
            }
        }
        self.visit(Potential(state))
    }
}

fn fixed<const K: usize>(
    model: &'static str,
    what: &'static str,
    values: &[f64],
) -> Result<[f64; K], LayoutError> {
    values.try_into().map_err(|_| LayoutError {
        model,
        what,
        expected: K,
        given: values.len(),
    })
}

/// ∂f/∂x and ∂f/∂u of a model at a state and inputs, as dense matrices (rows: the rates).
type Jacobians = (nalgebra::DMatrix<f64>, nalgebra::DMatrix<f64>);

impl AnyModel {
    /// The emitted Jacobians ∂f/∂x (N×N) and ∂f/∂u (N×M) at a state and inputs given as
    /// slices (see [`Model::state_jacobian`]).
    pub fn jacobians(&self, state: &[f64], input: &[f64]) -> Result<Jacobians, LayoutError> {
        struct Both<'a>(&'a [f64], &'a [f64]);
        impl Visitor for Both<'_> {
            type Output = Result<Jacobians, LayoutError>;
            fn visit<Mo: Model<f64, N, M>, const N: usize, const M: usize>(
                self,
                model: &Mo,
            ) -> Self::Output {
                let state: [f64; N] = fixed(Mo::NAME, "state entries", self.0)?;
                let input: [f64; M] = fixed(Mo::NAME, "inputs", self.1)?;
                let a = model.state_jacobian(&state, &input);
                let b = model.input_jacobian(&state, &input);
                Ok((
                    nalgebra::DMatrix::from_fn(N, N, |i, j| a[i][j]),
                    nalgebra::DMatrix::from_fn(N, M, |i, j| b[i][j]),
                ))
            }
        }
        self.visit(Both(state, input))
    }

    /// Where ∂f/∂x has entries that do not vanish identically ([`Model::STATE_JACOBIAN`]).
    pub fn state_jacobian_pattern(&self) -> &'static [(usize, usize)] {
        struct Pattern;
        impl Visitor for Pattern {
            type Output = &'static [(usize, usize)];
            fn visit<Mo: Model<f64, N, M>, const N: usize, const M: usize>(
                self,
                _: &Mo,
            ) -> Self::Output {
                Mo::STATE_JACOBIAN
            }
        }
        self.visit(Pattern)
    }
}
