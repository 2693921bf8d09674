//! Section 4.5: planar motion (manoeuvring), 4.41–4.46.
//!
//! The body-fixed acceleration comes from [dv/dt] + ω × v with ω = ψ̇k (4.4, 4.41); the yaw
//! equation is the z-component of the full Euler equation with p = q = 0, so that products
//! of inertia are seen to drop out of it; the midship form follows by substituting the change
//! of origin (4.45) into the form at G.

use super::kinematics::rotation_z;
use super::spatial::euler_equations;
use crate::check::{Component, Definition, Equation, definitions};
use crate::symbolic::{Expr, SymbolicError, Vec3, parse};

/// ω = ψ̇k: the book writes ψ̇ for the yaw rate r (4.41).
const YAW_RATE: [(&str, &str); 2] = [("psi_dot", "r"), ("psi_ddot", "r_dot")];

pub(super) fn equations() -> Result<Vec<Equation>, SymbolicError> {
    let yaw = definitions(&YAW_RATE)?;
    let at_g = residuals_at_g()?;
    Ok(vec![
        space_fixed(&yaw)?,
        acceleration(&yaw)?,
        form_at_g(&at_g, &yaw),
        track()?,
        form_at_midship(&at_g, &yaw)?,
    ])
}

/// Residuals of 4.39: d/dt(M Ẋ_G, M Ẏ_G) − (F_X, F_Y) in space axes (4.1), and the yaw
/// equation as for 4.43 (k = K, so H_G = I_zz ψ̇ K, 4.38).
pub fn space_fixed_residuals() -> Result<[Expr; 3], SymbolicError> {
    let rates = [
        ("X_dot", Expr::symbol("X_ddot")),
        ("Y_dot", Expr::symbol("Y_ddot")),
    ];
    let momentum = |v: &str| Expr::symbol("M") * Expr::symbol(v);
    let yaw = yaw_moment_equation()?;
    Ok([
        momentum("X_dot").time_derivative(&rates) - Expr::symbol("F_X"),
        momentum("Y_dot").time_derivative(&rates) - Expr::symbol("F_Y"),
        yaw - Expr::symbol("M_z"),
    ])
}

fn space_fixed(yaw: &[Definition]) -> Result<Equation, SymbolicError> {
    let derived = space_fixed_residuals()?;
    let book = ["M*X_ddot - F_X", "M*Y_ddot - F_Y", "Izz*psi_ddot - M_z"];
    Ok(Equation {
        number: "4.39",
        description: "planar equations in space-fixed axes",
        components: (0..3)
            .map(|i| Component::new(["X", "Y", "yaw"][i], derived[i].clone(), book[i], yaw))
            .collect(),
    })
}

/// The z-component of 4.51 for planar rotation (p = q = 0): I_zz ṙ, the products drop out.
fn yaw_moment_equation() -> Result<Expr, SymbolicError> {
    let planar_rates = [
        ("p", Expr::zero()),
        ("q", Expr::zero()),
        ("p_dot", Expr::zero()),
        ("q_dot", Expr::zero()),
    ];
    euler_equations()?.0[2].subs_all(&planar_rates)
}

/// a_G = [dv/dt] + ω × v for v = u i + v j, ω = r k.
fn planar_acceleration() -> Vec3 {
    let v = Vec3::new(Expr::symbol("u"), Expr::symbol("v"), Expr::zero());
    let v_rate = Vec3::new(Expr::symbol("u_dot"), Expr::symbol("v_dot"), Expr::zero());
    let omega = Vec3::new(Expr::zero(), Expr::zero(), Expr::symbol("r"));
    v_rate.add(&omega.cross(&v))
}

fn acceleration(yaw: &[Definition]) -> Result<Equation, SymbolicError> {
    let a = planar_acceleration();
    Ok(Equation {
        number: "4.42",
        description: "planar acceleration of G in body axes, from [dv/dt] + ω×v",
        components: vec![
            Component::new("i", a.0[0].clone(), "u_dot - v*psi_dot", yaw),
            Component::new("j", a.0[1].clone(), "v_dot + u*psi_dot", yaw),
        ],
    })
}

/// Residuals (left − right) of 4.43 at G: M a_G − F and the yaw moment equation.
pub fn residuals_at_g() -> Result<[Expr; 3], SymbolicError> {
    let a = planar_acceleration();
    let m = Expr::symbol("M");
    let planar_rates = [
        ("p", Expr::zero()),
        ("q", Expr::zero()),
        ("p_dot", Expr::zero()),
        ("q_dot", Expr::zero()),
    ];
    let yaw = euler_equations()?.0[2].subs_all(&planar_rates)?;
    Ok([
        &a.0[0] * &m - Expr::symbol("F_x"),
        &a.0[1] * &m - Expr::symbol("F_y"),
        yaw - Expr::symbol("M_z"),
    ])
}

fn form_at_g(at_g: &[Expr; 3], yaw: &[Definition]) -> Equation {
    let book = [
        "M*(u_dot - v*psi_dot) - F_x",
        "M*(v_dot + u*psi_dot) - F_y",
        "Izz*psi_ddot - M_z",
    ];
    Equation {
        number: "4.43",
        description: "planar equations in body axes at G (surge, sway, yaw)",
        components: (0..3)
            .map(|i| Component::new(["x", "y", "yaw"][i], at_g[i].clone(), book[i], yaw))
            .collect(),
    }
}

/// (Ẋ_G, Ẏ_G) = Rz(ψ)(u, v) (4.44, from 4.53).
fn track() -> Result<Equation, SymbolicError> {
    let velocity = Vec3::new(Expr::symbol("u"), Expr::symbol("v"), Expr::zero());
    let rate = rotation_z("psi").mul_vec(&velocity);
    Ok(Equation {
        number: "4.44",
        description: "track of G: the body velocity turned through ψ",
        components: vec![
            Component::new("X_dot", rate.0[0].clone(), "u*psi.cos() - v*psi.sin()", &[]),
            Component::new("Y_dot", rate.0[1].clone(), "u*psi.sin() + v*psi.cos()", &[]),
        ],
    })
}

/// 4.46: substitute 4.45 (v_G = v + x_G r, M_z(G) = M_z − x_G F_y) into 4.43, then eliminate
/// F_y from the yaw equation with the sway equation.
fn form_at_midship(at_g: &[Expr; 3], yaw: &[Definition]) -> Result<Equation, SymbolicError> {
    let derived = residuals_at_midship(at_g)?;
    let book = [
        "M*(u_dot - v*psi_dot - x_G*psi_dot.powi(2)) - F_x",
        "M*(v_dot + u*psi_dot + x_G*psi_ddot) - F_y",
        "(Izz + M*x_G.powi(2))*psi_ddot + M*x_G*(v_dot + u*psi_dot) - M_z",
    ];
    Ok(Equation {
        number: "4.46",
        description: "planar equations at midship, G at (x_G, 0, 0), by the origin shift 4.45",
        components: (0..3)
            .map(|i| Component::new(["x", "y", "yaw"][i], derived[i].clone(), book[i], yaw))
            .collect(),
    })
}

/// Residuals of 4.46, from those of 4.43 at G by the origin shift 4.45.
pub fn residuals_at_midship(at_g: &[Expr; 3]) -> Result<[Expr; 3], SymbolicError> {
    let sway_at_g = parse("v + x_G*r")?;
    let body_rates = [("v", Expr::symbol("v_dot")), ("r", Expr::symbol("r_dot"))];
    let origin_shift = [
        ("v_dot", sway_at_g.time_derivative(&body_rates)),
        ("v", sway_at_g),
        ("M_z", parse("M_z - x_G*F_y")?),
    ];
    let shifted: Vec<Expr> = at_g
        .iter()
        .map(|e| e.subs_all(&origin_shift))
        .collect::<Result<_, _>>()?;
    let sway_force = &shifted[1] + &Expr::symbol("F_y");
    let yaw_eliminated = shifted[2].subs("F_y", &sway_force)?;
    Ok([shifted[0].clone(), shifted[1].clone(), yaw_eliminated])
}
