//! A model under what acts on it, at a point: its rates, A and B.
//!
//! [`LinearPlant`] is what the linearisation reads, so that a catalog model under a scene's
//! loads and a scene-defined model (a ship on its table) are linearised by the same code: the
//! operating point, the states set aside, the trim, the modes. Each kind implements it in its
//! folder.

use super::LinearError;
use super::modes::{Naming, Reading};
use crate::models::Family;
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
    /// How the modes read each state entry of an eigenvector when they compare its entries
    /// ([`Reading`]), at `state`, in the model's layout: by default each as it is (a catalog
    /// body, whose motion gives no speed or length to read its entries against).
    fn readings(&self, state: &[f64]) -> Vec<Reading> {
        vec![Reading::AsIs; state.len()]
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
    /// The units of its state entries and inputs where they are not the SI units their names
    /// have everywhere else ([`crate::models::state_unit`]): a model in a scene's own units
    /// (an aircraft in feet) says them here, by name.
    fn units(&self) -> Vec<(&'static str, &'static str)> {
        Vec::new()
    }
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
