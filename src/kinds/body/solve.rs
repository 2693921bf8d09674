//! A catalog body's run: its model under its loads, integrated by its method, sampled at exactly
//! t = k·every.
//!
//! The scene's typed model is handed back from [`AnyModel`](crate::models::AnyModel) to the
//! generic runner with its state and input sizes known at compile time, so each step calls
//! the generated `rhs` inlined, as a hand-written program would. Rows go to a [`Sink`] as the
//! run goes (nothing is kept in memory): an adaptive method places them by dense output; a
//! fixed-step method integrates each output interval in equal steps no longer than the
//! scene's step, so every row lands on its time.
//!
//! A run is a `Problem` solved by the one loop every run is solved by
//! (`integrate::problem::solve`). Its schedule is the breakpoints of the loads given as time
//! tables (see [`super::table`]): each piece between them is integrated on its own, so
//! that no step straddles a jump: a fixed-step method lands on each breakpoint, an adaptive
//! one starts afresh from it (its step-size heuristic, its first stage), as it must after a
//! discontinuity; the rows go on at k·every across the cuts.
//!
//! A scene's stop condition (`integrator.stop_when`,
//! [`StopCondition`](crate::scene::StopCondition)) is the problem's, evaluated at the end of
//! every step. On the step where it first holds, the first time it holds is found by
//! bisection to adjacent floating-point numbers: on the dense output of an adaptive method,
//! and for a fixed-step method by taking the one step again from its start to each trial
//! time. The run ends there with a last row at that time, and [`Report::stopped_at`] says
//! when. The time found is the integrator's own crossing, to the last bit of t; its error
//! against the exact motion is the integrator's error there.
//!
//! A run that cannot go on stops with a [`RunError`] that says why, where and what to change,
//! and [`run_reporting`] reports what it did up to there. Every accepted step is checked, at
//! the cost of a few arithmetic operations (see [`super::guard`]): an Euler-angle attitude near
//! gimbal lock, a fixed step too long for the body's rate of turn, a state or a load input
//! that is not finite.
//!
//! A scene file run from a program, its rows handed to a sink of the caller's:
//!
//! ```
//! use eom::kinds::body::{BodyScene, run};
//! use eom::run::{Row, Sink};
//!
//! /// Keeps the pendulum's angle at each row.
//! struct Angles(Vec<(f64, f64)>);
//! impl Sink for Angles {
//!     fn row(&mut self, row: &Row) -> bool {
//!         self.0.push((row.t, row.state[0]));
//!         true // false would end the run here
//!     }
//! }
//!
//! let scene = BodyScene::load(std::path::Path::new("scenes/pendulum.toml"))?;
//! let mut angles = Angles(Vec::new());
//! let report = run(&scene, &mut angles)?;
//! assert_eq!(angles.0.len(), 4001); // a row every 0.005 s over 20 s
//! assert!((angles.0[0].1 - 150f64.to_radians()).abs() < 1e-15);
//! println!("{} steps, {} rhs calls", report.steps, report.rhs_evals);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::guard::Guard;
use super::{Body, BodyScene, PreparedLoads};
use crate::integrate::problem::{self, Flow, Problem};
use crate::integrate::segment::{self, Hooks, Piece};
use crate::integrate::{
    IntegrateError, LieMidpoint, Reached, RigidRotation, RowClock, Stats, Stepper,
};
use crate::models::{Driven, Model, Visitor};
use crate::run::{Row, Sink};
use crate::scene::Method;
use nalgebra::{Matrix3, Quaternion, SVector, UnitQuaternion, Vector3};
use std::convert::Infallible;
use std::ops::Range;
use std::time::Instant;
use thiserror::Error;

/// What a finished run reports.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Report {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps (adaptive methods).
    pub rejected: usize,
    /// Right-hand-side evaluations.
    pub rhs_evals: usize,
    /// Wall time of the integration and the rows, s.
    pub wall_seconds: f64,
    /// The end time; for a run that stopped early, its last row's time (0 if it wrote none).
    pub final_time: f64,
    /// The state at the final time.
    pub final_state: Vec<f64>,
    /// The largest change of the total energy over the rows, |E − E₀|, relative to the larger
    /// of |E₀| and the largest kinetic energy (a potential's zero is a convention, so E₀ alone
    /// may be 0), where every load has a potential (else `None`).
    pub energy_drift: Option<f64>,
    /// What the run did not stop for but a reader should know: a fixed step past its
    /// accuracy bound for the rate of turn (see [`guard`](super::guard)).
    pub warnings: Vec<String>,
    /// The time at which the scene's stop condition first held and ended the run, if it did.
    pub stopped_at: Option<f64>,
}

/// Why a run did not finish.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RunError {
    /// The integration failed; the message names the state component or the load input by
    /// its name.
    #[error("the run failed at t = {}: {message}", seconds(*t))]
    Integration {
        /// The time reached.
        t: f64,
        /// What went wrong.
        message: String,
    },
    /// The pitch of an Euler-angle attitude came within [`guard::gimbal_bound`](super::guard::gimbal_bound) of ±90°, or
    /// crossed it within one step: the Euler-angle rates (4.60) divide by cos θ.
    #[error("{}", gimbal_message(*t, *pitch_deg, *cos_pitch, *bound, *crossed_since))]
    GimbalLock {
        /// The time of the step that came too close.
        t: f64,
        /// The pitch there, degrees.
        pitch_deg: f64,
        /// cos θ there.
        cos_pitch: f64,
        /// The least |cos θ| allowed ([`guard::gimbal_bound`](super::guard::gimbal_bound)).
        bound: f64,
        /// Where the pitch went past ±90° within the step that ended at `t`, the step's
        /// start (a fixed step, or a pure pitch, can jump the bound's narrow band).
        crossed_since: Option<f64>,
    },
    /// A fixed step too long for how fast the state turns: h·|ω| beyond the method's stability
    /// limit on the imaginary axis, where the eigenvalues ±i|ω| of a rotation lie (see
    /// [`guard`](super::guard)).
    #[error(
        "the step is too long for the rotation at t = {} s: h·{rate_name} = {step} s × \
         {rate:.3} rad/s = {:.3}, beyond {method}'s stability limit {limit:.4} on the \
         imaginary axis, where every step grows the error; a step ≤ {:.3e} s is stable, one \
         ≤ {accurate_step:.3e} s keeps a turn within 10 %; or use an adaptive method (dop853)",
        seconds(*t),
        step * rate,
        limit / rate
    )]
    StepTooLarge {
        /// The time of the step.
        t: f64,
        /// The method's name in scene files.
        method: &'static str,
        /// The rate: |ω| of a body, |r| of a planar one, √(Mgh/I₀) of a pendulum, rad/s.
        rate: f64,
        /// How the message writes the rate: `|ω|`, `|r|`, `ω₀`.
        rate_name: &'static str,
        /// The step, s.
        step: f64,
        /// The largest h·rate the method is stable at ([`guard::RK4_LIMIT`](super::guard::RK4_LIMIT),
        /// [`guard::SYMPLECTIC_EULER_LIMIT`](super::guard::SYMPLECTIC_EULER_LIMIT)).
        limit: f64,
        /// The step at which one turn at this rate errs by 10 %
        /// ([`guard::Scheme::accuracy_bound`](super::guard::Scheme::accuracy_bound)), s.
        accurate_step: f64,
    },
}

/// A time as a message writes it: to six significant digits, as every number in a message
/// ([`Short`](crate::Short)), so that a step's time t₀ + k·h reads 1.829, not
/// 1.8290000000000002; the summary and the trajectory keep every digit.
pub(crate) fn seconds(t: f64) -> crate::Short {
    crate::Short(t)
}

/// What a [`RunError::GimbalLock`] says.
fn gimbal_message(
    t: f64,
    pitch_deg: f64,
    cos_pitch: f64,
    bound: f64,
    crossed_since: Option<f64>,
) -> String {
    let what = if let Some(since) = crossed_since {
        format!(
            "the pitch θ crossed ±90° in the step from t = {} s (θ = {pitch_deg:.6}° at its \
             end), and the Euler-angle rates (4.60) divide by cos θ, which is 0 at ±90°",
            seconds(since)
        )
    } else {
        format!(
            "the pitch θ = {pitch_deg:.9}° is {:.1e} rad from ±90°, nearer than ε|θ|/η = \
             {bound:.1e}, where the rounding of θ alone makes the Euler-angle rates (4.60), \
             which divide by cos θ, err by more than η",
            cos_pitch.abs()
        )
    };
    format!(
        "gimbal lock at t = {} s: {what}; set kinematics = \"quaternion\" in [model], which \
         has no singular attitude",
        seconds(t)
    )
}

/// A run as it ended: what it did, and why it stopped if it did not reach its end time.
#[derive(Debug, Clone, PartialEq)]
pub struct Ended {
    /// What the run did. For a run that stopped early, `final_time` and `final_state` are its
    /// last row's, and the energy drift is over the rows it wrote.
    pub report: Report,
    /// Why the run stopped early, if it did.
    pub error: Option<RunError>,
}

impl Ended {
    /// The report of a run that finished, or why it did not.
    pub fn into_result(self) -> Result<Report, RunError> {
        match self.error {
            None => Ok(self.report),
            Some(error) => Err(error),
        }
    }
}

/// Runs `scene`, handing every row to `sink`.
pub fn run(scene: &BodyScene, sink: &mut dyn Sink) -> Result<Report, RunError> {
    run_reporting(scene, sink).into_result()
}

/// Runs `scene` as [`run`] does, and reports what the run did also when it stopped early (a
/// failure, or the sink's refusal of a row): the rows written stay, and so does their account.
pub fn run_reporting(scene: &BodyScene, sink: &mut dyn Sink) -> Ended {
    scene.model().visit(Runner { scene, sink })
}

/// The run of one scene, generic over the model's sizes (see [`Visitor`]).
struct Runner<'a> {
    scene: &'a BodyScene,
    sink: &'a mut dyn Sink,
}

/// The rows' bookkeeping: energy, the last row the sink took, and the sink's verdict.
struct Rows<'a> {
    sink: &'a mut dyn Sink,
    start_energy: Option<f64>,
    /// The largest |E − E₀| and the largest kinetic energy so far.
    change: f64,
    kinetic: f64,
    /// The time and state of the last row the sink took.
    last: Option<(f64, Vec<f64>)>,
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
        let taken = self.sink.row(&Row {
            t,
            state,
            kinetic_energy: kinetic,
            potential_energy: potential,
        });
        if taken {
            let (time, last) = self.last.get_or_insert_with(|| (t, Vec::new()));
            *time = t;
            last.clear();
            last.extend_from_slice(state);
        }
        taken
    }

    /// The largest |E − E₀| over the rows relative to max(|E₀|, largest T), where the energy
    /// is a constant of the motion.
    fn drift(&self) -> Option<f64> {
        self.start_energy.map(|e0| {
            let scale = e0.abs().max(self.kinetic);
            if scale > 0.0 {
                self.change / scale
            } else {
                0.0
            }
        })
    }
}

impl Visitor for Runner<'_> {
    type Output = Ended;

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
            last: None,
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
        let mut guard = Guard::new(scene);
        let (result, stats) = if !guard.check(0.0, y0.as_slice()) {
            (Err(IntegrateError::Stopped { t: 0.0 }), Stats::default())
        } else if scene.integrator.method == Method::LieMidpoint {
            free_rotation(scene, &mut emit)
        } else {
            pieces(model, scene, y0, &mut guard, &mut emit)
        };
        let wall_seconds = clock.elapsed().as_secs_f64();
        let error = result.as_ref().err().map(|e| match e {
            // The guard ends a run by refusing its row; a stop without its reason is the sink's.
            IntegrateError::Stopped { .. } => guard
                .stop()
                .unwrap_or_else(|| run_error(e.clone(), &scene.state_names())),
            other => run_error(other.clone(), &scene.state_names()),
        });
        let stopped_at = match &result {
            Ok(reached) if reached.stopped => Some(reached.t),
            _ => None,
        };
        let (final_time, final_state) = match (result, rows.last.take()) {
            (Ok(end), _) => (end.t, end.state.as_slice().to_vec()),
            (Err(_), Some(last)) => last,
            (Err(_), None) => (0.0, scene.initial.clone()),
        };
        let report = Report {
            steps: stats.steps,
            rejected: stats.rejected,
            rhs_evals: stats.rhs_evals,
            wall_seconds,
            final_time,
            final_state,
            energy_drift: rows.drift(),
            warnings: [scene.integrator.warnings(), guard.warnings()].concat(),
            stopped_at,
        };
        Ended { report, error }
    }
}

fn step(scene: &BodyScene) -> f64 {
    scene
        .integrator
        .step
        .expect("a fixed-step method has a step")
}

/// The components symplectic Euler kicks first: the velocities of the model's state, read
/// from the catalog's layout by their units (m/s, rad/s), which every family keeps together.
fn kicked(scene: &BodyScene) -> Range<usize> {
    velocities(scene.selection.info.state)
}

/// The velocities of a state layout (the entries in m/s or rad/s), as the range they fill.
fn velocities(state: &[&str]) -> Range<usize> {
    let is_velocity =
        |name: &&str| matches!(crate::models::state_unit(name), Some("m/s" | "rad/s"));
    let first = state.iter().position(is_velocity).unwrap_or(0);
    let count = state.iter().filter(|n| is_velocity(n)).count();
    first..first + count
}

/// The scene's method with its settings.
fn stepper(scene: &BodyScene) -> Stepper {
    Stepper {
        method: scene.integrator.method,
        step: scene.integrator.step,
        adaptive: scene.integrator.adaptive,
        kicked: kicked(scene),
    }
}

/// The run cut at the breakpoints of the loads' time tables that fall inside it, each piece
/// integrated on its own with the loads read on that piece
/// ([`SceneLoads::prepared_on`](super::SceneLoads::prepared_on)), the rows going on
/// across the cuts; a scene without tables is one piece.
fn pieces<Mo: Model<f64, N, M>, const N: usize, const M: usize>(
    model: &Mo,
    scene: &BodyScene,
    y0: SVector<f64, N>,
    guard: &mut Guard,
    emit: &mut impl FnMut(f64, &SVector<f64, N>) -> bool,
) -> Piece<N> {
    let end = scene.integrator.end_time;
    let cuts = (scene.loads.breakpoints().into_iter())
        .filter(|t| *t > 0.0 && *t < end)
        .collect();
    let mut pieces = Pieces {
        model,
        scene,
        y0,
        guard,
        cuts,
        next: 0,
    };
    let observe = |(t, y): &(f64, SVector<f64, N>)| emit(*t, y);
    problem::solve(&mut pieces, (&stepper(scene), scene.every), observe)
}

/// A scene's run as the one loop runs it: cut at its load tables' breakpoints, the guard
/// checking every step, the stop condition ending it where it first holds.
struct Pieces<'a, Mo, const N: usize, const M: usize> {
    model: &'a Mo,
    scene: &'a BodyScene,
    y0: SVector<f64, N>,
    guard: &'a mut Guard,
    /// The breakpoints within the run, in order, and the index of the next.
    cuts: Vec<f64>,
    next: usize,
}

impl<'a, Mo: Model<f64, N, M>, const N: usize, const M: usize> Problem<N> for Pieces<'a, Mo, N, M> {
    type System = Driven<'a, Mo, PreparedLoads, M>;
    /// A scene watches for nothing but its stop condition.
    type Watch = Infallible;
    type Sample = (f64, SVector<f64, N>);

    /// A breakpoint changes the loads, not the state, and a row shows the state alone.
    const ROW_AT_CHANGE: bool = false;

    fn start(&mut self) -> (f64, SVector<f64, N>) {
        (0.0, self.y0)
    }

    fn end(&self) -> f64 {
        self.scene.integrator.end_time
    }

    fn next_change(&self) -> Option<f64> {
        self.cuts.get(self.next).copied()
    }

    /// The loads read on the piece from `t` to `until`.
    fn system(&self, t: f64, until: f64) -> Self::System {
        self.model.driven_by(self.scene.loads.prepared_on(t, until))
    }

    fn watches(&self, _: &Self::System, _: f64, _: &SVector<f64, N>) -> Vec<Infallible> {
        Vec::new()
    }

    fn g(&self, _: &Self::System, watch: Infallible, _: f64, _: &SVector<f64, N>) -> f64 {
        match watch {}
    }

    fn has_stop(&self) -> bool {
        self.scene.stop.is_some()
    }

    fn stop_holds(&self, t: f64, y: &SVector<f64, N>) -> bool {
        (self.scene.stop.as_ref()).is_some_and(|condition| condition.holds(t, y.as_slice()))
    }

    fn accepted(&mut self, t: f64, y: &SVector<f64, N>) -> bool {
        self.guard.check(t, y.as_slice())
    }

    fn change(&mut self, _: f64, _: &mut SVector<f64, N>) -> Flow {
        self.next += 1;
        Flow::Go
    }

    fn event(&mut self, watch: Infallible, _: f64, _: &mut SVector<f64, N>) -> Flow {
        match watch {}
    }

    fn sample(&self, t: f64, y: &SVector<f64, N>) -> Self::Sample {
        (t, *y)
    }
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

/// A spatial body free of moments about G with the Lie midpoint method: the rotation by the
/// geometric integrator, the translation exactly. The one run not solved by the one loop: the
/// geometric integrator steps a rotation ([`RigidRotation`]), not the model's right-hand side,
/// so it is driven over the one stretch driver (`segment::fixed_steps`) directly; a free body
/// has no schedule and no watches for the loop to add, only the stop condition the stretch
/// locates. Uniform gravity at G, the one load such a
/// scene may have, exerts no moment about G and accelerates G by g along +Z whatever the
/// attitude; so the velocity of G in space is V(t) = V₀ + g t Z, its position
/// x(t) = x₀ + V₀ t + ½ g t² Z, and its body components v(t) = R(t)ᵀ V(t).
fn free_rotation<const N: usize>(
    scene: &BodyScene,
    emit: &mut impl FnMut(f64, &SVector<f64, N>) -> bool,
) -> Piece<N> {
    let Body::Spatial { inertia, mass } = &scene.body else {
        unreachable!("lie-midpoint is refused for any scene but a spatial body");
    };
    debug_assert!(scene.loads.rotation_is_torque_free());
    let g = scene.loads.uniform_gravity_only().unwrap_or(0.0) / mass;
    let x = &scene.initial;
    let attitude =
        |s: &[f64]| UnitQuaternion::from_quaternion(Quaternion::new(s[0], s[1], s[2], s[3]));
    let velocity_in_space = attitude(&x[9..13]) * Vector3::new(x[0], x[1], x[2]);
    let position = Vector3::new(x[6], x[7], x[8]);
    // A free body's terms stand alone, so that its rows keep their bits (a −0 stays −0).
    let fall = Vector3::new(0.0, 0.0, g);
    let velocity_at = |t: f64| {
        if g == 0.0 {
            velocity_in_space
        } else {
            velocity_in_space + fall * t
        }
    };
    let position_at = |t: f64| {
        if g == 0.0 {
            position + velocity_in_space * t
        } else {
            position + velocity_in_space * t + fall * (0.5 * t * t)
        }
    };
    let whole = |t: f64, rotation: &SVector<f64, 7>| -> SVector<f64, N> {
        let q = attitude(&rotation.as_slice()[3..7]);
        let v = q.inverse() * velocity_at(t);
        let p = position_at(t);
        let mut state = SVector::<f64, N>::zeros();
        state.as_mut_slice()[..3].copy_from_slice(v.as_slice());
        state.as_mut_slice()[3..6].copy_from_slice(&rotation.as_slice()[..3]);
        state.as_mut_slice()[6..9].copy_from_slice(p.as_slice());
        state.as_mut_slice()[9..].copy_from_slice(&rotation.as_slice()[3..]);
        state
    };
    let start = SVector::<f64, 7>::from_iterator(x[3..6].iter().chain(&x[9..13]).copied());
    let system = FreeRotation {
        inertia: inertia.matrix(),
    };
    let mut method = LieMidpoint::new(step(scene));
    // Implicit midpoint is stable for every step on the imaginary axis, and the quaternion
    // has no singular attitude: nothing to check.
    let stop = scene
        .stop
        .as_ref()
        .map(|c| move |t: f64, r: &SVector<f64, 7>| c.holds(t, whole(t, r).as_slice()));
    let stop = stop
        .as_ref()
        .map(|f| f as &dyn Fn(f64, &SVector<f64, 7>) -> bool);
    let mut rows = RowClock::new(0.0, scene.every);
    let interval = (0.0, start, scene.integrator.end_time);
    let hooks = Hooks {
        check: &mut |_, _| true,
        stop,
        emit: &mut |t, r| emit(t, &whole(t, r)),
        row_at_end: true,
        row_at_stop: true,
    };
    let (result, stats) = segment::fixed_steps(&mut method, &system, interval, &mut rows, hooks);
    let whole_reached = |r: Reached<f64, 7>| Reached {
        t: r.t,
        state: whole(r.t, &r.state),
        stopped: r.stopped,
    };
    (result.map(whole_reached), stats)
}

/// An integration error as a run error, naming the state component or the load input.
fn run_error(error: IntegrateError, names: &[String]) -> RunError {
    match error {
        IntegrateError::NonFiniteState { component, t } => RunError::Integration {
            t,
            message: format!(
                "the state component {} is not finite",
                names.get(component).map_or("?", String::as_str)
            ),
        },
        IntegrateError::NonFiniteInput { name, value, t, .. } => RunError::Integration {
            t,
            message: format!(
                "the load input {name} is {value} at a finite state: the loads, not the \
                 model, made the run non-finite"
            ),
        },
        // The run's error says the time once: these messages leave it out.
        IntegrateError::StepSizeTooSmall { t, .. }
        | IntegrateError::MaxStepsExceeded { t, .. }
        | IntegrateError::NotConverged { t, .. }
        | IntegrateError::Stopped { t } => RunError::Integration {
            t,
            message: error.without_time(),
        },
        other => RunError::Integration {
            t: f64::NAN,
            message: other.to_string(),
        },
    }
}

#[cfg(test)]
mod tests {
    use crate::models::{CATALOG, Family};

    /// Every catalog layout keeps its velocities together, where symplectic Euler kicks
    /// them: the rates of the pendulum's angle, of a planar body in body or space axes, of a
    /// spatial body's velocity and rate, of a top's rate.
    #[test]
    fn each_layouts_velocities_are_one_range() {
        for info in CATALOG {
            let range = super::velocities(info.state);
            let wanted = match info.family {
                Family::Pendulum => 1..2,
                Family::PlanarAtG | Family::PlanarMidship => 0..3,
                Family::PlanarSpaceFixed => 3..6,
                Family::Spatial => 0..6,
                Family::Top => 0..3,
            };
            assert_eq!(range, wanted, "{}", info.name);
            for (i, name) in info.state.iter().enumerate() {
                let unit = crate::models::state_unit(name);
                let velocity = matches!(unit, Some("m/s" | "rad/s"));
                assert_eq!(velocity, range.contains(&i), "{}: {name}", info.name);
            }
        }
    }
}
