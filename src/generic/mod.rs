//! The generic forms: the chapter's equations written the way a careful engineer writes them
//! with nalgebra (`Vector3::cross`, a `Matrix3` inertia tensor and its inverse, `Rotation3`,
//! `UnitQuaternion`), with no symbolic help.
//!
//! They are the independent check on the generated models: the generated functions are
//! compared with these at random and extreme states, and benchmarked against them. So they
//! are correct, validated once, allocation-free and efficient (every parameter-only quantity,
//! such as `1/M` or `[I]⁻¹`, is computed once in a constructor), but they do not exploit what
//! only a generator knows: which terms a symmetry class makes zero, or which subexpressions
//! two equations share.
//!
//! All forms are generic over the scalar `T: RealField + Copy` (`f32` and `f64`);
//! parameters are validated in `f64` and converted with `nalgebra::convert`.
//!
//! | model | type, method | state | load |
//! |---|---|---|---|
//! | compound pendulum, 4.24 | [`Pendulum::rhs`] | `[θ, θ̇]` | moment about the pivot |
//! | planar at G, 4.43 + 4.44 | [`PlanarBody::rhs_body_at_g`] | `[u, v, r, X, Y, ψ]` | `(F_x, F_y, M_z)` body axes, about G |
//! | planar at midship, 4.46 + 4.44 | [`PlanarMidship::rhs_body_at_midship`] | `[u, v, r, X, Y, ψ]` of the midship origin | `(X, Y, N)` body axes, about midship |
//! | planar space-fixed, 4.39 | [`PlanarBody::rhs_space_fixed`] | `[X, Y, ψ, Ẋ, Ẏ, ψ̇]` | `(F_X, F_Y, M_z)` space axes |
//! | spatial, Euler angles, 4.49 + 4.51 + 4.57 + 4.60 | [`RigidBody::rhs_euler`] | `[u, v, w, p, q, r, x, y, z, φ, θ, ψ]` | force and moment about G, body axes |
//! | spatial, quaternion, 4.49 + 4.51 | [`RigidBody::rhs_quaternion`] | `[u, v, w, p, q, r, x, y, z, q0, q1, q2, q3]` | force and moment about G, body axes |
//!
//! Each method returns the time derivative of its state, entry by entry. In f64 each form also
//! implements the model contract ([`Model`](crate::models::Model)) under the name, state and
//! inputs of the generated model of the same equations (the space-fixed form as
//! [`PlanarSpaceFixed`], the rigid body once per kinematics), its Jacobians by dual numbers
//! through its own rates: so a test integrates a generic form and a generated model through one
//! trait and one integrator. The Euler-angle form
//! is singular at pitch `θ = ±90°` (4.60 divides by `cos θ`): it does not panic there, but its
//! rates are meaningless, so callers check with [`check_pitch`] or use the quaternion form.

mod contract;
pub(crate) mod error;
mod kinematics;
mod midship;
mod pendulum;
mod planar;
mod spatial;
mod state;

pub use error::ModelError;
pub use kinematics::{
    body_rates, body_to_space, check_pitch, euler_rates, gravity_in_body_euler,
    gravity_in_body_quaternion, quaternion_from_euler, quaternion_rate,
};
pub use midship::PlanarMidship;
pub use pendulum::Pendulum;
pub use planar::{PlanarBody, PlanarSpaceFixed, track};
pub use spatial::RigidBody;
pub use state::{
    ATTITUDE, EulerState, POSITION, QuaternionState, RATES, VELOCITY, attitude_quaternion,
    euler_state_to_quaternion_state, quaternion_state_of_rotation, quaternion_state_to_euler_state,
    rates, rotation_of_quaternion_state, velocity,
};
