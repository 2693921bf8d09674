//! 3-vectors and 3×3 matrices of expressions: the vector definitions the chapter starts from.
//!
//! Derivations are written with these (ω × r, [I]ω, Rz·Ry·Rx) and never in components, so
//! that each component equation is *computed* and then compared with the book's.

use super::expr::Expr;

/// A column 3-vector of expressions.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Vec3(pub [Expr; 3]);

/// A 3×3 matrix of expressions, row-major: `m.0[row][col]`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mat3(pub [[Expr; 3]; 3]);

impl Vec3 {
    /// A vector of three symbols, e.g. `Vec3::symbols(["p", "q", "r"])`.
    pub fn symbols(names: [&str; 3]) -> Self {
        Vec3(names.map(Expr::symbol))
    }

    /// A vector from three expressions.
    pub fn new(x: Expr, y: Expr, z: Expr) -> Self {
        Vec3([x, y, z])
    }

    /// The zero vector.
    pub fn zero() -> Self {
        Vec3(std::array::from_fn(|_| Expr::zero()))
    }

    /// The scalar product.
    pub fn dot(&self, other: &Vec3) -> Expr {
        (0..3).map(|i| &self.0[i] * &other.0[i]).sum()
    }

    /// The vector product `self × other`.
    pub fn cross(&self, other: &Vec3) -> Vec3 {
        let [a1, a2, a3] = &self.0;
        let [b1, b2, b3] = &other.0;
        Vec3::new(a2 * b3 - a3 * b2, a3 * b1 - a1 * b3, a1 * b2 - a2 * b1)
    }

    /// Component-wise sum.
    pub fn add(&self, other: &Vec3) -> Vec3 {
        Vec3(std::array::from_fn(|i| &self.0[i] + &other.0[i]))
    }

    /// Component-wise difference.
    pub fn sub(&self, other: &Vec3) -> Vec3 {
        Vec3(std::array::from_fn(|i| &self.0[i] - &other.0[i]))
    }

    /// Every component multiplied by a scalar expression.
    pub fn scale(&self, factor: &Expr) -> Vec3 {
        Vec3(std::array::from_fn(|i| &self.0[i] * factor))
    }

    /// Applies a fallible map to each component.
    pub fn try_map(
        &self,
        f: impl Fn(&Expr) -> Result<Expr, super::SymbolicError>,
    ) -> Result<Vec3, super::SymbolicError> {
        let [x, y, z] = &self.0;
        Ok(Vec3::new(f(x)?, f(y)?, f(z)?))
    }
}

impl Mat3 {
    /// A matrix from a row-major function of (row, col).
    pub fn from_fn(f: impl Fn(usize, usize) -> Expr) -> Self {
        Mat3(std::array::from_fn(|r| std::array::from_fn(|c| f(r, c))))
    }

    /// The identity.
    pub fn identity() -> Self {
        Self::from_fn(|r, c| Expr::int(i64::from(r == c)))
    }

    /// A symmetric matrix of symbols given its upper triangle names, row-major.
    pub fn symmetric(names: [[&str; 3]; 3]) -> Self {
        Self::from_fn(|r, c| Expr::symbol(names[r.min(c)][r.max(c)]))
    }

    /// The transpose.
    pub fn transpose(&self) -> Mat3 {
        Self::from_fn(|r, c| self.0[c][r].clone())
    }

    /// Matrix × vector.
    pub fn mul_vec(&self, v: &Vec3) -> Vec3 {
        Vec3(std::array::from_fn(|r| {
            (0..3).map(|k| &self.0[r][k] * &v.0[k]).sum()
        }))
    }

    /// Matrix × matrix.
    pub fn mul_mat(&self, other: &Mat3) -> Mat3 {
        Self::from_fn(|r, c| (0..3).map(|k| &self.0[r][k] * &other.0[k][c]).sum())
    }

    /// The inverse, adj / det, when the determinant is an invertible monomial.
    pub fn inverse(&self) -> Result<Mat3, super::SymbolicError> {
        let rows: Vec<Vec<Expr>> = self.0.iter().map(|row| row.to_vec()).collect();
        let inverse_det = determinant(&rows).reciprocal()?;
        let adjugate = adjugate(&rows);
        Ok(Self::from_fn(|r, c| &adjugate[r][c] * &inverse_det))
    }
}

fn minor(m: &[Vec<Expr>], row: usize, col: usize) -> Vec<Vec<Expr>> {
    m.iter()
        .enumerate()
        .filter(|(r, _)| *r != row)
        .map(|(_, line)| {
            line.iter()
                .enumerate()
                .filter(|(c, _)| *c != col)
                .map(|(_, e)| e.clone())
                .collect()
        })
        .collect()
}

/// The determinant of a square matrix given by rows, by cofactor expansion (the matrices
/// here are at most 3×3).
pub fn determinant(m: &[Vec<Expr>]) -> Expr {
    match m.len() {
        0 => Expr::int(1),
        1 => m[0][0].clone(),
        _ => (0..m.len())
            .map(|c| {
                let term = &m[0][c] * &determinant(&minor(m, 0, c));
                if c % 2 == 0 { term } else { -term }
            })
            .sum(),
    }
}

/// The adjugate (transposed cofactor matrix) of a square matrix given by rows.
pub fn adjugate(m: &[Vec<Expr>]) -> Vec<Vec<Expr>> {
    let n = m.len();
    (0..n)
        .map(|r| {
            (0..n)
                .map(|c| {
                    let cofactor = determinant(&minor(m, c, r));
                    if (r + c) % 2 == 0 {
                        cofactor
                    } else {
                        -cofactor
                    }
                })
                .collect()
        })
        .collect()
}
