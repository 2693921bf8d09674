//! The rudder's command and the engine's as the ship model's loads: what the steering gear
//! and the propeller rate are at a time and state, over one stretch of a manoeuvre.

use super::*;
use crate::kinds::ship::wind::Gust;

/// The steering gear under a command and the engine under its own, as the ship model's
/// loads: the rudder's rate δ̇, the propeller rate n and the wind's gust at a time and state.
#[derive(Debug, Clone, Copy)]
pub struct Steering<'a> {
    pub(super) rudder: &'a Rudder,
    pub(super) command: Command<'a>,
    /// The propeller-rate command; `None` for a ship without a propulsion model.
    pub(super) engine: Option<RateCommand>,
    /// The propeller rate without a command: an MMG ship's n₀, which balances the approach
    /// (zero, and read by no term, for a ship without a propeller).
    pub(super) held_rate: f64,
    /// The wind's gusts, for a ship in a gusting wind.
    pub(super) gust: Option<&'a Gust>,
}

/// The rudder command over one stretch.
#[derive(Debug, Clone, Copy)]
pub(super) enum Command<'a> {
    Hold(f64),
    Series(&'a Series),
    /// δ_c = integral + gain (r − target): the reverse spiral's controller.
    Track {
        integral: f64,
        gain: f64,
        target: f64,
    },
}

impl Steering<'_> {
    /// The saturated command at `t` with the yaw rate at `r`, and its slope (a series' without
    /// a lag).
    pub(super) fn command(&self, t: f64, r: f64) -> (f64, f64) {
        match self.command {
            Command::Hold(angle) => (self.rudder.saturate(angle), 0.0),
            Command::Track {
                integral,
                gain,
                target,
            } => (self.rudder.saturate(integral + gain * (r - target)), 0.0),
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

impl Steering<'_> {
    /// ((δ_c − δ)/T_δ)² − δ̇_max² at `t` with the rudder at `delta`: negative while the lag's
    /// rate is within its limit; `None` for a steering gear without both.
    pub(super) fn rate_margin(&self, t: f64, r: f64, delta: f64) -> Option<f64> {
        let (lag, max) = (self.rudder.time_constant?, self.rudder.max_rate?);
        let rate = (self.command(t, r).0 - delta) / lag;
        Some(rate * rate - max * max)
    }
}

impl Loads<f64, 7, 3> for Steering<'_> {
    /// δ̇: the lag's rate toward the saturated command, or a series' slope for a rudder
    /// without a lag (which follows its command); n: the engine's command at `t`, or the
    /// held rate without one; g: the gust at `t`, zero where the wind does not gust.
    fn at(&self, t: f64, state: &[f64; 7]) -> [f64; 3] {
        let (command, slope) = self.command(t, state[2]);
        let rate = self.engine.map_or(self.held_rate, |engine| engine.rate(t));
        let gust = self.gust.map_or(0.0, |gust| gust.at(t));
        [
            self.rudder.rate(command, state[6]).unwrap_or(slope),
            rate,
            gust,
        ]
    }
}
