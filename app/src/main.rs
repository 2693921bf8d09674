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
    #[cfg(unix)]
    // SAFETY: signal(2) with the default action, before any other thread exists; Rust's
    // runtime had set SIGPIPE to be ignored, which turns a closed pipe into a panic of print!.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    match cli::run(Cli::parse().command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {error:#}");
            ExitCode::from(cli::exit_code(&error))
        }
    }
}
