//! The standard manoeuvres as schedules and events over the one driver, and their figures.
//!
//! A manoeuvre is the ship model ([`ShipModel`], a [`Model`] like the catalog's) under the
//! steering gear's loads ([`Steering`]: the rudder's rate from its command), a `Problem`
//! solved by the one loop every run is solved by (`integrate::problem::solve`, over the one
//! driver, with any of its methods). The run is cut into stretches at the instants its
//! **schedule** changes the command (the execute, a pull-out's release, a series'
//! breakpoints) and at its **events**, instants the state defines: the heading has changed by
//! 90° (advance, transfer), the heading has passed ±ψ_a (the zig-zag reverses the rudder), the
//! yaw rate is zero (an overshoot is largest). An event is a zero crossing of a function g of the state (`Watch`), located by the driver where g
//! first has changed sign, to adjacent floating-point numbers of t on the integrator's own
//! solution (the dense output of an adaptive method, the step taken again for a fixed-step
//! one). So the figures are those of the integrated solution at the crossing, not at the
//! nearest step, and a zig-zag reverses its rudder where the rule says.
//!
//! The trajectory's rows are at t = k·every, as every scene's are, at each event, and at each
//! instant the schedule changes the command.
//!
//! A ship with a propulsion model turns its propeller at the approach's rate n₀ through every
//! manoeuvre but the crash stop, whose engine command goes from n₀ to full astern at the
//! engine's rate limit from the execute ([`RateCommand`]: the instants where n passes zero and
//! reaches full astern are the schedule's), the rudder amidships, until the event where the
//! ship stops (u = 0).
//!
//! A scene's stop condition (`integrator.stop_when`, on a row's names: `u < 1`, `t > 200`)
//! ends each run where it first holds, located as an event is. A figure the run had not read
//! by then is not given, and a note says where the run stopped and what it had not read: a
//! figure read where an event fell before the stop is the unstopped run's, while one read at
//! the end of the run (a steady turn, a pull-out's final yaw rate) would be read at the stop
//! instead, and is not given either.

use super::ShipError;
use super::mmg::MidshipState;
use super::model::ShipModel;
use super::propulsion::RateCommand;
use super::side::Side;
use super::spiral::{self, Progress, ReverseSpiral, Spiral, SpiralCurve};
use super::steady::steady_turns;
use crate::integrate::problem::{self, Flow, Problem};
use crate::integrate::{IntegrateError, OdeSystem, Stepper};
use crate::manoeuvring::course::Course;
use crate::manoeuvring::steering::{Rudder, Series};
use crate::models::{Driven, Loads, Model};
use crate::scene::stop::StopCondition;
use nalgebra::SVector;
use std::f64::consts::PI;

mod figures;
mod steering;
mod watch;

use steering::Command;
pub use steering::Steering;
use watch::Watch;

/// What the rudder does.
#[derive(Debug, Clone, PartialEq)]
pub enum ManoeuvreKind {
    /// The rudder to `rudder` (rad) at the execute, held: advance, transfer, tactical diameter,
    /// the steady turn.
    TurningCircle {
        /// δ, rad.
        rudder: f64,
    },
    /// The rudder to `rudder` at the execute, reversed each time the heading change passes
    /// ±`heading` (rad), to the side the rudder turns the ship.
    ZigZag {
        /// δ_a, rad.
        rudder: f64,
        /// ψ_a, rad.
        heading: f64,
    },
    /// The rudder to `rudder` at the execute and back to zero at `release` (s): whether the
    /// yaw rate dies out (a course-stable ship) or settles to a residual turn.
    PullOut {
        /// δ, rad.
        rudder: f64,
        /// When the rudder returns to zero, s.
        release: f64,
    },
    /// The command a piecewise-linear series of the scene gives.
    Series(Series),
    /// Dieudonné's direct spiral: each angle held until r settles, and back
    /// ([`super::spiral`]).
    Spiral(Spiral),
    /// Bech's reverse spiral: each yaw rate held by a controller on the rudder.
    ReverseSpiral(ReverseSpiral),
    /// The crash stop: from the approach at n₀, the propeller commanded to `astern` (rev/s,
    /// negative) at the execute, reached at the engine's rate limit, the rudder amidships;
    /// the run ends where the ship stops (u = 0): track reach, head reach, lateral deviation
    /// and the time to stop.
    CrashStop {
        /// The full-astern rate, rev/s.
        astern: f64,
    },
}

impl ManoeuvreKind {
    /// The same with the rudder put over to the other side (a turn's, a zig-zag's, a
    /// pull-out's angle); the others as they are.
    fn mirrored(&self) -> ManoeuvreKind {
        let mut kind = self.clone();
        match &mut kind {
            ManoeuvreKind::TurningCircle { rudder }
            | ManoeuvreKind::ZigZag { rudder, .. }
            | ManoeuvreKind::PullOut { rudder, .. } => *rudder = -*rudder,
            _ => {}
        }
        kind
    }
}

/// One manoeuvre of a scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Manoeuvre {
    /// Its name, for the output folder and the summary.
    pub name: String,
    /// What the rudder does.
    pub kind: ManoeuvreKind,
    /// When the rudder is put over, s (the figures are measured from here).
    pub execute: f64,
    /// The end of the run, s (a spiral's ends sooner once every angle is measured).
    pub duration: f64,
    /// The sides it is run to, each as a run of its own ([`super::side`]): both, or one, the
    /// rudder of `kind` turning the ship to the first; empty for a manoeuvre run as given.
    pub sides: Vec<Side>,
}

impl Manoeuvre {
    /// The runs it stands for: one per side, the rudder put to that side, each with that
    /// one side; or itself, for a manoeuvre of no side.
    pub fn runs(&self) -> Vec<(Option<Side>, Manoeuvre)> {
        let Some(&first) = self.sides.first() else {
            return vec![(None, self.clone())];
        };
        self.sides
            .iter()
            .map(|&side| {
                let kind = if side == first {
                    self.kind.clone()
                } else {
                    self.kind.mirrored()
                };
                let run = Manoeuvre {
                    kind,
                    sides: vec![side],
                    ..self.clone()
                };
                (Some(side), run)
            })
            .collect()
    }
}

/// The state a manoeuvre integrates: the model's seven and the distance run by midship.
pub type DriveState = SVector<f64, 8>;

/// One instant of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// t, s.
    pub t: f64,
    /// u, v, r, X, Y, ψ, δ, and the distance run (m).
    pub state: [f64; 8],
    /// The rudder command after saturation, rad.
    pub command: f64,
}

/// What a manoeuvre's row holds after its time, by name: the model's state in its order
/// ([`STATE`](super::model::STATE), in identifiers: `x` for X), then the rudder command after saturation and the
/// distance run ([`Sample::row`]).
pub const ROW: [&str; 9] = [
    "u", "v", "r", "x", "y", "psi", "delta", "command", "distance",
];

/// The columns of a manoeuvre's `trajectory.csv`, as every run's trajectory writer labels
/// them ([`crate::models::with_unit`]): t, [`ROW`], and the rigid body's kinetic energy.
pub fn trajectory_columns() -> Vec<String> {
    crate::output::trajectory::header(&ROW, false)
}

impl Sample {
    /// The row after its time, in [`ROW`]'s order.
    pub fn row(&self) -> [f64; 9] {
        let [u, v, r, x, y, psi, delta, distance] = self.state;
        [u, v, r, x, y, psi, delta, self.command, distance]
    }

    /// The model's seven state entries.
    pub fn model_state(&self) -> [f64; 7] {
        std::array::from_fn(|i| self.state[i])
    }
}

/// The figures of a manoeuvre, as (JSON key, value) pairs; `None` where the run did not get
/// there (a turn that never reached 180°).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Figures {
    /// Each figure by its key, in the order written.
    pub values: Vec<(&'static str, Option<f64>)>,
    /// `"port"` or `"starboard"`, for a turn.
    pub side: Option<&'static str>,
    /// What the run could not measure, and why.
    pub notes: Vec<String>,
    /// Points of the track to mark on its plot: (what, [X, Y]).
    pub marks: Vec<(String, [f64; 2])>,
    /// A spiral's r–δ curve.
    pub spiral: Option<SpiralCurve>,
}

impl Figures {
    /// The value of a figure, if the run measured it.
    pub fn get(&self, key: &str) -> Option<f64> {
        self.values
            .iter()
            .find(|(k, _)| *k == key)
            .and_then(|(_, v)| *v)
    }
}

/// The ship under its steering, with the distance run by midship as an eighth state
/// (ṡ = U = √(u² + v²)), integrated with the rest for the zig-zag's initial turning distance.
struct Tracked<'a> {
    driven: Driven<'a, ShipModel, Steering<'a>, 3>,
}

impl OdeSystem<f64, 8> for Tracked<'_> {
    // Inlined into the method's step wherever the loop's stretches are compiled, as into the
    // ship's own loop it was.
    #[inline]
    fn rhs(&self, t: f64, y: &DriveState, dy: &mut DriveState) {
        let state = SVector::<f64, 7>::from_fn(|i, _| y[i]);
        let mut rates = SVector::<f64, 7>::zeros();
        self.driven.rhs(t, &state, &mut rates);
        let distance = (y[0] * y[0] + y[1] * y[1]).sqrt();
        // Written whole, so that the integrator's reads of the rates, two at a time, find
        // them in as wide stores.
        *dy = SVector::from_fn(|i, _| if i < 7 { rates[i] } else { distance });
    }

    /// A load input that is not finite, or an MMG ship's state outside the paper's model
    /// (astern, the propeller stopped), with the reason.
    fn explain_non_finite(&self, t: f64, y: &DriveState) -> Option<IntegrateError> {
        let state = SVector::<f64, 7>::from_fn(|i, _| y[i]);
        if let Some(load) = self.driven.explain_non_finite(t, &state) {
            return Some(load);
        }
        let mmg = self.driven.model().mmg()?;
        let input = self.driven.loads().at(t, &state.data.0[0]);
        let error = mmg.loads([y[0], y[1], y[2], y[6], input[1]]).err()?;
        Some(IntegrateError::OutsideModel {
            reason: format!("the MMG forces: {error}"),
            t,
        })
    }
}

/// A manoeuvre run: where the ship went, and the figures.
#[derive(Debug, Clone)]
pub struct ManoeuvreRun {
    /// The figures, under the manoeuvre's kind.
    pub figures: Figures,
    /// Steps taken.
    pub steps: u64,
    /// Evaluations of the right-hand side.
    pub rhs_evals: u64,
    /// Where the stop condition ended the run, s; `None` where it did not.
    pub stopped_at: Option<f64>,
}

/// The record the driver keeps of a manoeuvre's events.
#[derive(Debug, Default)]
struct Log {
    /// The state at the execute.
    execute: Option<DriveState>,
    /// The state at a pull-out's release.
    release: Option<DriveState>,
    /// (t, state) at each watch that fired, in order, with what fired.
    events: Vec<(Watch, f64, DriveState)>,
    /// The course from the execute on, for the conditions the figures assume.
    course: Option<Course>,
}

/// The key that names the stop condition, for the notes.
const STOP_KEY: &str = "integrator.stop_when";

/// The names of a [`DriveState`]'s entries, for messages.
const DRIVE_STATE: [&str; 8] = ["u", "v", "r", "X", "Y", "psi", "delta", "distance"];

/// Runs a manoeuvre from `start` (the model's seven states) with `stepper`'s method, handing
/// each row (at t = k·`every` and at each event) to `observe`, which returns whether to go on
/// (false ends the run, an error that says it was stopped: Ctrl-C).
pub fn run(
    model: &ShipModel,
    rudder: &Rudder,
    manoeuvre: &Manoeuvre,
    start: [f64; 7],
    (stepper, every): (&Stepper, f64),
    observe: impl FnMut(&Sample) -> bool,
) -> Result<ManoeuvreRun, ShipError> {
    let settings = (stepper, every);
    run_until(model, rudder, manoeuvre, (start, None), settings, observe)
}

/// [`run`], ended where `stop` first holds on a row (t and [`ROW`]'s names), if it is given:
/// the last row is there, [`ManoeuvreRun::stopped_at`] says when, and the figures the run had
/// not read by then are not given (a note says so).
pub fn run_until(
    model: &ShipModel,
    rudder: &Rudder,
    manoeuvre: &Manoeuvre,
    (start, stop): ([f64; 7], Option<&StopCondition>),
    (stepper, every): (&Stepper, f64),
    observe: impl FnMut(&Sample) -> bool,
) -> Result<ManoeuvreRun, ShipError> {
    let mut y = DriveState::zeros();
    for (i, value) in start.iter().enumerate() {
        y[i] = *value;
    }
    let engine = model.propulsion().map(|propulsion| {
        let from = propulsion.approach_rate;
        let target = match manoeuvre.kind {
            ManoeuvreKind::CrashStop { astern } => astern,
            _ => from,
        };
        RateCommand {
            from,
            target,
            execute: manoeuvre.execute,
            max_rate: propulsion.max_rate,
        }
    });
    let mut driver = Driver {
        model,
        rudder,
        engine,
        manoeuvre,
        command: 0.0,
        watches: Vec::new(),
        switches: 0,
        side: 0.0,
        log: Log::default(),
        spiral: None,
        start: y,
        times: Vec::new(),
        pending: None,
        stop,
        stopped: None,
    };
    driver.times = driver.command_times();
    let (reached, stats) = problem::solve(&mut driver, (stepper, every), observe);
    let end = reached.map_err(|error| run_error(error, stepper))?;
    if end.stopped {
        // The course ends where the run does, as it does at the end of a whole run.
        driver.catch_up(end.t);
        driver.record(end.t, &end.state);
        driver.stopped = Some(end.t);
    }
    Ok(ManoeuvreRun {
        figures: driver.figures((end.t, &end.state)),
        steps: stats.steps as u64,
        rhs_evals: stats.rhs_evals as u64,
        stopped_at: driver.stopped,
    })
}

/// A manoeuvre as the one loop runs it: the schedule's instants, the events it watches for
/// (and the steering gear's rate limit), the rows with the command, the course from every
/// accepted step.
impl<'a> Problem<8> for Driver<'a> {
    type System = Tracked<'a>;
    type Watch = Watch;
    type Sample = Sample;

    fn start(&mut self) -> (f64, DriveState) {
        let mut y = self.start;
        self.apply_times(0.0, &mut y);
        (0.0, y)
    }

    fn end(&self) -> f64 {
        self.manoeuvre.duration
    }

    fn next_change(&self) -> Option<f64> {
        self.times.first().copied()
    }

    fn system(&self, _t: f64, _until: f64) -> Tracked<'a> {
        self.system()
    }

    fn watches(&self, system: &Tracked<'a>, t: f64, y: &DriveState) -> Vec<Watch> {
        let mut watches = self.watches.clone();
        if (system.driven.loads().rate_margin(t, y[2], y[6])).is_some() {
            watches.push(Watch::RateLimit);
        }
        if self.model.mmg().is_some() {
            watches.extend([Watch::InflowSide(0), Watch::InflowSide(1)]);
        }
        watches
    }

    fn g(&self, system: &Tracked<'a>, watch: Watch, t: f64, y: &DriveState) -> f64 {
        match watch {
            Watch::RateLimit => (system.driven.loads().rate_margin(t, y[2], y[6])).unwrap_or(0.0),
            // Zero (not watched) where the model has no angles: the run reports that state.
            Watch::InflowSide(which) => (self.model.mmg())
                .and_then(|mmg| {
                    let state = MidshipState {
                        u: y[0],
                        v_m: y[1],
                        r: y[2],
                    };
                    mmg.parameters.inflow_angles(state).ok()
                })
                .map_or(0.0, |angles| angles[which]),
            other => other.g(y, self.heading0(), self.heading_a()),
        }
    }

    fn has_stop(&self) -> bool {
        self.stop.is_some()
    }

    /// The scene's condition on the row at `(t, y)`, as trajectory.csv writes it.
    fn stop_holds(&self, t: f64, y: &DriveState) -> bool {
        (self.stop).is_some_and(|stop| stop.holds(t, &self.sample(t, y).row()))
    }

    fn accepted(&mut self, t: f64, y: &DriveState) -> bool {
        if let Some((time, state)) = self.pending.replace((t, *y)) {
            self.record(time, &state);
        }
        true
    }

    /// An event of the manoeuvre; at the steering gear's own only the form of δ̇ changes.
    fn event(&mut self, watch: Watch, t: f64, y: &mut DriveState) -> Flow {
        self.catch_up(t);
        if !watch.is_kink() {
            self.fire(watch, t, y);
        }
        self.settle(t, y)
    }

    fn change(&mut self, t: f64, y: &mut DriveState) -> Flow {
        self.catch_up(t);
        self.apply_times(t, y);
        self.settle(t, y)
    }

    /// The instant is recorded, as one the run goes on from.
    fn resumed(&mut self, t: f64, y: &DriveState) {
        self.catch_up(t);
        self.record(t, y);
    }

    fn finish(&mut self, t: f64, y: &DriveState) {
        self.catch_up(t);
        self.settle(t, y);
    }

    /// The state and the saturated command as it stands.
    fn sample(&self, t: f64, y: &DriveState) -> Sample {
        Sample {
            t,
            state: std::array::from_fn(|i| y[i]),
            command: self.system().driven.loads().command(t, y[2]).0,
        }
    }
}

/// A failed stretch as a ship's error, naming the state entry or the cause.
fn run_error(error: IntegrateError, stepper: &Stepper) -> ShipError {
    match error {
        IntegrateError::NonFiniteState { component, t } => ShipError::Run {
            time: t,
            reason: format!(
                "{} is not finite (the prime system's forces are undefined where the speed U \
                 is zero; {} may also be too coarse for this ship)",
                DRIVE_STATE.get(component).unwrap_or(&"?"),
                match stepper.step {
                    Some(step) => format!("a step of {step} s"),
                    None => "the tolerances".to_owned(),
                }
            ),
        },
        other => ShipError::Run {
            time: other.time().unwrap_or(f64::NAN),
            reason: other.without_time(),
        },
    }
}

/// The run's moving parts: the command, what it watches for, what it has seen.
struct Driver<'a> {
    model: &'a ShipModel,
    rudder: &'a Rudder,
    /// The propeller-rate command, for a ship with a propulsion model.
    engine: Option<RateCommand>,
    manoeuvre: &'a Manoeuvre,
    /// The held command (rad), before saturation.
    command: f64,
    watches: Vec<Watch>,
    /// Zig-zag reversals so far.
    switches: u32,
    /// The side (±1) of the heading change at the first reversal.
    side: f64,
    log: Log,
    /// A spiral under way.
    spiral: Option<Progress>,
    /// The state the run starts from.
    start: DriveState,
    /// The instants the command changes from here on, in order.
    times: Vec<f64>,
    /// The last accepted step, not yet recorded: the steps past where a stretch ends are
    /// its trial, not the ship's course.
    pending: Option<(f64, DriveState)>,
    /// The scene's stop condition, if it has one.
    stop: Option<&'a StopCondition>,
    /// Where it ended the run, s.
    stopped: Option<f64>,
}

impl<'a> Driver<'a> {
    /// The ship under the command as it stands.
    fn system(&self) -> Tracked<'a> {
        let command = match (&self.manoeuvre.kind, &self.spiral) {
            (ManoeuvreKind::Series(series), _) => Command::Series(series),
            (ManoeuvreKind::ReverseSpiral(reverse), Some(progress)) => Command::Track {
                integral: progress.integral,
                gain: reverse.gain,
                target: progress.setpoint().unwrap_or(0.0),
            },
            _ => Command::Hold(self.command),
        };
        let steering = Steering {
            rudder: self.rudder,
            command,
            engine: self.engine,
            held_rate: self.model.approach_rate(),
            gust: (self.model.wind()).and_then(|wind| wind.wind.gust.as_ref()),
        };
        Tracked {
            driven: self.model.driven_by(steering),
        }
    }

    fn heading0(&self) -> f64 {
        self.log.execute.map_or(0.0, |y| y[5])
    }

    fn heading_a(&self) -> f64 {
        match self.manoeuvre.kind {
            ManoeuvreKind::ZigZag { heading, .. } => heading,
            _ => 0.0,
        }
    }

    /// The instants where the command changes, in order, within the run.
    fn command_times(&self) -> Vec<f64> {
        let mut times = vec![self.manoeuvre.execute];
        match &self.manoeuvre.kind {
            ManoeuvreKind::PullOut { release, .. } => times.push(*release),
            ManoeuvreKind::Series(series) => times.extend_from_slice(series.breakpoints()),
            ManoeuvreKind::CrashStop { .. } => {
                times.extend(self.engine.iter().flat_map(RateCommand::breakpoints));
            }
            _ => {}
        }
        times.retain(|&t| t <= self.manoeuvre.duration);
        times.sort_by(f64::total_cmp);
        times.dedup();
        times
    }

    /// Applies every command change due at `t`.
    fn apply_times(&mut self, t: f64, y: &mut DriveState) {
        while self.times.first().is_some_and(|&time| time <= t) {
            let time = self.times.remove(0);
            if time == self.manoeuvre.execute {
                self.execute(y);
                if let Some(window) = self.settle_window() {
                    self.times.push(time + window);
                    self.times.sort_by(f64::total_cmp);
                }
            }
            if let ManoeuvreKind::PullOut { release, .. } = self.manoeuvre.kind
                && time == release
            {
                self.log.release = Some(*y);
                self.set_command(0.0, y);
            }
            if let ManoeuvreKind::Series(series) = &self.manoeuvre.kind
                && self.rudder.time_constant.is_none()
            {
                y[6] = self.rudder.saturate(series.angle(time));
            }
            if time > self.manoeuvre.execute {
                self.check_spiral(time, y);
            }
        }
    }

    /// A spiral's check at `t`: the setpoint's point taken if it has settled, the next put on,
    /// and the next check scheduled.
    fn check_spiral(&mut self, t: f64, y: &mut DriveState) {
        let (settle, gain) = match &self.manoeuvre.kind {
            ManoeuvreKind::Spiral(spiral) => (spiral.settle, None),
            ManoeuvreKind::ReverseSpiral(reverse) => (reverse.settle, Some(reverse.gain)),
            _ => return,
        };
        let Some(progress) = &mut self.spiral else {
            return;
        };
        progress.check(t, &settle, gain);
        // No wind-up: the integral part stays within the rudder's reach.
        let reach = self.rudder.max_angle.unwrap_or(std::f64::consts::FRAC_PI_2);
        progress.integral = progress.integral.clamp(-reach, reach);
        if let Some(setpoint) = progress.setpoint() {
            if gain.is_none() {
                self.set_command(setpoint, y);
            }
            self.times.push(t + settle.window);
            self.times.sort_by(f64::total_cmp);
        }
    }

    /// A spiral's window: the interval of its checks.
    fn settle_window(&self) -> Option<f64> {
        match &self.manoeuvre.kind {
            ManoeuvreKind::Spiral(spiral) => Some(spiral.settle.window),
            ManoeuvreKind::ReverseSpiral(reverse) => Some(reverse.settle.window),
            _ => None,
        }
    }

    /// Whether the ship has stopped in a crash stop (the event that ends it).
    fn stopped(&self) -> bool {
        self.event(Watch::Stopped).is_some()
    }

    /// Whether a spiral has measured every setpoint.
    fn spiral_done(&self) -> bool {
        self.spiral.as_ref().is_some_and(|p| p.setpoint().is_none())
    }

    /// A spiral's start at the execute: its first setpoint on, its first check scheduled.
    fn start_spiral(&mut self, y: &mut DriveState, mut progress: Progress) {
        let t = self.manoeuvre.execute;
        if let (ManoeuvreKind::Spiral(_), Some(angle)) = (&self.manoeuvre.kind, progress.setpoint())
        {
            self.set_command(angle, y);
        }
        progress.start(spiral_sample(t, y));
        self.spiral = Some(progress);
    }

    fn set_command(&mut self, angle: f64, y: &mut DriveState) {
        self.command = angle;
        if self.rudder.time_constant.is_none() {
            y[6] = self.rudder.saturate(angle);
        }
    }

    /// Records the stretch's last step if it came before `t`, where the stretch ended: a
    /// step past it is the stretch's trial, not the ship's course. Before what happens at `t`.
    fn catch_up(&mut self, t: f64) {
        if let Some((time, state)) = self.pending.take().filter(|(time, _)| *time < t) {
            self.record(time, &state);
        }
    }

    /// Records the instant `(t, y)` as the run goes on from it, after what happened there;
    /// a spiral that has measured every setpoint, or a crash stop's ship that has stopped,
    /// ends the run.
    fn settle(&mut self, t: f64, y: &DriveState) -> Flow {
        self.record(t, y);
        if self.spiral_done() || self.stopped() {
            Flow::Stop
        } else {
            Flow::Go
        }
    }

    /// Adds the instant to the course, from the execute on.
    fn record(&mut self, t: f64, y: &DriveState) {
        if let Some(progress) = &mut self.spiral {
            progress.record(spiral_sample(t, y));
        }
        let heading0 = self.heading0();
        if let Some(course) = &mut self.log.course {
            course.record(t, y[0], y[1], y[2], y[5] - heading0);
        }
    }

    fn execute(&mut self, y: &mut DriveState) {
        self.log.execute = Some(*y);
        let held = matches!(self.manoeuvre.kind, ManoeuvreKind::TurningCircle { .. });
        self.log.course = Some(Course::new(y[0].hypot(y[1]), held));
        match self.manoeuvre.kind {
            ManoeuvreKind::TurningCircle { rudder } => {
                self.set_command(rudder, y);
                self.watches = vec![Watch::HeadingChange(PI / 2.0), Watch::HeadingChange(PI)];
                if self.model.drifts() {
                    // A drifting circle: its first and second whole turns.
                    let turns = [2.0 * PI, 4.0 * PI].map(Watch::HeadingChange);
                    self.watches.extend(turns);
                }
            }
            ManoeuvreKind::ZigZag { rudder, heading } => {
                self.set_command(rudder, y);
                self.watches = vec![Watch::HeadingChange(heading)];
            }
            ManoeuvreKind::PullOut { rudder, .. } => self.set_command(rudder, y),
            ManoeuvreKind::Series(_) => {}
            ManoeuvreKind::Spiral(ref spiral) => {
                self.start_spiral(y, Progress::direct(spiral));
            }
            ManoeuvreKind::ReverseSpiral(ref reverse) => {
                self.start_spiral(y, Progress::reverse(reverse));
            }
            ManoeuvreKind::CrashStop { .. } => {
                self.set_command(0.0, y);
                self.watches = vec![Watch::Stopped];
            }
        }
    }

    fn fire(&mut self, watch: Watch, t: f64, y: &mut DriveState) {
        self.watches.retain(|w| *w != watch);
        self.log.events.push((watch, t, *y));
        if let ManoeuvreKind::ZigZag { .. } = self.manoeuvre.kind {
            match watch {
                Watch::HeadingChange(_) | Watch::HeadingOnSide(_) => {
                    if self.switches == 0 {
                        self.side = (y[5] - self.heading0()).signum();
                    }
                    self.switches += 1;
                    self.set_command(-self.command, y);
                    // The next reversal is on the other side; the overshoot is where r = 0.
                    let next_side = if self.switches % 2 == 1 {
                        -self.side
                    } else {
                        self.side
                    };
                    self.watches = vec![Watch::HeadingOnSide(next_side), Watch::YawRateZero];
                }
                Watch::YawRateZero | Watch::RateLimit | Watch::Stopped | Watch::InflowSide(_) => {}
            }
        }
    }
}

/// The instant a spiral's window records: t, r, δ and the speed u.
fn spiral_sample(t: f64, y: &DriveState) -> spiral::Sample {
    spiral::Sample {
        t,
        r: y[2],
        delta: y[6],
        u: y[0],
    }
}
