//! What every run gives, whatever its kind: its rows ([`Row`]), taken one by one by a
//! [`Sink`] as the run goes (nothing is kept in memory), and, for a scene of many runs, the
//! [`record::Recorder`] told where each run begins and ends.
//!
//! How each kind runs is its own ([`crate::kinds`]); every run is a problem solved by the one
//! loop (`integrate::problem`). A kind that compares its integrators on its end state fills
//! the one [`tradeoff::Tradeoff`]; any kind whose runs give figures is compared on them by
//! [`figure_tradeoff`]. A Monte Carlo of any scene runs its cases and counts what they give in
//! [`uncertainty`].

pub mod figure_tradeoff;
pub mod record;
pub mod scene;
pub mod tradeoff;
pub mod uncertainty;

/// One trajectory row.
#[derive(Debug, Clone, Copy)]
pub struct Row<'a> {
    /// The time.
    pub t: f64,
    /// The state, in the model's layout.
    pub state: &'a [f64],
    /// The kinetic energy (4.32).
    pub kinetic_energy: f64,
    /// The potential energy of the model's own field and of the loads, where there is one.
    pub potential_energy: Option<f64>,
}

/// Where a run's rows go: a CSV file, a plot's columns, a test's assertions.
pub trait Sink {
    /// Takes one row; `false` stops the run (the sink keeps its own reason).
    fn row(&mut self, row: &Row) -> bool;
}
