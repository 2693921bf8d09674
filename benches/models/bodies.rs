//! The bodies the per-call measurements use: for the spatial models one per symmetry class
//! (principal moments 2, 3 and 4 turned so that each class's products are non-zero), and the
//! planar body and the pendulum, as parameters of their platform-trig variants. Shared by the
//! models bench and `examples/rhs_calls.rs`, so that wall time, cycles and instruction counts
//! price the same calls.

use eom::InertiaTensor;
use eom::models::generated::std_trig;
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

/// The planar body at G: M = 5, I_zz = 4 (`PlanarAtG::new(5.0, 4.0)`).
pub fn planar_at_g() -> std_trig::planar_at_g::Parameters {
    std_trig::planar_at_g::Parameters {
        mass: 5.0,
        izz: 4.0,
    }
}

/// The same body with G 0.3 ahead of midship (`PlanarMidship::new(5.0, 4.0, 0.3)`).
pub fn planar_midship() -> std_trig::planar_midship::Parameters {
    std_trig::planar_midship::Parameters {
        mass: 5.0,
        izz: 4.0,
        x_g: 0.3,
    }
}

/// The pendulum: I₀ = 2, M = 1, g = 9.81, h = 0.5 (`PendulumParameters::new(2.0, 1.0, 9.81, 0.5)`).
pub fn pendulum() -> std_trig::pendulum::Parameters {
    std_trig::pendulum::Parameters {
        i0: 2.0,
        mass: 1.0,
        g: 9.81,
        h: 0.5,
    }
}
