//! Section 4.3: the compound pendulum, 4.24, from dH/dt = M about the pivot.

use crate::check::{Component, Equation};
use crate::symbolic::{Expr, SymbolicError, Vec3};

/// r_G = h(sin θ, −cos θ, 0): G seen from the pivot, θ from the downward vertical.
fn centre_of_gravity() -> Vec3 {
    let h = Expr::symbol("h");
    Vec3::new(
        &h * &Expr::sin("theta"),
        -(&h * &Expr::cos("theta")),
        Expr::zero(),
    )
}

/// The weight Mg, along −y.
fn weight() -> Vec3 {
    Vec3::new(
        Expr::zero(),
        -(Expr::symbol("M") * Expr::symbol("g")),
        Expr::zero(),
    )
}

/// I₀θ̈ − (r_G × M g)_z with r_G = h(sin θ, −cos θ, 0) from the pivot and gravity along −y:
/// the residual of 4.24.
pub fn residual() -> Expr {
    let gravity_moment = centre_of_gravity().cross(&weight()).0[2].clone();
    Expr::symbol("I0") * Expr::symbol("theta_ddot") - gravity_moment
}

/// V = −Mg·r_G: the weight's potential with the same vectors, zero with G level with the
/// pivot (4.35's −Mgh cos θ; 4.34's U = Mgh(1 − cos θ) is it plus the constant Mgh).
pub fn potential_energy() -> Expr {
    -weight().dot(&centre_of_gravity())
}

pub(super) fn equations() -> Result<Vec<Equation>, SymbolicError> {
    Ok(vec![Equation {
        number: "4.24",
        description: "compound pendulum I₀θ̈ = −Mgh sin θ, from dH/dt = r_G × Mg about the pivot",
        components: vec![Component::new(
            "θ",
            residual(),
            "I0*theta_ddot + M*g*h*theta.sin()",
            &[],
        )],
    }])
}
