//! A vehicle's manoeuvre: its fins under step commands or under the autopilots, integrated by
//! the one driver (`integrate::segment::advance`, any method), and the figures read where the
//! commands change.
//!
//! The run is cut into stretches at the instants the commands change (the steps, the
//! setpoints, and the autopilots' samples, [`super::autopilot`]), so each stretch holds its
//! commands and ends exactly at the next change: the figures of a step (the yaw rate, the
//! speed, the roll and pitch, the depth reached when it ends) are those of the integrated
//! solution at that instant, not at the nearest step. The trajectory's rows are at
//! t = k·every, as every scene's are, and at each change of the commands.

use super::VehicleError;
use super::autopilot::{Autopilots, Controller, Feedforward, Setpoints};
use super::fins::{FinSteps, Fins, Steering};
use super::model::VehicleModel;
use super::trial::{Progress, Trial, Watch};
use super::trim::{Held, Trim};
use crate::integrate::segment::{self, add};
use crate::integrate::{IntegrateError, RowClock, Stats, Stepper};
use crate::models::Model;
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
}

/// Runs a manoeuvre from `start` with `stepper`'s method, handing each row (at t = k·`every`
/// and at each change of the commands) to `observe`, which returns whether to go on (false
/// ends the run with [`VehicleError::Stopped`]: Ctrl-C).
pub fn run(
    model: &VehicleModel,
    fins: &Fins,
    manoeuvre: &VehicleManoeuvre,
    start: [f64; 15],
    (stepper, every): (&Stepper, f64),
    mut observe: impl FnMut(&Sample) -> bool,
) -> Result<VehicleRun, VehicleError> {
    let mut y = VehicleState::from(start);
    let schedule = schedule(manoeuvre);
    let mut changes: Vec<f64> = instants(manoeuvre, &schedule);
    changes.push(manoeuvre.duration);
    let mut t = 0.0;
    let mut command = Command::new(manoeuvre, &start);
    let mut steering = command.at(fins, t, &mut y, true);
    let mut rows = RowClock::new(0.0, every);
    let mut total = Stats::default();
    let mut ends = Vec::new();
    for b in changes {
        let last = b >= manoeuvre.duration;
        loop {
            let (reached, stats, fired) = stretch(
                model,
                steering,
                &mut command,
                (stepper, &mut rows),
                (t, y, b),
                last,
                &mut observe,
            );
            add(&mut total, stats);
            let reached = reached.map_err(|error| run_error(error, stepper))?;
            (t, y) = (reached.t, reached.state);
            let Some(kink) = fired else {
                // Stopped where the watched function is within rounding of zero, on the side
                // it started (the step taken again to the located time lands a last bit
                // apart): no event yet; the next stretch finds it if the sign changes.
                if reached.stopped && t < b {
                    continue;
                }
                break;
            };
            // An event: the trial takes it (a zig-zag reverses its fin), and a row shows the
            // state after it; at a rate limit's kink only the form of δ̇ changes.
            if let (Kink::Trial(watch), Some(progress)) = (kink, command.progress.as_mut()) {
                progress.fire(watch, t, &y.data.0[0]);
                steering = command.at(fins, t, &mut y, false);
            }
            let after = Sample {
                t,
                state: y.data.0[0],
                commands: steering.saturated(),
            };
            if !observe(&after) {
                return Err(VehicleError::Stopped { time: t });
            }
            if t >= b {
                break;
            }
        }
        if last || schedule.contains(&t) {
            ends.push(StepEnd {
                t,
                state: y.data.0[0],
                commands: steering.saturated(),
            });
        }
        if last {
            command.track(t, &y.data.0[0]);
        } else {
            steering = command.at(fins, t, &mut y, true);
            let after = Sample {
                t,
                state: y.data.0[0],
                commands: steering.saturated(),
            };
            if rows.next_time() != t && !observe(&after) {
                return Err(VehicleError::Stopped { time: t });
            }
        }
    }
    Ok(VehicleRun {
        ends,
        tracked: command.tracked,
        trial: command.progress,
        steps: total.steps as u64,
    })
}

/// What one stretch gives back: where it ended, its cost, and the event that ended it.
type Stretch = (
    Result<crate::integrate::Reached<f64, 15>, IntegrateError>,
    Stats,
    Option<Kink>,
);

/// What ends a stretch early: a trial's event, or a fin's rate limit starting or stopping to
/// act (a kink in its rate, which a step across would be first-order accurate about).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kink {
    /// The trial's watched function passed zero.
    Trial(Watch),
    /// Fin 0 (the rudder) or 1 (the stern planes) reached or left its rate limit.
    RateLimit(usize),
}

/// One stretch from `(a, y_a)` to `b` under `steering`, ending early where one of the trial's
/// watched functions or a fin's rate margin first changes sign; the trial's course records
/// every accepted step.
fn stretch(
    model: &VehicleModel,
    steering: Steering<'_>,
    command: &mut Command<'_>,
    (stepper, rows): (&Stepper, &mut RowClock<f64>),
    (a, y_a, b): (f64, VehicleState, f64),
    last: bool,
    observe: &mut impl FnMut(&Sample) -> bool,
) -> Stretch {
    let system = model.driven_by(steering);
    let progress = command.progress.take();
    let mut watches: Vec<Kink> = (progress.as_ref().map_or_else(Vec::new, Progress::watches))
        .into_iter()
        .map(Kink::Trial)
        .collect();
    watches.extend(
        (0..2)
            .filter(|&fin| steering.rate_margin(fin, &y_a.data.0[0]).is_some())
            .map(Kink::RateLimit),
    );
    let g = |watch: Kink, _: f64, y: &VehicleState| match watch {
        Kink::Trial(watch) => (progress.as_ref()).map_or(0.0, |p| p.g(watch, &y.data.0[0])),
        Kink::RateLimit(fin) => steering.rate_margin(fin, &y.data.0[0]).unwrap_or(0.0),
    };
    let sample = |t: f64, y: &VehicleState| Sample {
        t,
        state: y.data.0[0],
        commands: steering.saturated(),
    };
    // A fin without a lag jumps at a change: the row there shows it after the jump.
    let emit = &mut |t, y: &VehicleState| observe(&sample(t, y));
    let watched = segment::advance_watching(
        (stepper, &system),
        (a, y_a, b),
        rows,
        (&watches, g),
        (emit, last),
    );
    command.progress = progress.map(|mut p| {
        for (t, state) in &watched.steps {
            p.record(*t, &state.data.0[0]);
        }
        p
    });
    (watched.reached, watched.stats, watched.fired)
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
        IntegrateError::Stopped { t } => VehicleError::Stopped { time: t },
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
            time: f64::NAN,
            reason: other.to_string(),
        },
    }
}
