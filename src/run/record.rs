//! Where the runs of a scene put their rows: a [`Recorder`] is told when each run begins (its
//! path under the output, its columns) and ends, and takes its rows between. The command's
//! recorder writes each run's `trajectory.csv` and keeps its columns for the plots; a library
//! user's may keep them in memory, or drop them ([`Discard`]).
//!
//! A scene of many runs (a ship's manoeuvres, each to both sides) runs them in order through
//! one recorder, so that what a run writes, and whether it may go on, is the caller's and not
//! the kind's.

use super::Row;
use crate::output::drawing::RunDrawings;

/// Why a recorder could not keep what it was given: a file not written, a plot not drawn.
pub type RecordError = Box<dyn std::error::Error + Send + Sync>;

/// A run as it begins: where its rows go, what they hold, and how long it runs.
#[derive(Debug, Clone, Copy)]
pub struct RunStart<'a> {
    /// Its path under the output (`turning_circle_35/port`).
    pub path: &'a str,
    /// The state columns of each row, after the time.
    pub columns: &'a [String],
    /// About how many rows it gives.
    pub expected_rows: usize,
    /// The time it runs to, s (a progress bar's end).
    pub end_time: f64,
    /// Whether its rows carry a potential energy ([`Row::potential_energy`]): the trajectory
    /// then has the potential and total energy columns after the kinetic.
    pub potential: bool,
    /// The energies' unit: `J`, or the scene's own (an aircraft in feet: `ft lbf`).
    pub energy_unit: &'a str,
}

/// What a scene's runs hand their rows to, run after run.
pub trait Recorder {
    /// A run begins: its rows go under its path, each with the time then its columns.
    fn begin(&mut self, run: RunStart) -> Result<(), RecordError>;

    /// Takes one row of the run begun last; `false` ends the run (the recorder keeps its own
    /// reason: a write that failed, a signal).
    fn row(&mut self, row: &Row) -> bool;

    /// The run begun last has given its last row: everything it gave is kept.
    fn end(&mut self) -> Result<(), RecordError>;

    /// What the plots and the view of a run that ended draw, once its figures are known
    /// (its marks, its title): the command draws them from the rows it kept.
    fn drawn(&mut self, drawings: RunDrawings) -> Result<(), RecordError>;

    /// Whether the caller asked the runs to stop (Ctrl-C): a run checks it between rows it
    /// does not record (a refined run) and before it begins.
    fn stop_asked(&self) -> bool;

    /// Whether each run is run again refined, for how far its figures move (the summary's
    /// differences). A Monte Carlo's cases are not: what it reads is their spread, and the
    /// refined run would cost more than the case; their figures then give no difference.
    fn refines(&self) -> bool {
        true
    }

    /// Whether it keeps the rows it is given: a run whose recorder does not (a Monte Carlo's
    /// case, [`Discard`]) need not build them, and reads its figures alone.
    fn keeps_rows(&self) -> bool {
        true
    }
}

/// A recorder that keeps nothing and never asks to stop: for a library user who wants a
/// scene's figures alone.
#[derive(Debug, Default, Clone, Copy)]
pub struct Discard;

impl Recorder for Discard {
    fn begin(&mut self, _: RunStart) -> Result<(), RecordError> {
        Ok(())
    }

    fn row(&mut self, _: &Row) -> bool {
        true
    }

    fn end(&mut self) -> Result<(), RecordError> {
        Ok(())
    }

    fn drawn(&mut self, _: RunDrawings) -> Result<(), RecordError> {
        Ok(())
    }

    fn stop_asked(&self) -> bool {
        false
    }

    fn keeps_rows(&self) -> bool {
        false
    }
}
