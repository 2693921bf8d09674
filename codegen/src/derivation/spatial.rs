//! Section 4.6: spatial (6-DOF) motion, 4.47–4.52.
//!
//! Translation is M([dv/dt] + ω × v) = F (4.48); rotation is [dH/dt] + ω × H = M (4.50)
//! with H = \[I\]ω and the full symmetric tensor, so every product-of-inertia term of 4.51 is
//! computed, not copied. The symmetric cases follow by setting products to zero.

use super::{AXES, omega, rates_of};
use crate::check::{Component, Definition, Equation, definitions};
use crate::symbolic::{Expr, Mat3, SymbolicError, Vec3};

/// The book writes the mirrored products too; 4.14 makes each equal to its twin.
const MIRRORED_PRODUCTS: [(&str, &str); 3] = [("Iyx", "Ixy"), ("Izx", "Ixz"), ("Izy", "Iyz")];

/// The inertia tensor of 4.12 with symbols `Ixx … Izz`, symmetric.
pub fn inertia_tensor() -> Mat3 {
    Mat3::symmetric([["Ixx", "Ixy", "Ixz"], ["", "Iyy", "Iyz"], ["", "", "Izz"]])
}

/// \[I\]\[dω/dt\] + ω × (\[I\]ω): the left side of 4.50 in body axes.
pub fn euler_equations() -> Result<Vec3, SymbolicError> {
    let tensor = inertia_tensor();
    let h = tensor.mul_vec(&omega());
    Ok(tensor
        .mul_vec(&rates_of(["p", "q", "r"]))
        .add(&omega().cross(&h)))
}

/// M([dv/dt] + ω × v): the left side of 4.48.
pub fn translation() -> Vec3 {
    let v = Vec3::symbols(["u", "v", "w"]);
    rates_of(["u", "v", "w"])
        .add(&omega().cross(&v))
        .scale(&Expr::symbol("M"))
}

pub(super) fn equations() -> Result<Vec<Equation>, SymbolicError> {
    let mirrored = definitions(&MIRRORED_PRODUCTS)?;
    let rotation = euler_equations()?;
    let xz_symmetric = without_products(&rotation, &["Ixy", "Iyz"])?;
    let principal = without_products(&rotation, &["Ixy", "Iyz", "Ixz"])?;
    Ok(vec![
        translation_equation(),
        rotation_equation(
            "4.51",
            FULL,
            "Euler's equations with all products of inertia",
            &rotation,
            &mirrored,
        ),
        rotation_equation(
            "4.51 xz",
            XZ,
            "4.51 for a body symmetric about its xz-plane (I_xy = I_yz = 0)",
            &xz_symmetric,
            &mirrored,
        ),
        rotation_equation(
            "4.52",
            PRINCIPAL,
            "4.51 with all products zero (principal axes)",
            &principal,
            &mirrored,
        ),
    ])
}

fn translation_equation() -> Equation {
    let lhs = translation();
    let book = [
        "M*(u_dot + w*q - v*r) - F_x",
        "M*(v_dot + u*r - w*p) - F_y",
        "M*(w_dot + v*p - u*q) - F_z",
    ];
    let forces = Vec3::symbols(["F_x", "F_y", "F_z"]);
    Equation {
        number: "4.49",
        description: "translation in body axes, M([dv/dt] + ω×v) = F",
        components: (0..3)
            .map(|i| Component::new(AXES[i], &lhs.0[i] - &forces.0[i], book[i], &[]))
            .collect(),
    }
}

const FULL: [&str; 3] = [
    "Ixx*p_dot + (Izz - Iyy)*q*r + Ixy*(q_dot - r*p) + Ixz*(r_dot + p*q) + Iyz*(q.powi(2) - r.powi(2)) - M_x",
    "Iyy*q_dot + (Ixx - Izz)*r*p + Iyz*(r_dot - p*q) + Iyx*(p_dot + q*r) + Izx*(r.powi(2) - p.powi(2)) - M_y",
    "Izz*r_dot + (Iyy - Ixx)*p*q + Izx*(p_dot - q*r) + Izy*(q_dot + r*p) + Ixy*(p.powi(2) - q.powi(2)) - M_z",
];

const XZ: [&str; 3] = [
    "Ixx*p_dot + (Izz - Iyy)*q*r + Ixz*(r_dot + p*q) - M_x",
    "Iyy*q_dot + (Ixx - Izz)*r*p + Izx*(r.powi(2) - p.powi(2)) - M_y",
    "Izz*r_dot + (Iyy - Ixx)*p*q + Izx*(p_dot - q*r) - M_z",
];

const PRINCIPAL: [&str; 3] = [
    "Ixx*p_dot + (Izz - Iyy)*q*r - M_x",
    "Iyy*q_dot + (Ixx - Izz)*r*p - M_y",
    "Izz*r_dot + (Iyy - Ixx)*p*q - M_z",
];

fn rotation_equation(
    number: &'static str,
    book: [&str; 3],
    description: &'static str,
    lhs: &Vec3,
    mirrored: &[Definition],
) -> Equation {
    let moments = Vec3::symbols(["M_x", "M_y", "M_z"]);
    Equation {
        number,
        description,
        components: (0..3)
            .map(|i| Component::new(AXES[i], &lhs.0[i] - &moments.0[i], book[i], mirrored))
            .collect(),
    }
}

/// The equations with the named products of inertia set to zero.
pub fn without_products(lhs: &Vec3, products: &[&str]) -> Result<Vec3, SymbolicError> {
    let zeros: Vec<(&str, Expr)> = products.iter().map(|p| (*p, Expr::zero())).collect();
    lhs.try_map(|e| e.subs_all(&zeros))
}
