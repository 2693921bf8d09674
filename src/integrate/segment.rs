//! The one driver of a run: any method over a stretch of time, rows at t = k·every, a check
//! after every step, and a stop condition located where it first holds.
//!
//! A catalog scene and a ship's manoeuvre are both runs cut into stretches: at the breakpoints
//! of a load's time table, at the instants a manoeuvre's schedule changes its command, at the
//! events it watches for (a heading change, a zero yaw rate). Each stretch is one call of
//! [`advance`], which integrates with the run's method from `a` to `b` and hands back where it
//! ended; the caller changes what acts on the body (the loads, the command, a state that jumps
//! like a rudder without a lag) and goes on. So what a stretch does is written once:
//!
//! - **Rows** go to `emit` at exactly t = origin + k·every ([`RowClock`]), numbered across
//!   stretches: an adaptive method places them by dense output; a fixed-step method
//!   integrates each output interval in equal steps no longer than its step, so every row
//!   lands on its time. A row due at `b` itself is written by this stretch, or, where the state
//!   may jump there, left to the next one to write from the state it starts with
//!   ([`Hooks::row_at_end`]); likewise the row at a located stop ([`Hooks::row_at_stop`]).
//! - **The check** (`check`) sees the state after every accepted step; `false` ends the run.
//! - **The stop condition** (`stop`) is evaluated at the end of every step. On the step where
//!   it first holds, the first time it holds is found by bisection to adjacent floating-point
//!   numbers ([`first_time_holding`](super::first_time_holding)): on the dense output of an
//!   adaptive method, and for a fixed-step method by taking the one step again from its start
//!   to each trial time. So an event is located to the last bit of t on the integrator's own
//!   solution; its error against the exact motion is the integrator's error there. The stretch
//!   ends there with a row at that time.
//! - **Watches** are stop conditions too: a run with events (a ship's manoeuvre, a vehicle's
//!   trial) stops a stretch where one of its functions of the state first changes sign
//!   ([`super::problem`], the one loop every run's stretches are cut and resumed by).

use super::{
    AdaptiveOptions, Dop853, Dopri5, Euler, IntegrateError, Integrator, Method, OdeSystem, Reached,
    Rk4, RowClock, Statistics, Stats, SymplecticEuler, first_time_holding,
};
use nalgebra::SVector;
use std::ops::Range;

/// A run's method with its settings: what a run's stretches are stepped with.
#[derive(Debug, Clone, PartialEq)]
pub struct Stepper {
    /// The method. [`Method::LieMidpoint`] is not a general method (it integrates a free
    /// body's rotation alone) and is refused here.
    pub method: Method,
    /// The step of a fixed-step method, s.
    pub step: Option<f64>,
    /// The options of an adaptive method.
    pub adaptive: Option<AdaptiveOptions>,
    /// The state components symplectic Euler kicks first (the velocities).
    pub kicked: Range<usize>,
}

impl Stepper {
    /// The same method made finer: half the step taken between rows `every` apart
    /// ([`half_the_step`]), or tolerances a hundred times tighter (the check of a figure's
    /// convergence).
    pub fn refined(&self, every: f64) -> Self {
        Stepper {
            step: self.step.map(|h| half_the_step(h, every)),
            adaptive: self.adaptive.map(AdaptiveOptions::tightened),
            ..self.clone()
        }
    }

    /// What a summary says of the refined run ([`Method::refinement`]).
    pub fn refinement(&self) -> &'static str {
        self.method.refinement()
    }
}

/// Half the step a fixed-step method takes with step `h` between rows `every` apart. It runs
/// each interval between rows in equal steps of at most `h` (counted with the same slack as
/// the fixed-step methods count them), so the step taken may be shorter than `h`: where `every` is
/// shorter than `h`, halving `h` alone would change nothing, and a figure would seem to have
/// converged. Where `h` divides `every`, this is `h / 2`.
pub fn half_the_step(h: f64, every: f64) -> f64 {
    step_taken(h, every) / 2.0
}

/// The step a fixed-step method takes with step `h` between rows `every` apart: each interval
/// between rows in equal steps of at most `h`, counted with the same slack as the fixed-step
/// methods count them. It is `h` where `h` divides `every`, shorter otherwise.
pub fn step_taken(h: f64, every: f64) -> f64 {
    let steps = ((every / h) * (1.0 - 1e-9)).ceil().max(1.0);
    every / steps
}

/// Where a stretch ended, and what it cost.
pub(crate) type Piece<const N: usize> = (Result<Reached<f64, N>, IntegrateError>, Stats);

/// A stop condition as a stretch evaluates it.
pub(crate) type Stop<'a, const N: usize> = Option<&'a dyn Fn(f64, &SVector<f64, N>) -> bool>;

/// Where a stretch's rows go; `false` ends the run.
pub(crate) type Emit<'a, const N: usize> = &'a mut dyn FnMut(f64, &SVector<f64, N>) -> bool;

/// What a stretch reports to, and asks of, its caller.
pub(crate) struct Hooks<'a, const N: usize> {
    /// Sees the state after every accepted step; `false` ends the run.
    pub(crate) check: &'a mut dyn FnMut(f64, &SVector<f64, N>) -> bool,
    /// Ends the stretch where it first holds.
    pub(crate) stop: Stop<'a, N>,
    /// Takes each row; `false` ends the run.
    pub(crate) emit: Emit<'a, N>,
    /// Whether a row due at the stretch's end `b` is written by it (`true`), or left to the
    /// next stretch, which writes it from the state it starts with (where the state jumps at
    /// `b`, the row then shows the state after the jump).
    pub(crate) row_at_end: bool,
    /// Whether the row at the instant `stop` ends the stretch is written by it (`true`), or
    /// left to the caller, which may change the state there first (an event that reverses a
    /// rudder without a lag). A row due at that very instant is then the caller's too.
    pub(crate) row_at_stop: bool,
}

/// A `Stepper` built by hand without the setting its method needs (the scene checkers always
/// give it): an error, not a panic.
fn missing(what: &'static str) -> IntegrateError {
    IntegrateError::MissingSetting { what }
}

/// Adds one run's counts to a total.
pub(crate) fn add(total: &mut Stats, stats: Stats) {
    total.steps += stats.steps;
    total.rejected += stats.rejected;
    total.rhs_evals += stats.rhs_evals;
}

/// One stretch of a run, from `a` to `b`, with `stepper`'s method (see the module's docs).
pub(crate) fn advance<S: OdeSystem<f64, N>, const N: usize>(
    stepper: &Stepper,
    system: &S,
    interval: (f64, SVector<f64, N>, f64),
    rows: &mut RowClock<f64>,
    hooks: Hooks<'_, N>,
) -> Piece<N> {
    let method = stepper.method;
    if method.is_adaptive() {
        let Hooks {
            check,
            stop,
            emit,
            row_at_end,
            row_at_stop,
        } = hooks;
        let Some(options) = stepper.adaptive else {
            return (
                Err(missing("adaptive options (rtol, atol)")),
                Stats::default(),
            );
        };
        let stop = |t: f64, y: &SVector<f64, N>| stop.is_some_and(|stop| stop(t, y));
        macro_rules! sampled {
            ($method:ident) => {{
                let mut method = $method::new(options);
                (rows.row_at_end, rows.row_at_stop) = (row_at_end, row_at_stop);
                let result = method.sample_until(system, interval, rows, (check, stop, emit));
                (rows.row_at_end, rows.row_at_stop) = (true, true);
                (result, method.stats())
            }};
        }
        return match method {
            Method::Dopri5 => sampled!(Dopri5),
            _ => sampled!(Dop853),
        };
    }
    let Some(step) = stepper.step else {
        return (Err(missing("step")), Stats::default());
    };
    match method {
        Method::Euler => fixed_steps(&mut Euler::new(step), system, interval, rows, hooks),
        Method::Rk4 => fixed_steps(&mut Rk4::new(step), system, interval, rows, hooks),
        Method::SymplecticEuler => {
            let mut method = SymplecticEuler::new(step, stepper.kicked.clone());
            fixed_steps(&mut method, system, interval, rows, hooks)
        }
        Method::Dop853 | Method::Dopri5 => unreachable!("adaptive methods sample above"),
        Method::LieMidpoint => (
            Err(IntegrateError::NotApplicable {
                method: method.name(),
            }),
            Stats::default(),
        ),
    }
}

/// A fixed-step method from `a` to `b` over each output interval in turn (equal steps of at
/// most its step, so that each row lands on its time, and the last on `b`), its statistics
/// summed. `check` sees the state after every step; a `false` stops the run at the end of that
/// interval, before its row is written. Where `stop` first holds at the end of a step, the step
/// is taken again to trial times for the first time it holds ([`locate`]) and the stretch ends
/// there.
pub(crate) fn fixed_steps<I, S, const N: usize>(
    method: &mut I,
    system: &S,
    (a, y_a, b): (f64, SVector<f64, N>, f64),
    rows: &mut RowClock<f64>,
    hooks: Hooks<'_, N>,
) -> Piece<N>
where
    I: Integrator<f64, N, S>,
{
    let Hooks {
        check,
        stop,
        emit,
        row_at_end,
        row_at_stop,
    } = hooks;
    let mut total = Stats::default();
    let (mut t, mut y) = (a, y_a);
    while rows.next_time() <= a {
        if !emit(rows.next_time(), &y) {
            return (Err(IntegrateError::Stopped { t }), total);
        }
        rows.next += 1;
    }
    if stop.is_some_and(|stop| stop(t, &y)) {
        let stopped = true;
        return (
            Ok(Reached {
                t,
                state: y,
                stopped,
            }),
            total,
        );
    }
    loop {
        let (t_next, is_row) = match rows.next_time() {
            row if row < b || (row == b && row_at_end) => (row, true),
            _ => (b, false),
        };
        let mut start = (t, y);
        let mut crossed = None;
        let mut halted = false;
        let result = method.integrate_with(system, t, y, t_next, |t, y| {
            if crossed.is_some() || halted {
                return;
            }
            halted = !check(t, y);
            if let Some(stop) = stop {
                if stop(t, y) {
                    crossed = Some((start, t));
                } else {
                    start = (t, *y);
                }
            }
        });
        add(&mut total, method.stats());
        if halted {
            return (Err(IntegrateError::Stopped { t: t_next }), total);
        }
        match result {
            Ok(next) => y = next,
            Err(e) => return (Err(e), total),
        }
        if let (Some(stop), Some(((t0, y0), t1))) = (stop, crossed) {
            let (reached, stats) = locate(method, system, (t0, y0, t1), stop);
            add(&mut total, stats);
            return match reached {
                Ok(reached) => (last_row(reached, rows, row_at_stop.then_some(emit)), total),
                Err(e) => (Err(e), total),
            };
        }
        t = t_next;
        if is_row {
            if !emit(t, &y) {
                return (Err(IntegrateError::Stopped { t }), total);
            }
            rows.next += 1;
        }
        if t >= b {
            let stopped = false;
            return (
                Ok(Reached {
                    t,
                    state: y,
                    stopped,
                }),
                total,
            );
        }
    }
}

/// The first time in `(t0, t1]` at which `stop` holds, for a fixed-step method whose step from
/// `(t0, y0)` to `t1` made it hold: the one step is taken again from `t0` to each trial time
/// of a bisection ([`first_time_holding`]).
fn locate<I, S, const N: usize>(
    method: &mut I,
    system: &S,
    (t0, y0, t1): (f64, SVector<f64, N>, f64),
    stop: &dyn Fn(f64, &SVector<f64, N>) -> bool,
) -> Piece<N>
where
    I: Integrator<f64, N, S>,
{
    let mut total = Stats::default();
    let mut failure = None;
    let mut step_to = |t: f64| {
        let result = method.integrate(system, t0, y0, t);
        add(&mut total, method.stats());
        result
    };
    let t = first_time_holding(t0, t1, |t| match step_to(t) {
        Ok(y) => stop(t, &y),
        Err(e) => {
            failure = Some(e);
            true
        }
    });
    let reached = match failure {
        Some(e) => Err(e),
        None => step_to(t).map(|state| Reached {
            t,
            state,
            stopped: true,
        }),
    };
    (reached, total)
}

/// Writes the row at which a stop condition ended the stretch (it takes the place of a row
/// due at that very time), where `emit` is given; else the caller writes it.
fn last_row<const N: usize>(
    reached: Reached<f64, N>,
    rows: &mut RowClock<f64>,
    emit: Option<Emit<'_, N>>,
) -> Result<Reached<f64, N>, IntegrateError> {
    if rows.next_time() == reached.t {
        rows.next += 1;
    }
    if emit.is_none_or(|emit| emit(reached.t, &reached.state)) {
        Ok(reached)
    } else {
        Err(IntegrateError::Stopped { t: reached.t })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector1;

    /// Half the step is half the one taken: `h / 2` to the bit where `h` divides the rows'
    /// interval (the example scenes' steps and intervals), half the interval where the rows
    /// are closer than `h`, and half the shortened step where `h` does not divide it.
    #[test]
    fn half_the_step_is_half_the_step_taken_between_rows() {
        for (h, every) in [
            (0.1, 1.0),
            (0.2, 2.0),
            (0.02, 0.5),
            (0.01, 0.1),
            (0.005, 0.005),
        ] {
            assert_eq!(half_the_step(h, every), h / 2.0, "h = {h}, every = {every}");
        }
        assert_eq!(half_the_step(0.02, 0.005), 0.0025);
        // 1 s in steps of at most 0.3 s is four steps of 0.25 s.
        assert_eq!(half_the_step(0.3, 1.0), 0.125);
    }

    /// A stepper built by hand without its step or its tolerances is an error, not a panic;
    /// with them, a stretch of ẏ = 1 reaches its end with its rows on k·every.
    #[test]
    fn a_stepper_without_its_setting_is_an_error() {
        let system = |_t: f64, _y: &Vector1<f64>, dy: &mut Vector1<f64>| dy[0] = 1.0;
        let mut rows_seen = Vec::new();
        let mut run = |stepper: &Stepper| {
            let mut rows = RowClock::new(0.0, 0.25);
            let hooks = Hooks {
                check: &mut |_, _| true,
                stop: None,
                emit: &mut |t, _| {
                    rows_seen.push(t);
                    true
                },
                row_at_end: true,
                row_at_stop: true,
            };
            advance(
                stepper,
                &system,
                (0.0, Vector1::new(0.0), 1.0),
                &mut rows,
                hooks,
            )
            .0
        };
        for method in [Method::Rk4, Method::Dop853] {
            let bare = Stepper {
                method,
                step: None,
                adaptive: None,
                kicked: 0..1,
            };
            assert!(matches!(
                run(&bare),
                Err(IntegrateError::MissingSetting { .. })
            ));
        }
        let rk4 = Stepper {
            method: Method::Rk4,
            step: Some(0.1),
            adaptive: None,
            kicked: 0..1,
        };
        let reached = run(&rk4).unwrap();
        assert_eq!((reached.t, reached.stopped), (1.0, false));
        // RK4 integrates a constant rate exactly, up to the rounding of 12 steps' sums.
        assert!((reached.state[0] - 1.0).abs() <= 4.0 * f64::EPSILON);
        assert_eq!(rows_seen, [0.0, 0.25, 0.5, 0.75, 1.0]);
    }
}
