//! Section 4.2: the parallel-axis (Steiner) theorem, 4.23, by substituting r = r_G + r′.

use super::integrate_over_body;
use crate::check::{Component, Equation, definitions};
use crate::symbolic::{Expr, Mat3, SymbolicError, parse};

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
        .collect::<Result<Vec<_>, SymbolicError>>()?;
    let components = components
        .into_iter()
        .chain(in_the_tensor_about_g()?)
        .collect();
    Ok(vec![Equation {
        number: "4.23",
        description: "Steiner: tensor about O from the tensor about G, products included",
        components,
    }])
}

/// The same entries from [`tensor_about_origin`], which speaks of the tensor about G itself.
fn in_the_tensor_about_g() -> Result<Vec<Component>, SymbolicError> {
    let tensor = tensor_about_origin()?;
    let at = [(0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (2, 0)];
    Ok(STEINER
        .iter()
        .zip(at)
        .map(|((label, _, book), (r, c))| {
            let label = format!("{label} from [I_G]");
            Component::new(label, tensor.0[r][c].clone(), *book, &[])
        })
        .collect())
}

/// 4.13–4.14 read backwards: the second moments about G from the tensor about G,
/// `∫x′² dm = (I_yy + I_zz − I_xx)/2`, `∫x′y′ dm = −I_xy`, and cyclically.
const SECOND_MOMENTS_ABOUT_G: [(&str, &str); 6] = [
    ("Sxx_G", "(Iyy_G + Izz_G - Ixx_G)/2"),
    ("Syy_G", "(Izz_G + Ixx_G - Iyy_G)/2"),
    ("Szz_G", "(Ixx_G + Iyy_G - Izz_G)/2"),
    ("Sxy_G", "-Ixy_G"),
    ("Syz_G", "-Iyz_G"),
    ("Sxz_G", "-Izx_G"),
];

/// The tensor about O of a body whose tensor about G is `Ixx_G … Izx_G` and whose G is at
/// `r_G = (x_G, y_G, z_G)` from O: 4.23 computed, not copied. Each entry is the integral of
/// 4.13–4.14 about O with r = r_G + r′ substituted, and the second moments about G that it
/// leaves are traded for the tensor about G (4.13–4.14 read backwards).
pub fn tensor_about_origin() -> Result<Mat3, SymbolicError> {
    let second_moments = definitions(&SECOND_MOMENTS_ABOUT_G)?;
    let pairs: Vec<(&str, Expr)> = second_moments
        .iter()
        .map(|(symbol, value)| (symbol.as_str(), value.clone()))
        .collect();
    let entry = |label: &str| -> Result<Expr, SymbolicError> {
        let (_, integrand, _) = STEINER
            .iter()
            .find(|(l, _, _)| *l == label)
            .expect("every entry of the tensor is listed");
        about_origin(&parse(integrand)?)?.subs_all(&pairs)
    };
    let [xx, yy, zz] = [entry("Ixx")?, entry("Iyy")?, entry("Izz")?];
    let [xy, yz, zx] = [entry("Ixy")?, entry("Iyz")?, entry("Izx")?];
    Ok(Mat3([
        [xx, xy.clone(), zx.clone()],
        [xy, yy, yz.clone()],
        [zx, yz, zz],
    ]))
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
