//! Explicit Euler, yₙ₊₁ = yₙ + h f(tₙ, yₙ): order 1, one RHS evaluation per step.
//!
//! It is here as the baseline of the work–precision comparison: it shows what the cheapest
//! possible step buys, and its energy error grows without bound on rotation problems.

use nalgebra::{RealField, SVector};

use super::{IntegrateError, Integrator, OdeSystem, Statistics, Stats, explain_failure, run_fixed};

/// The explicit Euler method with a fixed step.
#[derive(Debug, Clone)]
pub struct Euler {
    h: f64,
    stats: Stats,
}

impl Euler {
    /// A method with the largest step `h`; the interval is cut into equal steps no longer than
    /// `h` (an invalid `h` is reported when integrating).
    pub fn new(h: f64) -> Self {
        Self {
            h,
            stats: Stats::default(),
        }
    }
}

fn euler_step<T, const N: usize, S>(system: &S, t: T, h: T, y: &mut SVector<T, N>)
where
    T: RealField + Copy,
    S: OdeSystem<T, N> + ?Sized,
{
    let mut dy = SVector::<T, N>::zeros();
    system.rhs(t, y, &mut dy);
    y.axpy(h, &dy, T::one());
}

impl<T, const N: usize, S> Integrator<T, N, S> for Euler
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
            euler_step(system, t, h, y);
            Ok(1)
        };
        let explain = |t: T, h: T, y: &SVector<T, N>| {
            explain_failure(system, |probe| euler_step(probe, t, h, &mut y.clone()))
        };
        let interval = (t0, y0, t_end);
        run_fixed(self.h, &mut self.stats, interval, step, explain, observe)
    }
}

impl Statistics for Euler {
    fn stats(&self) -> Stats {
        self.stats
    }
}
