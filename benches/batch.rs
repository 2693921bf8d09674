//! Bodies per second, stepped in batches: 4096 bodies of one model, RK4, as scalar f64 and
//! scalar f32 (one body at a time), f64×4 lanes and f32×8 lanes, for a quaternion and an
//! Euler-angle model.
//!
//! `cargo bench --bench batch` runs seven interleaved rounds (each form in turn, 20 steps of all
//! 4096 bodies each) and prints the medians as body-steps per second and their ratio to scalar
//! f64. Build with `RUSTFLAGS="-C target-cpu=native"` (and another `CARGO_TARGET_DIR`) for the
//! machine's own vector width: the default x86-64 target has 128-bit SSE2 registers only.

use eom::batch::Batch;
use eom::models::{Model, SpatialFullEuler, SpatialPrincipalQuaternion};
use eom::{Constant, InertiaTensor};
use simba::simd::{SimdRealField, WideF32x8, WideF64x4};
use std::hint::black_box;
use std::time::Instant;

const BODIES: usize = 4096;
const STEPS: usize = 20;
const ROUNDS: usize = 7;
const H: f64 = 1e-3;

/// 4096 bodies with rates, velocities and attitudes spread over their ranges (a fixed
/// sequence), N = 13 with a quaternion, 12 with Euler angles.
fn starts<const N: usize>() -> Vec<[f64; N]> {
    (0..BODIES)
        .map(|i| {
            let f = i as f64 / BODIES as f64;
            let mut y = [0.0; 13];
            y[..6].copy_from_slice(&[5.0 + 30.0 * f, 2.0 - 4.0 * f, 0.3, 1.5 * f, -0.7, 0.4]);
            let attitude =
                nalgebra::UnitQuaternion::from_euler_angles(6.0 * f - 3.0, 1.2 * f - 0.6, 2.0);
            if N == 13 {
                y[9..13].copy_from_slice(&[attitude.w, attitude.i, attitude.j, attitude.k]);
            } else {
                let (roll, pitch, yaw) = attitude.euler_angles();
                y[9..12].copy_from_slice(&[roll, pitch, yaw]);
            }
            std::array::from_fn(|i| y[i])
        })
        .collect()
}

/// Seconds for `STEPS` RK4 steps of every body in a batch of lanes `T`.
fn time<T, Mo, const N: usize>(model: &Mo, starts: &[[T::Element; N]]) -> f64
where
    T: SimdRealField + Copy,
    T::Element: Copy,
    Mo: Model<T, N, 6>,
{
    let mut batch = Batch::<T, N>::new(starts);
    let loads = Constant([0.0, 0.0, 0.0, 0.0, 0.0, 0.5].map(|x| T::from_subset(&x)));
    let clock = Instant::now();
    for step in 0..STEPS {
        batch.step_rk4(model, &loads, step as f64 * H, H);
    }
    let seconds = clock.elapsed().as_secs_f64();
    black_box(batch.state(BODIES - 1));
    seconds
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// One model in each form.
struct Forms<'a, M64, M32, M4, M8> {
    f64: &'a M64,
    f32: &'a M32,
    f64x4: &'a M4,
    f32x8: &'a M8,
}

/// The four forms of one model, interleaved; prints a table row per form.
fn compare<M64, M32, M4, M8, const N: usize>(name: &str, model: Forms<M64, M32, M4, M8>)
where
    M64: Model<f64, N, 6>,
    M32: Model<f32, N, 6>,
    M4: Model<WideF64x4, N, 6>,
    M8: Model<WideF32x8, N, 6>,
{
    let starts = starts::<N>();
    let narrow: Vec<[f32; N]> = starts.iter().map(|y| y.map(|x| x as f32)).collect();
    let mut times = [vec![], vec![], vec![], vec![]];
    // `cargo bench --bench batch -- FORM` times only the forms whose name holds FORM (for
    // counting one form's instructions under callgrind).
    let only = std::env::args().nth(1).filter(|a| !a.starts_with('-'));
    let wanted = |form: &str| only.as_deref().is_none_or(|only| form.contains(only));
    for _ in 0..ROUNDS {
        if wanted("f64 scalar") {
            times[0].push(time::<f64, _, N>(model.f64, &starts));
        }
        if wanted("f32 scalar") {
            times[1].push(time::<f32, _, N>(model.f32, &narrow));
        }
        if wanted("f64×4") {
            times[2].push(time::<WideF64x4, _, N>(model.f64x4, &starts));
        }
        if wanted("f32×8") {
            times[3].push(time::<WideF32x8, _, N>(model.f32x8, &narrow));
        }
    }
    if only.is_some() {
        return;
    }
    let rates = times.map(|t| (BODIES * STEPS) as f64 / median(t));
    for (form, rate) in ["f64 scalar", "f32 scalar", "f64×4", "f32×8"]
        .iter()
        .zip(rates)
    {
        println!(
            "| {name} | {form} | {:.2} | {:.2} |",
            rate / 1e6,
            rate / rates[0]
        );
    }
}

fn main() {
    let tensor = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.0).expect("a valid tensor");
    let avx2 = cfg!(target_feature = "avx2");
    let fma = cfg!(target_feature = "fma");
    println!(
        "{BODIES} bodies, {STEPS} RK4 steps per round, medians of {ROUNDS} interleaved rounds; \
         target features avx2 {avx2}, fma {fma}"
    );
    println!();
    println!("| model | form | 10⁶ body-steps/s | × scalar f64 |");
    println!("|---|---|---:|---:|");
    compare::<_, _, _, _, 13>(
        "spatial_principal_quaternion",
        Forms {
            f64: &SpatialPrincipalQuaternion::<f64>::new(5.0, &tensor).expect("valid"),
            f32: &SpatialPrincipalQuaternion::<f32>::new(5.0, &tensor).expect("valid"),
            f64x4: &SpatialPrincipalQuaternion::<WideF64x4>::new(5.0, &tensor).expect("valid"),
            f32x8: &SpatialPrincipalQuaternion::<WideF32x8>::new(5.0, &tensor).expect("valid"),
        },
    );
    let tensor = InertiaTensor::new(2.0, 3.0, 4.0, 0.1, -0.05, 0.2).expect("a valid tensor");
    compare::<_, _, _, _, 12>(
        "spatial_full_euler",
        Forms {
            f64: &SpatialFullEuler::<f64>::new(5.0, &tensor).expect("valid"),
            f32: &SpatialFullEuler::<f32>::new(5.0, &tensor).expect("valid"),
            f64x4: &SpatialFullEuler::<WideF64x4>::new(5.0, &tensor).expect("valid"),
            f32x8: &SpatialFullEuler::<WideF32x8>::new(5.0, &tensor).expect("valid"),
        },
    );
}
