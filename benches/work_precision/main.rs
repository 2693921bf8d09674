//! The work–precision harness: every integrator on every reference problem, over a sweep of
//! steps (fixed-step methods) or tolerances (adaptive: rtol from 1e-3 to 1e-12), against the
//! exact solutions of `eom::reference`, with `ode_solvers`' Dopri5 and Dop853 as the peer.
//!
//! `cargo bench --bench work_precision` prints the Markdown report and writes it, with the
//! plots, to `target/work_precision/` and to `docs/work_precision/` of the workspace (the
//! copy the README shows): `work_precision.md`, `work_precision.svg` (error against time, one
//! panel per problem) and `tennis_racket_variants.svg` (the tennis racket's model variants).
//!
//! The tennis racket is run in every model form: f64 and f32; quaternion and Euler-angle
//! kinematics; the hand-written forms of `eom::reference::torque_free`, the generated models
//! of `eom::models` and the generic nalgebra form `eom::generic::RigidBody`; pruned (principal
//! axes) and full tensor (see `spatial` for how the 6-DOF models are fitted to the problem).
//!
//! `cargo bench --bench work_precision -- turned` runs only the racket in turned axes (the
//! generated full model beside the generic form) and prints its report without writing any
//! file; `-- turned generated` or `-- turned generic` runs one form alone. With
//! `WORK_PRECISION_REPS=n` every run is repeated exactly `n` times after the first instead of
//! for a time budget, so that a profiler (`perf stat`, callgrind) sees a known number of RHS
//! calls: the RHS evals column times `n + 1`.
//!
//! To add a model, add one line to the list of its problem (a name and a system); to compare
//! two models side by side in the report, add their names to `names::PAIRS`.

mod names;
mod peer;
mod plot;
mod report;
mod spatial;
mod sweep;

use std::path::{Path, PathBuf};

use eom::PendulumParameters;
use eom::generic::{RigidBody, quaternion_state_of_rotation, rotation_of_quaternion_state};
use eom::integrate::OdeSystem;
use eom::models::{SpatialFullQuaternion, SpatialPrincipalEuler, SpatialPrincipalQuaternion};
use eom::reference::torque_free::{EulerAngleBody, FullTensorBody};
use eom::reference::{AxisymmetricTop, LargeSwing, PlanarTurn, ReferenceProblem, TennisRacket};
use nalgebra::{Matrix3, Quaternion, RealField, SVector, UnitQuaternion, Vector3};

use eom::models::{Constant, Model};
use report::BASE;
use spatial::{
    MASS, TurnedAxes, euler_state, generic_euler, generic_quaternion, rotation_of_euler,
};
use sweep::{Case, RTOLS, Row, sweep_geometric, sweep_runge_kutta};

/// The largest relative change between two lists of conserved quantities.
fn drift(start: &[f64], end: &[f64]) -> f64 {
    start
        .iter()
        .zip(end)
        .map(|(a, b)| (b / a - 1.0).abs())
        .fold(0.0, f64::max)
}

/// The judge of a problem in its own state layout: error at its horizon and invariant drift.
fn judge_of<const N: usize>(
    p: &impl ReferenceProblem<N>,
) -> impl Fn(&SVector<f64, N>) -> (f64, f64) + '_ {
    let (t_end, start) = (p.t_end(), p.invariants(&p.initial_state()));
    move |y| (p.error(t_end, y), drift(&start, &p.invariants(y)))
}

/// The case of a problem in its own state layout.
fn case_of<'a, const N: usize>(
    p: &impl ReferenceProblem<N>,
    model: &str,
    judge: &'a dyn Fn(&SVector<f64, N>) -> (f64, f64),
) -> Case<'a, N> {
    Case {
        problem: p.name(),
        model: model.to_string(),
        y0: p.initial_state(),
        t_end: p.t_end(),
        judge,
    }
}

fn pendulum_rows() -> Vec<Row> {
    let parameters = PendulumParameters::new(2.0, 3.0, 9.81, 0.5).expect("valid pendulum");
    let p = LargeSwing::new(&parameters, 150f64.to_radians()).expect("a swing below π");
    let judge = judge_of(&p);
    let case = case_of(&p, BASE, &judge);
    let mut rows = sweep_runge_kutta::<f64, 2, _>(&case, &p, Some(1..2), &RTOLS);
    rows.extend(peer::sweep_peer(&case, &p));
    rows
}

fn axisymmetric_rows() -> Vec<Row> {
    let attitude = UnitQuaternion::from_euler_angles(0.1, 0.4, -0.7);
    let top =
        AxisymmetricTop::new(2.0, 3.5, Vector3::new(0.6, -0.3, 1.2), attitude).expect("valid top");
    let judge = judge_of(&top);
    let case = case_of(&top, BASE, &judge);
    let mut rows = sweep_runge_kutta::<f64, 7, _>(&case, &top.body(), Some(0..3), &RTOLS);
    rows.extend(sweep_geometric::<f64, _>(&case, &top.body()));
    rows.extend(peer::sweep_peer(&case, &top.body()));
    rows
}

fn planar_rows() -> Vec<Row> {
    let turn = PlanarTurn::new(1000.0, 0.2, (300.0, -150.0), (5.0, 0.4)).expect("valid turn");
    let judge = judge_of(&turn);
    let case = case_of(&turn, BASE, &judge);
    let mut rows = sweep_runge_kutta::<f64, 5, _>(&case, &turn, Some(0..2), &RTOLS);
    rows.extend(peer::sweep_peer(&case, &turn));
    rows
}

/// The tennis racket in every form: the base model (f64, principal axes 4.52, quaternion),
/// in f32, with Euler-angle kinematics (4.60), with the full-tensor form (4.51), and through
/// the generated spatial models and the generic nalgebra form.
fn racket_rows() -> Vec<Row> {
    let racket = tennis_racket();
    let moments = racket.body().moments;
    let judge = judge_of(&racket);
    let case = |model: &str| case_of(&racket, model, &judge);
    let full = FullTensorBody::new(Matrix3::from_diagonal(&moments)).expect("invertible");
    let mut rows = sweep_runge_kutta::<f64, 7, _>(&case(BASE), &racket.body(), Some(0..3), &RTOLS);
    rows.extend(sweep_geometric::<f64, _>(&case(BASE), &racket.body()));
    rows.extend(peer::sweep_peer(&case(BASE), &racket.body()));
    // The hand-written model variants, one line each; the spatial models follow.
    rows.extend(sweep_runge_kutta::<f32, 7, _>(
        &case("f32"),
        &racket.body(),
        None,
        &RTOLS[..4],
    ));
    rows.extend(sweep_runge_kutta::<f64, 7, _>(
        &case("f64, full tensor 4.51"),
        &full,
        None,
        &RTOLS,
    ));
    rows.extend(sweep_geometric::<f64, _>(
        &case("f64, full tensor 4.51"),
        &full,
    ));
    rows.extend(euler_angle_rows(&racket));
    rows.extend(spatial_rows(&racket));
    rows
}

/// The start state and the judge of the tennis racket with Euler-angle kinematics: the state
/// `[p, q, r, φ, θ, ψ]` is judged by turning the angles into the quaternion of Rz(ψ)Ry(θ)Rx(φ)
/// (4.56).
fn euler_angle_judge(
    racket: &TennisRacket,
) -> (
    SVector<f64, 6>,
    impl Fn(&SVector<f64, 6>) -> (f64, f64) + '_,
) {
    let y = racket.initial_state();
    let (roll, pitch, yaw) =
        UnitQuaternion::from_quaternion(Quaternion::new(y[3], y[4], y[5], y[6])).euler_angles();
    let y0 = SVector::<f64, 6>::from([y[0], y[1], y[2], roll, pitch, yaw]);
    let base = judge_of(racket);
    let judge = move |e: &SVector<f64, 6>| {
        let q = UnitQuaternion::from_euler_angles(e[3], e[4], e[5]);
        base(&SVector::<f64, 7>::from([
            e[0], e[1], e[2], q.w, q.i, q.j, q.k,
        ]))
    };
    (y0, judge)
}

/// The case of the tennis racket in a state layout other than its own.
fn racket_case<'a, const M: usize>(
    racket: &TennisRacket,
    model: &str,
    y0: SVector<f64, M>,
    judge: &'a dyn Fn(&SVector<f64, M>) -> (f64, f64),
) -> Case<'a, M> {
    Case {
        problem: racket.name(),
        model: model.into(),
        y0,
        t_end: racket.t_end(),
        judge,
    }
}

/// The tennis racket with Euler-angle kinematics: the hand-written form (4.52 with 4.60), the
/// generated `SpatialPrincipalEuler` and the generic `RigidBody::rhs_euler`.
fn euler_angle_rows(racket: &TennisRacket) -> Vec<Row> {
    let (y0, judge) = euler_angle_judge(racket);
    let case = |model: &str| racket_case(racket, model, y0, &judge);
    let body = EulerAngleBody {
        moments: racket.body().moments,
    };
    let tensor = spatial::principal_tensor(racket);
    let generated = SpatialPrincipalEuler::<f64>::new(MASS, &tensor).expect("valid model");
    let generic = RigidBody::<f64>::new(MASS, &tensor).expect("valid body");
    let mut rows = variant::<f64, 6>(&case("f64, Euler angles 4.60"), &body, &RTOLS);
    // The spatial models in their own 12-state, judged on its rotational part.
    let whole = |y: &SVector<f64, 12>| judge(&rotation_of_euler(y));
    let case = |model: &str| racket_case(racket, model, euler_state(&y0), &whole);
    let system = generated.driven_by(Constant::zero());
    rows.extend(variant::<f64, 12>(
        &case(names::GENERATED_EULER),
        &system,
        &RTOLS,
    ));
    rows.extend(variant::<f64, 12>(
        &case(names::GENERIC_EULER),
        &generic_euler(generic),
        &RTOLS,
    ));
    rows
}

/// Every Runge–Kutta method on one model variant, without symplectic Euler.
fn variant<T: RealField + Copy, const M: usize>(
    case: &Case<M>,
    system: &impl OdeSystem<T, M>,
    rtols: &[f64],
) -> Vec<Row> {
    sweep_runge_kutta::<T, M, _>(case, system, None, rtols)
}

/// The tennis racket through the generated spatial models and the generic nalgebra form in
/// quaternion kinematics, each in its own 13-state (see [`spatial`]); one line per model.
fn spatial_rows(racket: &TennisRacket) -> Vec<Row> {
    let base = judge_of(racket);
    let judge = |y: &SVector<f64, 13>| base(&rotation_of_quaternion_state(y));
    let y0 = quaternion_state_of_rotation(&racket.initial_state());
    let case = |model: &str| racket_case(racket, model, y0, &judge);
    let tensor = spatial::principal_tensor(racket);
    let pruned = SpatialPrincipalQuaternion::<f64>::new(MASS, &tensor).expect("valid model");
    let full = SpatialFullQuaternion::<f64>::new(MASS, &tensor).expect("valid model");
    let pruned32 = SpatialPrincipalQuaternion::<f32>::new(MASS, &tensor).expect("valid model");
    let generic = RigidBody::<f64>::new(MASS, &tensor).expect("valid body");
    let generic32 = RigidBody::<f32>::new(MASS, &tensor).expect("valid body");
    let mut rows = Vec::new();
    let system = pruned.driven_by(Constant::zero());
    rows.extend(variant::<f64, 13>(&case(names::GENERATED), &system, &RTOLS));
    rows.extend(variant::<f64, 13>(
        &case(names::GENERIC),
        &generic_quaternion(generic),
        &RTOLS,
    ));
    let system = full.driven_by(Constant::zero());
    rows.extend(variant::<f64, 13>(
        &case(names::GENERATED_FULL_ZERO),
        &system,
        &RTOLS,
    ));
    let system = pruned32.driven_by(Constant::zero());
    rows.extend(variant::<f32, 13>(
        &case(names::GENERATED_F32),
        &system,
        &RTOLS[..4],
    ));
    rows.extend(variant::<f32, 13>(
        &case(names::GENERIC_F32),
        &generic_quaternion(generic32),
        &RTOLS[..4],
    ));
    rows.extend(turned_axes_rows(racket, None));
    rows
}

/// The same racket in body axes turned from its principal axes: the full generated model and
/// the generic form, judged after turning the end state back (see [`spatial::TurnedAxes`]);
/// `only` (`"generated"` or `"generic"`) keeps one of the two.
fn turned_axes_rows(racket: &TennisRacket, only: Option<&str>) -> Vec<Row> {
    let turned = TurnedAxes::new(racket);
    let base = judge_of(racket);
    let judge = |y: &SVector<f64, 13>| base(&turned.to_principal(&rotation_of_quaternion_state(y)));
    let y0 = quaternion_state_of_rotation(&turned.initial_state(racket));
    let case = |model: &str| racket_case(racket, model, y0, &judge);
    let full = SpatialFullQuaternion::<f64>::new(MASS, turned.tensor()).expect("valid model");
    let generic = RigidBody::<f64>::new(MASS, turned.tensor()).expect("valid body");
    let mut rows = Vec::new();
    if only != Some("generic") {
        let system = full.driven_by(Constant::zero());
        rows.extend(variant::<f64, 13>(
            &case(names::TURNED_GENERATED),
            &system,
            &RTOLS,
        ));
    }
    if only != Some("generated") {
        rows.extend(variant::<f64, 13>(
            &case(names::TURNED_GENERIC),
            &generic_quaternion(generic),
            &RTOLS,
        ));
    }
    rows
}

/// Writes `text` to `name` in each of the output directories.
fn write_all(dirs: &[PathBuf], name: &str, text: &str) {
    for dir in dirs {
        std::fs::write(dir.join(name), text).expect("write the report");
    }
}

/// The racket of [`racket_rows`].
fn tennis_racket() -> TennisRacket {
    let attitude = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
    TennisRacket::new(Vector3::new(1.0, 2.0, 3.0), 1.0, 0.1, attitude).expect("valid racket")
}

fn main() {
    // `-- turned [generated|generic]` profiles one comparison (see the module docs).
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    if args.first().is_some_and(|a| a == "turned") {
        let rows = turned_axes_rows(&tennis_racket(), args.get(1).map(String::as_str));
        println!("{}", report::markdown(&rows));
        return;
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = root.join("target").join("work_precision");
    let docs = root.join("docs").join("work_precision");
    for dir in [&out, &docs] {
        std::fs::create_dir_all(dir).expect("create the output directory");
    }
    let mut rows = pendulum_rows();
    rows.extend(axisymmetric_rows());
    rows.extend(racket_rows());
    rows.extend(planar_rows());
    let markdown = report::markdown(&rows);
    println!("{markdown}");
    write_all(&[out.clone(), docs.clone()], "work_precision.md", &markdown);
    let problems = ["pendulum", "axisymmetric", "tennis racket", "planar turn"];
    plot::problems(&rows, &problems, &out.join("work_precision.svg")).expect("plot the problems");
    plot::variants(&rows, &out.join("tennis_racket_variants.svg")).expect("plot the variants");
    for svg in ["work_precision.svg", "tennis_racket_variants.svg"] {
        std::fs::copy(out.join(svg), docs.join(svg)).expect("copy the plot");
    }
    eprintln!("wrote {} and {}", out.display(), docs.display());
}
