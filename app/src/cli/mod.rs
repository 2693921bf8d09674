//! The subcommands of `eom`, one module each; this file only lists and dispatches them.

mod derive;
mod eval;
mod linear;
mod mass;
mod merge;
mod models;
mod new;
mod record;
mod run;
mod serves;
mod sweep;
mod swing;
mod tradeoff;
mod uncertainty;
mod values;
mod view;

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
    /// Print a scene template of a family, every key commented with its unit, axes, default
    /// and whether it is required; it runs as printed.
    New(new::Args),
    /// Run a scene file: integrate it and write trajectory.csv, summary.json and SVG plots.
    Run(run::Args),
    /// Linearise a scene about the point its [linear] table names (A, B, the modes and a
    /// stability verdict, from the proved Jacobians): a catalog scene, by default at its initial
    /// state; a ship at its approach, with Nomoto's K, T₁, T₂, T₃, course stability and the
    /// pivot point beside; a vehicle at its cruise, through its table's Euler-angle twin.
    Linear(linear::Args),
    /// Merge the tables of a sweep's shards (`eom run --shard K/N`), once all are done, into
    /// one sweep.csv sorted by case; a Monte Carlo's into uncertainty.csv, with the statistics
    /// and plots one run writes.
    SweepMerge(merge::Args),
    /// Run a scene with every applicable integrator over steps and tolerances, and recommend
    /// the cheapest setting that meets a target error.
    Tradeoff(tradeoff::Args),
}

/// Runs one subcommand, or the default scene when there is none.
pub fn run(command: Option<Command>) -> anyhow::Result<()> {
    let Some(command) = command else {
        return run::run_default();
    };
    match command {
        Command::Derive(args) => derive::run(args),
        Command::Mass(args) => mass::run(args),
        Command::Models(args) => models::run(args),
        Command::Swing(args) => swing::run(args),
        Command::Eval(args) => eval::run(args),
        Command::New(args) => new::run(args),
        Command::Run(args) => run::run_command(args),
        Command::Tradeoff(args) => tradeoff::run(args),
        Command::Linear(args) => linear::run(args),
        Command::SweepMerge(args) => merge::run(args),
    }
}

/// The exit code of a failed command, by what failed (README lists them): 3 the scene file
/// (syntax, an unknown key, a wrong type, a missing key, a value out of range, an aircraft's
/// `[trim]` that cannot be flown or found: it is solved as the scene is read), 4 reading or
/// writing files (an output folder that another run holds, that holds a run, that eom did not write, that
/// is a system folder or that cannot be written included), 5
/// the run itself (gimbal lock, a step too long for the rate of turn, a state or a load that is
/// not finite, a step below the minimum, too many steps, `eom linear`'s `linear.trim` that does
/// not converge; cases
/// of a sweep or a Monte Carlo that failed, the others run), 128 + the signal for a run ended by
/// one (130 for Ctrl-C, 143 for SIGTERM), 1 anything else; 2 a usage error, clap's own or a
/// command used on what it does not serve (`--shard` without a `[sweep]`, a trajectory over
/// 100 MB without `--large-output`).
pub fn exit_code(error: &anyhow::Error) -> u8 {
    use eom::scene::{Problem, SceneError};
    for cause in error.chain() {
        if cause.downcast_ref::<run::Usage>().is_some() {
            return 2;
        }
        if cause.downcast_ref::<run::CasesFailed>().is_some() {
            return 5;
        }
        if let Some(interrupted) = cause.downcast_ref::<run::Interrupted>() {
            return u8::try_from(128 + interrupted.signal).unwrap_or(1);
        }
        if cause
            .downcast_ref::<eom::output::folder::FolderError>()
            .is_some()
            || cause.downcast_ref::<run::DefaultFolderTaken>().is_some()
        {
            return 4;
        }
        if let Some(scene) = cause.downcast_ref::<SceneError>() {
            return match scene.problem {
                Problem::Read(_) => 4,
                _ => 3,
            };
        }
        if cause.downcast_ref::<std::io::Error>().is_some() {
            return 4;
        }
        if let Some(linear) = cause.downcast_ref::<eom::linear::LinearError>() {
            return if linear.is_scene_error() { 3 } else { 5 };
        }
        if let Some(kind) = cause.downcast_ref::<eom::kinds::KindError>() {
            use eom::kinds::KindError;
            return match kind {
                KindError::Scene(_) => 3,
                KindError::Output(_) => 4,
                KindError::Run(_) => 5,
                KindError::Stopped(_) => 130,
                KindError::Internal(_) => 1,
            };
        }
    }
    1
}

#[cfg(test)]
mod tests {
    use super::exit_code;
    use eom::kinds::KindError;

    /// A run of any kind that cannot go on exits 5 (README's table); a value it refuses, 3;
    /// one stopped by Ctrl-C, 130; what it could not write, 4; a model not built, 1.
    #[test]
    fn every_kinds_errors_exit_by_what_failed() {
        let code = |class: fn(Box<dyn std::error::Error + Send + Sync>) -> KindError| {
            let error = class("why".into());
            exit_code(&anyhow::Error::new(error).context("the scene"))
        };
        assert_eq!(code(KindError::Scene), 3);
        assert_eq!(code(KindError::Output), 4);
        assert_eq!(code(KindError::Run), 5);
        assert_eq!(code(KindError::Stopped), 130);
        assert_eq!(code(KindError::Internal), 1);
    }
}
