//! `eom derive`: derive every equation afresh, prove it, and print the report.

use std::io::Write;
use std::time::Instant;

/// Options of `eom derive`.
#[derive(clap::Args)]
pub struct Args {
    /// Also print, on stderr, how long deriving and proving took.
    #[arg(long)]
    timing: bool,
}

/// Prints the derivation report as Markdown; fails if any equation is not proved.
pub fn run(args: Args) -> anyhow::Result<()> {
    let start = Instant::now();
    let equations = eom_codegen::derivation::all()?;
    let outcome = equations
        .iter()
        .try_for_each(eom_codegen::check::Equation::check);
    let elapsed = start.elapsed();
    let report = eom_codegen::report::markdown(&equations);
    std::io::stdout().lock().write_all(report.as_bytes())?;
    if args.timing {
        eprintln!(
            "derived and proved {} equations in {:.3} s",
            equations.len(),
            elapsed.as_secs_f64()
        );
    }
    outcome.map_err(Into::into)
}
