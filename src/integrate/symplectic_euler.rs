//! Semi-implicit (symplectic) Euler: first the "kick" components (velocities, angular
//! velocities) from the state at the start of the step, then the "drift" components
//! (positions, angles, attitude) from the state with the kicked components already updated.
//!
//! For separable mechanics (θ̇ = ω, ω̇ = a(θ), as in the pendulum 4.24) this is the symplectic
//! Euler method: order 1 like explicit Euler, but its energy error stays bounded instead of
//! growing. Which components are kicked is a range given by the user, since a generic RHS does
//! not say which of its components are velocities. The general form costs two RHS evaluations
//! per step (one for each half), documented and counted.

use std::ops::Range;

use nalgebra::{RealField, SVector};

use super::{IntegrateError, Integrator, OdeSystem, Statistics, Stats, explain_failure, run_fixed};

/// The semi-implicit Euler method with a fixed step and a range of "kick" components.
#[derive(Debug, Clone)]
pub struct SymplecticEuler {
    h: f64,
    kick: Range<usize>,
    stats: Stats,
}

impl SymplecticEuler {
    /// A method with the largest step `h` whose components in `kick` (e.g. `1..2` for the
    /// pendulum's θ̇ in the state (θ, θ̇)) are updated first; components of `kick` beyond the
    /// state are ignored.
    pub fn new(h: f64, kick: Range<usize>) -> Self {
        Self {
            h,
            kick,
            stats: Stats::default(),
        }
    }
}

/// One step: the `kick` components from the state at the start, then the others from the
/// state with the kicked ones updated.
fn kick_drift<T, const N: usize, S>(
    system: &S,
    kick: &Range<usize>,
    (t, h): (T, T),
    y: &mut SVector<T, N>,
) where
    T: RealField + Copy,
    S: OdeSystem<T, N> + ?Sized,
{
    let mut dy = SVector::<T, N>::zeros();
    system.rhs(t, y, &mut dy);
    for i in kick.clone() {
        y[i] += h * dy[i];
    }
    system.rhs(t, y, &mut dy);
    for i in (0..N).filter(|i| !kick.contains(i)) {
        y[i] += h * dy[i];
    }
}

impl<T, const N: usize, S> Integrator<T, N, S> for SymplecticEuler
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
        let kick = self.kick.start.min(N)..self.kick.end.min(N);
        let step = |t: T, h: T, y: &mut SVector<T, N>| {
            kick_drift(system, &kick, (t, h), y);
            Ok(2)
        };
        let explain = |t: T, h: T, y: &SVector<T, N>| {
            explain_failure(system, |probe| {
                kick_drift(probe, &kick, (t, h), &mut y.clone());
            })
        };
        let interval = (t0, y0, t_end);
        run_fixed(self.h, &mut self.stats, interval, step, explain, observe)
    }
}

impl Statistics for SymplecticEuler {
    fn stats(&self) -> Stats {
        self.stats
    }
}
