//! The inertia tensor in the chapter's convention, and the checks that make it physical.
//!
//! The chapter (4.12–4.14) puts the minus sign *inside* the products of inertia:
//! `Ixy = −∫xy dm`, so that `H = [I] ω` with `[I]` holding `Ixy` itself off the diagonal.
//! Every tensor `eom` accepts passes through [`InertiaTensor::new`] or
//! [`InertiaTensor::from_matrix`], which refuse a tensor that no rigid body can have.

use crate::ParameterError;
use crate::Short;
use crate::validate::finite;
use nalgebra::{Matrix3, SymmetricEigen};
use thiserror::Error;

/// Why a tensor is not the inertia tensor of any rigid body.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum InertiaError {
    /// A component is NaN or infinite (the error names it, e.g. `"Ixy"`).
    #[error("inertia component {0}")]
    NotFinite(ParameterError),
    /// A component so large that the checks' sums overflow f64 (the tensor of a body in
    /// units too small for it): named as overflow, not as the inequality it would fail.
    #[error(
        "inertia component {name} = {} is too large to check in f64: the sums of moments that \
         4.13 and 4.23 need overflow beyond {}; give the tensor in larger units (t m², not kg m²)",
        Short(*value),
        Short(f64::MAX)
    )]
    Overflow {
        /// The largest component.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// The matrix differs from its transpose.
    #[error("inertia tensor is not symmetric: {upper} = {} but {lower} = {}", Short(*a), Short(*b))]
    NotSymmetric {
        /// The upper-triangle component.
        upper: &'static str,
        /// The mirrored component.
        lower: &'static str,
        /// Value of `upper`.
        a: f64,
        /// Value of `lower`.
        b: f64,
    },
    /// Some rotation has zero or negative moment: the smallest eigenvalue is not positive.
    #[error("inertia tensor is not positive definite (smallest principal moment {})", Short(*smallest))]
    NotPositiveDefinite {
        /// The smallest eigenvalue.
        smallest: f64,
    },
    /// A moment exceeds the sum of the other two (4.13 gives `Ixx + Iyy − Izz = 2∫z² dm ≥ 0`).
    #[error("triangle inequality fails: {a} + {b} = {} < {c} = {}", Short(*sum), Short(*value))]
    TriangleInequality {
        /// First of the two smaller moments.
        a: &'static str,
        /// Second of the two smaller moments.
        b: &'static str,
        /// The moment that is too large.
        c: &'static str,
        /// `a + b`.
        sum: f64,
        /// The value of `c`.
        value: f64,
    },
    /// The second-moment matrix `∫ r rᵀ dm = ½ tr[I] 𝟙 − [I]` has a negative eigenvalue: the
    /// products of inertia are too large for the moments (checked in principal axes).
    #[error(
        "products of inertia are too large for the moments: ∫r rᵀdm has eigenvalue {}",
        Short(*smallest)
    )]
    SecondMomentNotPositive {
        /// The smallest eigenvalue of the second-moment matrix.
        smallest: f64,
    },
}

/// Relative slack allowed in the inequalities, for tensors computed in floating point: a flat
/// plate satisfies `Ixx + Iyy = Izz` exactly, and its computed tensor may miss by a few ulps.
const SLACK: f64 = 1e-12;

/// A validated inertia tensor about some point, in body axes, chapter convention (4.12–4.14).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InertiaTensor {
    matrix: Matrix3<f64>,
}

const NAMES: [[&str; 3]; 3] = [
    ["Ixx", "Ixy", "Ixz"],
    ["Iyx", "Iyy", "Iyz"],
    ["Izx", "Izy", "Izz"],
];

impl InertiaTensor {
    /// Builds the tensor from its six independent components (products with the sign of 4.14).
    ///
    /// ```
    /// use eom::InertiaTensor;
    /// let box_tensor = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.0).unwrap();
    /// assert_eq!(box_tensor.matrix()[(2, 2)], 4.0);
    /// assert!(InertiaTensor::new(1.0, 1.0, 3.0, 0.0, 0.0, 0.0).is_err()); // 1 + 1 < 3
    /// ```
    pub fn new(
        ixx: f64,
        iyy: f64,
        izz: f64,
        ixy: f64,
        iyz: f64,
        izx: f64,
    ) -> Result<Self, InertiaError> {
        let matrix = Matrix3::new(ixx, ixy, izx, ixy, iyy, iyz, izx, iyz, izz);
        Self::from_matrix(matrix)
    }

    /// Builds the tensor from a full matrix laid out as 4.12 writes it.
    pub fn from_matrix(matrix: Matrix3<f64>) -> Result<Self, InertiaError> {
        check_finite(&matrix)?;
        check_range(&matrix)?;
        check_symmetric(&matrix)?;
        check_positive_definite(&matrix)?;
        check_triangle(&matrix)?;
        check_second_moments(&matrix)?;
        Ok(Self { matrix })
    }

    /// The matrix `[I]` of 4.12.
    pub fn matrix(&self) -> Matrix3<f64> {
        self.matrix
    }

    /// Moment about x, `Ixx`.
    pub fn ixx(&self) -> f64 {
        self.matrix[(0, 0)]
    }
    /// Moment about y, `Iyy`.
    pub fn iyy(&self) -> f64 {
        self.matrix[(1, 1)]
    }
    /// Moment about z, `Izz`.
    pub fn izz(&self) -> f64 {
        self.matrix[(2, 2)]
    }
    /// Product `Ixy = −∫xy dm`.
    pub fn ixy(&self) -> f64 {
        self.matrix[(0, 1)]
    }
    /// Product `Iyz = −∫yz dm`.
    pub fn iyz(&self) -> f64 {
        self.matrix[(1, 2)]
    }
    /// Product `Izx = −∫zx dm`.
    pub fn izx(&self) -> f64 {
        self.matrix[(2, 0)]
    }

    /// Principal moments (ascending) and the axes as columns, from nalgebra's symmetric
    /// eigendecomposition.
    pub fn principal(&self) -> (nalgebra::Vector3<f64>, Matrix3<f64>) {
        let eigen = SymmetricEigen::new(self.matrix);
        let mut order = [0usize, 1, 2];
        order.sort_by(|&i, &j| eigen.eigenvalues[i].total_cmp(&eigen.eigenvalues[j]));
        let moments = nalgebra::Vector3::from_fn(|i, _| eigen.eigenvalues[order[i]]);
        let axes = Matrix3::from_fn(|r, c| eigen.eigenvectors[(r, order[c])]);
        (moments, axes)
    }
}

fn check_finite(m: &Matrix3<f64>) -> Result<(), InertiaError> {
    for r in 0..3 {
        for c in 0..3 {
            finite(NAMES[r][c], m[(r, c)]).map_err(InertiaError::NotFinite)?;
        }
    }
    Ok(())
}

/// The checks add up to three moments and the eigen-solver squares them; beyond f64::MAX/8
/// (~2e307) their sums overflow and a sound tensor would be refused for the wrong reason.
fn check_range(m: &Matrix3<f64>) -> Result<(), InertiaError> {
    let (row, column) = m.iamax_full();
    let value = m[(row, column)];
    match (8.0 * value.abs()).is_finite() {
        true => Ok(()),
        false => Err(InertiaError::Overflow {
            name: NAMES[row][column],
            value,
        }),
    }
}

fn check_symmetric(m: &Matrix3<f64>) -> Result<(), InertiaError> {
    let scale = m.diagonal().abs().max();
    for (r, c) in [(0, 1), (1, 2), (0, 2)] {
        let (a, b) = (m[(r, c)], m[(c, r)]);
        if (a - b).abs() > SLACK * scale {
            return Err(InertiaError::NotSymmetric {
                upper: NAMES[r][c],
                lower: NAMES[c][r],
                a,
                b,
            });
        }
    }
    Ok(())
}

fn check_triangle(m: &Matrix3<f64>) -> Result<(), InertiaError> {
    let d = [m[(0, 0)], m[(1, 1)], m[(2, 2)]];
    for (a, b, c) in [(0, 1, 2), (1, 2, 0), (2, 0, 1)] {
        let sum = d[a] + d[b];
        if sum < d[c] - SLACK * (d[0].abs() + d[1].abs() + d[2].abs()) {
            return Err(InertiaError::TriangleInequality {
                a: NAMES[a][a],
                b: NAMES[b][b],
                c: NAMES[c][c],
                sum,
                value: d[c],
            });
        }
    }
    Ok(())
}

fn check_positive_definite(m: &Matrix3<f64>) -> Result<(), InertiaError> {
    let smallest = SymmetricEigen::new(*m).eigenvalues.min();
    if smallest > 0.0 {
        Ok(())
    } else {
        Err(InertiaError::NotPositiveDefinite { smallest })
    }
}

fn check_second_moments(m: &Matrix3<f64>) -> Result<(), InertiaError> {
    let second = Matrix3::identity() * (0.5 * m.trace()) - m;
    let smallest = SymmetricEigen::new(second).eigenvalues.min();
    if smallest >= -SLACK * m.trace() {
        Ok(())
    } else {
        Err(InertiaError::SecondMomentNotPositive { smallest })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_box_is_accepted() {
        // Box 1 × 2 × 3, mass 12: Ixx = 13, Iyy = 10, Izz = 5 (4.20–4.21).
        assert!(InertiaTensor::new(13.0, 10.0, 5.0, 0.0, 0.0, 0.0).is_ok());
    }

    #[test]
    fn flat_plate_on_the_triangle_boundary_is_accepted() {
        assert!(InertiaTensor::new(1.0, 2.0, 3.0, 0.0, 0.0, 0.0).is_ok());
    }

    #[test]
    fn nan_component_is_named() {
        let err = InertiaTensor::new(1.0, 1.0, 1.0, f64::NAN, 0.0, 0.0).unwrap_err();
        assert!(matches!(err, InertiaError::NotFinite(ref e) if e.field == "Ixy"));
        assert_eq!(
            err.to_string(),
            "inertia component Ixy must be finite, got NaN"
        );
    }

    #[test]
    fn asymmetric_matrix_is_refused() {
        let m = Matrix3::new(2.0, 0.1, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 2.0);
        let err = InertiaTensor::from_matrix(m).unwrap_err();
        assert!(matches!(
            err,
            InertiaError::NotSymmetric { upper: "Ixy", .. }
        ));
    }

    #[test]
    fn triangle_violation_names_the_large_moment() {
        let err = InertiaTensor::new(1.0, 1.0, 3.0, 0.0, 0.0, 0.0).unwrap_err();
        assert!(matches!(
            err,
            InertiaError::TriangleInequality { c: "Izz", .. }
        ));
    }

    #[test]
    fn negative_moment_is_refused() {
        let err = InertiaTensor::new(-1.0, 2.0, 2.0, 0.0, 0.0, 0.0).unwrap_err();
        assert!(matches!(err, InertiaError::NotPositiveDefinite { .. }));
    }

    #[test]
    fn oversized_product_is_refused() {
        // Moments 2, 2, 2 with Ixy = 1.5: positive definite (eigenvalues 0.5, 2, 3.5) but the
        // second-moment matrix ½tr − I has eigenvalue 3 − 3.5 < 0: no mass distribution has it.
        let err = InertiaTensor::new(2.0, 2.0, 2.0, 1.5, 0.0, 0.0).unwrap_err();
        assert!(matches!(err, InertiaError::SecondMomentNotPositive { .. }));
    }

    #[test]
    fn principal_moments_of_a_rotated_tensor() {
        let t = InertiaTensor::new(3.0, 3.0, 4.0, -1.0, 0.0, 0.0).unwrap();
        let (moments, axes) = t.principal();
        assert!(
            (moments - nalgebra::Vector3::new(2.0, 4.0, 4.0))
                .abs()
                .max()
                < 1e-12
        );
        let back = axes * Matrix3::from_diagonal(&moments) * axes.transpose();
        assert!((back - t.matrix()).abs().max() < 1e-12);
    }
}
