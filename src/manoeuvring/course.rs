//! What a manoeuvre's figures assume about the ship's course, checked on the run.
//!
//! A figure is only what its definition says if the ship did what the definition assumes:
//! a *steady* turning radius and speed need a turn that has settled, advance and tactical
//! diameter need a ship that is still going ahead when its heading passes 90° and 180°. A
//! made-up table can send a ship astern in its turn while the heading still passes 540°; the
//! numbers read off such a run are not the figures they are named after. So the run keeps a
//! record of its course after the execute, and each figure is given only where its condition
//! held; where one did not, the figure is absent and a note says why.
//!
//! The conditions, stated:
//! - **Going ahead**: u > 0 at every step after the execute up to the instant read.
//! - **Not stopped**: the speed U = √(u² + v²) stays above [`STOPPED_FRACTION`] of the speed
//!   at the execute.
//! - **Turning one way**: once the heading has changed by [`TURN_ESTABLISHED`], the yaw rate
//!   keeps the sign of the heading change.
//! - **Steady**: the heading has changed by 540° or more, and over the last 360° of heading
//!   change before the end both U and r stay within [`STEADY_TOLERANCE`] (relative) of their
//!   final values.

use std::f64::consts::PI;

/// The largest relative variation of U and of r over the last 360° for a steady turn.
pub const STEADY_TOLERANCE: f64 = 0.01;
/// Below this fraction of the approach speed the ship counts as stopped.
pub const STOPPED_FRACTION: f64 = 0.05;
/// The heading change (rad, 10°) after which the turn's side is taken as established.
pub const TURN_ESTABLISHED: f64 = PI / 18.0;
/// The least heading change (rad, 540°) before a turn may be read as steady.
pub const STEADY_AFTER: f64 = 3.0 * PI;

/// One instant of the course after the execute.
#[derive(Debug, Clone, Copy)]
struct Point {
    t: f64,
    /// ψ − ψ at the execute.
    turned: f64,
    speed: f64,
    r: f64,
}

/// The course after the execute, as the conditions need it.
#[derive(Debug, Default, Clone)]
pub struct Course {
    approach_speed: f64,
    /// Whether the rudder is held, so that the turn has one side (a zig-zag's reverses).
    held: bool,
    points: Vec<Point>,
    /// When u first fell below zero.
    pub astern: Option<f64>,
    /// When U first fell below the stopped fraction of the approach speed.
    pub stopped: Option<f64>,
    /// When r first took the sign opposite to the turn's, once the turn was established.
    pub reversed: Option<f64>,
}

impl Course {
    /// A course from the execute, where the ship runs at `approach_speed` (m/s); `held`: the
    /// rudder is held there (a turning circle), so the turn should keep its side.
    pub fn new(approach_speed: f64, held: bool) -> Self {
        Self {
            approach_speed,
            held,
            ..Self::default()
        }
    }

    /// Records the instant `t` with u, v, r and the heading change since the execute. The
    /// instants come in the run's order: a step taken past where a stretch ended (an event)
    /// is the stretch's trial, not the course, and is not recorded (a test build checks it).
    pub fn record(&mut self, t: f64, u: f64, v: f64, r: f64, turned: f64) {
        debug_assert!(
            self.points.last().is_none_or(|last| last.t <= t),
            "the course went back from t = {} to {t}",
            self.points.last().map_or(f64::NAN, |last| last.t)
        );
        let speed = u.hypot(v);
        if u < 0.0 && self.astern.is_none() {
            self.astern = Some(t);
        }
        if speed < STOPPED_FRACTION * self.approach_speed && self.stopped.is_none() {
            self.stopped = Some(t);
        }
        let established = turned.abs() >= TURN_ESTABLISHED;
        if self.held && established && r * turned < 0.0 && self.reversed.is_none() {
            self.reversed = Some(t);
        }
        self.points.push(Point {
            t,
            turned,
            speed,
            r,
        });
    }

    /// The heading change at the last instant recorded, rad (positive to starboard).
    pub fn turned(&self) -> f64 {
        self.points.last().map_or(0.0, |p| p.turned)
    }

    /// Why a figure read at `t` does not hold, if the ship went astern or stopped by then.
    pub fn broken_by(&self, t: f64) -> Option<String> {
        match (
            self.astern.filter(|&a| a <= t),
            self.stopped.filter(|&s| s <= t),
        ) {
            (Some(a), _) => Some(format!("the ship went astern (u < 0) at t = {a:.1} s")),
            (None, Some(s)) => Some(format!(
                "the ship stopped (U below {:.0} % of the approach speed) at t = {s:.1} s",
                STOPPED_FRACTION * 100.0
            )),
            (None, None) => None,
        }
    }

    /// What the course did that the figures do not assume, one note each.
    pub fn notes(&self) -> Vec<String> {
        let mut notes = Vec::new();
        if let Some(t) = self.astern {
            notes.push(format!(
                "the ship went astern (u < 0) at t = {t:.1} s: no figure read after that is given"
            ));
        }
        if let Some(t) = self.stopped {
            notes.push(format!(
                "the ship stopped (U below {:.0} % of the approach speed {:.3} m/s) at t = \
                 {t:.1} s: no figure read after that is given",
                STOPPED_FRACTION * 100.0,
                self.approach_speed
            ));
        }
        if let Some(t) = self.reversed {
            notes.push(format!(
                "the ship turned the other way (r changed sign against the turn) at t = {t:.1} s"
            ));
        }
        notes
    }

    /// The steady turn's speed U and yaw rate r (the last instant's), or why the turn is not
    /// steady by the criterion of the module's documentation.
    pub fn steady(&self) -> Result<(f64, f64), String> {
        let Some(last) = self.points.last() else {
            return Err("the run ended at the execute".into());
        };
        if let Some(why) = self.broken_by(last.t).or_else(|| {
            self.reversed
                .map(|t| format!("the ship turned the other way at t = {t:.1} s"))
        }) {
            return Err(format!("no steady turn: {why}"));
        }
        if last.turned.abs() < STEADY_AFTER {
            return Err(format!(
                "the heading changed by {:.1}° by the end: the steady turn is read after 540°; \
                 lengthen duration_s",
                last.turned.abs().to_degrees()
            ));
        }
        let window = self
            .points
            .iter()
            .filter(|p| (last.turned - p.turned).abs() <= 2.0 * PI);
        let variation = |value: fn(&Point) -> f64| {
            let end = value(last);
            window
                .clone()
                .map(|p| (value(p) - end).abs())
                .fold(0.0, f64::max)
                / end.abs()
        };
        let (speed, yaw_rate) = (variation(|p| p.speed), variation(|p| p.r));
        if speed > STEADY_TOLERANCE || yaw_rate > STEADY_TOLERANCE {
            return Err(format!(
                "the turn has not settled: over the last 360° of heading U varied by {:.3} % \
                 and r by {:.3} % of their final values (a steady turn needs both within {} %); \
                 lengthen duration_s",
                speed * 100.0,
                yaw_rate * 100.0,
                STEADY_TOLERANCE * 100.0
            ));
        }
        Ok((last.speed, last.r))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A turn at r = −0.02 rad/s and 5 m/s whose speed and rate follow `wobble(t)`.
    fn turn(wobble: impl Fn(f64) -> f64, seconds: f64) -> Course {
        let mut course = Course::new(5.0, true);
        let mut turned = 0.0;
        for k in 0..=(seconds as usize * 10) {
            let t = k as f64 * 0.1;
            let r = -0.02 * wobble(t);
            course.record(t, 5.0 * wobble(t), 0.0, r, turned);
            turned += r * 0.1;
        }
        course
    }

    #[test]
    fn a_settled_turn_is_steady_and_a_wobbling_one_is_not() {
        let settled = turn(|t| 1.0 + 0.5 * (-t / 20.0).exp(), 1200.0);
        let (speed, r) = settled.steady().unwrap();
        assert!((speed - 5.0).abs() < 1e-6 && (r + 0.02).abs() < 1e-6);
        let wobbling = turn(|t| 1.0 + 0.05 * (t / 30.0).sin(), 1200.0);
        let why = wobbling.steady().unwrap_err();
        assert!(why.contains("has not settled"), "{why}");
    }

    #[test]
    fn a_short_turn_is_not_steady() {
        let short = turn(|_| 1.0, 300.0);
        assert!(short.steady().unwrap_err().contains("read after 540°"));
    }

    #[test]
    fn going_astern_stopping_and_reversing_are_named() {
        let mut course = Course::new(5.0, true);
        course.record(0.0, 5.0, 0.0, -0.01, 0.0);
        course.record(10.0, 2.0, 0.0, -0.02, -0.5);
        course.record(20.0, 0.1, 0.0, 0.01, -0.6);
        course.record(30.0, -0.9, 0.0, 0.01, -0.4);
        assert_eq!(course.reversed, Some(20.0));
        assert_eq!(course.stopped, Some(20.0));
        assert_eq!(course.astern, Some(30.0));
        assert!(course.broken_by(15.0).is_none());
        assert!(course.broken_by(25.0).unwrap().contains("stopped"));
        assert!(course.broken_by(30.0).unwrap().contains("astern"));
        assert_eq!(course.notes().len(), 3);
        assert!(course.steady().unwrap_err().contains("astern"));
    }
}
