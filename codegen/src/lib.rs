//! # eom-codegen — derive, prove and emit rigid-body equations of motion
//!
//! A small symbolic engine ([`symbolic`]) expands the vector definitions of a rigid body's
//! equations of motion (ω×r, r×(ω×r), ω×H, Rz·Ry·Rx, the Euler-rate matrix) into component
//! equations, and [`check`] proves each equal to the textbook's own form before any code is
//! emitted. A derivation that disagrees with the book stops the build and prints the residual.
#![deny(missing_docs)]

pub mod check;
pub mod derivation;
pub mod emit;
pub mod model;
pub mod report;
pub mod symbolic;
