//! ∫ f dm over the body, for f a polynomial of degree ≤ 2 in body coordinates about G.
//!
//! The integral is linear, so it acts term by term: a term of degree 0 integrates to M times
//! its coefficient, a term of degree 1 to zero because the origin is the centre of gravity
//! (∫ r dm = 0, 4.6), and a term of degree 2 to a second-moment symbol `Sxy{suffix}` = ∫xy dm.
//! Reading the moments and products of inertia off these symbols is how 4.13–4.14 and 4.23
//! come out of the vector definitions.

use crate::symbolic::{Atom, Expr, Monomial, SymbolicError};

const AXIS_LETTERS: [char; 3] = ['x', 'y', 'z'];

/// Integrates `f` over the body with the origin of `coordinates` at G.
pub fn integrate_over_body(
    f: &Expr,
    coordinates: [&str; 3],
    suffix: &str,
) -> Result<Expr, SymbolicError> {
    let mut integral = Expr::zero();
    for (monomial, coefficient) in f.terms() {
        let (rest, exponents) = split_coordinates(monomial, coordinates);
        let moment = match exponents.iter().sum::<i32>() {
            0 => Expr::symbol("M"),
            1 => Expr::zero(),
            2 if exponents.iter().all(|&e| e >= 0) => second_moment(exponents, suffix),
            _ => return Err(SymbolicError::UnsupportedMoment(monomial.to_string())),
        };
        integral = integral + Expr::term(coefficient.clone(), rest) * moment;
    }
    Ok(integral)
}

fn split_coordinates(monomial: &Monomial, coordinates: [&str; 3]) -> (Monomial, [i32; 3]) {
    let mut rest = monomial.clone();
    let exponents = coordinates.map(|c| {
        let (without, power) = rest.without(&Atom::Symbol(c.to_owned()));
        rest = without;
        power
    });
    (rest, exponents)
}

/// `Sxx`, `Sxy`, … for the exponents of a degree-2 monomial, axes in x-y-z order.
fn second_moment(exponents: [i32; 3], suffix: &str) -> Expr {
    let axes: String = (0..3)
        .flat_map(|i| std::iter::repeat_n(AXIS_LETTERS[i], exponents[i] as usize))
        .collect();
    Expr::symbol(&format!("S{axes}{suffix}"))
}
