//! The steering gear: the commanded angle saturated at δ_max, followed by a first-order lag,
//! whose rate is limited to δ̇_max; and the commands a manoeuvre gives it.
//!
//! The rudder angle δ is a state of the model (its rate is the model's input), so the lag and
//! the rate limit are integrated with the ship. Without a lag the rudder follows its command
//! at once: a new command sets δ, and a time series moves δ at the series' slope. A rate
//! limit acts on the lag's rate, so it needs a lag.

/// The steering gear's limits, in radians and seconds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rudder {
    /// δ_max: the command is clamped to ±δ_max.
    pub max_angle: Option<f64>,
    /// δ̇_max: the lag's rate is clamped to ±δ̇_max.
    pub max_rate: Option<f64>,
    /// T_δ of the lag δ̇ = (δ_c − δ)/T_δ.
    pub time_constant: Option<f64>,
}

impl Rudder {
    /// The command after saturation.
    pub fn saturate(&self, command: f64) -> f64 {
        match self.max_angle {
            Some(max) => command.clamp(-max, max),
            None => command,
        }
    }

    /// δ̇ with the saturated command `command` and the angle `delta`, or `None` for a rudder
    /// without a lag (it follows its command at once).
    pub fn rate(&self, command: f64, delta: f64) -> Option<f64> {
        let lag = self.time_constant?;
        let rate = (command - delta) / lag;
        Some(match self.max_rate {
            Some(max) => rate.clamp(-max, max),
            None => rate,
        })
    }
}

/// A piecewise-linear command: angles (rad) at times (s), constant before the first and
/// after the last.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    times: Vec<f64>,
    angles: Vec<f64>,
}

impl Series {
    /// A series of strictly increasing finite times and finite angles, of equal length, at
    /// least one; `None` otherwise.
    pub fn new(times: Vec<f64>, angles: Vec<f64>) -> Option<Self> {
        let increasing = times.windows(2).all(|w| w[0] < w[1]);
        let finite = times.iter().chain(&angles).all(|x| x.is_finite());
        (times.len() == angles.len() && !times.is_empty() && increasing && finite)
            .then_some(Series { times, angles })
    }

    /// The times where the slope changes: the run steps onto each.
    pub fn breakpoints(&self) -> &[f64] {
        &self.times
    }

    /// The segment `t` falls in (the later one at a breakpoint), as its index from 0 (before
    /// the first time) to n (after the last).
    fn segment(&self, t: f64) -> usize {
        self.times.partition_point(|&time| time <= t)
    }

    /// The command at `t`; at a breakpoint, the limit from the right.
    pub fn angle(&self, t: f64) -> f64 {
        let i = self.segment(t);
        if i == 0 {
            return self.angles[0];
        }
        if i == self.times.len() {
            return self.angles[i - 1];
        }
        let (t0, t1) = (self.times[i - 1], self.times[i]);
        let (a0, a1) = (self.angles[i - 1], self.angles[i]);
        a0 + (a1 - a0) * ((t - t0) / (t1 - t0))
    }

    /// dδ_c/dt at `t`, from the right at a breakpoint.
    pub fn slope(&self, t: f64) -> f64 {
        let i = self.segment(t);
        if i == 0 || i == self.times.len() {
            return 0.0;
        }
        (self.angles[i] - self.angles[i - 1]) / (self.times[i] - self.times[i - 1])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lag_rate_is_limited_and_the_command_saturated() {
        let rudder = Rudder {
            max_angle: Some(0.5),
            max_rate: Some(0.1),
            time_constant: Some(2.0),
        };
        assert_eq!(rudder.saturate(0.7), 0.5);
        assert_eq!(rudder.saturate(-0.7), -0.5);
        assert_eq!(rudder.rate(0.5, 0.0), Some(0.1));
        assert_eq!(rudder.rate(0.0, 0.1), Some(-0.05));
        let ideal = Rudder {
            max_angle: None,
            max_rate: None,
            time_constant: None,
        };
        assert_eq!(ideal.rate(0.3, 0.0), None);
    }

    #[test]
    fn a_series_interpolates_and_holds_its_ends() {
        let series = Series::new(vec![1.0, 3.0, 4.0], vec![0.0, 0.2, -0.2]).unwrap();
        assert_eq!(series.angle(0.0), 0.0);
        assert_eq!(series.angle(2.0), 0.1);
        assert_eq!(series.slope(2.0), 0.1);
        assert_eq!(series.slope(3.0), -0.4);
        assert_eq!(series.angle(5.0), -0.2);
        assert_eq!(series.slope(5.0), 0.0);
        assert!(Series::new(vec![1.0, 1.0], vec![0.0, 0.0]).is_none());
        assert!(Series::new(vec![], vec![]).is_none());
    }
}
