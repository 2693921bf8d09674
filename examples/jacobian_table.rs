//! The table of docs/linear.md: for every catalog model, the cost of one `rhs`, the entries
//! of ∂f/∂x and ∂f/∂u that the generator proved and emitted (of N² and N·M), the cost of the
//! emitted ∂f/∂x, and the time of one evaluation of both Jacobians, emitted and by dual
//! numbers (the median of 11 rounds of 20 000 evaluations; `cargo bench --bench jacobian`
//! measures the same calls with criterion). Then the same for the scene-defined models of
//! `scenes/mariner.toml` and `scenes/remus100.toml`, whose proved programs are interpreted:
//! their Jacobian programs against dual numbers through their interpreted `rhs`.
//!
//! ```sh
//! cargo run --release --example jacobian_table
//! ```

use eom::models::Model;
use eom_codegen::emit::{Operations, generate};
use eom_test_support::jacobian::{Sink, by_dual_numbers, each_model, emitted, point};
use num_dual::Dual64;
use std::hint::black_box;
use std::time::Instant;

const CALLS: u32 = 20_000;
const ROUNDS: usize = 11;

/// Nanoseconds per call of `f`, the median of [`ROUNDS`] rounds.
fn nanoseconds<R>(mut f: impl FnMut() -> R) -> f64 {
    let mut rounds: Vec<f64> = (0..ROUNDS)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..CALLS {
                black_box(f());
            }
            start.elapsed().as_secs_f64() * 1e9 / f64::from(CALLS)
        })
        .collect();
    rounds.sort_by(f64::total_cmp);
    rounds[ROUNDS / 2]
}

fn cost(o: &Operations) -> String {
    format!(
        "{} add, {} mul, {} div, {} trig",
        o.add, o.mul, o.div, o.trig
    )
}

struct Table;

impl Sink for Table {
    fn model<Mo, Md, const N: usize, const M: usize>(&mut self, name: &str, model: &Mo, dual: &Md)
    where
        Mo: Model<f64, N, M>,
        Md: Model<Dual64, N, M>,
    {
        let spec = eom_codegen::model::Model::all()
            .into_iter()
            .find(|m| m.name() == name)
            .expect("the catalog and the generator list the same models");
        let generated = generate(spec).expect("every catalog model generates");
        let (state, input) = point::<N, M>();
        let fast = nanoseconds(|| emitted(model, black_box(&state), black_box(&input)));
        let slow = nanoseconds(|| by_dual_numbers(dual, black_box(&state), black_box(&input)));
        println!(
            "| {name} | {} | {} of {} | {} of {} | {} | {fast:.0} | {slow:.0} | {:.1} |",
            cost(&generated.operations),
            generated.state_jacobian.len(),
            N * N,
            generated.input_jacobian.len(),
            N * M,
            cost(&generated.state_jacobian_operations),
            slow / fast
        );
    }
}

fn main() {
    println!(
        "| model | `rhs` | ∂f/∂x entries | ∂f/∂u entries | `state_jacobian` | emitted [ns] | dual \
         numbers [ns] | ratio |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    each_model(&mut Table);
    println!();
    println!(
        "| scene model (interpreted) | `rhs` | ∂f/∂x entries | ∂f/∂u entries | Jacobian \
         programs [ns] | dual numbers [ns] | ratio |"
    );
    println!("|---|---|---|---|---|---|---|");
    let mariner =
        eom::kinds::ship::ShipScene::load("scenes/mariner.toml".as_ref()).expect("the scene");
    let ship = eom::kinds::ship::ShipModel::new(&mariner.table).expect("the Mariner builds");
    let mut state = mariner.start();
    (state[1], state[2], state[6]) = (0.3, 0.004, 0.05);
    scene_row("mariner", &ship, ship.operations(), (&state, &[0.0; 3]));
    let remus = std::fs::read_to_string("scenes/remus100.toml").expect("the scene");
    let remus =
        eom::kinds::vehicle::VehicleScene::parse(&remus, "remus100.toml").expect("REMUS builds");
    let mut state = remus.start().expect("REMUS cruises");
    (state[1], state[2], state[4], state[13]) = (0.05, -0.02, 0.01, 0.03);
    let operations = remus.model.operations();
    scene_row("remus100", &remus.model, operations, (&state, &[0.0; 2]));
}

/// One scene-defined model's row: its Jacobian programs against dual numbers through `rhs`.
fn scene_row<Mo, const N: usize, const M: usize>(
    name: &str,
    model: &Mo,
    operations: Operations,
    (state, input): (&[f64; N], &[f64; M]),
) where
    Mo: Model<f64, N, M> + Model<Dual64, N, M>,
{
    let fast = nanoseconds(|| emitted::<Mo, N, M>(model, black_box(state), black_box(input)));
    let slow =
        nanoseconds(|| by_dual_numbers::<Mo, N, M>(model, black_box(state), black_box(input)));
    println!(
        "| {name} | {} | {} of {} | {} of {} | {fast:.0} | {slow:.0} | {:.1} |",
        cost(&operations),
        <Mo as Model<f64, N, M>>::STATE_JACOBIAN.len(),
        N * N,
        <Mo as Model<f64, N, M>>::INPUT_JACOBIAN.len(),
        N * M,
        slow / fast
    );
}
