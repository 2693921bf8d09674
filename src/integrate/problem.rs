//! One shape for every run, and the one loop that solves it.
//!
//! A catalog scene, a ship's manoeuvre and a vehicle's trial are one problem: a state
//! integrated from its start to its end under inputs that hold between the instants where
//! they change, the run cut at those instants and at the events its state defines. It is the
//! shape of diffsol's problem (init, rhs, root, reset, out) and of an FMI model's time events,
//! state events and discrete updates; a kind says its own ([`Problem`]) and [`solve`] runs it
//! over the one driver ([`segment::advance`]), so what a run does between and at its instants
//! is written once:
//!
//! - **The schedule** (time events): the next instant the inputs change
//!   ([`Problem::next_change`]): a load table's breakpoint, a manoeuvre's execute, a series'
//!   breakpoint, an autopilot's sample. A change may put later ones on (a spiral's next check).
//!   Each stretch ends exactly there, so no step straddles a jump, and
//!   [`Problem::change`] resets the inputs (and a state that jumps, a rudder without a lag).
//! - **The watches** (state events): functions of the state whose change of sign is an event
//!   ([`Problem::watches`], [`Problem::g`]): a heading change, a zero yaw rate, a fin reaching
//!   its rate limit (a kink a step across would be first-order accurate about). The stretch
//!   ends where the first changes sign, located to adjacent floating-point numbers of t on the
//!   integrator's own solution, and [`Problem::event`] says what happens there.
//! - **The stop condition** ([`Problem::stop_holds`]): a condition on the state that ends the
//!   run where it first holds, located as a watch is (a scene's `stop_when`); where it holds
//!   at the start, the run ends there.
//! - **Rows** go to the observer at t = k·every, at each event and at each change (the state
//!   and the inputs after it), at the stop, and at the end ([`Problem::sample`]).
//! - **Accepted steps** go to [`Problem::accepted`] as they are taken: a course's record, a
//!   guard's check, which may end the run there.
//!
//! A problem says its system under the inputs as they stand as a concrete type
//! ([`Problem::System`]), so each stretch's steps are compiled for that model: the loop costs
//! no call through a pointer per step beyond the driver's own. A system's `rhs` written in a
//! kind's module is marked `#[inline]`, so that it is inlined into the method's step where
//! this loop's stretches are compiled (without it the mariner's manoeuvres ran 5 % slower).

use super::segment::{self, Hooks, Piece, add};
use super::{IntegrateError, OdeSystem, Reached, RowClock, Stats, Stepper};
use nalgebra::SVector;
use std::cell::RefCell;

/// What a run does after a change of its schedule or an event (or after a stretch).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Flow {
    /// It goes on.
    Go,
    /// It ends here (a spiral has measured every setpoint, a crash stop's ship has stopped).
    Stop,
}

/// A run as the one loop solves it (see the module's docs).
pub(crate) trait Problem<const N: usize> {
    /// The model under the inputs as they stand over one stretch.
    type System: OdeSystem<f64, N>;
    /// What the run watches for.
    type Watch: Copy;
    /// What a row hands the observer.
    type Sample;

    /// Whether a row shows each scheduled change: `true` where the row shows the inputs (a
    /// rudder's command) or the state may jump there; a body's rows show neither, and its
    /// load tables' breakpoints get no row of their own.
    const ROW_AT_CHANGE: bool = true;

    /// The start (t₀, y₀), after what the schedule changes at t₀.
    fn start(&mut self) -> (f64, SVector<f64, N>);

    /// The end of the run.
    fn end(&self) -> f64;

    /// The next instant the schedule changes the inputs, if one is due.
    fn next_change(&self) -> Option<f64>;

    /// The system from `t` to `until` under the inputs as they stand.
    fn system(&self, t: f64, until: f64) -> Self::System;

    /// What the stretch from `(t, y)` under `system` watches for.
    fn watches(&self, system: &Self::System, t: f64, y: &SVector<f64, N>) -> Vec<Self::Watch>;

    /// The watched function: `watch`'s event is where it changes sign.
    fn g(&self, system: &Self::System, watch: Self::Watch, t: f64, y: &SVector<f64, N>) -> f64;

    /// Whether the run has a stop condition ([`stop_holds`](Self::stop_holds)); one without is
    /// not asked after every step.
    fn has_stop(&self) -> bool {
        false
    }

    /// Whether the stop condition holds at `(t, y)`: the run ends where it first does.
    fn stop_holds(&self, _t: f64, _y: &SVector<f64, N>) -> bool {
        false
    }

    /// Sees the state after every accepted step, the stretch's last too, past an event or
    /// not; `false` ends the run there.
    fn accepted(&mut self, _t: f64, _y: &SVector<f64, N>) -> bool {
        true
    }

    /// The schedule's change at `t`: the inputs (and a state that jumps) reset.
    fn change(&mut self, t: f64, y: &mut SVector<f64, N>) -> Flow;

    /// The event `watch` at `t`: the inputs (and a state that jumps) reset.
    fn event(&mut self, watch: Self::Watch, t: f64, y: &mut SVector<f64, N>) -> Flow;

    /// A stretch stopped at `(t, y)` where a watch was found within rounding of its zero
    /// without having changed sign (the step taken again to the located time lands a last
    /// bit apart): no event; the run goes on from there, and the steps past `t` were the
    /// stretch's trial.
    fn resumed(&mut self, _t: f64, _y: &SVector<f64, N>) {}

    /// The run has reached its end at `(t, y)`.
    fn finish(&mut self, _t: f64, _y: &SVector<f64, N>) {}

    /// The row at `(t, y)`.
    fn sample(&self, t: f64, y: &SVector<f64, N>) -> Self::Sample;
}

/// Runs `problem` from its start to its end with `stepper`'s method, each row (at
/// t = k·`every` and at each change, event and stop) handed to `observe`, whose `false` ends
/// the run ([`IntegrateError::Stopped`]). Gives where it ended (`stopped` where the stop
/// condition ended it) and what it cost.
pub(crate) fn solve<P: Problem<N>, const N: usize>(
    problem: &mut P,
    (stepper, every): (&Stepper, f64),
    mut observe: impl FnMut(&P::Sample) -> bool,
) -> Piece<N> {
    let (mut t, mut y) = problem.start();
    let end = problem.end();
    let mut rows = RowClock::new(t, every);
    let mut total = Stats::default();
    // The step observer changes the problem while the watches read it, each between the
    // other's calls.
    let problem = RefCell::new(problem);
    let mut row = |p: &P, t: f64, y: &SVector<f64, N>| observe(&p.sample(t, y));
    loop {
        let b = (problem.borrow().next_change()).map_or(end, |change| change.min(end));
        let (result, stats, fired) =
            stretch(&problem, stepper, (t, y, b, end), &mut rows, &mut row);
        add(&mut total, stats);
        let mut reached = match result {
            Ok(reached) => reached,
            Err(error) => return (Err(error), total),
        };
        let p = &mut **problem.borrow_mut();
        match resume(p, (t, b, end), (&mut reached, fired), (&rows, &mut row)) {
            Ok(Flow::Go) => (t, y) = (reached.t, reached.state),
            Ok(Flow::Stop) => return (Ok(reached), total),
            Err(refused) => return (Err(refused), total),
        }
    }
}

/// What happens where a stretch from `a` ended (`reached`, short of `b` or at it): the stop
/// condition ends the run; an event (`fired`) resets the problem, with a row after it; at
/// `b`, the schedule's change resets it, with a row where [`Problem::ROW_AT_CHANGE`] (a row
/// due there is the next stretch's first, from the state after it); at `end`, the run ends.
/// The state after a reset is `reached`'s; whether the run goes on, or `Err` where the
/// observer refused a row.
fn resume<P: Problem<N>, const N: usize>(
    p: &mut P,
    (a, b, end): (f64, f64, f64),
    (reached, fired): (&mut Reached<f64, N>, Option<P::Watch>),
    (rows, row): (&RowClock<f64>, Row<'_, P, N>),
) -> Result<Flow, IntegrateError> {
    let (t, y) = (reached.t, &mut reached.state);
    let mut written = |p: &P, y: &SVector<f64, N>| {
        row(p, t, y)
            .then_some(())
            .ok_or(IntegrateError::Stopped { t })
    };
    if reached.stopped && p.has_stop() && p.stop_holds(t, y) {
        // A condition holding at the stretch's start ends it before a step: its row there,
        // if one was due, is written.
        if t > a {
            written(p, y)?;
        }
        return Ok(Flow::Stop);
    }
    let mut flow = Flow::Go;
    if let Some(watch) = fired {
        flow = p.event(watch, t, y);
        written(p, y)?;
    } else if reached.stopped {
        // No event yet (see [`Problem::resumed`]); the next stretch finds it if the sign
        // changes. The row due here, which the stop took the place of, is written.
        p.resumed(t, y);
        if rows.next > 0 && rows.time(rows.next - 1) == t {
            written(p, y)?;
        }
    }
    reached.stopped = false;
    // Short of the stretch's end (after an event, or resumed): the run goes on.
    if flow == Flow::Stop || t < b {
        return Ok(flow);
    }
    if t >= end {
        p.finish(t, y);
        return Ok(Flow::Stop);
    }
    flow = p.change(t, y);
    if P::ROW_AT_CHANGE && rows.next_time() != t {
        written(p, y)?;
    }
    Ok(flow)
}

/// Where a problem's rows go: the sample at `(t, y)` to the observer; `false` ends the run.
type Row<'a, P, const N: usize> = &'a mut dyn FnMut(&P, f64, &SVector<f64, N>) -> bool;

/// Where a stretch ended, what it cost, and the watch whose event ended it.
type Stretch<W, const N: usize> = (Result<Reached<f64, N>, IntegrateError>, Stats, Option<W>);

/// One stretch of `problem` from `(a, y_a)` to `b` under its system as it stands: every
/// accepted step to [`Problem::accepted`], every row to `row`, ending early where the stop
/// condition first holds or one of its watches first changes sign from its sign at `a` (one
/// at zero at `a` is not watched), located to adjacent floating-point numbers of t. The row
/// at a located stop is the loop's (it may reset the state there first); the row due at `b`
/// is this stretch's where `b` is the run's end, else the next stretch's first.
fn stretch<P: Problem<N>, const N: usize>(
    problem: &RefCell<&mut P>,
    stepper: &Stepper,
    (a, y_a, b, end): (f64, SVector<f64, N>, f64, f64),
    rows: &mut RowClock<f64>,
    row: Row<'_, P, N>,
) -> Stretch<P::Watch, N> {
    let (system, watches, start, has_stop) = {
        let p = problem.borrow();
        let system = p.system(a, b);
        let watches = p.watches(&system, a, &y_a);
        let start: Vec<f64> = watches.iter().map(|w| p.g(&system, *w, a, &y_a)).collect();
        (system, watches, start, p.has_stop())
    };
    // Whether `watch`, at g0 when the stretch began, has changed its sign at (t, y).
    let moved = |p: &P, watch: P::Watch, g0: f64, t: f64, y: &SVector<f64, N>| {
        g0 != 0.0 && p.g(&system, watch, t, y).signum() != g0.signum()
    };
    // Asked after every step: no list made.
    let stop = |t: f64, y: &SVector<f64, N>| {
        let p: &P = &problem.borrow();
        (has_stop && p.stop_holds(t, y))
            || (watches.iter().zip(&start)).any(|(w, g0)| moved(p, *w, *g0, t, y))
    };
    let hooks = Hooks {
        check: &mut |t, y| problem.borrow_mut().accepted(t, y),
        stop: (has_stop || !watches.is_empty())
            .then_some(&stop as &dyn Fn(f64, &SVector<f64, N>) -> bool),
        emit: &mut |t, y| row(&**problem.borrow(), t, y),
        row_at_end: b >= end,
        row_at_stop: false,
    };
    let (reached, stats) = segment::advance(stepper, &system, (a, y_a, b), rows, hooks);
    let fired = reached.as_ref().ok().filter(|r| r.stopped).and_then(|r| {
        let p: &P = &problem.borrow();
        let changed =
            (watches.iter().zip(&start)).filter(|(w, g0)| moved(p, **w, **g0, r.t, &r.state));
        let nearness = |w: &P::Watch| p.g(&system, *w, r.t, &r.state).abs();
        (changed.map(|(w, _)| *w)).min_by(|a, b| nearness(a).total_cmp(&nearness(b)))
    });
    (reached, stats, fired)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::{AdaptiveOptions, Method};
    use nalgebra::Vector1;

    /// ẏ = `rate`.
    struct Rate(f64);

    impl OdeSystem<f64, 1> for Rate {
        fn rhs(&self, _t: f64, _y: &Vector1<f64>, dy: &mut Vector1<f64>) {
            dy[0] = self.0;
        }
    }

    /// The level y = 1/4 that [`Ramp`] watches for.
    #[derive(Debug, Clone, Copy, PartialEq)]
    struct Level;

    /// y(0) = 0, ẏ = 1 until the schedule's change at t = 1, then ẏ = −1, watching from there
    /// for y = 1/4 (at t = 7/4), where y is reset to 1; the run ends at t = 3, or where
    /// y > `stop_above` first holds.
    struct Ramp {
        rate: f64,
        changes: Vec<f64>,
        watching: bool,
        stop_above: Option<f64>,
        events: Vec<(f64, f64)>,
        steps: usize,
        finished: Option<f64>,
    }

    impl Ramp {
        fn new(stop_above: Option<f64>) -> Self {
            Ramp {
                rate: 1.0,
                changes: vec![1.0],
                watching: false,
                stop_above,
                events: Vec::new(),
                steps: 0,
                finished: None,
            }
        }
    }

    impl Problem<1> for Ramp {
        type System = Rate;
        type Watch = Level;
        type Sample = (f64, f64);

        fn start(&mut self) -> (f64, Vector1<f64>) {
            (0.0, Vector1::new(0.0))
        }

        fn end(&self) -> f64 {
            3.0
        }

        fn next_change(&self) -> Option<f64> {
            self.changes.first().copied()
        }

        fn system(&self, _t: f64, _until: f64) -> Rate {
            Rate(self.rate)
        }

        fn watches(&self, _: &Rate, _: f64, _: &Vector1<f64>) -> Vec<Level> {
            if self.watching { vec![Level] } else { vec![] }
        }

        fn g(&self, _: &Rate, _: Level, _: f64, y: &Vector1<f64>) -> f64 {
            y[0] - 0.25
        }

        fn has_stop(&self) -> bool {
            self.stop_above.is_some()
        }

        fn stop_holds(&self, _t: f64, y: &Vector1<f64>) -> bool {
            self.stop_above.is_some_and(|level| y[0] > level)
        }

        fn accepted(&mut self, _t: f64, _y: &Vector1<f64>) -> bool {
            self.steps += 1;
            true
        }

        fn change(&mut self, _t: f64, _y: &mut Vector1<f64>) -> Flow {
            self.changes.remove(0);
            self.rate = -1.0;
            self.watching = true;
            Flow::Go
        }

        fn event(&mut self, _: Level, t: f64, y: &mut Vector1<f64>) -> Flow {
            self.events.push((t, y[0]));
            y[0] = 1.0;
            self.watching = false;
            Flow::Go
        }

        fn finish(&mut self, t: f64, _y: &Vector1<f64>) {
            self.finished = Some(t);
        }

        fn sample(&self, t: f64, y: &Vector1<f64>) -> (f64, f64) {
            (t, y[0])
        }
    }

    /// RK4 at a step of 0.1 and DOP853: both integrate a constant rate exactly but for
    /// rounding.
    fn steppers() -> [Stepper; 2] {
        let fixed = Stepper {
            method: Method::Rk4,
            step: Some(0.1),
            adaptive: None,
            kicked: 0..1,
        };
        let adaptive = Stepper {
            method: Method::Dop853,
            step: None,
            adaptive: Some(AdaptiveOptions::dop853(1e-10, 1e-10)),
            kicked: 0..1,
        };
        [fixed, adaptive]
    }

    /// Solves `ramp` with `stepper`, rows every 0.5 s.
    fn solved(ramp: &mut Ramp, stepper: &Stepper) -> (Reached<f64, 1>, Vec<(f64, f64)>) {
        let mut rows = Vec::new();
        let (reached, _) = solve(ramp, (stepper, 0.5), |row: &(f64, f64)| {
            rows.push(*row);
            true
        });
        (reached.unwrap(), rows)
    }

    /// The scheduled change turns the rate at t = 1; the watch fires where y = 1/4, at
    /// t = 7/4, located to the rounding of the integrated solution; the reset's y = 1 is
    /// what the event's row shows and what the run goes on from, to y(3) = −1/4. The rows are
    /// at k·0.5 s (the one at the change from the state after it) and at the event.
    #[test]
    fn one_loop_changes_on_schedule_and_resets_at_an_event() {
        // The rounding of a few dozen sums of steps near 1: a few ulps of 1.
        let near = |a: f64, b: f64| (a - b).abs() <= 1e-14;
        for stepper in steppers() {
            let mut ramp = Ramp::new(None);
            let (end, rows) = solved(&mut ramp, &stepper);
            let method = stepper.method.name();
            assert_eq!((end.t, end.stopped, ramp.finished), (3.0, false, Some(3.0)));
            assert!(
                near(end.state[0], -0.25),
                "{method}: y(3) = {}",
                end.state[0]
            );
            let [(t, y)] = ramp.events[..] else {
                panic!("{method}: events {:?}", ramp.events);
            };
            assert!(
                near(t, 1.75) && near(y, 0.25),
                "{method}: event at {t}, y = {y}"
            );
            let wanted = [
                (0.0, 0.0),
                (0.5, 0.5),
                (1.0, 1.0),
                (1.5, 0.5),
                (t, 1.0),
                (2.0, 0.75),
                (2.5, 0.25),
                (3.0, -0.25),
            ];
            assert_eq!(rows.len(), wanted.len(), "{method}: {rows:?}");
            for (row, want) in rows.iter().zip(wanted) {
                assert!(row.0 == want.0 && near(row.1, want.1), "{method}: {row:?}");
            }
            assert!(ramp.steps > 0, "{method}: no step was seen");
        }
    }

    /// A stop condition ends the run where it first holds, located, with a row there and no
    /// `finish`; one that holds at the start ends it there, before a step, with the start's
    /// row alone.
    #[test]
    fn a_stop_condition_ends_the_run_where_it_first_holds() {
        for stepper in steppers() {
            let method = stepper.method.name();
            let mut ramp = Ramp::new(Some(0.6));
            let (end, rows) = solved(&mut ramp, &stepper);
            assert!(end.stopped && ramp.finished.is_none(), "{method}");
            // The first time y > 0.6 holds on y = t: 0.6 within the rounding of the sums.
            assert!(
                (end.t - 0.6).abs() <= 1e-14,
                "{method}: stopped at {}",
                end.t
            );
            let times: Vec<f64> = rows.iter().map(|r| r.0).collect();
            assert_eq!(times, [0.0, 0.5, end.t], "{method}");

            let mut ramp = Ramp::new(Some(-1.0));
            let (end, rows) = solved(&mut ramp, &stepper);
            assert_eq!((end.t, end.stopped, ramp.steps), (0.0, true, 0), "{method}");
            assert_eq!(rows, [(0.0, 0.0)], "{method}");
        }
    }
}

#[cfg(test)]
mod resumed {
    use super::*;
    use crate::integrate::Method;
    use nalgebra::Vector1;
    use std::cell::Cell;

    /// ẏ = 1 to t = 1, watching a function that seems to change sign on its first evaluation
    /// at t ≥ 1/2 and not when asked again there: as a watch within rounding of its zero
    /// does where the step taken again to the located time lands a last bit apart.
    #[derive(Default)]
    struct Flicker {
        flickered: Cell<bool>,
        resumed: Vec<f64>,
        events: usize,
    }

    impl Problem<1> for Flicker {
        type System = fn(f64, &Vector1<f64>, &mut Vector1<f64>);
        type Watch = ();
        type Sample = f64;

        fn start(&mut self) -> (f64, Vector1<f64>) {
            (0.0, Vector1::new(0.0))
        }

        fn end(&self) -> f64 {
            1.0
        }

        fn next_change(&self) -> Option<f64> {
            None
        }

        fn system(&self, _t: f64, _until: f64) -> Self::System {
            |_, _, dy| dy[0] = 1.0
        }

        fn watches(&self, _: &Self::System, _: f64, _: &Vector1<f64>) -> Vec<()> {
            vec![()]
        }

        fn g(&self, _: &Self::System, _: (), t: f64, _: &Vector1<f64>) -> f64 {
            if t >= 0.5 && !self.flickered.replace(true) {
                -1.0
            } else {
                1.0
            }
        }

        fn change(&mut self, _: f64, _: &mut Vector1<f64>) -> Flow {
            Flow::Go
        }

        fn event(&mut self, _: (), _: f64, _: &mut Vector1<f64>) -> Flow {
            self.events += 1;
            Flow::Go
        }

        fn resumed(&mut self, t: f64, _: &Vector1<f64>) {
            self.resumed.push(t);
        }

        fn sample(&self, t: f64, _: &Vector1<f64>) -> f64 {
            t
        }
    }

    /// No event: the run goes on from where the stretch stopped, the problem told; the row
    /// due there (t = 1/2, a step's end), which the stop took the place of, is written once.
    #[test]
    fn a_stretch_stopped_without_an_event_goes_on_and_keeps_its_row() {
        let stepper = Stepper {
            method: Method::Rk4,
            step: Some(0.1),
            adaptive: None,
            kicked: 0..1,
        };
        let mut flicker = Flicker::default();
        let mut rows = Vec::new();
        let (reached, _) = solve(&mut flicker, (&stepper, 0.5), |t: &f64| {
            rows.push(*t);
            true
        });
        let reached = reached.unwrap();
        assert_eq!(
            (reached.t, reached.stopped, flicker.events),
            (1.0, false, 0)
        );
        assert_eq!(rows, [0.0, 0.5, 1.0]);
        assert_eq!(flicker.resumed, [0.5]);
    }
}
