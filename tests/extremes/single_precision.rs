//! f32 against f64: the same RK4 steps through the generated principal model in both
//! precisions, so that the gap between the runs is the precision alone.
//!
//! The f32 run starts from the f64 state rounded (relative ε₃₂/2), with the model's
//! coefficients rounded, and rounds every stage. For a motion whose frequencies f32 can only
//! hold to their rounding, the phase error grows linearly, as ε₃₂ · ω · t; the long runs of
//! `--example f32_vs_f64` show it for the top over 1000 periods (rates 1.00–1.08
//! ε₃₂|ω₀|t) and show the racket growing faster (its period depends on an energy that f32
//! lets wander). These tests hold both over a short run.

use eom::generic::quaternion_state_of_rotation;
use eom::integrate::{Integrator, Rk4};
use eom::models::{Constant, Model};
use eom::reference::ReferenceProblem;
use nalgebra::{SVector, Vector3};

use eom_test_support::extremes::{
    RACKET_MOMENTS, principal_model, racket, rotation_gap, top, top_moments,
};

/// f32's machine epsilon, 2⁻²³.
const EPS32: f64 = f32::EPSILON as f64;

/// RK4 in f32 and in f64 from `start` with `steps_per_period` steps per `period`, for
/// `periods` periods: the gaps (rates relative to |ω₀|, attitude angle) after each period.
fn gaps(
    moments: &Vector3<f64>,
    start: SVector<f64, 13>,
    period: f64,
    steps_per_period: usize,
    periods: usize,
) -> Vec<(f64, f64)> {
    let run = |single: bool| {
        let mut marks = Vec::new();
        let mut count = 0usize;
        let h = period / steps_per_period as f64;
        // Both runs end at the same f32 time, so that they cut it into the same number of
        // steps: an f64 end a little short of the f32 one would take one step fewer.
        let t_end = f64::from((period * periods as f64) as f32);
        let mut mark = |y: SVector<f64, 13>| {
            count += 1;
            if count.is_multiple_of(steps_per_period) {
                marks.push(y);
            }
        };
        if single {
            let model = principal_model::<f32>(moments);
            Rk4::new(h)
                .integrate_with(
                    &model.driven_by(Constant::zero()),
                    0.0f32,
                    start.cast::<f32>(),
                    t_end as f32,
                    |_, y| mark(y.cast::<f64>()),
                )
                .expect("the f32 run completes");
        } else {
            let model = principal_model::<f64>(moments);
            Rk4::new(h)
                .integrate_with(
                    &model.driven_by(Constant::zero()),
                    0.0,
                    start,
                    t_end,
                    |_, y| mark(*y),
                )
                .expect("the f64 run completes");
        }
        marks
    };
    let (single, double) = (run(true), run(false));
    assert_eq!(single.len(), periods);
    let w0 = start.fixed_rows::<3>(3).norm();
    single
        .iter()
        .zip(&double)
        .map(|(a, b)| rotation_gap(a, b, w0))
        .collect()
}

#[test]
fn an_f32_top_drifts_from_the_f64_top_linearly_in_time() {
    // Ten precession periods, 500 RK4 steps each; u = ε₃₂ |ω₀| t, n the steps so far.
    // - The rates turn at λ = (I₃ − I₁) r / I₁, which f32 holds to the rounding of r, of the
    //   coefficient and of the step (ε₃₂/2 each), so their phase error grows as
    //   ≲ 1.5 ε₃₂ λ t ≤ 1.5u; each step also rounds them, a random walk of about ε₃₂ √n.
    //   Bound: 2u + ε₃₂ √n (measured 0.42–2.03u; 2.03u after the first period, where the
    //   walk is the larger part, against a bound of 7.6u there).
    // - The attitude precesses at |H|/I₁, which carries the rounding of the rates, and its
    //   own steps round it too. Bound: 16u + ε₃₂ √n (measured 1.7–3.8u here, up to 8.3u over
    //   1000 periods at 2000 steps per period).
    let top = top(1.0);
    let period = 0.5 * top.t_end();
    let start = quaternion_state_of_rotation(&top.initial_state());
    let w0 = start.fixed_rows::<3>(3).norm();
    let steps_per_period = 500;
    let gaps = gaps(&top_moments(), start, period, steps_per_period, 10);
    for (k, (rates, attitude)) in gaps.iter().enumerate() {
        let u = EPS32 * w0 * period * (k + 1) as f64;
        let walk = EPS32 * ((steps_per_period * (k + 1)) as f64).sqrt();
        println!(
            "top, period {}: rates {:.2} u, attitude {:.2} u",
            k + 1,
            rates / u,
            attitude / u
        );
        assert!(
            *rates <= 2.0 * u + walk,
            "period {}: rates {rates:e} = {:.2} u",
            k + 1,
            rates / u
        );
        assert!(
            *attitude <= 16.0 * u + walk,
            "period {}: attitude {attitude:e} = {:.2} u",
            k + 1,
            attitude / u
        );
    }
}

#[test]
fn an_f32_racket_stays_within_a_linear_bound_over_two_periods() {
    // Two periods (four flips), 1000 RK4 steps each; u = ε₃₂ |ω₀| t. The racket's gap grows
    // faster than linearly over long runs (6.6u after one period and 117u after a thousand
    // at 2000 steps per period, --example f32_vs_f64), because its period depends on an
    // energy that f32 lets wander; over two periods it stays within 16u, over twice the
    // largest seen in either setting (2.1u here).
    let racket = racket(1.0);
    let start = quaternion_state_of_rotation(&racket.initial_state());
    let w0 = start.fixed_rows::<3>(3).norm();
    let moments = Vector3::from(RACKET_MOMENTS);
    let gaps = gaps(&moments, start, racket.period(), 1000, 2);
    for (k, (rates, attitude)) in gaps.iter().enumerate() {
        let u = EPS32 * w0 * racket.period() * (k + 1) as f64;
        let gap = rates.max(*attitude);
        println!("racket, period {}: gap {:.2} u", k + 1, gap / u);
        assert!(
            gap <= 16.0 * u,
            "period {}: gap {gap:e} = {:.2} u",
            k + 1,
            gap / u
        );
    }
}
