//! The compound pendulum (4.24–4.29), its exact large-amplitude motion, its energy (4.33–4.35)
//! and the swing test that recovers κ_G from a measured period.

use eom::energy::{pendulum_kinetic_energy, pendulum_potential_energy};
use eom::swing::{
    STANDARD_GRAVITY, SwingError, SwingTest, SwungBody, measure_period, period_factor,
};
use eom::{ParameterError, PendulumParameters};

/// A model-ship-like body: κ_G = 0.25 m, swung 0.12 m from G, 20 kg.
const KAPPA_G: f64 = 0.25;
const PIVOT_TO_CG: f64 = 0.12;
const MASS: f64 = 20.0;

fn pendulum() -> SwungBody {
    let parameters =
        PendulumParameters::from_gyradius(KAPPA_G, MASS, STANDARD_GRAVITY, PIVOT_TO_CG).unwrap();
    SwungBody::new(&parameters).unwrap()
}

fn swing_test(period: f64, amplitude: f64) -> SwingTest {
    SwingTest {
        period,
        pivot_to_cg: PIVOT_TO_CG,
        mass: MASS,
        gravity: STANDARD_GRAVITY,
        amplitude,
    }
}

#[test]
fn small_amplitude_period_inverts_4_27_through_4_28_and_4_29() {
    let p = pendulum();
    let test = p.measurement(0.0).unwrap();
    assert_eq!(test, swing_test(p.small_amplitude_period(), 0.0));
    let result = test.solve().unwrap();
    let i0 = MASS * (KAPPA_G * KAPPA_G + PIVOT_TO_CG * PIVOT_TO_CG);
    // Relative 1e-14: a square root, a division and a subtraction of nearby squares.
    assert!((result.kappa_g - KAPPA_G).abs() < 1e-14 * KAPPA_G);
    assert!((result.inertia_pivot - i0).abs() < 1e-14 * i0);
    assert!((result.inertia_g - MASS * KAPPA_G * KAPPA_G).abs() < 1e-13 * MASS * KAPPA_G * KAPPA_G);
    let length = result.kappa_pivot.powi(2) / PIVOT_TO_CG;
    assert!((result.equivalent_length - length).abs() < 1e-15 * length);
    assert_eq!(result.period_factor, 1.0);
}

#[test]
fn period_factor_matches_its_series_at_small_amplitude() {
    // T/T₀ = 1 + θ²/16 + 11θ⁴/3072 + 173θ⁶/737280 + O(θ⁸); at θ = 0.1 the next term is 2e-13.
    for theta in [0.01_f64, 0.05, 0.1] {
        let series = 1.0
            + theta.powi(2) / 16.0
            + 11.0 * theta.powi(4) / 3072.0
            + 173.0 * theta.powi(6) / 737_280.0;
        assert!((period_factor(theta).unwrap() - series).abs() < 1e-12);
    }
}

#[test]
fn exact_swing_satisfies_4_24() {
    // Central differences with step 1e-5: truncation O(h²) ≈ 1e-10, rounding ε/h ≈ 1e-11.
    let p = pendulum();
    let omega0_squared = p.natural_frequency().powi(2);
    for degrees in [10.0, 90.0, 160.0] {
        let swing = p.released_from(f64::to_radians(degrees)).unwrap();
        let h = 1e-5;
        for i in 0..40 {
            let t = 0.037 * i as f64;
            let difference = (swing.exact(t + h) - swing.exact(t - h)) / (2.0 * h);
            let [angle, rate] = swing.exact(t).into();
            let scale = omega0_squared;
            assert!((difference[1] + omega0_squared * angle.sin()).abs() < 1e-8 * scale);
            assert!((difference[0] - rate).abs() < 1e-8 * p.natural_frequency());
        }
    }
}

#[test]
fn exact_swing_starts_at_rest_and_has_the_elliptic_period() {
    let p = pendulum();
    let amplitude = f64::to_radians(120.0);
    let swing = p.released_from(amplitude).unwrap();
    // Absolute 1e-7: if sn(K) misses 1 by a few ulps, asin near 1 turns that into √(2ε) ≈ 2e-8.
    let [angle, rate] = swing.exact(0.0).into();
    assert!((angle - amplitude).abs() < 1e-7);
    assert!(rate.abs() < 1e-12);
    let period = swing.period();
    assert!((period - p.period(amplitude).unwrap()).abs() < 1e-14 * period);
    // The body passes the bottom at T/4 and 3T/4, moving in opposite directions.
    let (quarter, three_quarters) = (swing.exact(0.25 * period), swing.exact(0.75 * period));
    assert!(quarter[0].abs() < 1e-13 && three_quarters[0].abs() < 1e-13);
    assert!(quarter[1] < 0.0 && three_quarters[1] > 0.0);
}

#[test]
fn energy_is_conserved_along_the_exact_swing_4_33_to_4_35() {
    let p = pendulum();
    let i0 = p.parameters().i0();
    for degrees in [1.0, 30.0, 90.0, 170.0] {
        let amplitude = f64::to_radians(degrees);
        let swing = p.released_from(amplitude).unwrap();
        let initial = pendulum_potential_energy(MASS, STANDARD_GRAVITY, PIVOT_TO_CG, amplitude);
        for i in 0..200 {
            let t = 0.0173 * i as f64;
            let [angle, rate] = swing.exact(t).into();
            let kinetic = pendulum_kinetic_energy(i0, rate);
            let potential = pendulum_potential_energy(MASS, STANDARD_GRAVITY, PIVOT_TO_CG, angle);
            // Relative 1e-14: U = 2Mgh sin²(θ/2) = 2Mgh k² sn² and T = 2Mgh k² cn², so the sum
            // is 2Mgh k² (sn² + cn²), exact to the Jacobi functions' few ulps (observed 5e-16).
            assert!(
                (kinetic + potential - initial).abs() < 1e-14 * initial,
                "θ₀ = {degrees}°, t = {t}: {} vs {initial}",
                kinetic + potential
            );
        }
    }
}

/// Samples the exact swing densely and irregularly in phase: 1237 samples over 8.3 periods.
fn sampled_swing(amplitude: f64) -> (Vec<f64>, Vec<f64>, f64) {
    let swing = pendulum().released_from(amplitude).unwrap();
    let period = swing.period();
    let times: Vec<f64> = (0..1237)
        .map(|i| i as f64 * 8.3 * period / 1236.0)
        .collect();
    let angles = times.iter().map(|&t| swing.exact(t)[0]).collect();
    (times, angles, period)
}

#[test]
fn swing_test_recovers_kappa_g_from_a_sampled_swing_with_the_amplitude_correction() {
    let amplitude = f64::to_radians(15.0);
    let (times, angles, exact_period) = sampled_swing(amplitude);
    let measured = measure_period(&times, &angles).unwrap();
    let period_error = (measured - exact_period).abs() / exact_period;
    let corrected = swing_test(measured, amplitude).solve().unwrap();
    let uncorrected = swing_test(measured, 0.0).solve().unwrap();
    let error = (corrected.kappa_g - KAPPA_G).abs() / KAPPA_G;
    let error_uncorrected = (uncorrected.kappa_g - KAPPA_G).abs() / KAPPA_G;
    println!(
        "15° swing: period error {period_error:.2e}, κ_G error {error:.2e} corrected, \
         {error_uncorrected:.2e} uncorrected (T/T₀ − 1 = {:.3e})",
        corrected.period_factor - 1.0
    );
    assert!(error < 1e-6, "κ_G relative error {error}");
    // Without the correction κ is too large by T/T₀ − 1 ≈ θ₀²/16 ≈ 0.43 %, and κ_G by that
    // times κ²/κ_G² ≈ 1.23: more than a thousand times the tolerance above.
    assert!(
        error_uncorrected > 1e-3,
        "uncorrected error {error_uncorrected}"
    );
}

#[test]
fn measured_period_matches_the_exact_period() {
    for degrees in [5.0, 60.0, 150.0] {
        let (times, angles, exact_period) = sampled_swing(f64::to_radians(degrees));
        let measured = measure_period(&times, &angles).unwrap();
        // Relative 1e-8: a hundredth of what the 1e-6 target on κ_G needs (κ_G's relative
        // error is κ²/κ_G² ≈ 1.2 times the period's). Observed: 2e-10 at 5°, 1e-9 at 150°,
        // with 150 samples per period and cubic inverse interpolation of each crossing.
        assert!(
            (measured - exact_period).abs() < 1e-8 * exact_period,
            "{degrees}°"
        );
    }
}

#[test]
fn bad_swing_arguments_name_the_fault() {
    let cases = [
        (swing_test(-2.0, 0.0), "period"),
        (swing_test(f64::NAN, 0.0), "period"),
        (
            SwingTest {
                pivot_to_cg: 0.0,
                ..swing_test(2.0, 0.0)
            },
            "pivot_to_cg",
        ),
        (
            SwingTest {
                mass: -1.0,
                ..swing_test(2.0, 0.0)
            },
            "mass",
        ),
        (
            SwingTest {
                gravity: f64::INFINITY,
                ..swing_test(2.0, 0.0)
            },
            "gravity",
        ),
    ];
    for (test, field) in cases {
        let err = test.solve().unwrap_err();
        assert!(
            matches!(err, SwingError::Parameter(ref e) if e.field == field),
            "{err}"
        );
    }
    for degrees in [180.0, 200.0, -5.0, f64::NAN] {
        let err = swing_test(2.0, f64::to_radians(degrees))
            .solve()
            .unwrap_err();
        assert!(
            matches!(err, SwingError::AmplitudeOutOfRange { .. }),
            "{err}"
        );
    }
    // κ = (0.1 / 2π) √(g · 1) ≈ 0.05 m < h = 1 m: κ_G would be imaginary.
    let short = SwingTest {
        pivot_to_cg: 1.0,
        ..swing_test(0.1, 0.0)
    };
    let err = short.solve().unwrap_err();
    assert!(matches!(err, SwingError::ImaginaryGyradius { .. }));
    assert!(err.to_string().contains("imaginary"), "{err}");
}

#[test]
fn bad_samples_name_the_fault() {
    let t = [0.0, 1.0, 2.0, 3.0];
    let a = [-1.0, 1.0, -1.0, 1.0];
    assert!(matches!(
        measure_period(&t, &a[..3]),
        Err(SwingError::LengthMismatch { .. })
    ));
    let nan = [-1.0, f64::NAN, -1.0, 1.0];
    assert!(matches!(
        measure_period(&t, &nan),
        Err(SwingError::NotFiniteSample {
            field: "angles",
            index: 1
        })
    ));
    let backwards = [0.0, 1.0, 1.0, 3.0];
    assert!(matches!(
        measure_period(&backwards, &a),
        Err(SwingError::TimesNotIncreasing { index: 2 })
    ));
    let once = [-1.0, 1.0, 1.0, 1.0];
    assert!(matches!(
        measure_period(&t, &once),
        Err(SwingError::TooFewCrossings { found: 1 })
    ));
    assert_eq!(measure_period(&t, &a).unwrap(), 2.0);
}

#[test]
fn impossible_pendulums_are_refused() {
    // I₀ < M h² would make I_G negative (4.29).
    let err = PendulumParameters::new(1.0, 10.0, STANDARD_GRAVITY, 1.0).unwrap_err();
    assert_eq!(err.field, "i0");
    // Without gravity the body does not swing: there is no period to time.
    let weightless = PendulumParameters::new(1.0, 1.0, 0.0, 0.1).unwrap();
    assert!(matches!(
        SwungBody::new(&weightless).unwrap_err(),
        SwingError::Parameter(ParameterError { field: "g", .. })
    ));
    assert!(pendulum().released_from(std::f64::consts::PI).is_err());
}

/// The swing test on a simulated pendulum: the generated model (4.24) integrated by DOP853 at
/// rtol 1e-12, sampled by dense output, its period measured from the trajectory, κ_G
/// recovered with the amplitude correction.
#[test]
fn swing_test_recovers_kappa_g_from_an_integrated_swing() {
    use eom::integrate::{AdaptiveOptions, Dop853};
    use eom::models::{Constant, Model};
    use nalgebra::SVector;
    let amplitude = f64::to_radians(15.0);
    let p = pendulum();
    let model = eom::models::Pendulum::<f64>::new(p.parameters());
    let system = model.driven_by(Constant::zero());
    let period = p.period(amplitude).unwrap();
    let times: Vec<f64> = (1..1237)
        .map(|i| i as f64 * 8.3 * period / 1236.0)
        .collect();
    let mut states = vec![SVector::<f64, 2>::zeros(); times.len()];
    let mut method = Dop853::new(AdaptiveOptions::dop853(1e-12, 1e-12));
    method
        .solve_at(
            &system,
            0.0,
            SVector::from([amplitude, 0.0]),
            &times,
            &mut states,
        )
        .unwrap();
    let angles: Vec<f64> = states.iter().map(|y| y[0]).collect();
    let measured = measure_period(&times, &angles).unwrap();
    let corrected = swing_test(measured, amplitude).solve().unwrap();
    let error = (corrected.kappa_g - KAPPA_G).abs() / KAPPA_G;
    println!("integrated 15° swing: κ_G relative error {error:.2e}");
    // The trajectory is good to ~1e-11 and the crossing interpolation to ~1e-10 (as for the
    // sampled exact swing above), so 1e-6 has a wide margin; without the correction the error
    // is ~5e-3 (previous test).
    assert!(error < 1e-6, "κ_G relative error {error}");
}
