//! Long runs: 10⁶ steps of torque-free tumbling with RK4 (on the hand-written principal-axes
//! form and on the generated `SpatialPrincipalQuaternion`, which assumes |q| = 1 and does not
//! normalise) and with the geometric integrator, reporting the drift of the kinetic energy, of |H| and of the angular momentum in space, and
//! the quaternion's distance from unit length.
//!
//! `cargo bench --bench long_run` prints the table and writes it to
//! `target/work_precision/long_run.md` and `docs/work_precision/long_run.md`. The body is the tennis racket of the work–precision
//! harness (I = (1, 2, 3), ω₀ = (0, 1, 0.1)), tumbling through its flips for 500 periods of its
//! body rates with 2000 steps per period.

use std::fmt::Write;
use std::path::Path;
use std::time::Instant;

use eom::InertiaTensor;
use eom::integrate::{Integrator, LieMidpoint, Rk4};
use eom::models::{Constant, Model, SpatialPrincipalQuaternion};
use eom::reference::{ReferenceProblem, TennisRacket};
use nalgebra::{Quaternion, SVector, UnitQuaternion, Vector3};

/// Steps per run.
const STEPS: usize = 1_000_000;
/// Steps per period of the body rates.
const STEPS_PER_PERIOD: usize = 2000;

/// The largest drifts seen over a run (sampled every 100 steps and at the end).
#[derive(Debug, Default)]
struct Drift {
    energy: f64,
    momentum: f64,
    momentum_in_space: f64,
    quaternion_norm: f64,
}

impl Drift {
    /// Folds the state `y` into the maxima, against the start values.
    fn observe(&mut self, racket: &TennisRacket, start: &[f64], y: &SVector<f64, 7>) {
        let invariants = racket.invariants(y);
        self.energy = self.energy.max((invariants[0] / start[0] - 1.0).abs());
        self.momentum = self.momentum.max((invariants[1] / start[1] - 1.0).abs());
        let q = Quaternion::new(y[3], y[4], y[5], y[6]);
        self.quaternion_norm = self.quaternion_norm.max((q.norm() - 1.0).abs());
        let w = Vector3::new(y[0], y[1], y[2]);
        let h = UnitQuaternion::from_quaternion(q) * racket.body().moments.component_mul(&w);
        let h0 = racket.momentum_in_space();
        self.momentum_in_space = self.momentum_in_space.max((h - h0).norm() / h0.norm());
    }
}

/// The racket's `[p, q, r, q0, q1, q2, q3]` in a spatial model's 13-state, at rest in
/// translation (u = v = w = 0, x = y = z = 0), which no load changes.
fn spatial_state(y: &SVector<f64, 7>) -> SVector<f64, 13> {
    let mut state = SVector::<f64, 13>::zeros();
    state
        .fixed_rows_mut::<3>(3)
        .copy_from(&y.fixed_rows::<3>(0));
    state
        .fixed_rows_mut::<4>(9)
        .copy_from(&y.fixed_rows::<4>(3));
    state
}

/// The racket's `[p, q, r, q0, q1, q2, q3]` of a spatial model's 13-state.
fn racket_state(state: &SVector<f64, 13>) -> SVector<f64, 7> {
    let mut y = SVector::<f64, 7>::zeros();
    y.fixed_rows_mut::<3>(0)
        .copy_from(&state.fixed_rows::<3>(3));
    y.fixed_rows_mut::<4>(3)
        .copy_from(&state.fixed_rows::<4>(9));
    y
}

/// Runs `method` on `system` for [`STEPS`] steps from the racket's start placed in the
/// system's layout by `place`, judging each state by its racket part, `project`; returns the
/// drifts, the RHS evaluations and the time.
fn long_run<const N: usize, S: ?Sized, I: Integrator<f64, N, S>>(
    racket: &TennisRacket,
    system: &S,
    mut method: I,
    place: impl Fn(&SVector<f64, 7>) -> SVector<f64, N>,
    project: impl Fn(&SVector<f64, N>) -> SVector<f64, 7>,
) -> (Drift, usize, f64) {
    let start = racket.invariants(&racket.initial_state());
    let t_end = racket.period() * (STEPS / STEPS_PER_PERIOD) as f64;
    let mut drift = Drift::default();
    let mut count = 0usize;
    let clock = Instant::now();
    let end = method
        .integrate_with(
            system,
            0.0,
            place(&racket.initial_state()),
            t_end,
            |_, y| {
                count += 1;
                if count % 100 == 0 {
                    drift.observe(racket, &start, &project(y));
                }
            },
        )
        .expect("the long run completes");
    let seconds = clock.elapsed().as_secs_f64();
    drift.observe(racket, &start, &project(&end));
    assert_eq!(method.stats().steps, STEPS);
    (drift, method.stats().rhs_evals, seconds)
}

fn main() {
    let attitude = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
    let racket =
        TennisRacket::new(Vector3::new(1.0, 2.0, 3.0), 1.0, 0.1, attitude).expect("valid racket");
    let h = racket.period() / STEPS_PER_PERIOD as f64;
    let mut table = String::from(
        "| method | steps | h | max energy drift | max abs(H) drift | max H-in-space drift | max abs(abs(q) - 1) | RHS evals | time [s] |\n|---|---|---|---|---|---|---|---|---|\n",
    );
    let moments = racket.body().moments;
    let tensor = InertiaTensor::new(moments.x, moments.y, moments.z, 0.0, 0.0, 0.0)
        .expect("the racket's moments are physical");
    let model = SpatialPrincipalQuaternion::<f64>::new(1.0, &tensor).expect("valid model");
    let body = racket.body();
    let same = |y: &SVector<f64, 7>| *y;
    let runs = [
        (
            "RK4, hand-written 4.52",
            long_run(&racket, &body, Rk4::new(h), same, same),
        ),
        (
            "RK4, generated SpatialPrincipalQuaternion",
            long_run(
                &racket,
                &model.driven_by(Constant::zero()),
                Rk4::new(h),
                spatial_state,
                racket_state,
            ),
        ),
        (
            "Lie midpoint",
            long_run(&racket, &body, LieMidpoint::new(h), same, same),
        ),
    ];
    for (name, (d, evals, seconds)) in runs {
        let _ = writeln!(
            table,
            "| {name} | {STEPS} | {h:.4e} | {:.2e} | {:.2e} | {:.2e} | {:.2e} | {evals} | {seconds:.3} |",
            d.energy, d.momentum, d.momentum_in_space, d.quaternion_norm
        );
    }
    println!("{table}");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for out in [root.join("target"), root.join("docs")] {
        let out = out.join("work_precision");
        std::fs::create_dir_all(&out).expect("create the output directory");
        std::fs::write(out.join("long_run.md"), &table).expect("write the long-run table");
    }
}
