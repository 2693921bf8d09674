//! The IMO manoeuvring criteria of the Mariner over the uncertainty of its coefficients: a
//! Monte Carlo of turning circles and zig-zags, every hydrodynamic coefficient perturbed.
//!
//! ```sh
//! cargo run --release --example monte_carlo                         # 10⁴ cases, every core
//! cargo run --release --example monte_carlo -- --turning-only       # the turning circles alone
//! cargo run --release --example monte_carlo -- --cases 1000 --seed 7 --shard 0/2
//! cargo run --release --example monte_carlo -- --scene my_mariner.toml   # another method, say
//! ```
//!
//! **The cases.** Case k draws, from its own stream (splitmix64 seeded by the seed and k, so a
//! case is the same in any shard, on any number of threads), one factor per hydrodynamic
//! coefficient of the table eom reads from `scenes/mariner.toml`: the 39 terms of the force
//! polynomial (the rigid-body terms the published table folds in taken out first) and the 5
//! added masses. Each factor is 1 + σz, σ = 0.10, z standard normal truncated to |z| ≤ 3
//! (redrawn beyond), so no coefficient changes sign. The body, U₀, the rudder and the
//! manoeuvres are the scene's.
//!
//! **A case** runs the scene's turning circle and its two zig-zags (10°/10°, 20°/20°), each to
//! port and to starboard, with the scene's method (DOPRI5 at 1e-6, what `eom tradeoff`
//! recommends for it; `--scene` reads another copy of the Mariner), and judges the IMO
//! criteria (MSC.137(76)) on them as `eom run` does: the worse side decides. The model of a
//! case is the scene's model with the case's values ([`ShipModel::with_table`]): 4.46 is
//! derived, proved and compiled once, not per case, since that takes about ten times as long
//! as a turning circle.
//!
//! **The report.** Per criterion, the share of cases that pass with its 95 % Wilson score
//! interval (p̂ and n as counted, z = 1.96: it stays inside [0, 1] and keeps its coverage
//! near 0 and 1, where the Mariner's criteria are); the cases whose figure could not be read
//! are counted apart. Then cases per second on every core (rayon), and turning circles per
//! second. `--shard K/N` runs the cases k ≡ K (mod N) only, for one process of N; each
//! prints its counts (`counts:`), which add up over the shards to the whole run's.

use eom::kinds::ship::imo::{Trial, criteria};
use eom::kinds::ship::manoeuvre::{Figures, Manoeuvre, ManoeuvreKind, run};
use eom::kinds::ship::{ShipModel, ShipScene, Side};
use eom::scene::sweep::parse_shard;
use eom_test_support::random::Random;
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

/// The relative standard deviation of every coefficient.
const SIGMA: f64 = 0.10;
/// Where the normal draws are truncated, in standard deviations.
const TRUNCATION: f64 = 3.0;

/// The command line.
struct Args {
    scene: Option<std::path::PathBuf>,
    cases: usize,
    seed: u64,
    shard: (usize, usize),
    turning_only: bool,
}

fn parse_args() -> Result<Args, String> {
    let mut args = Args {
        scene: None,
        cases: 10_000,
        seed: 2026,
        shard: (0, 1),
        turning_only: false,
    };
    let mut words = std::env::args().skip(1);
    while let Some(word) = words.next() {
        let mut value = |name: &str| words.next().ok_or(format!("{name} needs a value"));
        match word.as_str() {
            "--cases" => {
                let text = value("--cases")?;
                args.cases = text.parse().map_err(|_| format!("--cases {text}"))?;
            }
            "--seed" => {
                let text = value("--seed")?;
                args.seed = text.parse().map_err(|_| format!("--seed {text}"))?;
            }
            "--shard" => args.shard = parse_shard(&value("--shard")?)?,
            "--turning-only" => args.turning_only = true,
            "--scene" => args.scene = Some(value("--scene")?.into()),
            other => return Err(format!("unknown argument `{other}`")),
        }
    }
    Ok(args)
}

/// A standard normal draw within ±`TRUNCATION` (Box–Muller, redrawn beyond).
fn normal(random: &mut Random) -> f64 {
    loop {
        let (a, b) = (random.unit(), random.unit());
        let z = (-2.0 * (1.0 - a).ln()).sqrt() * (std::f64::consts::TAU * b).cos();
        if z.abs() <= TRUNCATION {
            return z;
        }
    }
}

/// What one case gave: each criterion's verdict (None: not judged), and how many turning
/// circles it ran; or why it failed.
type Outcome = Result<(Vec<(String, Option<bool>)>, usize), String>;

/// Case `k`: the table perturbed, the manoeuvres run to both sides, the criteria judged.
fn case(
    scene: &ShipScene,
    base: &ShipModel,
    manoeuvres: &[&Manoeuvre],
    seed: u64,
    k: usize,
) -> Outcome {
    let mut random = Random(seed ^ (k as u64).wrapping_mul(0xD1B5_4A32_D192_ED03));
    let mut table = scene.table.clone();
    for value in table.terms.values_mut().chain(table.added_mass.iter_mut()) {
        *value *= 1.0 + SIGMA * normal(&mut random);
    }
    let model = base.with_table(&table).map_err(|e| e.to_string())?;
    let mut runs: Vec<Vec<(Option<Side>, Figures)>> = Vec::new();
    let mut turning = 0;
    for manoeuvre in manoeuvres {
        let mut sides = Vec::new();
        for (side, one) in manoeuvre.runs() {
            let settings = (&scene.stepper, scene.every);
            let done = run(&model, &scene.rudder, &one, scene.start(), settings, |_| {
                true
            })
            .map_err(|e| format!("{}: {e}", manoeuvre.name))?;
            turning += usize::from(matches!(one.kind, ManoeuvreKind::TurningCircle { .. }));
            sides.push((side, done.figures));
        }
        runs.push(sides);
    }
    let trials: Vec<Trial> = (manoeuvres.iter().zip(&runs))
        .map(|(m, sides)| (*m, sides.iter().map(|(s, f)| (*s, f)).collect()))
        .collect();
    let judged = criteria(scene, &trials);
    let verdicts = judged
        .iter()
        .map(|c| (c.name.to_string(), c.pass()))
        .collect();
    Ok((verdicts, turning))
}

/// The 95 % Wilson score interval of `passes` in `n`.
fn wilson(passes: usize, n: usize) -> (f64, f64) {
    if n == 0 {
        return (f64::NAN, f64::NAN);
    }
    let (z, n_f) = (1.96_f64, n as f64);
    let p = passes as f64 / n_f;
    let centre = p + z * z / (2.0 * n_f);
    let spread = z * (p * (1.0 - p) / n_f + z * z / (4.0 * n_f * n_f)).sqrt();
    let scale = 1.0 + z * z / n_f;
    ((centre - spread) / scale, (centre + spread) / scale)
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(args) => args,
        Err(message) => {
            eprintln!(
                "{message}\nusage: monte_carlo [--cases N] [--seed S] [--shard K/N] [--turning-only]"
            );
            return ExitCode::from(2);
        }
    };
    let path = (args.scene.clone())
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/mariner.toml"));
    let scene = match ShipScene::load(&path) {
        Ok(scene) => scene,
        Err(error) => {
            eprintln!("{}: {error}", path.display());
            return ExitCode::FAILURE;
        }
    };
    let clock = Instant::now();
    let base = match ShipModel::new(&scene.table) {
        Ok(model) => model,
        Err(error) => {
            eprintln!("the Mariner's model: {error}");
            return ExitCode::FAILURE;
        }
    };
    let built = clock.elapsed().as_secs_f64();
    let clock = Instant::now();
    let mut table = scene.table.clone();
    table.terms.values_mut().for_each(|v| *v *= 1.01);
    let reparameterised = (0..100).filter(|_| base.with_table(&table).is_ok()).count();
    let with_table = clock.elapsed().as_secs_f64() / reparameterised.max(1) as f64;
    let manoeuvres: Vec<&Manoeuvre> = (scene.manoeuvres.iter())
        .filter(|m| match m.kind {
            ManoeuvreKind::TurningCircle { .. } => true,
            ManoeuvreKind::ZigZag { .. } => !args.turning_only,
            _ => false,
        })
        .collect();
    let (k, n) = args.shard;
    let cases: Vec<usize> = (0..args.cases).filter(|i| i % n == k).collect();
    println!(
        "Mariner Monte Carlo: {} cases of {} (shard {k}/{n}), seed {}, every coefficient × (1 + {SIGMA}·z), z ~ N(0, 1) within ±{TRUNCATION}",
        cases.len(),
        args.cases,
        args.seed
    );
    println!(
        "  model derived, proved and compiled once in {:.1} ms; each case's values in {:.1} µs \
         (ShipModel::with_table); compiled: {}",
        built * 1e3,
        with_table * 1e6,
        base.is_compiled()
    );
    let clock = Instant::now();
    let outcomes: Vec<Outcome> = cases
        .par_iter()
        .map(|&i| case(&scene, &base, &manoeuvres, args.seed, i))
        .collect();
    let seconds = clock.elapsed().as_secs_f64();
    report(&outcomes, seconds, &manoeuvres);
    ExitCode::SUCCESS
}

/// The pass rates with their intervals, the failures, and the throughput.
fn report(outcomes: &[Outcome], seconds: f64, manoeuvres: &[&Manoeuvre]) {
    // criterion → (passes, fails, not judged), in the order the criteria are listed.
    let mut counts: Vec<(String, [usize; 3])> = Vec::new();
    let mut failures: BTreeMap<String, usize> = BTreeMap::new();
    let mut turning = 0;
    for outcome in outcomes {
        match outcome {
            Ok((verdicts, circles)) => {
                turning += circles;
                for (name, verdict) in verdicts {
                    let at = match counts.iter().position(|(n, _)| n == name) {
                        Some(at) => at,
                        None => {
                            counts.push((name.clone(), [0; 3]));
                            counts.len() - 1
                        }
                    };
                    counts[at].1[match verdict {
                        Some(true) => 0,
                        Some(false) => 1,
                        None => 2,
                    }] += 1;
                }
            }
            Err(reason) => *failures.entry(reason.clone()).or_default() += 1,
        }
    }
    println!(
        "  {:<24} {:>8} {:>8} {:>10} {:>20}",
        "criterion", "judged", "pass", "rate", "95% Wilson interval"
    );
    for (name, [pass, fail, unjudged]) in &counts {
        let judged = pass + fail;
        let note = if *unjudged > 0 {
            format!("  ({unjudged} not judged)")
        } else {
            String::new()
        };
        if judged == 0 {
            println!(
                "  {name:<24} {judged:>8} {pass:>8} {:>10}   {:>16}{note}",
                "—", "—"
            );
            continue;
        }
        let (lo, hi) = wilson(*pass, judged);
        let rate = *pass as f64 / judged as f64;
        println!("  {name:<24} {judged:>8} {pass:>8} {rate:>10.4}   [{lo:.4}, {hi:.4}]{note}");
    }
    for (reason, count) in &failures {
        println!("  {count} cases failed: {reason}");
    }
    let shown: Vec<String> = counts
        .iter()
        .map(|(name, [p, f, u])| format!("{name}={p}/{}/{u}", p + f))
        .collect();
    println!("  counts: {} (pass/judged/not judged)", shown.join(" "));
    let names: Vec<&str> = manoeuvres.iter().map(|m| m.name.as_str()).collect();
    println!(
        "  {} cases ({}, each to both sides) in {seconds:.2} s on {} threads: {:.0} cases/s, {:.0} turning circles/s",
        outcomes.len(),
        names.join(", "),
        rayon::current_num_threads(),
        outcomes.len() as f64 / seconds,
        turning as f64 / seconds,
    );
}
