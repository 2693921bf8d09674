//! The model under the scene's loads at a point: its rates, A and B.

use super::LinearError;
use crate::models::AnyModel;
use crate::scene::SceneLoads;
use nalgebra::DMatrix;

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

impl Plant<'_> {
    /// The model's inputs at `state`: the loads there plus `extra`.
    pub fn inputs(&self, state: &[f64], extra: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; extra.len()];
        self.loads.inputs(state, &mut out);
        out.iter().zip(extra).map(|(l, e)| l + e).collect()
    }

    /// The rates, A and B at `state` with `extra` added to the loads' inputs.
    pub fn evaluate(&self, state: &[f64], extra: &[f64]) -> Result<Evaluation, LinearError> {
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
