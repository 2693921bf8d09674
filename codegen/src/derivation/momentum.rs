//! Section 4.1: angular momentum about G, from ∫ r × (ω × r) dm (4.7–4.15).

use super::{AXES, integrate_over_body, omega};
use crate::check::{Component, Equation, definitions};
use crate::symbolic::{SymbolicError, Vec3};

/// The moments (4.13) and products (4.14) of inertia as second moments `Sxy = ∫xy dm`.
/// The book writes `Iyx`, `Izx`, `Izy` too; 4.14 says each equals its mirror.
pub const TENSOR_IN_SECOND_MOMENTS: [(&str, &str); 9] = [
    ("Ixx", "Syy + Szz"),
    ("Iyy", "Szz + Sxx"),
    ("Izz", "Sxx + Syy"),
    ("Ixy", "-Sxy"),
    ("Iyx", "-Sxy"),
    ("Iyz", "-Syz"),
    ("Izy", "-Syz"),
    ("Izx", "-Sxz"),
    ("Ixz", "-Sxz"),
];

fn position() -> Vec3 {
    Vec3::symbols(["x", "y", "z"])
}

/// H_G = ∫ r × (ω × r) dm (4.7), as a vector in second moments.
pub fn angular_momentum() -> Result<Vec3, SymbolicError> {
    let r = position();
    r.cross(&omega().cross(&r))
        .try_map(|f| integrate_over_body(f, ["x", "y", "z"], ""))
}

pub(super) fn equations() -> Result<Vec<Equation>, SymbolicError> {
    Ok(vec![
        omega_cross_r(),
        r_cross_omega_cross_r(),
        tensor_form()?,
        moments()?,
        products()?,
    ])
}

fn omega_cross_r() -> Equation {
    let derived = omega().cross(&position());
    let book = ["q*z - r*y", "r*x - p*z", "p*y - q*x"];
    Equation {
        number: "4.9",
        description: "ω × r in components",
        components: components(&derived, book),
    }
}

fn r_cross_omega_cross_r() -> Equation {
    let r = position();
    let derived = r.cross(&omega().cross(&r));
    let book = [
        "y*(p*y - q*x) - z*(r*x - p*z)",
        "z*(q*z - r*y) - x*(p*y - q*x)",
        "x*(r*x - p*z) - y*(q*z - r*y)",
    ];
    Equation {
        number: "4.10",
        description: "r × (ω × r) in components",
        components: components(&derived, book),
    }
}

fn components(derived: &Vec3, book: [&str; 3]) -> Vec<Component> {
    (0..3)
        .map(|i| Component::new(AXES[i], derived.0[i].clone(), book[i], &[]))
        .collect()
}

fn tensor_form() -> Result<Equation, SymbolicError> {
    let h = angular_momentum()?;
    let tensor = definitions(&TENSOR_IN_SECOND_MOMENTS)?;
    let book = [
        "Ixx*p + Ixy*q + Ixz*r",
        "Iyx*p + Iyy*q + Iyz*r",
        "Izx*p + Izy*q + Izz*r",
    ];
    let components = (0..3)
        .map(|i| Component::new(format!("H_{}", AXES[i]), h.0[i].clone(), book[i], &tensor))
        .collect();
    Ok(Equation {
        number: "4.12",
        description: "H_G = [I]ω: ∫ r×(ω×r) dm is linear in ω with the tensor of 4.13–4.14",
        components,
    })
}

/// The entry of [I] read off H as the coefficient of one rate: ∂H_row/∂ω_col.
fn entry(h: &Vec3, row: usize, col: usize) -> crate::symbolic::Expr {
    h.0[row].coefficient_of(["p", "q", "r"][col])
}

fn read_off(entries: &[(usize, usize)]) -> Result<Vec<Component>, SymbolicError> {
    let h = angular_momentum()?;
    Ok(entries
        .iter()
        .map(|&(row, col)| {
            let name = format!("I{}{}", AXES[row], AXES[col]);
            let book = TENSOR_IN_SECOND_MOMENTS
                .iter()
                .find(|(n, _)| *n == name)
                .map_or("", |(_, text)| *text);
            Component::new(name, entry(&h, row, col), book, &[])
        })
        .collect())
}

fn moments() -> Result<Equation, SymbolicError> {
    Ok(Equation {
        number: "4.13",
        description: "moments of inertia, read off H as the coefficients of p, q, r",
        components: read_off(&[(0, 0), (1, 1), (2, 2)])?,
    })
}

fn products() -> Result<Equation, SymbolicError> {
    Ok(Equation {
        number: "4.14",
        description: "products of inertia (minus sign inside), read off H",
        components: read_off(&[(0, 1), (1, 0), (1, 2), (2, 1), (2, 0), (0, 2)])?,
    })
}
