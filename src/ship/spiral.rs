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
//! most [`Settle::tolerance`] over that window (max − min), and, for the reverse spiral, when
//! the mean r is within the same tolerance of the commanded rate and the mean rudder moved by
//! at most [`Settle::rudder_tolerance`] from the window before (the controller holds r at
//! once; the rudder follows the slower modes, the speed's). An angle not settled after
//! [`Settle::max_hold`] is taken as it stands and marked `settled: false`.
//!
//! What the criterion allows: if r approaches its steady value as one exponential of time
//! constant T, r(t) = r_s + A e^(−t/T), the variation over the last window is
//! |A| e^(−t/T)(1 − e^(−W/T)) while the distance left is |A| e^(−t/T), so a settled r is
//! within tolerance/(e^(W/T) − 1) of the steady one ([`Settle::error_bound`]).
//!
//! The schedule is the one driver's: the checks are instants of the manoeuvre's schedule (a
//! stretch ends at each), where the command changes if the angle has settled. The reverse
//! spiral's controller is δ_c = δ_i + g (r − r_c), its proportional part a load of the state,
//! and its integral part δ_i moved at each check by g (W/T_i) (r̄ − r_c) with T_i = W: a
//! sampled integral, as a digital autopilot's is, so the integrated state stays the ship's.
//! The gain is g = −1/(b_r τ), b_r the yaw acceleration per radian of rudder about the
//! straight course and τ the scene's `controller_time_s`: the closed loop's yaw rate settles
//! with time constant about τ.

use super::manoeuvre::Figures;

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
}

impl Settle {
    /// The largest distance between a settled r and the steady one for an approach as one
    /// exponential of time constant `time_constant` (s): tolerance/(e^(W/T) − 1).
    pub fn error_bound(&self, time_constant: f64) -> f64 {
        self.tolerance / (self.window / time_constant.abs()).exp_m1()
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
}

/// The loop of an r–δ curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Loop {
    /// The range of δ where two steady turns exist, rad.
    pub width: f64,
    /// The jump in r across the loop at δ = 0 (or the angle nearest it), rad/s; `None` where
    /// the loop does not reach δ = 0.
    pub height: Option<f64>,
}

/// A spiral's measured curve.
#[derive(Debug, Clone, PartialEq)]
pub struct SpiralCurve {
    /// The points in the order measured.
    pub points: Vec<SpiralPoint>,
    /// The criterion they were measured by.
    pub settle: Settle,
}

impl SpiralCurve {
    /// The loop, or `None` where the curve has none: a course-stable ship's.
    ///
    /// Direct spiral: the angles where the two passes' steady r have opposite signs, each
    /// larger than the tolerance; the loop runs from halfway to the next angle below the
    /// lowest of them to halfway to the next above the highest (so its width is known to the
    /// spacing of the angles); its height is the difference of the passes' r at δ = 0, or at
    /// the angle of the loop nearest it. Reverse spiral: the curve δ(r) turns back between
    /// its folds; the width is the δ between them, the height the r between the outer
    /// crossings of δ(r) with the loop's middle angle, halfway between the folds (δ = 0 for a
    /// ship without bias; a propeller's bias moves the loop off it).
    pub fn find_loop(&self) -> Option<Loop> {
        if self.points.iter().any(|p| p.branch == Branch::Reverse) {
            reverse_loop(&self.points)
        } else {
            direct_loop(&self.points, self.settle.tolerance)
        }
    }
}

fn direct_loop(points: &[SpiralPoint], tolerance: f64) -> Option<Loop> {
    let on = |branch: Branch, rudder: f64| {
        points
            .iter()
            .find(|p| p.branch == branch && p.rudder == rudder)
            .map(|p| p.yaw_rate)
    };
    let mut angles: Vec<f64> = points.iter().map(|p| p.rudder).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    let split: Vec<(f64, f64)> = angles
        .iter()
        .filter_map(|&d| {
            let (first, back) = (on(Branch::First, d)?, on(Branch::Back, d)?);
            let apart = first * back < 0.0 && first.abs().min(back.abs()) > tolerance;
            apart.then_some((d, (first - back).abs()))
        })
        .collect();
    let (&(low, _), &(high, _)) = (split.first()?, split.last()?);
    let index = |d: f64| angles.iter().position(|&a| a == d).unwrap_or(0);
    let below = index(low)
        .checked_sub(1)
        .map_or(low, |i| 0.5 * (low + angles[i]));
    let above = angles
        .get(index(high) + 1)
        .map_or(high, |a| 0.5 * (high + a));
    let height = split
        .iter()
        .min_by(|a, b| a.0.abs().total_cmp(&b.0.abs()))
        .map(|(_, h)| *h);
    Some(Loop {
        width: above - below,
        height,
    })
}

fn reverse_loop(points: &[SpiralPoint]) -> Option<Loop> {
    let mut curve: Vec<(f64, f64)> = points.iter().map(|p| (p.yaw_rate, p.rudder)).collect();
    curve.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (first, last) = (curve.first()?, curve.last()?);
    let trend = (last.1 - first.1).signum();
    // The points at either end of a stretch where δ(r) goes against the curve's trend.
    let folded: Vec<f64> = curve
        .windows(2)
        .filter(|w| (w[1].1 - w[0].1) * trend < 0.0)
        .flat_map(|w| [w[0].1, w[1].1])
        .collect();
    if folded.is_empty() {
        return None;
    }
    let low = folded.iter().copied().fold(f64::INFINITY, f64::min);
    let high = folded.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let middle = 0.5 * (low + high);
    let crossings: Vec<f64> = curve
        .windows(2)
        .map(|w| (w[0].0, w[0].1 - middle, w[1].0, w[1].1 - middle))
        .filter(|(_, d0, _, d1)| d0 * d1 < 0.0 || *d1 == 0.0)
        .map(|(r0, d0, r1, d1)| r0 - d0 * (r1 - r0) / (d1 - d0))
        .collect();
    let height = (crossings.len() >= 3).then(|| crossings[crossings.len() - 1] - crossings[0]);
    Some(Loop {
        width: high - low,
        height,
    })
}

/// A spiral's figures: the loop's width and height (zero for a curve without a loop; the
/// height `None` where the loop does not reach δ = 0), the curve itself, and notes for each
/// angle that did not settle and for a run that ended before every angle was measured
/// (`done`).
pub fn figures(points: Vec<SpiralPoint>, settle: Settle, done: bool) -> Figures {
    let mut notes = Vec::new();
    for p in points.iter().filter(|p| !p.settled) {
        notes.push(format!(
            "δ = {:.2}°, r = {:.4}°/s ({} pass) had not settled after {:.0} s: r still varied \
             by more than {}°/s over {} s",
            p.rudder.to_degrees(),
            p.yaw_rate.to_degrees(),
            p.branch.name(),
            p.held,
            settle.tolerance.to_degrees(),
            settle.window
        ));
    }
    if !done {
        notes.push(
            "the run ended before every setpoint was measured: lengthen duration_s or \
             max_hold_s"
                .into(),
        );
    }
    let curve = SpiralCurve { points, settle };
    let found = done.then(|| curve.find_loop());
    let width = found.map(|l| l.map_or(0.0, |l| l.width.to_degrees()));
    let height = found.and_then(|l| match l {
        None => Some(0.0),
        Some(l) => l.height.map(f64::to_degrees),
    });
    Figures {
        values: vec![("loop_width_deg", width), ("loop_height_deg_s", height)],
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
    /// (t, r, δ) since the last check.
    window: Vec<(f64, f64, f64)>,
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

    /// Starts the first setpoint at `t`.
    pub(crate) fn start(&mut self, t: f64, r: f64, delta: f64) {
        self.started = t;
        self.window = vec![(t, r, delta)];
    }

    /// Adds an instant to the window.
    pub(crate) fn record(&mut self, t: f64, r: f64, delta: f64) {
        if self.setpoint().is_some() && self.window.last().is_none_or(|w| t > w.0) {
            self.window.push((t, r, delta));
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
        let (variation, mean_r, mean_delta) = window_statistics(&self.window);
        let last = self.window.last().copied().unwrap_or((t, 0.0, 0.0));
        let on_target = gain.is_none()
            || ((mean_r - setpoint).abs() <= settle.tolerance
                && self
                    .previous_rudder
                    .is_some_and(|d| (mean_delta - d).abs() <= settle.rudder_tolerance));
        let settled = variation <= settle.tolerance && on_target;
        self.previous_rudder = Some(mean_delta);
        let held = t - self.started;
        let changed = settled || held >= settle.max_hold * (1.0 - 1e-12);
        if changed {
            let reverse = gain.is_some();
            self.points.push(SpiralPoint {
                rudder: if reverse { mean_delta } else { setpoint },
                yaw_rate: if reverse { mean_r } else { last.1 },
                target: reverse.then_some(setpoint),
                branch,
                settled,
                held,
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

/// (max r − min r, the time-weighted mean r, the mean δ) over a window of (t, r, δ).
fn window_statistics(window: &[(f64, f64, f64)]) -> (f64, f64, f64) {
    let low = window.iter().map(|w| w.1).fold(f64::INFINITY, f64::min);
    let high = window.iter().map(|w| w.1).fold(f64::NEG_INFINITY, f64::max);
    let (mut span, mut r, mut delta) = (0.0, 0.0, 0.0);
    for w in window.windows(2) {
        let dt = w[1].0 - w[0].0;
        span += dt;
        r += 0.5 * dt * (w[0].1 + w[1].1);
        delta += 0.5 * dt * (w[0].2 + w[1].2);
    }
    match window {
        [] => (f64::INFINITY, 0.0, 0.0),
        [only] => (0.0, only.1, only.2),
        _ if span > 0.0 => (high - low, r / span, delta / span),
        [first, ..] => (high - low, first.1, first.2),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(rudder_deg: f64, r: f64, branch: Branch) -> SpiralPoint {
        SpiralPoint {
            rudder: rudder_deg.to_radians(),
            yaw_rate: r,
            target: None,
            branch,
            settled: true,
            held: 100.0,
        }
    }

    /// An unstable ship's direct spiral: between −2° and 2° the passes disagree.
    #[test]
    fn a_direct_loop_is_where_the_passes_disagree() {
        let angles = [6.0, 4.0, 2.0, 0.0, -2.0, -4.0, -6.0];
        let first = [-0.3, -0.25, -0.2, -0.15, -0.1, 0.25, 0.3];
        let back = [-0.3, -0.25, 0.1, 0.15, 0.2, 0.25, 0.3];
        let mut points: Vec<SpiralPoint> = (angles.iter().zip(first))
            .map(|(&d, r)| point(d, r, Branch::First))
            .collect();
        points.extend(
            (angles.iter().zip(back).rev().skip(1)).map(|(&d, r)| point(d, r, Branch::Back)),
        );
        let settle = Settle {
            window: 100.0,
            tolerance: 1e-3,
            max_hold: 1000.0,
            rudder_tolerance: 1e-3,
        };
        let curve = SpiralCurve { points, settle };
        let found = curve.find_loop().unwrap();
        // From halfway between −4° and −2° to halfway between 2° and 4°.
        assert!((found.width.to_degrees() - 6.0).abs() < 1e-12, "{found:?}");
        assert!((found.height.unwrap() - 0.3).abs() < 1e-12);
        // The same passes agreeing: no loop.
        let mut stable = curve.clone();
        for p in &mut stable.points {
            p.yaw_rate = -0.05 * p.rudder.to_degrees();
        }
        assert_eq!(stable.find_loop(), None);
    }

    #[test]
    fn a_reverse_loop_is_where_the_rudder_turns_back() {
        // δ(r) = r³ − r, a loop between the folds at r = ±1/√3, crossing zero at r = 0, ±1.
        let points: Vec<SpiralPoint> = (-12..=12)
            .map(|k| {
                let r = f64::from(k) / 10.0;
                SpiralPoint {
                    rudder: r * r * r - r,
                    branch: Branch::Reverse,
                    ..point(0.0, r, Branch::Reverse)
                }
            })
            .collect();
        let settle = Settle {
            window: 100.0,
            tolerance: 1e-3,
            max_hold: 1000.0,
            rudder_tolerance: 1e-3,
        };
        let found = SpiralCurve { points, settle }.find_loop().unwrap();
        // The grid's extremes of δ: ±(0.6 − 0.216) = ±0.384 (the folds are ±0.3849).
        assert!((found.width - 0.768).abs() < 1e-12, "{found:?}");
        assert!((found.height.unwrap() - 2.0).abs() < 1e-12);
    }

    #[test]
    fn the_error_bound_follows_one_exponential() {
        let settle = Settle {
            window: 100.0,
            tolerance: 1e-3,
            max_hold: 1000.0,
            rudder_tolerance: 1e-3,
        };
        // W = T ln 2: the variation over the window equals the distance left.
        let t = 100.0 / std::f64::consts::LN_2;
        assert!((settle.error_bound(t) - 1e-3).abs() < 1e-15);
    }
}
