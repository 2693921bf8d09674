//! Calls one right-hand side many times, for counting instructions per call with callgrind,
//! which is repeatable where wall time on a shared machine is not:
//!
//! ```sh
//! cargo build --release --example rhs_calls
//! valgrind --tool=callgrind --callgrind-out-file=/dev/null target/release/examples/rhs_calls generated principal_euler 2000
//! ```
//! The difference between two call counts, divided by the difference in calls, is the cost of
//! one call. `form` is `generated` or `generic`; `variant` is `{full,xz,principal}_{euler,quaternion}`.

use eom::InertiaTensor;
use eom::generic::RigidBody;
use eom::models::{
    SpatialFullEuler, SpatialFullQuaternion, SpatialPrincipalEuler, SpatialPrincipalQuaternion,
    SpatialXzEuler, SpatialXzQuaternion,
};
use nalgebra::{Matrix3, Rotation3, SVector, Vector3};
use std::hint::black_box;

/// Distinct states, built before the calls so that their cost does not depend on the count.
const STATES: usize = 64;

const FORCE: [f64; 3] = [10.0, -2.0, 1.0];
const MOMENT: [f64; 3] = [0.5, 0.2, -0.3];

/// Principal moments 2, 3, 4 turned by `roll, pitch, yaw`: products where the rotation puts them.
fn tensor(roll: f64, pitch: f64, yaw: f64) -> InertiaTensor {
    let r = Rotation3::from_euler_angles(roll, pitch, yaw).into_inner();
    let mut m = r * Matrix3::from_diagonal(&Vector3::new(2.0, 3.0, 4.0)) * r.transpose();
    m = (m + m.transpose()) * 0.5;
    if roll == 0.0 && yaw == 0.0 {
        (m[(0, 1)], m[(1, 0)], m[(1, 2)], m[(2, 1)]) = (0.0, 0.0, 0.0, 0.0);
    }
    InertiaTensor::from_matrix(m).expect("a physical tensor")
}

/// The state of call `i`: a little different each time, so nothing is hoisted out of the loop;
/// every output is consumed, so nothing is dropped as dead code.
fn state<const N: usize>(i: usize, quaternion: bool) -> [f64; N] {
    let s = 1e-6 * i as f64;
    let mut x = [0.0; N];
    x[..6].copy_from_slice(&[1.0 + s, 0.2, -0.1, 0.3, -0.2, 0.5]);
    if quaternion {
        let q = nalgebra::UnitQuaternion::from_euler_angles(0.1 + s, 0.2, 0.3);
        x[9..13].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    } else {
        x[9..12].copy_from_slice(&[0.1 + s, 0.2, 0.3]);
    }
    x
}

macro_rules! run_generated {
    ($model:ty, $tensor:expr, $n:literal, $quaternion:expr, $calls:expr) => {{
        let model = <$model>::new(5.0, &$tensor).expect("valid body");
        let states: Vec<[f64; $n]> = (0..STATES).map(|i| state::<$n>(i, $quaternion)).collect();
        let mut sum = 0.0;
        for i in 0..$calls {
            let output = model.rhs(black_box(&states[i % STATES]), &FORCE, &MOMENT);
            sum += black_box(output).iter().sum::<f64>();
        }
        sum
    }};
}

fn run_generic(tensor: &InertiaTensor, quaternion: bool, calls: usize) -> f64 {
    let body = RigidBody::<f64>::new(5.0, tensor).expect("valid body");
    let (f, m) = (Vector3::from(FORCE), Vector3::from(MOMENT));
    let euler: Vec<SVector<f64, 12>> = (0..STATES)
        .map(|i| SVector::from(state::<12>(i, false)))
        .collect();
    let quaternions: Vec<SVector<f64, 13>> = (0..STATES)
        .map(|i| SVector::from(state::<13>(i, true)))
        .collect();
    let mut sum = 0.0;
    for i in 0..calls {
        sum += if quaternion {
            black_box(body.rhs_quaternion(black_box(&quaternions[i % STATES]), &f, &m)).sum()
        } else {
            black_box(body.rhs_euler(black_box(&euler[i % STATES]), &f, &m)).sum()
        };
    }
    sum
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (form, variant) = (
        args.get(1).map_or("generated", |s| s),
        args.get(2).map_or("principal_euler", |s| s),
    );
    let calls: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let (full, xz, principal) = (
        tensor(0.3, -0.2, 0.5),
        tensor(0.0, 0.4, 0.0),
        tensor(0.0, 0.0, 0.0),
    );
    let quaternion = variant.ends_with("quaternion");
    let body = match variant.split('_').next() {
        Some("full") => full,
        Some("xz") => xz,
        _ => principal,
    };
    let sum = match (form, variant) {
        ("generic", _) => run_generic(&body, quaternion, calls),
        (_, "full_euler") => run_generated!(SpatialFullEuler<f64>, body, 12, false, calls),
        (_, "xz_euler") => run_generated!(SpatialXzEuler<f64>, body, 12, false, calls),
        (_, "principal_euler") => {
            run_generated!(SpatialPrincipalEuler<f64>, body, 12, false, calls)
        }
        (_, "full_quaternion") => run_generated!(SpatialFullQuaternion<f64>, body, 13, true, calls),
        (_, "xz_quaternion") => run_generated!(SpatialXzQuaternion<f64>, body, 13, true, calls),
        _ => run_generated!(SpatialPrincipalQuaternion<f64>, body, 13, true, calls),
    };
    println!("{form} {variant}: {calls} calls (checksum {sum:.6})");
}
