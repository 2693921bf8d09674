//! # eom — rigid-body equations of motion, derived, proved and emitted
//!
//! The equations of a rigid body (ships, underwater vehicles, aircraft, pendulums) are derived
//! from their vector definitions by the symbolic engine in `eom-codegen`, proved equal to the
//! textbook's own forms when this crate is built, and emitted as specialised Rust. This crate
//! holds what runs: the validated physical inputs, the special functions the reference
//! solutions need, and (as they land) the generated models, the integrators and the generic
//! nalgebra forms they are checked against.
#![deny(missing_docs)]

pub mod elliptic;
pub mod energy;
pub mod generic;
mod inertia;
pub mod integrate;
pub mod mass;
pub mod models;
mod pendulum;
pub mod reference;
pub mod swing;
mod validate;

pub use inertia::{InertiaError, InertiaTensor};
pub use pendulum::PendulumParameters;
pub use validate::ParameterError;
