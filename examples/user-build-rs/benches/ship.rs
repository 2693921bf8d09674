//! Three ways to run a scene-defined table, timed against each other: this crate's ships
//! compiled by rustc from `build.rs`; the same tables as `eom` runs a scene's, compiled to
//! machine code when the scene is read (Cranelift, feature `jit`); and interpreted (`eom`'s
//! reference evaluator of the proved program). For the ten-term ship of `build.rs` and the
//! Mariner (39 terms, `scenes/mariner.toml`) all three, for REMUS (six degrees of freedom,
//! `scenes/remus100.toml`, no rustc form here) the last two: ns per right-hand-side call,
//! seven interleaved rounds of 10⁶ calls each (10⁵ for the interpreter), medians, each call on
//! the state the last left; the same inside `eom`'s RK4 for the ten-term ship; what compiling
//! each model costs; and how many outputs of the rustc and Cranelift forms differ in their
//! bits over 10⁵ random states (none in the default build, where both are op by op, and the
//! bench stops if one does; with `-C target-cpu=native` rustc's `mul_add`s are fused,
//! Cranelift's code is not).
//!
//! `cargo bench -p eom-example-user-build-rs`

use eom::integrate::{Integrator, Rk4, Statistics};
use eom::nalgebra::SVector;
use eom::scene::AnyScene;
use eom::ship::table::{GivenTable, ShipBody, ShipTable};
use eom::ship::{RigidBodyTerms, ShipModel, ShipScene, Units, YawInertia};
use eom::vehicle::VehicleModel;
use eom::{Constant, Model, OdeSystem};
use eom_codegen::model::ship::{ADDED_MASS, PRIME_SCALES, ShipSpec};
use eom_example_user_build_rs::{example_ship, mariner, ship};
use std::collections::BTreeMap;
use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

const CALLS: usize = 1_000_000;
const ROUNDS: usize = 7;

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

fn scene_path(file: &str) -> String {
    format!("{}/../../scenes/{file}", env!("CARGO_MANIFEST_DIR"))
}

/// The Mariner's table as `eom` reads its scene.
fn mariner_table() -> ShipTable {
    ShipScene::load(Path::new(&scene_path("mariner.toml")))
        .expect("the Mariner's scene reads")
        .table
}

/// Every parameter of `table` by its symbol, as `eom`'s ship model fills them.
fn symbols(table: &ShipTable) -> BTreeMap<String, f64> {
    let spec = ShipSpec {
        units: table.units,
        yaw_inertia: table.body.yaw_inertia_about,
        terms: table.terms.keys().copied().collect(),
        propulsion: false,
    };
    let body = [table.body.mass, table.body.yaw_inertia, table.body.x_g];
    let scales = [
        table.density.unwrap_or(f64::NAN),
        table.length.unwrap_or(f64::NAN),
        table.design_speed,
    ];
    (spec.body_symbols().into_iter().zip(body))
        .chain(ADDED_MASS.into_iter().zip(table.added_mass))
        .chain(PRIME_SCALES.into_iter().zip(scales))
        .map(|(symbol, value)| (symbol.to_owned(), value))
        .chain(table.terms.iter().map(|(t, v)| (t.symbol(), *v)))
        .collect()
}

fn remus() -> VehicleModel {
    let text = std::fs::read_to_string(scene_path("remus100.toml")).expect("REMUS's scene");
    match AnyScene::parse(&text, "remus100.toml", Path::new(".")) {
        Ok(AnyScene::Vehicle(scene)) => scene.model,
        _ => panic!("remus100.toml is read as a vehicle"),
    }
}

/// Seconds per call over `calls` calls, each on a state nudged by the last rates.
fn time<const N: usize>(start: [f64; N], calls: usize, rhs: impl Fn(&[f64; N]) -> [f64; N]) -> f64 {
    let mut state = start;
    let clock = Instant::now();
    for _ in 0..calls {
        let rates = rhs(black_box(&state));
        for (x, r) in state.iter_mut().zip(rates) {
            *x += 1e-9 * r;
        }
    }
    black_box(state);
    clock.elapsed().as_secs_f64() / calls as f64
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

/// The medians of `ROUNDS` interleaved rounds of each contender, in ns per call.
fn rounds(contenders: &[&dyn Fn() -> f64]) -> Vec<f64> {
    let mut times = vec![Vec::new(); contenders.len()];
    for _ in 0..ROUNDS {
        for (time, contender) in times.iter_mut().zip(contenders) {
            time.push(contender() * 1e9);
        }
    }
    times.into_iter().map(median).collect()
}

/// Median ms to compile `model`'s program, of `ROUNDS` compilations.
fn compile_ms<M>(compile: impl Fn() -> M) -> f64 {
    median(
        (0..ROUNDS)
            .map(|_| {
                let clock = Instant::now();
                black_box(compile());
                clock.elapsed().as_secs_f64() * 1e3
            })
            .collect(),
    )
}

/// A splitmix64 draw in [−bound, bound).
fn draw(seed: &mut u64, bound: f64) -> f64 {
    *seed = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *seed;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    bound * (2.0 * ((z >> 11) as f64 / (1u64 << 53) as f64) - 1.0)
}

/// Outputs of `a` and `b` whose bits differ, over 10⁵ random ship states.
fn differing_bits(
    a: impl Fn(&[f64; 7], f64) -> [f64; 7],
    b: impl Fn(&[f64; 7], f64) -> [f64; 7],
) -> usize {
    let mut seed = 1;
    let bounds = [12.0, 4.0, 0.1, 5000.0, 5000.0, 20.0, 0.8];
    (0..100_000)
        .map(|_| {
            let state = bounds.map(|b| draw(&mut seed, b));
            let rate = draw(&mut seed, 0.1);
            let (x, y) = (a(&state, rate), b(&state, rate));
            x.iter()
                .zip(&y)
                .filter(|(x, y)| x.to_bits() != y.to_bits())
                .count()
        })
        .sum()
}

fn print(name: &str, [rustc, jit, interpreted]: [Option<f64>; 3]) {
    let show = |x: Option<f64>| x.map_or("—".to_owned(), |x| format!("{x:.1}"));
    let ratio = |x: Option<f64>, y: Option<f64>| {
        x.zip(y)
            .map_or("—".to_owned(), |(x, y)| format!("{:.2}", x / y))
    };
    println!(
        "{name}: ns per call rustc {}, jit {}, interpreted {}; jit/rustc {}, interpreted/jit {}",
        show(rustc),
        show(jit),
        show(interpreted),
        ratio(jit, rustc),
        ratio(interpreted, jit),
    );
}

fn main() {
    let ship_start = [6.0, 0.4, -0.02, 10.0, -5.0, 0.3, 0.1];
    let k = ship::Coefficients::<f64>::new(&example_ship());
    let jit = ShipModel::new(&table()).expect("the table builds");
    assert!(jit.is_compiled(), "the ten-term table compiles");
    let interpreted = jit.interpreted();
    let differing = differing_bits(|s, d| k.rhs(s, &[d]), |s, d| jit.rhs(s, &[d, 0.0]));
    println!(
        "ship, 10 terms: rustc and jit outputs differing in their bits: {differing} of 700000"
    );
    let times = rounds(&[
        &|| time(ship_start, CALLS, |y| k.rhs(y, &[0.01])),
        &|| time(ship_start, CALLS, |y| jit.rhs(y, &[0.01, 0.0])),
        &|| time(ship_start, CALLS / 10, |y| interpreted.rhs(y, &[0.01, 0.0])),
    ]);
    print(
        "ship, 10 terms",
        [Some(times[0]), Some(times[1]), Some(times[2])],
    );
    // Each is a model: the same driver, the same RK4.
    let (driven, jit_driven) = (
        k.driven_by(Constant([0.0])),
        jit.driven_by(Constant([0.0, 0.0])),
    );
    let interpreted_driven = interpreted.driven_by(Constant([0.0, 0.0]));
    let times = rounds(&[
        &|| time_rk4(&driven) * 1e-9,
        &|| time_rk4(&jit_driven) * 1e-9,
        &|| time_rk4(&interpreted_driven) * 1e-9,
    ]);
    print(
        "ship, 10 terms, in RK4",
        [Some(times[0]), Some(times[1]), Some(times[2])],
    );

    let table = mariner_table();
    let values = symbols(&table);
    let m = mariner::Coefficients::<f64>::new(&mariner::Parameters::from_symbols(|s| {
        values.get(s).copied().unwrap_or(f64::NAN)
    }));
    // The prime system's forces scale with U, an input of the generated program that
    // `eom`'s model computes from the state: so here.
    let m_rhs = |s: &[f64; 7], d: f64| m.rhs(s, &[d, (s[0] * s[0] + s[1] * s[1]).sqrt()]);
    let jit = ShipModel::new(&table).expect("the Mariner builds");
    assert!(jit.is_compiled() && jit.terms() == 39);
    let interpreted = jit.interpreted();
    let differing = differing_bits(m_rhs, |s, d| jit.rhs(s, &[d, 0.0]));
    println!("Mariner: rustc and jit outputs differing in their bits: {differing} of 700000");
    assert!(cfg!(target_feature = "fma") || differing == 0);
    let mariner_start = [7.5, 0.3, -0.01, 10.0, -5.0, 0.3, 0.1];
    let times = rounds(&[
        &|| time(mariner_start, CALLS, |y| m_rhs(y, 0.01)),
        &|| time(mariner_start, CALLS, |y| jit.rhs(y, &[0.01, 0.0])),
        &|| {
            time(mariner_start, CALLS / 10, |y| {
                interpreted.rhs(y, &[0.01, 0.0])
            })
        },
    ]);
    print(
        "Mariner, 39 terms",
        [Some(times[0]), Some(times[1]), Some(times[2])],
    );
    let build = compile_ms(|| ShipModel::new(&table));
    let compile = compile_ms(|| interpreted.compiled());
    println!("Mariner: built and proved in {build:.1} ms, of which compiled in {compile:.2} ms");

    let vehicle = remus();
    assert!(vehicle.is_compiled(), "REMUS compiles");
    let vehicle_interpreted = vehicle.interpreted();
    let mut vehicle_start = [0.0; 15];
    vehicle_start[..6].copy_from_slice(&[1.5, 0.05, -0.03, 0.01, 0.02, -0.03]);
    vehicle_start[9] = 1.0;
    vehicle_start[13] = 0.05;
    let times = rounds(&[
        &|| time(vehicle_start, CALLS, |y| vehicle.rhs(y, &[0.01, -0.01])),
        &|| {
            time(vehicle_start, CALLS / 10, |y| {
                vehicle_interpreted.rhs(y, &[0.01, -0.01])
            })
        },
    ]);
    print(
        "REMUS, six degrees of freedom",
        [None, Some(times[0]), Some(times[1])],
    );
    let compile = compile_ms(|| vehicle_interpreted.compiled());
    println!("REMUS: compiled in {compile:.2} ms");
}
