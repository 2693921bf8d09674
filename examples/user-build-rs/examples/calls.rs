//! Runs one form of one table's right-hand side a given number of times, each call on the
//! state the last left (as the bench's loop does), and nothing else: what instructions one
//! call costs is then counted under callgrind, the loop being the only function collected.
//!
//! ```sh
//! cargo build --release -p eom-example-user-build-rs --example calls
//! valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*calls::run*' \
//!     target/release/examples/calls remus jit 100000
//! ```
//!
//! `TABLE` is `ten` (the ten-term ship of `build.rs`), `mariner` or `remus`; `FORM` is
//! `rustc`, `jit` (compiled when the scene is read) or `interpreted`; `TABLE` `ten-rk4` runs the
//! ten-term ship's steady turn inside eom's RK4 (the bench's "inside RK4", `CALLS` its right-hand
//! sides), `FORM` `rustc` or `jit`, the function collected then `calls::rk4`:
//!
//! ```sh
//! valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*calls::rk4*' \
//!     target/release/examples/calls ten-rk4 jit 100000
//! ```
//!
//! A ship's calls start at the heading ψ = 0.3 rad, within ±π/4, where the kernel's sine and
//! cosine need no reduction; a fourth argument gives another (`calls ten jit 100000 2.0`: the
//! path a steady turn takes once its heading has left ±π/4, as inside RK4).
//!
//! `TABLE` `lanes` and `scalar-cases` (`FORM` `rustc`, `CALLS` the RK4 steps) run 64 of the
//! Mariner's turning circles of `benches/lanes.rs` (approaches at 0.95–1.05 U₀, rudder orders
//! 20°, 25°, 30°, 35° through the scene's steering gear, steps of 0.1 s): `lanes` four cases to
//! a `Batch<WideF64x4, 7>`, `scalar-cases` one at a time (`Batch<f64, 7>`), the function
//! collected `calls::turns`; its count over 64 × `CALLS` is the instructions per case-step:
//!
//! ```sh
//! valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*calls::turns*' \
//!     target/release/examples/calls lanes rustc 3400
//! ```

#[path = "../tests/common/mod.rs"]
#[allow(dead_code)]
mod common;
#[path = "../tests/common/gear.rs"]
mod gear;

use common::{mariner_coefficients, mariner_rates, mariner_table, remus_coefficients, remus_rates};
use eom::batch::Batch;
use eom::integrate::{Integrator, Rk4};
use eom::kinds::ship::ShipModel;
use eom::nalgebra::SVector;
use eom::{Constant, Model, OdeSystem};
use eom_example_user_build_rs::{example_ship, mariner, ship};
use simba::simd::{SimdRealField, WideF64x4};
use std::hint::black_box;

/// `system`'s steady turn in RK4 at 0.1 s for `calls` right-hand sides (four a step), as the
/// bench's `time_rk4` runs it.
#[inline(never)]
fn rk4(system: &impl OdeSystem<f64, 7>, start: [f64; 7], calls: usize) -> [f64; 7] {
    let mut method = Rk4::new(0.1);
    let end = 0.1 * (calls / 4) as f64;
    let reached = method.integrate(system, 0.0, SVector::from(start), end);
    reached.expect("a steady turn integrates").into()
}

/// The turning circles of `benches/lanes.rs`, as 64 cases (each lane of a group of four its
/// own rudder order, `gear::RUDDER_ORDERS_DEG`).
const TURNS: usize = 64;

/// `steps` RK4 steps of 0.1 s of every batch under its loads: the loop the bench times.
#[inline(never)]
fn turns<T, Mo, L>(model: &Mo, batches: &mut [(Batch<T, 7>, L)], steps: usize)
where
    T: SimdRealField + Copy,
    T::Element: Copy,
    Mo: Model<T, 7, 2>,
    L: eom::Loads<T, 7, 2>,
{
    for step in 0..steps {
        for (batch, loads) in batches.iter_mut() {
            batch.step_rk4(model, loads, step as f64 * 0.1, 0.1);
        }
    }
}

/// The 64 turns through `steps` steps, in f64×4 lanes (`lanes`) or one at a time; their end
/// states, in order.
fn cases(lanes: bool, steps: usize) -> Vec<f64> {
    let table = mariner_table();
    let values = common::symbols(&table);
    let parameters =
        mariner::Parameters::from_symbols(|s| values.get(s).copied().unwrap_or(f64::NAN));
    let starts: Vec<[f64; 7]> = (0..TURNS)
        .map(|i| {
            let speed = table.design_speed * (0.95 + 0.1 * i as f64 / TURNS as f64);
            [speed, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
        })
        .collect();
    let orders = gear::RUDDER_ORDERS_DEG.map(f64::to_radians);
    let ends: Vec<[f64; 7]> = if lanes {
        let m = mariner::Coefficients::<WideF64x4>::new(&parameters);
        let loads = gear::steering_gear(WideF64x4::from(orders));
        let mut batches = [(Batch::<WideF64x4, 7>::new(&starts), loads)];
        turns(&m, &mut batches, steps);
        batches[0].0.states()
    } else {
        let m = mariner::Coefficients::<f64>::new(&parameters);
        let mut batches: Vec<_> = (orders.iter().enumerate())
            .map(|(lane, &order)| {
                let cases: Vec<[f64; 7]> = starts.iter().skip(lane).step_by(4).copied().collect();
                (Batch::<f64, 7>::new(&cases), gear::steering_gear(order))
            })
            .collect();
        turns(&m, &mut batches, steps);
        (0..TURNS).map(|i| batches[i % 4].0.state(i / 4)).collect()
    };
    ends.concat()
}

/// `calls` calls of `rhs`, each on the state nudged by the last rates: the loop of the bench.
#[inline(never)]
fn run<const N: usize>(
    start: [f64; N],
    calls: usize,
    rhs: impl Fn(&[f64; N]) -> [f64; N],
) -> [f64; N] {
    let mut state = start;
    for _ in 0..calls {
        let rates = rhs(black_box(&state));
        for (x, r) in state.iter_mut().zip(rates) {
            *x += 1e-9 * r;
        }
    }
    state
}

fn main() {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let (table, form, calls, heading) = match arguments.as_slice() {
        [table, form, calls] => (table, form, calls, 0.3),
        [table, form, calls, heading] => {
            (table, form, calls, heading.parse().expect("a heading, rad"))
        }
        _ => {
            eprintln!(
                "usage: calls TABLE FORM CALLS [HEADING] (TABLE: ten, ten-rk4, mariner, remus, lanes, scalar-cases; FORM: rustc, jit, interpreted)"
            );
            std::process::exit(2);
        }
    };
    let calls: usize = calls.parse().expect("CALLS is a count");
    let ship_start = [6.0, 0.4, -0.02, 10.0, -5.0, heading, 0.1];
    let end = match (table.as_str(), form.as_str()) {
        ("ten", "rustc") => {
            let k = ship::Coefficients::<f64>::new(&example_ship());
            run(ship_start, calls, |y| k.rhs(y, &[0.01])).to_vec()
        }
        ("lanes", "rustc") => cases(true, calls),
        ("scalar-cases", "rustc") => cases(false, calls),
        ("ten-rk4", "rustc") => {
            let k = ship::Coefficients::<f64>::new(&example_ship());
            rk4(&k.driven_by(Constant([0.0])), ship_start, calls).to_vec()
        }
        ("ten-rk4", _) => {
            let jit = ShipModel::new(&common::table()).expect("the table builds");
            rk4(&jit.driven_by(Constant([0.0, 0.0, 0.0])), ship_start, calls).to_vec()
        }
        ("ten", form) => {
            let jit = ShipModel::new(&common::table()).expect("the table builds");
            let model = if form == "jit" {
                jit
            } else {
                jit.interpreted()
            };
            run(ship_start, calls, |y| model.rhs(y, &[0.01, 0.0, 0.0])).to_vec()
        }
        ("mariner", form) => {
            let table = mariner_table();
            let start = [7.5, 0.3, -0.01, 10.0, -5.0, heading, 0.1];
            if form == "rustc" {
                let m = mariner_coefficients(&table);
                run(start, calls, |y| mariner_rates(&m, y, 0.01)).to_vec()
            } else {
                let jit = ShipModel::new(&table).expect("the Mariner builds");
                let model = if form == "jit" {
                    jit
                } else {
                    jit.interpreted()
                };
                run(start, calls, |y| model.rhs(y, &[0.01, 0.0, 0.0])).to_vec()
            }
        }
        ("remus", form) => {
            let scene = common::remus_scene();
            let mut start = [0.0; 15];
            start[..6].copy_from_slice(&[1.5, 0.05, -0.03, 0.01, 0.02, -0.03]);
            start[9] = 1.0;
            start[13] = 0.05;
            if form == "rustc" {
                let r = remus_coefficients(&scene);
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
                run(start, calls, rustc).to_vec()
            } else {
                let model = if form == "jit" {
                    scene.model.clone()
                } else {
                    scene.model.interpreted()
                };
                run(start, calls, |y| model.rhs(y, &[0.01, -0.01])).to_vec()
            }
        }
        _ => panic!("unknown table {table}"),
    };
    black_box(end);
}
