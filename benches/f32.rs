//! f32 against f64, per right-hand-side call, in one interleaved run: every spatial variant of
//! the catalog over the same 1024 states, each call's outputs summed, the two precisions taking
//! turns round after round (f64 first in even rounds, f32 first in odd ones), medians of 11
//! rounds. The Euler variants run twice: with roll, pitch and heading within ±π/4, where
//! `eom_kernel::sin_cos` evaluates the angle as it is, and spread over [−π, π) (pitch within
//! ±80°), where it reduces most of them and its branch goes either way from call to call.
//!
//! ```sh
//! cargo bench --bench f32                                                        # x86-64 baseline
//! RUSTFLAGS="-C target-cpu=native" CARGO_TARGET_DIR=target/native cargo bench --bench f32
//! ```
//!
//! ratio = f64's ns per call over f32's: above 1, f32 is faster.

use eom::models::{self, Model};
use std::hint::black_box;
use std::time::Instant;

const STATES: usize = 1024;
const PASSES: usize = 20;
const ROUNDS: usize = 11;
const INPUT: [f64; 6] = [10.0, -2.0, 1.0, 0.5, 0.2, -0.3];

/// A fixed sequence in [0, 1): the golden-ratio walk, one stride per coordinate.
fn spread(i: usize, stride: f64) -> f64 {
    (i as f64 * stride).fract()
}

/// 1024 states of `N` entries (12 with Euler angles, 13 with a quaternion): velocities and rates
/// spread over ±5 m/s and ±1.5 rad/s, forward speed 5–40 m/s, roll and heading in
/// ±`roll_yaw`, pitch in ±`pitch`.
fn states<const N: usize>(roll_yaw: f64, pitch: f64) -> Vec<[f64; N]> {
    (0..STATES)
        .map(|i| {
            let u = |k: usize| spread(i, 0.618_033_988_75 + 0.1 * k as f64) * 2.0 - 1.0;
            let mut y = [0.0; 13];
            y[0] = 22.5 + 17.5 * u(0);
            y[1] = 5.0 * u(1);
            y[2] = 5.0 * u(2);
            y[3..6].copy_from_slice(&[1.5 * u(3), 1.5 * u(4), 1.5 * u(5)]);
            let (roll, pitch, yaw) = (roll_yaw * u(6), pitch * u(7), roll_yaw * u(8));
            if N == 13 {
                let q = nalgebra::UnitQuaternion::from_euler_angles(roll, pitch, yaw);
                y[9..13].copy_from_slice(&[q.w, q.i, q.j, q.k]);
            } else {
                y[9..12].copy_from_slice(&[roll, pitch, yaw]);
            }
            std::array::from_fn(|j| y[j])
        })
        .collect()
}

/// Nanoseconds per call of `model` over `states`, every output summed.
fn time<T, Mo, const N: usize>(model: &Mo, states: &[[T; N]], input: &[T; 6]) -> f64
where
    T: nalgebra::RealField + Copy + Default,
    Mo: Model<T, N, 6>,
{
    let start = Instant::now();
    let mut sum = T::default();
    for _ in 0..PASSES {
        for state in states {
            let rate = model.rhs(black_box(state), black_box(input));
            sum = rate.iter().fold(sum, |sum, &x| sum + x);
        }
    }
    black_box(sum);
    start.elapsed().as_secs_f64() * 1e9 / (PASSES * states.len()) as f64
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// One variant at one set of states, f64 and f32 in turn; prints a table row.
fn compare<M64, M32, const N: usize>(name: &str, model: (&M64, &M32), states: &[[f64; N]])
where
    M64: Model<f64, N, 6>,
    M32: Model<f32, N, 6>,
{
    let narrow: Vec<[f32; N]> = states.iter().map(|y| y.map(|x| x as f32)).collect();
    let input32 = INPUT.map(|x| x as f32);
    let (mut wide, mut single, mut ratios) = (vec![], vec![], vec![]);
    for round in 0..ROUNDS {
        let (a, b) = if round % 2 == 0 {
            let a = time(model.0, states, &INPUT);
            (a, time(model.1, &narrow, &input32))
        } else {
            let b = time(model.1, &narrow, &input32);
            (time(model.0, states, &INPUT), b)
        };
        wide.push(a);
        single.push(b);
        ratios.push(a / b);
    }
    let range = ratios
        .iter()
        .copied()
        .fold((f64::MAX, f64::MIN), |(lo, hi), r| (lo.min(r), hi.max(r)));
    println!(
        "| {name} | {:.1} | {:.1} | **{:.2}** ({:.2}–{:.2}) |",
        median(wide),
        median(single),
        median(ratios),
        range.0,
        range.1
    );
}

macro_rules! spatial_rows {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {
        fn spatial() {
            $(spatial_rows!(@item $module, $type, $family $(($($option),+))?);)*
        }
    };
    (@item $module:ident, $type:ident, Spatial($symmetry:ident, $kinematics:ident)) => {
        let tensor = eom_test_support::bodies::tensor_of(models::Symmetry::$symmetry);
        let wide = models::$type::<f64>::new(5.0, &tensor).expect("a valid body");
        let single = models::$type::<f32>::new(5.0, &tensor).expect("a valid body");
        spatial_rows!(@rows $module, $kinematics, (&wide, &single));
    };
    (@item $module:ident, $type:ident, $($other:tt)*) => {};
    (@rows $module:ident, Euler, $models:expr) => {
        let name = stringify!($module);
        compare::<_, _, 12>(&format!("{name}, angles within ±π/4"), $models, &states(0.7, 0.7));
        compare::<_, _, 12>(&format!("{name}, angles anywhere"), $models, &states(3.1, 1.4));
    };
    (@rows $module:ident, Quaternion, $models:expr) => {
        compare::<_, _, 13>(stringify!($module), $models, &states(3.1, 1.4));
    };
}

eom::for_each_model!(spatial_rows);

fn main() {
    let avx2 = cfg!(target_feature = "avx2");
    let fma = cfg!(target_feature = "fma");
    println!(
        "{STATES} states × {PASSES} passes per round, medians of {ROUNDS} interleaved rounds; \
         target features avx2 {avx2}, fma {fma}"
    );
    println!();
    println!("| variant | ns/call f64 | ns/call f32 | f64 / f32 (range over rounds) |");
    println!("|---|---:|---:|---:|");
    spatial();
}
