//! Calls one right-hand side many times, for counting the instructions of one call with
//! callgrind, which is repeatable where wall time on a shared machine is not:
//!
//! ```sh
//! cargo build --release --example rhs_calls
//! valgrind --tool=callgrind --toggle-collect='*measured*' --callgrind-out-file=/dev/null \
//!     target/release/examples/rhs_calls generated principal_euler 1000
//! ```
//!
//! Each call goes through one `#[inline(never)]` function, `measured`, so collecting only
//! inside it counts the right-hand side and nothing of the loop around it: the total divided
//! by the number of calls is the cost of one call. `form` is `generated` or `generic`; `model`
//! is a model of the catalog (`eom models`), the spatial ones with or without their
//! `spatial_` prefix (`principal_euler`); the generated side has one arm per catalog entry. Built with `--features platform-trig`, the
//! generated models call the platform's sin and cos instead of `eom_kernel::sin_cos`: the
//! difference between the two builds is the kernel's share.

use eom::generic::{PlanarBody, PlanarMidship, RigidBody};
use eom::models::{self, Model, ModelInfo, Symmetry};
use eom::{InertiaTensor, PendulumParameters};
use nalgebra::{SVector, Vector2, Vector3};
use std::hint::black_box;

/// Distinct states, built before the calls so that their cost does not depend on the count.
const STATES: usize = 64;

const FORCE: [f64; 3] = [10.0, -2.0, 1.0];
const MOMENT: [f64; 3] = [0.5, 0.2, -0.3];
const LOAD: [f64; 3] = [10.0, -2.0, 0.5];

/// The one function whose instructions are counted: it calls `f` once.
#[inline(never)]
fn measured<R>(f: impl Fn() -> R) -> R {
    f()
}

/// The sum of an output's entries, so that every output is consumed.
trait Total {
    fn total(&self) -> f64;
}

impl<const N: usize> Total for [f64; N] {
    fn total(&self) -> f64 {
        self.iter().sum()
    }
}

impl<const N: usize> Total for SVector<f64, N> {
    fn total(&self) -> f64 {
        self.sum()
    }
}

/// Calls `f` on each of `states` in turn, `calls` times in all, consuming every output.
fn run<S, R: Total>(states: &[S], calls: usize, f: impl Fn(&S) -> R) -> f64 {
    let mut sum = 0.0;
    for i in 0..calls {
        let state = black_box(&states[i % STATES]);
        sum += black_box(measured(|| f(state))).total();
    }
    sum
}

/// The tensor of a spatial model's symmetry class (`full_euler` → the full tensor).
fn class_tensor(model: &str) -> InertiaTensor {
    let symmetry = catalog_entry(model)
        .and_then(|info| info.symmetry)
        .unwrap_or(Symmetry::Principal);
    eom_test_support::bodies::tensor_of(symmetry)
}

/// The catalog's entry of `model`, named with or without its `spatial_` prefix.
fn catalog_entry(model: &str) -> Option<&'static ModelInfo> {
    ModelInfo::find(model).or_else(|| ModelInfo::find(&format!("spatial_{model}")))
}

/// The state of call `i`: a little different each time, so nothing is hoisted out of the loop.
fn spatial_state<const N: usize>(i: usize) -> [f64; N] {
    let s = 1e-6 * i as f64;
    let mut x = [0.0; N];
    x[..6].copy_from_slice(&[1.0 + s, 0.2, -0.1, 0.3, -0.2, 0.5]);
    if N == 13 {
        let q = nalgebra::UnitQuaternion::from_euler_angles(0.1 + s, 0.2, 0.3);
        x[9..13].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    } else {
        x[9..12].copy_from_slice(&[0.1 + s, 0.2, 0.3]);
    }
    x
}

/// A top's state: the spatial state's rates and attitude.
fn top_state<const N: usize>(i: usize) -> [f64; N] {
    let spatial: [f64; 13] = spatial_state(i);
    let mut x = [0.0; N];
    x[..3].copy_from_slice(&spatial[3..6]);
    if N == 7 {
        x[3..].copy_from_slice(&spatial[9..13]);
    } else {
        let s = 1e-6 * i as f64;
        x[3..].copy_from_slice(&[0.1 + s, 0.2, 0.3]);
    }
    x
}

fn states<const N: usize>(make: impl Fn(usize) -> [f64; N]) -> Vec<[f64; N]> {
    (0..STATES).map(make).collect()
}

fn planar_state(i: usize) -> [f64; 6] {
    [1.0 + 1e-6 * i as f64, 0.2, 0.1, 0.0, 0.0, 0.3]
}

fn pendulum_state(i: usize) -> [f64; 2] {
    [0.3 + 1e-6 * i as f64, 0.1]
}

/// The pendulum every form measures.
fn pendulum() -> PendulumParameters {
    PendulumParameters::new(2.0, 1.0, 9.81, 0.5).expect("a physical pendulum")
}

/// Calls the generated model named `model` (a catalog name, spatial ones with or without
/// their `spatial_` prefix): one arm per catalog entry, written by `for_each_model!`, each
/// with its inputs as literals, as the generic side has them, so that the compiler folds them
/// into both alike.
macro_rules! generated_calls {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {
        fn generated(model: &str, calls: usize) -> Option<f64> {
            let name = catalog_entry(model)?.name;
            $(
                if name == stringify!($module) {
                    let model = generated_calls!(@model $type, $family $(($($option),+))?);
                    return Some(run(
                        &states(generated_calls!(@state $family $(($($option),+))?)),
                        calls,
                        |x| model.rhs(x, &generated_calls!(@input $family)),
                    ));
                }
            )*
            None
        }
    };
    (@model $type:ident, Pendulum) => { models::$type::<f64>::new(&pendulum()) };
    (@model $type:ident, PlanarMidship) => { models::$type::<f64>::new(5.0, 4.0, 0.3).ok()? };
    (@model $type:ident, Spatial($symmetry:ident, $kinematics:ident)) => {
        models::$type::<f64>::new(5.0, &eom_test_support::bodies::tensor_of(Symmetry::$symmetry)).ok()?
    };
    (@model $type:ident, Top($kinematics:ident)) => {
        models::$type::<f64>::new(5.0, &eom_test_support::bodies::tensor_of(Symmetry::Principal), 0.3, 9.81).ok()?
    };
    (@model $type:ident, $planar:ident) => { models::$type::<f64>::new(5.0, 4.0).ok()? };
    (@state Pendulum) => { pendulum_state };
    (@state Spatial($symmetry:ident, Euler)) => { spatial_state::<12> };
    (@state Spatial($symmetry:ident, Quaternion)) => { spatial_state::<13> };
    (@state Top(Euler)) => { top_state::<6> };
    (@state Top(Quaternion)) => { top_state::<7> };
    (@state $planar:ident) => { planar_state };
    (@input Pendulum) => { [0.0] };
    (@input Spatial) => { [FORCE[0], FORCE[1], FORCE[2], MOMENT[0], MOMENT[1], MOMENT[2]] };
    (@input Top) => { MOMENT };
    (@input $planar:ident) => { LOAD };
}

eom::for_each_model!(generated_calls);

fn generic(model: &str, calls: usize) -> Option<f64> {
    let load = Vector3::from(LOAD);
    let (f, m) = (Vector3::from(FORCE), Vector3::from(MOMENT));
    let planar = |i| SVector::<f64, 6>::from(planar_state(i));
    let spatial = |i| SVector::<f64, 12>::from(spatial_state::<12>(i));
    let spatial_q = |i| SVector::<f64, 13>::from(spatial_state::<13>(i));
    Some(match model {
        "pendulum" => {
            let p = eom::generic::Pendulum::<f64>::new(&pendulum());
            let xs: Vec<_> = (0..STATES)
                .map(|i| Vector2::from(pendulum_state(i)))
                .collect();
            run(&xs, calls, |x| p.rhs(x, 0.0))
        }
        "planar_at_g" | "planar_space_fixed" => {
            let p = PlanarBody::<f64>::new(5.0, 4.0).ok()?;
            let xs: Vec<_> = (0..STATES).map(planar).collect();
            if model == "planar_at_g" {
                run(&xs, calls, |x| p.rhs_body_at_g(x, &load))
            } else {
                run(&xs, calls, |x| p.rhs_space_fixed(x, &load))
            }
        }
        "planar_midship" => {
            let p = PlanarMidship::<f64>::new(5.0, 4.0, 0.3).ok()?;
            let xs: Vec<_> = (0..STATES).map(planar).collect();
            run(&xs, calls, |x| p.rhs_body_at_midship(x, &load))
        }
        // The top has no generic form: its rates are checked against nalgebra in tests/top.rs.
        _ if model.starts_with("top_") => return None,
        _ if model.ends_with("_euler") => {
            let body = RigidBody::<f64>::new(5.0, &class_tensor(model)).ok()?;
            let xs: Vec<_> = (0..STATES).map(spatial).collect();
            run(&xs, calls, |x| body.rhs_euler(x, &f, &m))
        }
        _ if model.ends_with("_quaternion") => {
            let body = RigidBody::<f64>::new(5.0, &class_tensor(model)).ok()?;
            let xs: Vec<_> = (0..STATES).map(spatial_q).collect();
            run(&xs, calls, |x| body.rhs_quaternion(x, &f, &m))
        }
        _ => return None,
    })
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let form = args.get(1).map_or("generated", String::as_str);
    let model = args.get(2).map_or("principal_euler", String::as_str);
    let calls: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let sum = match form {
        "generated" => generated(model, calls),
        "generic" => generic(model, calls),
        _ => None,
    };
    match sum {
        Some(sum) => println!("{form} {model}: {calls} calls (checksum {sum:.6})"),
        None => {
            eprintln!("usage: rhs_calls generated|generic MODEL [CALLS]; see the source");
            std::process::exit(2);
        }
    }
}
