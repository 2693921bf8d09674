//! The classical Runge–Kutta method of order 4: four RHS evaluations per step,
//! yₙ₊₁ = yₙ + h (k₁ + 2k₂ + 2k₃ + k₄)/6.
//!
//! It is the fixed-step workhorse of simulation codes, so the long runs measure what it does
//! to the energy and the quaternion norm over 10⁶ steps against the geometric integrator.

use nalgebra::{RealField, SVector};
use simba::simd::SimdRealField;

use super::{IntegrateError, Integrator, OdeSystem, Statistics, Stats, explain_failure, run_fixed};

/// The classical fourth-order Runge–Kutta method with a fixed step.
#[derive(Debug, Clone)]
pub struct Rk4 {
    h: f64,
    stats: Stats,
}

impl Rk4 {
    /// A method with the largest step `h`; the interval is cut into equal steps no longer than
    /// `h` (an invalid `h` is reported when integrating).
    pub fn new(h: f64) -> Self {
        Self {
            h,
            stats: Stats::default(),
        }
    }
}

/// One classical RK4 step of size `h` from `(t, y)`, in place: the step [`Rk4`] takes, and
/// the one for drivers that choose their own steps (a manoeuvre that steps onto the instant
/// an event happens). The same arithmetic as [`rk4_array`], in the same order, on nalgebra
/// vectors (`tests/batch.rs` checks the two bit for bit): along an integrator's chain of
/// dependent stages this form is the faster (`cargo bench --bench driver`, two runs: a
/// scene's run took 0.95–0.97 of the bare calls' time with it, 1.61–1.62 with the array
/// form), where for many independent bodies the array form is three times the faster
/// (`cargo bench --bench batch`).
pub fn rk4_step<T, const N: usize, S>(system: &S, t: T, h: T, y: &mut SVector<T, N>)
where
    T: SimdRealField + Copy,
    S: OdeSystem<T, N> + ?Sized,
{
    let half = h * T::from_subset(&0.5);
    let (mut k1, mut k2, mut k3, mut k4) = (
        SVector::zeros(),
        SVector::zeros(),
        SVector::zeros(),
        SVector::zeros(),
    );
    system.rhs(t, y, &mut k1);
    system.rhs(t + half, &(*y + k1 * half), &mut k2);
    system.rhs(t + half, &(*y + k2 * half), &mut k3);
    system.rhs(t + h, &(*y + k3 * h), &mut k4);
    let sixth = h / T::from_subset(&6.0);
    *y += (k1 + (k2 + k3) * T::from_subset(&2.0) + k4) * sixth;
}

/// The RK4 step on a plain array, for any of simba's scalars (f64, f32, SIMD lanes, dual
/// numbers): `y + h(k₁ + 2k₂ + 2k₃ + k₄)/6` with the stages at `y + (h/2)k₁`, `y + (h/2)k₂`,
/// `y + h k₃`: the step of [`crate::batch`], where many bodies' steps overlap.
#[inline(always)]
pub fn rk4_array<T: SimdRealField + Copy, const N: usize>(
    rate: impl Fn(T, &[T; N]) -> [T; N],
    t: T,
    h: T,
    y: &mut [T; N],
) {
    let half = h * T::from_subset(&0.5);
    let ahead = |k: &[T; N], s: T| -> [T; N] { std::array::from_fn(|i| y[i] + k[i] * s) };
    let k1 = rate(t, y);
    let k2 = rate(t + half, &ahead(&k1, half));
    let k3 = rate(t + half, &ahead(&k2, half));
    let k4 = rate(t + h, &ahead(&k3, h));
    let sixth = h / T::from_subset(&6.0);
    let two = T::from_subset(&2.0);
    for i in 0..N {
        y[i] += (k1[i] + (k2[i] + k3[i]) * two + k4[i]) * sixth;
    }
}

impl<T, const N: usize, S> Integrator<T, N, S> for Rk4
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
        let step = |t: T, h: T, y: &mut SVector<T, N>| {
            rk4_step(system, t, h, y);
            Ok(4)
        };
        let explain = |t: T, h: T, y: &SVector<T, N>| {
            explain_failure(system, |probe| rk4_step(probe, t, h, &mut y.clone()))
        };
        let interval = (t0, y0, t_end);
        run_fixed(self.h, &mut self.stats, interval, step, explain, observe)
    }
}

impl Statistics for Rk4 {
    fn stats(&self) -> Stats {
        self.stats
    }
}
