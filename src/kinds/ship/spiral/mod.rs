//! The spiral tests: the steady yaw rate against the rudder angle, the r–δ curve, whose loop
//! (hysteresis) shows a course-unstable ship (MSC/Circ.1053, the explanatory notes to IMO
//! MSC.137(76), judge course stability by it).
//!
//! - **Dieudonné's direct spiral** ([`Spiral`]): the rudder is put to each angle of a list in
//!   turn (from one side through zero to the other) and back through the list to the first,
//!   each angle held until the yaw rate has settled; the steady r at each. On an unstable ship
//!   the two passes disagree between the loop's ends: there the ship keeps turning to the
//!   side it came from.
//! - **Bech's reverse spiral** ([`ReverseSpiral`]): a controller holds a commanded yaw rate
//!   with the rudder; the mean rudder and the mean yaw rate over the settled window are a
//!   point of the curve. The curve is single-valued in r, so it is measured through the
//!   loop's unstable middle too, where the direct spiral cannot go.
//!
//! **Settled**, stated: each angle (or commanded rate) is held and checked at the end of each
//! window of [`Settle::window`] seconds from its start; it has settled when r varied by at
//! most [`Settle::tolerance`] over that window (max − min) and the speed u, the quantity that
//! converges slowest, by at most [`Settle::speed_tolerance`]; and, for the reverse spiral,
//! when the mean r is within the same tolerance of the commanded rate and the mean rudder
//! moved by at most [`Settle::rudder_tolerance`] from the window before. The speed is checked
//! because what is read follows it: a ship put into a turn overshoots its steady r while it
//! still has the approach's speed, then r drifts back as the speed falls, and an r (or the
//! reverse spiral's rudder) that turns back stops moving for a window while the speed still
//! drifts and the turn is far from steady. An angle not settled after [`Settle::max_hold`] is
//! taken as it stands and marked `settled: false`; no figure rests on it ([`verdict`]).
//!
//! What the criterion allows: if r approaches its steady value as one exponential of time
//! constant T, r(t) = r_s + A e^(−t/T), the variation over the last window is
//! |A| e^(−t/T)(1 − e^(−W/T)) while the distance left is |A| e^(−t/T), so a settled r is
//! within tolerance/(e^(W/T) − 1) of the steady one ([`Settle::error_bound`]); with T the
//! ship's slowest sway–yaw time constant, |T₁| of Nomoto's model about the straight course
//! ([`Settle::time_constant`]), that is the criterion's resolution ([`Settle::resolution`]):
//! two settled r closer than twice it may be one steady turn.
//!
//! The schedule is the one driver's: the checks are instants of the manoeuvre's schedule (a
//! stretch ends at each), where the command changes if the angle has settled. The reverse
//! spiral's controller is δ_c = δ_i + g (r − r_c), its proportional part a load of the state,
//! and its integral part δ_i moved at each check by g (W/T_i) (r̄ − r_c) with T_i = W: a
//! sampled integral, as a digital autopilot's is, so the integrated state stays the ship's.
//! The gain is g = −1/(b_r τ), b_r the yaw acceleration per radian of rudder about the
//! straight course and τ the scene's `controller_time_s`: the closed loop's yaw rate settles
//! with time constant about τ.

pub mod verdict;

use super::manoeuvre::Figures;
use super::steady::SteadyTurns;
use crate::Short;
pub use verdict::{Loop, Verdict};

/// When an angle (or a commanded rate) counts as held long enough.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settle {
    /// W, s: the window over which r is checked, and the interval of the checks.
    pub window: f64,
    /// The largest variation of r over the window, rad/s.
    pub tolerance: f64,
    /// The longest an angle is held, s.
    pub max_hold: f64,
    /// The reverse spiral's: the largest change of the mean rudder angle from one window to
    /// the next, rad (the controller holds r at once; δ follows the slower modes, the speed's).
    pub rudder_tolerance: f64,
    /// The largest variation of the speed u over the window, m/s (the quantity that
    /// converges slowest).
    pub speed_tolerance: f64,
    /// T, s: the ship's slowest sway–yaw time constant, |T₁| of Nomoto's model about the
    /// straight course (the slowest decay of the linear model's modes where T₁ is not real).
    pub time_constant: f64,
}

impl Settle {
    /// The largest distance between a settled r and the steady one for an approach as one
    /// exponential of time constant `time_constant` (s): tolerance/(e^(W/T) − 1).
    pub fn error_bound(&self, time_constant: f64) -> f64 {
        self.tolerance / (self.window / time_constant.abs()).exp_m1()
    }

    /// ε, rad/s: the largest distance of a settled r from the steady one, the error bound at
    /// the ship's own time constant; two settled r closer than 2ε may be one steady turn.
    pub fn resolution(&self) -> f64 {
        self.error_bound(self.time_constant)
    }
}

/// Dieudonné's direct spiral.
#[derive(Debug, Clone, PartialEq)]
pub struct Spiral {
    /// The rudder angles of the first pass, rad, strictly monotonic; the run comes back
    /// through them in reverse.
    pub rudders: Vec<f64>,
    /// When each has settled.
    pub settle: Settle,
    /// L, m: the steady turns traced beside the points are in variables scaled by it.
    pub length: f64,
}

/// Bech's reverse spiral.
#[derive(Debug, Clone, PartialEq)]
pub struct ReverseSpiral {
    /// The commanded yaw rates, rad/s, in the order run.
    pub yaw_rates: Vec<f64>,
    /// When each has settled.
    pub settle: Settle,
    /// g, rad of rudder per rad/s of yaw rate above the commanded one.
    pub gain: f64,
    /// L, m: the steady turns traced beside the points are in variables scaled by it.
    pub length: f64,
}

/// Which pass of a spiral a point is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Branch {
    /// The direct spiral's first pass through its angles.
    First,
    /// Its way back.
    Back,
    /// The reverse spiral's (one).
    Reverse,
}

impl Branch {
    /// `first`, `back` or `reverse`.
    pub fn name(self) -> &'static str {
        match self {
            Branch::First => "first",
            Branch::Back => "back",
            Branch::Reverse => "reverse",
        }
    }
}

/// One point of the r–δ curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpiralPoint {
    /// δ, rad: the angle held (direct), the mean over the settled window (reverse).
    pub rudder: f64,
    /// r, rad/s: at the end of the settled window (direct), its mean over it (reverse).
    pub yaw_rate: f64,
    /// The commanded yaw rate (reverse), rad/s.
    pub target: Option<f64>,
    /// Which pass.
    pub branch: Branch,
    /// Whether r settled by the criterion before the longest hold.
    pub settled: bool,
    /// How long the angle was held, s.
    pub held: f64,
    /// When the point was taken, s.
    pub at: f64,
}

/// A spiral's measured curve, and the steady turns it measures.
#[derive(Debug, Clone, PartialEq)]
pub struct SpiralCurve {
    /// The points in the order measured.
    pub points: Vec<SpiralPoint>,
    /// The criterion they were measured by.
    pub settle: Settle,
    /// Why the points do not cover every setpoint (the run ended first, or the ship went
    /// astern or stopped and the points after are not given); `None` for a whole spiral.
    pub incomplete: Option<String>,
    /// The steady turns over the spiral's range of rudder angles, by continuation, or why
    /// they could not be traced.
    pub steady: Result<SteadyTurns, String>,
}

impl SpiralCurve {
    /// What the points say: a loop, none, or undetermined ([`verdict`]).
    pub fn verdict(&self) -> Verdict {
        verdict::of(self)
    }

    /// The loop, where the points show one ([`SpiralCurve::verdict`]).
    pub fn find_loop(&self) -> Option<Loop> {
        match self.verdict() {
            Verdict::Loop(found) => Some(found),
            Verdict::NoLoop | Verdict::Undetermined(_) => None,
        }
    }

    /// The range of rudder angles the points span, rad.
    pub fn rudder_range(&self) -> (f64, f64) {
        let rudders: Vec<f64> = self.points.iter().map(|p| p.rudder).collect();
        range(&rudders)
    }
}

/// The least and the largest of `angles`.
pub fn range(angles: &[f64]) -> (f64, f64) {
    let low = angles.iter().copied().fold(f64::INFINITY, f64::min);
    (
        low,
        angles.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    )
}

/// A spiral's figures: the loop's width and height from its settled points (zero for a
/// curve without a loop, the height `None` where the loop does not reach δ = 0; both `None`
/// where the verdict is undetermined, and a note says why), the width between the folds of
/// the steady-turn curve, the curve itself, and notes for each angle that did not settle.
pub fn figures(curve: SpiralCurve) -> Figures {
    let settle = curve.settle;
    let mut notes = Vec::new();
    for p in curve.points.iter().filter(|p| !p.settled) {
        let moved = match p.branch {
            Branch::Reverse => format!(
                "r, the mean rudder or the speed still moved by more than {}°/s, {}° or {} m/s",
                Short(settle.tolerance.to_degrees()),
                Short(settle.rudder_tolerance.to_degrees()),
                Short(settle.speed_tolerance)
            ),
            _ => format!(
                "r or the speed still varied by more than {}°/s or {} m/s",
                Short(settle.tolerance.to_degrees()),
                Short(settle.speed_tolerance)
            ),
        };
        notes.push(format!(
            "δ = {:.2}°, r = {:.4}°/s ({} pass) had not settled after {:.0} s: {moved} over {} \
             s; no figure rests on it",
            p.rudder.to_degrees(),
            p.yaw_rate.to_degrees(),
            p.branch.name(),
            p.held,
            Short(settle.window)
        ));
    }
    notes.extend(curve.incomplete.clone());
    let verdict = curve.verdict();
    let (width, height) = match &verdict {
        Verdict::NoLoop => (Some(0.0), Some(0.0)),
        Verdict::Loop(found) => (Some(found.width), found.height),
        Verdict::Undetermined(why) => {
            if curve.incomplete.is_none() {
                notes.push(format!("no loop figure: {why}"));
            }
            (None, None)
        }
    };
    let steady = curve.steady.as_ref().ok().and_then(SteadyTurns::loop_width);
    if let Err(why) = &curve.steady {
        notes.push(format!("the steady turns were not traced: {why}"));
    }
    Figures {
        values: vec![
            ("loop_width_deg", width.map(f64::to_degrees)),
            ("loop_height_deg_s", height.map(f64::to_degrees)),
            ("steady_loop_width_deg", steady.map(f64::to_degrees)),
        ],
        side: None,
        notes,
        marks: vec![],
        spiral: Some(curve),
    }
}

/// A spiral under way: the setpoints left, the current one's window, the points measured.
#[derive(Debug, Clone, Default)]
pub(crate) struct Progress {
    /// Each setpoint (δ, or a commanded r) with its pass.
    setpoints: Vec<(f64, Branch)>,
    /// The index of the one held.
    current: usize,
    /// When it was put on, s.
    started: f64,
    /// (t, r, δ, u) since the last check.
    window: Vec<Sample>,
    /// The reverse spiral's integral part δ_i, rad.
    pub(crate) integral: f64,
    /// The mean δ over the window before, rad (reverse spiral).
    previous_rudder: Option<f64>,
    /// The points measured.
    pub(crate) points: Vec<SpiralPoint>,
}

impl Progress {
    /// A direct spiral's: the angles, then back through them.
    pub(crate) fn direct(spiral: &Spiral) -> Self {
        let mut setpoints: Vec<(f64, Branch)> =
            spiral.rudders.iter().map(|&d| (d, Branch::First)).collect();
        let back = spiral.rudders.iter().rev().skip(1);
        setpoints.extend(back.map(|&d| (d, Branch::Back)));
        Progress {
            setpoints,
            ..Progress::default()
        }
    }

    /// A reverse spiral's: the commanded rates in order.
    pub(crate) fn reverse(spiral: &ReverseSpiral) -> Self {
        Progress {
            setpoints: (spiral.yaw_rates.iter())
                .map(|&r| (r, Branch::Reverse))
                .collect(),
            ..Progress::default()
        }
    }

    /// The setpoint held, `None` once every one is measured.
    pub(crate) fn setpoint(&self) -> Option<f64> {
        self.setpoints.get(self.current).map(|(s, _)| *s)
    }

    /// Starts the first setpoint at `at`.
    pub(crate) fn start(&mut self, at: Sample) {
        self.started = at.t;
        self.window = vec![at];
    }

    /// Adds an instant to the window.
    pub(crate) fn record(&mut self, at: Sample) {
        if self.setpoint().is_some() && self.window.last().is_none_or(|w| at.t > w.t) {
            self.window.push(at);
        }
    }

    /// The check at the end of a window at `t`: whether the setpoint has settled, and if so
    /// (or if it has been held [`Settle::max_hold`]) its point is taken and the next one put
    /// on. A reverse spiral's integral part moves by `gain` (W/T_i)(r̄ − r_c) when not settled.
    /// Returns whether the setpoint changed.
    pub(crate) fn check(&mut self, t: f64, settle: &Settle, gain: Option<f64>) -> bool {
        let Some((setpoint, branch)) = self.setpoints.get(self.current).copied() else {
            return false;
        };
        let window = Window::of(&self.window);
        let last = self.window.last().copied().unwrap_or(Sample {
            t,
            r: 0.0,
            delta: 0.0,
            u: 0.0,
        });
        let (mean_r, mean_delta) = (window.mean_r, window.mean_delta);
        let on_target = gain.is_none()
            || ((mean_r - setpoint).abs() <= settle.tolerance
                && self
                    .previous_rudder
                    .is_some_and(|d| (mean_delta - d).abs() <= settle.rudder_tolerance));
        let settled = window.r_variation <= settle.tolerance
            && window.speed_variation <= settle.speed_tolerance
            && on_target;
        self.previous_rudder = Some(mean_delta);
        let held = t - self.started;
        let changed = settled || held >= settle.max_hold * (1.0 - 1e-12);
        if changed {
            let reverse = gain.is_some();
            self.points.push(SpiralPoint {
                rudder: if reverse { mean_delta } else { setpoint },
                yaw_rate: if reverse { mean_r } else { last.r },
                target: reverse.then_some(setpoint),
                branch,
                settled,
                held,
                at: t,
            });
            self.current += 1;
            self.started = t;
            self.previous_rudder = None;
        } else if let Some(gain) = gain {
            // T_i = W: the window's mean error, integrated over it, over T_i.
            self.integral += gain * (mean_r - setpoint);
        }
        self.window = vec![last];
        changed
    }
}

/// One instant of a spiral's window.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Sample {
    /// t, s.
    pub(crate) t: f64,
    /// r, rad/s.
    pub(crate) r: f64,
    /// δ, rad.
    pub(crate) delta: f64,
    /// u, m/s.
    pub(crate) u: f64,
}

/// What a window of samples says.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Window {
    /// max r − min r.
    r_variation: f64,
    /// max u − min u.
    speed_variation: f64,
    /// The time-weighted mean r.
    mean_r: f64,
    /// The time-weighted mean δ.
    mean_delta: f64,
}

impl Window {
    fn of(samples: &[Sample]) -> Self {
        let spread = |value: fn(&Sample) -> f64| {
            let low = samples.iter().map(value).fold(f64::INFINITY, f64::min);
            samples.iter().map(value).fold(f64::NEG_INFINITY, f64::max) - low
        };
        let (mut span, mut r, mut delta) = (0.0, 0.0, 0.0);
        for w in samples.windows(2) {
            let dt = w[1].t - w[0].t;
            span += dt;
            r += 0.5 * dt * (w[0].r + w[1].r);
            delta += 0.5 * dt * (w[0].delta + w[1].delta);
        }
        let (mean_r, mean_delta) = match samples {
            [] => (0.0, 0.0),
            _ if span > 0.0 => (r / span, delta / span),
            [first, ..] => (first.r, first.delta),
        };
        Window {
            r_variation: if samples.is_empty() {
                f64::INFINITY
            } else {
                spread(|s| s.r)
            },
            speed_variation: if samples.is_empty() {
                f64::INFINITY
            } else {
                spread(|s| s.u)
            },
            mean_r,
            mean_delta,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_error_bound_follows_one_exponential() {
        // W = T ln 2: the variation over the window equals the distance left.
        let t = 100.0 / std::f64::consts::LN_2;
        let settle = Settle {
            window: 100.0,
            tolerance: 1e-3,
            max_hold: 1000.0,
            rudder_tolerance: 1e-3,
            speed_tolerance: 1e-3,
            time_constant: t,
        };
        assert!((settle.error_bound(t) - 1e-3).abs() < 1e-15);
        assert_eq!(settle.resolution(), settle.error_bound(t));
    }

    /// A window whose rudder has stopped moving while the speed still drifts: the speed's
    /// variation is what the reverse spiral's check reads.
    #[test]
    fn a_window_measures_the_speeds_drift() {
        let samples: Vec<Sample> = (0..=10)
            .map(|k| {
                let t = f64::from(k) * 10.0;
                Sample {
                    t,
                    r: 0.01,
                    delta: -0.02,
                    u: 4.0 - 1e-3 * t,
                }
            })
            .collect();
        let window = Window::of(&samples);
        assert_eq!(window.r_variation, 0.0);
        assert!((window.speed_variation - 0.1).abs() < 1e-12);
        assert!((window.mean_delta + 0.02).abs() < 1e-15);
    }
}
