//! Section 4.2: the parallel-axis (Steiner) theorem, 4.23, by substituting r = r_G + r′.

use super::integrate_over_body;
use crate::check::{Component, Equation, definitions};
use crate::symbolic::{Expr, SymbolicError, parse};

/// The tensor about G in second moments of the primed coordinates, `Sxy_G = ∫x′y′ dm`.
const TENSOR_ABOUT_G: [(&str, &str); 6] = [
    ("Ixx_G", "Syy_G + Szz_G"),
    ("Iyy_G", "Szz_G + Sxx_G"),
    ("Izz_G", "Sxx_G + Syy_G"),
    ("Ixy_G", "-Sxy_G"),
    ("Iyz_G", "-Syz_G"),
    ("Izx_G", "-Sxz_G"),
];

/// (component, integrand of 4.13–4.14 about O, the book's 4.23).
const STEINER: [(&str, &str, &str); 6] = [
    ("Ixx", "y*y + z*z", "Ixx_G + M*(y_G.powi(2) + z_G.powi(2))"),
    ("Iyy", "z*z + x*x", "Iyy_G + M*(z_G.powi(2) + x_G.powi(2))"),
    ("Izz", "x*x + y*y", "Izz_G + M*(x_G.powi(2) + y_G.powi(2))"),
    ("Ixy", "-x*y", "Ixy_G - M*x_G*y_G"),
    ("Iyz", "-y*z", "Iyz_G - M*y_G*z_G"),
    ("Izx", "-z*x", "Izx_G - M*z_G*x_G"),
];

pub(super) fn equations() -> Result<Vec<Equation>, SymbolicError> {
    let about_g = definitions(&TENSOR_ABOUT_G)?;
    let components = STEINER
        .iter()
        .map(|(label, integrand, book)| {
            let derived = about_origin(&parse(integrand)?)?;
            Ok(Component::new(*label, derived, *book, &about_g))
        })
        .collect::<Result<_, SymbolicError>>()?;
    Ok(vec![Equation {
        number: "4.23",
        description: "Steiner: tensor about O from the tensor about G, products included",
        components,
    }])
}

/// ∫ f dm with x = x_G + x′ (and so on) substituted, integrated over the primed coordinates.
fn about_origin(integrand: &Expr) -> Result<Expr, SymbolicError> {
    let shifted = integrand.subs_all(&[
        ("x", parse("x_G + xp")?),
        ("y", parse("y_G + yp")?),
        ("z", parse("z_G + zp")?),
    ])?;
    integrate_over_body(&shifted, ["xp", "yp", "zp"], "_G")
}
