//! The generated models behind one trait and a validated constructor each.
//!
//! The catalog of variants is written once, in `eom-codegen` (`Model::all`); the build script
//! emits from it every model's code ([`generated`]), the list [`CATALOG`], the runtime's
//! [`Symmetry`], [`Kinematics`] and [`Family`], and the macro `for_each_model!`, from which
//! the typed models below are written. Each typed model validates its parameters once
//! (finite numbers, mass > 0, a physical inertia tensor, products of inertia zero where the
//! symmetry class prunes them; the pendulum takes them already validated as a
//! [`crate::PendulumParameters`]), computes the generated coefficients once, and implements
//! [`Model`]: the state and input layouts, `rhs`, the kinetic energy (4.32) and the
//! Jacobians, generic over the scalar `T: SimdRealField + Copy` (`f32`, `f64`,
//! `simba::simd::WideF64x4` lanes, dual numbers). That implementation is the generated
//! coefficients' own, which the emitter writes into each generated file (so a model a user
//! emits from their own `build.rs` has it too); the contract is `eom-kernel`'s, re-exported
//! here. [`Model::driven_by`] turns a model and its [`Loads`] into an
//! [`OdeSystem`](crate::integrate::OdeSystem).
//!
//! | type | state | inputs |
//! |---|---|---|
//! | [`Pendulum`] | `[θ, θ̇]` | moment about the pivot |
//! | [`PlanarAtG`] | `[u, v, r, X, Y, ψ]` | `[F_x, F_y, M_z]` body axes, about G |
//! | [`PlanarMidship`] | `[u, v, r, X, Y, ψ]` of the midship origin | `[X, Y, N]` body axes, about midship |
//! | [`PlanarSpaceFixed`] | `[X, Y, ψ, Ẋ, Ẏ, ψ̇]` | `[F_X, F_Y, M_z]` space axes |
//! | [`SpatialFullEuler`], [`SpatialXzEuler`], [`SpatialPrincipalEuler`] | `[u, v, w, p, q, r, x, y, z, φ, θ, ψ]` | force and moment about G, body axes |
//! | [`SpatialFullQuaternion`], [`SpatialXzQuaternion`], [`SpatialPrincipalQuaternion`] | `[u, v, w, p, q, r, x, y, z, q0, q1, q2, q3]` | force and moment about G, body axes |
//! | [`TopEuler`] | `[p, q, r, φ, θ, ψ]` | moment about the pivot, body axes |
//! | [`TopQuaternion`] | `[p, q, r, q0, q1, q2, q3]` | moment about the pivot, body axes |
//!
//! The Euler-angle variants are singular at θ = ±90° (4.60 divides by cos θ); use a
//! quaternion variant for attitudes that may get there. The pendulum and the tops also report
//! their potential energy in the weight's field ([`Model::potential_energy`]): Mg times the
//! height of G above the pivot.

mod attitude;
mod info;
mod model;
mod pendulum;
mod planar;
mod units;

pub use attitude::{attitude, euler_angles, euler_angles_of_quaternion};
pub use eom_kernel::Operations;
pub use info::ModelInfo;
pub use model::{Constant, Driven, Loads, Model};
pub use units::{ENERGY_UNIT, TIME_UNIT, input_unit, state_unit, state_with_unit, with_unit};

include!(concat!(env!("OUT_DIR"), "/catalog.rs"));

mod any;
mod dynamic;
mod spatial;
mod top;
mod typed;

pub use any::{AnyModel, LayoutError, Visitor};
pub use dynamic::{DynModel, Erased, SizeError};
pub use spatial::{FromBody, PRODUCT_TOLERANCE};
pub use typed::*;
