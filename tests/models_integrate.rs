//! Every model of the catalog, integrated as a user integrates it: `model.driven_by(loads)`
//! handed to an integrator, with no adapter. Without loads the energy of each model is a
//! constant of its motion (the kinetic energy it reports, 4.32, plus the potential energy the
//! pendulum and the top report, 4.35), so DOP853 at a tight tolerance must keep it; with a
//! constant load the change of kinetic energy must equal the work done.

use eom::PendulumParameters;
use eom::integrate::{AdaptiveOptions, Dop853, Integrator};
use eom::models::{Constant, Kinematics, Model, Symmetry};
use eom_test_support::bodies::tensor;
use nalgebra::SVector;

/// DOP853 at rtol = atol = 1e-12 over a few periods of the motion: the local errors are
/// ~1e-12 of the state, and energy, a smooth function of it, drifts by a few times that per
/// unit time; 1e-9 relative leaves a wide margin while a wrong rate (an error of one term)
/// changes the energy at order one.
const ENERGY_TOLERANCE: f64 = 1e-9;

fn method() -> Dop853 {
    Dop853::new(AdaptiveOptions::dop853(1e-12, 1e-12))
}

/// A tumbling start: translating, spinning near the middle axis, attitude away from the
/// Euler singularity.
fn spatial_start<const N: usize>(kinematics: Kinematics) -> [f64; N] {
    let mut state = [0.0; N];
    state[..6].copy_from_slice(&[1.0, 0.5, -0.2, 0.3, 2.0, 0.1]);
    let (roll, pitch, yaw) = (0.2, -0.3, 0.5);
    match kinematics {
        Kinematics::Euler => state[9..12].copy_from_slice(&[roll, pitch, yaw]),
        Kinematics::Quaternion => {
            let q = nalgebra::UnitQuaternion::from_euler_angles(roll, pitch, yaw);
            state[9..13].copy_from_slice(&[q.w, q.i, q.j, q.k]);
        }
    }
    state
}

/// A top's start: the spatial start's attitude, spinning at 15 rad/s about the body z-axis
/// with a little wobble.
fn top_start<const N: usize>(kinematics: Kinematics) -> [f64; N] {
    let spatial: [f64; 13] = spatial_start(kinematics);
    let mut state = [0.0; N];
    state[..3].copy_from_slice(&[0.3, 0.2, 15.0]);
    state[3..].copy_from_slice(&spatial[9..6 + N]);
    state
}

/// The energy a model keeps without loads, relative change over `t_end`.
fn energy_drift<Mo: Model<f64, N, M>, const N: usize, const M: usize>(
    model: &Mo,
    start: [f64; N],
    t_end: f64,
    potential: impl Fn(&[f64; N]) -> f64,
) -> f64 {
    let energy = |y: &[f64; N]| model.kinetic_energy(y) + potential(y);
    let free = model.driven_by(Constant::zero());
    let end = method()
        .integrate(&free, 0.0, SVector::from(start), t_end)
        .expect("the run completes");
    let (before, after) = (energy(&start), energy(&end.data.0[0]));
    ((after - before) / before).abs()
}

macro_rules! conservation_tests {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {$(
        #[test]
        fn $module() {
            let drift = conservation_tests!(@drift $type, $family $(($($option),+))?);
            println!("{}: energy drift {drift:.1e}", stringify!($module));
            assert!(drift < ENERGY_TOLERANCE, "{}: energy drift {drift:e}", stringify!($module));
        }
    )*};
    (@drift $type:ident, Pendulum) => {{
        let parameters = PendulumParameters::new(2.0, 3.0, 9.81, 0.5).unwrap();
        let model = eom::models::$type::<f64>::new(&parameters);
        // The emitted −Mgh cos θ (4.35); the energy is 3·9.81·0.5·(−cos 2.5) = 11.8, far from 0.
        let potential = |y: &[f64; 2]| model.potential_energy(y).expect("a pendulum has one");
        energy_drift(&model, [2.5, 0.0], 10.0, potential)
    }};
    (@drift $type:ident, Top($kinematics:ident)) => {{
        // An asymmetric top (I_O = 2.32, 3.32, 4.5) spun fast about its largest axis, tilted
        // 0.36 rad: it nutates but stays far from pitch ±90°, so the Euler variant runs too.
        let model = eom::models::$type::<f64>::new(2.0, &tensor(Symmetry::Principal), 0.4, 9.81)
            .unwrap();
        let state = top_start(Kinematics::$kinematics);
        let potential = |y: &_| model.potential_energy(y).expect("a top has one");
        energy_drift(&model, state, 10.0, potential)
    }};
    (@drift $type:ident, PlanarMidship) => {{
        let model = eom::models::$type::<f64>::new(1000.0, 2.0e5, 3.0).unwrap();
        energy_drift(&model, [5.0, 0.4, 0.05, 0.0, 0.0, 0.3], 100.0, |_| 0.0)
    }};
    (@drift $type:ident, $planar:ident) => {{
        let model = eom::models::$type::<f64>::new(1000.0, 2.0e5).unwrap();
        energy_drift(&model, [5.0, 0.4, 0.05, 0.0, 0.0, 0.3], 100.0, |_| 0.0)
    }};
    (@drift $type:ident, Spatial($symmetry:ident, $kinematics:ident)) => {{
        let model = eom::models::$type::<f64>::new(5.0, &tensor(Symmetry::$symmetry)).unwrap();
        let start = spatial_start(Kinematics::$kinematics);
        energy_drift(&model, start, 10.0, |_| 0.0)
    }};
}

mod energy_is_kept_without_loads {
    use super::*;
    eom::for_each_model!(conservation_tests);
}

/// A constant force and moment on a spatial body, and a closure of time and state: the change
/// of kinetic energy equals the work, ∫(F·v + M·ω) dt, accumulated along the run from the
/// observer's states by the trapezoidal rule on a fine output grid.
#[test]
fn a_load_closure_does_the_work_the_kinetic_energy_gains() {
    use eom::models::SpatialXzQuaternion;
    let model = SpatialXzQuaternion::<f64>::new(5.0, &tensor(Symmetry::Xz)).unwrap();
    // A moment that turns with time and a drag on the surge: any smooth load will do.
    let loads = |t: f64, y: &[f64; 13]| [-0.4 * y[0], 1.0, 0.0, 0.2 * t.cos(), 0.0, -0.1];
    let power = |t: f64, y: &[f64; 13]| {
        let l = loads(t, y);
        (0..3)
            .map(|i| l[i] * y[i] + l[3 + i] * y[3 + i])
            .sum::<f64>()
    };
    let start: [f64; 13] = spatial_start(Kinematics::Quaternion);
    let system = model.driven_by(loads);
    let times: Vec<f64> = (1..=4000).map(|i| f64::from(i) * 1e-3).collect();
    let mut states = vec![SVector::<f64, 13>::zeros(); times.len()];
    method()
        .solve_at(&system, 0.0, SVector::from(start), &times, &mut states)
        .unwrap();
    let mut work = 0.0;
    let (mut t0, mut p0) = (0.0, power(0.0, &start));
    for (&t, y) in times.iter().zip(&states) {
        let p = power(t, &y.data.0[0]);
        work += 0.5 * (p + p0) * (t - t0);
        (t0, p0) = (t, p);
    }
    let gained =
        model.kinetic_energy(&states.last().unwrap().data.0[0]) - model.kinetic_energy(&start);
    println!("gained {gained:.9}, work {work:.9}");
    // The trapezoidal rule on steps of 1e-3 errs by ~h²/12 · |P''| · T ≈ 3e-7 · |P''|, with
    // |P''| of order the power times the rates squared (~4): a few 1e-7 of the work (5e-8
    // seen). The integration itself is good to ~1e-11. 1e-6 of the work is the bound; a
    // missing or misplaced load term changes the balance at order one.
    assert!(
        (gained - work).abs() < 1e-6 * work.abs().max(1.0),
        "gained {gained}, work {work}"
    );
}
