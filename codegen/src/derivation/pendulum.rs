//! Section 4.3: the compound pendulum, 4.24, from dH/dt = M about the pivot.

use crate::check::{Component, Equation};
use crate::symbolic::{Expr, SymbolicError, Vec3};

/// I₀θ̈ − (r_G × M g)_z with r_G = h(sin θ, −cos θ, 0) from the pivot and gravity along −y:
/// the residual of 4.24.
pub fn residual() -> Expr {
    let h = Expr::symbol("h");
    let r_g = Vec3::new(
        &h * &Expr::sin("theta"),
        -(&h * &Expr::cos("theta")),
        Expr::zero(),
    );
    let weight = Vec3::new(
        Expr::zero(),
        -(Expr::symbol("M") * Expr::symbol("g")),
        Expr::zero(),
    );
    let gravity_moment = r_g.cross(&weight).0[2].clone();
    Expr::symbol("I0") * Expr::symbol("theta_ddot") - gravity_moment
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
