//! The ship of `build.rs`, compiled, against the same table run by `eom`'s evaluator of the
//! proved program (what `eom run` does with a scene's table): ns per right-hand-side call,
//! seven interleaved rounds of 10⁶ calls each, medians, each call on the state the last left;
//! then ns per evaluation inside `eom`'s RK4, the compiled ship driven through the contract
//! its file implements (`driven_by`), the evaluated one through a closure.
//!
//! `cargo bench -p eom-example-user-build-rs`

use eom::integrate::{Integrator, Rk4, Statistics};
use eom::nalgebra::SVector;
use eom::ship::table::{GivenTable, ShipBody, ShipTable};
use eom::ship::{RigidBodyTerms, ShipModel, Units, YawInertia};
use eom::{Constant, Model, OdeSystem};
use eom_example_user_build_rs::{example_ship, ship};
use std::hint::black_box;
use std::time::Instant;

const CALLS: usize = 1_000_000;

/// The same numbers as `example_ship`, as a table `eom` reads.
fn table() -> ShipTable {
    let p = example_ship();
    let coefficients = [
        ("Xudot", p.x_udot),
        ("Yvdot", p.y_vdot),
        ("Yrdot", p.y_rdot),
        ("Nvdot", p.n_vdot),
        ("Nrdot", p.n_rdot),
        ("Xu", p.x_u),
        ("Xvv", p.x_vv),
        ("Yv", p.y_v),
        ("Yr", p.y_r),
        ("Yvvv", p.y_vvv),
        ("Yd", p.y_d),
        ("Nv", p.n_v),
        ("Nr", p.n_r),
        ("Nvvr", p.n_vvr),
        ("Nd", p.n_d),
    ];
    let given = GivenTable {
        units: Units::Dimensional,
        body: ShipBody {
            mass: p.mass,
            yaw_inertia: p.izz,
            yaw_inertia_about: YawInertia::AboutG,
            x_g: p.x_g,
        },
        density: None,
        length: None,
        design_speed: 6.0,
        rigid_body_terms: RigidBodyTerms::Separate,
        coefficients: coefficients
            .iter()
            .map(|(k, v)| ((*k).into(), *v))
            .collect(),
        propulsion: None,
    };
    ShipTable::new(&given).expect("a valid table")
}

/// Seconds for `CALLS` calls, each on a state nudged by the last rates.
fn time(rhs: impl Fn(&[f64; 7]) -> [f64; 7]) -> f64 {
    let mut state = [6.0, 0.4, -0.02, 10.0, -5.0, 0.3, 0.1];
    let clock = Instant::now();
    for _ in 0..CALLS {
        let rates = rhs(black_box(&state));
        for (x, r) in state.iter_mut().zip(rates) {
            *x += 1e-9 * r;
        }
    }
    black_box(state);
    clock.elapsed().as_secs_f64()
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

fn main() {
    let k = ship::Coefficients::<f64>::new(&example_ship());
    let evaluated = ShipModel::new(&table()).expect("the table builds");
    // The two agree before they are timed.
    let state = [6.0, 0.4, -0.02, 10.0, -5.0, 0.3, 0.1];
    let (a, b) = (k.rhs(&state, &[0.01]), evaluated.rhs(&state, &[0.01, 0.0]));
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() <= 1e-12 * x.abs().max(1e-9), "{x} vs {y}");
    }
    let (mut compiled, mut interpreted) = (vec![], vec![]);
    for _ in 0..7 {
        compiled.push(time(|y| k.rhs(y, &[0.01])));
        interpreted.push(time(|y| evaluated.rhs(y, &[0.01, 0.0])));
    }
    let (c, i) = (median(compiled), median(interpreted));
    let ns = |s: f64| s / CALLS as f64 * 1e9;
    println!(
        "ship, 10 terms: compiled {:.1} ns per call, evaluated {:.1} ns per call, ratio {:.2}",
        ns(c),
        ns(i),
        i / c
    );
    let driven = k.driven_by(Constant([0.0]));
    // The interpreted ship is a model too: the same driver, the same RK4.
    let closure = evaluated.driven_by(Constant([0.0, 0.0]));
    let (mut compiled, mut interpreted) = (vec![], vec![]);
    for _ in 0..7 {
        compiled.push(time_rk4(&driven));
        interpreted.push(time_rk4(&closure));
    }
    let (c, i) = (median(compiled), median(interpreted));
    println!(
        "ship, 10 terms, in RK4: compiled {c:.1} ns per evaluation, evaluated {i:.1} ns per \
         evaluation, ratio {:.2}",
        i / c
    );
}
