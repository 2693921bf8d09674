//! Running a scene: its model under its loads, integrated by its method, sampled at exactly
//! t = k·every.
//!
//! The scene's typed model is handed back from [`AnyModel`](crate::models::AnyModel) to the
//! generic [`Runner`] with its state and input sizes known at compile time, so each step calls
//! the generated `rhs` inlined, as a hand-written program would. Rows go to a [`Sink`] as the
//! run goes (nothing is kept in memory): an adaptive method places them by dense output; a
//! fixed-step method integrates each output interval in equal steps no longer than the
//! scene's step, so every row lands on its time.

use crate::integrate::{
    Dop853, Dopri5, Euler, IntegrateError, Integrator, LieMidpoint, RigidRotation, Rk4, Statistics,
    Stats, SymplecticEuler,
};
use crate::models::{Family, Kinematics, Model, Visitor};
use crate::scene::{Body, Method, Scene, SceneLoads};
use nalgebra::{Matrix3, Quaternion, SVector, UnitQuaternion, Vector3};
use std::ops::Range;
use std::time::Instant;
use thiserror::Error;

/// One trajectory row.
#[derive(Debug, Clone, Copy)]
pub struct Row<'a> {
    /// The time.
    pub t: f64,
    /// The state, in the model's layout.
    pub state: &'a [f64],
    /// The kinetic energy (4.32).
    pub kinetic_energy: f64,
    /// The potential energy of the model's own field and of the loads, where there is one.
    pub potential_energy: Option<f64>,
}

/// Where a run's rows go: a CSV file, a plot's columns, a test's assertions.
pub trait Sink {
    /// Takes one row; `false` stops the run (the sink keeps its own reason).
    fn row(&mut self, row: &Row) -> bool;
}

/// What a finished run reports.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps (adaptive methods).
    pub rejected: usize,
    /// Right-hand-side evaluations.
    pub rhs_evals: usize,
    /// Wall time of the integration and the rows, s.
    pub wall_seconds: f64,
    /// The time reached.
    pub final_time: f64,
    /// The state at the final time.
    pub final_state: Vec<f64>,
    /// The largest change of the total energy over the rows, |E − E₀|, relative to the larger
    /// of |E₀| and the largest kinetic energy (a potential's zero is a convention, so E₀ alone
    /// may be 0), where every load has a potential (else `None`).
    pub energy_drift: Option<f64>,
}

/// Why a run did not finish.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RunError {
    /// The integration failed; the message names the state component by its name.
    #[error("the run failed at t = {t}: {message}")]
    Integration {
        /// The time reached.
        t: f64,
        /// What went wrong.
        message: String,
    },
    /// The sink stopped the run.
    #[error("the run was stopped at t = {t}")]
    Stopped {
        /// The time reached.
        t: f64,
    },
}

/// Runs `scene`, handing every row to `sink`.
pub fn run(scene: &Scene, sink: &mut dyn Sink) -> Result<Report, RunError> {
    scene.model().visit(Runner { scene, sink })
}

/// The run of one scene, generic over the model's sizes (see [`Visitor`]).
struct Runner<'a> {
    scene: &'a Scene,
    sink: &'a mut dyn Sink,
}

/// The rows' bookkeeping: energy, and the sink's verdict.
struct Rows<'a> {
    sink: &'a mut dyn Sink,
    start_energy: Option<f64>,
    /// The largest |E − E₀| and the largest kinetic energy so far.
    change: f64,
    kinetic: f64,
}

impl Rows<'_> {
    fn emit(
        &mut self,
        t: f64,
        state: &[f64],
        kinetic: f64,
        potential: Option<f64>,
        conserved: bool,
    ) -> bool {
        if conserved {
            let total = kinetic + potential.unwrap_or(0.0);
            let start = *self.start_energy.get_or_insert(total);
            self.change = self.change.max((total - start).abs());
            self.kinetic = self.kinetic.max(kinetic.abs());
        }
        self.sink.row(&Row {
            t,
            state,
            kinetic_energy: kinetic,
            potential_energy: potential,
        })
    }
}

impl Visitor for Runner<'_> {
    type Output = Result<Report, RunError>;

    fn visit<Mo: Model<f64, N, M>, const N: usize, const M: usize>(
        self,
        model: &Mo,
    ) -> Self::Output {
        let Runner { scene, sink } = self;
        let loads = &scene.loads;
        let mut rows = Rows {
            sink,
            start_energy: None,
            change: 0.0,
            kinetic: 0.0,
        };
        let has_potential = loads.has_potential();
        let mut emit = |t: f64, y: &SVector<f64, N>| {
            let state = &y.data.0[0];
            // The model's own potential (the pendulum's and the top's gravity) and the loads';
            // the energy is a constant of the motion only where every load has a potential.
            let own = model.potential_energy(state);
            let of_loads = loads.potential_energy(state);
            let potential = (own.is_some() || has_potential)
                .then(|| own.unwrap_or(0.0) + of_loads.unwrap_or(0.0));
            let conserved = of_loads.is_some();
            rows.emit(t, state, model.kinetic_energy(state), potential, conserved)
        };
        let y0 = SVector::<f64, N>::from_column_slice(&scene.initial);
        let clock = Instant::now();
        let system = model.driven_by(loads.clone());
        let spec = &scene.integrator;
        let interval = (0.0, y0, spec.end_time);
        let (result, stats) = match spec.method {
            Method::Dop853 => {
                let mut method =
                    Dop853::new(spec.adaptive.expect("an adaptive method has options"));
                let result = method.sample_every(&system, interval, scene.every, &mut emit);
                (result, method.stats())
            }
            Method::Dopri5 => {
                let mut method =
                    Dopri5::new(spec.adaptive.expect("an adaptive method has options"));
                let result = method.sample_every(&system, interval, scene.every, &mut emit);
                (result, method.stats())
            }
            Method::Euler => fixed_steps(&mut Euler::new(step(scene)), &system, scene, &mut emit),
            Method::Rk4 => fixed_steps(&mut Rk4::new(step(scene)), &system, scene, &mut emit),
            Method::SymplecticEuler => {
                let mut method = SymplecticEuler::new(step(scene), kicked(scene));
                fixed_steps(&mut method, &system, scene, &mut emit)
            }
            Method::LieMidpoint => free_rotation(scene, &mut emit),
        };
        let wall_seconds = clock.elapsed().as_secs_f64();
        let end = result.map_err(|e| run_error(e, &scene.state_names()))?;
        Ok(Report {
            steps: stats.steps,
            rejected: stats.rejected,
            rhs_evals: stats.rhs_evals,
            wall_seconds,
            final_time: spec.end_time,
            final_state: end.as_slice().to_vec(),
            energy_drift: rows.start_energy.map(|e0| {
                let scale = e0.abs().max(rows.kinetic);
                if scale > 0.0 {
                    rows.change / scale
                } else {
                    0.0
                }
            }),
        })
    }
}

fn step(scene: &Scene) -> f64 {
    scene
        .integrator
        .step
        .expect("a fixed-step method has a step")
}

/// The components symplectic Euler kicks first: the velocities of each family's state.
fn kicked(scene: &Scene) -> Range<usize> {
    match scene.selection.info.family {
        Family::Pendulum => 1..2,
        Family::PlanarAtG | Family::PlanarMidship => 0..3,
        Family::PlanarSpaceFixed => 3..6,
        Family::Spatial => 0..6,
        Family::Top => 0..3,
    }
}

/// The times a fixed-step run stops at: every row time k·every ≤ end_time (k ≥ 1), as
/// `(time, is_a_row)`, then the end time if it is not a row time itself.
fn stops(scene: &Scene) -> Vec<(f64, bool)> {
    let end = scene.integrator.end_time;
    let mut stops: Vec<(f64, bool)> = (1..)
        .map(|k| k as f64 * scene.every)
        .take_while(|t| *t <= end)
        .map(|t| (t, true))
        .collect();
    if stops.last().is_none_or(|(t, _)| *t != end) {
        stops.push((end, false));
    }
    stops
}

/// A fixed-step method over each output interval in turn (equal steps of at most the
/// scene's step, so that each row lands on its time), its statistics summed.
fn fixed_steps<I, S, const N: usize>(
    method: &mut I,
    system: &S,
    scene: &Scene,
    emit: &mut impl FnMut(f64, &SVector<f64, N>) -> bool,
) -> (Result<SVector<f64, N>, IntegrateError>, Stats)
where
    I: Integrator<f64, N, S>,
{
    let mut total = Stats::default();
    let mut y = SVector::<f64, N>::from_column_slice(&scene.initial);
    let mut t = 0.0;
    if !emit(t, &y) {
        return (Err(IntegrateError::Stopped { t }), total);
    }
    for (t_next, is_row) in stops(scene) {
        let result = method.integrate(system, t, y, t_next);
        let stats = method.stats();
        total.steps += stats.steps;
        total.rhs_evals += stats.rhs_evals;
        match result {
            Ok(next) => y = next,
            Err(e) => return (Err(e), total),
        }
        t = t_next;
        if is_row && !emit(t, &y) {
            return (Err(IntegrateError::Stopped { t }), total);
        }
    }
    (Ok(y), total)
}

/// A free body's rotation, `[p, q, r, q0, q1, q2, q3]`, for the geometric integrator.
struct FreeRotation {
    inertia: Matrix3<f64>,
}

impl RigidRotation<f64> for FreeRotation {
    fn inertia(&self) -> Matrix3<f64> {
        self.inertia
    }
}

/// A free spatial body with the Lie midpoint method: the rotation by the geometric
/// integrator, the translation exactly (with no force the velocity of G is constant in
/// space: v(t) = R(t)ᵀ V, x(t) = x₀ + V t).
fn free_rotation<const N: usize>(
    scene: &Scene,
    emit: &mut impl FnMut(f64, &SVector<f64, N>) -> bool,
) -> (Result<SVector<f64, N>, IntegrateError>, Stats) {
    let Body::Spatial { inertia, .. } = &scene.body else {
        unreachable!("lie-midpoint is refused for any scene but a free spatial body");
    };
    debug_assert!(matches!(
        scene.loads,
        SceneLoads::Spatial(crate::scene::SpatialLoads {
            kinematics: Kinematics::Quaternion,
            ..
        })
    ));
    let x = &scene.initial;
    let attitude =
        |s: &[f64]| UnitQuaternion::from_quaternion(Quaternion::new(s[0], s[1], s[2], s[3]));
    let velocity_in_space = attitude(&x[9..13]) * Vector3::new(x[0], x[1], x[2]);
    let position = Vector3::new(x[6], x[7], x[8]);
    let whole = |t: f64, rotation: &SVector<f64, 7>| -> SVector<f64, N> {
        let q = attitude(&rotation.as_slice()[3..7]);
        let v = q.inverse() * velocity_in_space;
        let p = position + velocity_in_space * t;
        let mut state = SVector::<f64, N>::zeros();
        state.as_mut_slice()[..3].copy_from_slice(v.as_slice());
        state.as_mut_slice()[3..6].copy_from_slice(&rotation.as_slice()[..3]);
        state.as_mut_slice()[6..9].copy_from_slice(p.as_slice());
        state.as_mut_slice()[9..].copy_from_slice(&rotation.as_slice()[3..]);
        state
    };
    let rotation_scene = RotationScene {
        scene,
        start: SVector::<f64, 7>::from_iterator(x[3..6].iter().chain(&x[9..13]).copied()),
    };
    let system = FreeRotation {
        inertia: inertia.matrix(),
    };
    let mut method = LieMidpoint::new(step(scene));
    let (result, stats) =
        rotation_scene.run(&mut method, &system, &mut |t, r| emit(t, &whole(t, r)));
    (result.map(|r| whole(scene.integrator.end_time, &r)), stats)
}

/// The rotational part of a free-body scene, run interval by interval like [`fixed_steps`].
struct RotationScene<'a> {
    scene: &'a Scene,
    start: SVector<f64, 7>,
}

impl RotationScene<'_> {
    fn run(
        &self,
        method: &mut LieMidpoint,
        system: &FreeRotation,
        emit: &mut impl FnMut(f64, &SVector<f64, 7>) -> bool,
    ) -> (Result<SVector<f64, 7>, IntegrateError>, Stats) {
        let mut shifted = self.scene.clone();
        shifted.initial = self.start.as_slice().to_vec();
        fixed_steps(method, system, &shifted, emit)
    }
}

/// An integration error as a run error, naming the state component.
fn run_error(error: IntegrateError, names: &[String]) -> RunError {
    match error {
        IntegrateError::Stopped { t } => RunError::Stopped { t },
        IntegrateError::NonFiniteState { component, t } => RunError::Integration {
            t,
            message: format!(
                "the state component {} is not finite",
                names.get(component).map_or("?", String::as_str)
            ),
        },
        IntegrateError::StepSizeTooSmall { t, .. } | IntegrateError::MaxStepsExceeded { t, .. } => {
            RunError::Integration {
                t,
                message: error.to_string(),
            }
        }
        other => RunError::Integration {
            t: f64::NAN,
            message: other.to_string(),
        },
    }
}

pub mod tradeoff;
