//! A vehicle's standard trials: the turning circle at a fixed rudder, and the zig-zag in the
//! horizontal plane (the rudder, on the heading) or the vertical one (the stern planes, on the
//! pitch), with the events of the one driver and their figures.
//!
//! The events are located where they happen, by the driver's stop condition (bisection to
//! adjacent floating-point times on the integrator's own solution): the heading passing 90° and
//! 180° from the execute, a zig-zag's heading (pitch) passing ±the switch angle, where the fin
//! is reversed, and the heading (pitch) rate passing zero, where the overshoot is read. A
//! vertical zig-zag's pitch is measured from the trim's, as a horizontal one's heading is from
//! the execute's: a vehicle that trims nose up zig-zags about its trim, not about level. The
//! rates are the Euler angles' (4.60): ψ̇ = (q sin φ + r cos φ)/cos θ, θ̇ = q cos φ − r sin φ.
//!
//! The turning circle's steady figures are given only once the turn has settled, by the
//! criterion the ship's turning circle uses ([`crate::manoeuvring::course`]): the heading has changed
//! by 540° and over the last 360° the horizontal speed and the heading rate stay within 1 % of
//! their final values; else the summary says why not. The steady diameter is then
//! 2 V_h / |ψ̇| at the end, V_h the horizontal speed of O from 4.57.
//!
//! A run the scene's stop condition ended ([`Ended::AtStopCondition`]) gives the figures of the events
//! that fell before the stop, and none of those read at the end of the run (the steady
//! diameter, the speed, rates and attitude at the end): they are not given, rather than read
//! at the stop.

use super::autopilot::wrapped;
use super::manoeuvre::euler_angles;
use super::summary::degrees;
use crate::Short;
use crate::manoeuvring::Course;
use serde::Serialize;
use std::f64::consts::{PI, TAU};

/// The plane of a zig-zag.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Plane {
    /// The rudder, switched on the heading.
    Horizontal,
    /// The stern planes, switched on the pitch.
    Vertical,
}

/// A standard trial.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Trial {
    /// The rudder held at the manoeuvre's step from the execute on.
    TurningCircle {
        /// The execute, s.
        execute: f64,
    },
    /// The fin to ±`fin` at the execute, reversed each time the heading (pitch) passes the
    /// switch angle on the side the fin drives it to.
    ZigZag {
        /// The plane.
        plane: Plane,
        /// The fin's angle, rad (its sign: the first side).
        fin: f64,
        /// The switch angle, rad: from the execute's heading, or from the trim's pitch.
        switch: f64,
        /// The execute, s.
        execute: f64,
    },
}

/// A function of the state whose sign change is an event.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Watch {
    /// The heading passing this change from the execute's, rad.
    Turned(f64),
    /// The zig-zag's angle (heading change or pitch) passing this value, rad.
    Switch(f64),
    /// The zig-zag's angle's rate passing zero.
    RateZero,
}

/// The Euler angles' rates (φ̇ left out): ψ̇ and θ̇ (4.60).
pub fn heading_and_pitch_rates(state: &[f64; 15]) -> (f64, f64) {
    rates_at(state, euler_angles(state))
}

/// [`heading_and_pitch_rates`] with the state's Euler angles already read.
fn rates_at(state: &[f64; 15], [phi, theta, _]: [f64; 3]) -> (f64, f64) {
    let (q, r) = (state[4], state[5]);
    let (s, c) = phi.sin_cos();
    ((q * s + r * c) / theta.cos(), q * c - r * s)
}

/// An event of a trial.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Event {
    /// When, s.
    pub t: f64,
    /// What fired.
    pub watch: Watch,
    /// The state there, before any fin is switched.
    pub state: [f64; 15],
}

/// A trial under way: what it watches, what it has seen, the course after the execute.
#[derive(Debug, Clone)]
pub struct Progress {
    trial: Trial,
    /// The heading at the execute, rad.
    heading0: f64,
    /// The pitch at the start (the trim's), rad.
    pitch0: f64,
    /// The fin's sign now (a zig-zag's side), and whether the execute has come.
    sign: f64,
    started: bool,
    /// The events seen, in order.
    pub events: Vec<Event>,
    /// The course after the execute, for a turning circle's steady criterion.
    pub course: Option<Course>,
    /// The state at the execute.
    at_execute: Option<[f64; 15]>,
    /// The heading change since the execute, unwrapped, and the last heading read.
    turned: f64,
    last_heading: f64,
    /// Whether the rate's zero after the last switch has been seen.
    rate_zero_seen: bool,
}

impl Progress {
    /// A trial from the state `start`.
    pub fn new(trial: Trial, start: &[f64; 15]) -> Self {
        let [_, pitch, heading] = euler_angles(start);
        Progress {
            trial,
            heading0: heading,
            pitch0: pitch,
            sign: 1.0,
            started: false,
            events: Vec::new(),
            course: None,
            at_execute: None,
            turned: 0.0,
            last_heading: heading,
            rate_zero_seen: true,
        }
    }

    /// The execute has come at `state`.
    pub fn execute(&mut self, state: &[f64; 15]) {
        self.started = true;
        self.at_execute = Some(*state);
        self.heading0 = euler_angles(state)[2];
        self.last_heading = self.heading0;
        self.turned = 0.0;
        // Only the turning circle's steady figures read the course.
        self.course = matches!(self.trial, Trial::TurningCircle { .. })
            .then(|| Course::new(horizontal_speed(state), true));
    }

    /// Whether the execute has come.
    pub fn started(&self) -> bool {
        self.started
    }

    /// The trial's execute.
    pub fn execute_time(&self) -> f64 {
        match self.trial {
            Trial::TurningCircle { execute } | Trial::ZigZag { execute, .. } => execute,
        }
    }

    /// After each accepted step: the course, with the heading unwrapped.
    pub fn record(&mut self, t: f64, state: &[f64; 15]) {
        if !self.started {
            return;
        }
        // The quaternion read as angles once per step: the heading, and the course's rates.
        let angles = euler_angles(state);
        self.turned += wrapped(angles[2] - self.last_heading, TAU);
        self.last_heading = angles[2];
        if let Some(course) = self.course.as_mut() {
            let (psi_dot, _) = rates_at(state, angles);
            let v = horizontal_speed_at(state, angles);
            course.record(t, v, 0.0, psi_dot, self.turned);
        }
    }

    /// The fin the trial commands and its angle now, rad: (0 rudder or 1 stern planes), or
    /// `None` before the execute or for a turning circle (its rudder is the steps').
    pub fn fin(&self) -> Option<(usize, f64)> {
        match self.trial {
            Trial::ZigZag { plane, fin, .. } if self.started => {
                let index = if plane == Plane::Horizontal { 0 } else { 1 };
                Some((index, self.sign * fin))
            }
            _ => None,
        }
    }

    /// What to watch from here on.
    pub fn watches(&self) -> Vec<Watch> {
        if !self.started {
            return Vec::new();
        }
        match self.trial {
            Trial::TurningCircle { .. } => {
                let seen = |target: f64| {
                    (self.events.iter())
                        .any(|e| matches!(e.watch, Watch::Turned(x) if x.abs() == target))
                };
                // ±90° until one is passed (the side of the turn is not known before), then
                // 180°, then nothing. Each watched function is wrapped, so it also jumps half a
                // turn from its target: there the other target's function passes zero, which
                // the nearest-to-zero rule takes.
                if !seen(PI / 2.0) {
                    vec![Watch::Turned(PI / 2.0), Watch::Turned(-PI / 2.0)]
                } else if !seen(PI) {
                    vec![Watch::Turned(PI)]
                } else {
                    Vec::new()
                }
            }
            Trial::ZigZag { switch, .. } => {
                let mut watches = Vec::new();
                if self.events.iter().all(|e| e.watch == Watch::RateZero) {
                    // Before the first switch: the side the fin drives it to is not known yet.
                    watches.extend([Watch::Switch(switch), Watch::Switch(-switch)]);
                } else {
                    watches.push(Watch::Switch(-self.side() * switch));
                }
                if !self.rate_zero_seen {
                    watches.push(Watch::RateZero);
                }
                watches
            }
        }
    }

    /// The side of the zig-zag's last switch: the sign of the angle it passed.
    fn side(&self) -> f64 {
        (self.events.iter().rev())
            .find_map(|e| match e.watch {
                Watch::Switch(x) => Some(x.signum()),
                _ => None,
            })
            .unwrap_or(1.0)
    }

    /// The zig-zag's angle: the heading change since the execute, or the pitch from the
    /// trim's.
    fn angle(&self, state: &[f64; 15]) -> f64 {
        match self.trial {
            Trial::ZigZag {
                plane: Plane::Vertical,
                ..
            } => euler_angles(state)[1] - self.pitch0,
            _ => wrapped(euler_angles(state)[2] - self.heading0, TAU),
        }
    }

    /// The watched function at `state`: its sign changes at the event.
    pub fn g(&self, watch: Watch, state: &[f64; 15]) -> f64 {
        match watch {
            // The heading change near the target, wrapped so that the function passes zero
            // there and not half a turn away.
            Watch::Turned(target) => wrapped(euler_angles(state)[2] - self.heading0 - target, TAU),
            Watch::Switch(value) => self.angle(state) - value,
            Watch::RateZero => {
                let (psi_dot, theta_dot) = heading_and_pitch_rates(state);
                match self.trial {
                    Trial::ZigZag {
                        plane: Plane::Vertical,
                        ..
                    } => theta_dot,
                    _ => psi_dot,
                }
            }
        }
    }

    /// An event: recorded; a switch reverses the zig-zag's fin and waits for the rate's zero.
    pub fn fire(&mut self, watch: Watch, t: f64, state: &[f64; 15]) {
        self.events.push(Event {
            t,
            watch,
            state: *state,
        });
        match watch {
            Watch::Switch(_) => {
                self.sign = -self.sign;
                self.rate_zero_seen = false;
            }
            Watch::RateZero => self.rate_zero_seen = true,
            Watch::Turned(_) => {}
        }
    }
}

/// √(ẋ² + ẏ²) of O in space axes at `state` (4.57, by the quaternion's rotation).
pub fn horizontal_speed(state: &[f64; 15]) -> f64 {
    horizontal_speed_at(state, euler_angles(state))
}

/// [`horizontal_speed`] with the state's Euler angles already read.
fn horizontal_speed_at(state: &[f64; 15], [phi, theta, psi]: [f64; 3]) -> f64 {
    let (u, v, w) = (state[0], state[1], state[2]);
    let (sf, cf) = phi.sin_cos();
    let (st, ct) = theta.sin_cos();
    let (sp, cp) = psi.sin_cos();
    let north = u * ct * cp + v * (sf * st * cp - cf * sp) + w * (cf * st * cp + sf * sp);
    let east = u * ct * sp + v * (sf * st * sp + cf * cp) + w * (cf * st * sp - sf * cp);
    north.hypot(east)
}

/// Where a run ended, for the figures read there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ended<'a> {
    /// At the end of the manoeuvre, in this state.
    AtEnd(&'a [f64; 15]),
    /// Where the scene's stop condition first held, at this time (s): no figure is read there.
    AtStopCondition(f64),
}

/// The turning circle's figures.
#[derive(Debug, Clone, Serialize)]
pub struct TurningCircleFigures {
    /// The rudder held, degrees.
    pub rudder_deg: f64,
    /// The distance run along the approach's heading when the heading has changed by 90°, m.
    pub advance_m: Option<f64>,
    /// The distance across it then, m.
    pub transfer_m: Option<f64>,
    /// The distance across the approach's heading when the heading has changed by 180°, m.
    pub tactical_diameter_m: Option<f64>,
    /// The steady turn's diameter 2 V_h/|ψ̇|, m: given once the turn has settled.
    pub steady_diameter_m: Option<f64>,
    /// √(u² + v² + w²) at the end, m/s; `None` where the stop condition ended the run (so
    /// for each figure at the end).
    pub speed_m_s: Option<f64>,
    /// ψ̇ at the end, degrees per second.
    pub heading_rate_deg_s: Option<f64>,
    /// φ and θ at the end, degrees.
    pub roll_deg: Option<f64>,
    /// θ at the end, degrees.
    pub pitch_deg: Option<f64>,
    /// z at the end less z at the execute, m (down positive).
    pub depth_change_m: Option<f64>,
    /// Why the steady figures are not given, where they are not.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub not_steady_because: Option<String>,
    /// The points to mark on the track, (what, [x, y] in m): the execute, and the 90° and
    /// 180° points with their figures, as a ship's turning circle marks them.
    #[serde(skip)]
    pub marks: Vec<(String, [f64; 2])>,
}

/// A zig-zag's figures.
#[derive(Debug, Clone, Serialize)]
pub struct ZigZagFigures {
    /// The plane.
    pub plane: Plane,
    /// The fin's angle, degrees.
    pub fin_deg: f64,
    /// The switch angle, degrees.
    pub switch_deg: f64,
    /// When the fin was reversed, s.
    pub switches_s: Vec<f64>,
    /// After each switch, how far the angle went past the switch angle, degrees.
    pub overshoots_deg: Vec<f64>,
    /// When each overshoot was reached, s.
    pub overshoots_at_s: Vec<f64>,
    /// Why there are no figures, where the angle never reached a switch.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub no_figures_because: Option<String>,
}

/// A trial's figures.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum TrialFigures {
    /// A turning circle's.
    TurningCircle(TurningCircleFigures),
    /// A zig-zag's.
    ZigZag(ZigZagFigures),
}

impl TrialFigures {
    /// The figures of `progress` where the run ended (`end`).
    pub fn of(progress: &Progress, (rudder, end): (f64, Ended<'_>)) -> Self {
        match progress.trial {
            Trial::TurningCircle { .. } => {
                TrialFigures::TurningCircle(turning_circle(progress, rudder, end))
            }
            Trial::ZigZag {
                plane, fin, switch, ..
            } => TrialFigures::ZigZag(zig_zag(progress, (plane, fin, switch), end)),
        }
    }

    /// The figures as numbers, for the refined run's difference.
    pub fn values(&self) -> Vec<f64> {
        match self {
            TrialFigures::TurningCircle(f) => [
                f.advance_m,
                f.transfer_m,
                f.tactical_diameter_m,
                f.steady_diameter_m,
                f.speed_m_s,
                f.heading_rate_deg_s,
                f.roll_deg,
                f.pitch_deg,
                f.depth_change_m,
            ]
            .iter()
            .map(|v| v.unwrap_or(f64::INFINITY))
            .collect(),
            TrialFigures::ZigZag(f) => (f.overshoots_deg.iter())
                .chain(&f.overshoots_at_s)
                .chain(&f.switches_s)
                .copied()
                .collect(),
        }
    }
}

/// The largest difference between two runs' trial figures (infinite where they have not the
/// same figures, or one is given and the other not).
pub fn largest_trial_difference(a: &TrialFigures, b: &TrialFigures) -> f64 {
    let (a, b) = (a.values(), b.values());
    if a.len() != b.len() {
        return f64::INFINITY;
    }
    (a.iter().zip(&b))
        .map(|(x, y)| if x == y { 0.0 } else { (x - y).abs() })
        .fold(0.0, f64::max)
}

/// A zig-zag's figures: its switches, and after each the overshoot where the angle's rate is
/// zero; without a switch, why there are none.
fn zig_zag(
    progress: &Progress,
    (plane, fin, switch): (Plane, f64, f64),
    end: Ended<'_>,
) -> ZigZagFigures {
    let switches: Vec<f64> = (progress.events.iter())
        .filter(|e| matches!(e.watch, Watch::Switch(_)))
        .map(|e| e.t)
        .collect();
    let mut overshoots = Vec::new();
    let mut at = Vec::new();
    for (i, event) in progress.events.iter().enumerate() {
        if event.watch != Watch::RateZero {
            continue;
        }
        let passed = (progress.events[..i].iter().rev()).find_map(|e| match e.watch {
            Watch::Switch(x) => Some(x),
            _ => None,
        });
        if let Some(x) = passed {
            let beyond = (progress.angle(&event.state) - x) * x.signum();
            overshoots.push(beyond.to_degrees());
            at.push(event.t);
        }
    }
    let no_figures_because = switches.is_empty().then(|| {
        let angle = match plane {
            Plane::Horizontal => "the heading change",
            Plane::Vertical => "the pitch from the trim's",
        };
        let (switch, execute) = (Short(degrees(switch)), Short(progress.execute_time()));
        match end {
            Ended::AtEnd(end) => format!(
                "{angle} did not reach ±{switch}° between the execute at {execute} s and the end \
                 of the run: it was {}° at the end, so the fin was never reversed",
                Short(progress.angle(end).to_degrees())
            ),
            Ended::AtStopCondition(t) => format!(
                "{angle} did not reach ±{switch}° between the execute at {execute} s and t = \
                 {t:.1} s, where integrator.stop_when stopped the run"
            ),
        }
    });
    ZigZagFigures {
        plane,
        fin_deg: degrees(fin),
        switch_deg: degrees(switch),
        switches_s: switches,
        overshoots_deg: overshoots,
        overshoots_at_s: at,
        no_figures_because,
    }
}

fn turning_circle(progress: &Progress, rudder: f64, end: Ended<'_>) -> TurningCircleFigures {
    let at = |target: f64| {
        (progress.events.iter()).find_map(|e| match e.watch {
            Watch::Turned(x) if x.abs() == target => Some(e.state),
            _ => None,
        })
    };
    // Along and across the approach's heading from the execute's position.
    let origin = progress.execute_position();
    let along_across = |state: &[f64; 15]| {
        let (dx, dy) = (state[6] - origin[0], state[7] - origin[1]);
        let (s, c) = progress.heading0.sin_cos();
        (dx * c + dy * s, -dx * s + dy * c)
    };
    let ninety = at(PI / 2.0).map(|s| along_across(&s));
    let one_eighty = at(PI).map(|s| along_across(&s));
    let mut marks = vec![("execute".to_owned(), origin)];
    if let (Some((advance, transfer)), Some(state)) = (ninety, at(PI / 2.0)) {
        let label = format!(
            "90°: advance {advance:.1} m, transfer {:.1} m",
            transfer.abs()
        );
        marks.push((label, [state[6], state[7]]));
    }
    if let (Some((_, across)), Some(state)) = (one_eighty, at(PI)) {
        let label = format!("180°: tactical diameter {:.1} m", across.abs());
        marks.push((label, [state[6], state[7]]));
    }
    let end = match end {
        Ended::AtEnd(end) => Ok(end),
        Ended::AtStopCondition(t) => Err(format!(
            "the run was stopped at t = {t:.1} s (integrator.stop_when): the steady turn is read \
             at the end"
        )),
    };
    let steady = match (&end, progress.course.as_ref()) {
        (Err(why), _) => Err(why.clone()),
        (Ok(_), None) => Err("the execute did not come".to_owned()),
        (Ok(_), Some(course)) => course.steady(),
    };
    let at_end = end.ok().map(|end| {
        let [phi, theta, _] = euler_angles(end);
        let (psi_dot, _) = heading_and_pitch_rates(end);
        let speed = (end[0] * end[0] + end[1] * end[1] + end[2] * end[2]).sqrt();
        let depth_change = end[8] - progress.execute_depth();
        (speed, psi_dot, phi, theta, depth_change)
    });
    TurningCircleFigures {
        rudder_deg: degrees(rudder),
        advance_m: ninety.map(|(along, _)| along),
        transfer_m: ninety.map(|(_, across)| across.abs()),
        tactical_diameter_m: one_eighty.map(|(_, across)| across.abs()),
        steady_diameter_m: steady
            .as_ref()
            .ok()
            .map(|(speed, rate)| 2.0 * speed / rate.abs()),
        speed_m_s: at_end.map(|(speed, ..)| speed),
        heading_rate_deg_s: at_end.map(|(_, psi_dot, ..)| psi_dot.to_degrees()),
        roll_deg: at_end.map(|(_, _, phi, ..)| phi.to_degrees()),
        pitch_deg: at_end.map(|(.., theta, _)| theta.to_degrees()),
        depth_change_m: at_end.map(|(.., depth_change)| depth_change),
        not_steady_because: steady.err(),
        marks,
    }
}

impl Progress {
    /// Where O was at the execute (x, y).
    fn execute_position(&self) -> [f64; 2] {
        self.at_execute.map_or([0.0; 2], |s| [s[6], s[7]])
    }

    /// z at the execute.
    fn execute_depth(&self) -> f64 {
        self.at_execute.map_or(0.0, |s| s[8])
    }
}
