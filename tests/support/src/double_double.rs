//! Double-double arithmetic: a number is an unevaluated sum hi + lo of two f64 with
//! |lo| ≤ ulp(hi)/2, about 106 bits, enough to stand for the exact value of an f64 formula
//! when judging the f64 evaluation (Dekker 1971; the algorithms of Hida, Li & Bailey's QD).
//! Each operation is accurate to a few units of 2⁻¹⁰⁴ relative, so a 3×3 solve with
//! cond([I]) = 10⁶ is exact to about 10⁻²⁵, nine orders below the f64 errors it judges.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// hi + lo, normalised so that hi = fl(hi + lo).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dd {
    pub hi: f64,
    pub lo: f64,
}

/// a + b = s + e exactly (Knuth), for any a, b.
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// a + b = s + e exactly, for |a| ≥ |b|.
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// a · b = p + e exactly, by the fused multiply–add.
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl Dd {
    /// The exact value of an f64.
    pub fn new(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }

    fn normalised(hi: f64, lo: f64) -> Self {
        let (hi, lo) = quick_two_sum(hi, lo);
        Self { hi, lo }
    }

    /// The nearest f64 (to within one rounding of the f64 result).
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    /// |self|, exactly.
    pub fn abs(self) -> Self {
        if self.hi < 0.0 { -self } else { self }
    }
}

impl From<f64> for Dd {
    fn from(x: f64) -> Self {
        Self::new(x)
    }
}

impl Add for Dd {
    type Output = Dd;
    fn add(self, b: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, b.hi);
        let (t, f) = two_sum(self.lo, b.lo);
        let (s, e) = quick_two_sum(s, e + t);
        Dd::normalised(s, e + f)
    }
}

impl Neg for Dd {
    type Output = Dd;
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Sub for Dd {
    type Output = Dd;
    fn sub(self, b: Dd) -> Dd {
        self + (-b)
    }
}

impl Mul for Dd {
    type Output = Dd;
    fn mul(self, b: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, b.hi);
        Dd::normalised(p, e + (self.hi * b.lo + self.lo * b.hi))
    }
}

impl Div for Dd {
    type Output = Dd;
    fn div(self, b: Dd) -> Dd {
        // Long division: three quotient digits, each from the remainder of the last.
        let q1 = self.hi / b.hi;
        let r = self - b * Dd::new(q1);
        let q2 = r.hi / b.hi;
        let r = r - b * Dd::new(q2);
        let q3 = r.hi / b.hi;
        let (q1, q2) = quick_two_sum(q1, q2);
        Dd { hi: q1, lo: q2 } + Dd::new(q3)
    }
}

/// A 3-vector of double-doubles.
pub type Vec3 = [Dd; 3];

/// The f64 vector, exactly.
pub fn vec3(v: [f64; 3]) -> Vec3 {
    v.map(Dd::new)
}

pub fn cross(a: &Vec3, b: &Vec3) -> Vec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// m v for a 3×3 matrix given by rows.
pub fn mul(m: &[Vec3; 3], v: &Vec3) -> Vec3 {
    m.map(|row| row[0] * v[0] + row[1] * v[1] + row[2] * v[2])
}

/// The solution x of m x = b by Cramer's rule: adj(m) b / det(m), every product in
/// double-double (exact to ~cond(m) · 2⁻¹⁰⁴).
pub fn solve(m: &[Vec3; 3], b: &Vec3) -> Vec3 {
    let cofactor = |r: usize, c: usize| {
        let (r1, r2, c1, c2) = ((r + 1) % 3, (r + 2) % 3, (c + 1) % 3, (c + 2) % 3);
        m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]
    };
    let det = m[0][0] * cofactor(0, 0) + m[0][1] * cofactor(0, 1) + m[0][2] * cofactor(0, 2);
    // adj(m)[i][j] = cofactor(j, i)
    [0, 1, 2].map(|i| (cofactor(0, i) * b[0] + cofactor(1, i) * b[1] + cofactor(2, i) * b[2]) / det)
}

/// Euler's equations 4.51 with no applied moment, solved for ω̇ in double-double:
/// [I] ω̇ = −ω × [I] ω, from the f64 entries of [I] and ω taken as exact.
pub fn euler_rates(inertia: &[[f64; 3]; 3], omega: [f64; 3]) -> [f64; 3] {
    let m = inertia.map(vec3);
    let w = vec3(omega);
    let h = mul(&m, &w);
    let b = cross(&h, &w); // −ω × H = H × ω
    solve(&m, &b).map(Dd::to_f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn double_double_carries_what_f64_drops() {
        // (1 + 2⁻⁶⁰) − 1 is lost in f64 and kept here; 1/3 · 3 comes back to 1 to 2⁻¹⁰⁰.
        let tiny = 2f64.powi(-60);
        let sum = Dd::new(1.0) + Dd::new(tiny) - Dd::new(1.0);
        assert_eq!(sum.to_f64(), tiny);
        let third = Dd::new(1.0) / Dd::new(3.0);
        let back = third * Dd::new(3.0) - Dd::new(1.0);
        assert!(back.to_f64().abs() < 2f64.powi(-100), "{back:?}");
        // A product whose f64 rounding error the fused multiply-add recovers exactly.
        let a = 1.0 + 2f64.powi(-30);
        let square = Dd::new(a) * Dd::new(a);
        assert_eq!(
            (square.hi, square.lo),
            (1.0 + 2f64.powi(-29), 2f64.powi(-60))
        );
    }

    #[test]
    fn the_solve_inverts_an_ill_conditioned_matrix() {
        // m = diag(1e-6, 1, 1) turned about (1, 1, 1): the solve of m x = m e returns e to
        // far better than f64 could (cond 10⁶).
        let c = 1.0 / 3.0;
        let m = [[c + 1e-6, c, c], [c, c + 1.0, c], [c, c, c + 1.0]].map(vec3);
        let e = vec3([0.3, -0.7, 1.1]);
        let x = solve(&m, &mul(&m, &e));
        for (xi, ei) in x.iter().zip(&e) {
            assert!((*xi - *ei).to_f64().abs() < 1e-24, "{xi:?} vs {ei:?}");
        }
    }
}
