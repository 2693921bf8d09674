//! Dormand–Prince 8(5,3), as in Hairer's code DOP853 (Hairer, Nørsett & Wanner, *Solving ODEs
//! I*, §II.10): twelve stages of an eighth-order method, whose error is estimated by a
//! fifth-order embedded solution corrected by a third-order one,
//! `err = |h| · e₅ / √(N · (e₅² + 0.01 e₃²))` in the weighted RMS norm (Hairer's "8(5,3)").
//!
//! The thirteenth evaluation, f(tₙ₊₁, yₙ₊₁), is made only when the step is accepted and is
//! the first stage of the next step: 12 RHS evaluations per accepted step, 11 per rejected one.
//! Step control: α = 1/8 − 0.2β with β = 0 by default (the classical controller), step ratios
//! in [0.333, 6], as in Hairer's code. Dense output (Hairer's seventh-order extension, three
//! more stages per accepted step, only when asked for) is in [`Dop853::solve_at`].
//!
//! The coefficients are Hairer's published constants; the tests check the tableau's row sums
//! and order conditions and the method's order of convergence. The stepping loop is the one
//! every embedded pair shares (`adaptive.rs`); this file holds the tableau and the 8(5,3)
//! estimate, `dop853_dense.rs` the dense output.

use nalgebra::{RealField, SVector};

use super::adaptive::{self, AcceptedStep, EmbeddedPair, combine};
use super::controller::{in_units_of, weight};
use super::dop853_dense::interpolant;
use super::{
    AdaptiveOptions, IntegrateError, Integrator, OdeSystem, Reached, RowClock, Statistics, Stats,
    lit,
};

/// The rows aᵢⱼ of stages 2–12 (Hairer's `dop853.f`).
const A: [&[f64]; 11] = [
    &[0.05260015195876773],
    &[0.0197250569845379, 0.0591751709536137],
    &[0.02958758547680685, 0.0, 0.08876275643042054],
    &[
        0.2413651341592667,
        0.0,
        -0.8845494793282861,
        0.924834003261792,
    ],
    &[
        0.037037037037037035,
        0.0,
        0.0,
        0.17082860872947386,
        0.12546768756682242,
    ],
    &[
        0.037109375,
        0.0,
        0.0,
        0.17025221101954405,
        0.06021653898045596,
        -0.017578125,
    ],
    &[
        0.03709200011850479,
        0.0,
        0.0,
        0.17038392571223998,
        0.10726203044637328,
        -0.015319437748624402,
        0.008273789163814023,
    ],
    &[
        0.6241109587160757,
        0.0,
        0.0,
        -3.3608926294469414,
        -0.868219346841726,
        27.59209969944671,
        20.154067550477894,
        -43.48988418106996,
    ],
    &[
        0.47766253643826434,
        0.0,
        0.0,
        -2.4881146199716677,
        -0.590290826836843,
        21.230051448181193,
        15.279233632882423,
        -33.28821096898486,
        -0.020331201708508627,
    ],
    &[
        -0.9371424300859873,
        0.0,
        0.0,
        5.186372428844064,
        1.0914373489967295,
        -8.149787010746927,
        -18.52006565999696,
        22.739487099350505,
        2.4936055526796523,
        -3.0467644718982196,
    ],
    &[
        2.273310147516538,
        0.0,
        0.0,
        -10.53449546673725,
        -2.0008720582248625,
        -17.9589318631188,
        27.94888452941996,
        -2.8589982771350235,
        -8.87285693353063,
        12.360567175794303,
        0.6433927460157636,
    ],
];
/// The eighth-order weights bᵢ (stages 1–12).
const B: [f64; 12] = [
    0.054293734116568765,
    0.0,
    0.0,
    0.0,
    0.0,
    4.450312892752409,
    1.8915178993145003,
    -5.801203960010585,
    0.3111643669578199,
    -0.1521609496625161,
    0.20136540080403034,
    0.04471061572777259,
];
/// The weights of the third-order estimate on stages 1, 9 and 12.
const BHH: [f64; 3] = [0.2440944881889764, 0.7338466882816118, 0.022058823529411766];
/// The weights of the fifth-order error estimate (stages 1–12).
const ER: [f64; 12] = [
    0.01312004499419488,
    0.0,
    0.0,
    0.0,
    0.0,
    -1.2251564463762044,
    -0.4957589496572502,
    1.6643771824549864,
    -0.35032884874997366,
    0.3341791187130175,
    0.08192320648511571,
    -0.022355307863886294,
];
/// The nodes cᵢ (c₁₂ = 1).
const C: [f64; 12] = [
    0.0,
    0.05260015195876773,
    0.0789002279381516,
    0.1183503419072274,
    0.2816496580927726,
    0.3333333333333333,
    0.25,
    0.3076923076923077,
    0.6512820512820513,
    0.6,
    0.8571428571428571,
    1.0,
];

/// The adaptive Dormand–Prince 8(5,3) method.
#[derive(Debug, Clone)]
pub struct Dop853 {
    options: AdaptiveOptions,
    stats: Stats,
}

impl Dop853 {
    /// A method with the given options (see [`AdaptiveOptions::dop853`] for Hairer's defaults).
    pub fn new(options: AdaptiveOptions) -> Self {
        Self {
            options,
            stats: Stats::default(),
        }
    }

    /// Integrates from `(t0, y0)` to the last of `times` (ascending, none before `t0`) and
    /// writes the state at each of `times` into `out` by dense output: the steps are chosen by
    /// the tolerance alone, and each accepted step that holds an output time costs three more
    /// RHS evaluations (counted in the statistics).
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
        adaptive::solve_at::<Self, 12, T, N>(run_state, system, (t0, y0), times, out)
    }

    /// Integrates from `(t0, y0)` to `t_end` and hands the state at every `t0 + k·every`
    /// (k = 0, 1, … up to `t_end`) to `emit` as the run goes, by dense output: the steps are
    /// chosen by the tolerance alone, nothing is stored, and `emit` returning `false` stops
    /// the run with [`IntegrateError::Stopped`]. Returns the state at `t_end`.
    ///
    /// ```
    /// use eom::models::Pendulum;
    /// use eom::{AdaptiveOptions, Constant, Dop853, Model, PendulumParameters};
    /// use eom::nalgebra::SVector;
    ///
    /// // A compound pendulum released at 90°, sampled every 0.1 s for 2 s.
    /// let parameters = PendulumParameters::new(2.0, 3.0, 9.81, 0.5)?;
    /// let pendulum = Pendulum::<f64>::new(&parameters);
    /// let mut dop853 = Dop853::new(AdaptiveOptions::dop853(1e-10, 1e-10));
    /// let start = SVector::from([std::f64::consts::FRAC_PI_2, 0.0]);
    /// let mut rows = Vec::new();
    /// dop853.sample_every(&pendulum.driven_by(Constant::zero()), (0.0, start, 2.0), 0.1, |t, y| {
    ///     rows.push((t, y[0]));
    ///     true
    /// })?;
    /// assert_eq!(rows.len(), 21);
    /// assert!(rows.iter().all(|(_, theta)| theta.abs() <= std::f64::consts::FRAC_PI_2 + 1e-9));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
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
        adaptive::sample::<Self, 12, T, N>(run_state, system, interval, every, (check, emit))
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
        adaptive::sample_until::<Self, 12, T, N>(run_state, system, interval, rows, handlers)
    }
}

impl EmbeddedPair<12> for Dop853 {
    const ORDER: i32 = 8;
    const ALPHA: (f64, f64) = (0.125, 0.2);
    const C: [f64; 12] = C;
    const A: &'static [&'static [f64]] = &A;
    const B: [f64; 12] = B;
    const FSAL: bool = false;
    const DENSE_RHS: usize = 3;

    /// Hairer's 8(5,3) estimate: `|h| · e₅ / √(N · (e₅² + 0.01 e₃²))` in the weighted RMS norm.
    fn error<T: RealField + Copy, const N: usize>(
        k: &[SVector<T, N>; 12],
        increment: &SVector<T, N>,
        h: T,
        (y, y_new): (&SVector<T, N>, &SVector<T, N>),
        tols: (T, T),
    ) -> T {
        let e5 = combine(&ER, k);
        let e3 = increment
            - (k[0] * lit::<T>(BHH[0]) + k[8] * lit::<T>(BHH[1]) + k[11] * lit::<T>(BHH[2]));
        let (mut sum5, mut sum3) = (T::zero(), T::zero());
        for i in 0..N {
            let w = weight(y[i], y_new[i], tols);
            let (r5, r3) = (in_units_of(e5[i], w), in_units_of(e3[i], w));
            sum5 += r5 * r5;
            sum3 += r3 * r3;
        }
        let mut denominator = sum5 + lit::<T>(0.01) * sum3;
        if denominator <= T::zero() {
            denominator = T::one();
        }
        h.abs() * sum5 / (denominator * lit::<T>(N as f64)).sqrt()
    }

    /// Hairer's seventh-order extension, three more stages (see [`interpolant`]).
    fn dense_output<T, const N: usize, Sys>(
        system: &Sys,
        step: &AcceptedStep<'_, T, N, 12>,
    ) -> impl Fn(T) -> SVector<T, N>
    where
        T: RealField + Copy,
        Sys: OdeSystem<T, N> + ?Sized,
    {
        let interpolant = interpolant(system, step);
        move |t| interpolant.eval(t)
    }
}

impl<T, const N: usize, S> Integrator<T, N, S> for Dop853
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
        adaptive::integrate::<Self, 12, T, N>(run_state, system, (t0, y0, t_end), observe)
    }
}

impl Statistics for Dop853 {
    fn stats(&self) -> Stats {
        self.stats
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // Tolerances: the coefficients carry 30 digits rounded to f64, and the sums mix terms up
    // to 45 in size, so 1e-13 allows the rounding of each term.
    const TOL: f64 = 1e-13;

    #[test]
    fn tableau_rows_sum_to_nodes() {
        for (s, row) in A.iter().enumerate() {
            assert!(
                (row.iter().sum::<f64>() - C[s + 1]).abs() < TOL,
                "stage {}",
                s + 2
            );
        }
    }

    #[test]
    fn eighth_order_weights_integrate_polynomials_of_degree_seven() {
        for k in 1..=8 {
            let s: f64 = B.iter().zip(C).map(|(b, c)| b * c.powi(k - 1)).sum();
            assert!((s - 1.0 / f64::from(k)).abs() < TOL, "Σ b c^{}", k - 1);
        }
    }

    #[test]
    fn eighth_order_weights_satisfy_the_depth_two_tree_conditions() {
        // Σᵢⱼ bᵢ aᵢⱼ cⱼ^k = 1/((k+1)(k+2)) for k = 0..6.
        for k in 0..=6 {
            let mut s = 0.0;
            for (r, row) in A.iter().enumerate() {
                for (j, a) in row.iter().enumerate() {
                    s += B[r + 1] * a * C[j].powi(k);
                }
            }
            let expected = 1.0 / f64::from((k + 1) * (k + 2));
            assert!((s - expected).abs() < TOL, "k = {k}");
        }
    }

    #[test]
    fn error_estimators_vanish_on_constants() {
        // Both estimates are differences of consistent quadratures: Σ er = 0 and Σ bhh = 1.
        assert!(ER.iter().sum::<f64>().abs() < TOL);
        assert!((BHH.iter().sum::<f64>() - 1.0).abs() < TOL);
    }
}
