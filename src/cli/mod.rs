//! The subcommands of `eom`, one module each; this file only lists and dispatches them.

mod derive;
mod eval;
mod mass;
mod models;
mod swing;
mod values;

use clap::Subcommand;

/// What `eom` can do.
#[derive(Subcommand)]
pub enum Command {
    /// Derive every equation of the chapter, prove it against the book, print the report.
    Derive(derive::Args),
    /// List every generated model variant with its operation count per call.
    Models(models::Args),
    /// Mass, centre of gravity, inertia tensor, principal axes and radii of gyration of a body
    /// described in a TOML file (4.12–4.23).
    Mass(mass::Args),
    /// The swing test: radius of gyration from a measured pendulum period (4.24–4.29), with
    /// the correction for a finite amplitude.
    Swing(swing::Args),
    /// Evaluate one model's right-hand side at a state read from JSON (generic nalgebra form).
    Eval(eval::Args),
}

/// Runs one subcommand.
pub fn run(command: Command) -> anyhow::Result<()> {
    match command {
        Command::Derive(args) => derive::run(args),
        Command::Mass(args) => mass::run(args),
        Command::Models(args) => models::run(args),
        Command::Swing(args) => swing::run(args),
        Command::Eval(args) => eval::run(args),
    }
}
