//! A catalog body's scene linearised ([`crate::linear`]): its model under its loads as a
//! [`LinearPlant`], at the point its `[linear]` table names (by default its initial state); a
//! quaternion model is linearised in the Euler angles of the same body.

use super::{Body, BodyScene, SceneLoads};
use crate::linear::{
    EULER_PITCH_LIMIT, Evaluation, LinearError, LinearPlant, Linearisation, linearise, set_at,
};
use crate::models::{AnyModel, Family, Kinematics, euler_angles};
use nalgebra::DMatrix;

/// The model to linearise, its state and the loads on it: a quaternion model becomes the
/// Euler-angle model of the same body. A quaternion's four components hold three angles, so
/// its norm would be a mode that means nothing (a zero eigenvalue that makes every verdict
/// marginal), and a top spinning about its axis turns every component steadily while the
/// gravity moment reads them all, so no part of the quaternion could be set aside; in Euler
/// angles the spin is the heading ψ alone. A point within 1° of θ = ±90°, where Euler angles
/// do not hold, is refused.
fn model_and_state(scene: &BodyScene, state: Vec<f64>) -> Result<Linearised, LinearError> {
    let info = scene.selection.info;
    let as_it_is = |state| Linearised {
        model: scene.model(),
        state,
        loads: None,
        note: None,
    };
    if info.kinematics != Some(Kinematics::Quaternion) {
        return Ok(as_it_is(state));
    }
    let (model, velocities) = match &scene.body {
        Body::Top {
            mass,
            inertia,
            h,
            g,
        } => (AnyModel::top(Kinematics::Euler, *mass, inertia, *h, *g), 3),
        Body::Spatial { mass, inertia } => (
            AnyModel::spatial(
                info.symmetry.expect("a spatial model has a symmetry class"),
                Kinematics::Euler,
                *mass,
                inertia,
            ),
            9,
        ),
        _ => return Ok(as_it_is(state)),
    };
    let model = model.expect("checked when the scene was read");
    let angles = euler_angles(Kinematics::Quaternion, &state[velocities..]);
    if angles[1].abs() > EULER_PITCH_LIMIT {
        return Err(LinearError::NotFinite(format!(
            "the pitch θ = {}° is within 1° of ±90°, where the Euler angles a quaternion scene \
             is linearised in do not hold; linearise at another attitude (linear.at)",
            angles[1].to_degrees()
        )));
    }
    let mut euler = state[..velocities].to_vec();
    euler.extend(angles);
    let mut loads = scene.loads.clone();
    if let SceneLoads::Spatial(spatial) = &mut loads {
        spatial.kinematics = Kinematics::Euler;
    }
    let note = "a quaternion scene is linearised in the Euler angles of the same body (a \
                quaternion's four components hold three angles: its norm would be a mode of \
                no meaning)";
    Ok(Linearised {
        model,
        state: euler,
        loads: Some(loads),
        note: Some(note.into()),
    })
}

/// What a scene is linearised as: its model or the Euler-angle twin of a quaternion model.
struct Linearised {
    model: AnyModel,
    state: Vec<f64>,
    /// The loads read in the twin's layout, where they differ from the scene's.
    loads: Option<SceneLoads>,
    note: Option<String>,
}

/// Linearises a catalog scene about the point its `[linear]` table names: the initial state
/// with the table's `at` entries, trimmed for its `trim` variables.
pub fn linearise_scene(scene: &BodyScene) -> Result<Linearisation, LinearError> {
    let info = scene.selection.info;
    let mut state = scene.initial.clone();
    let mut extra = vec![0.0; info.inputs.len()];
    set_at(
        &scene.linear,
        (info.state, info.inputs, &[]),
        (&mut state, &mut extra),
    )?;
    let twin = model_and_state(scene, state)?;
    let plant = Plant {
        model: twin.model,
        loads: twin.loads.as_ref().unwrap_or(&scene.loads),
    };
    let mut linearisation = linearise(&plant, (twin.state, extra), &scene.linear)?;
    linearisation.note = twin.note;
    Ok(linearisation)
}

/// A model, the loads acting on it, and inputs added to them.
#[derive(Debug, Clone)]
pub struct Plant<'a> {
    /// The model.
    pub model: AnyModel,
    /// The scene's loads, evaluated at each state.
    pub loads: &'a SceneLoads,
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
