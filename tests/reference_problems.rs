//! The exact solutions of the reference problems are checked against the mathematics they
//! come from: each satisfies its differential equation (by finite differences), starts where
//! the problem starts, and conserves what the flow conserves. None of this uses an integrator.

use eom::integrate::OdeSystem;
use eom::reference::{AxisymmetricTop, LargeSwing, PlanarTurn, ReferenceProblem, TennisRacket};
use eom::{ParameterError, PendulumParameters};
use eom_test_support::bodies::{racket, top};
use nalgebra::{SVector, UnitQuaternion, Vector3};

/// The largest relative mismatch between the central difference of `exact` and the RHS of
/// `system` along the exact solution, at 20 times in [0, t_end]. Step 1e-5: truncation
/// O(h²|y‴|) ≈ 1e-10 and round-off O(ε/h) ≈ 1e-11 for states and rates of order one.
fn derivative_mismatch<const N: usize>(
    exact: impl Fn(f64) -> SVector<f64, N>,
    system: &impl OdeSystem<f64, N>,
    t_end: f64,
) -> f64 {
    let h = 1e-5;
    let mut worst: f64 = 0.0;
    for i in 0..20 {
        let t = t_end * f64::from(i) / 19.0 + 0.1;
        let difference = (exact(t + h) - exact(t - h)) / (2.0 * h);
        let mut rhs = SVector::<f64, N>::zeros();
        system.rhs(t, &exact(t), &mut rhs);
        worst = worst.max((difference - rhs).amax() / rhs.amax().max(1.0));
    }
    worst
}

fn pendulum_parameters() -> PendulumParameters {
    PendulumParameters::new(2.0, 3.0, 9.81, 0.5).unwrap()
}

fn pendulum() -> LargeSwing {
    // θ₀ = 150°: far outside the small-angle regime (the period is 1.76× that of 4.27).
    LargeSwing::new(&pendulum_parameters(), 150f64.to_radians()).unwrap()
}

fn turn() -> PlanarTurn {
    PlanarTurn::new(1000.0, 0.2, (300.0, -150.0), (5.0, 0.4)).unwrap()
}

#[test]
fn pendulum_exact_solution_satisfies_4_24() {
    let p = pendulum();
    assert!(derivative_mismatch(|t| p.exact(t), &p, 2.0 * p.period()) < 1e-8);
}

#[test]
fn pendulum_starts_at_rest_at_theta0_and_returns_after_one_period() {
    let p = pendulum();
    // 1e-12: sn(K) = 1 to round-off, and the periodicity of sn is exact in the AGM algorithm
    // up to the rounding of 4K.
    assert!((p.exact(0.0) - p.initial_state()).amax() < 1e-12);
    assert!((p.exact(p.period()) - p.initial_state()).amax() < 1e-12);
    // Released from rest, it first swings towards θ = 0.
    let just_after = p.exact(1e-3 * p.period());
    assert!(just_after[0] < p.theta0() && just_after[1] < 0.0);
    // Half a period later it is at rest on the other side.
    let half = p.exact(0.5 * p.period());
    assert!((half[0] + 150f64.to_radians()).abs() < 1e-12 && half[1].abs() < 1e-10);
}

#[test]
fn pendulum_period_tends_to_4_27_at_small_amplitude() {
    // At θ₀ = 1e-3, 4K(m)/ω₀ = (2π/ω₀)(1 + θ₀²/16 + …): relative excess 6.25e-8.
    let p = LargeSwing::new(&pendulum_parameters(), 1e-3).unwrap();
    let small = std::f64::consts::TAU / p.omega0();
    let excess = p.period() / small - 1.0;
    assert!((excess - 6.25e-8).abs() < 1e-11, "excess {excess}");
}

#[test]
fn pendulum_exact_solution_conserves_energy_4_35() {
    let p = pendulum();
    let e0 = p.energy(&p.initial_state());
    for i in 0..50 {
        let e = p.energy(&p.exact(0.1 * f64::from(i)));
        // 1e-13 relative: two evaluations of elementary functions near round-off.
        assert!((e / e0 - 1.0).abs() < 1e-13);
    }
}

#[test]
fn axisymmetric_exact_solution_satisfies_euler_and_quaternion_equations() {
    let top = top();
    assert!(derivative_mismatch(|t| top.exact(t), &top.body(), top.t_end()) < 1e-8);
}

#[test]
fn axisymmetric_exact_solution_keeps_angular_momentum_fixed_in_space() {
    let top = top();
    let moments = top.body().moments;
    let h_space = |t: f64| top.attitude(t) * moments.component_mul(&top.rates(t));
    for i in 0..20 {
        // 1e-13 relative: a rotation of a vector of order one, composed of three quaternions.
        assert!((h_space(0.7 * f64::from(i)) - h_space(0.0)).norm() < 1e-13 * h_space(0.0).norm());
    }
}

#[test]
fn tennis_racket_exact_rates_satisfy_euler_equations_4_52() {
    let racket = racket();
    let state = |t: f64| {
        let w = racket.rates(t);
        SVector::<f64, 3>::new(w.x, w.y, w.z)
    };
    let moments = racket.body().moments;
    let euler = move |_t: f64, w: &SVector<f64, 3>, dw: &mut SVector<f64, 3>| {
        let (i1, i2, i3) = (moments.x, moments.y, moments.z);
        *dw = SVector::<f64, 3>::new(
            (i2 - i3) * w.y * w.z / i1,
            (i3 - i1) * w.z * w.x / i2,
            (i1 - i2) * w.x * w.y / i3,
        );
    };
    assert!(derivative_mismatch(state, &euler, racket.period()) < 1e-8);
}

#[test]
fn tennis_racket_exact_rates_conserve_energy_and_momentum() {
    let racket = racket();
    let y0 = racket.initial_state();
    let i0 = racket.invariants(&y0);
    for k in 0..40 {
        let w = racket.rates(racket.period() * f64::from(k) / 39.0);
        let y = SVector::<f64, 7>::from([w.x, w.y, w.z, 1.0, 0.0, 0.0, 0.0]);
        for (a, b) in racket.invariants(&y).iter().zip(&i0) {
            // 1e-13 relative: sn² + cn² = 1 and dn² + m sn² = 1 hold to a few ulps.
            assert!((a / b - 1.0).abs() < 1e-13);
        }
    }
}

#[test]
fn tennis_racket_starts_at_its_initial_state_and_flips_twice_per_period() {
    let racket = racket();
    let w0 = racket.rates(0.0);
    // 1e-12: cn(K) vanishes to round-off of K.
    assert!((w0 - Vector3::new(0.0, 1.0, 0.1)).amax() < 1e-12);
    let half = racket.rates(0.5 * racket.period());
    assert!(
        (half - Vector3::new(0.0, -1.0, 0.1)).amax() < 1e-10,
        "flipped: {half}"
    );
    let full = racket.rates(racket.period());
    assert!((full - w0).amax() < 1e-10);
    // Between the flips the body turns mostly about its intermediate axis 2.
    assert!(racket.parameter() > 0.9);
}

#[test]
fn planar_turn_exact_solution_satisfies_4_43_and_4_44() {
    let turn = turn();
    assert!(derivative_mismatch(|t| turn.exact(t), &turn, turn.t_end()) < 1e-8);
    assert!((turn.exact(0.0) - turn.initial_state()).amax() < 1e-15);
}

#[test]
fn planar_turn_speed_relative_to_the_steady_turn_is_constant() {
    let turn = turn();
    let c0 = turn.invariants(&turn.initial_state())[0];
    for i in 0..30 {
        let c = turn.invariants(&turn.exact(2.0 * f64::from(i)))[0];
        // 1e-14 relative: one complex rotation of a value of order one.
        assert!((c / c0 - 1.0).abs() < 1e-14);
    }
}

#[test]
fn reference_problems_reject_impossible_parameters_naming_them() {
    let named = |e: ParameterError| e.field;
    let bad_mass = PendulumParameters::new(2.0, -1.0, 9.81, 0.5).unwrap_err();
    assert_eq!(named(bad_mass), "mass");
    let over_the_top = LargeSwing::new(&pendulum_parameters(), 4.0).unwrap_err();
    assert_eq!(named(over_the_top), "theta0");
    let upside_down = PendulumParameters::new(2.0, 1.0, -9.81, 0.5).unwrap();
    assert_eq!(named(LargeSwing::new(&upside_down, 1.0).unwrap_err()), "g");
    let unordered = TennisRacket::new(
        Vector3::new(2.0, 1.0, 3.0),
        1.0,
        0.1,
        UnitQuaternion::identity(),
    );
    assert_eq!(named(unordered.unwrap_err()), "I2");
    let on_axis = TennisRacket::new(
        Vector3::new(1.0, 2.0, 3.0),
        1.0,
        0.0,
        UnitQuaternion::identity(),
    );
    assert_eq!(named(on_axis.unwrap_err()), "omega3");
    assert_eq!(
        named(PlanarTurn::new(1.0, 0.0, (1.0, 0.0), (1.0, 0.0)).unwrap_err()),
        "r"
    );
    let nan_inertia = AxisymmetricTop::new(f64::NAN, 1.0, Vector3::x(), UnitQuaternion::identity());
    assert_eq!(named(nan_inertia.unwrap_err()), "i1");
}
