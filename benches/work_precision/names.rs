//! The names of the tennis racket's model variants, and the pairs of them the report sets side
//! by side (each pair differs in one thing: the form of the right-hand side, the tensor, the
//! kinematics or the precision).

use super::report::BASE;

/// The generated `SpatialPrincipalQuaternion` (pruned: 4.52 with quaternion kinematics).
pub const GENERATED: &str = "f64, generated principal, quaternion";
/// The generic nalgebra form `RigidBody::rhs_quaternion` on the principal tensor.
pub const GENERIC: &str = "f64, generic nalgebra, quaternion";
/// The generated `SpatialFullQuaternion` fed the principal tensor (products zero).
pub const GENERATED_FULL_ZERO: &str = "f64, generated full, zero products";
/// The generated `SpatialPrincipalQuaternion` in f32.
pub const GENERATED_F32: &str = "f32, generated principal, quaternion";
/// The generic nalgebra form in f32.
pub const GENERIC_F32: &str = "f32, generic nalgebra, quaternion";
/// The generated `SpatialPrincipalEuler` (4.52 with 4.60).
pub const GENERATED_EULER: &str = "f64, generated principal, Euler angles";
/// The generic nalgebra form `RigidBody::rhs_euler` on the principal tensor.
pub const GENERIC_EULER: &str = "f64, generic nalgebra, Euler angles";
/// The generated `SpatialFullQuaternion` with the racket described in turned body axes.
pub const TURNED_GENERATED: &str = "f64, turned axes, generated full, quaternion";
/// The generic nalgebra form with the racket described in turned body axes.
pub const TURNED_GENERIC: &str = "f64, turned axes, generic nalgebra, quaternion";

/// The comparisons of the report: (what is compared, model A, model B); ratios are A/B.
pub const PAIRS: [(&str, &str, &str); 9] = [
    ("generated / generic, principal axes", GENERATED, GENERIC),
    ("generated / hand-written 4.52", GENERATED, BASE),
    (
        "generated / generic, turned axes (full)",
        TURNED_GENERATED,
        TURNED_GENERIC,
    ),
    (
        "generated / generic, Euler angles",
        GENERATED_EULER,
        GENERIC_EULER,
    ),
    ("generated / generic, f32", GENERATED_F32, GENERIC_F32),
    (
        "pruned / full, same body (principal vs turned axes)",
        GENERATED,
        TURNED_GENERATED,
    ),
    (
        "pruned / full, same tensor (zero products)",
        GENERATED,
        GENERATED_FULL_ZERO,
    ),
    (
        "Euler angles / quaternion, generated",
        GENERATED_EULER,
        GENERATED,
    ),
    ("f32 / f64, generated", GENERATED_F32, GENERATED),
];
