//! A vehicle's manoeuvre: its fins under step commands or under the autopilots, a `Problem`
//! solved by the one loop every run is solved by (`integrate::problem::solve`, over the one
//! driver, any method), and the figures read where the commands change.
//!
//! The run is cut into stretches at the instants the commands change (the steps, the
//! setpoints, and the autopilots' samples, [`super::autopilot`]), so each stretch holds its
//! commands and ends exactly at the next change: the figures of a step (the yaw rate, the
//! speed, the roll and pitch, the depth reached when it ends) are those of the integrated
//! solution at that instant, not at the nearest step. The trajectory's rows are at
//! t = k·every, as every scene's are, and at each change of the commands.
//!
//! A scene's stop condition (`integrator.stop_when`, on a row's names: `z > 20`, `t > 30`)
//! ends the run where it first holds, located as an event is, with its last row there. The
//! step of the commands it cut short has no end to read its figures at, so the run keeps
//! only the steps that ended before it ([`VehicleRun::stopped_at`] says where it stopped).

use super::VehicleError;
use super::autopilot::{Autopilots, Controller, Feedforward, Setpoints};
use super::fins::{FinSteps, Fins, Steering};
use super::model::VehicleModel;
use super::trial::{Progress, Trial, Watch};
use super::trim::{Held, Trim};
use crate::integrate::problem::{self, Flow, Problem};
use crate::integrate::{IntegrateError, Stepper};
use crate::models::{Driven, Model};
use crate::scene::stop::StopCondition;
use nalgebra::SVector;

/// One manoeuvre of a scene: the fins' steps, from its trim, and the autopilots with what
/// they are commanded to hold.
#[derive(Debug, Clone, PartialEq)]
pub struct VehicleManoeuvre {
    /// Its name, for the output folder and the summary.
    pub name: String,
    /// The fins' commands (of a fin whose autopilot is on, overridden by it).
    pub steps: FinSteps,
    /// The autopilots and their setpoints, for an autopiloted manoeuvre.
    pub autopilot: Option<(Autopilots, Setpoints)>,
    /// The standard trial it is, if it is one: its events and figures.
    pub trial: Option<Trial>,
    /// The end of the run, s.
    pub duration: f64,
    /// The steady motion it starts from ([`super::trim`]), its autopilots holding what they
    /// hold from the start.
    pub trim: Trim,
}

impl VehicleManoeuvre {
    /// What its autopilots hold from its start: each one given a setpoint holds, before the
    /// first, the start's heading or depth.
    pub fn held(&self) -> Held {
        self.autopilot
            .as_ref()
            .map_or_else(Held::default, |(_, setpoints)| Held {
                heading: setpoints.heading_deg.is_some(),
                depth: setpoints.depth.is_some(),
            })
    }
}

/// The state a run integrates.
pub type VehicleState = SVector<f64, 15>;

/// One instant of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// t, s.
    pub t: f64,
    /// The model's state ([`super::model::STATE`]).
    pub state: [f64; 15],
    /// The fins' commands after saturation, rad.
    pub commands: [f64; 2],
}

/// What a row holds after its time, by name: the model's state, the fins' commands, the Euler
/// angles of the attitude (for reading; the run carries the quaternion).
pub const ROW: [&str; 20] = [
    "u",
    "v",
    "w",
    "p",
    "q",
    "r",
    "x",
    "y",
    "z",
    "q0",
    "q1",
    "q2",
    "q3",
    "dr",
    "ds",
    "dr_command",
    "ds_command",
    "phi",
    "theta",
    "psi",
];

/// The columns of a manoeuvre's `trajectory.csv`: t, [`ROW`], and the kinetic energy of the
/// body and the fluid.
pub fn trajectory_columns() -> Vec<String> {
    crate::output::trajectory::header(&ROW, false)
}

impl Sample {
    /// The row after its time, in [`ROW`]'s order.
    pub fn row(&self) -> [f64; 20] {
        let [phi, theta, psi] = euler_angles(&self.state);
        std::array::from_fn(|i| match i {
            0..15 => self.state[i],
            15 | 16 => self.commands[i - 15],
            17 => phi,
            18 => theta,
            _ => psi,
        })
    }
}

/// The state reflected in the body's x–z plane: v, p, r, y, q1, q3 and the fins change sign.
/// A vehicle symmetric about that plane, without a propeller torque, runs a manoeuvre's mirror
/// ([`FinSteps::mirrored`]) through the mirrored states.
pub fn mirrored(state: &[f64; 15]) -> [f64; 15] {
    const ODD: [usize; 8] = [1, 3, 5, 7, 10, 12, 13, 14];
    std::array::from_fn(|i| {
        if ODD.contains(&i) {
            -state[i]
        } else {
            state[i]
        }
    })
}

/// Roll, pitch and yaw (φ, θ, ψ, rad; Z·Y·X) of the state's quaternion, scaled to unit length.
pub fn euler_angles(state: &[f64; 15]) -> [f64; 3] {
    let [q0, q1, q2, q3] = [state[9], state[10], state[11], state[12]];
    let norm = q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3;
    [
        (2.0 * (q0 * q1 + q2 * q3)).atan2(q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3),
        (2.0 * (q0 * q2 - q1 * q3) / norm).clamp(-1.0, 1.0).asin(),
        (2.0 * (q0 * q3 + q1 * q2)).atan2(q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3),
    ]
}

/// Where the run stood when a command changed or the run ended: the figures of the step that
/// ends there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepEnd {
    /// t, s.
    pub t: f64,
    /// The state just before the change.
    pub state: [f64; 15],
    /// The commands that held up to here (rad, saturated).
    pub commands: [f64; 2],
}

/// Where an autopilot's error stood at one of its samples.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tracked {
    /// t, s.
    pub t: f64,
    /// The heading ψ and depth z then (degrees, m).
    pub value: (f64, f64),
    /// What the autopilots were commanded to hold (degrees, m; `None` where off).
    pub setpoint: (Option<f64>, Option<f64>),
}

/// A manoeuvre run: where the commands changed and the run ended, and what it cost.
#[derive(Debug, Clone)]
pub struct VehicleRun {
    /// The state at the end of each step of the commands (the first: the cruise before the
    /// first change), in order, the last at the end of the run. Under an autopilot the steps
    /// are those of the manoeuvre's fin steps and setpoints, not its samples.
    pub ends: Vec<StepEnd>,
    /// Under an autopilot, the heading and depth at each of its samples and at the end.
    pub tracked: Vec<Tracked>,
    /// A trial's events and course.
    pub trial: Option<Progress>,
    /// Steps taken.
    pub steps: u64,
    /// Evaluations of the right-hand side.
    pub rhs_evals: u64,
    /// Where the stop condition ended the run, s; `None` where it did not. A stopped run's
    /// `ends` and `tracked` stop before it: the step it cut short did not end.
    pub stopped_at: Option<f64>,
}

/// Runs a manoeuvre from `start` with `stepper`'s method, handing each row (at t = k·`every`
/// and at each change of the commands) to `observe`, which returns whether to go on (false
/// ends the run, an error that says it was stopped: Ctrl-C).
pub fn run(
    model: &VehicleModel,
    fins: &Fins,
    manoeuvre: &VehicleManoeuvre,
    start: [f64; 15],
    (stepper, every): (&Stepper, f64),
    observe: impl FnMut(&Sample) -> bool,
) -> Result<VehicleRun, VehicleError> {
    let settings = (stepper, every);
    run_until(model, fins, manoeuvre, (start, None), settings, observe)
}

/// The first row of `manoeuvre` from `start`: the state with the fins without a lag at their
/// first commands, and those commands (the autopilots' first sample).
pub fn first_row(fins: &Fins, manoeuvre: &VehicleManoeuvre, start: [f64; 15]) -> Sample {
    let mut y = VehicleState::from(start);
    let mut command = Command::new(manoeuvre, &start);
    let steering = command.at(fins, 0.0, &mut y, true);
    Sample {
        t: 0.0,
        state: y.data.0[0],
        commands: steering.saturated(),
    }
}

/// [`run`], ended where `stop` first holds on a row (t and [`ROW`]'s names), if it is given:
/// the last row is there, and [`VehicleRun::stopped_at`] says when.
pub fn run_until(
    model: &VehicleModel,
    fins: &Fins,
    manoeuvre: &VehicleManoeuvre,
    (start, stop): ([f64; 15], Option<&StopCondition>),
    (stepper, every): (&Stepper, f64),
    observe: impl FnMut(&Sample) -> bool,
) -> Result<VehicleRun, VehicleError> {
    let mut y = VehicleState::from(start);
    let schedule = schedule(manoeuvre);
    let changes = instants(manoeuvre, &schedule);
    let mut command = Command::new(manoeuvre, &start);
    let steering = command.at(fins, 0.0, &mut y, true);
    let mut runner = Runner {
        model,
        manoeuvre,
        start: y,
        schedule,
        changes,
        next: 0,
        command,
        steering,
        ends: Vec::new(),
        stop,
        pending: None,
    };
    let (reached, stats) = problem::solve(&mut runner, (stepper, every), observe);
    let end = reached.map_err(|error| run_error(error, stepper))?;
    Ok(VehicleRun {
        ends: runner.ends,
        tracked: runner.command.tracked,
        trial: runner.command.progress,
        steps: stats.steps as u64,
        rhs_evals: stats.rhs_evals as u64,
        stopped_at: end.stopped.then_some(end.t),
    })
}

/// What ends a stretch early: a trial's event, or a fin's rate limit starting or stopping to
/// act (a kink in its rate, which a step across would be first-order accurate about).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kink {
    /// The trial's watched function passed zero.
    Trial(Watch),
    /// Fin 0 (the rudder) or 1 (the stern planes) reached or left its rate limit.
    RateLimit(usize),
}

/// A manoeuvre under way: the commands as they stand, where they change, and where each
/// step of them ended.
struct Runner<'a> {
    model: &'a VehicleModel,
    manoeuvre: &'a VehicleManoeuvre,
    /// The state at the start, the fins without a lag at their first commands.
    start: VehicleState,
    /// The instants the steps or the setpoints change ([`schedule`]).
    schedule: Vec<f64>,
    /// Where the run is cut ([`instants`]), and the index of the next.
    changes: Vec<f64>,
    next: usize,
    command: Command<'a>,
    /// The fins' loads as they stand.
    steering: Steering<'a>,
    ends: Vec<StepEnd>,
    /// The scene's stop condition, if it has one.
    stop: Option<&'a StopCondition>,
    /// The last accepted step, not yet recorded in the trial's course: a step past where a
    /// stretch ends (an event, a change) is its trial, run with the commands before it, not
    /// the vehicle's course.
    pending: Option<(f64, VehicleState)>,
}

impl Runner<'_> {
    /// Records `(t, y)` in the trial's course, if the manoeuvre is a trial.
    fn record(&mut self, t: f64, y: &VehicleState) {
        if let Some(progress) = self.command.progress.as_mut() {
            progress.record(t, &y.data.0[0]);
        }
    }

    /// Records the pending step where it lies before `t`, the instant the run goes on from;
    /// one at or past it is dropped.
    fn catch_up(&mut self, t: f64) {
        if let Some((time, state)) = self.pending.take().filter(|(time, _)| *time < t) {
            self.record(time, &state);
        }
    }

    /// Where a step of the commands ended at `(t, y)`.
    fn step_end(&self, t: f64, y: &VehicleState) -> StepEnd {
        StepEnd {
            t,
            state: y.data.0[0],
            commands: self.steering.saturated(),
        }
    }
}

/// A manoeuvre as the one loop runs it: cut where the commands change, watching the trial's
/// events and the fins' rate limits, the trial's course from every accepted step.
impl<'a> Problem<15> for Runner<'a> {
    type System = Driven<'a, VehicleModel, Steering<'a>, 2>;
    type Watch = Kink;
    type Sample = Sample;

    fn start(&mut self) -> (f64, VehicleState) {
        (0.0, self.start)
    }

    fn end(&self) -> f64 {
        self.manoeuvre.duration
    }

    fn next_change(&self) -> Option<f64> {
        self.changes.get(self.next).copied()
    }

    fn system(&self, _t: f64, _until: f64) -> Self::System {
        self.model.driven_by(self.steering)
    }

    fn watches(&self, _system: &Self::System, _t: f64, y: &VehicleState) -> Vec<Kink> {
        let progress = self.command.progress.as_ref();
        let mut watches: Vec<Kink> = (progress.map_or_else(Vec::new, Progress::watches))
            .into_iter()
            .map(Kink::Trial)
            .collect();
        watches.extend(
            (0..2)
                .filter(|&fin| self.steering.rate_margin(fin, &y.data.0[0]).is_some())
                .map(Kink::RateLimit),
        );
        watches
    }

    fn g(&self, _system: &Self::System, watch: Kink, _t: f64, y: &VehicleState) -> f64 {
        match watch {
            Kink::Trial(watch) => {
                (self.command.progress.as_ref()).map_or(0.0, |p| p.g(watch, &y.data.0[0]))
            }
            Kink::RateLimit(fin) => self.steering.rate_margin(fin, &y.data.0[0]).unwrap_or(0.0),
        }
    }

    fn has_stop(&self) -> bool {
        self.stop.is_some()
    }

    /// The scene's condition on the row at `(t, y)`, as trajectory.csv writes it.
    fn stop_holds(&self, t: f64, y: &VehicleState) -> bool {
        (self.stop).is_some_and(|stop| stop.holds(t, &self.sample(t, y).row()))
    }

    /// The step before it, which the run went on from, joins the trial's course.
    fn accepted(&mut self, t: f64, y: &VehicleState) -> bool {
        if let Some((time, state)) = self.pending.replace((t, *y)) {
            self.record(time, &state);
        }
        true
    }

    /// The trial takes its event (a zig-zag reverses its fin); at a rate limit's kink only
    /// the form of δ̇ changes.
    fn event(&mut self, kink: Kink, t: f64, y: &mut VehicleState) -> Flow {
        self.catch_up(t);
        if let (Kink::Trial(watch), Some(progress)) = (kink, self.command.progress.as_mut()) {
            progress.fire(watch, t, &y.data.0[0]);
            self.steering = self.command.at(self.steering.fins, t, y, false);
        }
        self.record(t, y);
        Flow::Go
    }

    /// A step's end is recorded where the steps or the setpoints change, then the commands
    /// (the autopilots sampled anew) change.
    fn change(&mut self, t: f64, y: &mut VehicleState) -> Flow {
        self.catch_up(t);
        self.next += 1;
        if self.schedule.contains(&t) {
            self.ends.push(self.step_end(t, y));
        }
        self.steering = self.command.at(self.steering.fins, t, y, true);
        self.record(t, y);
        Flow::Go
    }

    /// The instant is recorded, as one the run goes on from.
    fn resumed(&mut self, t: f64, y: &VehicleState) {
        self.catch_up(t);
        self.record(t, y);
    }

    fn finish(&mut self, t: f64, y: &VehicleState) {
        self.catch_up(t);
        self.record(t, y);
        self.ends.push(self.step_end(t, y));
        self.command.track(t, &y.data.0[0]);
    }

    fn sample(&self, t: f64, y: &VehicleState) -> Sample {
        Sample {
            t,
            state: y.data.0[0],
            commands: self.steering.saturated(),
        }
    }
}

/// The instants within the run where the steps or the setpoints change.
fn schedule(manoeuvre: &VehicleManoeuvre) -> Vec<f64> {
    let setpoints = manoeuvre.autopilot.as_ref().map(|(_, s)| &s.times[..]);
    let mut times: Vec<f64> = (manoeuvre.steps.times().iter())
        .chain(setpoints.into_iter().flatten())
        .copied()
        .filter(|&t| t > 0.0 && t < manoeuvre.duration)
        .collect();
    times.sort_by(f64::total_cmp);
    times.dedup();
    times
}

/// Where the run is cut: the `schedule`'s instants ([`schedule`]), and the autopilots'
/// samples k·T_s (one within a millionth of a period of a scheduled instant is that instant).
fn instants(manoeuvre: &VehicleManoeuvre, schedule: &[f64]) -> Vec<f64> {
    let mut times = schedule.to_vec();
    if let Some((autopilots, _)) = &manoeuvre.autopilot {
        let period = autopilots.sample;
        let count = (manoeuvre.duration / period).ceil() as u64;
        let near = |t: f64| schedule.iter().any(|&s| (s - t).abs() <= 1e-6 * period);
        times.extend(
            (1..count)
                .map(|k| k as f64 * period)
                .filter(|&t| t < manoeuvre.duration && !near(t)),
        );
        times.sort_by(f64::total_cmp);
    }
    times
}

/// What commands the fins through a run: the steps, and the autopilots where they are on.
struct Command<'a> {
    manoeuvre: &'a VehicleManoeuvre,
    /// The heading (degrees) and depth of the start, held before the first setpoint.
    cruise: (f64, f64),
    controller: Controller,
    last: f64,
    tracked: Vec<Tracked>,
    /// The trial under way, if the manoeuvre is one.
    progress: Option<Progress>,
    /// The autopilots' commands since their last sample.
    held: Option<[Option<f64>; 2]>,
}

impl<'a> Command<'a> {
    /// The commands of `manoeuvre` from `start`, its trim: the autopilots act about the trim's
    /// fins and pitch.
    fn new(manoeuvre: &'a VehicleManoeuvre, start: &[f64; 15]) -> Self {
        let [_, pitch, heading] = euler_angles(start);
        let trim = Feedforward {
            rudder: start[13],
            stern_planes: start[14],
            pitch,
            pitch_rate: start[4],
            yaw_rate: start[5],
        };
        Command {
            manoeuvre,
            cruise: (heading.to_degrees(), start[8]),
            controller: Controller::about(trim),
            last: 0.0,
            tracked: Vec::new(),
            progress: manoeuvre.trial.map(|trial| Progress::new(trial, start)),
            held: None,
        }
    }

    /// Records the heading and depth at `t` against the setpoints, under an autopilot.
    fn track(&mut self, t: f64, state: &[f64; 15]) {
        if let Some((_, setpoints)) = &self.manoeuvre.autopilot {
            self.tracked.push(Tracked {
                t,
                value: (euler_angles(state)[2].to_degrees(), state[8]),
                setpoint: setpoints.at(t, self.cruise),
            });
        }
    }

    /// The fins' loads from `t` on: the steps' commands, a trial's fin and those of the
    /// autopilots that are on in their place, the autopilots sampled anew if `sample` (else
    /// holding their last commands: an event is not a sample); a fin without a lag is set to
    /// its saturated command.
    fn at(&mut self, fins: &'a Fins, t: f64, y: &mut VehicleState, sample: bool) -> Steering<'a> {
        let mut commands = self.manoeuvre.steps.angles(t);
        if let Some(progress) = self.progress.as_mut() {
            if !progress.started() && t >= progress.execute_time() {
                progress.execute(&y.data.0[0]);
            }
            if let Some((fin, angle)) = progress.fin() {
                commands[fin] = angle;
            }
        }
        if let Some(held) = self.held.filter(|_| !sample) {
            for (command, held) in commands.iter_mut().zip(held) {
                if let Some(value) = held {
                    *command = value;
                }
            }
        } else if let Some((autopilots, setpoints)) = &self.manoeuvre.autopilot {
            let state = y.data.0[0];
            self.track(t, &state);
            let limits = [fins.rudder.max_angle, fins.stern_planes.max_angle];
            let computed = self.controller.commands(
                autopilots,
                (&state, euler_angles(&state)),
                setpoints.at(t, self.cruise),
                limits,
                t - self.last,
            );
            self.last = t;
            self.held = Some(computed);
            for (command, computed) in commands.iter_mut().zip(computed) {
                if let Some(value) = computed {
                    *command = value;
                }
            }
        }
        let steering = Steering { fins, commands };
        let saturated = steering.saturated();
        for (i, fin) in [fins.rudder, fins.stern_planes].iter().enumerate() {
            if fin.time_constant.is_none() {
                y[13 + i] = saturated[i];
            }
        }
        steering
    }
}

/// A failed stretch as a vehicle's error, naming the state entry or the cause.
fn run_error(error: IntegrateError, stepper: &Stepper) -> VehicleError {
    match error {
        IntegrateError::NonFiniteState { component, t } => VehicleError::Run {
            time: t,
            reason: format!(
                "{} is not finite ({} may be too coarse for this vehicle)",
                super::model::STATE.get(component).unwrap_or(&"?"),
                match stepper.step {
                    Some(step) => format!("a step of {step} s"),
                    None => "the tolerances".to_owned(),
                }
            ),
        },
        other => VehicleError::Run {
            time: other.time().unwrap_or(f64::NAN),
            reason: other.without_time(),
        },
    }
}
