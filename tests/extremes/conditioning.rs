//! Inertia ratios of 10⁶ and nearly equal moments.
//!
//! Each generated form computes ω̇ = [I]⁻¹(−ω × [I]ω) from f64 data. With the f64 entries of
//! [I] and ω taken as exact, the double-double solve of `double_double` is the exact answer to
//! ~10⁻²⁵, and the f64 error is measured against it as
//!
//!   ρ = |ω̇ − ω̇ₑₓ| / (ε |[I]⁻¹|₂ |ω| |[I]ω|),
//!
//! the error in units of ε times the size of what [I]⁻¹ multiplies. Because
//! |ω̇ₑₓ| ≥ |ω × [I]ω| / |[I]|, ρ bounds the relative error by
//!
//!   |ω̇ − ω̇ₑₓ| / |ω̇ₑₓ| ≤ ρ · cond([I]) · ε / sin∠(ω, [I]ω):
//!
//! the condition number of the tensor times that of the cross product (how near ω is to a
//! principal axis, where ω̇ vanishes). ρ of order one is the error of rounding each term once,
//! as good as an f64 evaluation gets without extra precision, and that is what every form
//! delivers (largest ρ seen 0.96, at cond 10⁴; 0.73 at cond 10⁶;
//! `--example extremes` prints the table).

use nalgebra::Vector3;

use eom_test_support::extremes::{
    ROD_MOMENTS, conditioning, near_symmetric_run, rod_runs, tensor_matrix,
};

/// The bound on ρ for every form and tensor: four times the largest seen (0.96), which is a
/// few roundings in each of the products, the cross product and the inverse's entries.
const RHO_BOUND: f64 = 4.0;

/// Random ω per tensor (magnitudes 10⁻³ to 10³ rad/s, directions uniform in a cube).
const SAMPLES: usize = 300;

/// The thin rods (I_xx = r, I_yy = 1, I_zz = 1 + r/2: I_zz − I_yy ≤ I_xx, as a physical body
/// must have) and the near-symmetric bodies (I = (1.3, 2, 2(1 + δ))), each in principal axes
/// and turned so that every product of inertia is non-zero.
fn bodies() -> Vec<(String, Vector3<f64>)> {
    let mut bodies: Vec<_> = [1e-2, 1e-4, 1e-6]
        .iter()
        .map(|&r| (format!("rod {r:e}"), Vector3::new(r, 1.0, 1.0 + 0.5 * r)))
        .collect();
    bodies.extend([1e-6, 1e-9, 1e-12].iter().map(|&d| {
        (
            format!("near-symmetric {d:e}"),
            Vector3::new(1.3, 2.0, 2.0 * (1.0 + d)),
        )
    }));
    bodies
}

#[test]
fn every_form_of_the_rates_is_as_accurate_as_the_tensor_s_condition_allows() {
    for (name, moments) in bodies() {
        for turned in [false, true] {
            let inertia = tensor_matrix(&moments, turned);
            let worst = conditioning(&inertia, SAMPLES, 0x9e37_79b9_7f4a_7c15);
            let context = format!("{name}, turned {turned}: {worst:?}");
            println!("{context}");
            assert!(
                worst.full.rho <= RHO_BOUND,
                "generated full model: {context}"
            );
            assert!(worst.generic.rho <= RHO_BOUND, "generic form: {context}");
            if let Some(principal) = worst.principal {
                assert!(
                    principal.rho <= RHO_BOUND,
                    "generated principal model: {context}"
                );
            }
            // In principal axes the principal model exists; turned, it refuses the products.
            assert_eq!(worst.principal.is_some(), !turned, "{context}");
        }
    }
}

#[test]
fn the_principal_model_loses_only_what_the_difference_of_two_moments_costs() {
    // The principal model's coefficients are differences of quotients, I_yy/I_xx − I_zz/I_xx:
    // when I_yy ≈ I_zz the difference cancels, and ṗ is as accurate as the difference of the
    // two moments allows, ε (I_yy + I_zz)/|I_yy − I_zz| relative (2.2e-4 at δ = 10⁻¹²;
    // measured 1.1e-4, so the bound is twice that estimate). The other rates keep a few ε.
    // A relative perturbation of ε in I_yy or I_zz — the rounding of the data — moves ṗ by
    // as much, so this is the conditioning of the data, not of the code.
    for (name, moments) in bodies() {
        let worst = conditioning(
            &tensor_matrix(&moments, false),
            SAMPLES,
            0x2545_f491_4f6c_dd1d,
        );
        let principal = worst.principal.expect("a principal tensor");
        let pairs = [
            (moments.y, moments.z),
            (moments.z, moments.x),
            (moments.x, moments.y),
        ];
        let difference_condition = pairs
            .iter()
            .map(|(a, b)| (a + b) / (a - b).abs())
            .fold(1.0, f64::max);
        let bound = 2.0 * f64::EPSILON * difference_condition;
        assert!(
            principal.componentwise <= bound,
            "{name}: componentwise {:e} beyond {bound:e}",
            principal.componentwise
        );
    }
}

#[test]
fn an_exactly_symmetric_rod_in_principal_axes_has_exact_rates() {
    // I_yy = I_zz exactly: the coefficient of qr in ṗ is I_yy/I_xx − I_zz/I_xx = 0 exactly,
    // and the other two are single products; every form agrees with the exact answer to the
    // last bit at every sample.
    let inertia = tensor_matrix(&Vector3::new(1e-6, 1.0, 1.0), false);
    let worst = conditioning(&inertia, SAMPLES, 0x1234_5678_9abc_def1);
    let principal = worst.principal.expect("a principal tensor");
    assert!(principal.componentwise <= f64::EPSILON, "{worst:?}");
}

#[test]
fn a_thin_rod_tumbles_without_nan_and_keeps_energy_and_momentum() {
    // DOP853 at 1e-10 over 100 s (about 116 rad of tumbling), in principal axes (generated
    // principal model) and turned (generated full model, cond([I]) = 10⁶).
    //
    // - In principal axes the drifts are the method's: each accepted step changes T and |H|
    //   by at most about its local error, so the drift is below steps · tol (measured 1.1e-9
    //   against 2.9e-8).
    // - Turned, the rates carry an error of up to ρ·ε·|[I]⁻¹||ω||[I]ω| ≈ cond·ε·|ω|² (ρ ≤ 1
    //   above), a perturbation of the vector field that the drift integrates over the angle
    //   turned: below steps · tol + cond · ε · |ω| t (measured 8.3e-10 against 5.4e-8).
    // - The two runs are the same motion: the turned run's rates, turned back, differ from
    //   the principal run's by the field's error integrated twice, below
    //   cond · ε · (|ω| t)² + 2 · steps · tol (measured 4.7e-8 against 3.0e-6). At 1e-12 the
    //   principal run keeps its energy to 5e-12 and the turned one is still 2.2e-7 off: a
    //   thin rod given in turned axes is limited by cond([I])·ε, not by the tolerance.
    //   Rotate it to principal axes.
    let (tol, t_end) = (1e-10, 100.0);
    let runs = rod_runs(tol, t_end);
    let cond =
        eom_test_support::extremes::condition(&tensor_matrix(&Vector3::from(ROD_MOMENTS), true));
    let (principal_steps, turned_steps) = (runs.steps.0 as f64, runs.steps.1 as f64);
    let field = cond * f64::EPSILON;
    let context = format!("{runs:?}, cond {cond:e}");
    println!("thin rod: {context}");
    let principal_bound = principal_steps * tol;
    assert!(runs.principal.energy <= principal_bound, "{context}");
    assert!(runs.principal.momentum <= principal_bound, "{context}");
    let turned_bound = turned_steps * tol + field * runs.turned_angle;
    assert!(runs.turned.energy <= turned_bound, "{context}");
    assert!(runs.turned.momentum <= turned_bound, "{context}");
    let difference_bound =
        field * runs.turned_angle.powi(2) + (principal_steps + turned_steps) * tol;
    assert!(runs.difference <= difference_bound, "{context}");
}

#[test]
fn a_body_with_two_moments_equal_to_1e_12_moves_as_the_symmetric_top() {
    // I = (1.3, 2, 2(1 + δ)) with δ = 10⁻¹², DOP853 at 1e-12 for five of the top's horizons
    // (about 84 rad turned), against the exact solution of the exactly symmetric top (axes
    // permuted). The asymmetry changes Euler's equations by about δ|ω|², so the motion leaves
    // the symmetric one by about δ|ω|t relative; the tolerance adds what the symmetric body's
    // own run has. Measured: 3.06e-11 for δ = 0, 3.94e-11 for δ = 10⁻¹² (bound 1.1e-10);
    // δ = 10⁻⁹ and 10⁻⁶ leave by 1.9e-8 and 1.9e-5, linear in δ as the estimate says.
    let (tol, periods) = (1e-12, 5.0);
    let symmetric = near_symmetric_run(0.0, tol, periods);
    let delta = 1e-12;
    let near = near_symmetric_run(delta, tol, periods);
    let top = eom_test_support::extremes::top_of_near_symmetric();
    let w0 = Vector3::new(0.6, -0.3, 1.2).norm();
    let turned = w0 * periods * eom::reference::ReferenceProblem::t_end(&top);
    let bound = symmetric.error + delta * turned;
    println!("δ = 0: {symmetric:?}; δ = {delta:e}: {near:?}; bound {bound:e}");
    assert!(
        near.error <= bound,
        "{near:?} against {bound:e} (δ = 0: {symmetric:?})"
    );
    // T and |H| are the method's to keep: below steps · tol (measured 4e-15).
    let steps = near.steps as f64;
    assert!(
        near.drifts.energy <= steps * tol && near.drifts.momentum <= steps * tol,
        "{near:?}"
    );
}
