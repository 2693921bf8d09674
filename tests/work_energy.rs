//! The work–energy theorem on the generated right-hand sides: the rate of change of the
//! kinetic energy (4.30–4.32) computed from the accelerations a model returns equals the power
//! of the loads applied to it; without loads the kinetic energy and |H|² are constant.
//!
//! Nothing here refers to the generic forms: the identities hold for the exact equations, so
//! a generated model that satisfies them to round-off at random states has its dynamics right
//! up to terms that do no work.

use eom::energy::kinetic_energy;
use eom::models::{Model, Pendulum, PlanarAtG, PlanarMidship, PlanarSpaceFixed};
use eom_test_support::properties;
use eom_test_support::properties::{
    Kinematics, PendulumCase, Pitch, PlanarCase, Spatial, SpatialCase, Symmetry, at_g_scale,
    generated, inverse_scale, midship_scale, pendulum_case, pendulum_scale, planar_case,
    space_fixed_scale, spatial_case, spatial_scale,
};
use nalgebra::{Matrix3, Vector3};

/// An identity evaluated in f64 through a generated right-hand side: the accelerations are
/// within ~16·(ε/2) of their term sizes (the scale of `eom_test_support::properties`), and forming the power and
/// M v·v̇ + ω·[I]ω̇ from them adds at most ~8 roundings more, so the two sides differ by at most
/// ~12ε times the size of the terms; 64ε allows a factor of five.
const TOLERANCE: f64 = 64.0 * f64::EPSILON;

/// The accelerations v̇ and ω̇ a generated model returns, and their term sizes.
struct Rates {
    velocity: Vector3<f64>,
    omega: Vector3<f64>,
    velocity_scale: Vector3<f64>,
    omega_scale: Vector3<f64>,
    /// The rest of the state's rate (attitude rates) and its term sizes.
    attitude: Vec<f64>,
    attitude_scale: Vec<f64>,
}

fn rates<S: Spatial<f64>>(case: &SpatialCase) -> Rates {
    let out = generated::<S>(case);
    let inverse = inverse_scale(&case.tensor.matrix()).terms;
    let scale = spatial_scale(case, S::KINEMATICS, &inverse);
    Rates {
        velocity: Vector3::from_column_slice(&out[0..3]),
        omega: Vector3::from_column_slice(&out[3..6]),
        velocity_scale: Vector3::from_column_slice(&scale[0..3]),
        omega_scale: Vector3::from_column_slice(&scale[3..6]),
        attitude: out[9..].to_vec(),
        attitude_scale: scale[9..].to_vec(),
    }
}

/// |dT/dt − (F·v + M·ω)| over the size of the terms, with dT/dt = M v·v̇ + ω·[I]ω̇ (the time
/// derivative of 4.32 in body axes: both quadratic forms are frame-invariant).
fn spatial_power_gap<S: Spatial<f64>>(case: &SpatialCase) -> f64 {
    let r = rates::<S>(case);
    let inertia = case.tensor.matrix();
    let (v, w) = (case.velocity, case.omega);
    let d_kinetic = case.mass * v.dot(&r.velocity) + w.dot(&(inertia * r.omega));
    let power = case.force.dot(&v) + case.moment.dot(&w);
    let scale = case.mass * v.abs().dot(&r.velocity_scale)
        + w.abs().dot(&(inertia.abs() * r.omega_scale))
        + case.force.abs().dot(&v.abs())
        + case.moment.abs().dot(&w.abs());
    (d_kinetic - power).abs() / scale
}

/// Without loads: dT/dt = 0 and d|H|²/dt = 2H·[I]ω̇ = 0 (H = [I]ω, 4.15), and for a
/// quaternion variant d|q|²/dt = 2q·q̇ = 0. Returns the largest of the three gaps.
fn torque_free_gap<S: Spatial<f64>>(case: &SpatialCase) -> f64 {
    let case = case.torque_free();
    let energy = spatial_power_gap::<S>(&case);
    let r = rates::<S>(&case);
    let inertia: Matrix3<f64> = case.tensor.matrix();
    let h = inertia * case.omega;
    let h_terms = inertia.abs() * case.omega.abs();
    let momentum =
        h.dot(&(inertia * r.omega)).abs() / h_terms.dot(&(inertia.abs() * r.omega_scale));
    let quaternion = match S::KINEMATICS {
        Kinematics::Euler => 0.0,
        Kinematics::Quaternion => {
            let q = case.state(Kinematics::Quaternion).split_off(9);
            let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
            let terms = dot(
                &q.iter().map(|x| x.abs()).collect::<Vec<_>>(),
                &r.attitude_scale,
            );
            dot(&q, &r.attitude).abs() / terms
        }
    };
    energy.max(momentum).max(quaternion)
}

/// At G: dT/dt = M(u u̇ + v v̇) + I_zz r ṙ against the power F_x u + F_y v + M_z r.
fn at_g_power_gap(case: &PlanarCase) -> f64 {
    let rate = PlanarAtG::<f64>::new(case.mass, case.izz)
        .unwrap()
        .rhs(&case.state, &case.load);
    let [u, v, r, ..] = case.state;
    let s = at_g_scale(case);
    let (m, izz) = (case.mass, case.izz);
    let d_kinetic = m * (u * rate[0] + v * rate[1]) + izz * r * rate[2];
    let power = case.load[0] * u + case.load[1] * v + case.load[2] * r;
    let scale = m * (u.abs() * s[0] + v.abs() * s[1])
        + izz * r.abs() * s[2]
        + [u, v, r]
            .iter()
            .zip(case.load)
            .map(|(x, f)| (x * f).abs())
            .sum::<f64>();
    (d_kinetic - power).abs() / scale
}

/// At midship, G at (x_G, 0, 0). The kinetic energy is T = ½M(u² + v_G²) + ½I_zz r² with
/// v_G = v + x_G r (4.45), so dT/dt = M(u u̇ + v_G(v̇ + x_G ṙ)) + I_zz r ṙ.
///
/// The power of the loads is the force dotted with the velocity of the point the moment is
/// taken about, plus the moment times r: (X, Y) are applied with N about midship, so the power
/// is X u + Y v + N r with the midship velocities. Check against the loads at G: the moment
/// about G is M_z = N − Y x_G (4.45) and G moves with (u, v_G), so
/// X u + Y v_G + M_z r = X u + Y v + Y x_G r + N r − Y x_G r = X u + Y v + N r.
fn midship_power_gap(case: &PlanarCase) -> f64 {
    let rate = PlanarMidship::<f64>::new(case.mass, case.izz, case.x_g)
        .unwrap()
        .rhs(&case.state, &case.load);
    let [u, v, r, ..] = case.state;
    let s = midship_scale(case, false);
    let (m, izz, x_g) = (case.mass, case.izz, case.x_g);
    let v_g = v + x_g * r;
    let d_kinetic = m * (u * rate[0] + v_g * (rate[1] + x_g * rate[2])) + izz * r * rate[2];
    let power = case.load[0] * u + case.load[1] * v + case.load[2] * r;
    let v_g_terms = v.abs() + (x_g * r).abs();
    let scale = m * (u.abs() * s[0] + v_g_terms * (s[1] + x_g.abs() * s[2]))
        + izz * r.abs() * s[2]
        + [u, v, r]
            .iter()
            .zip(case.load)
            .map(|(x, f)| (x * f).abs())
            .sum::<f64>();
    (d_kinetic - power).abs() / scale
}

/// Space-fixed: dT/dt = M(Ẋ Ẍ + Ẏ Ÿ) + I_zz ψ̇ ψ̈ against F_X Ẋ + F_Y Ẏ + M_z ψ̇.
fn space_fixed_power_gap(case: &PlanarCase) -> f64 {
    let state = case.space_fixed_state();
    let rate = PlanarSpaceFixed::<f64>::new(case.mass, case.izz)
        .unwrap()
        .rhs(&state, &case.load);
    let s = space_fixed_scale(case);
    let (m, izz) = (case.mass, case.izz);
    let [x_dot, y_dot, psi_dot] = [state[3], state[4], state[5]];
    let d_kinetic = m * (x_dot * rate[3] + y_dot * rate[4]) + izz * psi_dot * rate[5];
    let power = case.load[0] * x_dot + case.load[1] * y_dot + case.load[2] * psi_dot;
    let scale = m * (x_dot.abs() * s[3] + y_dot.abs() * s[4])
        + izz * psi_dot.abs() * s[5]
        + [x_dot, y_dot, psi_dot]
            .iter()
            .zip(case.load)
            .map(|(x, f)| (x * f).abs())
            .sum::<f64>();
    (d_kinetic - power).abs() / scale
}

/// The pendulum with gravity's work as potential energy (4.34): d(T + U)/dt =
/// I₀ θ̇ θ̈ + M g h sin θ θ̇ against the power of the applied moment, M_O θ̇.
fn pendulum_power_gap(case: &PendulumCase) -> f64 {
    let (i0, m, g, h) = (case.i0, case.mass, case.g, case.h);
    let rate = Pendulum::<f64>::new(&case.parameters()).rhs(&case.state, &[case.moment]);
    let [theta, theta_dot] = case.state;
    let d_energy = i0 * theta_dot * rate[1] + m * g * h * theta.sin() * theta_dot;
    let power = case.moment * theta_dot;
    let s = pendulum_scale(case);
    let scale =
        i0 * theta_dot.abs() * s[1] + (m * g * h * theta.sin() * theta_dot).abs() + power.abs();
    (d_energy - power).abs() / scale
}

/// The kinetic energy a spatial model reports is 4.32 as `eom::energy` computes it.
fn kinetic_energy_gap<S: Spatial<f64>>(case: &SpatialCase) -> f64 {
    let model = S::build(case.mass, &case.tensor).unwrap();
    let ours = model.kinetic(&case.state(S::KINEMATICS));
    let theirs = kinetic_energy(
        case.mass,
        &case.velocity,
        &case.tensor.matrix(),
        &case.omega,
    );
    // Both are sums of positive terms (ωᵀ[I]ω adds products of either sign, bounded by the
    // absolute form): relative to that, a dozen roundings.
    let terms = 0.5 * case.mass * case.velocity.norm_squared()
        + 0.5
            * case
                .omega
                .abs()
                .dot(&(case.tensor.matrix().abs() * case.omega.abs()));
    (ours - theirs).abs() / terms
}

properties! {
    planar_at_g_kinetic_energy_rate_is_the_power: planar_case(), at_g_power_gap, TOLERANCE;
    planar_midship_kinetic_energy_rate_is_x_u_plus_y_v_plus_n_r: planar_case(), midship_power_gap, TOLERANCE;
    planar_space_fixed_kinetic_energy_rate_is_the_power: planar_case(), space_fixed_power_gap, TOLERANCE;
    pendulum_energy_rate_is_the_power_of_the_applied_moment: pendulum_case(), pendulum_power_gap, TOLERANCE;
}

/// For every spatial variant of the catalog: the kinetic energy's rate is the power of the
/// loads; without loads energy, |H|² and |q|² stay constant; the energy it reports is 4.32.
macro_rules! spatial_properties {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {
        $(spatial_properties!(@item $module $type $family $(($($option),+))?);)*
    };
    (@item $module:ident $type:ident Spatial($symmetry:ident, $kinematics:ident)) => {
        mod $module {
            use super::*;
            type Variant = eom::models::$type<f64>;
            const CLASS: Symmetry = Symmetry::$symmetry;

            properties! {
                kinetic_energy_rate_is_the_power: spatial_case(CLASS, Pitch::Random), spatial_power_gap::<Variant>, TOLERANCE;
                torque_free_keeps_energy_momentum_and_unit_quaternion: spatial_case(CLASS, Pitch::Random), torque_free_gap::<Variant>, TOLERANCE;
                reports_the_kinetic_energy_of_4_32: spatial_case(CLASS, Pitch::Random), kinetic_energy_gap::<Variant>, TOLERANCE;
            }
        }
    };
    (@item $($other:tt)*) => {};
}

eom::for_each_model!(spatial_properties);
