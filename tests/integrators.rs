//! The integrators: their cost is asserted from their statistics and from a counting RHS,
//! their order of convergence is measured on problems with exact solutions, their failures
//! name the culprit, and the geometric integrator conserves what it claims.

use eom_test_support::bodies::{racket, top};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use eom::PendulumParameters;
use eom::integrate::{
    AdaptiveOptions, Dop853, Dopri5, Euler, IntegrateError, Integrator, LieMidpoint, Rk4,
    Statistics, SymplecticEuler, min_rtol,
};
use eom::reference::torque_free::PrincipalBody;
use eom::reference::{LargeSwing, PlanarTurn, ReferenceProblem};
use nalgebra::{Quaternion, SVector, UnitQuaternion, Vector1, Vector2, Vector3};

fn pendulum() -> LargeSwing {
    let parameters = PendulumParameters::new(2.0, 3.0, 9.81, 0.5).unwrap();
    LargeSwing::new(&parameters, 150f64.to_radians()).unwrap()
}

/// The error at the problem's horizon of `method` on `problem`.
fn error_of<const N: usize, P, M>(problem: &P, method: &mut M) -> f64
where
    P: ReferenceProblem<N> + eom::integrate::OdeSystem<f64, N>,
    M: Integrator<f64, N, P>,
{
    error_at(problem, method, problem.t_end())
}

/// The error at `t_end` of `method` on `problem`.
fn error_at<const N: usize, P, M>(problem: &P, method: &mut M, t_end: f64) -> f64
where
    P: ReferenceProblem<N> + eom::integrate::OdeSystem<f64, N>,
    M: Integrator<f64, N, P>,
{
    let y = method
        .integrate(problem, 0.0, problem.initial_state(), t_end)
        .unwrap();
    problem.error(t_end, &y)
}

/// The ratio of errors at steps h and h/2 (a method of order p gives 2^p asymptotically).
fn halving_ratio(error_at: impl Fn(f64) -> f64, h: f64) -> f64 {
    error_at(h) / error_at(0.5 * h)
}

#[test]
fn rk4_evaluates_the_rhs_exactly_four_times_per_step() {
    let calls = Cell::new(0usize);
    let counting = |_t: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>| {
        calls.set(calls.get() + 1);
        *dy = Vector2::new(y[1], -y[0]);
    };
    let mut rk4 = Rk4::new(0.01);
    rk4.integrate(&counting, 0.0, Vector2::new(1.0, 0.0), 1.0)
        .unwrap();
    assert_eq!(rk4.stats().steps, 100);
    assert_eq!(rk4.stats().rhs_evals, 400);
    assert_eq!(calls.get(), 400);
}

#[test]
fn euler_and_symplectic_euler_count_their_evaluations() {
    let calls = Cell::new(0usize);
    let counting = |_t: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>| {
        calls.set(calls.get() + 1);
        *dy = Vector2::new(y[1], -y[0]);
    };
    let mut euler = Euler::new(0.1);
    euler
        .integrate(&counting, 0.0, Vector2::new(1.0, 0.0), 1.0)
        .unwrap();
    assert_eq!(
        (euler.stats().steps, euler.stats().rhs_evals, calls.get()),
        (10, 10, 10)
    );
    let mut symplectic = SymplecticEuler::new(0.1, 1..2);
    symplectic
        .integrate(&counting, 0.0, Vector2::new(1.0, 0.0), 1.0)
        .unwrap();
    assert_eq!(symplectic.stats().rhs_evals, 20);
    assert_eq!(calls.get(), 30);
}

#[test]
fn dopri5_reuses_its_last_stage_six_evaluations_per_step() {
    let calls = Cell::new(0usize);
    let p = pendulum();
    let counting = |t: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>| {
        calls.set(calls.get() + 1);
        eom::integrate::OdeSystem::rhs(&p, t, y, dy);
    };
    let mut dopri = Dopri5::new(AdaptiveOptions::dopri5(1e-8, 1e-10));
    dopri
        .integrate(&counting, 0.0, p.initial_state(), p.t_end())
        .unwrap();
    let s = dopri.stats();
    // One evaluation at t0, one in Hairer's initial-step heuristic, six per step tried.
    assert_eq!(s.rhs_evals, 2 + 6 * (s.steps + s.rejected));
    assert_eq!(calls.get(), s.rhs_evals);
    assert!(s.steps > 10);
}

#[test]
fn dop853_does_twelve_evaluations_per_accepted_step() {
    let calls = Cell::new(0usize);
    let p = pendulum();
    let counting = |t: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>| {
        calls.set(calls.get() + 1);
        eom::integrate::OdeSystem::rhs(&p, t, y, dy);
    };
    let mut dop = Dop853::new(AdaptiveOptions::dop853(1e-10, 1e-12));
    dop.integrate(&counting, 0.0, p.initial_state(), p.t_end())
        .unwrap();
    let s = dop.stats();
    // Eleven stages per step tried, plus the first stage of the next step once accepted.
    assert_eq!(s.rhs_evals, 2 + 12 * s.steps + 11 * s.rejected);
    assert_eq!(calls.get(), s.rhs_evals);
}

// Order of convergence: each method runs with a fixed step, the step is halved, and the
// ratio of the errors tends to 2^p. The problems are chosen so that the runs sit in the
// asymptotic range, well above round-off: the planar turn (smooth in every component) for the
// higher orders, and the large-amplitude pendulum at 0.3 of its period for the first-order
// methods. (At a whole period the first-order term of symplectic Euler cancels — it is
// conjugate to a second-order method — so the ratio there would be 4, not 2.) The bounds
// allow ±12% around 2^p for the higher-order terms; a method of the wrong order lands a
// factor of two or more away.

fn turn() -> PlanarTurn {
    PlanarTurn::new(1000.0, 0.2, (300.0, -150.0), (5.0, 0.4)).unwrap()
}

#[test]
fn explicit_euler_converges_at_order_one() {
    let p = pendulum();
    let t_end = 0.3 * p.period();
    let ratio = halving_ratio(|h| error_at(&p, &mut Euler::new(h), t_end), t_end / 2000.0);
    assert!((1.76..2.24).contains(&ratio), "ratio {ratio}");
}

#[test]
fn symplectic_euler_converges_at_order_one() {
    let p = pendulum();
    let t_end = 0.3 * p.period();
    let error = |h| error_at(&p, &mut SymplecticEuler::new(h, 1..2), t_end);
    let ratio = halving_ratio(error, t_end / 2000.0);
    assert!((1.76..2.24).contains(&ratio), "ratio {ratio}");
}

#[test]
fn rk4_converges_at_order_four() {
    let turn = turn();
    let ratio = halving_ratio(|h| error_of(&turn, &mut Rk4::new(h)), turn.t_end() / 400.0);
    assert!((14.0..18.0).contains(&ratio), "ratio {ratio}");
}

/// Options that pin an adaptive method to the fixed step `h`: tolerances so loose that no
/// step is rejected and a maximum step of `h`.
fn pinned(mut options: AdaptiveOptions, h: f64) -> AdaptiveOptions {
    options.h0 = Some(h);
    options.h_max = h;
    options
}

#[test]
fn dopri5_converges_at_order_five() {
    let turn = turn();
    let error = |h| {
        error_of(
            &turn,
            &mut Dopri5::new(pinned(AdaptiveOptions::dopri5(1e3, 1e3), h)),
        )
    };
    let ratio = halving_ratio(error, turn.t_end() / 200.0);
    assert!((28.0..36.0).contains(&ratio), "ratio {ratio}");
}

#[test]
fn dop853_converges_at_order_eight() {
    let turn = turn();
    let error = |h| {
        error_of(
            &turn,
            &mut Dop853::new(pinned(AdaptiveOptions::dop853(1e3, 1e3), h)),
        )
    };
    let ratio = halving_ratio(error, turn.t_end() / 20.0);
    assert!((225.0..287.0).contains(&ratio), "ratio {ratio}");
}

#[test]
fn dopri5_dense_output_is_fourth_order_between_steps() {
    // Interpolated states at 37 times that are not step ends, against the exact solution;
    // with a continuous extension of order 4 the error falls by 2⁵ per halving of the step
    // locally, and the global error of the steps by 2⁵ too: the ratio must exceed 2⁴ = 16.
    let p = pendulum();
    let times: Vec<f64> = (1..=37).map(|i| p.period() * f64::from(i) / 37.5).collect();
    let worst = |h: f64| {
        let mut out = vec![SVector::<f64, 2>::zeros(); times.len()];
        let mut dopri = Dopri5::new(pinned(AdaptiveOptions::dopri5(1e3, 1e3), h));
        dopri
            .solve_at(&p, 0.0, p.initial_state(), &times, &mut out)
            .unwrap();
        times
            .iter()
            .zip(&out)
            .map(|(t, y)| p.error(*t, y))
            .fold(0.0, f64::max)
    };
    let ratio = halving_ratio(worst, p.period() / 60.0);
    assert!(ratio > 16.0, "ratio {ratio}");
    // And the interpolant is far better than the step: at h = T/60 the error is below 1e-5.
    assert!(worst(p.period() / 60.0) < 1e-5);
}

#[test]
fn dop853_dense_output_is_seventh_order_between_steps() {
    // Hairer's continuous extension of DOP853 has order 7: the interpolation error falls by at
    // least 2⁷ = 128 per halving of the step (2⁸ locally). Interior times of the planar turn,
    // with the step pinned; the errors stay well above round-off at these steps.
    let turn = turn();
    let times: Vec<f64> = (1..=29)
        .map(|i| turn.t_end() * f64::from(i) / 29.5)
        .collect();
    let worst = |h: f64| {
        let mut out = vec![SVector::<f64, 5>::zeros(); times.len()];
        let mut dop = Dop853::new(pinned(AdaptiveOptions::dop853(1e3, 1e3), h));
        dop.solve_at(&turn, 0.0, turn.initial_state(), &times, &mut out)
            .unwrap();
        times
            .iter()
            .zip(&out)
            .map(|(t, y)| turn.error(*t, y))
            .fold(0.0, f64::max)
    };
    let ratio = halving_ratio(worst, turn.t_end() / 20.0);
    assert!(ratio > 128.0, "ratio {ratio}");
}

#[test]
fn dop853_dense_output_costs_three_evaluations_per_step_used() {
    // The step is pinned to a tenth of the span and given (no initial-step heuristic): one
    // evaluation at t0, 12 per step, and 3 more for each of the 3 steps that hold an output.
    let turn = turn();
    let t_end = turn.t_end();
    let times = [0.15 * t_end, 0.55 * t_end, t_end];
    let mut out = [SVector::<f64, 5>::zeros(); 3];
    let mut dop = Dop853::new(pinned(AdaptiveOptions::dop853(1e3, 1e3), 0.1 * t_end));
    dop.solve_at(&turn, 0.0, turn.initial_state(), &times, &mut out)
        .unwrap();
    let s = dop.stats();
    assert_eq!((s.steps, s.rejected), (10, 0));
    assert_eq!(s.rhs_evals, 1 + 12 * 10 + 3 * 3);
}

#[test]
fn adaptive_methods_meet_their_tolerance_on_the_pendulum() {
    // The global error of a tolerance-controlled run is not bounded by the tolerance, but on a
    // well-conditioned problem over one period it stays within a factor 100 of it.
    let p = pendulum();
    for rtol in [1e-6, 1e-9] {
        let e5 = error_of(&p, &mut Dopri5::new(AdaptiveOptions::dopri5(rtol, rtol)));
        let e8 = error_of(&p, &mut Dop853::new(AdaptiveOptions::dop853(rtol, rtol)));
        assert!(
            e5 < 100.0 * rtol && e8 < 100.0 * rtol,
            "rtol {rtol}: {e5}, {e8}"
        );
    }
}

#[test]
fn adaptive_methods_follow_the_tennis_racket_through_two_flips() {
    // Near the separatrix errors grow between flips; at rtol 1e-10 both methods must still
    // land within 1e-6 of the exact rates and H direction after two flips.
    let racket = racket();
    let body = racket.body();
    let y0 = racket.initial_state();
    let t_end = racket.t_end();
    let y5 = Dopri5::new(AdaptiveOptions::dopri5(1e-10, 1e-12)).integrate(&body, 0.0, y0, t_end);
    let y8 = Dop853::new(AdaptiveOptions::dop853(1e-10, 1e-12)).integrate(&body, 0.0, y0, t_end);
    assert!(racket.error(t_end, &y5.unwrap()) < 1e-6);
    assert!(racket.error(t_end, &y8.unwrap()) < 1e-6);
}

#[test]
fn integrators_run_in_single_precision() {
    // RK4 in f32 on the pendulum: the error floor is f32 round-off accumulated over 1000
    // steps, about 1e-4 at most; in f64 the same run is 1e-9-accurate, so the f32 run is
    // limited by its precision, not by the method.
    let p = pendulum();
    let y0 = p.initial_state().cast::<f32>();
    let y = Rk4::new(p.period() / 1000.0)
        .integrate(&p, 0.0f32, y0, p.period() as f32)
        .unwrap();
    let error = p.error(p.period(), &y.cast::<f64>());
    assert!(error < 1e-4 && error > 1e-8, "error {error}");
}

#[test]
fn lie_midpoint_conserves_energy_momentum_and_unit_quaternion() {
    // 10⁴ steps of the tennis racket. Each step conserves T and |H|² exactly but for the
    // rounding of its update (a few ulps); 1e-12 allows even a systematic drift of 1e4 ulps.
    let racket = racket();
    let body = racket.body();
    let mut lie = LieMidpoint::new(racket.t_end() / 10_000.0);
    let y0 = racket.initial_state();
    let (mut worst_invariant, mut worst_norm): (f64, f64) = (0.0, 0.0);
    let i0 = racket.invariants(&y0);
    lie.integrate_with(&body, 0.0, y0, racket.t_end(), |_, y| {
        for (a, b) in racket.invariants(y).iter().zip(&i0) {
            worst_invariant = worst_invariant.max((a / b - 1.0).abs());
        }
        worst_norm = worst_norm.max((y.fixed_rows::<4>(3).norm() - 1.0).abs());
    })
    .unwrap();
    assert!(
        worst_invariant < 1e-12,
        "invariants drift {worst_invariant}"
    );
    assert!(worst_norm < 1e-12, "quaternion norm error {worst_norm}");
    assert_eq!(lie.stats().steps, 10_000);
}

#[test]
fn lie_midpoint_keeps_angular_momentum_fixed_in_space() {
    // The Cayley attitude update cancels the Cayley form of the midpoint step exactly, so
    // R(q)[I]ω is constant up to round-off (1e-12 relative over 2000 steps).
    let racket = racket();
    let body = racket.body();
    let y = LieMidpoint::new(racket.t_end() / 2000.0)
        .integrate(&body, 0.0, racket.initial_state(), racket.t_end())
        .unwrap();
    let q = UnitQuaternion::from_quaternion(Quaternion::new(y[3], y[4], y[5], y[6]));
    let h = q * body.moments.component_mul(&Vector3::new(y[0], y[1], y[2]));
    let h_space = racket.momentum_in_space();
    assert!(
        (h - h_space).norm() < 1e-12 * h_space.norm(),
        "{h} vs {h_space}"
    );
}

#[test]
fn lie_midpoint_converges_at_order_two() {
    let top = top();
    let error = |h: f64| {
        let y = LieMidpoint::new(h).integrate(&top.body(), 0.0, top.initial_state(), top.t_end());
        top.error(top.t_end(), &y.unwrap())
    };
    let ratio = halving_ratio(error, top.t_end() / 400.0);
    assert!((3.5..4.5).contains(&ratio), "ratio {ratio}");
}

#[test]
fn invalid_steps_and_tolerances_are_named() {
    let decay = |_t: f64, y: &Vector1<f64>, dy: &mut Vector1<f64>| *dy = -*y;
    let y0 = Vector1::new(1.0);
    for h in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = Rk4::new(h).integrate(&decay, 0.0, y0, 1.0).unwrap_err();
        assert!(
            matches!(e, IntegrateError::InvalidStep { name: "h", .. }),
            "{e}"
        );
    }
    let e = Dopri5::new(AdaptiveOptions::dopri5(-1e-6, 1e-9)).integrate(&decay, 0.0, y0, 1.0);
    assert!(matches!(
        e,
        Err(IntegrateError::InvalidTolerance { name: "rtol", .. })
    ));
    let e = Dop853::new(AdaptiveOptions::dop853(1e-6, f64::NAN)).integrate(&decay, 0.0, y0, 1.0);
    assert!(matches!(
        e,
        Err(IntegrateError::InvalidTolerance { name: "atol", .. })
    ));
    let e = Euler::new(0.1).integrate(&decay, 1.0, y0, 0.0);
    assert!(matches!(e, Err(IntegrateError::InvalidInterval { .. })));
}

/// A relative tolerance below ten rounding units of the scalar type is refused before the
/// first step, naming the precision and the smallest accepted; at the limit, above it, and 0
/// with an absolute tolerance, the run goes. In f32 the limit is 6.0e-7: rtol 1e-6 runs.
#[test]
fn a_tolerance_below_the_precision_is_refused() {
    let decay32 = |_t: f32, y: &Vector1<f32>, dy: &mut Vector1<f32>| *dy = -*y;
    let decay64 = |_t: f64, y: &Vector1<f64>, dy: &mut Vector1<f64>| *dy = -*y;
    let min32 = min_rtol::<f32>();
    assert!((5.9e-7..6.0e-7).contains(&min32), "{min32}");
    for rtol in [1e-9, 1e-7, 0.99 * min32] {
        let refused = Dop853::new(AdaptiveOptions::dop853(rtol, rtol))
            .integrate(&decay32, 0.0, Vector1::new(1.0), 1.0)
            .unwrap_err();
        assert_eq!(
            refused,
            IntegrateError::ToleranceBelowPrecision {
                rtol,
                min: min32,
                precision: "f32"
            }
        );
        assert!(refused.to_string().contains("rtol"), "{refused}");
        let refused = Dopri5::new(AdaptiveOptions::dopri5(rtol, rtol)).integrate(
            &decay32,
            0.0,
            Vector1::new(1.0),
            1.0,
        );
        assert!(matches!(
            refused,
            Err(IntegrateError::ToleranceBelowPrecision { .. })
        ));
    }
    for (rtol, atol) in [(min32, 1e-6), (1e-6, 1e-6), (0.0, 1e-6)] {
        let end = Dop853::new(AdaptiveOptions::dop853(rtol, atol))
            .integrate(&decay32, 0.0, Vector1::new(1.0), 1.0)
            .unwrap_or_else(|e| panic!("rtol {rtol}: {e}"));
        assert!(
            (end[0] - (-1.0f32).exp()).abs() < 1e-5,
            "rtol {rtol}: {end}"
        );
    }
    // f64: 1.1e-15.
    let min64 = min_rtol::<f64>();
    let refused = Dop853::new(AdaptiveOptions::dop853(1e-16, 1e-16)).integrate(
        &decay64,
        0.0,
        Vector1::new(1.0),
        1.0,
    );
    assert!(matches!(
        refused,
        Err(IntegrateError::ToleranceBelowPrecision { precision: "f64", min, .. }) if min == min64
    ));
    let end = Dop853::new(AdaptiveOptions::dop853(2.0 * min64, 1e-16))
        .integrate(&decay64, 0.0, Vector1::new(1.0), 1.0)
        .expect("twice the limit runs");
    assert!((end[0] - (-1.0f64).exp()).abs() < 1e-14, "{end}");
}

#[test]
fn adaptive_limits_stop_the_run_and_say_where() {
    let p = pendulum();
    let mut few = AdaptiveOptions::dopri5(1e-10, 1e-10);
    few.max_steps = 20;
    match Dopri5::new(few).integrate(&p, 0.0, p.initial_state(), p.t_end()) {
        Err(IntegrateError::MaxStepsExceeded { t, max_steps: 20 }) => {
            assert!(t > 0.0 && t < p.t_end())
        }
        other => panic!("expected MaxStepsExceeded, got {other:?}"),
    }
    let mut coarse = AdaptiveOptions::dop853(1e-12, 1e-12);
    coarse.h_min = 0.5;
    match Dop853::new(coarse).integrate(&p, 0.0, p.initial_state(), p.t_end()) {
        Err(IntegrateError::StepSizeTooSmall { h, h_min, .. }) => {
            assert!(h < h_min && h_min == 0.5)
        }
        other => panic!("expected StepSizeTooSmall, got {other:?}"),
    }
}

#[test]
fn a_non_finite_state_names_its_component_and_time() {
    // ẏ₁ = y₁², y₁(0) = 1 blows up at t = 1; component 0 is harmless.
    let blow_up = |_t: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>| {
        *dy = Vector2::new(0.0, y[1] * y[1]);
    };
    let e = Euler::new(0.01)
        .integrate(&blow_up, 0.0, Vector2::new(0.0, 1.0), 100.0)
        .unwrap_err();
    match e {
        IntegrateError::NonFiniteState { component: 1, t } => assert!(t > 1.0 && t < 100.0),
        other => panic!("expected NonFiniteState in component 1, got {other:?}"),
    }
    let nan = |_t: f64, _y: &Vector2<f64>, dy: &mut Vector2<f64>| *dy = Vector2::new(f64::NAN, 0.0);
    let e = Dopri5::new(AdaptiveOptions::dopri5(1e-6, 1e-6)).integrate(
        &nan,
        0.0,
        Vector2::zeros(),
        1.0,
    );
    assert!(
        matches!(e, Err(IntegrateError::NonFiniteState { component: 0, .. })),
        "{e:?}"
    );
}

#[test]
fn lie_midpoint_refuses_a_step_too_large_for_its_iteration() {
    // h|ω| = 10: the fixed-point iteration cannot contract.
    let body = PrincipalBody {
        moments: Vector3::new(1.0, 2.0, 3.0),
    };
    let y0 = SVector::<f64, 7>::from([3.0, 10.0, 1.0, 1.0, 0.0, 0.0, 0.0]);
    let e = LieMidpoint::new(1.0)
        .integrate(&body, 0.0, y0, 5.0)
        .unwrap_err();
    assert!(
        matches!(e, IntegrateError::NotConverged { t: 0.0, .. }),
        "{e}"
    );
}

#[test]
fn planar_turn_is_integrated_to_its_exact_track() {
    let turn = turn();
    let e = error_of(
        &turn,
        &mut Dop853::new(AdaptiveOptions::dop853(1e-12, 1e-12)),
    );
    // 1e-9: the tolerance times the error growth of two turns (linear in t for this system).
    assert!(e < 1e-9, "error {e}");
}

/// The global allocator of this test binary: the system's, counting allocations per thread
/// (tests run in parallel threads, so a global count would mix them up).
struct CountingAllocator;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

// SAFETY: every call is forwarded unchanged to the system allocator; the count is a
// const-initialised thread-local without destructor, safe to touch from inside the allocator.
unsafe impl GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|a| a.set(a.get() + 1));
        // SAFETY: the caller upholds `alloc`'s contract, which `System.alloc` shares.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` was allocated by `System` with this layout, through `alloc` above.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: CountingAllocator = CountingAllocator;

/// The allocations made on this thread while `run` runs.
fn allocations_during(run: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.with(Cell::get);
    run();
    ALLOCATIONS.with(Cell::get) - before
}

#[test]
fn no_integrator_allocates() {
    // Every method, over a whole tumbling run of the tennis racket (hundreds of steps): not a
    // single heap allocation, so none per step.
    let racket = racket();
    let (body, y0, t_end) = (racket.body(), racket.initial_state(), racket.t_end());
    let h = t_end / 500.0;
    // The counter does see allocations.
    assert!(allocations_during(|| drop(std::hint::black_box(vec![0u8; 16]))) >= 1);
    let count = allocations_during(|| {
        Euler::new(h).integrate(&body, 0.0, y0, t_end).unwrap();
        SymplecticEuler::new(h, 0..3)
            .integrate(&body, 0.0, y0, t_end)
            .unwrap();
        Rk4::new(h).integrate(&body, 0.0, y0, t_end).unwrap();
        LieMidpoint::new(h)
            .integrate(&body, 0.0, y0, t_end)
            .unwrap();
        Dopri5::new(AdaptiveOptions::dopri5(1e-9, 1e-9))
            .integrate(&body, 0.0, y0, t_end)
            .unwrap();
        Dop853::new(AdaptiveOptions::dop853(1e-9, 1e-9))
            .integrate(&body, 0.0, y0, t_end)
            .unwrap();
    });
    assert_eq!(count, 0);
    let times = [1.0, 2.5, t_end];
    let mut out = [SVector::<f64, 7>::zeros(); 3];
    let mut dopri = Dopri5::new(AdaptiveOptions::dopri5(1e-9, 1e-9));
    let count = allocations_during(|| dopri.solve_at(&body, 0.0, y0, &times, &mut out).unwrap());
    assert_eq!(count, 0);
    let mut dop = Dop853::new(AdaptiveOptions::dop853(1e-9, 1e-9));
    let mut out8 = [SVector::<f64, 7>::zeros(); 3];
    let count = allocations_during(|| dop.solve_at(&body, 0.0, y0, &times, &mut out8).unwrap());
    assert_eq!(count, 0);
    // The end state by dense output is the end state of the run.
    let end = Dopri5::new(AdaptiveOptions::dopri5(1e-9, 1e-9)).integrate(&body, 0.0, y0, t_end);
    assert_eq!(out[2], end.unwrap());
}

#[test]
fn dense_output_refuses_unordered_times_and_short_buffers() {
    let p = pendulum();
    let mut dopri = Dopri5::new(AdaptiveOptions::dopri5(1e-6, 1e-6));
    let mut out = [SVector::<f64, 2>::zeros(); 2];
    let e = dopri.solve_at(&p, 0.0, p.initial_state(), &[1.0, 0.5], &mut out);
    assert!(
        matches!(
            e,
            Err(IntegrateError::InvalidInterval {
                t0: 1.0,
                t_end: 0.5
            })
        ),
        "{e:?}"
    );
    let e = dopri.solve_at(&p, 0.0, p.initial_state(), &[0.5, 1.0, 2.0], &mut out);
    assert!(
        matches!(e, Err(IntegrateError::OutputLength { times: 3, slots: 2 })),
        "{e:?}"
    );
}

#[test]
fn pure_relative_tolerance_handles_components_that_stay_zero() {
    // atol = 0 with a component that is exactly zero throughout (p of a body spinning about
    // its third axis): the weight of that component is zero, and its zero error must not
    // turn into 0/0.
    let body = PrincipalBody {
        moments: Vector3::new(1.0, 2.0, 3.0),
    };
    let y0 = SVector::<f64, 7>::from([0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0]);
    let y5 = Dopri5::new(AdaptiveOptions::dopri5(1e-9, 0.0))
        .integrate(&body, 0.0, y0, 3.0)
        .unwrap();
    let y8 = Dop853::new(AdaptiveOptions::dop853(1e-9, 0.0))
        .integrate(&body, 0.0, y0, 3.0)
        .unwrap();
    // Steady spin about axis 3: q = (cos(t/2), 0, 0, sin(t/2)); 1e-8 is 10× the tolerance.
    for y in [y5, y8] {
        assert!((y[3] - 1.5f64.cos()).abs() < 1e-8 && (y[6] - 1.5f64.sin()).abs() < 1e-8);
        assert_eq!((y[0], y[1], y[4], y[5]), (0.0, 0.0, 0.0, 0.0));
    }
}

/// A body spun up about its symmetry axis 3 by a constant body torque.
struct SpunUp;

impl eom::integrate::RigidRotation<f64> for SpunUp {
    fn inertia(&self) -> nalgebra::Matrix3<f64> {
        nalgebra::Matrix3::from_diagonal(&Vector3::new(2.0, 2.0, 3.0))
    }

    fn torque(&self, _t: f64, _q: &Quaternion<f64>, _w: &Vector3<f64>) -> Vector3<f64> {
        Vector3::new(0.0, 0.0, 0.6)
    }
}

#[test]
fn lie_midpoint_applies_a_body_torque() {
    // I₃ṙ = M: r(t) = r₀ + Mt/I₃ and the attitude turns about z by r₀t + Mt²/(2I₃). The
    // midpoint update of H is exact for this linear growth (1e-12: round-off of 1000 sums);
    // the Cayley attitude step errs by (hω)³/12 per step, about 1e-7 in all here (bound 1e-6).
    let y0 = SVector::<f64, 7>::from([0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0]);
    let y = LieMidpoint::new(1e-3)
        .integrate(&SpunUp, 0.0, y0, 1.0)
        .unwrap();
    assert!((y[2] - 1.2).abs() < 1e-12 && y[0] == 0.0 && y[1] == 0.0);
    let exact = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 1.0 + 0.1);
    let q = Quaternion::new(y[3], y[4], y[5], y[6]);
    assert!(eom::reference::attitude_angle(&exact, &q) < 1e-6);
}
