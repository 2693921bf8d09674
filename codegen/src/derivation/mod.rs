//! The derivations, one module per section of the chapter, each next to its reference forms.
//!
//! Every derived form is computed from vector or matrix definitions with the symbolic engine;
//! nothing here is typed in component form except the book's own equations, which are the
//! reference texts the checker compares against.

mod body_integral;
pub mod energy;
pub mod kinematics;
mod momentum;
pub mod pendulum;
pub mod planar;
pub mod quaternion;
pub mod spatial;
mod steiner;
pub mod top;
pub mod vehicle;

use crate::check::{CheckError, Equation};
use crate::symbolic::{Expr, SymbolicError, Vec3};

pub use body_integral::integrate_over_body;
pub use kinematics::{rotation_x, rotation_y, rotation_z};
pub use quaternion::Quaternion;
pub use steiner::tensor_about_origin;

/// A section's derivations.
type Section = fn() -> Result<Vec<Equation>, SymbolicError>;

/// Every equation, in the chapter's order, then what is built beyond it.
pub fn all() -> Result<Vec<Equation>, CheckError> {
    let sections: [(&'static str, Section); 9] = [
        ("4.9–4.14", momentum::equations),
        ("4.23", steiner::equations),
        ("4.24", pendulum::equations),
        ("4.32–4.35", energy::equations),
        ("4.42–4.46", planar::equations),
        ("4.49–4.52", spatial::equations),
        ("4.57–4.60", kinematics::equations),
        ("quaternion", quaternion::equations),
        ("top", top::equations),
    ];
    let mut all = Vec::new();
    for (number, section) in sections {
        all.extend(section().map_err(|source| CheckError::Derivation { number, source })?);
    }
    Ok(all)
}

/// ω = p i + q j + r k (4.8).
fn omega() -> Vec3 {
    Vec3::symbols(["p", "q", "r"])
}

/// The rates of the body's velocity and angular velocity, [dv/dt] and [dω/dt] in body axes.
fn rates_of(names: [&str; 3]) -> Vec3 {
    Vec3(names.map(|n| Expr::symbol(&format!("{n}_dot"))))
}

/// Component labels for a vector equation.
const AXES: [&str; 3] = ["x", "y", "z"];
