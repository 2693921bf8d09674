//! The `eom` command-line tool: one subcommand per job, each in `src/cli/`.

mod cli;

use clap::Parser;
use std::process::ExitCode;

/// Rigid-body equations of motion: derived, proved, emitted, integrated and measured.
#[derive(Parser)]
#[command(name = "eom", version, about)]
struct Cli {
    /// What to do; with none, run the default scene (the tennis-racket flip).
    #[command(subcommand)]
    command: Option<cli::Command>,
}

fn main() -> ExitCode {
    match cli::run(Cli::parse().command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {error:#}");
            ExitCode::from(cli::exit_code(&error))
        }
    }
}
