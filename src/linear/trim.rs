//! Trim: the free variables a `[linear]` table names, solved so that the reduced state is in
//! equilibrium, by Newton's method on its rates.
//!
//! The Jacobian of the reduced rates by the free variables is a set of columns of A (a state
//! entry) or of B (an input), the proved programs again. The step is the least-squares one
//! (through the singular value decomposition), so that more equations than free variables
//! are solved as far as they can be, and it is halved until the largest rate falls.

use super::plant::LinearPlant;
use super::{EQUILIBRIUM_TOLERANCE, LinearError, rate_scale};
use nalgebra::{DMatrix, DVector};

/// A free variable: a state entry or an input, by index.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Free {
    /// The state entry of this index.
    State(usize),
    /// The input of this index (added to the loads').
    Input(usize),
}

/// The most Newton steps before the trim is declared not to converge.
pub const MAX_ITERATIONS: usize = 50;

/// A trimmed point.
#[derive(Debug, Clone, PartialEq)]
pub struct Trimmed {
    /// The state.
    pub state: Vec<f64>,
    /// The inputs added to the loads'.
    pub extra: Vec<f64>,
    /// The Newton steps taken.
    pub iterations: usize,
}

/// Solves for `free` so that the rates of `reduced` vanish, from `state` and `extra`;
/// `names` name the free variables in the error.
pub fn trim(
    plant: &dyn LinearPlant,
    (state, extra): (&[f64], &[f64]),
    reduced: &[usize],
    free: &[Free],
    names: &str,
) -> Result<Trimmed, LinearError> {
    let (mut state, mut extra) = (state.to_vec(), extra.to_vec());
    let largest = |s: &[f64], e: &[f64]| -> Result<f64, LinearError> {
        let rates = plant.evaluate(s, e)?.rates;
        Ok(reduced.iter().fold(0.0f64, |m, &i| m.max(rates[i].abs())))
    };
    for iteration in 0..=MAX_ITERATIONS {
        let tolerance = EQUILIBRIUM_TOLERANCE * rate_scale(&state);
        let evaluation = plant.evaluate(&state, &extra)?;
        let residual =
            DVector::from_iterator(reduced.len(), reduced.iter().map(|&i| evaluation.rates[i]));
        let size = residual.amax();
        if size <= tolerance {
            return Ok(Trimmed {
                state,
                extra,
                iterations: iteration,
            });
        }
        let fail = || {
            let largest = residual.iamax();
            LinearError::NoConvergence {
                iterations: iteration,
                variables: names.to_owned(),
                state: plant.state_names()[reduced[largest]].to_owned(),
                residual: residual[largest],
                tolerance,
            }
        };
        if iteration == MAX_ITERATIONS {
            return Err(fail());
        }
        let jacobian = DMatrix::from_fn(reduced.len(), free.len(), |r, c| match free[c] {
            Free::State(j) => evaluation.a[(reduced[r], j)],
            Free::Input(j) => evaluation.b[(reduced[r], j)],
        });
        let step = jacobian
            .svd(true, true)
            .solve(&residual, 1e-12)
            .map_err(|_| fail())?;
        let mut scale = 1.0;
        loop {
            let (mut s, mut e) = (state.clone(), extra.clone());
            for (variable, delta) in free.iter().zip(step.iter()) {
                match *variable {
                    Free::State(j) => s[j] -= scale * delta,
                    Free::Input(j) => e[j] -= scale * delta,
                }
            }
            if largest(&s, &e).is_ok_and(|r| r < size) {
                (state, extra) = (s, e);
                break;
            }
            scale /= 2.0;
            if scale < 1e-9 {
                return Err(fail());
            }
        }
    }
    unreachable!("the loop returns by its last iteration")
}
