//! Solving the proved implicit forms for the accelerations.
//!
//! The proofs are about implicit forms, mass matrix × acceleration + bias = force. The mass
//! matrix depends on parameters only, so it is inverted symbolically as adjugate over
//! determinant; when the determinant is not a monomial (a full or xz-symmetric inertia tensor)
//! its reciprocal becomes a parameter-level symbol computed once. A diagonal mass matrix (a
//! tensor in principal axes) is inverted entry by entry instead. The solution is checked by
//! substituting it back: A·a + rest must vanish once each named symbol is its reciprocal.

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
    /// The reciprocals that had to be named: of the determinant, or of each diagonal entry
    /// that is not a monomial ([`solve_diagonal`]).
    pub reciprocals: Vec<Reciprocal>,
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
        reciprocals: reciprocal.into_iter().collect(),
    };
    verify(model, &matrix, &solution)?;
    Ok(solution)
}

/// Solves `residuals = 0` for the `unknowns` when each residual holds only its own unknown, with
/// a parameter-only coefficient (a diagonal mass matrix: a tensor in principal axes): each
/// unknown is minus the rest of its row over its coefficient. A coefficient that is not a
/// monomial (I_xx + M h²) gets its reciprocal named `names[i]`, computed once, so that the
/// emitted coefficients are 1/(I_xx + M h²) and its multiples rather than cofactors over a
/// determinant.
pub fn solve_diagonal(
    model: &str,
    residuals: &[Expr],
    unknowns: &[&str],
    names: &[&str],
) -> Result<Solution, BuildError> {
    let matrix: Vec<Vec<Expr>> = residuals
        .iter()
        .map(|r| unknowns.iter().map(|u| r.coefficient_of(u)).collect())
        .collect();
    let off_diagonal = matrix
        .iter()
        .enumerate()
        .flat_map(|(i, row)| row.iter().enumerate().filter(move |(j, _)| *j != i))
        .find(|(_, entry)| !entry.is_zero());
    if let Some((_, entry)) = off_diagonal {
        return Err(BuildError::Verification {
            model: model.into(),
            what: "a diagonal solve met an unknown outside its own row".into(),
            residual: entry.to_string(),
        });
    }
    let zeros: Vec<(&str, Expr)> = unknowns.iter().map(|u| (*u, Expr::zero())).collect();
    let rest = residuals
        .iter()
        .map(|r| r.subs_all(&zeros))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|source| BuildError::Symbolic {
            model: model.into(),
            source,
        })?;
    let mut reciprocals = Vec::new();
    let mut inverse = vec![vec![Expr::zero(); unknowns.len()]; unknowns.len()];
    for (i, row) in matrix.iter().enumerate() {
        inverse[i][i] = match row[i].reciprocal() {
            Ok(exact) => exact,
            Err(_) => {
                reciprocals.push(Reciprocal {
                    symbol: names[i].into(),
                    of: row[i].clone(),
                });
                Expr::symbol(names[i])
            }
        };
    }
    let solution = Solution {
        inverse,
        rest,
        reciprocals,
    };
    verify(model, &matrix, &solution)?;
    Ok(solution)
}

/// A·a + rest = 0 with a = −A⁻¹ rest. With a named reciprocal d = 1/x in the solution,
/// A·a + rest is affine in d, A₀ + B d, which vanishes at d = 1/x iff A₀x + B = 0; each named
/// reciprocal is eliminated so in turn, and any other power of it is left in the residual.
fn verify(model: &str, matrix: &[Vec<Expr>], solution: &Solution) -> Result<(), BuildError> {
    let a = solution.accelerations(&solution.rest);
    for (row, rest) in matrix.iter().zip(&solution.rest) {
        let lhs: Expr = row.iter().zip(&a).map(|(m, x)| m * x).sum::<Expr>() + rest;
        let residual = solution.reciprocals.iter().fold(lhs, |lhs, r| {
            let a = lhs.coefficient_of_power(&r.symbol, 0);
            let b = lhs.coefficient_of(&r.symbol);
            let affine = &a + &(&b * &Expr::symbol(&r.symbol));
            &(&a * &r.of + b) + &(&lhs - &affine)
        });
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
