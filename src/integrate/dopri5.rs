//! Dormand–Prince 5(4) (Dormand & Prince 1980; Hairer, Nørsett & Wanner, *Solving ODEs I*,
//! Table II.5.2): seven stages, the fifth-order solution is propagated, the embedded
//! fourth-order one only estimates the error.
//!
//! - FSAL ("first same as last"): the seventh stage is f(tₙ₊₁, yₙ₊₁), the first stage of the
//!   next step, so an accepted step costs six RHS evaluations, not seven.
//! - Step control: the PI controller of [`AdaptiveOptions`] (β = 0.04, α = 0.2 − 0.75β), and
//!   the initial step by Hairer's heuristic, as in his code.
//! - Dense output: Hairer's fourth-order continuous extension (the five coefficients of his
//!   `CONTD5`), built from the stages already computed, so output at any time costs no RHS
//!   evaluation; see [`Dopri5::solve_at`].
//!
//! The stepping loop is the one every embedded pair shares (`adaptive.rs`); this file holds
//! the tableau, the error estimate and the dense output.

use nalgebra::{RealField, SVector};

use super::adaptive::{self, AcceptedStep, EmbeddedPair, combine};
use super::controller::scaled_rms;
use super::{
    AdaptiveOptions, IntegrateError, Integrator, OdeSystem, Reached, RowClock, Statistics, Stats,
};

/// The nodes cᵢ.
const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];

/// The rows aᵢⱼ of the Butcher tableau (row 7 holds the fifth-order weights b).
const A2: [f64; 1] = [1.0 / 5.0];
const A3: [f64; 2] = [3.0 / 40.0, 9.0 / 40.0];
const A4: [f64; 3] = [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0];
const A5: [f64; 4] = [
    19372.0 / 6561.0,
    -25360.0 / 2187.0,
    64448.0 / 6561.0,
    -212.0 / 729.0,
];
const A6: [f64; 5] = [
    9017.0 / 3168.0,
    -355.0 / 33.0,
    46732.0 / 5247.0,
    49.0 / 176.0,
    -5103.0 / 18656.0,
];
const B: [f64; 7] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
    0.0,
];

/// The error weights eᵢ = bᵢ − b̂ᵢ (fifth minus fourth order), stage 2 has weight zero.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// Hairer's dense-output coefficients dᵢ (stage 2 has weight zero).
const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

/// The adaptive Dormand–Prince 5(4) method.
///
/// ```
/// use eom::integrate::{AdaptiveOptions, Dopri5, Integrator};
/// use nalgebra::Vector1;
///
/// let decay = |_t: f64, y: &Vector1<f64>, dy: &mut Vector1<f64>| *dy = -*y;
/// let mut dopri = Dopri5::new(AdaptiveOptions::dopri5(1e-10, 1e-12));
/// let y = dopri.integrate(&decay, 0.0, Vector1::new(1.0), 2.0).unwrap();
/// assert!((y[0] - (-2f64).exp()).abs() < 1e-9);
/// ```
#[derive(Debug, Clone)]
pub struct Dopri5 {
    options: AdaptiveOptions,
    stats: Stats,
}

impl Dopri5 {
    /// A method with the given options (see [`AdaptiveOptions::dopri5`] for Hairer's defaults).
    pub fn new(options: AdaptiveOptions) -> Self {
        Self {
            options,
            stats: Stats::default(),
        }
    }

    /// Integrates from `(t0, y0)` to the last of `times` (sorted ascending, none before `t0`)
    /// and writes the state at each of `times` into `out`, by dense output: the steps are
    /// chosen by the tolerance alone, not by the output times.
    pub fn solve_at<T, const N: usize, S>(
        &mut self,
        system: &S,
        t0: T,
        y0: SVector<T, N>,
        times: &[T],
        out: &mut [SVector<T, N>],
    ) -> Result<(), IntegrateError>
    where
        T: RealField + Copy,
        S: OdeSystem<T, N> + ?Sized,
    {
        let run_state = (&self.options, &mut self.stats);
        adaptive::solve_at::<Self, 7, T, N>(run_state, system, (t0, y0), times, out)
    }

    /// Integrates from `(t0, y0)` to `t_end` and hands the state at every `t0 + k·every`
    /// (k = 0, 1, … up to `t_end`) to `emit` as the run goes, by dense output: the steps are
    /// chosen by the tolerance alone, nothing is stored, and `emit` returning `false` stops
    /// the run with [`IntegrateError::Stopped`]. Returns the state at `t_end`.
    pub fn sample_every<T, const N: usize, S>(
        &mut self,
        system: &S,
        (t0, y0, t_end): (T, SVector<T, N>, T),
        every: T,
        emit: impl FnMut(T, &SVector<T, N>) -> bool,
    ) -> Result<SVector<T, N>, IntegrateError>
    where
        T: RealField + Copy,
        S: OdeSystem<T, N> + ?Sized,
    {
        self.sample_every_checked(system, (t0, y0, t_end), every, |_, _| true, emit)
    }

    /// As [`sample_every`](Self::sample_every), and `check(t, y)` at the end of every accepted
    /// step, before the samples the step holds are emitted: `false` stops the run there
    /// ([`IntegrateError::Stopped`]). A condition of the state (an attitude near a singular
    /// one) is so caught at the step that reaches it, not at the next sample.
    pub fn sample_every_checked<T, const N: usize, S>(
        &mut self,
        system: &S,
        (t0, y0, t_end): (T, SVector<T, N>, T),
        every: T,
        check: impl FnMut(T, &SVector<T, N>) -> bool,
        emit: impl FnMut(T, &SVector<T, N>) -> bool,
    ) -> Result<SVector<T, N>, IntegrateError>
    where
        T: RealField + Copy,
        S: OdeSystem<T, N> + ?Sized,
    {
        let run_state = (&self.options, &mut self.stats);
        let interval = (t0, y0, t_end);
        adaptive::sample::<Self, 7, T, N>(run_state, system, interval, every, (check, emit))
    }

    /// As [`sample_every_checked`](Self::sample_every_checked), continuing the rows of
    /// `rows`, and ending where `stop(t, y)` first holds, located on the dense output of the
    /// step that reaches it (see `adaptive::sample_until`).
    pub(crate) fn sample_until<T, const N: usize, S>(
        &mut self,
        system: &S,
        interval: (T, SVector<T, N>, T),
        rows: &mut RowClock<T>,
        handlers: (
            impl FnMut(T, &SVector<T, N>) -> bool,
            impl FnMut(T, &SVector<T, N>) -> bool,
            impl FnMut(T, &SVector<T, N>) -> bool,
        ),
    ) -> Result<Reached<T, N>, IntegrateError>
    where
        T: RealField + Copy,
        S: OdeSystem<T, N> + ?Sized,
    {
        let run_state = (&self.options, &mut self.stats);
        adaptive::sample_until::<Self, 7, T, N>(run_state, system, interval, rows, handlers)
    }
}

impl EmbeddedPair<7> for Dopri5 {
    const ORDER: i32 = 5;
    const ALPHA: (f64, f64) = (0.2, 0.75);
    const C: [f64; 7] = C;
    const A: &'static [&'static [f64]] = &[&A2, &A3, &A4, &A5, &A6];
    const B: [f64; 7] = B;
    const FSAL: bool = true;
    const DENSE_RHS: usize = 0;

    /// The weighted RMS norm of h Σ eᵢkᵢ.
    fn error<T: RealField + Copy, const N: usize>(
        k: &[SVector<T, N>; 7],
        _increment: &SVector<T, N>,
        h: T,
        (y, y_new): (&SVector<T, N>, &SVector<T, N>),
        tols: (T, T),
    ) -> T {
        scaled_rms(&(combine(&E, k) * h), y, y_new, tols)
    }

    /// Hairer's `CONTD5` extension, from the stages already computed.
    fn dense_output<T, const N: usize, Sys>(
        _system: &Sys,
        step: &AcceptedStep<'_, T, N, 7>,
    ) -> impl Fn(T) -> SVector<T, N>
    where
        T: RealField + Copy,
        Sys: OdeSystem<T, N> + ?Sized,
    {
        let interpolant = dense(step);
        move |t| interpolant.eval(t)
    }
}

/// The continuous extension over one accepted step from `t_old` to `t_old + h`: a polynomial
/// of degree four in θ = (t − t_old)/h, y(θ) = r₁ + θ(r₂ + (1−θ)(r₃ + θ(r₄ + (1−θ) r₅))).
#[derive(Debug, Clone, Copy)]
pub struct Dopri5Interpolant<T: RealField + Copy, const N: usize> {
    t_old: T,
    h: T,
    r: [SVector<T, N>; 5],
}

impl<T: RealField + Copy, const N: usize> Dopri5Interpolant<T, N> {
    /// The interpolated state at `t` (meant for `t` within the step; outside it extrapolates).
    pub fn eval(&self, t: T) -> SVector<T, N> {
        let theta = (t - self.t_old) / self.h;
        let theta1 = T::one() - theta;
        let [r1, r2, r3, r4, r5] = &self.r;
        r1 + (r2 + (r3 + (r4 + r5 * theta1) * theta) * theta1) * theta
    }
}

/// The continuous extension of an accepted step (Hairer's `CONTD5` coefficients).
fn dense<T: RealField + Copy, const N: usize>(
    step: &AcceptedStep<'_, T, N, 7>,
) -> Dopri5Interpolant<T, N> {
    let (h, y_old, k) = (step.h, step.y_old, step.k);
    let r2 = step.y_new - y_old;
    let r3 = k[0] * h - r2;
    let r4 = r2 - k[6] * h - r3;
    let r5 = combine(&D, k) * h;
    Dopri5Interpolant {
        t_old: step.t_old,
        h,
        r: [*y_old, r2, r3, r4, r5],
    }
}

impl<T, const N: usize, S> Integrator<T, N, S> for Dopri5
where
    T: RealField + Copy,
    S: OdeSystem<T, N> + ?Sized,
{
    fn integrate_with<F>(
        &mut self,
        system: &S,
        t0: T,
        y0: SVector<T, N>,
        t_end: T,
        observe: F,
    ) -> Result<SVector<T, N>, IntegrateError>
    where
        F: FnMut(T, &SVector<T, N>),
    {
        let run_state = (&self.options, &mut self.stats);
        adaptive::integrate::<Self, 7, T, N>(run_state, system, (t0, y0, t_end), observe)
    }
}

impl Statistics for Dopri5 {
    fn stats(&self) -> Stats {
        self.stats
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The full rows of the tableau, stage 7 holding b.
    fn rows() -> Vec<Vec<f64>> {
        vec![
            vec![],
            A2.to_vec(),
            A3.to_vec(),
            A4.to_vec(),
            A5.to_vec(),
            A6.to_vec(),
            B.to_vec(),
        ]
    }

    // Tolerance 1e-14: sums of a few rationals of order one, each rounded once.
    const TOL: f64 = 1e-14;

    #[test]
    fn tableau_rows_sum_to_nodes() {
        for (i, row) in rows().iter().enumerate() {
            assert!((row.iter().sum::<f64>() - C[i]).abs() < TOL, "row {i}");
        }
    }

    #[test]
    fn fifth_order_weights_satisfy_quadrature_and_tree_conditions() {
        for k in 1..=5 {
            let s: f64 = B.iter().zip(C).map(|(bi, ci)| bi * ci.powi(k - 1)).sum();
            assert!((s - 1.0 / f64::from(k)).abs() < TOL, "Σ b c^{}", k - 1);
        }
        // Σᵢⱼ bᵢ aᵢⱼ cⱼ^k = 1/((k+1)(k+2)) for k = 0..3 (the trees of order up to 5 with a
        // single branch of depth two).
        let a = rows();
        for k in 0..=3 {
            let mut s = 0.0;
            for (i, row) in a.iter().enumerate() {
                for (j, aij) in row.iter().enumerate() {
                    s += B[i] * aij * C[j].powi(k);
                }
            }
            let expected = 1.0 / f64::from((k + 1) * (k + 2));
            assert!((s - expected).abs() < TOL, "k = {k}");
        }
    }

    #[test]
    fn fourth_order_weights_satisfy_quadrature_conditions() {
        // b̂ = b − e (with b₇ = 0) integrates polynomials of degree ≤ 3 exactly.
        let b_hat: Vec<f64> = B.iter().zip(E).map(|(b, e)| b - e).collect();
        for k in 1..=4 {
            let s: f64 = b_hat
                .iter()
                .zip(C)
                .map(|(bi, ci)| bi * ci.powi(k - 1))
                .sum();
            assert!((s - 1.0 / f64::from(k)).abs() < TOL, "Σ b̂ c^{}", k - 1);
        }
        // And not degree 4: the estimate really is of lower order.
        let s5: f64 = b_hat.iter().zip(C).map(|(bi, ci)| bi * ci.powi(4)).sum();
        assert!((s5 - 0.2).abs() > 1e-6);
    }

    #[test]
    fn dense_output_matches_both_ends_of_the_step() {
        // The interpolant must reproduce y_old at θ = 0 and y_new at θ = 1 (identities of the
        // construction; 1e-15 is a few ulps of values of order one).
        let decay = |_t: f64, y: &SVector<f64, 1>, dy: &mut SVector<f64, 1>| *dy = -*y;
        let y = SVector::<f64, 1>::new(1.0);
        let mut k = [-y; 7];
        let (y_new, _) =
            adaptive::trial::<Dopri5, 7, f64, 1, _>(&decay, (0.0, 0.1), &y, (1.0, 1.0), &mut k);
        let (y_old, k, k_new) = (&y, &k, &k[6]);
        let step = AcceptedStep {
            t_old: 0.0,
            h: 0.1,
            y_old,
            y_new: &y_new,
            k,
            k_new,
        };
        let p = dense(&step);
        assert!((p.eval(0.0)[0] - 1.0).abs() < 1e-15);
        assert!((p.eval(0.1)[0] - y_new[0]).abs() < 1e-15);
    }
}
