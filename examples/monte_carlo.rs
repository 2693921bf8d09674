//! A Monte Carlo of a scene from Rust: what `eom run` does with a scene's `[uncertainty]`
//! (docs/uncertainty.md), through the library, for a program that wants the cases' outcomes
//! themselves.
//!
//! ```sh
//! cargo run --release --example monte_carlo                 # scenes/mariner_uncertainty.toml
//! cargo run --release --example monte_carlo -- scenes/mariner_turning_uncertainty.toml 1000
//! ```
//!
//! The scene's `[uncertainty]` ([`Uncertainty`]) says which numbers vary, by which laws, how
//! many cases and the seed; case k draws its values from its own stream, so a case is the
//! same on any number of threads. [`run_cases`] runs the cases on every core (a ship's model
//! derived and proved once, each case's coefficients taken into it), each to its figures and
//! verdicts ([`CaseOutcome`]); [`Statistics`] counts them: each figure's mean, standard
//! deviation and percentiles, each verdict's pass rate with its 95 % Wilson interval. Here
//! the outcomes are also used directly: the cases whose tactical diameter is the largest.

use eom::run::uncertainty::{CaseOutcome, PERCENTILES, Statistics, run_cases};
use eom::scene::uncertainty::Uncertainty;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

fn main() -> ExitCode {
    let mut args = std::env::args().skip(1);
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let path = (args.next().map(PathBuf::from))
        .unwrap_or_else(|| root.join("scenes/mariner_uncertainty.toml"));
    let cases: Option<usize> = match args.next().map(|n| n.parse()) {
        Some(Ok(cases)) => Some(cases),
        Some(Err(_)) => {
            eprintln!("usage: monte_carlo [SCENE] [CASES]");
            return ExitCode::from(2);
        }
        None => None,
    };
    let name = path.display().to_string();
    let uncertainty = match std::fs::read_to_string(&path)
        .map_err(|e| e.to_string())
        .and_then(|text| Uncertainty::parse(&text, &name).map_err(|e| e.to_string()))
    {
        Ok(uncertainty) => uncertainty,
        Err(error) => {
            eprintln!("{name}: {error}");
            return ExitCode::FAILURE;
        }
    };
    let indices: Vec<usize> = (0..cases.unwrap_or(uncertainty.cases)).collect();
    let base = path.parent().unwrap_or(Path::new("."));
    let clock = Instant::now();
    let outcomes = run_cases(&uncertainty, &indices, (&name, base), &|| false);
    let seconds = clock.elapsed().as_secs_f64();
    print!("{}", Statistics::of(&outcomes, &PERCENTILES).report());
    println!(
        "{} cases in {seconds:.2} s on {} threads",
        outcomes.len(),
        rayon::current_num_threads()
    );
    // The outcomes themselves: the three widest turns, with the values that made them.
    let diameter = |o: &CaseOutcome| {
        (o.figures.iter())
            .filter(|(name, _)| name.ends_with("tactical_diameter_m"))
            .filter_map(|(_, value)| *value)
            .fold(f64::NAN, f64::max)
    };
    let mut widest: Vec<&CaseOutcome> = outcomes.iter().filter(|o| diameter(o) > 0.0).collect();
    widest.sort_by(|a, b| diameter(b).total_cmp(&diameter(a)));
    for outcome in widest.iter().take(3) {
        let (at, _) = (uncertainty.varied.iter().zip(&outcome.values))
            .enumerate()
            .map(|(at, (number, value))| (at, (value / number.nominal - 1.0).abs()))
            .filter(|(_, change)| change.is_finite())
            .fold(
                (0, 0.0),
                |best, next| if next.1 > best.1 { next } else { best },
            );
        println!(
            "case {}: tactical diameter {:.1} m; its largest change, {} = {:.4e} (scene {:.4e})",
            outcome.index,
            diameter(outcome),
            uncertainty.varied[at].key,
            outcome.values[at],
            uncertainty.varied[at].nominal
        );
    }
    ExitCode::SUCCESS
}
