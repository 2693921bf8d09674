//! Bodies more than one test, bench or example is built on. The bodies the per-call
//! measurements use, one per symmetry class ([`tensor_of`]: principal moments 2, 3 and 4
//! turned so that each class's products are non-zero), are shared by the models bench,
//! `examples/rhs_calls.rs` and eom-peer, so that wall time, cycles and instruction counts
//! price the same calls.

use eom::InertiaTensor;
use eom::models::Symmetry;
use eom::reference::{AxisymmetricTop, TennisRacket};
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

/// diag(2, 3, 4) turned by the Euler angles `roll, pitch, yaw`.
fn turned(roll: f64, pitch: f64, yaw: f64) -> Matrix3<f64> {
    let r = Rotation3::from_euler_angles(roll, pitch, yaw).into_inner();
    r * Matrix3::from_diagonal(&Vector3::new(2.0, 3.0, 4.0)) * r.transpose()
}

/// Every product non-zero.
pub fn full_tensor() -> InertiaTensor {
    InertiaTensor::from_matrix(turned(0.3, -0.2, 0.5)).expect("a physical tensor")
}

/// Principal axes: no products.
pub fn principal_tensor() -> InertiaTensor {
    InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.0).expect("a physical tensor")
}

/// The body of a symmetry class: the turned tensor above when the class keeps every product,
/// diag(2, 3, 4) turned about the one axis that leaves exactly the kept product when it keeps
/// one (about y for the xz class, with the other products set exactly to zero), principal
/// axes when it keeps none. Read from what the class prunes, so a new class needs no edit.
pub fn tensor_of(class: Symmetry) -> InertiaTensor {
    let kept: Vec<&str> = ["Ixy", "Iyz", "Ixz"]
        .into_iter()
        .filter(|p| !class.pruned().contains(p))
        .collect();
    let mut m = match kept.as_slice() {
        [] => return principal_tensor(),
        ["Ixy"] => turned(0.0, 0.0, 0.4),
        ["Iyz"] => turned(0.4, 0.0, 0.0),
        ["Ixz"] => turned(0.0, 0.4, 0.0),
        _ => return full_tensor(),
    };
    for (product, (r, c)) in [("Ixy", (0, 1)), ("Iyz", (1, 2)), ("Ixz", (0, 2))] {
        if !kept.contains(&product) {
            (m[(r, c)], m[(c, r)]) = (0.0, 0.0);
        }
    }
    InertiaTensor::from_matrix(m).expect("a physical tensor")
}

/// A tensor of the class: the products it keeps are non-zero.
pub fn tensor(class: Symmetry) -> InertiaTensor {
    let keep = |name: &str, value: f64| {
        if class.pruned().contains(&name) {
            0.0
        } else {
            value
        }
    };
    InertiaTensor::new(
        2.0,
        3.0,
        4.5,
        keep("Ixy", 0.1),
        keep("Iyz", -0.05),
        keep("Ixz", 0.2),
    )
    .expect("a physical tensor")
}

/// The tennis racket of the integrator tests: moments 1, 2, 3, spun near its middle axis
/// from a turned attitude.
pub fn racket() -> TennisRacket {
    let attitude = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
    TennisRacket::new(Vector3::new(1.0, 2.0, 3.0), 1.0, 0.1, attitude).unwrap()
}

/// The torque-free symmetric top of the integrator tests.
pub fn top() -> AxisymmetricTop {
    let attitude = UnitQuaternion::from_euler_angles(0.1, 0.4, -0.7);
    AxisymmetricTop::new(2.0, 3.5, Vector3::new(0.6, -0.3, 1.2), attitude).unwrap()
}
