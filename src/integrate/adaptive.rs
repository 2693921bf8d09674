//! The one driver of the adaptive methods: any embedded explicit Runge–Kutta pair, stepped
//! under error control.
//!
//! [`Dopri5`](super::Dopri5) and [`Dop853`](super::Dop853) differ in their coefficients, in how
//! they turn their stages into an error estimate, and in their dense output — and in nothing
//! else. The initial step, the step budget, the PI controller, acceptance and rejection, the
//! reuse of f(tₙ₊₁, yₙ₊₁) as the next first stage, the finiteness check, the observer and the
//! counting of RHS evaluations are Hairer's for both. So a method is an [`EmbeddedPair`] — its
//! tableau and what is genuinely its own — and [`run`] is the loop that steps every pair: a
//! fix to the loop reaches every method, and a new pair is its coefficients.

use nalgebra::{RealField, SVector};

use super::controller::{PiController, Verdict, initial_step};
use super::{
    AdaptiveOptions, IntegrateError, OdeSystem, Probe, Stats, check_finite, check_interval,
    explain_failure, first_time_holding, lit, to_f64,
};

/// An embedded explicit Runge–Kutta pair with `S` stages, as [`run`] steps it.
///
/// Stage 1 is f(tₙ, yₙ); the rows of [`A`](EmbeddedPair::A) give stages 2, 3, … in turn. In an
/// FSAL pair the last stage is f(tₙ + h, yₙ₊₁), whose row is the weights b, and it is part of
/// every step; otherwise f(tₙ₊₁, yₙ₊₁) is evaluated once the step is accepted. Either way it is
/// the first stage of the next step.
pub(crate) trait EmbeddedPair<const S: usize> {
    /// The order of the propagated solution (it sets Hairer's initial step).
    const ORDER: i32;
    /// The controller's exponent α = α₀ − w β, as (α₀, w) (see [`PiController::new`]).
    const ALPHA: (f64, f64);
    /// The nodes cᵢ.
    const C: [f64; S];
    /// The rows aᵢⱼ of stages 2, 3, … (all but the FSAL stage, whose row is [`B`](Self::B)).
    const A: &'static [&'static [f64]];
    /// The weights bᵢ of the propagated solution.
    const B: [f64; S];
    /// Whether the last stage is f(tₙ + h, yₙ₊₁) ("first same as last").
    const FSAL: bool;
    /// The RHS evaluations [`dense_output`](Self::dense_output) makes.
    const DENSE_RHS: usize;

    /// The scaled error of a trial step (accepted when at most one) from its stages `k`, the
    /// increment Σ bᵢkᵢ, the step `h`, the states at both ends and `tols = (rtol, atol)`.
    fn error<T: RealField + Copy, const N: usize>(
        k: &[SVector<T, N>; S],
        increment: &SVector<T, N>,
        h: T,
        ends: (&SVector<T, N>, &SVector<T, N>),
        tols: (T, T),
    ) -> T;

    /// The continuous extension of an accepted step: the state at any time within it.
    fn dense_output<T, const N: usize, Sys>(
        system: &Sys,
        step: &AcceptedStep<'_, T, N, S>,
    ) -> impl Fn(T) -> SVector<T, N>
    where
        T: RealField + Copy,
        Sys: OdeSystem<T, N> + ?Sized;
}

/// One accepted step as dense output needs it: where it started, its size, the states at
/// both ends, its stages and f(tₙ₊₁, yₙ₊₁) (borrowed, so that a run without dense output
/// copies nothing).
pub(crate) struct AcceptedStep<'a, T: RealField + Copy, const N: usize, const S: usize> {
    pub(crate) t_old: T,
    pub(crate) h: T,
    pub(crate) y_old: &'a SVector<T, N>,
    pub(crate) y_new: &'a SVector<T, N>,
    pub(crate) k: &'a [SVector<T, N>; S],
    pub(crate) k_new: &'a SVector<T, N>,
}

/// Σ wⱼ kⱼ over the stages whose weight is non-zero (many of Dop853's coefficients are zero,
/// and skipping them saves their multiply-adds).
pub(crate) fn combine<T: RealField + Copy, const N: usize>(
    w: &[f64],
    k: &[SVector<T, N>],
) -> SVector<T, N> {
    let mut sum = SVector::<T, N>::zeros();
    for (wj, kj) in w.iter().zip(k) {
        if *wj != 0.0 {
            sum.axpy(lit(*wj), kj, T::one());
        }
    }
    sum
}

/// Evaluates stages 2–S of a step of size `h` from `(t, y)` into `k`, whose first entry is
/// the first stage, and returns the candidate state and its scaled error.
pub(crate) fn trial<P, const S: usize, T, const N: usize, Sys>(
    system: &Sys,
    (t, h): (T, T),
    y: &SVector<T, N>,
    tols: (T, T),
    k: &mut [SVector<T, N>; S],
) -> (SVector<T, N>, T)
where
    P: EmbeddedPair<S>,
    T: RealField + Copy,
    Sys: OdeSystem<T, N> + ?Sized,
{
    for (s, row) in P::A.iter().enumerate() {
        let ys = y + combine(row, &k[..]) * h;
        system.rhs(t + h * lit(P::C[s + 1]), &ys, &mut k[s + 1]);
    }
    let increment = combine(&P::B, &k[..]);
    let y_new = y + increment * h;
    if P::FSAL {
        system.rhs(t + h, &y_new, &mut k[S - 1]);
    }
    let err = P::error(k, &increment, h, (y, &y_new), tols);
    (y_new, err)
}

/// Integrates from `(t0, y0)` to `t_end` with the pair `P`, calling `on_step` after every
/// accepted step; `on_step` returns the RHS evaluations it made, which are counted too, or
/// `None` to stop the run there ([`IntegrateError::Stopped`]).
/// `stats` holds the counts of the run so far, also when it fails.
pub(crate) fn run<P, const S: usize, T, const N: usize>(
    (options, stats): (&AdaptiveOptions, &mut Stats),
    system: &(impl OdeSystem<T, N> + ?Sized),
    (t0, y0, t_end): (T, SVector<T, N>, T),
    mut on_step: impl FnMut(&AcceptedStep<'_, T, N, S>) -> Option<usize>,
) -> Result<SVector<T, N>, IntegrateError>
where
    P: EmbeddedPair<S>,
    T: RealField + Copy,
{
    const { assert!(P::A.len() + 1 + P::FSAL as usize == S) };
    *stats = Stats::default();
    let Some(start) = start(options, system, (t0, &y0, t_end), P::ORDER)? else {
        return Ok(y0);
    };
    let Start {
        mut k1,
        mut progress,
        tols,
        rhs_evals,
    } = start;
    stats.rhs_evals = rhs_evals;
    let mut y = y0;
    let mut controller = PiController::new(options, P::ALPHA);
    let mut k = [SVector::<T, N>::zeros(); S];
    loop {
        let last = progress.next_step()?;
        let (t, h) = (progress.t, progress.h);
        k[0] = k1;
        let (y_new, err) = trial::<P, S, T, N, _>(system, (t, h), &y, tols, &mut k);
        stats.rhs_evals += S - 1;
        if !err.is_finite() {
            // Replay the step to name a non-finite load input, if the system can.
            let replay = |probe: &Probe<'_, _>| {
                let mut stages = [SVector::<T, N>::zeros(); S];
                probe.rhs(t, &y, &mut stages[0]);
                trial::<P, S, T, N, _>(probe, (t, h), &y, tols, &mut stages);
            };
            let (cause, replayed) = explain_failure(system, replay);
            stats.rhs_evals += replayed;
            if let Some(cause) = cause {
                return Err(cause);
            }
            check_finite(&y_new, t + h)?;
        }
        let accepted = progress.record(controller.decide(err, h), last);
        (stats.steps, stats.rejected) = (progress.steps, progress.rejected);
        if !accepted {
            continue;
        }
        stats.rhs_evals +=
            next_first_stage::<P, S, T, N>(system, (progress.t, &y_new), &k, &mut k1);
        let step = AcceptedStep {
            t_old: t,
            h,
            y_old: &y,
            y_new: &y_new,
            k: &k,
            k_new: &k1,
        };
        match on_step(&step) {
            Some(evals) => stats.rhs_evals += evals,
            None => return Err(IntegrateError::Stopped { t: to_f64(t + h) }),
        }
        y = y_new;
        if last {
            return Ok(y);
        }
    }
}

/// Writes f(tₙ₊₁, yₙ₊₁), the first stage of the next step, into `k1` once a step is accepted:
/// the last stage of an FSAL pair, a new evaluation otherwise. Returns the evaluations made.
fn next_first_stage<P, const S: usize, T, const N: usize>(
    system: &(impl OdeSystem<T, N> + ?Sized),
    (t_new, y_new): (T, &SVector<T, N>),
    k: &[SVector<T, N>; S],
    k1: &mut SVector<T, N>,
) -> usize
where
    P: EmbeddedPair<S>,
    T: RealField + Copy,
{
    if P::FSAL {
        *k1 = k[S - 1];
        0
    } else {
        system.rhs(t_new, y_new, k1);
        1
    }
}

/// [`Integrator::integrate_with`](super::Integrator::integrate_with) for the pair `P`.
pub(crate) fn integrate<P, const S: usize, T, const N: usize>(
    run_state: (&AdaptiveOptions, &mut Stats),
    system: &(impl OdeSystem<T, N> + ?Sized),
    interval: (T, SVector<T, N>, T),
    mut observe: impl FnMut(T, &SVector<T, N>),
) -> Result<SVector<T, N>, IntegrateError>
where
    P: EmbeddedPair<S>,
    T: RealField + Copy,
{
    run::<P, S, T, N>(run_state, system, interval, |step| {
        observe(step.t_old + step.h, step.y_new);
        Some(0)
    })
}

/// Integrates from `(t0, y0)` to the last of `times` (ascending, none before `t0`) with the
/// pair `P` and writes the state at each of `times` into `out` by dense output: the steps are
/// chosen by the tolerance alone, and only the steps that hold an output time build their
/// continuous extension.
pub(crate) fn solve_at<P, const S: usize, T, const N: usize>(
    run_state: (&AdaptiveOptions, &mut Stats),
    system: &(impl OdeSystem<T, N> + ?Sized),
    (t0, y0): (T, SVector<T, N>),
    times: &[T],
    out: &mut [SVector<T, N>],
) -> Result<(), IntegrateError>
where
    P: EmbeddedPair<S>,
    T: RealField + Copy,
{
    check_outputs(t0, times, out.len())?;
    let Some(&t_end) = times.last() else {
        return Ok(());
    };
    let mut next = times.iter().take_while(|&&t| t <= t0).count();
    out[..next].fill(y0);
    let y_end = run::<P, S, T, N>(run_state, system, (t0, y0, t_end), |step| {
        let t_new = step.t_old + step.h;
        if next == times.len() || times[next] > t_new {
            return Some(0);
        }
        let state_at = P::dense_output(system, step);
        while next < times.len() && times[next] <= t_new {
            out[next] = state_at(times[next]);
            next += 1;
        }
        Some(P::DENSE_RHS)
    })?;
    // Times equal to t_end that rounding kept out of the last step get the end state.
    out[next..].fill(y_end);
    Ok(())
}

/// Integrates from `(t0, y0)` to `t_end` with the pair `P` and hands the state at every
/// `t0 + k·every` (k = 0, 1, … while the time is at most `t_end`) to `emit`, by dense output,
/// as the run goes: nothing is stored, so a run of any length streams. Each time is computed
/// as `t0 + k·every`, not accumulated. `check(t, y)` sees the end of every accepted step
/// before the samples the step holds are emitted. `check` or `emit` returning `false` stops
/// the run ([`IntegrateError::Stopped`]).
pub(crate) fn sample<P, const S: usize, T, const N: usize>(
    run_state: (&AdaptiveOptions, &mut Stats),
    system: &(impl OdeSystem<T, N> + ?Sized),
    (t0, y0, t_end): (T, SVector<T, N>, T),
    every: T,
    (check, emit): (
        impl FnMut(T, &SVector<T, N>) -> bool,
        impl FnMut(T, &SVector<T, N>) -> bool,
    ),
) -> Result<SVector<T, N>, IntegrateError>
where
    P: EmbeddedPair<S>,
    T: RealField + Copy,
{
    let mut rows = RowClock::new(t0, every);
    let never = |_: T, _: &SVector<T, N>| false;
    let handlers = (check, never, emit);
    let reached =
        sample_until::<P, S, T, N>(run_state, system, (t0, y0, t_end), &mut rows, handlers)?;
    Ok(reached.state)
}

/// Sample times `origin + k·every`, numbered so that a run cut into pieces (at a load
/// table's breakpoints) goes on with the next row where the last piece stopped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RowClock<T> {
    origin: T,
    every: T,
    /// The number k of the next row to write.
    pub(crate) next: usize,
    /// Whether a row due at the very end of the stretch being integrated is written by it
    /// (`true`), or left to the next stretch, which writes it from the state it starts with,
    /// where the state may jump (see [`super::segment`]).
    pub(crate) row_at_end: bool,
    /// Whether the row at the instant a stop condition ends the stretch is written by it
    /// (`true`), or by the caller, which may change the state there first.
    pub(crate) row_at_stop: bool,
}

impl<T: RealField + Copy> RowClock<T> {
    /// Rows at `origin + k·every` from k = 0.
    pub(crate) fn new(origin: T, every: T) -> Self {
        Self {
            origin,
            every,
            next: 0,
            row_at_end: true,
            row_at_stop: true,
        }
    }

    /// Whether the row due at `t` is written by a stretch that ends at `t_end`.
    pub(crate) fn writes(&self, t: T, t_end: T) -> bool {
        t < t_end || (t == t_end && self.row_at_end)
    }

    /// The time of row k, computed, not accumulated.
    pub(crate) fn time(&self, k: usize) -> T {
        self.origin + self.every * lit::<T>(k as f64)
    }

    /// The time of the next row.
    pub(crate) fn next_time(&self) -> T {
        self.time(self.next)
    }
}

/// Where a run ended: at its end time, or where its stop condition first held.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Reached<T: RealField + Copy, const N: usize> {
    /// The time.
    pub(crate) t: T,
    /// The state there.
    pub(crate) state: SVector<T, N>,
    /// Whether the stop condition ended the run.
    pub(crate) stopped: bool,
}

/// As [`sample`], continuing the rows of `rows` (those at or before `t0` are the start's),
/// and ending the run where `stop(t, y)` first holds: on the step at whose end it holds,
/// the dense output is searched by bisection for the first time it holds, to adjacent
/// floating-point numbers ([`first_time_holding`]); the rows before that time are emitted,
/// then a last row there. A condition that holds at `t0` ends the run at once.
pub(crate) fn sample_until<P, const S: usize, T, const N: usize>(
    (options, stats): (&AdaptiveOptions, &mut Stats),
    system: &(impl OdeSystem<T, N> + ?Sized),
    (t0, y0, t_end): (T, SVector<T, N>, T),
    rows: &mut RowClock<T>,
    (mut check, mut stop, mut emit): (
        impl FnMut(T, &SVector<T, N>) -> bool,
        impl FnMut(T, &SVector<T, N>) -> bool,
        impl FnMut(T, &SVector<T, N>) -> bool,
    ),
) -> Result<Reached<T, N>, IntegrateError>
where
    P: EmbeddedPair<S>,
    T: RealField + Copy,
{
    if !(rows.every.is_finite() && rows.every > T::zero()) {
        return Err(IntegrateError::InvalidStep {
            name: "every",
            value: to_f64(rows.every),
        });
    }
    check_interval(t0, t_end)?;
    while rows.next_time() <= t0 {
        if !emit(rows.next_time(), &y0) {
            return Err(IntegrateError::Stopped { t: to_f64(t0) });
        }
        rows.next += 1;
    }
    if stop(t0, &y0) {
        return Ok(Reached {
            t: t0,
            state: y0,
            stopped: true,
        });
    }
    let mut ended = None;
    let run_state = (options, &mut *stats);
    let result = run::<P, S, T, N>(run_state, system, (t0, y0, t_end), |step| {
        let t_new = step.t_old + step.h;
        if !check(t_new, step.y_new) {
            return None;
        }
        let stopping = stop(t_new, step.y_new);
        let next = rows.next_time();
        if !stopping && (next > t_new || next > t_end) {
            return Some(0);
        }
        let state_at = P::dense_output(system, step);
        let until = if stopping {
            let t = first_time_holding(step.t_old, t_new, |t| stop(t, &state_at(t)));
            let state = if t == t_new { *step.y_new } else { state_at(t) };
            (t, state)
        } else {
            (t_new, *step.y_new)
        };
        // A row at the stopping time itself is the last row, written below.
        let before = |t: T| if stopping { t < until.0 } else { t <= until.0 };
        while rows.writes(rows.next_time(), t_end) && before(rows.next_time()) {
            let t = rows.next_time();
            if !emit(t, &state_at(t)) {
                return None;
            }
            rows.next += 1;
        }
        if stopping {
            if rows.next_time() == until.0 {
                rows.next += 1;
            }
            if !rows.row_at_stop || emit(until.0, &until.1) {
                ended = Some(until);
            }
            return None;
        }
        Some(P::DENSE_RHS)
    });
    let y_end = match (result, ended) {
        (Ok(y_end), _) => y_end,
        (Err(IntegrateError::Stopped { .. }), Some((t, state))) => {
            // The step that stopped built its dense output.
            stats.rhs_evals += P::DENSE_RHS;
            return Ok(Reached {
                t,
                state,
                stopped: true,
            });
        }
        (Err(e), _) => return Err(e),
    };
    // A sample time at t_end that rounding kept out of the last step gets the end state.
    if rows.writes(rows.next_time(), t_end) {
        if !emit(rows.next_time(), &y_end) {
            return Err(IntegrateError::Stopped { t: to_f64(t_end) });
        }
        rows.next += 1;
    }
    Ok(Reached {
        t: t_end,
        state: y_end,
        stopped: false,
    })
}

/// Checks that the output times are ascending, none before `t0`, and that `out` holds one
/// state per time.
fn check_outputs<T: RealField + Copy>(
    t0: T,
    times: &[T],
    slots: usize,
) -> Result<(), IntegrateError> {
    if slots != times.len() {
        return Err(IntegrateError::OutputLength {
            times: times.len(),
            slots,
        });
    }
    let mut previous = t0;
    for &t in times {
        if !t.is_finite() || t < previous {
            let (t0, t_end) = (to_f64(previous), to_f64(t));
            return Err(IntegrateError::InvalidInterval { t0, t_end });
        }
        previous = t;
    }
    Ok(())
}

/// The state of an adaptive run between steps: where it is, what it has spent, and the
/// checks every step must pass.
struct Progress<T> {
    t: T,
    t_end: T,
    h: T,
    steps: usize,
    rejected: usize,
    h_min: T,
    h_max: T,
    max_steps: usize,
}

impl<T: RealField + Copy> Progress<T> {
    /// A run from `t0` to `t_end` with the limits of `options` and the first step `h`.
    fn new(options: &AdaptiveOptions, t0: T, t_end: T, h: T) -> Self {
        let h_max = if options.h_max.is_finite() {
            lit(options.h_max)
        } else {
            t_end - t0
        };
        Self {
            t: t0,
            t_end,
            h: h.min(h_max),
            steps: 0,
            rejected: 0,
            h_min: lit(options.h_min),
            h_max,
            max_steps: options.max_steps,
        }
    }

    /// Checks the step budget and the step size, then shortens the step to land on `t_end`
    /// when it would (nearly) reach it. Returns whether this is the last step.
    fn next_step(&mut self) -> Result<bool, IntegrateError> {
        if self.steps + self.rejected >= self.max_steps {
            let (t, max_steps) = (to_f64(self.t), self.max_steps);
            return Err(IntegrateError::MaxStepsExceeded { t, max_steps });
        }
        if self.h < self.h_min || self.t + self.h * lit(0.1) == self.t {
            let (t, h, h_min) = (to_f64(self.t), to_f64(self.h), to_f64(self.h_min));
            return Err(IntegrateError::StepSizeTooSmall { t, h, h_min });
        }
        let last = self.t + self.h * lit(1.01) >= self.t_end;
        if last {
            self.h = self.t_end - self.t;
        }
        Ok(last)
    }

    /// Applies the controller's verdict on the step just tried; returns whether it was kept.
    fn record(&mut self, verdict: Verdict<T>, last: bool) -> bool {
        match verdict {
            Verdict::Accept(h_new) => {
                self.steps += 1;
                self.t = if last { self.t_end } else { self.t + self.h };
                self.h = h_new.min(self.h_max);
                true
            }
            Verdict::Reject(h_new) => {
                self.rejected += 1;
                self.h = h_new;
                false
            }
        }
    }
}

/// What an adaptive run knows before its first step.
struct Start<T: RealField + Copy, const N: usize> {
    /// f(t0, y0), the first stage of the first step.
    k1: SVector<T, N>,
    /// The run's position, with the first step size.
    progress: Progress<T>,
    /// (rtol, atol) in the scalar type.
    tols: (T, T),
    /// The RHS evaluations spent so far (f0, and one more for the initial step heuristic).
    rhs_evals: usize,
}

/// Checks the options, the interval and the initial state, evaluates f(t0, y0) and chooses
/// the first step (given, or by Hairer's heuristic for a method of order `order`). `None`
/// when there is nothing to integrate (`t_end = t0`).
fn start<T, const N: usize, S>(
    options: &AdaptiveOptions,
    system: &S,
    (t0, y0, t_end): (T, &SVector<T, N>, T),
    order: i32,
) -> Result<Option<Start<T, N>>, IntegrateError>
where
    T: RealField + Copy,
    S: OdeSystem<T, N> + ?Sized,
{
    options.validate()?;
    options.check_precision::<T>()?;
    check_interval(t0, t_end)?;
    check_finite(y0, t0)?;
    if t_end == t0 {
        return Ok(None);
    }
    let tols = (lit::<T>(options.rtol), lit::<T>(options.atol));
    let mut k1 = SVector::zeros();
    system.rhs(t0, y0, &mut k1);
    let mut progress = Progress::new(options, t0, t_end, t_end - t0);
    let (h, rhs_evals) = match options.h0 {
        Some(h0) => (lit::<T>(h0).min(progress.h_max), 1),
        None => (
            initial_step(system, (t0, y0, &k1), order, tols, progress.h_max),
            2,
        ),
    };
    progress.h = h;
    Ok(Some(Start {
        k1,
        progress,
        tols,
        rhs_evals,
    }))
}
