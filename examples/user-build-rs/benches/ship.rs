//! The ship of `build.rs`, compiled, against the same table run by `eom`'s evaluator of the
//! proved program (what `eom run` does with a scene's table): ns per right-hand-side call,
//! seven interleaved rounds of 10⁶ calls each, medians, each call on the state the last left.
//!
//! `cargo bench -p eom-example-user-build-rs`

use eom::Model;
use eom::ship::table::{GivenTable, ShipBody, ShipTable};
use eom::ship::{RigidBodyTerms, ShipModel, Units, YawInertia};
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

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let k = ship::Coefficients::<f64>::new(&example_ship());
    let evaluated = ShipModel::new(&table()).expect("the table builds");
    // The two agree before they are timed.
    let state = [6.0, 0.4, -0.02, 10.0, -5.0, 0.3, 0.1];
    let (a, b) = (
        ship::rhs(&k, &state, &[0.01]),
        evaluated.rhs(&state, &[0.01]),
    );
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() <= 1e-12 * x.abs().max(1e-9), "{x} vs {y}");
    }
    let (mut compiled, mut interpreted) = (vec![], vec![]);
    for _ in 0..7 {
        compiled.push(time(|y| ship::rhs(&k, y, &[0.01])));
        interpreted.push(time(|y| evaluated.rhs(y, &[0.01])));
    }
    let (c, i) = (median(compiled), median(interpreted));
    let ns = |s: f64| s / CALLS as f64 * 1e9;
    println!(
        "ship, 10 terms: compiled {:.1} ns per call, evaluated {:.1} ns per call, ratio {:.2}",
        ns(c),
        ns(i),
        i / c
    );
}
