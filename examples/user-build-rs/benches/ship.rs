//! Three ways to run a scene-defined table, timed against each other: this crate's ships
//! compiled by rustc from `build.rs`; the same tables as `eom` runs a scene's, compiled to
//! machine code when the scene is read (Cranelift, feature `jit`); and interpreted (`eom`'s
//! reference evaluator of the proved program). For the ten-term ship of `build.rs`, the Mariner
//! (39 terms, `scenes/mariner.toml`) and REMUS (six degrees of freedom,
//! `scenes/remus100.toml`): ns per right-hand-side call, seven interleaved rounds of 10⁶ calls each (10⁵ for the interpreter), medians, each call on
//! the state the last left; the same inside `eom`'s RK4 for the ten-term ship; what compiling
//! each model costs; and how many outputs of the rustc and Cranelift forms differ in their
//! bits over 10⁵ random states (none in the default build, where both are op by op, and the
//! bench stops if one does; with `-C target-cpu=native` rustc's `mul_add`s are fused,
//! Cranelift's code is not).
//!
//! `cargo bench -p eom-example-user-build-rs`, or with the names of the tables to run (`ten`,
//! `mariner`, `remus`) after `--`: `cargo bench -p eom-example-user-build-rs -- ten remus`.

#[path = "../tests/common/mod.rs"]
mod common;

use common::{
    differing_bits, differing_vehicle_bits, mariner_coefficients, mariner_rates, mariner_table,
    remus_coefficients, remus_rates, remus_scene, table,
};
use eom::integrate::{Integrator, Rk4, Statistics};
use eom::kinds::ship::ShipModel;
use eom::nalgebra::SVector;
use eom::{Constant, Model, OdeSystem};
use eom_example_user_build_rs::{example_ship, ship};
use std::hint::black_box;
use std::time::Instant;

const CALLS: usize = 1_000_000;
const ROUNDS: usize = 7;

/// Seconds per call over `calls` calls, each on a state nudged by the last rates.
fn time<const N: usize>(start: [f64; N], calls: usize, rhs: impl Fn(&[f64; N]) -> [f64; N]) -> f64 {
    let mut state = start;
    let clock = Instant::now();
    for _ in 0..calls {
        let rates = rhs(black_box(&state));
        for (x, r) in state.iter_mut().zip(rates) {
            *x += 1e-9 * r;
        }
    }
    black_box(state);
    clock.elapsed().as_secs_f64() / calls as f64
}

/// ns per evaluation of `system`'s right-hand side in a steady turn of 2.5·10⁵ RK4 steps
/// (10⁶ evaluations), the rudder held at 0.1 rad.
fn time_rk4(system: &impl OdeSystem<f64, 7>) -> f64 {
    let start = SVector::from([6.0, 0.4, -0.02, 10.0, -5.0, 0.3, 0.1]);
    let mut method = Rk4::new(0.1);
    let clock = Instant::now();
    let end = method.integrate(system, 0.0, black_box(start), 25_000.0);
    let seconds = clock.elapsed().as_secs_f64();
    black_box(end.expect("a steady turn integrates"));
    seconds / method.stats().rhs_evals as f64 * 1e9
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The medians of `ROUNDS` interleaved rounds of each contender, in ns per call.
fn rounds(contenders: &[&dyn Fn() -> f64]) -> Vec<f64> {
    let mut times = vec![Vec::new(); contenders.len()];
    for _ in 0..ROUNDS {
        for (time, contender) in times.iter_mut().zip(contenders) {
            time.push(contender() * 1e9);
        }
    }
    times.into_iter().map(median).collect()
}

/// Median ms to compile `model`'s program, of `ROUNDS` compilations.
fn compile_ms<M>(compile: impl Fn() -> M) -> f64 {
    median(
        (0..ROUNDS)
            .map(|_| {
                let clock = Instant::now();
                black_box(compile());
                clock.elapsed().as_secs_f64() * 1e3
            })
            .collect(),
    )
}

fn print(name: &str, [rustc, jit, interpreted]: [Option<f64>; 3]) {
    let show = |x: Option<f64>| x.map_or("—".to_owned(), |x| format!("{x:.1}"));
    let ratio = |x: Option<f64>, y: Option<f64>| {
        x.zip(y)
            .map_or("—".to_owned(), |(x, y)| format!("{:.2}", x / y))
    };
    println!(
        "{name}: ns per call rustc {}, jit {}, interpreted {}; jit/rustc {}, interpreted/jit {}",
        show(rustc),
        show(jit),
        show(interpreted),
        ratio(jit, rustc),
        ratio(interpreted, jit),
    );
}

/// Whether the table `name` is to run: every one, unless the command line names some.
fn chosen(name: &str) -> bool {
    let named: Vec<String> = (std::env::args().skip(1))
        .filter(|a| !a.starts_with('-'))
        .collect();
    named.is_empty() || named.iter().any(|n| n == name)
}

fn main() {
    if chosen("ten") {
        ten_terms();
    }
    if chosen("mariner") {
        mariner();
    }
    if chosen("remus") {
        remus();
    }
}

/// The ten-term ship of `build.rs`, alone and inside RK4.
fn ten_terms() {
    let ship_start = [6.0, 0.4, -0.02, 10.0, -5.0, 0.3, 0.1];
    let k = ship::Coefficients::<f64>::new(&example_ship());
    let jit = ShipModel::new(&table()).expect("the table builds");
    assert!(jit.is_compiled(), "the ten-term table compiles");
    let interpreted = jit.interpreted();
    let differing = differing_bits(|s, d| k.rhs(s, &[d]), |s, d| jit.rhs(s, &[d, 0.0, 0.0]));
    println!(
        "ship, 10 terms: rustc and jit outputs differing in their bits: {differing} of 700000"
    );
    let times = rounds(&[
        &|| time(ship_start, CALLS, |y| k.rhs(y, &[0.01])),
        &|| time(ship_start, CALLS, |y| jit.rhs(y, &[0.01, 0.0, 0.0])),
        &|| {
            time(ship_start, CALLS / 10, |y| {
                interpreted.rhs(y, &[0.01, 0.0, 0.0])
            })
        },
    ]);
    print(
        "ship, 10 terms",
        [Some(times[0]), Some(times[1]), Some(times[2])],
    );
    // Each is a model: the same driver, the same RK4.
    let (driven, jit_driven) = (
        k.driven_by(Constant([0.0])),
        jit.driven_by(Constant([0.0, 0.0, 0.0])),
    );
    let interpreted_driven = interpreted.driven_by(Constant([0.0, 0.0, 0.0]));
    let times = rounds(&[
        &|| time_rk4(&driven) * 1e-9,
        &|| time_rk4(&jit_driven) * 1e-9,
        &|| time_rk4(&interpreted_driven) * 1e-9,
    ]);
    print(
        "ship, 10 terms, in RK4",
        [Some(times[0]), Some(times[1]), Some(times[2])],
    );
}

/// The Mariner's 39 terms, and what building and compiling its model costs.
fn mariner() {
    let table = mariner_table();
    let m = mariner_coefficients(&table);
    let m_rhs = |s: &[f64; 7], d: f64| mariner_rates(&m, s, d);
    let jit = ShipModel::new(&table).expect("the Mariner builds");
    assert!(jit.is_compiled() && jit.terms() == 39);
    let interpreted = jit.interpreted();
    let differing = differing_bits(m_rhs, |s, d| jit.rhs(s, &[d, 0.0, 0.0]));
    println!("Mariner: rustc and jit outputs differing in their bits: {differing} of 700000");
    assert!(cfg!(target_feature = "fma") || differing == 0);
    let mariner_start = [7.5, 0.3, -0.01, 10.0, -5.0, 0.3, 0.1];
    let times = rounds(&[
        &|| time(mariner_start, CALLS, |y| m_rhs(y, 0.01)),
        &|| time(mariner_start, CALLS, |y| jit.rhs(y, &[0.01, 0.0, 0.0])),
        &|| {
            time(mariner_start, CALLS / 10, |y| {
                interpreted.rhs(y, &[0.01, 0.0, 0.0])
            })
        },
    ]);
    print(
        "Mariner, 39 terms",
        [Some(times[0]), Some(times[1]), Some(times[2])],
    );
    let build = compile_ms(|| ShipModel::new(&table));
    let compile = compile_ms(|| interpreted.compiled());
    println!("Mariner: built and proved in {build:.1} ms, of which compiled in {compile:.2} ms");
}

/// REMUS in six degrees of freedom, and what compiling its model costs.
fn remus() {
    let scene = remus_scene();
    let r = remus_coefficients(&scene);
    let vehicle = &scene.model;
    assert!(vehicle.is_compiled(), "REMUS compiles");
    let body = |rates: [f64; 15]| -> [f64; 13] { std::array::from_fn(|i| rates[i]) };
    let differing = differing_vehicle_bits(
        |s| remus_rates(&r, s),
        |s| body(vehicle.rhs(s, &[0.0, 0.0])),
    );
    println!("REMUS: rustc and jit outputs differing in their bits: {differing} of 1300000");
    assert!(cfg!(target_feature = "fma") || differing == 0);
    // The fins' rates are the inputs: the rustc form's state leaves the fins out, so each of
    // its calls moves them as eom's model does.
    let rustc = |y: &[f64; 15]| {
        let rates = remus_rates(&r, y);
        std::array::from_fn(|i| {
            if i < 13 {
                rates[i]
            } else {
                [0.01, -0.01][i - 13]
            }
        })
    };
    let vehicle_interpreted = vehicle.interpreted();
    let mut vehicle_start = [0.0; 15];
    vehicle_start[..6].copy_from_slice(&[1.5, 0.05, -0.03, 0.01, 0.02, -0.03]);
    vehicle_start[9] = 1.0;
    vehicle_start[13] = 0.05;
    let times = rounds(&[
        &|| time(vehicle_start, CALLS, rustc),
        &|| time(vehicle_start, CALLS, |y| vehicle.rhs(y, &[0.01, -0.01])),
        &|| {
            time(vehicle_start, CALLS / 10, |y| {
                vehicle_interpreted.rhs(y, &[0.01, -0.01])
            })
        },
    ]);
    print(
        "REMUS, six degrees of freedom",
        [Some(times[0]), Some(times[1]), Some(times[2])],
    );
    let compile = compile_ms(|| vehicle_interpreted.compiled());
    println!("REMUS: compiled in {compile:.2} ms");
}
