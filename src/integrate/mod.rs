//! Integrators for the equations of motion, behind one trait.
//!
//! Every model `eom` emits, every generic nalgebra form and any right-hand side a user writes
//! plugs into the same two traits: [`OdeSystem`] says what the derivative is, [`Integrator`]
//! says how to advance. States are const-generic [`SVector`]s, so a step allocates nothing;
//! the scalar is any [`RealField`] that is `Copy` (f32, f64), because step-size control compares
//! numbers. Each integrator keeps [`Stats`] of its last run (steps, rejected steps, RHS
//! evaluations), which the tests assert and the work–precision harness reports.
//!
//! The methods, one file each:
//! - [`Euler`]: explicit Euler, order 1 — the baseline every other method is measured against;
//! - [`SymplecticEuler`]: semi-implicit Euler, order 1, symplectic for separable mechanics;
//! - [`Rk4`]: the classical fourth-order Runge–Kutta method;
//! - [`Dopri5`]: Dormand–Prince 5(4), PI step control, FSAL and dense output;
//! - [`Dop853`]: Dormand–Prince 8(5,3), Hairer's coefficients, error estimator and dense
//!   output;
//! - [`LieMidpoint`]: a geometric integrator for rigid-body rotation (4.50 with the quaternion
//!   attitude) that conserves energy and |H| to round-off and keeps the quaternion unit.
//!
//! Two drivers step them, so that what a run checks and counts is written once: `run_fixed`
//! (below) cuts the interval into equal steps for the fixed-step methods, and `adaptive.rs`
//! runs the embedded pairs Dopri5 and Dop853, which are their tableaux and error estimates.
//! Over both, `segment.rs` is the one driver of a run, a scene's or a ship's manoeuvre: any
//! [`Method`] ([`Stepper`]) from one instant to the next, rows at t = k·every, a check after
//! every step, and a stop condition (a time table's breakpoint, a manoeuvre's event) located
//! where it first holds on the method's own solution. Over it, `problem.rs` is the one loop
//! every run is solved by: a run says its start, end, schedule, watches, resets and rows as a
//! `Problem`, and `solve` cuts it into stretches and resumes it after each.

mod adaptive;
mod controller;
mod dop853;
mod dop853_dense;
mod dopri5;
mod error;
mod euler;
mod lie_midpoint;
mod method;
pub(crate) mod problem;
mod rk4;
pub(crate) mod segment;
mod stats;
mod symplectic_euler;

pub(crate) use adaptive::{Reached, RowClock};
pub use controller::{AdaptiveOptions, min_rtol};
pub use dop853::Dop853;
pub use dopri5::Dopri5;
pub use error::IntegrateError;
pub use euler::Euler;
pub use lie_midpoint::{LieMidpoint, RigidRotation};
pub use method::Method;
pub use rk4::{Rk4, rk4_array, rk4_step};
pub use segment::{Stepper, half_the_step};
pub use stats::Stats;
pub use symplectic_euler::SymplecticEuler;

use std::cell::Cell;

use nalgebra::{RealField, SVector};

/// A system of first-order ordinary differential equations ẏ = f(t, y) with an `N`-component
/// state.
///
/// Implemented for every closure `Fn(T, &SVector<T, N>, &mut SVector<T, N>)`, so a user's own
/// right-hand side needs no wrapper:
///
/// ```
/// use eom::integrate::{Integrator, Rk4, Statistics};
/// use nalgebra::Vector2;
///
/// // The harmonic oscillator ẍ = −x, state (x, ẋ).
/// let oscillator = |_t: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>| {
///     *dy = Vector2::new(y[1], -y[0]);
/// };
/// let mut rk4 = Rk4::new(1e-3);
/// let y = rk4.integrate(&oscillator, 0.0, Vector2::new(1.0, 0.0), 1.0).unwrap();
/// assert!((y[0] - 1f64.cos()).abs() < 1e-12);
/// assert_eq!(rk4.stats().rhs_evals, 4 * 1000);
/// ```
pub trait OdeSystem<T, const N: usize> {
    /// Writes the derivative ẏ = f(t, y) into `dy`.
    fn rhs(&self, t: T, y: &SVector<T, N>, dy: &mut SVector<T, N>);

    /// Why the derivative at a finite `(t, y)` is not finite, where the system can tell it
    /// from its parts: a model driven by loads names the load input that is not finite
    /// ([`IntegrateError::NonFiniteInput`]). The integrators call it only after a step has
    /// failed, replaying that step to find its first non-finite derivative, so a run that goes
    /// well never pays for it. `None` (the default): the state component is named instead.
    fn explain_non_finite(&self, t: T, y: &SVector<T, N>) -> Option<IntegrateError> {
        let _ = (t, y);
        None
    }
}

impl<T, const N: usize, F> OdeSystem<T, N> for F
where
    F: Fn(T, &SVector<T, N>, &mut SVector<T, N>),
{
    fn rhs(&self, t: T, y: &SVector<T, N>, dy: &mut SVector<T, N>) {
        self(t, y, dy)
    }
}

/// A method that advances the state of a system `S` from `t0` to `t_end`.
///
/// The system type is a parameter of the trait, so a method states which systems it accepts:
/// the Runge–Kutta methods take any [`OdeSystem`], the geometric [`LieMidpoint`] only a
/// [`RigidRotation`]. Only forward integration (`t_end ≥ t0`) is supported.
pub trait Integrator<T: RealField + Copy, const N: usize, S: ?Sized>: Statistics {
    /// Integrates from `(t0, y0)` to `t_end`, calling `observe(t, y)` after every accepted step
    /// (not at `t0`), and returns the state at `t_end`.
    fn integrate_with<F>(
        &mut self,
        system: &S,
        t0: T,
        y0: SVector<T, N>,
        t_end: T,
        observe: F,
    ) -> Result<SVector<T, N>, IntegrateError>
    where
        F: FnMut(T, &SVector<T, N>);

    /// Integrates from `(t0, y0)` to `t_end` and returns the state at `t_end`.
    fn integrate(
        &mut self,
        system: &S,
        t0: T,
        y0: SVector<T, N>,
        t_end: T,
    ) -> Result<SVector<T, N>, IntegrateError> {
        self.integrate_with(system, t0, y0, t_end, |_, _| {})
    }
}

/// The cost counters of an integrator's last run (a trait of its own, without the scalar and
/// system parameters of [`Integrator`], so that `method.stats()` needs no annotation).
pub trait Statistics {
    /// The statistics of the last call to [`Integrator::integrate_with`].
    fn stats(&self) -> Stats;
}

/// Converts an `f64` constant (a coefficient, a tolerance) to the scalar type.
#[inline(always)]
pub(crate) fn lit<T: RealField>(x: f64) -> T {
    nalgebra::convert(x)
}

/// Converts a scalar back to `f64` for error messages and statistics.
pub(crate) fn to_f64<T: RealField>(x: T) -> f64 {
    x.to_subset().unwrap_or(f64::NAN)
}

/// Checks that `t0` and `t_end` are finite and in order.
pub(crate) fn check_interval<T: RealField + Copy>(t0: T, t_end: T) -> Result<(), IntegrateError> {
    let (a, b) = (to_f64(t0), to_f64(t_end));
    if a.is_finite() && b.is_finite() && b >= a {
        Ok(())
    } else {
        Err(IntegrateError::InvalidInterval { t0: a, t_end: b })
    }
}

/// Returns an error naming the first non-finite component of `y`, if any.
pub(crate) fn check_finite<T: RealField + Copy, const N: usize>(
    y: &SVector<T, N>,
    t: T,
) -> Result<(), IntegrateError> {
    match y.iter().position(|v| !v.is_finite()) {
        None => Ok(()),
        Some(component) => Err(IntegrateError::NonFiniteState {
            component,
            t: to_f64(t),
        }),
    }
}

/// A system that watches another's derivatives while a failed step is replayed through it:
/// the first derivative that is not finite at a finite state is handed to the system's
/// [`OdeSystem::explain_non_finite`], once. It counts its calls, which are real calls of the
/// user's right-hand side and so part of the statistics.
pub(crate) struct Probe<'a, S: ?Sized> {
    system: &'a S,
    seen: Cell<bool>,
    cause: Cell<Option<IntegrateError>>,
    calls: Cell<usize>,
}

impl<T: RealField + Copy, const N: usize, S: OdeSystem<T, N> + ?Sized> OdeSystem<T, N>
    for Probe<'_, S>
{
    fn rhs(&self, t: T, y: &SVector<T, N>, dy: &mut SVector<T, N>) {
        self.system.rhs(t, y, dy);
        self.calls.set(self.calls.get() + 1);
        if !self.seen.get() && !dy.iter().all(|v| v.is_finite()) && y.iter().all(|v| v.is_finite())
        {
            self.seen.set(true);
            self.cause.set(self.system.explain_non_finite(t, y));
        }
    }
}

/// Replays a failed step through a [`Probe`] of `system` and returns the system's account of
/// its first non-finite derivative, if it gives one, and the RHS evaluations the replay made.
pub(crate) fn explain_failure<S: ?Sized>(
    system: &S,
    replay: impl FnOnce(&Probe<'_, S>),
) -> (Option<IntegrateError>, usize) {
    let probe = Probe {
        system,
        seen: Cell::new(false),
        cause: Cell::new(None),
        calls: Cell::new(0),
    };
    replay(&probe);
    (probe.cause.take(), probe.calls.get())
}

/// The first time in `(lo, hi]` at which `holds` is true, given that it is false at `lo`
/// and true at `hi`: bisection until `lo` and `hi` are adjacent floating-point numbers
/// (about 50 halvings of a step), so the time found is exact to the last bit of the
/// solution `holds` reads. Where the condition holds and fails again within the interval,
/// it is one of the times it starts to hold.
pub(crate) fn first_time_holding<T: RealField + Copy>(
    mut lo: T,
    mut hi: T,
    mut holds: impl FnMut(T) -> bool,
) -> T {
    loop {
        let mid = lo + (hi - lo) * lit::<T>(0.5);
        if mid <= lo || mid >= hi {
            return hi;
        }
        if holds(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
}

/// A fixed step `h` as it is used: the interval is cut into `n = ⌈(t_end − t0)/h⌉` equal steps
/// (a relative slack of 1e-9 keeps `h` that divides the interval from gaining a sliver step),
/// so the last step lands on `t_end` and the step used never exceeds `h`.
fn uniform_steps<T: RealField + Copy>(
    h: f64,
    t0: T,
    t_end: T,
) -> Result<(usize, T), IntegrateError> {
    if !(h.is_finite() && h > 0.0) {
        return Err(IntegrateError::InvalidStep {
            name: "h",
            value: h,
        });
    }
    check_interval(t0, t_end)?;
    let span = to_f64(t_end - t0);
    let n = ((span / h) * (1.0 - 1e-9)).ceil();
    if n > usize::MAX as f64 / 2.0 {
        return Err(IntegrateError::InvalidStep {
            name: "h",
            value: h,
        });
    }
    let n = n as usize;
    if n == 0 {
        return Ok((0, T::zero()));
    }
    Ok((n, (t_end - t0) / lit::<T>(n as f64)))
}

/// Drives a fixed-step method from `t0` to `t_end` in the uniform steps of at most `h` that
/// [`uniform_steps`] makes. Each step is made by `step(t, h, y)`, which returns the RHS
/// evaluations it spent; after each come a finiteness check and an observer call, and a
/// failed step ends the run. A step that leaves the state non-finite is first handed to
/// `explain(t, h, y)` with the state it started from, which replays it (through
/// [`explain_failure`]) to name a non-finite load input and returns the evaluations it made.
/// `stats` counts the run as it goes, so a failed run reports the steps it completed.
pub(crate) fn run_fixed<T: RealField + Copy, const N: usize>(
    h: f64,
    stats: &mut Stats,
    (t0, y0, t_end): (T, SVector<T, N>, T),
    mut step: impl FnMut(T, T, &mut SVector<T, N>) -> Result<usize, IntegrateError>,
    explain: impl FnOnce(T, T, &SVector<T, N>) -> (Option<IntegrateError>, usize),
    mut observe: impl FnMut(T, &SVector<T, N>),
) -> Result<SVector<T, N>, IntegrateError> {
    *stats = Stats::default();
    let (n, h) = uniform_steps(h, t0, t_end)?;
    let mut y = y0;
    for k in 0..n {
        let t = t0 + h * lit::<T>(k as f64);
        let start = y;
        stats.rhs_evals += step(t, h, &mut y)?;
        let t_next = t0 + h * lit::<T>((k + 1) as f64);
        if let Err(error) = check_finite(&y, t_next) {
            let (cause, replayed) = explain(t, h, &start);
            stats.rhs_evals += replayed;
            return Err(cause.unwrap_or(error));
        }
        stats.steps += 1;
        observe(t_next, &y);
    }
    Ok(y)
}

#[cfg(test)]
mod tests {
    use std::cell::Cell;

    use nalgebra::Vector2;

    use super::*;

    #[test]
    fn a_load_that_turns_nan_is_named_by_every_method() {
        use crate::models::{Model, SpatialPrincipalQuaternion};
        let inertia = crate::InertiaTensor::new(2.0, 3.0, 4.5, 0.0, 0.0, 0.0).unwrap();
        let body = SpatialPrincipalQuaternion::<f64>::new(1.0, &inertia).unwrap();
        let mut start = [0.0; 13];
        start[0] = 1.0;
        start[9] = 1.0;
        let start = SVector::from(start);
        // A pitching moment that a user's formula turns into NaN after t = 0.5 s.
        let moment = |t: f64, _: &[f64; 13]| {
            let m_y = if t > 0.5 { f64::NAN } else { 0.1 };
            [0.0, 0.0, 0.0, 0.0, m_y, 0.0]
        };
        let system = body.driven_by(moment);
        let h = 0.01;
        let mut euler = Euler::new(h);
        let mut symplectic = SymplecticEuler::new(h, 0..6);
        let mut rk4 = Rk4::new(h);
        let options = AdaptiveOptions::dop853(1e-9, 1e-9);
        let mut dopri5 = Dopri5::new(AdaptiveOptions::dopri5(1e-9, 1e-9));
        let mut dop853 = Dop853::new(options);
        let runs = [
            ("euler", euler.integrate(&system, 0.0, start, 1.0)),
            ("symplectic", symplectic.integrate(&system, 0.0, start, 1.0)),
            ("rk4", rk4.integrate(&system, 0.0, start, 1.0)),
            ("dopri5", dopri5.integrate(&system, 0.0, start, 1.0)),
            ("dop853", dop853.integrate(&system, 0.0, start, 1.0)),
        ];
        for (method, run) in runs {
            let Err(IntegrateError::NonFiniteInput {
                index,
                name,
                value,
                t,
            }) = run
            else {
                panic!("{method}: {run:?}");
            };
            assert_eq!((index, name), (4, "M_y"), "{method}");
            assert!(value.is_nan(), "{method}");
            // The first evaluation past 0.5 s: within one step for the fixed steps.
            assert!(
                t > 0.5 && (method.starts_with("dop") || t <= 0.5 + h),
                "{method}: {t}"
            );
        }
        // The right-hand side of a plain closure cannot tell why: the state is named.
        let blow_up = |_t: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>| {
            *dy = Vector2::new(0.0, if y[1] > 10.0 { f64::INFINITY } else { 1.0 });
        };
        let run = Rk4::new(0.5).integrate(&blow_up, 0.0, Vector2::new(0.0, 0.0), 100.0);
        assert!(matches!(
            run,
            Err(IntegrateError::NonFiniteState { component: 1, .. })
        ));
    }

    #[test]
    fn a_failed_fixed_step_run_counts_what_it_did() {
        // ẏ₁ = y₁², y₁(0) = 1 blows up at t = 1; explicit Euler overflows some steps later.
        // The statistics must agree with the steps observed and the RHS calls made (the
        // failed step's call and its replay, which looks for a load to blame, included), not
        // claim the whole interval.
        let calls = Cell::new(0usize);
        let blow_up = |_t: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>| {
            calls.set(calls.get() + 1);
            *dy = Vector2::new(0.0, y[1] * y[1]);
        };
        let mut observed = 0;
        let mut euler = Euler::new(0.1);
        let run = euler.integrate_with(&blow_up, 0.0, Vector2::new(0.0, 1.0), 100.0, |_, _| {
            observed += 1
        });
        assert!(matches!(run, Err(IntegrateError::NonFiniteState { .. })));
        let stats = euler.stats();
        assert!(observed > 10 && observed < 100);
        assert_eq!((stats.steps, stats.rhs_evals), (observed, observed + 2));
        assert_eq!(calls.get(), stats.rhs_evals);
    }
}
