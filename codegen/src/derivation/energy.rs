//! Section 4.4: kinetic energy (4.30–4.32) and the pendulum's energy integral (4.34–4.35).

use super::momentum::{TENSOR_IN_SECOND_MOMENTS, angular_momentum};
use super::{integrate_over_body, omega};
use crate::check::{Component, Equation, definitions};
use crate::symbolic::{Expr, SymbolicError, Vec3, parse};

const KINETIC_ENERGY: &str = "M*(u.powi(2) + v.powi(2) + w.powi(2))/2 \
    + (p*(Ixx*p + Ixy*q + Ixz*r) + q*(Iyx*p + Iyy*q + Iyz*r) + r*(Izx*p + Izy*q + Izz*r))/2";

pub(super) fn equations() -> Result<Vec<Equation>, SymbolicError> {
    Ok(vec![
        kinetic_energy()?,
        pendulum_kinetic_energy()?,
        pendulum_energy_is_conserved()?,
    ])
}

/// T = ½Mv_G·v_G + ½ω·(\[I\]ω) in the symbols of the tensor the models use (`Ixx … Izz`, 4.12,
/// symmetric): the form the generated models emit, proved equal to 4.32 below.
pub fn rigid_body_kinetic_energy() -> Result<Expr, SymbolicError> {
    let v_g = Vec3::symbols(["u", "v", "w"]);
    let h = super::spatial::inertia_tensor().mul_vec(&omega());
    let twice = &v_g.dot(&v_g) * &Expr::symbol("M") + omega().dot(&h);
    Ok(&twice * &parse("1/2")?)
}

/// T = ½∫ v·v dm with v = v_G + ω × r (4.5, 4.30), against ½Mv_G² + ½ωᵀ[I]ω and ½ω·H (4.32).
fn kinetic_energy() -> Result<Equation, SymbolicError> {
    let v_g = Vec3::symbols(["u", "v", "w"]);
    let r = Vec3::symbols(["x", "y", "z"]);
    let v = v_g.add(&omega().cross(&r));
    let half = parse("1/2")?;
    let derived = integrate_over_body(&(&v.dot(&v) * &half), ["x", "y", "z"], "")?;
    let via_momentum =
        &(&v_g.dot(&v_g) * &Expr::symbol("M") + &omega().dot(&angular_momentum()?)) * &half;
    let tensor = definitions(&TENSOR_IN_SECOND_MOMENTS)?;
    Ok(Equation {
        number: "4.32",
        description: "kinetic energy T = ½Mv_G² + ½ωᵀ[I]ω = ½Mv_G² + ½ω·H_G",
        components: vec![
            Component::new("½∫v·v dm", derived, KINETIC_ENERGY, &tensor),
            Component::new("½Mv_G² + ½ω·H_G", via_momentum, KINETIC_ENERGY, &tensor),
            Component::new(
                "½Mv_G² + ½ω·[I]ω as the models emit it",
                rigid_body_kinetic_energy()?.subs_all(&tensor_pairs(&tensor))?,
                KINETIC_ENERGY,
                &tensor,
            ),
        ],
    })
}

/// The pendulum's kinetic energy from ½Mv_G² + ½I_Gθ̇² (v_G = θ̇k × r_G, I_G = I₀ − Mh², 4.29):
/// the form its model emits, proved equal to ½I₀θ̇² (4.34) below.
pub fn pendulum_kinetic_energy_form() -> Result<Expr, SymbolicError> {
    let rate = Vec3::new(Expr::zero(), Expr::zero(), Expr::symbol("theta_dot"));
    let h = Expr::symbol("h");
    let r_g = Vec3::new(
        &h * &Expr::sin("theta"),
        -(&h * &Expr::cos("theta")),
        Expr::zero(),
    );
    let v_g = rate.cross(&r_g);
    let i_g = parse("I0 - M*h.powi(2)")?;
    let theta_dot_sq = parse("theta_dot.powi(2)")?;
    Ok(&(&v_g.dot(&v_g) * &Expr::symbol("M") + &i_g * &theta_dot_sq) * &parse("1/2")?)
}

/// T = ½M v_G² + ½ I_G θ̇² with v_G = θ̇k × r_G and I_G = I₀ − M h² (4.29), against ½ I₀ θ̇².
fn pendulum_kinetic_energy() -> Result<Equation, SymbolicError> {
    let derived = pendulum_kinetic_energy_form()?;
    Ok(Equation {
        number: "4.34",
        description: "pendulum: T = ½Mv_G² + ½I_Gθ̇² = ½I₀θ̇²",
        components: vec![Component::new("T", derived, "I0*theta_dot.powi(2)/2", &[])],
    })
}

fn tensor_pairs(definitions: &[crate::check::Definition]) -> Vec<(&str, Expr)> {
    definitions
        .iter()
        .map(|(symbol, value)| (symbol.as_str(), value.clone()))
        .collect()
}

/// d/dt(½I₀θ̇² − Mgh cos θ) vanishes once θ̈ is taken from 4.24.
fn pendulum_energy_is_conserved() -> Result<Equation, SymbolicError> {
    let energy = parse("I0*theta_dot.powi(2)/2 - M*g*h*theta.cos()")?;
    let rates = [
        ("theta", Expr::symbol("theta_dot")),
        ("theta_dot", Expr::symbol("theta_ddot")),
    ];
    let equation_of_motion = parse("-M*g*h*theta.sin()/I0")?;
    let derived = energy
        .time_derivative(&rates)
        .subs("theta_ddot", &equation_of_motion)?;
    Ok(Equation {
        number: "4.35",
        description: "pendulum energy ½I₀θ̇² − Mgh cos θ is constant along 4.24",
        components: vec![
            Component::new("dE/dt", derived, "0", &[]),
            Component::new(
                "V = −Mg·r_G as the model emits it",
                super::pendulum::potential_energy(),
                "-M*g*h*theta.cos()",
                &[],
            ),
        ],
    })
}
