//! The work–precision harness: every integrator on every reference problem, over a sweep of
//! steps (fixed-step methods) or tolerances (adaptive: rtol from 1e-3 to 1e-12), against the
//! exact solutions of `eom::reference`, with `ode_solvers`' Dopri5 and Dop853 as the peer.
//!
//! `cargo bench --bench work_precision` prints the Markdown report and writes it, with the
//! plots, to `target/work_precision/`: `work_precision.md`, `work_precision.svg` (error
//! against time, one panel per problem) and `tennis_racket_variants.svg`.
//!
//! To add a model, add one line to the list of its problem (a name and a system).

mod peer;
mod plot;
mod report;
mod sweep;

use std::path::Path;

use eom::reference::torque_free::{EulerAngleBody, FullTensorBody};
use eom::reference::{
    AxisymmetricTop, CompoundPendulum, PlanarTurn, ReferenceProblem, TennisRacket,
};
use nalgebra::{Matrix3, Quaternion, SVector, UnitQuaternion, Vector3};

use report::BASE;
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
    let p =
        CompoundPendulum::new(2.0, 3.0, 9.81, 0.5, 150f64.to_radians()).expect("valid pendulum");
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
/// in f32, with Euler-angle kinematics (4.60), and with the full-tensor form (4.51).
fn racket_rows() -> Vec<Row> {
    let attitude = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
    let racket =
        TennisRacket::new(Vector3::new(1.0, 2.0, 3.0), 1.0, 0.1, attitude).expect("valid racket");
    let moments = racket.body().moments;
    let judge = judge_of(&racket);
    let case = |model: &str| case_of(&racket, model, &judge);
    let full = FullTensorBody::new(Matrix3::from_diagonal(&moments)).expect("invertible");
    let mut rows = sweep_runge_kutta::<f64, 7, _>(&case(BASE), &racket.body(), Some(0..3), &RTOLS);
    rows.extend(sweep_geometric::<f64, _>(&case(BASE), &racket.body()));
    rows.extend(peer::sweep_peer(&case(BASE), &racket.body()));
    // The model variants, one line each (a generated model joins here when it exists).
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
    rows
}

/// The tennis racket with Euler-angle kinematics: the state `[p, q, r, φ, θ, ψ]` is judged by
/// turning the angles into the quaternion of Rz(ψ)Ry(θ)Rx(φ) (4.56).
fn euler_angle_rows(racket: &TennisRacket) -> Vec<Row> {
    let body = EulerAngleBody {
        moments: racket.body().moments,
    };
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
    let case = Case {
        problem: racket.name(),
        model: "f64, Euler angles 4.60".into(),
        y0,
        t_end: racket.t_end(),
        judge: &judge,
    };
    sweep_runge_kutta::<f64, 6, _>(&case, &body, None, &RTOLS)
}

fn main() {
    let out = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("target")
        .join("work_precision");
    std::fs::create_dir_all(&out).expect("create target/work_precision");
    let mut rows = pendulum_rows();
    rows.extend(axisymmetric_rows());
    rows.extend(racket_rows());
    rows.extend(planar_rows());
    let markdown = report::markdown(&rows);
    println!("{markdown}");
    std::fs::write(out.join("work_precision.md"), &markdown).expect("write the report");
    let problems = ["pendulum", "axisymmetric", "tennis racket", "planar turn"];
    plot::problems(&rows, &problems, &out.join("work_precision.svg")).expect("plot the problems");
    plot::variants(&rows, &out.join("tennis_racket_variants.svg")).expect("plot the variants");
    eprintln!("wrote {}", out.display());
}
