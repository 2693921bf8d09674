//! Aircraft on their aerodynamic tables: the other half of the chapter's 4.6, whose six
//! equations are written "for aircraft and underwater robots".
//!
//! An aircraft's loads are coefficient tables in the angle of attack, the sideslip and the
//! controls times the dynamic pressure, an engine with its own lag and rotor, in an
//! atmosphere that changes with altitude. The model ([`model`]) is the proved program of
//! `eom_codegen::model::aircraft`; what is not a polynomial (the lookups, the air, the
//! engine's piecewise laws) is computed beside it and read as its inputs, with its slopes in
//! the Jacobians.

pub mod aero;
pub mod atmosphere;
pub mod derivatives;
pub mod engine;
pub mod file;
mod keys;
mod kind;
pub mod linear;
pub mod manoeuvre;
pub mod model;
pub mod run;
pub mod scene;
pub mod tables;
pub mod trim;

pub use kind::KIND;
pub use model::{
    AircraftError, AircraftModel, Airframe, CONTROLS, InQuaternion, QUATERNION_STATE, STATE,
};
pub use scene::AircraftScene;
