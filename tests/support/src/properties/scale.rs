//! The size of the terms of every output of every model: the formula evaluated with the
//! absolute value of each factor, which the rounding error of any evaluation order stays below
//! to first order.

use super::cases::{Kinematics, PendulumCase, PlanarCase, SpatialCase};
use nalgebra::{Matrix3, Quaternion, Rotation3, Vector3};

/// The largest |a − b| / scale over the entries; an entry with zero scale must agree exactly.
pub fn relative_gap(a: &[f64], b: &[f64], scale: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    assert_eq!(a.len(), scale.len());
    a.iter()
        .zip(b)
        .zip(scale)
        .map(|((x, y), s)| match (x - y).abs() {
            0.0 => 0.0,
            gap if *s > 0.0 => gap / s,
            _ => f64::INFINITY,
        })
        .fold(0.0, f64::max)
}

/// For non-negative vectors: the cross product with every term added, |a_y b_z| + |a_z b_y|, ….
pub fn cross_abs(a: &Vector3<f64>, b: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(
        a.y * b.z + a.z * b.y,
        a.z * b.x + a.x * b.z,
        a.x * b.y + a.y * b.x,
    )
}

/// The size of the terms of [I]⁻¹ = adj[I] / det[I], entry by entry.
pub struct InverseScale {
    /// |[I]⁻¹| itself: what an evaluation with exact coefficients multiplies (the f32 models,
    /// whose coefficients are computed in f64 and rounded once).
    pub value: Matrix3<f64>,
    /// The terms of computing it in f64: each cofactor's two products over |det|, plus the
    /// cofactor times the terms of the determinant over det². The second part is the
    /// conditioning of the tensor: for the rotated rod (1, 10⁶, 10⁶) the determinant's terms
    /// are 10⁶ times the determinant, and any two f64 inverses differ by about 10⁶ ε.
    pub terms: Matrix3<f64>,
}

/// The term sizes of the inverse of a symmetric 3×3 matrix, computed by cofactors.
pub fn inverse_scale(i: &Matrix3<f64>) -> InverseScale {
    let cofactor = |r: usize, c: usize| {
        let (r1, r2, c1, c2) = ((r + 1) % 3, (r + 2) % 3, (c + 1) % 3, (c + 2) % 3);
        let (a, b) = (i[(r1, c1)] * i[(r2, c2)], i[(r1, c2)] * i[(r2, c1)]);
        (a - b, a.abs() + b.abs())
    };
    let signed = Matrix3::from_fn(|r, c| cofactor(c, r).0);
    let absolute = Matrix3::from_fn(|r, c| cofactor(c, r).1);
    let det = (0..3)
        .map(|c| i[(0, c)] * signed[(c, 0)])
        .sum::<f64>()
        .abs();
    let det_terms = (0..3)
        .map(|c| i[(0, c)].abs() * absolute[(c, 0)])
        .sum::<f64>();
    InverseScale {
        value: signed.abs() / det,
        terms: absolute / det + signed.abs() * (det_terms / (det * det)),
    }
}

/// The term size of each output of a spatial model at the case, given the term sizes of [I]⁻¹.
pub fn spatial_scale(
    case: &SpatialCase,
    kinematics: Kinematics,
    inverse: &Matrix3<f64>,
) -> Vec<f64> {
    let (v, w) = (case.velocity.abs(), case.omega.abs());
    let inertia = case.tensor.matrix().abs();
    // 4.49: F/M − ω × v.
    let translation = case.force.abs() / case.mass + cross_abs(&w, &v);
    // 4.51: [I]⁻¹ (M − ω × [I]ω).
    let bracket = case.moment.abs() + cross_abs(&w, &(inertia * w));
    let rotation = inverse * bracket;
    let mut scale: Vec<f64> = translation.iter().chain(rotation.iter()).copied().collect();
    match kinematics {
        Kinematics::Euler => scale.extend(euler_kinematics_scale(&case.euler, &v, &w)),
        Kinematics::Quaternion => {
            let q = case.quaternion.quaternion();
            scale.extend(quaternion_kinematics_scale(q, &v, &w));
        }
    }
    scale
}

/// Terms of E v (4.57, E = Rz Ry Rx multiplied out with absolute values) and of 4.60, where
/// tan θ and sec θ make every term of φ̇ and ψ̇ as large as 1/|cos θ|.
fn euler_kinematics_scale(euler: &Vector3<f64>, v: &Vector3<f64>, w: &Vector3<f64>) -> Vec<f64> {
    let turn = |axis, angle| Rotation3::from_axis_angle(&axis, angle).into_inner().abs();
    let (phi, theta, psi) = (euler.x, euler.y, euler.z);
    let e = turn(Vector3::z_axis(), psi)
        * turn(Vector3::y_axis(), theta)
        * turn(Vector3::x_axis(), phi);
    let track = e * v;
    let (s_phi, c_phi) = phi.sin_cos();
    let (s_theta, c_theta) = theta.sin_cos();
    let lateral = w.y * s_phi.abs() + w.z * c_phi.abs();
    let sec = 1.0 / c_theta.abs();
    let mut scale: Vec<f64> = track.iter().copied().collect();
    scale.extend([
        w.x + lateral * s_theta.abs() * sec,
        w.y * c_phi.abs() + w.z * s_phi.abs(),
        lateral * sec,
    ]);
    scale
}

/// Terms of the rotation v + 2q₀(q⃗ × v) + 2q⃗ × (q⃗ × v) and of q̇ = ½ q ⊗ (0, ω).
fn quaternion_kinematics_scale(
    q: &Quaternion<f64>,
    v: &Vector3<f64>,
    w: &Vector3<f64>,
) -> Vec<f64> {
    let (q0, qv) = (q.w.abs(), q.imag().abs());
    let t = cross_abs(&qv, v);
    let track = v + (t * q0 + cross_abs(&qv, &t)) * 2.0;
    let mut scale: Vec<f64> = track.iter().copied().collect();
    scale.push(0.5 * qv.dot(w));
    scale.extend(((w * q0 + cross_abs(&qv, w)) * 0.5).iter());
    scale
}

/// Terms of the track 4.44, u cos ψ ∓ v sin ψ.
fn track_scale(u: f64, v: f64, psi: f64) -> [f64; 2] {
    let (s, c) = psi.sin_cos();
    let (u, v, s, c) = (u.abs(), v.abs(), s.abs(), c.abs());
    [u * c + v * s, u * s + v * c]
}

/// Term sizes of the body-fixed form at G, 4.43 + 4.44.
pub fn at_g_scale(case: &PlanarCase) -> [f64; 6] {
    let [u, v, r, _, _, psi] = case.state;
    let [fx, fy, mz] = case.load.map(f64::abs);
    let [x_dot, y_dot] = track_scale(u, v, psi);
    let (u, v, r) = (u.abs(), v.abs(), r.abs());
    [
        fx / case.mass + v * r,
        fy / case.mass + u * r,
        mz / case.izz,
        x_dot,
        y_dot,
        r,
    ]
}

/// Term sizes of the midship form, 4.46 + 4.44, solved with the inverse of the sway–yaw mass
/// matrix [[M, M x_G], [M x_G, I_zz + M x_G²]]. Its determinant is M I_zz, but computed from
/// the entries it is the difference of terms as large as M I_zz + 2M²x_G²: with `conditioned`
/// the scale carries that ratio, as an f64 inverse computed from the entries does.
pub fn midship_scale(case: &PlanarCase, conditioned: bool) -> [f64; 6] {
    let (m, izz, x_g) = (case.mass, case.izz, case.x_g.abs());
    let [u, v, r, _, _, psi] = case.state;
    let [x, y, n] = case.load.map(f64::abs);
    let adjugate = nalgebra::Matrix2::new(izz + m * x_g * x_g, m * x_g, m * x_g, m);
    let det = m * izz;
    let det_terms = m * (izz + m * x_g * x_g) + (m * x_g).powi(2);
    let condition = if conditioned {
        1.0 + det_terms / det
    } else {
        1.0
    };
    let inverse = adjugate * (condition / det);
    let [x_dot, y_dot] = track_scale(u, v, psi);
    let (u, v, r) = (u.abs(), v.abs(), r.abs());
    let bias = nalgebra::Vector2::new(y + m * u * r, n + m * x_g * u * r);
    let sway_yaw = inverse * bias;
    let surge = x / m + v * r + x_g * r * r;
    [surge, sway_yaw.x, sway_yaw.y, x_dot, y_dot, r]
}

/// Term sizes of the space-fixed form, 4.39.
pub fn space_fixed_scale(case: &PlanarCase) -> [f64; 6] {
    let [x_dot, y_dot, psi_dot] = [case.state[0], case.state[1], case.state[2]].map(f64::abs);
    let [fx, fy, mz] = case.load.map(f64::abs);
    [
        x_dot,
        y_dot,
        psi_dot,
        fx / case.mass,
        fy / case.mass,
        mz / case.izz,
    ]
}

/// Term sizes of the pendulum, 4.24: θ̇ and (Mgh/I₀)|sin θ| + |M_O|/I₀.
pub fn pendulum_scale(case: &PendulumCase) -> [f64; 2] {
    let [theta, rate] = case.state;
    let stiffness = case.mass * case.g * case.h / case.i0;
    [
        rate.abs(),
        stiffness * theta.sin().abs() + case.moment.abs() / case.i0,
    ]
}
