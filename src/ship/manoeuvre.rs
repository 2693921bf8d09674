//! The standard manoeuvres, run with RK4 steps that land on every event, and their figures.
//!
//! A manoeuvre's figures are read at instants the state defines: the heading has changed by
//! 90° (advance, transfer), the heading has passed ±ψ_a (the zig-zag reverses the rudder),
//! the yaw rate is zero (an overshoot is largest). Each instant is found on the step that
//! contains it by solving g(y(s)) = 0 for the sub-step s, where y(s) is the RK4 step of size
//! s from the step's start (the Illinois variant of regula falsi, to a bracket of 1e-12 of
//! the step), and the run then steps to exactly that instant: the figures are those of the
//! integrated solution at the crossing, not at the nearest step, and a zig-zag reverses its
//! rudder where the rule says. Times where the command changes (the execute, a pull-out's
//! release, a series' breakpoints) are stepped onto as well.

use super::ShipError;
use super::course::Course;
use super::model::{STATE, ShipModel};
use super::rudder::{Rudder, Series};
use crate::integrate::{OdeSystem, rk4_step};
use crate::models::{TIME_UNIT, state_with_unit, with_unit};
use nalgebra::SVector;
use std::f64::consts::PI;

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
    /// The end of the run, s.
    pub duration: f64,
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

/// The columns of a manoeuvre's `trajectory.csv`, each labelled with its unit
/// ([`crate::models::with_unit`]): t, the model's state in its order ([`STATE`], in
/// identifiers: `x` for X), then the rudder command after saturation and the distance run;
/// a [`Sample`]'s time, its first seven state entries, its command and its distance.
pub fn trajectory_columns() -> Vec<String> {
    let mut columns = vec![with_unit("t", TIME_UNIT)];
    columns.extend(
        STATE
            .iter()
            .map(|name| state_with_unit(&name.to_lowercase())),
    );
    columns.extend([with_unit("command", "rad"), with_unit("distance", "m")]);
    columns
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

/// The ship, its rudder and the command, as one ODE system of eight states.
struct Driven<'a> {
    model: &'a ShipModel,
    rudder: &'a Rudder,
    command: Command<'a>,
}

/// The rudder command over one step.
#[derive(Debug, Clone, Copy)]
enum Command<'a> {
    Hold(f64),
    Series(&'a Series),
}

impl Driven<'_> {
    /// The saturated command at `t`, and its slope (a series' without a lag).
    fn command(&self, t: f64) -> (f64, f64) {
        match self.command {
            Command::Hold(angle) => (self.rudder.saturate(angle), 0.0),
            Command::Series(series) => {
                let angle = series.angle(t);
                let saturated = self.rudder.saturate(angle);
                let slope = if saturated == angle {
                    series.slope(t)
                } else {
                    0.0
                };
                (saturated, slope)
            }
        }
    }
}

impl OdeSystem<f64, 8> for Driven<'_> {
    fn rhs(&self, t: f64, y: &DriveState, dy: &mut DriveState) {
        let state: [f64; 7] = std::array::from_fn(|i| y[i]);
        let (command, slope) = self.command(t);
        let delta_rate = self.rudder.rate(command, state[6]).unwrap_or(slope);
        let rates = self.model.rhs(&state, delta_rate);
        for (i, rate) in rates.iter().enumerate() {
            dy[i] = *rate;
        }
        dy[7] = (state[0] * state[0] + state[1] * state[1]).sqrt();
    }
}

/// What a run watches for: a function of the state whose zero is an event.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Watch {
    /// |ψ − ψ₀| reaches `angle` (rad): g = (ψ − ψ₀)² − angle².
    HeadingChange(f64),
    /// ψ − ψ₀ reaches `side`·ψ_a: g = side·(ψ − ψ₀) − ψ_a.
    HeadingOnSide(f64),
    /// The yaw rate is zero: g = r.
    YawRateZero,
}

impl Watch {
    fn g(self, y: &DriveState, heading0: f64, heading_a: f64) -> f64 {
        let change = y[5] - heading0;
        match self {
            Watch::HeadingChange(angle) => change * change - angle * angle,
            Watch::HeadingOnSide(side) => side * change - heading_a,
            Watch::YawRateZero => y[2],
        }
    }
}

/// A manoeuvre run: where the ship went, and the figures.
#[derive(Debug, Clone)]
pub struct ManoeuvreRun {
    /// The figures, under the manoeuvre's kind.
    pub figures: Figures,
    /// Steps taken.
    pub steps: u64,
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

/// Runs a manoeuvre from `start` (the model's seven states) with RK4 steps of at most
/// `step`, calling `observe` at the start, after every step and at every event; `observe`
/// returns whether to go on (false ends the run with [`ShipError::Stopped`]: Ctrl-C).
pub fn run(
    model: &ShipModel,
    rudder: &Rudder,
    manoeuvre: &Manoeuvre,
    start: [f64; 7],
    step: f64,
    mut observe: impl FnMut(&Sample) -> bool,
) -> Result<ManoeuvreRun, ShipError> {
    let mut y = DriveState::zeros();
    for (i, value) in start.iter().enumerate() {
        y[i] = *value;
    }
    let mut driver = Driver {
        model,
        rudder,
        manoeuvre,
        command: 0.0,
        watches: Vec::new(),
        switches: 0,
        side: 0.0,
        log: Log::default(),
    };
    let mut times = driver.command_times();
    let mut t = 0.0;
    let mut steps = 0;
    // Times are counted from the last event, t = anchor + k·h, so that they do not gather
    // the round-off of a running sum over 10⁴ steps.
    let (mut anchor, mut k) = (0.0, 0u64);
    driver.apply_times(t, &mut y, &mut times);
    let mut go_on = observe(&driver.sample(t, &y));
    while t < manoeuvre.duration {
        if !go_on {
            return Err(ShipError::Stopped { time: t });
        }
        let next_time = times.first().copied().unwrap_or(manoeuvre.duration);
        let boundary = next_time.min(manoeuvre.duration);
        let h = if boundary - t <= step * (1.0 + 1e-9) {
            boundary - t
        } else {
            step
        };
        let mut trial = y;
        rk4_step(&driver.system(), t, h, &mut trial);
        steps += 1;
        match driver.first_event(t, h, &y, &trial) {
            Some((s, watch)) => {
                if s < h {
                    y = driver.step_to(t, s, &y);
                } else {
                    y = trial;
                }
                t += s;
                (anchor, k) = (t, 0);
                driver.fire(watch, t, &mut y);
            }
            None => {
                y = trial;
                if h == boundary - t {
                    (t, anchor, k) = (boundary, boundary, 0);
                } else {
                    k += 1;
                    t = anchor + k as f64 * step;
                }
                driver.apply_times(t, &mut y, &mut times);
            }
        }
        if let Some(i) = (0..8).find(|&i| !y[i].is_finite()) {
            let name = ["u", "v", "r", "X", "Y", "psi", "delta", "distance"][i];
            return Err(ShipError::Run {
                time: t,
                reason: format!(
                    "{name} is not finite (the prime system's forces are undefined where the \
                     speed U is zero; a step of {step} s may also be too long for this ship)"
                ),
            });
        }
        driver.record(t, &y);
        go_on = observe(&driver.sample(t, &y));
    }
    let figures = driver.figures(&y);
    Ok(ManoeuvreRun { figures, steps })
}

/// Solves g(s) = 0 on [0, h] with g(0) = g0 and g(h) = g1 of opposite signs (Illinois).
fn locate(g: impl Fn(f64) -> f64, h: f64, g0: f64, g1: f64) -> f64 {
    let (mut a, mut b, mut ga, mut gb) = (0.0, h, g0, g1);
    let mut side = 0;
    for _ in 0..100 {
        if (b - a).abs() <= 1e-12 * h {
            break;
        }
        let s = (a * gb - b * ga) / (gb - ga);
        let gs = g(s);
        if gs == 0.0 {
            return s;
        }
        if gs.signum() == gb.signum() {
            b = s;
            gb = gs;
            if side == -1 {
                ga *= 0.5;
            }
            side = -1;
        } else {
            a = s;
            ga = gs;
            if side == 1 {
                gb *= 0.5;
            }
            side = 1;
        }
    }
    b
}

/// The run's moving parts: the command, what it watches for, what it has seen.
struct Driver<'a> {
    model: &'a ShipModel,
    rudder: &'a Rudder,
    manoeuvre: &'a Manoeuvre,
    /// The held command (rad), before saturation.
    command: f64,
    watches: Vec<Watch>,
    /// Zig-zag reversals so far.
    switches: u32,
    /// The side (±1) of the heading change at the first reversal.
    side: f64,
    log: Log,
}

impl<'a> Driver<'a> {
    fn system(&self) -> Driven<'a> {
        let command = match &self.manoeuvre.kind {
            ManoeuvreKind::Series(series) => Command::Series(series),
            _ => Command::Hold(self.command),
        };
        Driven {
            model: self.model,
            rudder: self.rudder,
            command,
        }
    }

    /// The earliest watch whose function changes sign over the step of `h` from `(t, y)` to
    /// `trial`, and the sub-step `s` at which it is zero.
    fn first_event(
        &self,
        t: f64,
        h: f64,
        y: &DriveState,
        trial: &DriveState,
    ) -> Option<(f64, Watch)> {
        let system = self.system();
        let (heading0, heading_a) = (self.heading0(), self.heading_a());
        let crossing = |&watch: &Watch| {
            let g = |y: &DriveState| watch.g(y, heading0, heading_a);
            let (g0, g1) = (g(y), g(trial));
            (g0 != 0.0 && g0.signum() != g1.signum()).then(|| {
                let at = |s: f64| {
                    let mut probe = *y;
                    rk4_step(&system, t, s, &mut probe);
                    g(&probe)
                };
                (locate(at, h, g0, g1), watch)
            })
        };
        self.watches
            .iter()
            .filter_map(crossing)
            .min_by(|a, b| a.0.total_cmp(&b.0))
    }

    fn step_to(&self, t: f64, s: f64, y: &DriveState) -> DriveState {
        let mut y = *y;
        rk4_step(&self.system(), t, s, &mut y);
        y
    }

    fn sample(&self, t: f64, y: &DriveState) -> Sample {
        Sample {
            t,
            state: std::array::from_fn(|i| y[i]),
            command: self.system().command(t).0,
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
            _ => {}
        }
        times.retain(|&t| t <= self.manoeuvre.duration);
        times.sort_by(f64::total_cmp);
        times.dedup();
        times
    }

    /// Applies every command change due at `t`.
    fn apply_times(&mut self, t: f64, y: &mut DriveState, times: &mut Vec<f64>) {
        while times.first().is_some_and(|&time| time <= t) {
            let time = times.remove(0);
            if time == self.manoeuvre.execute {
                self.execute(y);
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
        }
    }

    fn set_command(&mut self, angle: f64, y: &mut DriveState) {
        self.command = angle;
        if self.rudder.time_constant.is_none() {
            y[6] = self.rudder.saturate(angle);
        }
    }

    /// Adds the instant to the course, from the execute on.
    fn record(&mut self, t: f64, y: &DriveState) {
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
            }
            ManoeuvreKind::ZigZag { rudder, heading } => {
                self.set_command(rudder, y);
                self.watches = vec![Watch::HeadingChange(heading)];
            }
            ManoeuvreKind::PullOut { rudder, .. } => self.set_command(rudder, y),
            ManoeuvreKind::Series(_) => {}
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
                Watch::YawRateZero => {}
            }
        }
    }

    fn figures(&self, end: &DriveState) -> Figures {
        let Some(execute) = self.log.execute else {
            return Figures {
                notes: vec!["the run ended before the execute".into()],
                ..Figures::default()
            };
        };
        let course = self.log.course.clone().unwrap_or_default();
        let mut figures = match self.manoeuvre.kind {
            ManoeuvreKind::TurningCircle { .. } => self.turning_figures(&execute, &course),
            ManoeuvreKind::ZigZag { heading, .. } => {
                self.zigzag_figures(&execute, heading, &course)
            }
            ManoeuvreKind::PullOut { release, .. } => {
                pull_out_figures(self.log.release.as_ref(), end, release)
            }
            ManoeuvreKind::Series(_) => Figures::default(),
        };
        figures.notes.extend(course.notes());
        figures
    }

    fn event(&self, wanted: Watch) -> Option<(f64, DriveState)> {
        self.log
            .events
            .iter()
            .find(|(watch, _, _)| *watch == wanted)
            .map(|(_, t, y)| (*t, *y))
    }

    /// The turning circle's figures, each where the condition it assumes held
    /// ([`Course`]): advance and transfer at 90°, the tactical diameter at 180° while the ship
    /// goes ahead; the steady radius and speed once the turn has settled.
    fn turning_figures(&self, execute: &DriveState, course: &Course) -> Figures {
        let psi0 = execute[5];
        // (advance, transfer): the displacement of midship in the axes of the approach.
        let offset = |y: &DriveState| {
            let (dx, dy) = (y[3] - execute[3], y[4] - execute[4]);
            let (s, c) = psi0.sin_cos();
            (dx * c + dy * s, -dx * s + dy * c)
        };
        let t_exec = self.manoeuvre.execute;
        let mut notes = Vec::new();
        let mut holding = |angle: f64, what: &str| {
            let (t, y) = self.event(Watch::HeadingChange(angle))?;
            match course.broken_by(t) {
                Some(why) => {
                    notes.push(format!(
                        "{what} not given: {why}, before the heading changed by {:.0}°",
                        angle.to_degrees()
                    ));
                    None
                }
                None => Some((t, y)),
            }
        };
        let at_90 = holding(PI / 2.0, "advance and transfer");
        let at_180 = holding(PI, "the tactical diameter");
        let steady = course.steady().map_err(|why| notes.push(why)).ok();
        let mut marks = vec![("execute".to_owned(), [execute[3], execute[4]])];
        if let Some((_, y)) = at_90 {
            let (advance, transfer) = offset(&y);
            let label = format!(
                "90°: advance {advance:.1} m, transfer {:.1} m",
                transfer.abs()
            );
            marks.push((label, [y[3], y[4]]));
        }
        if let Some((_, y)) = at_180 {
            let label = format!("180°: tactical diameter {:.1} m", offset(&y).1.abs());
            marks.push((label, [y[3], y[4]]));
        }
        Figures {
            values: vec![
                ("advance_90_m", at_90.map(|(_, y)| offset(&y).0)),
                ("transfer_90_m", at_90.map(|(_, y)| offset(&y).1.abs())),
                (
                    "tactical_diameter_m",
                    at_180.map(|(_, y)| offset(&y).1.abs()),
                ),
                (
                    "steady_turning_radius_m",
                    steady.map(|(speed, r)| speed / r.abs()),
                ),
                ("steady_speed_m_s", steady.map(|(speed, _)| speed)),
                ("t_90_s", at_90.map(|(t, _)| t - t_exec)),
                ("t_180_s", at_180.map(|(t, _)| t - t_exec)),
            ],
            side: Some(if course.turned() > 0.0 {
                "starboard"
            } else {
                "port"
            }),
            notes,
            marks,
        }
    }

    /// The zig-zag's figures; none where the ship went astern or stopped before the last
    /// reversal or overshoot they are read from.
    fn zigzag_figures(&self, execute: &DriveState, heading_a: f64, course: &Course) -> Figures {
        let psi0 = execute[5];
        // Instants after the ship went astern or stopped are not the zig-zag's.
        let holds = |t: f64| course.broken_by(t).is_none();
        let switches: Vec<(f64, DriveState)> = self
            .log
            .events
            .iter()
            .filter(|(w, t, _)| !matches!(w, Watch::YawRateZero) && holds(*t))
            .map(|(_, t, y)| (*t, *y))
            .collect();
        // The k-th overshoot: the largest heading change past the k-th reversal, where r = 0.
        let overshoot = |k: usize| {
            let after = switches.get(k)?.0;
            let side = if k.is_multiple_of(2) {
                self.side
            } else {
                -self.side
            };
            let (_, _, y) = self
                .log
                .events
                .iter()
                .find(|(w, t, _)| *w == Watch::YawRateZero && *t > after)
                .filter(|(_, t, _)| holds(*t))?;
            Some((side * (y[5] - psi0) - heading_a).to_degrees())
        };
        let t_exec = self.manoeuvre.execute;
        let mut notes = Vec::new();
        if switches.len() < 3 {
            notes.push(format!(
                "{} reversals by the end: the period needs three; lengthen duration_s",
                switches.len()
            ));
        }
        Figures {
            values: vec![
                ("first_overshoot_deg", overshoot(0)),
                ("second_overshoot_deg", overshoot(1)),
                ("reach_time_s", switches.first().map(|(t, _)| t - t_exec)),
                ("period_s", switches.get(2).map(|(t, _)| t - switches[0].0)),
                (
                    "initial_turning_distance_m",
                    switches.first().map(|(_, y)| y[7] - execute[7]),
                ),
            ],
            side: None,
            notes,
            marks: vec![],
        }
    }
}

/// A pull-out: the yaw rate when the rudder is released and at the end; a course-stable ship's
/// dies out, an unstable one's settles to a residual turn.
fn pull_out_figures(at_release: Option<&DriveState>, end: &DriveState, release: f64) -> Figures {
    Figures {
        values: vec![
            ("release_s", Some(release)),
            (
                "yaw_rate_at_release_deg_s",
                at_release.map(|y| y[2].to_degrees()),
            ),
            ("final_yaw_rate_deg_s", Some(end[2].to_degrees())),
        ],
        side: None,
        notes: vec![],
        marks: vec![],
    }
}
