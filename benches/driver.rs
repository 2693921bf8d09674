//! What the scene driver costs: a 10⁶-step RK4 run of the tennis racket with a trajectory
//! row every 1000 steps, written to CSV as `eom run` writes it, against the same integration
//! with no output and against the bare right-hand-side calls alone (4·10⁶ calls, each on the
//! state the last one left, as an integrator's stages are).
//!
//! `cargo bench --bench driver` prints the three times of each of five interleaved rounds and
//! the ratios of their medians.

use eom::Integrator;
use eom::integrate::Rk4;
use eom::kinds::body::{BodyScene, run};
use eom::models::{AnyModel, Model, Visitor};
use eom::output::trajectory::TrajectoryWriter;
use nalgebra::SVector;
use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

const STEPS: usize = 1_000_000;
const ROWS_EVERY: usize = 1000;

/// The default scene with RK4 over 10⁶ steps and a row every 1000 steps.
fn scene() -> BodyScene {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("scenes/tennis_racket.toml")).expect("the scene");
    let step = 20.0 / STEPS as f64;
    let text = text
        .replace("method = \"dop853\"", "method = \"rk4\"")
        .replace("rtol = 1e-10\n", "")
        .replace("atol = 1e-10\n", &format!("step = {step:e}\n"))
        .replace(
            "every = 0.01 ",
            &format!("every = {:e} ", step * ROWS_EVERY as f64),
        );
    BodyScene::parse(&text, "tennis_racket.toml", root).expect("a valid scene")
}

/// The scene through the driver, rows into a CSV file.
fn driver(scene: &BodyScene, out: &Path) -> f64 {
    let names = scene.state_names();
    let mut writer = TrajectoryWriter::create(out, &names, (false, "J"), STEPS / ROWS_EVERY + 1)
        .expect("a CSV file");
    let clock = Instant::now();
    let report = run(scene, &mut writer).expect("the run completes");
    writer.finish().expect("the CSV is written");
    assert_eq!(report.steps, STEPS);
    clock.elapsed().as_secs_f64()
}

/// The same RK4 integration of the same model under the same loads, no rows.
struct Bare<'a>(&'a BodyScene);

impl Visitor for Bare<'_> {
    type Output = (f64, f64);

    fn visit<Mo: Model<f64, N, M>, const N: usize, const M: usize>(self, model: &Mo) -> (f64, f64) {
        let scene = self.0;
        let y0 = SVector::<f64, N>::from_column_slice(&scene.initial);
        let system = model.driven_by(scene.loads.prepared());
        let clock = Instant::now();
        let end = Rk4::new(20.0 / STEPS as f64)
            .integrate(&system, 0.0, y0, 20.0)
            .expect("the run completes");
        black_box(end);
        let integrate = clock.elapsed().as_secs_f64();
        // 4·10⁶ calls, each on the state the last left (a small step along its rate).
        let input = [0.0; M];
        let mut y: [f64; N] = y0.data.0[0];
        let clock = Instant::now();
        for _ in 0..4 * STEPS {
            // The inputs opaque to the compiler, as a scene's are.
            let d = model.rhs(black_box(&y), black_box(&input));
            for (yi, di) in y.iter_mut().zip(d) {
                *yi += 5e-6 * di;
            }
        }
        black_box(y);
        (integrate, clock.elapsed().as_secs_f64())
    }
}

fn median(mut x: Vec<f64>) -> f64 {
    x.sort_by(f64::total_cmp);
    x[x.len() / 2]
}

fn main() {
    let scene = scene();
    let model: AnyModel = scene.model();
    let out = std::env::temp_dir().join("eom-driver-bench.csv");
    let (mut driven, mut plain, mut bare) = (Vec::new(), Vec::new(), Vec::new());
    println!("round | driver, CSV [s] | RK4 alone [s] | bare rhs calls [s]");
    for round in 0..5 {
        let d = driver(&scene, &out);
        let (p, b) = model.visit(Bare(&scene));
        println!("{round} | {d:.4} | {p:.4} | {b:.4}");
        driven.push(d);
        plain.push(p);
        bare.push(b);
    }
    let (d, p, b) = (median(driven), median(plain), median(bare));
    println!(
        "medians: driver {d:.4} s, RK4 alone {p:.4} s, bare rhs {b:.4} s; driver / bare = {:.3}, driver / RK4 alone = {:.3}",
        d / b,
        d / p
    );
    let _ = std::fs::remove_file(out);
}
