//! An attitude as a model carries it in its state, Euler angles `[φ, θ, ψ]` (E of 4.57) or a
//! quaternion `[q0, q1, q2, q3]`: the rotation it is, and its roll, pitch and yaw, for every
//! kind that reads one (a body's loads in space axes, a vehicle's linearisation in Euler
//! angles).

use super::Kinematics;
use nalgebra::{Quaternion, Rotation3, UnitQuaternion};

/// The rotation from body to space axes of an attitude, `[φ, θ, ψ]` (E of 4.57) or
/// `[q0, q1, q2, q3]` (normalised).
pub fn attitude(kinematics: Kinematics, a: &[f64]) -> Rotation3<f64> {
    match kinematics {
        Kinematics::Euler => Rotation3::from_euler_angles(a[0], a[1], a[2]),
        Kinematics::Quaternion => {
            let q = Quaternion::new(a[0], a[1], a[2], a[3]);
            UnitQuaternion::from_quaternion(q).to_rotation_matrix()
        }
    }
}

/// Roll, pitch and yaw, radians, of an attitude as the model carries it (the state from its
/// attitude entries on: index 9 of a spatial state, 3 of a top's).
pub fn euler_angles(kinematics: Kinematics, attitude_entries: &[f64]) -> [f64; 3] {
    match kinematics {
        Kinematics::Euler => [
            attitude_entries[0],
            attitude_entries[1],
            attitude_entries[2],
        ],
        Kinematics::Quaternion => {
            euler_angles_of_quaternion([0, 1, 2, 3].map(|k| attitude_entries[k]))
        }
    }
}

/// Roll, pitch and yaw, radians (z–y–x), of the quaternion `[q0, q1, q2, q3]` (q0 the scalar,
/// normalised): what a drawing of a quaternion's attitude plots.
///
/// ```
/// let half = std::f64::consts::FRAC_PI_8;
/// // A turn of π/4 about z, the quaternion twice unit length.
/// let [roll, pitch, yaw] = eom::models::euler_angles_of_quaternion([2.0 * half.cos(), 0.0, 0.0, 2.0 * half.sin()]);
/// assert!(roll.abs() < 1e-15 && pitch.abs() < 1e-15);
/// assert!((yaw - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
/// ```
pub fn euler_angles_of_quaternion(q: [f64; 4]) -> [f64; 3] {
    let (r, p, y) = attitude(Kinematics::Quaternion, &q).euler_angles();
    [r, p, y]
}
