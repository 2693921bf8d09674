//! The numbers of the mass matrix: M_RB + M_A evaluated for a parameter set, checked positive
//! definite by Cholesky, and inverted once.
//!
//! The symbolic matrix is the one read off the proved residuals (the coefficients of the
//! accelerations), so the numbers are those of the equations, not of a second formula.

use super::{VehicleError, VehicleSpec, inverse_entry, split};
use crate::derivation::vehicle::VELOCITIES;
use crate::symbolic::Expr;
use std::collections::BTreeMap;

/// The largest |M·M⁻¹ − 𝟙| entry accepted.
const INVERSE_TOLERANCE: f64 = 1e-9;

impl VehicleSpec {
    /// M_RB + M_A in the spec's parameters, read off the proved residuals.
    pub fn mass_matrix(&self) -> Result<[[Expr; 6]; 6], VehicleError> {
        let residuals = self.residuals()?;
        Ok(split("vehicle", &residuals)?.0)
    }

    /// M_RB + M_A for the values given by symbol (`M`, `Ixx`, `x_G`, `Xudot`, …). An
    /// added-mass entry given under both its names must have one value.
    pub fn mass_matrix_values(
        &self,
        values: &BTreeMap<String, f64>,
    ) -> Result<[[f64; 6]; 6], VehicleError> {
        self.check_partners(values)?;
        let matrix = self.mass_matrix()?;
        let mut numbers = [[0.0; 6]; 6];
        for (row, entries) in numbers.iter_mut().zip(&matrix) {
            for (number, entry) in row.iter_mut().zip(entries) {
                *number = evaluate(entry, values)?;
            }
        }
        Ok(numbers)
    }

    fn check_partners(&self, values: &BTreeMap<String, f64>) -> Result<(), VehicleError> {
        let (_, partners) = self.added_mass_entries()?;
        for (first, second) in partners {
            if let (Some(&value), Some(&mirror_value)) = (values.get(&first), values.get(&second))
                && value != mirror_value
            {
                return Err(VehicleError::AsymmetricAddedMass {
                    name: first,
                    value,
                    mirror: second,
                    mirror_value,
                });
            }
        }
        Ok(())
    }

    /// The parameters `minv_uu` … `minv_rr` of the system for the values given: the entries
    /// of (M_RB + M_A)⁻¹ by Cholesky, after checking that the matrix is positive definite
    /// (else the error names the entries of the row that fails) and that M·M⁻¹ = 𝟙 to 1e-9.
    pub fn inverse_mass_matrix(
        &self,
        values: &BTreeMap<String, f64>,
    ) -> Result<Vec<(String, f64)>, VehicleError> {
        let numbers = self.mass_matrix_values(values)?;
        let inverse = match cholesky_inverse(&numbers) {
            Ok(inverse) => inverse,
            Err((row, pivot)) => return Err(self.not_positive_definite(values, row, pivot)?),
        };
        let worst = (0..6)
            .flat_map(|i| (0..6).map(move |j| (i, j)))
            .map(|(i, j)| {
                let product: f64 = (0..6).map(|k| numbers[i][k] * inverse[k][j]).sum();
                (product - f64::from(u8::from(i == j))).abs()
            })
            .fold(0.0, f64::max);
        if worst > INVERSE_TOLERANCE {
            return Err(VehicleError::Unsupported(format!(
                "the mass matrix is too ill-conditioned to invert: |M·M⁻¹ − 1| = {worst:e}"
            )));
        }
        let mut entries = Vec::new();
        for (i, row) in inverse.iter().enumerate() {
            for (j, value) in row.iter().enumerate().skip(i) {
                entries.push((inverse_entry(i, j), *value));
            }
        }
        Ok(entries)
    }

    fn not_positive_definite(
        &self,
        values: &BTreeMap<String, f64>,
        row: usize,
        pivot: f64,
    ) -> Result<VehicleError, VehicleError> {
        let matrix = self.mass_matrix()?;
        let mut named: Vec<String> = Vec::new();
        for entry in &matrix[row][..=row] {
            for symbol in entry.symbols() {
                let text = format!(
                    "{symbol} = {}",
                    values.get(&symbol).copied().unwrap_or(f64::NAN)
                );
                if !named.contains(&text) {
                    named.push(text);
                }
            }
        }
        Ok(VehicleError::NotPositiveDefinite {
            axis: VELOCITIES[row],
            size: row + 1,
            pivot,
            entries: named.join(", "),
        })
    }
}

fn evaluate(entry: &Expr, values: &BTreeMap<String, f64>) -> Result<f64, VehicleError> {
    for symbol in entry.symbols() {
        if !values.get(&symbol).is_some_and(|v| v.is_finite()) {
            return Err(VehicleError::MissingValue(symbol));
        }
    }
    Ok(entry.eval(&|s| values[s]))
}

/// The inverse of a symmetric positive definite matrix by Cholesky, M = LLᵀ,
/// M⁻¹ = L⁻ᵀL⁻¹; or the row whose pivot is not positive, and the pivot.
pub fn cholesky_inverse(m: &[[f64; 6]; 6]) -> Result<[[f64; 6]; 6], (usize, f64)> {
    let mut l = [[0.0; 6]; 6];
    for i in 0..6 {
        for j in 0..=i {
            let sum: f64 = (0..j).map(|k| l[i][k] * l[j][k]).sum();
            if i == j {
                let pivot = m[i][i] - sum;
                if !(pivot > 0.0 && pivot.is_finite()) {
                    return Err((i, pivot));
                }
                l[i][i] = pivot.sqrt();
            } else {
                l[i][j] = (m[i][j] - sum) / l[j][j];
            }
        }
    }
    // L⁻¹, lower triangular, by forward substitution row by row.
    let mut l_inv = [[0.0; 6]; 6];
    for i in 0..6 {
        let row: [f64; 6] = std::array::from_fn(|column| {
            if column > i {
                return 0.0;
            }
            let identity = f64::from(u8::from(i == column));
            let sum: f64 = (column..i).map(|k| l[i][k] * l_inv[k][column]).sum();
            (identity - sum) / l[i][i]
        });
        l_inv[i] = row;
    }
    let mut inverse = [[0.0; 6]; 6];
    for (i, row) in inverse.iter_mut().enumerate() {
        for (j, value) in row.iter_mut().enumerate() {
            *value = (i.max(j)..6).map(|k| l_inv[k][i] * l_inv[k][j]).sum();
        }
    }
    Ok(inverse)
}
