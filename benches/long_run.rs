//! Long runs: about 10⁶ steps of torque-free tumbling with every integrator that applies,
//! reporting the drift of the kinetic energy, of |H| and of the angular momentum in space, and
//! the quaternion's distance from unit length.
//!
//! `cargo bench --bench long_run` prints the page and writes it to
//! `target/work_precision/long_run.md` and `docs/work_precision/long_run.md`. The body is the
//! tennis racket of the work–precision harness (I = (1, 2, 3), ω₀ = (0, 1, 0.1)), tumbling
//! through its flips. The fixed-step methods take 10⁶ steps of a 2000th of a period (500
//! periods); DOPRI5 and DOP853 run at a tolerance for as many periods as take them about 10⁶
//! accepted steps (counted on one period first). Every method but the geometric one integrates
//! the generated `SpatialPrincipalQuaternion` (`model.driven_by(Constant::zero())`), which
//! assumes |q| = 1 and does not normalise; the Lie midpoint method needs the inertia tensor
//! itself (`RigidRotation`), as `eom run` gives it, and RK4 also runs on the hand-written 4.52
//! for comparison.

use std::fmt::Write;
use std::path::Path;
use std::time::Instant;

use eom::InertiaTensor;
use eom::generic::{quaternion_state_of_rotation, rotation_of_quaternion_state};
use eom::integrate::{
    AdaptiveOptions, Dop853, Dopri5, Euler, IntegrateError, Integrator, LieMidpoint, Rk4,
    SymplecticEuler,
};
use eom::models::{Constant, Model, SpatialPrincipalQuaternion};
use eom::reference::{ReferenceProblem, TennisRacket};
use nalgebra::{Quaternion, SVector, UnitQuaternion, Vector3};

/// Steps per run of a fixed-step method, and roughly per run of an adaptive one.
const STEPS: usize = 1_000_000;
/// Steps per period of the body rates for the fixed-step methods.
const STEPS_PER_PERIOD: usize = 2000;
/// Steps between two observations of the drifts (and at the end).
const OBSERVE_EVERY: usize = 100;

/// The largest drifts seen over a run, and when the energy first left by 1 %.
#[derive(Debug, Default)]
struct Drift {
    energy: f64,
    momentum: f64,
    momentum_in_space: f64,
    quaternion_norm: f64,
    /// The first observed step at which the energy drift exceeded 1 %.
    energy_one_percent: Option<usize>,
}

impl Drift {
    /// Folds the state `y` after `step` steps into the maxima, against the start values.
    fn observe(&mut self, racket: &TennisRacket, start: &[f64], y: &SVector<f64, 7>, step: usize) {
        let invariants = racket.invariants(y);
        let energy = (invariants[0] / start[0] - 1.0).abs();
        self.energy = self.energy.max(energy);
        if energy > 0.01 && self.energy_one_percent.is_none() {
            self.energy_one_percent = Some(step);
        }
        self.momentum = self.momentum.max((invariants[1] / start[1] - 1.0).abs());
        let q = Quaternion::new(y[3], y[4], y[5], y[6]);
        self.quaternion_norm = self.quaternion_norm.max((q.norm() - 1.0).abs());
        let w = Vector3::new(y[0], y[1], y[2]);
        let h = UnitQuaternion::from_quaternion(q) * racket.body().moments.component_mul(&w);
        let h0 = racket.momentum_in_space();
        self.momentum_in_space = self.momentum_in_space.max((h - h0).norm() / h0.norm());
    }
}

/// One row of the table.
struct Row {
    method: String,
    setting: String,
    /// The tolerance of an adaptive method.
    tol: Option<f64>,
    periods: f64,
    drift: Drift,
    steps: usize,
    rhs_evals: usize,
    seconds: f64,
    failure: Option<IntegrateError>,
}

/// Runs `method` on `system` for `periods` periods of the racket from its start placed in the
/// system's layout by `place`, judging each state by its racket part, `project`.
fn long_run<const N: usize, S: ?Sized, I: Integrator<f64, N, S>>(
    (racket, periods): (&TennisRacket, f64),
    system: &S,
    mut method: I,
    place: impl Fn(&SVector<f64, 7>) -> SVector<f64, N>,
    project: impl Fn(&SVector<f64, N>) -> SVector<f64, 7>,
    (name, setting): (&str, String),
) -> Row {
    let start = racket.invariants(&racket.initial_state());
    let t_end = racket.period() * periods;
    let mut drift = Drift::default();
    let mut count = 0usize;
    let clock = Instant::now();
    let end = method.integrate_with(
        system,
        0.0,
        place(&racket.initial_state()),
        t_end,
        |_, y| {
            count += 1;
            if count.is_multiple_of(OBSERVE_EVERY) {
                drift.observe(racket, &start, &project(y), count);
            }
        },
    );
    let seconds = clock.elapsed().as_secs_f64();
    let failure = match end {
        Ok(end) => {
            drift.observe(racket, &start, &project(&end), count);
            None
        }
        Err(e) => Some(e),
    };
    Row {
        method: name.to_string(),
        setting,
        tol: None,
        periods,
        drift,
        steps: method.stats().steps,
        rhs_evals: method.stats().rhs_evals,
        seconds,
        failure,
    }
}

/// An adaptive method's tolerance and how many periods give it about [`STEPS`] steps.
fn periods_for<S: ?Sized, I: Integrator<f64, 13, S>>(
    racket: &TennisRacket,
    system: &S,
    mut method: I,
) -> f64 {
    method
        .integrate(
            system,
            0.0,
            quaternion_state_of_rotation(&racket.initial_state()),
            racket.period(),
        )
        .expect("one period");
    (STEPS as f64 / method.stats().steps as f64).round()
}

fn adaptive(tol: f64, dop853: bool) -> AdaptiveOptions {
    let options = if dop853 {
        AdaptiveOptions::dop853(tol, tol)
    } else {
        AdaptiveOptions::dopri5(tol, tol)
    };
    AdaptiveOptions {
        max_steps: 2 * STEPS,
        ..options
    }
}

fn main() {
    let attitude = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
    let racket =
        TennisRacket::new(Vector3::new(1.0, 2.0, 3.0), 1.0, 0.1, attitude).expect("valid racket");
    let h = racket.period() / STEPS_PER_PERIOD as f64;
    let fixed_periods = (STEPS / STEPS_PER_PERIOD) as f64;
    let moments = racket.body().moments;
    let tensor = InertiaTensor::new(moments.x, moments.y, moments.z, 0.0, 0.0, 0.0)
        .expect("the racket's moments are physical");
    let model = SpatialPrincipalQuaternion::<f64>::new(1.0, &tensor).expect("valid model");
    let generated = model.driven_by(Constant::zero());
    let body = racket.body();
    let same = |y: &SVector<f64, 7>| *y;
    let fixed = (&racket, fixed_periods);
    let step = || format!("h = {h:.4e}");
    let mut rows = vec![
        long_run(
            fixed,
            &generated,
            Euler::new(h),
            quaternion_state_of_rotation,
            rotation_of_quaternion_state,
            ("Euler", step()),
        ),
        long_run(
            fixed,
            &generated,
            SymplecticEuler::new(h, 0..6),
            quaternion_state_of_rotation,
            rotation_of_quaternion_state,
            ("symplectic Euler (kick u…r)", step()),
        ),
        long_run(
            fixed,
            &generated,
            Rk4::new(h),
            quaternion_state_of_rotation,
            rotation_of_quaternion_state,
            ("RK4", step()),
        ),
        long_run(
            fixed,
            &body,
            Rk4::new(h),
            same,
            same,
            ("RK4, hand-written 4.52", step()),
        ),
    ];
    for tol in [1e-9, 1e-12] {
        let periods = periods_for(&racket, &generated, Dopri5::new(adaptive(tol, false)));
        rows.push(Row {
            tol: Some(tol),
            ..long_run(
                (&racket, periods),
                &generated,
                Dopri5::new(adaptive(tol, false)),
                quaternion_state_of_rotation,
                rotation_of_quaternion_state,
                ("DOPRI5", format!("rtol = atol = {tol:.0e}")),
            )
        });
    }
    for tol in [1e-9, 1e-12] {
        let periods = periods_for(&racket, &generated, Dop853::new(adaptive(tol, true)));
        rows.push(Row {
            tol: Some(tol),
            ..long_run(
                (&racket, periods),
                &generated,
                Dop853::new(adaptive(tol, true)),
                quaternion_state_of_rotation,
                rotation_of_quaternion_state,
                ("DOP853", format!("rtol = atol = {tol:.0e}")),
            )
        });
    }
    rows.push(long_run(
        fixed,
        &body,
        LieMidpoint::new(h),
        same,
        same,
        ("Lie midpoint (the tensor, as `eom run` gives it)", step()),
    ));

    let mut table = String::from(
        "| method | setting | periods | steps | max energy drift | max abs(H) drift | max H-in-space drift | max abs(abs(q) − 1) | RHS evals | time [s] | note |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for row in &rows {
        let d = &row.drift;
        let note = match (&row.failure, d.energy_one_percent) {
            (Some(e), Some(k)) => {
                format!(
                    "stopped: {e}; energy off by 1 % from step {k} on; drifts up to the last finite state"
                )
            }
            (Some(e), None) => format!("stopped: {e}"),
            (None, Some(k)) => format!("energy off by 1 % from step {k} on"),
            (None, None) => String::new(),
        };
        let _ = writeln!(
            table,
            "| {} | {} | {:.0} | {} | {:.2e} | {:.2e} | {:.2e} | {:.2e} | {} | {:.3} | {note} |",
            row.method,
            row.setting,
            row.periods,
            row.steps,
            d.energy,
            d.momentum,
            d.momentum_in_space,
            d.quaternion_norm,
            row.rhs_evals,
            row.seconds,
        );
    }
    // The adaptive pairs' energy drift per period covered, in units of their tolerance.
    let per_period = rows
        .iter()
        .filter_map(|row| Some(row.drift.energy / (row.tol? * row.periods)))
        .fold((f64::INFINITY, 0.0f64), |(low, high), x| {
            (low.min(x), high.max(x))
        });
    let page = format!(
        "# Long runs: 10⁶ steps of the tennis racket\n\n\
         Regenerate with `cargo bench --bench long_run` (a few seconds once built; it writes this \
         page). \
         The tennis racket of the work–precision harness, I = (1, 2, 3), ω₀ = (0, 1, 0.1) \
         rad/s, period {period:.3} s (two flips), torque-free. The fixed-step methods take \
         {STEPS} steps of h = period / {STEPS_PER_PERIOD} ({fixed_periods:.0} periods); DOPRI5 \
         and DOP853 run for as many periods as take them about {STEPS} accepted steps at their \
         tolerance. All but two rows integrate the generated `SpatialPrincipalQuaternion` \
         through `model.driven_by(Constant::zero())`, which does not normalise the quaternion; \
         \"RK4, hand-written 4.52\" runs the reference problem's own right-hand side, and the \
         Lie midpoint method takes the inertia tensor (`RigidRotation`), as `eom run` gives \
         it. Drifts are relative to the start (the quaternion's absolute), the largest seen \
         every {OBSERVE_EVERY} steps and at the end. Times are wall-clock on a machine shared \
         with other jobs: read them as rough.\n\n\
         {table}\n\
         - Explicit and symplectic Euler cannot run this: each step adds h²/2 · f·[I]f to the \
         energy, and since f grows with the square of the rates the growth feeds itself until \
         the state overflows (symplectic Euler kicks the rates first, which for Euler's \
         equations is the same explicit step: they are not separable).\n\
         - RK4 drifts slowly, and by the same through the generated model as through the \
         hand-written 4.52: the drift is RK4's truncation error, not the arithmetic.\n\
         - The adaptive pairs drift in energy by about one tolerance per period they cover \
         ({:.1}–{:.1} × tol per period here), so over 10⁶ steps a loose tolerance, which \
         covers many periods, drifts the most.\n\
         - The Lie midpoint method keeps energy and abs(H) (quadratic invariants of its \
         implicit midpoint step), H in space and the unit quaternion to round-off.\n",
        per_period.0,
        per_period.1,
        period = racket.period(),
    );
    println!("{page}");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for out in [root.join("target"), root.join("docs")] {
        let out = out.join("work_precision");
        std::fs::create_dir_all(&out).expect("create the output directory");
        std::fs::write(out.join("long_run.md"), &page).expect("write the long-run table");
    }
}
