//! The subcommands of `eom`, one module each; this file only lists and dispatches them.

mod derive;
mod eval;

use clap::Subcommand;

/// What `eom` can do.
#[derive(Subcommand)]
pub enum Command {
    /// Derive every equation of the chapter, prove it against the book, print the report.
    Derive(derive::Args),
    /// Evaluate one model's right-hand side at a state read from JSON (generic nalgebra form).
    Eval(eval::Args),
}

/// Runs one subcommand.
pub fn run(command: Command) -> anyhow::Result<()> {
    match command {
        Command::Derive(args) => derive::run(args),
        Command::Eval(args) => eval::run(args),
    }
}
