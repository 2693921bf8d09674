//! What a run cost, counted the same way for every method so they can be compared.

/// Counters of one integration run.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps (adaptive methods only).
    pub rejected: usize,
    /// Evaluations of the right-hand side (for [`LieMidpoint`](super::LieMidpoint): evaluations
    /// of Euler's equations inside the fixed-point iteration).
    pub rhs_evals: usize,
}
