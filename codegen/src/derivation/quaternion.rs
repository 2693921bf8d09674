//! Beyond the chapter: unit-quaternion attitude, singularity-free where Euler angles fail.
//!
//! The quaternion product is defined once; from it come the attitude kinematics
//! q̇ = ½ q ⊗ (0, ω), the rotation of a vector by q (the sandwich q ⊗ (0, v) ⊗ q*), and the
//! quaternion of the Euler angles, q = q_z(ψ) ⊗ q_y(θ) ⊗ q_x(φ). The rotation matrix of that
//! quaternion is proved equal to E of 4.57 symbolically by writing every angle through its
//! half angle (cos φ = cos²(φ/2) − sin²(φ/2), sin φ = 2 sin(φ/2) cos(φ/2)), so that the
//! identity follows from sin² + cos² = 1 alone.

use super::kinematics::{rotation_x_cs, rotation_y_cs, rotation_z_cs};
use crate::check::{Component, Equation};
use crate::symbolic::{Expr, Mat3, SymbolicError, Vec3, parse};

/// A quaternion (w, x, y, z) of expressions, scalar first.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Quaternion(pub [Expr; 4]);

impl Quaternion {
    /// Symbols `q0 q1 q2 q3`.
    pub fn symbols() -> Self {
        Quaternion(["q0", "q1", "q2", "q3"].map(Expr::symbol))
    }

    /// The pure quaternion (0, v).
    pub fn pure(v: &Vec3) -> Self {
        let [x, y, z] = v.0.clone();
        Quaternion([Expr::zero(), x, y, z])
    }

    fn vector(&self) -> Vec3 {
        Vec3::new(self.0[1].clone(), self.0[2].clone(), self.0[3].clone())
    }

    /// The Hamilton product (a₀b₀ − a·b, a₀b + b₀a + a × b).
    pub fn times(&self, other: &Quaternion) -> Quaternion {
        let (a0, b0) = (&self.0[0], &other.0[0]);
        let (a, b) = (self.vector(), other.vector());
        let scalar = a0 * b0 - a.dot(&b);
        let v = b.scale(a0).add(&a.scale(b0)).add(&a.cross(&b));
        let [x, y, z] = v.0;
        Quaternion([scalar, x, y, z])
    }

    /// The conjugate (w, −x, −y, −z).
    pub fn conjugate(&self) -> Quaternion {
        let [w, x, y, z] = self.0.clone();
        Quaternion([w, -x, -y, -z])
    }
}

/// q̇ = ½ q ⊗ (0, ω), with ω = (p, q, r) in body axes.
pub fn quaternion_rates() -> Result<Quaternion, SymbolicError> {
    let half = parse("1/2")?;
    let product = Quaternion::symbols().times(&Quaternion::pure(&Vec3::symbols(["p", "q", "r"])));
    Ok(Quaternion(product.0.map(|e| &e * &half)))
}

/// The rotation of `v` from body to space axes: the vector part of q ⊗ (0, v) ⊗ q*.
pub fn rotate(q: &Quaternion, v: &Vec3) -> Vec3 {
    let rotated = q.times(&Quaternion::pure(v)).times(&q.conjugate());
    rotated.vector()
}

/// cos and sin of an angle written through its half angle `{angle}_h`.
fn double_angle(angle: &str) -> (Expr, Expr) {
    let half = format!("{angle}_h");
    let (c, s) = (Expr::cos(&half), Expr::sin(&half));
    (&c * &c - &s * &s, &(&s * &c) * &Expr::int(2))
}

/// The rotation about one axis by the angle whose half is `{angle}_h`, as a quaternion.
fn axis_quaternion(angle: &str, axis: usize) -> Quaternion {
    let half = format!("{angle}_h");
    let mut parts = [Expr::cos(&half), Expr::zero(), Expr::zero(), Expr::zero()];
    parts[axis + 1] = Expr::sin(&half);
    Quaternion(parts)
}

/// q(φ, θ, ψ) = q_z(ψ) ⊗ q_y(θ) ⊗ q_x(φ), in half-angle atoms.
pub fn quaternion_of_euler_angles() -> Quaternion {
    axis_quaternion("psi", 2)
        .times(&axis_quaternion("theta", 1))
        .times(&axis_quaternion("phi", 0))
}

/// E = Rz(ψ)Ry(θ)Rx(φ) in half-angle atoms.
pub fn body_to_space_half_angles() -> Mat3 {
    let ((cz, sz), (cy, sy), (cx, sx)) = (
        double_angle("psi"),
        double_angle("theta"),
        double_angle("phi"),
    );
    rotation_z_cs(cz, sz)
        .mul_mat(&rotation_y_cs(cy, sy))
        .mul_mat(&rotation_x_cs(cx, sx))
}

/// The matrix of the rotation by q: column j is q ⊗ e_j ⊗ q*.
pub fn rotation_matrix(q: &Quaternion) -> Mat3 {
    let v = Vec3::symbols(["u", "v", "w"]);
    let rotated = rotate(q, &v);
    Mat3::from_fn(|r, c| rotated.0[r].coefficient_of(["u", "v", "w"][c]))
}

pub(super) fn equations() -> Result<Vec<Equation>, SymbolicError> {
    Ok(vec![rates()?, matrix_equals_e()])
}

fn rates() -> Result<Equation, SymbolicError> {
    let derived = quaternion_rates()?;
    let standard = [
        "-(q1*p + q2*q + q3*r)/2",
        "(q0*p + q2*r - q3*q)/2",
        "(q0*q + q3*p - q1*r)/2",
        "(q0*r + q1*q - q2*p)/2",
    ];
    Ok(Equation {
        number: "4.60 q",
        description: "beyond the chapter: quaternion attitude rates q̇ = ½ q ⊗ (0, ω)",
        components: (0..4)
            .map(|i| Component::new(format!("q{i}_dot"), derived.0[i].clone(), standard[i], &[]))
            .collect(),
    })
}

fn matrix_equals_e() -> Equation {
    let from_quaternion = rotation_matrix(&quaternion_of_euler_angles());
    let e = body_to_space_half_angles();
    let components = (0..3)
        .flat_map(|r| (0..3).map(move |c| (r, c)))
        .map(|(r, c)| {
            let difference = &from_quaternion.0[r][c] - &e.0[r][c];
            Component::new(format!("[{},{}]", r + 1, c + 1), difference, "0", &[])
        })
        .collect();
    Equation {
        number: "4.57 q",
        description: "beyond the chapter: the rotation by q(φ, θ, ψ) equals E of 4.57 (half angles)",
        components,
    }
}
