//! An aircraft's manoeuvres from its trim: the controls moved from their trimmed values on a
//! schedule (a doublet, a step, a pulse), the run a problem of the one loop, cut at each
//! change of the controls, and what a flight-test engineer reads from it.
//!
//! Figures: the peak and least load factor n_z (the normal specific force over g, positive
//! pulling up: −a_z/g in body axes), the largest |α| and |β| excursions and roll rate, the
//! speed and altitude at the end; after a rudder kick, the Dutch roll's period and damping
//! ratio read from the yaw rate's swings once the pulse is over (successive maxima: the
//! period their spacing, the damping from their logarithmic decrement).

use super::model::{AircraftModel, InQuaternion, QUATERNION_STATE, STATE, euler_of, quaternion_of};
use crate::integrate::problem::{self, Flow, Problem};
use crate::integrate::{IntegrateError, Stepper};
use crate::models::{Kinematics, Model};
use crate::scene::stop::StopCondition;
use eom_kernel::{Constant, Driven};
use nalgebra::SVector;

/// The kinds of manoeuvre.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Manoeuvre {
    /// The elevator +amount for `width`, −amount for `width`, then back.
    ElevatorDoublet,
    /// The aileron +amount from the start on.
    AileronStep,
    /// The rudder +amount for `width`, then back.
    RudderKick,
    /// The throttle +amount from the start on.
    ThrottleStep,
    /// The elevator −amount (trailing edge up: nose up) from the start on.
    PullUp,
}

impl Manoeuvre {
    /// Whether it takes a width.
    pub fn has_width(self) -> bool {
        matches!(self, Manoeuvre::ElevatorDoublet | Manoeuvre::RudderKick)
    }

    /// Which control it moves (index into [`CONTROLS`]).
    fn control(self) -> usize {
        match self {
            Manoeuvre::ThrottleStep => 0,
            Manoeuvre::ElevatorDoublet | Manoeuvre::PullUp => 1,
            Manoeuvre::AileronStep => 2,
            Manoeuvre::RudderKick => 3,
        }
    }
}

/// A manoeuvre, checked.
#[derive(Debug, Clone, PartialEq)]
pub struct AircraftManoeuvre {
    /// Its folder's name.
    pub name: String,
    /// What it does.
    pub kind: Manoeuvre,
    /// The change from the trim (deg; throttle 0 to 1).
    pub amount: f64,
    /// When it starts, s.
    pub start: f64,
    /// A doublet's half and a kick's pulse, s.
    pub width: f64,
    /// How long the run lasts, s.
    pub duration: f64,
}

impl AircraftManoeuvre {
    /// The instants the controls change, and the offset from the trim after each.
    fn schedule(&self) -> Vec<(f64, f64)> {
        let (a, s, w) = (self.amount, self.start, self.width);
        let changes = match self.kind {
            Manoeuvre::ElevatorDoublet => vec![(s, a), (s + w, -a), (s + 2.0 * w, 0.0)],
            Manoeuvre::RudderKick => vec![(s, a), (s + w, 0.0)],
            Manoeuvre::AileronStep | Manoeuvre::ThrottleStep => vec![(s, a)],
            Manoeuvre::PullUp => vec![(s, -a.abs())],
        };
        changes
            .into_iter()
            .filter(|(t, _)| *t < self.duration)
            .collect()
    }

    /// Every setting of the controls the manoeuvre gives, from `trim`'s.
    pub fn commands(&self, trim: &[f64; 4]) -> Vec<[f64; 4]> {
        let mut all = vec![*trim];
        for (_, offset) in self.schedule() {
            let mut controls = *trim;
            controls[self.kind.control()] += offset;
            all.push(controls);
        }
        all
    }
}

/// What a row holds after t: the state, the controls, the load factor.
pub const ROW: [&str; 18] = [
    "vt",
    "alpha",
    "beta",
    "phi",
    "theta",
    "psi",
    "p",
    "q",
    "r",
    "north",
    "east",
    "altitude",
    "power",
    "throttle",
    "elevator",
    "aileron",
    "rudder",
    "load_factor",
];

/// The columns of trajectory.csv after t.
pub fn trajectory_columns() -> Vec<String> {
    ROW.iter().map(|s| s.to_string()).collect()
}

/// n_z = −a_z/g: the body-z specific force, from the rates of V, α, β and the weight.
pub fn load_factor(model: &AircraftModel, state: &[f64; 13], rates: &[f64; 13]) -> f64 {
    let (vt, alpha, beta) = (state[0], state[1], state[2]);
    let (p, q) = (state[6], state[7]);
    let (sa, ca, sb, cb) = (alpha.sin(), alpha.cos(), beta.sin(), beta.cos());
    let (u, v) = (vt * ca * cb, vt * sb);
    let w_dot = rates[0] * sa * cb + vt * ca * cb * rates[1] - vt * sa * sb * rates[2];
    let g = model.gravity();
    let weight_z = g * state[4].cos() * state[3].cos();
    // ẇ = a_z + g cos θ cos φ + q u − p v, a_z the specific force.
    let a_z = w_dot - weight_z - q * u + p * v;
    -a_z / g
}

/// The row at `state` under `controls`.
pub fn row_at(model: &AircraftModel, state: &[f64; 13], controls: &[f64; 4]) -> [f64; 18] {
    let rates = model.rates(state, controls);
    let mut row = [0.0; 18];
    row[..13].copy_from_slice(state);
    row[13..17].copy_from_slice(controls);
    row[17] = load_factor(model, state, &rates);
    row
}

/// A row as the loop hands it.
#[derive(Debug, Clone, Copy)]
pub struct Sample {
    /// The time.
    pub t: f64,
    /// [`ROW`]'s values.
    pub row: [f64; 18],
    /// The kinetic energy.
    pub kinetic: f64,
}

/// What a run measured on its rows (at t = k·every and at each change of the controls, each
/// the integrator's own solution there, so every figure converges as the method does): the
/// extremes over the rows, and the yaw rate's maxima, each placed by the parabola through it
/// and its neighbours.
#[derive(Debug, Clone)]
pub struct Measured {
    /// The largest n_z and the least.
    pub load_factor: (f64, f64),
    /// The largest |α − α_trim|, |β|, |p|.
    pub excursions: [f64; 3],
    /// The least and the largest α over the rows.
    pub alpha_extremes: (f64, f64),
    /// The yaw rate's local maxima after the last change of the controls, (t, r − r_trim).
    pub yaw_peaks: Vec<(f64, f64)>,
    /// Its local minima after it, likewise.
    pub yaw_troughs: Vec<(f64, f64)>,
    /// The trim's α and r.
    trim: (f64, f64),
    /// When the controls last change.
    settled_from: f64,
    /// The last three rows' (t, r − r_trim) after it.
    recent: Vec<(f64, f64)>,
}

impl Measured {
    fn new(trim: &[f64; 13], settled_from: f64) -> Self {
        Measured {
            load_factor: (f64::NEG_INFINITY, f64::INFINITY),
            excursions: [0.0; 3],
            alpha_extremes: (f64::INFINITY, f64::NEG_INFINITY),
            yaw_peaks: Vec::new(),
            yaw_troughs: Vec::new(),
            trim: (trim[1], trim[8]),
            settled_from,
            recent: Vec::new(),
        }
    }

    /// Takes the row at `t`.
    fn row(&mut self, t: f64, row: &[f64; 18]) {
        let n = row[17];
        self.load_factor = (self.load_factor.0.max(n), self.load_factor.1.min(n));
        let excursions = [(row[1] - self.trim.0).abs(), row[2].abs(), row[6].abs()];
        for (e, x) in self.excursions.iter_mut().zip(excursions) {
            *e = e.max(x);
        }
        let (low, high) = self.alpha_extremes;
        self.alpha_extremes = (low.min(row[1]), high.max(row[1]));
        if t <= self.settled_from {
            return;
        }
        self.recent.push((t, row[8] - self.trim.1));
        if self.recent.len() > 3 {
            self.recent.remove(0);
        }
        if let [(ta, a), (tb, b), (tc, c)] = self.recent[..] {
            if b > a && b >= c {
                self.yaw_peaks.push(vertex((ta, a), (tb, b), (tc, c)));
            } else if b < a && b <= c {
                let (t, low) = vertex((ta, -a), (tb, -b), (tc, -c));
                self.yaw_troughs.push((t, -low));
            }
        }
    }
}

/// The vertex of the parabola through three points, the middle one the highest.
fn vertex((ta, a): (f64, f64), (tb, b): (f64, f64), (tc, c): (f64, f64)) -> (f64, f64) {
    // Divided differences: p(t) = b + d1 (t − tb) + d2 (t − tb)(t − ta).
    let d1 = (b - a) / (tb - ta);
    let d2 = ((c - b) / (tc - tb) - d1) / (tc - ta);
    if d2 >= 0.0 {
        return (tb, b);
    }
    // p'(t) = d1 + d2 (2t − ta − tb) = 0.
    let t = (ta + tb - d1 / d2) / 2.0;
    (t, b + d1 * (t - tb) + d2 * (t - tb) * (t - ta))
}

/// A manoeuvre run: what it cost and measured.
#[derive(Debug, Clone)]
pub struct AircraftRun {
    /// Accepted steps.
    pub steps: u64,
    /// Right-hand-side evaluations.
    pub rhs_evals: u64,
    /// Where it ended.
    pub end: [f64; 13],
    /// What it measured.
    pub measured: Measured,
    /// Where the stop condition ended it.
    pub stopped_at: Option<f64>,
}

/// Why a run could not go on.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RunError {
    /// The state left the model's domain.
    #[error("the run stopped at t = {} s: {reason}", crate::Short(*time))]
    Failed {
        /// When.
        time: f64,
        /// Why.
        reason: String,
    },
}

/// A form of the aircraft a manoeuvre integrates, of `N` states: its attitude in Euler angles
/// (the state rows are written in) or in a quaternion.
pub trait Flight<const N: usize>: Model<f64, N, 4> {
    /// The aircraft in its Euler-angle form, whose rows and figures the run writes.
    fn aircraft(&self) -> &AircraftModel;
    /// This form's state of an Euler-angle state.
    fn state_of_euler(&self, state: &[f64; 13]) -> [f64; N];
    /// The Euler-angle state of this form's state.
    fn euler_state(&self, state: &[f64; N]) -> [f64; 13];
    /// Why a run cannot go on at `state`, where it cannot.
    fn cannot_go_on(&self, state: &[f64; N]) -> Option<String>;
}

impl Flight<13> for AircraftModel {
    fn aircraft(&self) -> &AircraftModel {
        self
    }

    fn state_of_euler(&self, state: &[f64; 13]) -> [f64; 13] {
        *state
    }

    fn euler_state(&self, state: &[f64; 13]) -> [f64; 13] {
        *state
    }

    /// The Euler angles' rates are singular at θ = ±90°: a run that comes within 1° of it
    /// stops there, saying so, rather than writing rates that are not the aircraft's.
    fn cannot_go_on(&self, state: &[f64; 13]) -> Option<String> {
        let theta = state[4];
        (theta.abs() > crate::linear::EULER_PITCH_LIMIT).then(|| {
            format!(
                "the pitch θ = {:.2}° is within 1° of ±90°, where the Euler angles the \
                 aircraft is flown in do not hold (a loop or a vertical climb needs \
                 `aircraft.kinematics = \"quaternion\"`)",
                theta.to_degrees()
            )
        })
    }
}

impl Flight<14> for InQuaternion<'_> {
    fn aircraft(&self) -> &AircraftModel {
        InQuaternion::aircraft(self)
    }

    fn state_of_euler(&self, state: &[f64; 13]) -> [f64; 14] {
        quaternion_of(state)
    }

    fn euler_state(&self, state: &[f64; 14]) -> [f64; 13] {
        euler_of(state)
    }

    /// A quaternion has no singular attitude; one that has lost its length cannot say one.
    fn cannot_go_on(&self, state: &[f64; 14]) -> Option<String> {
        let norm = state[3..7].iter().map(|q| q * q).sum::<f64>().sqrt();
        ((norm - 1.0).abs() > 1e-3).then(|| {
            format!(
                "the attitude quaternion's length is {norm}, not 1 to within 1e-3: the \
                 integrator's tolerance or step is too coarse for the run"
            )
        })
    }
}

/// The sideslip beyond which a run stops, rad: 1° from ±90°, where sec β passes 57.
const SIDESLIP_LIMIT: f64 = std::f64::consts::FRAC_PI_2 - std::f64::consts::PI / 180.0;

/// The wind-axis state (V, α, β) holds for an aircraft flying forward of its side: its rates
/// divide by V and α̇ by cos β. Why a run cannot go on at airspeed `speed` and sideslip
/// `beta`, where it cannot (V not positive, or |β| within 1° of 90°).
fn wind_axes_cannot_go_on(speed: f64, beta: f64) -> Option<String> {
    if speed <= 0.0 {
        return Some(format!(
            "the airspeed V = {speed} is not positive: the wind-axis state (V, α, β) holds \
             only while the aircraft moves through the air"
        ));
    }
    (beta.abs() > SIDESLIP_LIMIT).then(|| {
        format!(
            "the sideslip β = {:.2}° is within 1° of ±90°, where the wind-axis state (V, α, β) \
             is singular (α̇ divides by cos β): the aircraft has departed",
            beta.to_degrees()
        )
    })
}

struct Runner<'a, F, const N: usize> {
    model: &'a F,
    trim: [f64; N],
    controls: [f64; 4],
    control: usize,
    changes: Vec<(f64, f64)>,
    next: usize,
    duration: f64,
    trim_controls: [f64; 4],
    stop: Option<&'a StopCondition>,
    /// Why the run cannot go on, where it cannot (the pitch at ±90°).
    failure: Option<(f64, String)>,
}

impl<'a, F: Flight<N>, const N: usize> Problem<N> for Runner<'a, F, N> {
    type System = Driven<'a, F, Constant<f64, 4>, 4>;
    type Watch = ();
    type Sample = Sample;

    fn start(&mut self) -> (f64, SVector<f64, N>) {
        (0.0, SVector::from(self.trim))
    }

    fn end(&self) -> f64 {
        self.duration
    }

    fn next_change(&self) -> Option<f64> {
        self.changes.get(self.next).map(|(t, _)| *t)
    }

    fn system(&self, _t: f64, _until: f64) -> Self::System {
        self.model.driven_by(Constant(self.controls))
    }

    fn watches(&self, _: &Self::System, _: f64, _: &SVector<f64, N>) -> Vec<()> {
        Vec::new()
    }

    fn g(&self, _: &Self::System, _: (), _: f64, _: &SVector<f64, N>) -> f64 {
        0.0
    }

    fn has_stop(&self) -> bool {
        self.stop.is_some()
    }

    fn stop_holds(&self, t: f64, y: &SVector<f64, N>) -> bool {
        (self.stop).is_some_and(|stop| stop.holds(t, &self.sample(t, y).row))
    }

    /// Where the wind-axis state or the form cannot go on (β or θ at ±90°), the run stops,
    /// saying why.
    fn accepted(&mut self, t: f64, y: &SVector<f64, N>) -> bool {
        let state = &y.data.0[0];
        let reason =
            wind_axes_cannot_go_on(state[0], state[2]).or_else(|| self.model.cannot_go_on(state));
        match reason {
            Some(reason) => {
                self.failure = Some((t, reason));
                false
            }
            None => true,
        }
    }

    fn change(&mut self, _t: f64, _y: &mut SVector<f64, N>) -> Flow {
        let (_, offset) = self.changes[self.next];
        self.next += 1;
        self.controls = self.trim_controls;
        self.controls[self.control] += offset;
        Flow::Go
    }

    fn event(&mut self, _: (), _: f64, _: &mut SVector<f64, N>) -> Flow {
        Flow::Go
    }

    fn sample(&self, t: f64, y: &SVector<f64, N>) -> Sample {
        let state = self.model.euler_state(&y.data.0[0]);
        let aircraft = self.model.aircraft();
        Sample {
            t,
            row: row_at(aircraft, &state, &self.controls),
            kinetic: aircraft.kinetic_energy(&state),
        }
    }
}

/// Runs `manoeuvre` from the trim (`state`, `controls`), each row to `observe`, the attitude
/// integrated in `kinematics` (the rows in Euler angles either way).
pub fn run(
    model: &AircraftModel,
    kinematics: Kinematics,
    manoeuvre: &AircraftManoeuvre,
    trim: (&[f64; 13], &[f64; 4]),
    method: (&Stepper, f64),
    stop: Option<&StopCondition>,
    observe: impl FnMut(&Sample) -> bool,
) -> Result<AircraftRun, RunError> {
    match kinematics {
        Kinematics::Euler => run_in(model, &STATE, manoeuvre, trim, method, stop, observe),
        Kinematics::Quaternion => {
            let flight = model.in_quaternion().map_err(|e| RunError::Failed {
                time: 0.0,
                reason: e.to_string(),
            })?;
            run_in(
                &flight,
                &QUATERNION_STATE,
                manoeuvre,
                trim,
                method,
                stop,
                observe,
            )
        }
    }
}

/// [`run`] in the form `model`, whose states `names` are.
#[allow(clippy::too_many_arguments)]
fn run_in<F: Flight<N>, const N: usize>(
    model: &F,
    names: &[&str; N],
    manoeuvre: &AircraftManoeuvre,
    (state, controls): (&[f64; 13], &[f64; 4]),
    (stepper, every): (&Stepper, f64),
    stop: Option<&StopCondition>,
    mut observe: impl FnMut(&Sample) -> bool,
) -> Result<AircraftRun, RunError> {
    let changes = manoeuvre.schedule();
    let settled_from = changes.last().map_or(0.0, |(t, _)| *t);
    let mut measured = Measured::new(state, settled_from);
    let mut runner = Runner {
        model,
        trim: model.state_of_euler(state),
        controls: *controls,
        control: manoeuvre.kind.control(),
        changes,
        next: 0,
        duration: manoeuvre.duration,
        trim_controls: *controls,
        stop,
        failure: None,
    };
    let observed = |sample: &Sample| {
        measured.row(sample.t, &sample.row);
        observe(sample)
    };
    let (reached, stats) = problem::solve(&mut runner, (stepper, every), observed);
    if let Some((time, reason)) = runner.failure {
        return Err(RunError::Failed { time, reason });
    }
    let end = reached.map_err(|error| match error {
        IntegrateError::NonFiniteState { component, t } => RunError::Failed {
            time: t,
            reason: format!(
                "{} is not finite (the aircraft left its atmosphere, or the step is too coarse)",
                names.get(component).unwrap_or(&"?")
            ),
        },
        other => RunError::Failed {
            time: other.time().unwrap_or(f64::NAN),
            reason: other.without_time(),
        },
    })?;
    Ok(AircraftRun {
        steps: stats.steps as u64,
        rhs_evals: stats.rhs_evals as u64,
        end: model.euler_state(&end.state.data.0[0]),
        measured,
        stopped_at: end.stopped.then_some(end.t),
    })
}

/// The Dutch roll's period (s) and damping ratio read from the yaw rate's successive swings
/// (at least three), where the response gives them: each maximum's height over the mean of
/// the minima either side of it, so that a slow drift of the yaw rate (a spiral, a turn the
/// kick left) is taken out to first order rather than read as damping.
pub fn dutch_roll(peaks: &[(f64, f64)], troughs: &[(f64, f64)]) -> Option<(f64, f64)> {
    let swing = |&(t, r): &(f64, f64)| {
        let before = troughs.iter().rev().find(|(tt, _)| *tt < t)?;
        let after = troughs.iter().find(|(tt, _)| *tt > t)?;
        Some((t, r - (before.1 + after.1) / 2.0))
    };
    let positive: Vec<(f64, f64)> = (peaks.iter())
        .filter_map(swing)
        .take_while(|(_, height)| *height > 0.0)
        .collect();
    if positive.len() < 3 {
        return None;
    }
    let cycles = (positive.len() - 1).min(3);
    let period = (positive[cycles].0 - positive[0].0) / cycles as f64;
    let decrement = (positive[0].1 / positive[cycles].1).ln() / cycles as f64;
    let damping = decrement / (4.0 * std::f64::consts::PI.powi(2) + decrement * decrement).sqrt();
    Some((period, damping))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The wind-axis state stops a run where it is singular, saying what: V not positive,
    /// |β| within 1° of 90° (on either side); 88° of sideslip goes on.
    #[test]
    fn the_wind_axes_stop_where_they_do_not_hold() {
        let stopped = wind_axes_cannot_go_on(0.0, 0.1).unwrap();
        assert!(stopped.contains("airspeed"), "{stopped}");
        for beta in [89.5f64, -89.5] {
            let stopped = wind_axes_cannot_go_on(500.0, beta.to_radians()).unwrap();
            assert!(stopped.contains("sideslip"), "{stopped}");
        }
        assert_eq!(wind_axes_cannot_go_on(500.0, 88f64.to_radians()), None);
    }
}
