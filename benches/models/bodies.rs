//! The bodies the per-call measurements use, one per symmetry class: principal moments 2, 3
//! and 4 turned so that each class's products are non-zero. Shared by the models bench and
//! `examples/rhs_calls.rs`, so that wall time, cycles and instruction counts price the same
//! calls.

use eom::InertiaTensor;
use nalgebra::{Matrix3, Rotation3, Vector3};

/// diag(2, 3, 4) turned by the Euler angles `roll, pitch, yaw`.
fn turned(roll: f64, pitch: f64, yaw: f64) -> Matrix3<f64> {
    let r = Rotation3::from_euler_angles(roll, pitch, yaw).into_inner();
    r * Matrix3::from_diagonal(&Vector3::new(2.0, 3.0, 4.0)) * r.transpose()
}

/// Every product non-zero.
pub fn full_tensor() -> InertiaTensor {
    InertiaTensor::from_matrix(turned(0.3, -0.2, 0.5)).expect("a physical tensor")
}

/// Turned about y only: I_xz non-zero, I_xy = I_yz = 0 (set exactly, not left to round-off).
pub fn xz_tensor() -> InertiaTensor {
    let mut m = turned(0.0, 0.4, 0.0);
    (m[(0, 1)], m[(1, 0)], m[(1, 2)], m[(2, 1)]) = (0.0, 0.0, 0.0, 0.0);
    InertiaTensor::from_matrix(m).expect("a physical tensor")
}

/// Principal axes: no products.
pub fn principal_tensor() -> InertiaTensor {
    InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.0).expect("a physical tensor")
}

/// The body of a symmetry class: the turned tensor above, with every product the class prunes
/// exactly zero (turned about the one axis that leaves exactly the kept product when the class
/// keeps one).
pub fn tensor_of(class: eom::models::Symmetry) -> InertiaTensor {
    let pruned = class.pruned();
    match pruned.len() {
        0 => full_tensor(),
        3 => principal_tensor(),
        _ if pruned.contains(&"Ixy") && pruned.contains(&"Iyz") => xz_tensor(),
        _ => panic!("no test body for the class {}", class.name()),
    }
}
