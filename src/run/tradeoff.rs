//! What each integration choice costs for one scene: every applicable method over a sweep of
//! steps or tolerances, each end state judged against a reference, and the cheapest setting
//! that meets a target error. A kind that compares its integrators so
//! ([`crate::kinds::Kind::tradeoff`]) fills a [`Tradeoff`]; what it recommends is decided
//! here, once.
//!
//! The reference is the exact solution where the scene has one (a pendulum released from
//! rest with no other load: Jacobi's elliptic functions), else DOP853 at rtol = atol =
//! 1e-13. The error of a run is the largest difference of a state
//! entry at the end time, relative to the largest entry of the reference state (at least 1):
//! `max |yᵢ − yᵢ,ref| / max(1, max |yᵢ,ref|)`. Cost is wall time, the best of
//! [`REPEATS`] runs (a shared machine's noise is one-sided), with the right-hand-side
//! evaluations beside it.
//!
//! A setting is recommended only where the errors converge ([`Tradeoff::recommend`]): every
//! tighter setting of its method meets the target too, and the reference repeats itself to
//! the target (DOP853 at rtol 1e-11 and 1e-12 end within it of the reference at 1e-13). A
//! motion that amplifies round-off (chaos, a spin started exactly about the intermediate
//! axis) fails the second test: its errors grow as the step shrinks (RK4 4.9e-7, then 3.2e-2,
//! then 2.00), and a setting that happens to land near the reference is no setting to trust.

/// How many times each setting runs; its time is the fastest.
pub const REPEATS: usize = 3;

/// The tolerances the adaptive methods are swept over.
pub const TOLERANCES: [f64; 10] = [
    1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12,
];

/// The step counts the fixed-step methods are swept over (steps over the whole run).
pub const STEP_COUNTS: [usize; 9] = [
    100, 300, 1_000, 3_000, 10_000, 30_000, 100_000, 300_000, 1_000_000,
];

/// One setting's outcome.
#[derive(Debug, Clone, PartialEq)]
pub struct TradeoffRow {
    /// The method's name in scene files.
    pub method: &'static str,
    /// The setting, `step = 0.001` or `rtol = atol = 1e-8`.
    pub setting: String,
    /// The end-state error (see the module doc); `None` when the run failed.
    pub error: Option<f64>,
    /// Right-hand-side evaluations.
    pub rhs_evals: usize,
    /// Wall time, s (best of [`REPEATS`]).
    pub seconds: f64,
    /// Why the run failed, if it did.
    pub failure: Option<String>,
}

/// The whole sweep.
#[derive(Debug, Clone)]
pub struct Tradeoff {
    /// What each setting runs, in words: the model, to the time it runs to
    /// (`pendulum to t = 20 s`).
    pub run: String,
    /// What the errors are measured against.
    pub reference: String,
    /// Every setting, method by method.
    pub rows: Vec<TradeoffRow>,
}

/// What the sweep recommends for a target error.
#[derive(Debug, Clone, PartialEq)]
pub enum Recommendation<'a> {
    /// The fastest setting whose error, and that of every tighter setting of its method, is at
    /// most the target.
    Setting(&'a TradeoffRow),
    /// Settings meet the target, but the errors do not converge, so none is recommended; why.
    NotConverged(String),
    /// No setting meets the target.
    NoneMeets,
}

impl Recommendation<'_> {
    /// The recommended setting, if there is one.
    pub fn setting(&self) -> Option<&TradeoffRow> {
        match self {
            Recommendation::Setting(row) => Some(row),
            _ => None,
        }
    }
}

/// How far past the target a tighter setting's error must land, after a coarser one met it,
/// for the errors to count as diverging rather than levelling off at round-off (which moves an
/// error by a small factor, not by orders of magnitude).
const DIVERGED: f64 = 100.0;

/// The tolerances of the DOP853 rows whose spread from the reference tells whether the
/// reference repeats itself.
const REFERENCE_CHECKS: [f64; 2] = [1e-11, 1e-12];

impl Tradeoff {
    /// The fastest setting that meets `target` where the errors converge (see the module
    /// docs), or why there is none.
    pub fn recommend(&self, target: f64) -> Recommendation<'_> {
        let meets = |row: &TradeoffRow| row.error.is_some_and(|e| e <= target);
        if !self.rows.iter().any(meets) {
            return Recommendation::NoneMeets;
        }
        if let Some(spread) = self.reference_spread()
            && spread > target
        {
            return Recommendation::NotConverged(format!(
                "the reference does not repeat itself to {target:e}: DOP853 at rtol 1e-11 and \
                 1e-12 ends up to {spread:.2e} from it at 1e-13, so the motion amplifies \
                 round-off (chaos, or a start on an unstable equilibrium such as a spin about \
                 the intermediate axis) and no setting's error can be told"
            ));
        }
        if let Some(why) = self.diverging(target) {
            return Recommendation::NotConverged(why);
        }
        let converged = |index: usize| {
            let row = &self.rows[index];
            // A tighter run that failed (too many steps) says nothing of convergence.
            let mut tighter =
                (self.rows[index..].iter()).filter(|r| r.method == row.method && r.error.is_some());
            tighter.all(meets)
        };
        let best = (0..self.rows.len())
            .filter(|&i| converged(i))
            .map(|i| &self.rows[i])
            .min_by(|a, b| a.seconds.total_cmp(&b.seconds));
        match best {
            Some(row) => Recommendation::Setting(row),
            None => Recommendation::NotConverged(self.growing_errors(target)),
        }
    }

    /// The largest end-state difference of DOP853 at rtol 1e-11 and 1e-12 from the reference;
    /// `None` for an exact reference, or where those runs failed.
    pub fn reference_spread(&self) -> Option<f64> {
        if !self.reference.starts_with("DOP853") {
            return None;
        }
        let checks: Vec<f64> = REFERENCE_CHECKS
            .iter()
            .filter_map(|tol| {
                let setting = format!("rtol = atol = {tol:e}");
                let row = (self.rows.iter()).find(|r| r.method == "dop853" && r.setting == setting);
                row?.error
            })
            .collect();
        (checks.len() == REFERENCE_CHECKS.len()).then(|| checks.into_iter().fold(0.0, f64::max))
    }

    /// Where a method meets the target and a tighter setting of it lands more than
    /// [`DIVERGED`] times the target away: its errors diverge as the step shrinks, not level
    /// off at round-off, so the reference itself is in doubt.
    fn diverging(&self, target: f64) -> Option<String> {
        let diverged = self.rows.iter().enumerate().find_map(|(index, row)| {
            let met = row.error.filter(|e| *e <= target)?;
            let later = (self.rows[index..].iter()).find(|r| {
                r.method == row.method && r.error.is_some_and(|e| e > DIVERGED * target)
            })?;
            Some((row, met, later))
        })?;
        let (row, met, later) = diverged;
        Some(format!(
            "the errors grow as the setting tightens ({} meets it at {} with {met:.2e}, then is \
             {:.2e} at {}): the motion amplifies round-off (chaos, or a start on an unstable \
             equilibrium such as a spin about the intermediate axis), so the reference is no \
             truer than any setting",
            row.method,
            row.setting,
            later.error.unwrap_or(f64::NAN),
            later.setting
        ))
    }

    /// Says where a method's error grows again past the target after meeting it.
    fn growing_errors(&self, target: f64) -> String {
        let mut said = Vec::new();
        for (index, row) in self.rows.iter().enumerate() {
            let Some(error) = row.error.filter(|e| *e <= target) else {
                continue;
            };
            let later = (self.rows[index..].iter())
                .find(|r| r.method == row.method && r.error.is_some_and(|e| e > target));
            if let Some(later) = later {
                let worse = later.error.unwrap_or(f64::NAN);
                said.push(format!(
                    "{} meets it at {} ({error:.2e}) but not at the tighter {} ({worse:.2e})",
                    row.method, row.setting, later.setting
                ));
                break;
            }
        }
        format!(
            "the errors do not converge as the setting tightens: {}",
            said.join("; ")
        )
    }
}
