//! A model under what acts on it, at a point: its rates, A and B.
//!
//! [`LinearPlant`] is what the linearisation reads, so that a catalog model under a scene's
//! loads ([`Plant`]) and a scene-defined model (a ship on its table) are linearised by the same
//! code: the operating point, the states set aside, the trim, the modes.

use super::LinearError;
use super::modes::Naming;
use crate::models::{AnyModel, Family};
use crate::scene::SceneLoads;
use nalgebra::DMatrix;

/// A model under what acts on it, as the linearisation reads it.
pub trait LinearPlant {
    /// The model's name.
    fn name(&self) -> &'static str;
    /// The family whose modes' names apply.
    fn family(&self) -> Family;
    /// Whose names its modes get: by default its family's.
    fn naming(&self) -> Naming {
        Naming::Family(self.family())
    }
    /// Every state entry's name, in the model's layout.
    fn state_names(&self) -> Vec<&'static str>;
    /// Every input's name.
    fn input_names(&self) -> Vec<&'static str>;
    /// Other names of state entries and inputs, as (alias, name): what a `[linear]` table may
    /// also call them (a ship's rudder angle `delta`, `rudder`).
    fn aliases(&self) -> &'static [(&'static str, &'static str)] {
        &[]
    }
    /// The inputs at `state`: what acts there plus `extra`.
    fn inputs(&self, state: &[f64], extra: &[f64]) -> Vec<f64>;
    /// The rates, A and B at `state` with `extra` added to the inputs.
    fn evaluate(&self, state: &[f64], extra: &[f64]) -> Result<Evaluation, LinearError>;
    /// Where ∂f/∂x can be non-zero, as (row, column): the model's declared pattern.
    fn pattern(&self) -> Vec<(usize, usize)>;
    /// How A and B are obtained, in words, as the outputs say it.
    fn jacobians(&self) -> &'static str;
}

/// A model, the loads acting on it, and inputs added to them.
#[derive(Debug, Clone)]
pub struct Plant<'a> {
    /// The model.
    pub model: AnyModel,
    /// The scene's loads, evaluated at each state.
    pub loads: &'a SceneLoads,
}

/// The rates, A = ∂f/∂x (loads included) and B = ∂f/∂u at one point.
#[derive(Debug, Clone)]
pub struct Evaluation {
    /// f(x, u).
    pub rates: Vec<f64>,
    /// ∂f/∂x with the loads' dependence on the state.
    pub a: DMatrix<f64>,
    /// ∂f/∂u.
    pub b: DMatrix<f64>,
}

impl LinearPlant for Plant<'_> {
    fn name(&self) -> &'static str {
        self.model.info().name
    }

    fn family(&self) -> Family {
        self.model.info().family
    }

    fn state_names(&self) -> Vec<&'static str> {
        self.model.info().state.to_vec()
    }

    fn input_names(&self) -> Vec<&'static str> {
        self.model.info().inputs.to_vec()
    }

    /// The model's inputs at `state`: the loads there plus `extra`.
    fn inputs(&self, state: &[f64], extra: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; extra.len()];
        self.loads.inputs(state, &mut out);
        out.iter().zip(extra).map(|(l, e)| l + e).collect()
    }

    fn pattern(&self) -> Vec<(usize, usize)> {
        self.model.state_jacobian_pattern().to_vec()
    }

    fn jacobians(&self) -> &'static str {
        "emitted and proved: the model's Jacobian programs, proved equal to the exact \
         derivatives of its equations at build time; the loads' dependence on the state \
         (∂f/∂u · ∂loads/∂x) by central differences"
    }

    /// The rates, A and B at `state` with `extra` added to the loads' inputs.
    fn evaluate(&self, state: &[f64], extra: &[f64]) -> Result<Evaluation, LinearError> {
        let layout = |e: crate::models::LayoutError| LinearError::NotFinite(e.to_string());
        let input = self.inputs(state, extra);
        let rates = self.model.rhs(state, &input).map_err(layout)?;
        let (jx, b) = self.model.jacobians(state, &input).map_err(layout)?;
        let a = jx + &b * self.loads_derivative(state, extra);
        let finite = rates
            .iter()
            .chain(a.iter())
            .chain(b.iter())
            .all(|v| v.is_finite());
        if !finite {
            return Err(LinearError::NotFinite(format!(
                "{} at state {:?}",
                self.model.info().name,
                state
            )));
        }
        Ok(Evaluation { rates, a, b })
    }
}

impl Plant<'_> {
    /// ∂loads/∂x by central differences, step 10⁻⁶ of each entry (at least 10⁻⁶): the
    /// loads are smooth but not emitted. The truncation error vanishes for linear damping
    /// and is ~10⁻¹² for the rest; rounding leaves ~10⁻¹⁰ relative. A load that does not
    /// depend on an entry gives an exactly zero column.
    fn loads_derivative(&self, state: &[f64], extra: &[f64]) -> DMatrix<f64> {
        let (n, m) = (state.len(), extra.len());
        let mut derivative = DMatrix::zeros(m, n);
        for j in 0..n {
            let step = 1e-6 * state[j].abs().max(1.0);
            let shifted = |dx: f64| {
                let mut x = state.to_vec();
                x[j] += dx;
                self.inputs(&x, extra)
            };
            let (plus, minus) = (shifted(step), shifted(-step));
            for i in 0..m {
                derivative[(i, j)] = (plus[i] - minus[i]) / (2.0 * step);
            }
        }
        derivative
    }
}
