//! Running one model with every method over its sweep, and recording what each run cost and
//! how close it came.

use std::ops::Range;
use std::time::Instant;

use eom::integrate::{
    AdaptiveOptions, Dop853, Dopri5, Euler, Integrator, LieMidpoint, OdeSystem, RigidRotation, Rk4,
    Stats, SymplecticEuler,
};
use nalgebra::{RealField, SVector};

/// The steps per run of the first-order methods.
pub const EULER_STEPS: [usize; 4] = [1_000, 10_000, 100_000, 1_000_000];
/// The steps per run of RK4 and the geometric method.
pub const RK4_STEPS: [usize; 6] = [100, 300, 1_000, 3_000, 10_000, 30_000];
/// The relative tolerances of the adaptive methods (atol = rtol: the states are of order one).
pub const RTOLS: [f64; 10] = [
    1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12,
];
/// The most steps an adaptive run may take (ours and the peer's alike).
pub const MAX_STEPS: usize = 1_000_000;

/// One run: what was integrated, how, and what it cost.
#[derive(Debug, Clone)]
pub struct Row {
    /// The reference problem.
    pub problem: &'static str,
    /// The model variant (form of the equations, kinematics, precision).
    pub model: String,
    /// The method.
    pub method: &'static str,
    /// The sweep parameter: steps per run, or rtol.
    pub setting: Setting,
    /// Error against the exact solution at the end (NaN if the run failed).
    pub error: f64,
    /// Largest relative drift of the conserved quantities at the end.
    pub drift: f64,
    /// The cost counters.
    pub stats: Stats,
    /// The best wall time of one run, in seconds.
    pub seconds: f64,
    /// Why the run failed, if it did.
    pub failure: Option<String>,
    /// For a run of the peer: the best time of our own method on the same run and tolerance,
    /// timed alternately with the peer's so that both see the same load on the machine.
    pub paired: Option<f64>,
}

/// The sweep parameter of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Setting {
    /// A fixed-step run with this many steps.
    Steps(usize),
    /// An adaptive run with this rtol.
    Rtol(f64),
}

impl std::fmt::Display for Setting {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Setting::Steps(n) => write!(f, "{n} steps"),
            Setting::Rtol(r) => write!(f, "rtol {r:.0e}"),
        }
    }
}

/// What is being integrated: a problem's horizon and start, and how to judge an end state.
pub struct Case<'a, const M: usize> {
    /// The reference problem's name.
    pub problem: &'static str,
    /// The model variant's name.
    pub model: String,
    /// The start state in the model's layout.
    pub y0: SVector<f64, M>,
    /// The end time.
    pub t_end: f64,
    /// (error against the exact solution, relative drift of the invariants) of an end state.
    pub judge: &'a dyn Fn(&SVector<f64, M>) -> (f64, f64),
}

/// The fixed number of repetitions of every run that `WORK_PRECISION_REPS` asks for, if any.
fn fixed_repetitions() -> Option<usize> {
    std::env::var("WORK_PRECISION_REPS").ok()?.parse().ok()
}

/// Runs `run` once for the result, then again until 100 ms have passed (at most 1000 times),
/// and returns the result with the best time of one run: the minimum is the least disturbed
/// by other work on the machine. With `WORK_PRECISION_REPS=n` the repetitions are exactly `n`.
pub fn timed<R>(mut run: impl FnMut() -> R) -> (R, f64) {
    let start = Instant::now();
    let result = run();
    let mut best = start.elapsed().as_secs_f64();
    let (fixed, budget) = (fixed_repetitions(), Instant::now());
    for _ in 0..fixed.unwrap_or(1000) {
        if fixed.is_none() && budget.elapsed().as_secs_f64() > 0.1 {
            break;
        }
        let start = Instant::now();
        std::hint::black_box(run());
        best = best.min(start.elapsed().as_secs_f64());
    }
    (result, best)
}

/// The best times of one run of `a` and of `b`, timed alternately for 200 ms (at most 2000
/// rounds), so that a change of load on the machine affects both alike.
pub fn timed_pair<A, B>(mut a: impl FnMut() -> A, mut b: impl FnMut() -> B) -> (f64, f64) {
    let (mut best_a, mut best_b) = (f64::INFINITY, f64::INFINITY);
    let budget = Instant::now();
    for _ in 0..2000 {
        if budget.elapsed().as_secs_f64() > 0.2 {
            break;
        }
        let start = Instant::now();
        std::hint::black_box(a());
        best_a = best_a.min(start.elapsed().as_secs_f64());
        let start = Instant::now();
        std::hint::black_box(b());
        best_b = best_b.min(start.elapsed().as_secs_f64());
    }
    (best_a, best_b)
}

/// Converts a state to the scalar type of a run.
fn to_scalar<T: RealField + Copy, const M: usize>(y: &SVector<f64, M>) -> SVector<T, M> {
    y.map(nalgebra::convert::<f64, T>)
}

/// Converts a state of a run back to f64 for judging.
fn to_f64<T: RealField + Copy, const M: usize>(y: &SVector<T, M>) -> SVector<f64, M> {
    y.map(|v| v.to_subset().unwrap_or(f64::NAN))
}

/// Runs `method` on `system` for the case and records the row.
pub fn record<T, const M: usize, S, I>(
    case: &Case<M>,
    system: &S,
    (name, setting): (&'static str, Setting),
    mut method: I,
) -> Row
where
    T: RealField + Copy,
    S: ?Sized,
    I: Integrator<T, M, S>,
{
    let y0 = to_scalar::<T, M>(&case.y0);
    let t_end: T = nalgebra::convert(case.t_end);
    let (result, seconds) = timed(|| method.integrate(system, T::zero(), y0, t_end));
    row_of(
        case,
        (name, setting),
        result.map(|y| to_f64(&y)),
        method.stats(),
        seconds,
    )
}

/// The row of a finished (or failed) run.
pub fn row_of<const M: usize>(
    case: &Case<M>,
    (method, setting): (&'static str, Setting),
    result: Result<SVector<f64, M>, impl std::fmt::Display>,
    stats: Stats,
    seconds: f64,
) -> Row {
    let (error, drift, failure) = match result {
        Ok(y) => {
            let (error, drift) = (case.judge)(&y);
            (error, drift, None)
        }
        Err(e) => (f64::NAN, f64::NAN, Some(e.to_string())),
    };
    let (problem, model) = (case.problem, case.model.clone());
    Row {
        problem,
        model,
        method,
        setting,
        error,
        drift,
        stats,
        seconds,
        failure,
        paired: None,
    }
}

/// Adaptive options for a sweep point, with the harness's step limit.
pub fn options(base: fn(f64, f64) -> AdaptiveOptions, rtol: f64) -> AdaptiveOptions {
    AdaptiveOptions {
        max_steps: MAX_STEPS,
        ..base(rtol, rtol)
    }
}

/// Every Runge–Kutta method of the crate over its sweep; `kick` selects the components that
/// symplectic Euler updates first, `rtols` the tolerances the precision can reach.
pub fn sweep_runge_kutta<T, const M: usize, S>(
    case: &Case<M>,
    system: &S,
    kick: Option<Range<usize>>,
    rtols: &[f64],
) -> Vec<Row>
where
    T: RealField + Copy,
    S: OdeSystem<T, M>,
{
    let mut rows = Vec::new();
    let h = |n: usize| case.t_end / n as f64;
    for n in EULER_STEPS {
        let setting = Setting::Steps(n);
        rows.push(record(case, system, ("Euler", setting), Euler::new(h(n))));
        if let Some(kick) = &kick {
            let method = SymplecticEuler::new(h(n), kick.clone());
            rows.push(record(case, system, ("symplectic Euler", setting), method));
        }
    }
    for n in RK4_STEPS {
        rows.push(record(
            case,
            system,
            ("RK4", Setting::Steps(n)),
            Rk4::new(h(n)),
        ));
    }
    for &rtol in rtols {
        let setting = Setting::Rtol(rtol);
        let dopri = Dopri5::new(options(AdaptiveOptions::dopri5, rtol));
        rows.push(record(case, system, ("DOPRI5", setting), dopri));
        let dop = Dop853::new(options(AdaptiveOptions::dop853, rtol));
        rows.push(record(case, system, ("DOP853", setting), dop));
    }
    rows
}

/// The geometric rotation integrator over its sweep.
pub fn sweep_geometric<T, S>(case: &Case<7>, system: &S) -> Vec<Row>
where
    T: RealField + Copy,
    S: RigidRotation<T>,
{
    let h = |n: usize| case.t_end / n as f64;
    RK4_STEPS
        .iter()
        .map(|&n| {
            record(
                case,
                system,
                ("Lie midpoint", Setting::Steps(n)),
                LieMidpoint::new(h(n)),
            )
        })
        .collect()
}
