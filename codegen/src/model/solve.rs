//! Solving the proved implicit forms for the accelerations.
//!
//! The proofs are about implicit forms, mass matrix × acceleration + bias = force. The mass
//! matrix depends on parameters only, so it is inverted symbolically as adjugate over
//! determinant; when the determinant is not a monomial (a full or xz-symmetric inertia tensor)
//! its reciprocal becomes a parameter-level symbol computed once. The solution is checked by
//! substituting it back: A·a + rest must vanish once that symbol is 1/det.

use super::system::{BuildError, Reciprocal};
use crate::symbolic::{Expr, adjugate, determinant};

/// The solved accelerations `a = −A⁻¹ rest`, as the inverse entries and the rest terms, so
/// that callers may expand the product or stage the rest terms.
#[derive(Debug, Clone)]
pub struct Solution {
    /// Entries of A⁻¹ as parameter expressions, row-major.
    pub inverse: Vec<Vec<Expr>>,
    /// The residuals with the accelerations set to zero.
    pub rest: Vec<Expr>,
    /// The reciprocal of the determinant, if it had to be named.
    pub reciprocal: Option<Reciprocal>,
}

impl Solution {
    /// a_i = −Σ_j inverse_ij · rest_j, with `rest` given (as expressions or stage symbols).
    pub fn accelerations(&self, rest: &[Expr]) -> Vec<Expr> {
        self.inverse
            .iter()
            .map(|row| -row.iter().zip(rest).map(|(a, b)| a * b).sum::<Expr>())
            .collect()
    }
}

/// Solves `residuals = 0` for the `unknowns`, which must enter linearly with parameter-only
/// coefficients.
pub fn solve_linear(
    model: &str,
    residuals: &[Expr],
    unknowns: &[&str],
    reciprocal_name: &str,
) -> Result<Solution, BuildError> {
    let symbolic = |source| BuildError::Symbolic {
        model: model.into(),
        source,
    };
    let matrix: Vec<Vec<Expr>> = residuals
        .iter()
        .map(|r| unknowns.iter().map(|u| r.coefficient_of(u)).collect())
        .collect();
    let zeros: Vec<(&str, Expr)> = unknowns.iter().map(|u| (*u, Expr::zero())).collect();
    let rest = residuals
        .iter()
        .map(|r| r.subs_all(&zeros))
        .collect::<Result<Vec<_>, _>>()
        .map_err(symbolic)?;
    let det = determinant(&matrix);
    let (inverse_det, reciprocal) = match det.reciprocal() {
        Ok(inverse) => (inverse, None),
        Err(_) => {
            let named = Reciprocal {
                symbol: reciprocal_name.into(),
                of: det.clone(),
            };
            (Expr::symbol(reciprocal_name), Some(named))
        }
    };
    let adjugate = adjugate(&matrix);
    let inverse = adjugate
        .iter()
        .map(|row| row.iter().map(|e| e * &inverse_det).collect())
        .collect();
    let solution = Solution {
        inverse,
        rest,
        reciprocal,
    };
    verify(model, &matrix, &det, &solution)?;
    Ok(solution)
}

/// A·a + rest = 0 with a = −A⁻¹ rest: with 1/det named d, A·a + rest = (1 − det·d)·rest, so
/// det·(A·a + rest) evaluated with d's coefficient must cancel.
fn verify(
    model: &str,
    matrix: &[Vec<Expr>],
    det: &Expr,
    solution: &Solution,
) -> Result<(), BuildError> {
    let a = solution.accelerations(&solution.rest);
    for (row, rest) in matrix.iter().zip(&solution.rest) {
        let lhs: Expr = row.iter().zip(&a).map(|(m, x)| m * x).sum::<Expr>() + rest;
        let residual = match &solution.reciprocal {
            None => lhs,
            Some(r) => {
                // lhs is affine in d = 1/det, A + B d, which vanishes at d = 1/det iff
                // A det + B = 0; any other power of d is left in the residual.
                let a = lhs.coefficient_of_power(&r.symbol, 0);
                let b = lhs.coefficient_of(&r.symbol);
                let affine = &a + &(&b * &Expr::symbol(&r.symbol));
                &(&a * det + b) + &(&lhs - &affine)
            }
        };
        if !residual.is_zero() {
            return Err(BuildError::Verification {
                model: model.into(),
                what: "the solved accelerations do not satisfy the proved equations".into(),
                residual: residual.to_string(),
            });
        }
    }
    Ok(())
}
