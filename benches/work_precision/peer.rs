//! The peer: the `ode_solvers` crate's Dopri5 and Dop853 on the same right-hand side and
//! tolerances. It brings its own nalgebra (0.34), so states are copied across at the boundary
//! (a copy of N numbers per evaluation, small against an evaluation of these models). Its
//! dense output at the end time is unreliable, so the end state is taken from its sparse
//! output (one entry per accepted step), and its settings are Hairer's defaults, as ours.
//! Each of its runs is timed alternately with the same run of ours, so that the ratio of the
//! two times is not disturbed by a change of load on the machine between them.

use eom::integrate::{AdaptiveOptions, Dop853, Dopri5, Integrator, OdeSystem, Stats};
use nalgebra::SVector;
use ode_solvers::{OutputType, System};

use super::sweep::{Case, MAX_STEPS, RTOLS, Row, Setting, options, row_of, timed_pair};

/// A system of this crate seen through the peer's trait.
struct Peer<'a, S>(&'a S);

impl<S: OdeSystem<f64, N>, const N: usize> System<f64, ode_solvers::SVector<f64, N>>
    for Peer<'_, S>
{
    fn system(
        &self,
        t: f64,
        y: &ode_solvers::SVector<f64, N>,
        dy: &mut ode_solvers::SVector<f64, N>,
    ) {
        let y = SVector::<f64, N>::from_column_slice(y.as_slice());
        let mut d = SVector::<f64, N>::zeros();
        self.0.rhs(t, &y, &mut d);
        dy.copy_from_slice(d.as_slice());
    }
}

/// The peer's statistics in ours.
fn stats_of(s: &ode_solvers::dop_shared::Stats) -> Stats {
    let (steps, rejected) = (s.accepted_steps as usize, s.rejected_steps as usize);
    Stats {
        steps,
        rejected,
        rhs_evals: s.num_eval as usize,
    }
}

/// The outcome of one peer run: its end state (from the sparse output) and its statistics.
type Outcome<const N: usize> = (Result<SVector<f64, N>, String>, Stats);

/// The end state of a peer run from its sparse output and the result of `integrate`.
fn outcome<const N: usize>(
    result: Result<ode_solvers::dop_shared::Stats, ode_solvers::dop_shared::IntegrationError>,
    ys: &[ode_solvers::SVector<f64, N>],
) -> Outcome<N> {
    match result {
        Ok(stats) => {
            let last = ys.last().expect("the sparse output holds the start");
            (
                Ok(SVector::<f64, N>::from_column_slice(last.as_slice())),
                stats_of(&stats),
            )
        }
        Err(e) => (Err(e.to_string()), Stats::default()),
    }
}

/// One run of the peer's Dopri5 with Hairer's defaults (β = 0.04, step ratios in [0.2, 10]).
fn dopri5<S: OdeSystem<f64, N>, const N: usize>(
    case: &Case<N>,
    system: &S,
    rtol: f64,
) -> Outcome<N> {
    let y0 = ode_solvers::SVector::<f64, N>::from_column_slice(case.y0.as_slice());
    let t = case.t_end;
    let mut solver = ode_solvers::Dopri5::from_param(
        Peer(system),
        0.0,
        t,
        t,
        y0,
        rtol,
        rtol,
        0.9,
        0.04,
        0.2,
        10.0,
        t,
        0.0,
        MAX_STEPS as u32,
        1000,
        OutputType::Sparse,
    );
    let result = solver.integrate();
    outcome(result, solver.y_out())
}

/// One run of the peer's Dop853 with Hairer's defaults (β = 0, step ratios in [0.333, 6]).
fn dop853<S: OdeSystem<f64, N>, const N: usize>(
    case: &Case<N>,
    system: &S,
    rtol: f64,
) -> Outcome<N> {
    let y0 = ode_solvers::SVector::<f64, N>::from_column_slice(case.y0.as_slice());
    let t = case.t_end;
    let mut solver = ode_solvers::Dop853::from_param(
        Peer(system),
        0.0,
        t,
        t,
        y0,
        rtol,
        rtol,
        0.9,
        0.0,
        0.333,
        6.0,
        t,
        0.0,
        MAX_STEPS as u32,
        1000,
        OutputType::Sparse,
    );
    let result = solver.integrate();
    outcome(result, solver.y_out())
}

/// The peer's two methods over the tolerance sweep, each timed alternately with ours.
pub fn sweep_peer<S: OdeSystem<f64, N>, const N: usize>(case: &Case<N>, system: &S) -> Vec<Row> {
    let mut rows = Vec::new();
    let t_end = case.t_end;
    for rtol in RTOLS {
        let setting = Setting::Rtol(rtol);
        let (end, stats) = dopri5(case, system, rtol);
        let mut ours = Dopri5::new(options(AdaptiveOptions::dopri5, rtol));
        let (paired, seconds) = timed_pair(
            || ours.integrate(system, 0.0, case.y0, t_end),
            || dopri5(case, system, rtol),
        );
        let row = row_of(case, ("ode_solvers Dopri5", setting), end, stats, seconds);
        rows.push(Row {
            paired: Some(paired),
            ..row
        });
        let (end, stats) = dop853(case, system, rtol);
        let mut ours = Dop853::new(options(AdaptiveOptions::dop853, rtol));
        let (paired, seconds) = timed_pair(
            || ours.integrate(system, 0.0, case.y0, t_end),
            || dop853(case, system, rtol),
        );
        let row = row_of(case, ("ode_solvers Dop853", setting), end, stats, seconds);
        rows.push(Row {
            paired: Some(paired),
            ..row
        });
    }
    rows
}
