//! Long runs: 10⁶ steps of torque-free tumbling with RK4 and with the geometric integrator,
//! reporting the drift of the kinetic energy, of |H| and of the angular momentum in space, and
//! the quaternion's distance from unit length.
//!
//! `cargo bench --bench long_run` prints the table and writes it to
//! `target/work_precision/long_run.md`. The body is the tennis racket of the work–precision
//! harness (I = (1, 2, 3), ω₀ = (0, 1, 0.1)), tumbling through its flips for 500 periods of its
//! body rates with 2000 steps per period.

use std::fmt::Write;
use std::path::Path;
use std::time::Instant;

use eom::integrate::{Integrator, LieMidpoint, Rk4};
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

/// Runs `method` for [`STEPS`] steps and returns the drifts, the RHS evaluations and the time.
fn long_run<I: Integrator<f64, 7, eom::reference::torque_free::PrincipalBody>>(
    racket: &TennisRacket,
    mut method: I,
) -> (Drift, usize, f64) {
    let start = racket.invariants(&racket.initial_state());
    let t_end = racket.period() * (STEPS / STEPS_PER_PERIOD) as f64;
    let mut drift = Drift::default();
    let mut count = 0usize;
    let clock = Instant::now();
    let end = method
        .integrate_with(
            &racket.body(),
            0.0,
            racket.initial_state(),
            t_end,
            |_, y| {
                count += 1;
                if count % 100 == 0 {
                    drift.observe(racket, &start, y);
                }
            },
        )
        .expect("the long run completes");
    let seconds = clock.elapsed().as_secs_f64();
    drift.observe(racket, &start, &end);
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
    let runs = [
        ("RK4", long_run(&racket, Rk4::new(h))),
        ("Lie midpoint", long_run(&racket, LieMidpoint::new(h))),
    ];
    for (name, (d, evals, seconds)) in runs {
        let _ = writeln!(
            table,
            "| {name} | {STEPS} | {h:.4e} | {:.2e} | {:.2e} | {:.2e} | {:.2e} | {evals} | {seconds:.3} |",
            d.energy, d.momentum, d.momentum_in_space, d.quaternion_norm
        );
    }
    println!("{table}");
    let out = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("target")
        .join("work_precision");
    std::fs::create_dir_all(&out).expect("create target/work_precision");
    std::fs::write(out.join("long_run.md"), &table).expect("write the long-run table");
}
