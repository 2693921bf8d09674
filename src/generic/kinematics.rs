//! Attitude kinematics: from body rates to the rates of the attitude and from body velocity
//! to the track, with Euler angles (4.53–4.60) and with unit quaternions.
//!
//! The rotation from body to space axes comes from nalgebra's own constructors, not from a
//! written-out matrix, so that the generic forms stay independent of the transcription the
//! generator is proved against. nalgebra's `from_euler_angles(roll, pitch, yaw)` is
//! `Rz(ψ) Ry(θ) Rx(φ)`, which is the chapter's `E` of 4.56–4.57.

use super::error::ModelError;
use nalgebra::{Quaternion, RealField, Rotation3, UnitQuaternion, Vector3};

/// The rotation `E = Rz(ψ) Ry(θ) Rx(φ)` that takes body components to space components
/// (4.56–4.57): `(Ẋ, Ẏ, Ż) = E (u, v, w)`.
///
/// ```
/// use eom::generic::body_to_space;
/// use nalgebra::Vector3;
/// // Heading 90°: the body x axis points along space Y.
/// let e = body_to_space(0.0, 0.0, std::f64::consts::FRAC_PI_2);
/// assert!((e * Vector3::x() - Vector3::y()).norm() < 1e-15);
/// ```
#[inline]
pub fn body_to_space<T: RealField + Copy>(phi: T, theta: T, psi: T) -> Rotation3<T> {
    Rotation3::from_euler_angles(phi, theta, psi)
}

/// The Euler-angle rates from the body rates `ω = (p, q, r)`, 4.60:
/// `φ̇ = p + (q sin φ + r cos φ) tan θ`, `θ̇ = q cos φ − r sin φ`,
/// `ψ̇ = (q sin φ + r cos φ) sec θ`.
///
/// Singular at `θ = ±90°`, where `cos θ = 0`: near there the rates grow as `1/cos θ`, and at
/// `cos θ = 0` exactly they are infinite or NaN. The function never panics; a caller that
/// may come near the singularity checks with [`check_pitch`] or carries the attitude as a
/// quaternion instead. `tan θ` and `sec θ` share one `sin_cos` and one division.
#[inline]
pub fn euler_rates<T: RealField + Copy>(phi: T, theta: T, omega: &Vector3<T>) -> Vector3<T> {
    let (sin_phi, cos_phi) = phi.sin_cos();
    let (sin_theta, cos_theta) = theta.sin_cos();
    let sec_theta = T::one() / cos_theta;
    let (p, q, r) = (omega.x, omega.y, omega.z);
    let q_sin_r_cos = q * sin_phi + r * cos_phi;
    Vector3::new(
        p + q_sin_r_cos * sin_theta * sec_theta,
        q * cos_phi - r * sin_phi,
        q_sin_r_cos * sec_theta,
    )
}

/// The body rates from the Euler-angle rates, 4.59 (the inverse of [`euler_rates`]):
/// `p = φ̇ − ψ̇ sin θ`, `q = θ̇ cos φ + ψ̇ cos θ sin φ`, `r = −θ̇ sin φ + ψ̇ cos θ cos φ`.
#[inline]
pub fn body_rates<T: RealField + Copy>(phi: T, theta: T, rates: &Vector3<T>) -> Vector3<T> {
    let (sin_phi, cos_phi) = phi.sin_cos();
    let (sin_theta, cos_theta) = theta.sin_cos();
    let (phi_dot, theta_dot, psi_dot) = (rates.x, rates.y, rates.z);
    Vector3::new(
        phi_dot - psi_dot * sin_theta,
        theta_dot * cos_phi + psi_dot * cos_theta * sin_phi,
        -theta_dot * sin_phi + psi_dot * cos_theta * cos_phi,
    )
}

/// Refuses a pitch where the Euler rates of 4.60 are not to be trusted: `|cos θ| < min_cos`.
///
/// ```
/// use eom::generic::check_pitch;
/// assert!(check_pitch(0.3_f64, 1e-3).is_ok());
/// assert!(check_pitch(std::f64::consts::FRAC_PI_2, 1e-3).is_err());
/// ```
pub fn check_pitch<T: RealField + Copy>(theta: T, min_cos: f64) -> Result<(), ModelError> {
    let cos_theta = nalgebra::try_convert::<T, f64>(theta.cos().abs()).unwrap_or(f64::NAN);
    if cos_theta >= min_cos {
        Ok(())
    } else {
        Err(ModelError::GimbalLock {
            theta: nalgebra::try_convert::<T, f64>(theta).unwrap_or(f64::NAN),
            cos_theta,
            limit: min_cos,
        })
    }
}

/// The unit quaternion of the same attitude as the Euler angles `(φ, θ, ψ)`: the rotation
/// `Rz(ψ) Ry(θ) Rx(φ)` of 4.57.
#[inline]
pub fn quaternion_from_euler<T: RealField + Copy>(phi: T, theta: T, psi: T) -> UnitQuaternion<T> {
    UnitQuaternion::from_euler_angles(phi, theta, psi)
}

/// The rate of the attitude quaternion for body rates `ω`: `q̇ = ½ q ⊗ (0, ω)`.
///
/// Singularity-free, and it keeps `|q|` constant in exact arithmetic (`q · q̇ = 0`), so the
/// stored quaternion is used as it is.
#[inline]
pub fn quaternion_rate<T: RealField + Copy>(
    q: &Quaternion<T>,
    omega: &Vector3<T>,
) -> Quaternion<T> {
    let half: T = nalgebra::convert(0.5);
    q * Quaternion::from_imag(*omega) * half
}

/// Uniform gravity `g` (along space Z, down) in body axes, from Euler angles: `Eᵀ (0, 0, g)
/// = g (−sin θ, sin φ cos θ, cos φ cos θ)` (4.57 transposed; the yaw ψ does not enter). Times
/// the mass it is the weight a spatial model takes as its body-axis force.
///
/// ```
/// use eom::generic::gravity_in_body_euler;
/// // Pitched nose-up by 90°: gravity points along body −x.
/// let g = gravity_in_body_euler(0.0, std::f64::consts::FRAC_PI_2, 9.81);
/// assert!((g.x + 9.81).abs() < 1e-12 && g.z.abs() < 1e-12);
/// ```
#[inline]
pub fn gravity_in_body_euler<T: RealField + Copy>(phi: T, theta: T, g: T) -> Vector3<T> {
    let (sin_phi, cos_phi) = phi.sin_cos();
    let (sin_theta, cos_theta) = theta.sin_cos();
    Vector3::new(-sin_theta, sin_phi * cos_theta, cos_phi * cos_theta) * g
}

/// Uniform gravity `g` (along space Z, down) in body axes, from the attitude quaternion of a
/// quaternion state (`q0` the scalar part), normalised first, so that a state whose `|q|` has
/// drifted still gives a vector of length `g`.
///
/// ```
/// use eom::generic::{gravity_in_body_euler, gravity_in_body_quaternion, quaternion_from_euler};
/// let q = quaternion_from_euler(0.3, -0.7, 2.0);
/// let from_q = gravity_in_body_quaternion(q.quaternion(), 9.81);
/// let from_angles = gravity_in_body_euler(0.3, -0.7, 9.81);
/// assert!((from_q - from_angles).norm() < 1e-12);
/// ```
#[inline]
pub fn gravity_in_body_quaternion<T: RealField + Copy>(q: &Quaternion<T>, g: T) -> Vector3<T> {
    let attitude = UnitQuaternion::from_quaternion(*q);
    attitude.inverse_transform_vector(&(Vector3::z() * g))
}
