//! Turning circles per second in SIMD lanes: 4096 of the rustc-compiled Mariner's turns
//! (`scenes/mariner.toml`'s table, approaches at 0.95–1.05 U₀, rudder orders 20°, 25°, 30°,
//! 35° to port through the scene's steering gear), each 3400 RK4 steps of 0.1 s (340 s), as
//! scalar f64 (`Batch<f64, 7>`, one case at a time) and as f64×4 lanes (`Batch<WideF64x4, 7>`,
//! four cases to a group, each lane its own rudder order and speed).
//!
//! `cargo bench -p eom-example-user-build-rs --bench lanes` runs seven interleaved rounds (each
//! form in turn, every case through its 3400 steps) and prints the medians as case-steps per
//! second and their ratio, after checking that every lane ended where its case alone did, bit
//! for bit. Both forms step with a fixed step shared by all cases, as `eom::batch` does: what the
//! lanes save is the right-hand sides and RK4's arithmetic, nothing of an adaptive driver's.
//! Build with `RUSTFLAGS="-C target-cpu=native"` (and another `CARGO_TARGET_DIR`) for the
//! machine's own vector width: the default x86-64 target has 128-bit SSE2 registers only.

#[path = "../tests/common/mod.rs"]
#[allow(dead_code)]
mod common;
#[path = "../tests/common/gear.rs"]
mod gear;

use common::{mariner_coefficients, mariner_table, symbols};
use eom::batch::Batch;
use eom_example_user_build_rs::mariner;
use simba::simd::WideF64x4;
use std::hint::black_box;
use std::time::Instant;

const CASES: usize = 4096;
const STEPS: usize = 3400;
const ROUNDS: usize = 7;
const H: f64 = 0.1;

/// The cases' straight approaches, rudder amidships, at speeds spread over ±5 % of U₀.
fn starts(design_speed: f64) -> Vec<[f64; 7]> {
    (0..CASES)
        .map(|i| {
            let speed = design_speed * (0.95 + 0.1 * i as f64 / CASES as f64);
            [speed, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
        })
        .collect()
}

fn orders() -> [f64; 4] {
    gear::RUDDER_ORDERS_DEG.map(f64::to_radians)
}

/// Seconds for every case's `STEPS` steps one case at a time, and the end states: the cases of
/// each rudder order in a `Batch<f64, 7>` of their own.
fn time_scalar(m: &mariner::Coefficients<f64>, starts: &[[f64; 7]]) -> (f64, Vec<[f64; 7]>) {
    let mut batches: Vec<(Batch<f64, 7>, _)> = (orders().iter().enumerate())
        .map(|(lane, &order)| {
            let cases: Vec<[f64; 7]> = starts.iter().skip(lane).step_by(4).copied().collect();
            (Batch::<f64, 7>::new(&cases), gear::steering_gear(order))
        })
        .collect();
    let clock = Instant::now();
    for step in 0..STEPS {
        for (batch, loads) in &mut batches {
            batch.step_rk4(m, loads, step as f64 * H, H);
        }
    }
    let seconds = clock.elapsed().as_secs_f64();
    let ends = (0..CASES).map(|i| batches[i % 4].0.state(i / 4)).collect();
    (seconds, black_box(ends))
}

/// Seconds for every case's `STEPS` steps four cases to a group of f64×4 lanes, and the end
/// states.
fn time_lanes(m: &mariner::Coefficients<WideF64x4>, starts: &[[f64; 7]]) -> (f64, Vec<[f64; 7]>) {
    let mut batch = Batch::<WideF64x4, 7>::new(starts);
    let loads = gear::steering_gear(WideF64x4::from(orders()));
    let clock = Instant::now();
    for step in 0..STEPS {
        batch.step_rk4(m, &loads, step as f64 * H, H);
    }
    let seconds = clock.elapsed().as_secs_f64();
    (seconds, black_box(batch.states()))
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn main() {
    let table = mariner_table();
    let scalar = mariner_coefficients(&table);
    // `Coefficients::new` computes the coefficients in f64 and splats them: every lane holds
    // the same table (what each call computes does not depend on it).
    let values = symbols(&table);
    let parameters =
        mariner::Parameters::from_symbols(|s| values.get(s).copied().unwrap_or(f64::NAN));
    let lanes = mariner::Coefficients::<WideF64x4>::new(&parameters);
    let starts = starts(table.design_speed);
    let avx2 = cfg!(target_feature = "avx2");
    let fma = cfg!(target_feature = "fma");
    println!(
        "{CASES} Mariner turns, {STEPS} RK4 steps of {H} s each per round, medians of {ROUNDS} \
         interleaved rounds; target features avx2 {avx2}, fma {fma}"
    );
    let mut times = [vec![], vec![]];
    let mut ends = [vec![], vec![]];
    for _ in 0..ROUNDS {
        let (seconds, end) = time_scalar(&scalar, &starts);
        times[0].push(seconds);
        ends[0] = end;
        let (seconds, end) = time_lanes(&lanes, &starts);
        times[1].push(seconds);
        ends[1] = end;
    }
    let bits =
        |ends: &[[f64; 7]]| -> Vec<[u64; 7]> { ends.iter().map(|y| y.map(f64::to_bits)).collect() };
    assert!(
        bits(&ends[0]) == bits(&ends[1]),
        "a lane ended elsewhere than its case alone"
    );
    let turned = |lane: usize| {
        let headings = ends[1]
            .iter()
            .skip(lane)
            .step_by(4)
            .map(|y| -y[5].to_degrees());
        let (low, high) = headings.fold((f64::INFINITY, 0.0_f64), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        });
        format!("{}°: {low:.0}–{high:.0}°", gear::RUDDER_ORDERS_DEG[lane])
    };
    println!(
        "every lane's end bit for bit its case's alone; heading turned after {} s by order: {}",
        STEPS as f64 * H,
        (0..4).map(turned).collect::<Vec<_>>().join(", ")
    );
    println!();
    println!("| form | 10⁶ case-steps/s | × scalar f64 |");
    println!("|---|---:|---:|");
    let rates = times.map(|t| (CASES * STEPS) as f64 / median(t));
    for (form, rate) in ["f64 scalar", "f64×4 lanes"].iter().zip(rates) {
        println!("| {form} | {:.3} | {:.2} |", rate / 1e6, rate / rates[0]);
    }
}
