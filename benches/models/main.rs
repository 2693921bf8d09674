//! Generated against generic, in one run: ns per right-hand-side call for every variant,
//! f32 against f64, and a batch of 4096 bodies stepped with f64 scalars against `WideF64x4`
//! lanes. The Euler variants run at two attitudes: roll, pitch and heading within ±π/4, and
//! all three beyond it (`*_large_angles`), since `eom_kernel::sin_cos` skips the argument
//! reduction for the first. To show the kernel's share, run it again with
//! `--features platform-trig`, which makes the generated models call the platform's sin and
//! cos.
//!
//! `cargo bench --bench models`; ratios are read from `target/criterion/*/*/new/estimates.json`
//! (see the README for the table of one run). The per-call groups run twice: in wall time, and
//! in CPU cycles (`spatial_rhs_cycles`, `planar_rhs_cycles`), which a shared machine disturbs
//! far less.

#[cfg(target_os = "linux")]
mod cycles;

use criterion::measurement::Measurement;
use criterion::{BenchmarkId, Criterion, Throughput};
use eom::generic::{PlanarBody, PlanarMidship, RigidBody};
use eom::models::{self, Model, generated};
use eom_test_support::bodies::tensor_of;
use nalgebra::{SVector, Vector2, Vector3};
use simba::simd::WideF64x4;
use std::hint::black_box;

const EULER_STATE: [f64; 12] = [1.0, 0.2, -0.1, 0.3, -0.2, 0.5, 0.0, 0.0, 0.0, 0.1, 0.2, 0.3];
/// The same motion with roll, pitch and heading all beyond ±π/4, where the emitted `sin_cos`
/// reduces every angle instead of evaluating it as it is.
const LARGE_ANGLES_STATE: [f64; 12] = [
    1.0, 0.2, -0.1, 0.3, -0.2, 0.5, 0.0, 0.0, 0.0, 1.0, -0.9, 2.5,
];
const FORCE: [f64; 3] = [10.0, -2.0, 1.0];
const MOMENT: [f64; 3] = [0.5, 0.2, -0.3];
/// [`FORCE`] and [`MOMENT`] as a spatial model's inputs.
const INPUT: [f64; 6] = [10.0, -2.0, 1.0, 0.5, 0.2, -0.3];

fn quaternion_state() -> [f64; 13] {
    let q = nalgebra::UnitQuaternion::from_euler_angles(0.1, 0.2, 0.3);
    let mut x = [0.0; 13];
    x[..9].copy_from_slice(&EULER_STATE[..9]);
    x[9..].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    x
}

/// Generated against generic, f64, one model at one state.
macro_rules! bench_against_generic {
    ($group:expr, $name:expr, $model:ty, $tensor:expr, $state:expr, $generic:ident) => {{
        let tensor = $tensor;
        let state = $state;
        let model = <$model>::new(5.0, &tensor).unwrap();
        $group.bench_function(BenchmarkId::new("generated_f64", $name), |b| {
            b.iter(|| model.rhs(black_box(&state), black_box(&INPUT)))
        });
        let body = RigidBody::<f64>::new(5.0, &tensor).unwrap();
        let x = SVector::from(state);
        let (f, m) = (Vector3::from(FORCE), Vector3::from(MOMENT));
        $group.bench_function(BenchmarkId::new("generic_f64", $name), |b| {
            b.iter(|| body.$generic(black_box(&x), black_box(&f), black_box(&m)))
        });
    }};
}

/// Generated against generic, and the generated model in f32.
macro_rules! bench_spatial {
    ($group:expr, $name:expr, $model:ty, $tensor:expr, $state:expr, $generic:ident) => {{
        let (tensor, state) = ($tensor, $state);
        bench_against_generic!($group, $name, $model, tensor, state, $generic);
        let model32 = <$model>::new(5.0, &tensor).unwrap();
        let state32 = state.map(|x| x as f32);
        let input32 = INPUT.map(|x| x as f32);
        $group.bench_function(BenchmarkId::new("generated_f32", $name), |b| {
            b.iter(|| model32.rhs(black_box(&state32), black_box(&input32)))
        });
    }};
}

/// Every spatial variant of the catalog, named without its `spatial_` prefix; the Euler
/// variants also at large angles.
macro_rules! spatial_benches {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {
        fn spatial<M: Measurement>(c: &mut Criterion<M>, suffix: &str) {
            let mut group = c.benchmark_group(format!("spatial_rhs{suffix}"));
            $(spatial_benches!(@item group, $module, $type, $family $(($($option),+))?);)*
            group.finish();
        }
    };
    (@item $group:ident, $module:ident, $type:ident, Spatial($symmetry:ident, $kinematics:ident)) => {
        let name = stringify!($module).trim_start_matches("spatial_");
        let tensor = tensor_of(models::Symmetry::$symmetry);
        spatial_benches!(@variant $group, name, models::$type<_>, tensor, $kinematics);
    };
    (@item $group:ident, $module:ident, $type:ident, $($other:tt)*) => {};
    (@variant $group:ident, $name:ident, $model:ty, $tensor:ident, Euler) => {
        bench_spatial!($group, $name, $model, $tensor.clone(), EULER_STATE, rhs_euler);
        let large = format!("{}_large_angles", $name);
        bench_against_generic!($group, &large, $model, $tensor, LARGE_ANGLES_STATE, rhs_euler);
    };
    (@variant $group:ident, $name:ident, $model:ty, $tensor:ident, Quaternion) => {
        bench_spatial!($group, $name, $model, $tensor, quaternion_state(), rhs_quaternion);
    };
}

eom::for_each_model!(spatial_benches);

fn planar<M: Measurement>(c: &mut Criterion<M>, suffix: &str) {
    let mut group = c.benchmark_group(format!("planar_rhs{suffix}"));
    let state = [1.0, 0.2, 0.1, 0.0, 0.0, 0.3];
    let load = [10.0, -2.0, 0.5];
    let (x, l) = (SVector::from(state), Vector3::from(load));
    let at_g = models::PlanarAtG::<f64>::new(5.0, 4.0).unwrap();
    let body = PlanarBody::<f64>::new(5.0, 4.0).unwrap();
    group.bench_function(BenchmarkId::new("generated_f64", "at_g"), |b| {
        b.iter(|| at_g.rhs(black_box(&state), black_box(&load)))
    });
    group.bench_function(BenchmarkId::new("generic_f64", "at_g"), |b| {
        b.iter(|| body.rhs_body_at_g(black_box(&x), black_box(&l)))
    });
    let midship = models::PlanarMidship::<f64>::new(5.0, 4.0, 0.3).unwrap();
    let generic_midship = PlanarMidship::<f64>::new(5.0, 4.0, 0.3).unwrap();
    group.bench_function(BenchmarkId::new("generated_f64", "midship"), |b| {
        b.iter(|| midship.rhs(black_box(&state), black_box(&load)))
    });
    group.bench_function(BenchmarkId::new("generic_f64", "midship"), |b| {
        b.iter(|| generic_midship.rhs_body_at_midship(black_box(&x), black_box(&l)))
    });
    let space = models::PlanarSpaceFixed::<f64>::new(5.0, 4.0).unwrap();
    group.bench_function(BenchmarkId::new("generated_f64", "space_fixed"), |b| {
        b.iter(|| space.rhs(black_box(&state), black_box(&load)))
    });
    group.bench_function(BenchmarkId::new("generic_f64", "space_fixed"), |b| {
        b.iter(|| body.rhs_space_fixed(black_box(&x), black_box(&l)))
    });
    let parameters = eom::PendulumParameters::new(2.0, 1.0, 9.81, 0.5).unwrap();
    let pendulum = models::Pendulum::<f64>::new(&parameters);
    let generic_pendulum = eom::generic::Pendulum::<f64>::new(&parameters);
    let theta = Vector2::new(0.3, 0.1);
    group.bench_function(BenchmarkId::new("generated_f64", "pendulum"), |b| {
        b.iter(|| pendulum.rhs(black_box(&[0.3, 0.1]), black_box(&[0.0])))
    });
    group.bench_function(BenchmarkId::new("generic_f64", "pendulum"), |b| {
        b.iter(|| generic_pendulum.rhs(black_box(&theta), black_box(0.0)))
    });
    group.finish();
}

const BODIES: usize = 4096;
const STEP: f64 = 1e-3;

/// One explicit Euler step of every body, f64 scalars: the state update is memory-light, so
/// this measures the right-hand side.
fn batch(c: &mut Criterion) {
    let mut group = c.benchmark_group("batch_4096_bodies");
    group.throughput(Throughput::Elements(BODIES as u64));
    let parameters = generated::spatial_xz_euler::Parameters {
        mass: 5.0,
        ixx: 2.0,
        iyy: 3.0,
        izz: 4.0,
        ixz: -0.2,
    };
    let k64 = generated::spatial_xz_euler::Coefficients::<f64>::new(&parameters);
    let mut scalar_states: Vec<[f64; 12]> = (0..BODIES).map(perturbed).collect();
    let input = INPUT;
    group.bench_function("f64", |b| {
        b.iter(|| {
            for x in scalar_states.iter_mut() {
                let d = generated::spatial_xz_euler::rhs(&k64, x, &input);
                for i in 0..12 {
                    x[i] += STEP * d[i];
                }
            }
        })
    });
    let k4 = generated::spatial_xz_euler::Coefficients::<WideF64x4>::new(&parameters);
    let mut lane_states: Vec<[WideF64x4; 12]> = (0..BODIES / 4)
        .map(|j| {
            std::array::from_fn(|i| {
                WideF64x4::from(std::array::from_fn::<f64, 4, _>(|l| {
                    perturbed(4 * j + l)[i]
                }))
            })
        })
        .collect();
    let input4: [WideF64x4; 6] = std::array::from_fn(|i| WideF64x4::from([input[i]; 4]));
    let step4 = WideF64x4::from([STEP; 4]);
    group.bench_function("wide_f64x4", |b| {
        b.iter(|| {
            for x in lane_states.iter_mut() {
                let d = generated::spatial_xz_euler::rhs(&k4, x, &input4);
                for i in 0..12 {
                    x[i] += step4 * d[i];
                }
            }
        })
    });
    group.finish();
}

/// A distinct, moderate state per body.
fn perturbed(i: usize) -> [f64; 12] {
    let s = (i as f64 * 0.618_033_988_75).fract() - 0.5;
    std::array::from_fn(|k| EULER_STATE[k] + 0.1 * s * (k as f64 + 1.0).sin())
}

/// Wall time first (every group), then the per-call groups again in CPU cycles where the
/// kernel grants a perf counter (`*_cycles` groups).
fn main() {
    let mut wall = Criterion::default().configure_from_args();
    spatial(&mut wall, "");
    planar(&mut wall, "");
    batch(&mut wall);
    #[cfg(target_os = "linux")]
    match cycles::Cycles::new() {
        Some(counter) => {
            let mut cycles = Criterion::default()
                .with_measurement(counter)
                .configure_from_args();
            spatial(&mut cycles, "_cycles");
            planar(&mut cycles, "_cycles");
            cycles.final_summary();
        }
        None => eprintln!("no perf counter here: the *_cycles groups are skipped"),
    }
    wall.final_summary();
}
