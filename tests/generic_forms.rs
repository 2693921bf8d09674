//! The generic forms checked against each other and against physics (ARCHITECTURE.md, lines of
//! evidence 3 and 4): space-fixed vs body-fixed planar, origin at G vs at midship, Euler
//! angles vs quaternions, spatial confined to the plane vs planar, conservation of energy and
//! angular momentum, the work–energy theorem, and refusal of bad parameters.

use eom::generic::{
    EulerState, ModelError, Pendulum, PlanarBody, PlanarMidship, RigidBody, body_rates,
    body_to_space, check_pitch, euler_rates, euler_state_to_quaternion_state,
    quaternion_from_euler, quaternion_state_to_euler_state,
};
use eom::{InertiaTensor, PendulumParameters};
use nalgebra::{Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector2, Vector3, Vector6};
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

/// Unit roundoff of `f64`.
const EPS: f64 = f64::EPSILON;

fn config() -> ProptestConfig {
    // 64 cases per property keeps the whole file near a second in the debug profile.
    ProptestConfig::with_cases(64)
}

fn vec3(range: f64) -> impl Strategy<Value = Vector3<f64>> {
    (-range..range, -range..range, -range..range).prop_map(|(a, b, c)| Vector3::new(a, b, c))
}

/// A physical inertia tensor: positive second moments `∫x², ∫y², ∫z²` spread over six decades
/// (inertia ratios up to about 10⁶), turned by an arbitrary rotation, so that all products
/// are present. `Ixx = ∫y² + ∫z²` etc. satisfies every check of `InertiaTensor` by
/// construction.
fn tensor() -> impl Strategy<Value = InertiaTensor> {
    let second = (-3.0..3.0f64, -3.0..3.0f64, -3.0..3.0f64);
    let angles = (-PI..PI, -PI..PI, -PI..PI);
    (second, angles).prop_map(|((a, b, c), (r1, r2, r3))| {
        let (a, b, c) = (10f64.powf(a), 10f64.powf(b), 10f64.powf(c));
        let principal = Matrix3::from_diagonal(&Vector3::new(b + c, c + a, a + b));
        let turn = Rotation3::from_euler_angles(r1, r2, r3).into_inner();
        let m = turn * principal * turn.transpose();
        InertiaTensor::from_matrix((m + m.transpose()) * 0.5).expect("valid by construction")
    })
}

fn body() -> impl Strategy<Value = RigidBody<f64>> {
    (0.1..1e3f64, tensor()).prop_map(|(m, t)| RigidBody::new(m, &t).unwrap())
}

/// Body rates of any direction with magnitudes spread over five decades, up to about 10³ rad/s.
fn body_rates_vector() -> impl Strategy<Value = Vector3<f64>> {
    (vec3(1.0), -2.0..3.0f64).prop_map(|(w, decade)| w * 10f64.powf(decade))
}

/// An Euler state with the pitch at least 10° away from ±90°.
fn euler_state() -> impl Strategy<Value = EulerState<f64>> {
    let attitude = (-PI..PI, -1.39..1.39f64, -PI..PI);
    let motion = (vec3(10.0), body_rates_vector(), vec3(100.0));
    (motion, attitude).prop_map(|((v, w, x), (phi, th, psi))| {
        let mut s = EulerState::zeros();
        s.fixed_rows_mut::<3>(0).copy_from(&v);
        s.fixed_rows_mut::<3>(3).copy_from(&w);
        s.fixed_rows_mut::<3>(6).copy_from(&x);
        s.fixed_rows_mut::<3>(9)
            .copy_from(&Vector3::new(phi, th, psi));
        s
    })
}

fn part(s: &[f64], at: usize) -> Vector3<f64> {
    Vector3::new(s[at], s[at + 1], s[at + 2])
}

/// The spectral condition number of `[I]`, which bounds how much roundoff `[I]⁻¹` amplifies.
fn condition(body: &RigidBody<f64>) -> f64 {
    body.inertia().norm() * body.inverse_inertia().norm()
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn planar_space_fixed_matches_body_fixed_at_g(
        m in 0.1..1e3f64, izz in 0.1..1e3f64,
        u in -10.0..10.0f64, v in -10.0..10.0f64, r in -3.0..3.0f64,
        psi in -PI..PI, load in vec3(100.0),
    ) {
        let ship = PlanarBody::<f64>::new(m, izz).unwrap();
        let body = ship.rhs_body_at_g(&Vector6::new(u, v, r, 1.0, 2.0, psi), &load);
        let (s, c) = psi.sin_cos();
        let (x_dot, y_dot) = (u * c - v * s, u * s + v * c);
        let space_load = Vector3::new(load.x * c - load.y * s, load.x * s + load.y * c, load.z);
        let space = ship.rhs_space_fixed(&Vector6::new(1.0, 2.0, psi, x_dot, y_dot, r), &space_load);
        // d/dt of the space velocity E(ψ)(u, v): Ẍ = u̇ cos ψ − v̇ sin ψ − Ẏ r, Ÿ = … + Ẋ r.
        let x_ddot = body[0] * c - body[1] * s - y_dot * r;
        let y_ddot = body[0] * s + body[1] * c + x_dot * r;
        // Relative 1e-13 of the largest term: a few tens of roundings of O(scale) products.
        let scale = load.norm() / m + (u.abs() + v.abs()) * r.abs() + 1.0;
        prop_assert!((space[3] - x_ddot).abs() <= 1e-13 * scale);
        prop_assert!((space[4] - y_ddot).abs() <= 1e-13 * scale);
        prop_assert!((space[5] - body[2]).abs() <= 1e-13 * (body[2].abs() + 1.0));
        prop_assert!((space[0] - body[3]).abs() <= 1e-13 * (u.abs() + v.abs()));
        prop_assert!((space[1] - body[4]).abs() <= 1e-13 * (u.abs() + v.abs()));
        prop_assert_eq!(space[2], body[5]);
    }

    #[test]
    fn midship_form_matches_cg_form_after_origin_shift(
        m in 1.0..1e3f64, k in 1.0..10.0f64, x_g in -3.0..3.0f64,
        u in -10.0..10.0f64, v_g in -10.0..10.0f64, r in -3.0..3.0f64,
        psi in -PI..PI, load in vec3(100.0),
    ) {
        let izz = m * k * k;
        let at_g = PlanarBody::<f64>::new(m, izz).unwrap();
        let midship = PlanarMidship::<f64>::new(m, izz, x_g).unwrap();
        let g = at_g.rhs_body_at_g(&Vector6::new(u, v_g, r, 0.0, 0.0, psi), &load);
        // 4.45: v_m = v − x_G r, N = M_z + F_y x_G; the midship origin is x_G behind G.
        let v_m = v_g - x_g * r;
        let n = load.z + load.y * x_g;
        let mid = midship.rhs_body_at_midship(
            &Vector6::new(u, v_m, r, -x_g * psi.cos(), -x_g * psi.sin(), psi),
            &Vector3::new(load.x, load.y, n),
        );
        let expected = Vector6::new(
            g[0],
            g[1] - x_g * g[2],
            g[2],
            g[3] + x_g * r * psi.sin(),
            g[4] - x_g * r * psi.cos(),
            g[5],
        );
        // The midship form solves a 2×2 system whose condition number is at most
        // (1 + x_G² + k²)²/k² < 1.2e4 here; 1e-10 relative is 40 ulps of that amplification.
        let scale = 1.0 + load.norm() / m + (u.abs() + v_g.abs() + x_g.abs() * r.abs()) * r.abs()
            + load.norm() / izz * (1.0 + x_g.abs());
        prop_assert!((mid - expected).abs().max() <= 1e-10 * scale, "{mid} vs {expected}");
    }

    #[test]
    fn euler_and_quaternion_forms_agree_away_from_the_singularity(
        body in body(), state in euler_state(), force in vec3(100.0), moment in vec3(100.0),
    ) {
        let euler = body.rhs_euler(&state, &force, &moment);
        let quat_state = euler_state_to_quaternion_state(&state);
        let quat = body.rhs_quaternion(&quat_state, &force, &moment);
        // Accelerations: the same code path on the same numbers, so bit-for-bit equal.
        prop_assert_eq!(euler.fixed_rows::<6>(0), quat.fixed_rows::<6>(0));
        // Position rates: a rotation matrix against a quaternion rotation of one attitude,
        // both exact to a few ulps of |v|.
        let speed = part(state.as_slice(), 0).norm();
        prop_assert!((euler.fixed_rows::<3>(6) - quat.fixed_rows::<3>(6)).norm() <= 1e-14 * speed.max(1.0));
        // Quaternion rate: the central difference of q(φ, θ, ψ) along the Euler rates, with
        // the angle step h|rates| = 1e-5. Truncation (h|d|)²|d|/48 ≈ 2e-12|d| and roundoff
        // EPS/h ≈ 1e-11|d|; 1e-9(1 + |d|) leaves a margin of a hundred.
        let d = part(euler.as_slice(), 9);
        let h = 1e-5 / (1.0 + d.norm());
        let angles = part(state.as_slice(), 9);
        let at = |s: f64| {
            let a = angles + d * s;
            *quaternion_from_euler(a.x, a.y, a.z).quaternion()
        };
        let numeric = (at(h) - at(-h)) / (2.0 * h);
        let analytic = Quaternion::new(quat[9], quat[10], quat[11], quat[12]);
        prop_assert!((numeric - analytic).norm() <= 1e-9 * (1.0 + d.norm()), "{numeric} vs {analytic}");
    }

    #[test]
    fn spatial_motion_in_the_plane_reduces_to_planar_at_g(
        m in 0.1..1e3f64, a in 0.01..10.0f64, b in 0.01..10.0f64, c in 0.01..10.0f64,
        turn in -PI..PI, u in -10.0..10.0f64, v in -10.0..10.0f64, r in -3.0..3.0f64,
        psi in -PI..PI, fx in -100.0..100.0f64, fy in -100.0..100.0f64, mz in -100.0..100.0f64,
    ) {
        // A tensor turned about z only: I_xy free, I_xz = I_yz = 0, so yaw is decoupled.
        let principal = Matrix3::from_diagonal(&Vector3::new(b + c, c + a, a + b));
        let rz = Rotation3::from_euler_angles(0.0, 0.0, turn).into_inner();
        let m3 = rz * principal * rz.transpose();
        let mut t = (m3 + m3.transpose()) * 0.5;
        (t[(0, 2)], t[(2, 0)], t[(1, 2)], t[(2, 1)]) = (0.0, 0.0, 0.0, 0.0);
        let tensor = InertiaTensor::from_matrix(t).unwrap();
        let spatial = RigidBody::<f64>::new(m, &tensor).unwrap();
        let planar = PlanarBody::<f64>::new(m, tensor.izz()).unwrap();
        let mut x = EulerState::zeros();
        (x[0], x[1], x[5], x[11]) = (u, v, r, psi);
        let s = spatial.rhs_euler(&x, &Vector3::new(fx, fy, 0.0), &Vector3::new(0.0, 0.0, mz));
        let p = planar.rhs_body_at_g(&Vector6::new(u, v, r, 0.0, 0.0, psi), &Vector3::new(fx, fy, mz));
        let reduced = Vector6::new(s[0], s[1], s[5], s[6], s[7], s[11]);
        let out_of_plane = Vector6::new(s[2], s[3], s[4], s[8], s[9], s[10]);
        // Relative 1e-13: the two forms round the same products differently (ṙ goes through
        // the 3×3 inverse), a few ulps each.
        let scale = 1.0 + (fx.abs() + fy.abs()) / m + (u.abs() + v.abs()) * (1.0 + r.abs())
            + mz.abs() / tensor.izz();
        prop_assert!((reduced - p).abs().max() <= 1e-13 * scale, "{reduced} vs {p}");
        prop_assert!(out_of_plane.abs().max() <= 1e-13 * scale, "{out_of_plane}");
    }

    #[test]
    fn torque_free_motion_conserves_energy_and_angular_momentum(
        body in body(), state in euler_state(),
    ) {
        let zero = Vector3::zeros();
        let rate = body.rhs_euler(&state, &zero, &zero);
        let (v, w) = (part(state.as_slice(), 0), part(state.as_slice(), 3));
        let (v_dot, w_dot) = (part(rate.as_slice(), 0), part(rate.as_slice(), 3));
        let h = body.angular_momentum(&w);
        let m = body.mass();
        // dT/dt = M v·v̇ + ω·[I]ω̇ (4.32, [I] symmetric); d|H|²/dt = 2 H·[I]ω̇ (the norm is
        // the same in body and space axes).
        let energy_rate = m * v.dot(&v_dot) + w.dot(&(body.inertia() * w_dot));
        let momentum_rate = 2.0 * h.dot(&(body.inertia() * w_dot));
        // Both vanish exactly in exact arithmetic. Roundoff: ω̇ = [I]⁻¹(−ω×H) carries a
        // relative error of order EPS·cond([I]) on a vector of size |ω||H|‖[I]⁻¹‖; 64 ulps of
        // the resulting scale covers the few dozen operations.
        let kappa = condition(&body);
        let energy_scale = m * v.norm_squared() * w.norm() + kappa * w.norm_squared() * h.norm();
        let momentum_scale = kappa * w.norm() * h.norm_squared();
        prop_assert!(energy_rate.abs() <= 64.0 * EPS * energy_scale, "{energy_rate:e} vs {energy_scale:e}");
        prop_assert!(momentum_rate.abs() <= 64.0 * EPS * momentum_scale, "{momentum_rate:e} vs {momentum_scale:e}");
    }

    #[test]
    fn kinetic_energy_rate_equals_power_of_force_and_moment(
        body in body(), state in euler_state(), force in vec3(100.0), moment in vec3(100.0),
    ) {
        let rate = body.rhs_euler(&state, &force, &moment);
        let (v, w) = (part(state.as_slice(), 0), part(state.as_slice(), 3));
        let (v_dot, w_dot) = (part(rate.as_slice(), 0), part(rate.as_slice(), 3));
        let energy_rate = body.mass() * v.dot(&v_dot) + w.dot(&(body.inertia() * w_dot));
        let power = force.dot(&v) + moment.dot(&w);
        // As above, with the load's terms added to the scale.
        let kappa = condition(&body);
        let h = body.angular_momentum(&w);
        let scale = force.norm() * v.norm() + kappa * moment.norm() * w.norm()
            + body.mass() * v.norm_squared() * w.norm() + kappa * w.norm_squared() * h.norm();
        prop_assert!((energy_rate - power).abs() <= 64.0 * EPS * scale);
    }

    #[test]
    fn kinetic_energy_4_32_changes_at_the_rate_the_equations_give(
        body in body(), state in euler_state(), force in vec3(100.0), moment in vec3(100.0),
    ) {
        let rate = body.rhs_euler(&state, &force, &moment);
        let (v, w) = (part(state.as_slice(), 0), part(state.as_slice(), 3));
        let (v_dot, w_dot) = (part(rate.as_slice(), 0), part(rate.as_slice(), 3));
        let energy_rate = body.mass() * v.dot(&v_dot) + w.dot(&(body.inertia() * w_dot));
        // T is quadratic in (v, ω), so the central difference along (v̇, ω̇) is exact for any
        // step h; only the roundoff of the two energies, EPS (T₊ + T₋)/h, remains.
        let h = (v.norm() + w.norm()) / (v_dot.norm() + w_dot.norm());
        let t = |s: f64| body.kinetic_energy(&(v + v_dot * s), &(w + w_dot * s));
        let (ahead, behind) = (t(h), t(-h));
        let difference = (ahead - behind) / (2.0 * h);
        let scale = (ahead + behind) / h;
        prop_assert!((difference - energy_rate).abs() <= 16.0 * EPS * scale);
    }

    #[test]
    fn angular_acceleration_satisfies_euler_equations_4_51(
        body in body(), w in body_rates_vector(), moment in vec3(100.0),
    ) {
        let d = body.angular_acceleration(&w, &moment);
        let i = body.inertia();
        let (p, q, r) = (w.x, w.y, w.z);
        let (ixx, iyy, izz) = (i[(0, 0)], i[(1, 1)], i[(2, 2)]);
        let (ixy, iyz, izx) = (i[(0, 1)], i[(1, 2)], i[(2, 0)]);
        // 4.51 as the chapter writes it, x component and its two cyclic permutations.
        let residual = Vector3::new(
            ixx * d.x + (izz - iyy) * q * r + ixy * (d.y - r * p) + izx * (d.z + p * q)
                + iyz * (q * q - r * r) - moment.x,
            iyy * d.y + (ixx - izz) * r * p + iyz * (d.z - p * q) + ixy * (d.x + q * r)
                + izx * (r * r - p * p) - moment.y,
            izz * d.z + (iyy - ixx) * p * q + izx * (d.x - q * r) + iyz * (d.y + r * p)
                + ixy * (p * p - q * q) - moment.z,
        );
        // Relative to |M| + ‖[I]‖|ω|² + ‖[I]‖|ω̇|, the sizes of the terms; 64 ulps after the
        // cond([I]) amplification of the solve.
        let scale = moment.norm() + i.norm() * (w.norm_squared() + d.norm());
        prop_assert!(residual.norm() <= 64.0 * EPS * condition(&body) * scale, "{residual}");
    }

    #[test]
    fn euler_rates_invert_body_rates_4_59(state in euler_state()) {
        let (w, phi, theta) = (part(state.as_slice(), 3), state[9], state[10]);
        let back = body_rates(phi, theta, &euler_rates(phi, theta, &w));
        // |cos θ| ≥ 0.18 here, so 4.60 amplifies roundoff by at most 6; 1e-14 relative.
        prop_assert!((back - w).norm() <= 1e-14 * (1.0 + w.norm()));
    }

    #[test]
    fn euler_rates_near_gimbal_lock_degrade_only_as_sec_theta(
        w in body_rates_vector(), phi in -PI..PI, decade in -6.0..-1.0f64, up in any::<bool>(),
    ) {
        // Pitch within 1e-6 to 0.1 rad of ±90°: 4.60 is finite but ill-conditioned there.
        let theta = if up { 1.0 } else { -1.0 } * (FRAC_PI_2 - 10f64.powf(decade));
        let back = body_rates(phi, theta, &euler_rates(phi, theta, &w));
        // The rates are of size |ω|/|cos θ| and 4.59 cancels them back to |ω|, so the error
        // is a few ulps of |ω|/|cos θ|; 64 ulps bounds it.
        prop_assert!((back - w).norm() <= 64.0 * EPS * w.norm() / theta.cos().abs());
    }

    #[test]
    fn body_to_space_is_rz_ry_rx_4_57(phi in -PI..PI, theta in -PI..PI, psi in -PI..PI) {
        let e = body_to_space(phi, theta, psi);
        let product = Rotation3::from_axis_angle(&Vector3::z_axis(), psi)
            * Rotation3::from_axis_angle(&Vector3::y_axis(), theta)
            * Rotation3::from_axis_angle(&Vector3::x_axis(), phi);
        // Entries of size ≤ 1, a few roundings each.
        prop_assert!((e.matrix() - product.matrix()).abs().max() <= 1e-15);
        let via_quaternion = quaternion_from_euler(phi, theta, psi).to_rotation_matrix();
        prop_assert!((e.matrix() - via_quaternion.matrix()).abs().max() <= 1e-15);
    }

    #[test]
    fn quaternion_rate_keeps_the_norm_and_position_rate_ignores_it(
        body in body(), state in euler_state(), scale in 0.5..2.0f64,
    ) {
        let x = euler_state_to_quaternion_state(&state);
        let mut stretched = x;
        stretched.fixed_rows_mut::<4>(9).scale_mut(scale);
        let zero = Vector3::zeros();
        let (a, b) = (body.rhs_quaternion(&x, &zero, &zero), body.rhs_quaternion(&stretched, &zero, &zero));
        // q·q̇ = ½ q·(q ⊗ (0, ω)) = 0 exactly in exact arithmetic; |q| = 1 and |q̇| ≤ |ω|/2.
        let w = part(state.as_slice(), 3).norm();
        prop_assert!(x.fixed_rows::<4>(9).dot(&a.fixed_rows::<4>(9)).abs() <= 8.0 * EPS * (1.0 + w));
        // The position rate uses the normalised quaternion: unchanged by the stretch up to
        // the rounding of the normalisation.
        let speed = part(state.as_slice(), 0).norm();
        prop_assert!((a.fixed_rows::<3>(6) - b.fixed_rows::<3>(6)).norm() <= 1e-14 * (1.0 + speed));
        // Round trip back to Euler angles (θ within ±80°, so unique).
        let back = quaternion_state_to_euler_state(&x);
        prop_assert!((back - state).abs().max() <= 1e-12 * (1.0 + state.abs().max()));
    }

    #[test]
    fn pendulum_energy_rate_equals_applied_power_4_35(
        i_g in 0.01..10.0f64, m in 0.1..10.0f64, h in 0.0..2.0f64, g in 0.0..20.0f64,
        theta in -PI..PI, theta_dot in -10.0..10.0f64, moment in -10.0..10.0f64,
    ) {
        let i0 = i_g + m * h * h;
        let p = Pendulum::<f64>::new(&PendulumParameters::new(i0, m, g, h).unwrap());
        let d = p.rhs(&Vector2::new(theta, theta_dot), moment);
        // dE/dt = I₀ θ̇ θ̈ + M g h sin θ θ̇ = moment·θ̇ (4.35 with the applied moment's power).
        let energy_rate = i0 * theta_dot * d[1] + m * g * h * theta.sin() * theta_dot;
        let scale = (m * g * h + moment.abs()) * theta_dot.abs();
        // Relative 1e-14: two products and a sum, then cancellation against the power.
        prop_assert!((energy_rate - moment * theta_dot).abs() <= 1e-14 * scale.max(1e-300));
        prop_assert_eq!(d[0], theta_dot);
    }
}

#[test]
fn f32_spatial_form_agrees_with_f64() {
    let tensor = InertiaTensor::new(2.0, 3.0, 4.5, -0.2, 0.1, 0.3).unwrap();
    let wide = RigidBody::<f64>::new(7.0, &tensor).unwrap();
    let narrow = RigidBody::<f32>::new(7.0, &tensor).unwrap();
    let state = EulerState::from_fn(|i, _| 0.3 + 0.17 * i as f64 - 0.05 * (i * i) as f64);
    let (force, moment) = (Vector3::new(3.0, -1.0, 2.0), Vector3::new(-0.5, 1.5, 0.25));
    let a = wide.rhs_euler(&state, &force, &moment);
    let b = narrow.rhs_euler(&state.cast::<f32>(), &force.cast(), &moment.cast());
    // f32 has 6e-8 unit roundoff; the tensor's condition number is below 3 and entries are
    // O(10), so 1e-5 relative to the largest entry is a margin of tens.
    let scale = a.abs().max();
    assert!(
        (a - b.cast::<f64>()).abs().max() <= 1e-5 * scale,
        "{a} vs {b}"
    );
    let q = narrow.rhs_quaternion(
        &euler_state_to_quaternion_state(&state.cast()),
        &force.cast(),
        &moment.cast(),
    );
    assert_eq!(q.fixed_rows::<6>(0), b.fixed_rows::<6>(0));
}

#[test]
fn euler_form_at_gimbal_lock_is_flagged_and_quaternion_form_is_finite() {
    let tensor = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.0).unwrap();
    let body = RigidBody::<f64>::new(1.0, &tensor).unwrap();
    let state = EulerState::from_fn(|i, _| if i == 10 { FRAC_PI_2 } else { 0.5 });
    let err = check_pitch(state[10], 1e-6).unwrap_err();
    assert!(matches!(err, ModelError::GimbalLock { .. }), "{err}");
    assert!(check_pitch(FRAC_PI_2 - 1e-3, 1e-6).is_ok());
    let zero = Vector3::zeros();
    // The Euler form does not panic at θ = 90° (in f64, cos θ = 6e-17, not zero), and its
    // accelerations and position rate do not involve 4.60, so they still agree with the
    // quaternion form's.
    let euler = body.rhs_euler(&state, &zero, &zero);
    let quat = body.rhs_quaternion(&euler_state_to_quaternion_state(&state), &zero, &zero);
    assert!(quat.iter().all(|x| x.is_finite()));
    assert!(
        (euler.fixed_rows::<9>(0) - quat.fixed_rows::<9>(0))
            .abs()
            .max()
            <= 1e-14
    );
}

#[test]
fn bad_parameters_are_refused_and_named() {
    let tensor = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.0).unwrap();
    let field =
        |e: ModelError, name: &str| matches!(e, ModelError::Parameter(p) if p.field == name);
    let mass = |e: ModelError| field(e, "mass");
    assert!(mass(RigidBody::<f64>::new(f64::NAN, &tensor).unwrap_err()));
    assert!(mass(RigidBody::<f64>::new(-1.0, &tensor).unwrap_err()));
    assert!(mass(RigidBody::<f32>::new(0.0, &tensor).unwrap_err()));
    // The pendulum's parameters are refused by `PendulumParameters::new`, before any form.
    assert!(field(PlanarBody::<f64>::new(1.0, 0.0).unwrap_err(), "izz"));
    assert!(mass(PlanarBody::<f64>::new(-2.0, 1.0).unwrap_err()));
    assert!(field(
        PlanarMidship::<f64>::new(1.0, 1.0, f64::INFINITY).unwrap_err(),
        "x_g"
    ));
    assert!(field(
        PlanarMidship::<f64>::new(1.0, f64::NAN, 0.1).unwrap_err(),
        "izz"
    ));
    let message = RigidBody::<f64>::new(-3.0, &tensor)
        .unwrap_err()
        .to_string();
    assert_eq!(message, "mass must be positive and finite, got -3");
}

#[test]
fn quaternion_state_carries_the_attitude_of_the_euler_angles() {
    let mut state = EulerState::zeros();
    (state[9], state[10], state[11]) = (0.1, -0.4, 2.0);
    let q = euler_state_to_quaternion_state(&state);
    let unit = UnitQuaternion::new_normalize(Quaternion::new(q[9], q[10], q[11], q[12]));
    let e = body_to_space(0.1, -0.4, 2.0);
    // Two exact constructions of one rotation, entries ≤ 1.
    assert!(
        (unit.to_rotation_matrix().matrix() - e.matrix())
            .abs()
            .max()
            <= 1e-15
    );
}
