//! The state layouts of the spatial forms, their indices, and the change from Euler angles
//! to a quaternion.
//!
//! Euler state (12): `[u, v, w, p, q, r, x, y, z, φ, θ, ψ]`.
//! Quaternion state (13): `[u, v, w, p, q, r, x, y, z, q0, q1, q2, q3]`, scalar first.
//! The first nine entries are shared, so a state moves from one to the other by rewriting the
//! attitude only.

use super::kinematics::quaternion_from_euler;
use nalgebra::{Quaternion, RealField, SVector, UnitQuaternion, Vector3};

/// The state of the spatial Euler-angle form, `[u, v, w, p, q, r, x, y, z, φ, θ, ψ]`.
pub type EulerState<T> = SVector<T, 12>;

/// The state of the spatial quaternion form, `[u, v, w, p, q, r, x, y, z, q0, q1, q2, q3]`.
pub type QuaternionState<T> = SVector<T, 13>;

/// Index of the body velocity `(u, v, w)` of G: entries `VELOCITY..VELOCITY + 3`.
pub const VELOCITY: usize = 0;
/// Index of the body rates `(p, q, r)`: entries `RATES..RATES + 3`.
pub const RATES: usize = 3;
/// Index of the position `(x, y, z)` of G in space axes: entries `POSITION..POSITION + 3`.
pub const POSITION: usize = 6;
/// Index of the attitude: `(φ, θ, ψ)` in the Euler state, `(q0, q1, q2, q3)` in the
/// quaternion state.
pub const ATTITUDE: usize = 9;

/// The body velocity `(u, v, w)` from either spatial state.
#[inline]
pub fn velocity<T: RealField + Copy, const N: usize>(state: &SVector<T, N>) -> Vector3<T> {
    Vector3::new(state[VELOCITY], state[VELOCITY + 1], state[VELOCITY + 2])
}

/// The body rates `(p, q, r)` from either spatial state.
#[inline]
pub fn rates<T: RealField + Copy, const N: usize>(state: &SVector<T, N>) -> Vector3<T> {
    Vector3::new(state[RATES], state[RATES + 1], state[RATES + 2])
}

/// The attitude quaternion of a quaternion state, as stored (not normalised).
#[inline]
pub fn attitude_quaternion<T: RealField + Copy>(state: &QuaternionState<T>) -> Quaternion<T> {
    let a = ATTITUDE;
    Quaternion::new(state[a], state[a + 1], state[a + 2], state[a + 3])
}

/// The quaternion state of the same motion as an Euler state: the attitude becomes
/// `UnitQuaternion::from_euler_angles(φ, θ, ψ)`, the rest is copied.
///
/// ```
/// use eom::generic::{EulerState, euler_state_to_quaternion_state};
/// let x = euler_state_to_quaternion_state(&EulerState::<f64>::zeros());
/// assert_eq!(x[9], 1.0); // the identity attitude, scalar first
/// ```
pub fn euler_state_to_quaternion_state<T: RealField + Copy>(
    state: &EulerState<T>,
) -> QuaternionState<T> {
    let a = ATTITUDE;
    let q = quaternion_from_euler(state[a], state[a + 1], state[a + 2]);
    let mut out = QuaternionState::zeros();
    out.fixed_rows_mut::<9>(0)
        .copy_from(&state.fixed_rows::<9>(0));
    out[a] = q.w;
    out[a + 1] = q.i;
    out[a + 2] = q.j;
    out[a + 3] = q.k;
    out
}

/// The Euler state of the same motion as a quaternion state, with `θ` in `[−90°, 90°]`
/// (nalgebra's `euler_angles` of the normalised quaternion).
pub fn quaternion_state_to_euler_state<T: RealField + Copy>(
    state: &QuaternionState<T>,
) -> EulerState<T> {
    let q = UnitQuaternion::new_normalize(attitude_quaternion(state));
    let (phi, theta, psi) = q.euler_angles();
    let mut out = EulerState::zeros();
    out.fixed_rows_mut::<9>(0)
        .copy_from(&state.fixed_rows::<9>(0));
    out[ATTITUDE] = phi;
    out[ATTITUDE + 1] = theta;
    out[ATTITUDE + 2] = psi;
    out
}

/// The quaternion state of a rotation `[p, q, r, q0, q1, q2, q3]` (the state of
/// [`RigidRotation`](crate::integrate::RigidRotation) and of the torque-free reference
/// problems), with the translation at rest: `u = v = w = 0`, `x = y = z = 0`.
///
/// ```
/// use eom::generic::{quaternion_state_of_rotation, rotation_of_quaternion_state};
/// use nalgebra::SVector;
/// let rotation = SVector::<f64, 7>::from([0.1, 6.0, 0.2, 1.0, 0.0, 0.0, 0.0]);
/// let state = quaternion_state_of_rotation(&rotation);
/// assert_eq!((state[4], state[9], state[0]), (6.0, 1.0, 0.0));
/// assert_eq!(rotation_of_quaternion_state(&state), rotation);
/// ```
pub fn quaternion_state_of_rotation<T: RealField + Copy>(
    rotation: &SVector<T, 7>,
) -> QuaternionState<T> {
    let mut state = QuaternionState::zeros();
    state
        .fixed_rows_mut::<3>(RATES)
        .copy_from(&rotation.fixed_rows::<3>(0));
    state
        .fixed_rows_mut::<4>(ATTITUDE)
        .copy_from(&rotation.fixed_rows::<4>(3));
    state
}

/// The rotation `[p, q, r, q0, q1, q2, q3]` of a quaternion state: its rates and attitude.
pub fn rotation_of_quaternion_state<T: RealField + Copy>(
    state: &QuaternionState<T>,
) -> SVector<T, 7> {
    let mut rotation = SVector::<T, 7>::zeros();
    rotation
        .fixed_rows_mut::<3>(0)
        .copy_from(&state.fixed_rows::<3>(RATES));
    rotation
        .fixed_rows_mut::<4>(3)
        .copy_from(&state.fixed_rows::<4>(ATTITUDE));
    rotation
}
