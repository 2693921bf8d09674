//! Spin rates of 10³ and 10⁴ rad/s.
//!
//! Torque-free motion has no time scale of its own: if ω(t) is a solution, so is s·ω(s t),
//! with the attitude following along. Spinning a body s times faster is the same problem in a
//! unit of time s times shorter, so an adaptive method at the same tolerance must take about
//! the same steps and reach about the same error per period. Only the weights of the error
//! norm, atol + rtol·|yᵢ| with atol = rtol, change: at 1 rad/s atol is as large as rtol·|ω|,
//! at 10⁴ rad/s it is nothing beside it, so the fast runs are held a little tighter.

use eom::reference::ReferenceProblem;
use nalgebra::Vector3;

use eom_test_support::extremes::{Adaptive, RATES, SpinRun, racket, spin_run, top, top_moments};

/// The tolerances (rtol = atol): loose, middling, tight.
const TOLERANCES: [f64; 3] = [1e-6, 1e-9, 1e-12];

/// The racket's end error after one period (two flips), in units of the tolerance. The
/// controllers hold each step's local error to the tolerance in Hairer's weighted RMS norm;
/// over a horizon the local errors add up, nothing damps them, and the racket's flip time
/// depends on its energy (logarithmically near the separatrix), which multiplies an energy
/// error into a phase error. Measured over the three rates, both methods and the three
/// tolerances: 3.5–19.3 × tol (largest at 1 rad/s, DOP853 at 1e-6), so 30 leaves a margin of
/// 1.5.
const RACKET_FACTOR: f64 = 30.0;

/// The axisymmetric top's end error after two precession periods, in units of the tolerance:
/// its precession and spin rates depend on |H| and r alone and nothing amplifies the local
/// errors; measured 0.68–2.7 × tol, so 4.
const TOP_FACTOR: f64 = 4.0;

/// The largest relative drift of the energy and of |H| over the run, in units of the
/// tolerance: neither is conserved by the methods, each step changes them by about its local
/// error; measured at most 5.5 × tol (the racket, DOP853 at 1e-6), so 10.
const DRIFT_FACTOR: f64 = 10.0;

/// A fast run against the same run at 1 rad/s. The error may not exceed twice that of the
/// unit-rate run (measured at most 1.01 times: the fast run's weights are the tighter), and
/// the steps may not exceed 1.5 times its steps. At 1 rad/s the weight of a rate ωᵢ is
/// tol·(1 + |ωᵢ|), (1 + |ωᵢ|)/|ωᵢ| times looser than at 10⁴ rad/s relative to the rate: up
/// to 4.3 times for the top's 0.3 rad/s, and steps go as tol^(−1/5) for DOPRI5, so up to
/// 4.3^(1/5) = 1.34 times the steps (measured at most 1.36).
fn compare(name: &str, rate: f64, fast: &SpinRun, unit: &SpinRun, tol: f64, factor: f64) {
    let context = format!("{name} at {rate} rad/s, tol {tol:e}: {fast:?} (1 rad/s: {unit:?})");
    println!(
        "{name} at {rate:e} rad/s, tol {tol:e}: error {:.2} tol, energy {:.2} tol, |H| {:.2} tol, error/unit-rate error {:.2}, steps/unit-rate steps {:.2}",
        fast.error / tol,
        fast.drifts.energy / tol,
        fast.drifts.momentum / tol,
        fast.error / unit.error,
        fast.stats.steps as f64 / unit.stats.steps as f64
    );
    assert!(
        fast.error <= factor * tol,
        "error beyond {factor} × tol: {context}"
    );
    assert!(
        fast.error <= 2.0 * unit.error,
        "worse than at 1 rad/s: {context}"
    );
    assert!(
        fast.drifts.energy <= DRIFT_FACTOR * tol && fast.drifts.momentum <= DRIFT_FACTOR * tol,
        "energy or |H| drift beyond {DRIFT_FACTOR} × tol: {context}"
    );
    assert!(
        2 * fast.stats.steps <= 3 * unit.stats.steps,
        "steps beyond 1.5 × those at 1 rad/s: {context}"
    );
}

#[test]
fn a_racket_spun_at_ten_thousand_rad_per_s_flips_as_accurately_as_at_one() {
    let moments = Vector3::from(eom_test_support::extremes::RACKET_MOMENTS);
    for method in Adaptive::ALL {
        for tol in TOLERANCES {
            let run = |rate: f64| {
                let racket = racket(rate);
                spin_run(&racket, &moments, method, tol, racket.t_end())
            };
            let unit = run(RATES[0]);
            assert!(unit.error <= RACKET_FACTOR * tol, "at 1 rad/s: {unit:?}");
            for rate in &RATES[1..] {
                let name = format!("racket, {}", method.name());
                compare(&name, *rate, &run(*rate), &unit, tol, RACKET_FACTOR);
            }
        }
    }
}

#[test]
fn an_axisymmetric_top_spun_at_ten_thousand_rad_per_s_keeps_its_attitude_to_the_tolerance() {
    let moments = top_moments();
    for method in Adaptive::ALL {
        for tol in TOLERANCES {
            let run = |rate: f64| {
                let top = top(rate);
                spin_run(&top, &moments, method, tol, top.t_end())
            };
            let unit = run(RATES[0]);
            assert!(unit.error <= TOP_FACTOR * tol, "at 1 rad/s: {unit:?}");
            for rate in &RATES[1..] {
                let name = format!("top, {}", method.name());
                compare(&name, *rate, &run(*rate), &unit, tol, TOP_FACTOR);
            }
        }
    }
}
