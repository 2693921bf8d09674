//! The fins: the rudder δ_r and the stern planes δ_s, each a steering gear like the ship's
//! rudder ([`Rudder`]: the command saturated, a first-order lag, its rate limited), and the
//! step commands a manoeuvre gives them.
//!
//! A fin's angle is a state of the model (its rate is the model's input). Without a lag a fin
//! follows its command at once: the run sets its angle at each step of the command. A rate
//! limit acts on the lag's rate, so it needs a lag; where the limit starts or stops acting δ̇
//! has a kink, which a step across would be only first-order accurate about, so the run
//! locates it as an event ([`Steering::rate_margin`]), as the ship's does.

pub use crate::manoeuvring::Rudder;
use crate::models::Loads;

/// The two fins' steering gears.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fins {
    /// The rudder, δ_r (a positive angle turns the vehicle to port on REMUS's table).
    pub rudder: Rudder,
    /// The stern planes, δ_s.
    pub stern_planes: Rudder,
}

/// Piecewise-constant commands of both fins (rad): from each time on, its angles, zero before
/// the first.
#[derive(Debug, Clone, PartialEq)]
pub struct FinSteps {
    times: Vec<f64>,
    angles: Vec<[f64; 2]>,
}

impl FinSteps {
    /// Steps at strictly increasing finite times to finite angles (rudder, stern planes), of
    /// equal length, at least one; `None` otherwise.
    pub fn new(times: Vec<f64>, angles: Vec<[f64; 2]>) -> Option<Self> {
        let increasing = times.windows(2).all(|w| w[0] < w[1]);
        let finite = times
            .iter()
            .chain(angles.iter().flatten())
            .all(|x| x.is_finite());
        (times.len() == angles.len() && !times.is_empty() && increasing && finite)
            .then_some(FinSteps { times, angles })
    }

    /// The same steps with every angle's sign reversed: the mirror manoeuvre.
    pub fn mirrored(&self) -> Self {
        FinSteps {
            times: self.times.clone(),
            angles: self.angles.iter().map(|[r, s]| [-r, -s]).collect(),
        }
    }

    /// The times where the command changes.
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// The commands at `t` (the new ones at a step's time).
    pub fn angles(&self, t: f64) -> [f64; 2] {
        match self.times.partition_point(|&time| time <= t) {
            0 => [0.0, 0.0],
            i => self.angles[i - 1],
        }
    }
}

/// The fins under their commands as one stretch holds them, as the model's loads: each fin's
/// rate from its command and angle (zero for a fin without a lag, set at the steps).
#[derive(Debug, Clone, Copy)]
pub struct Steering<'a> {
    /// The fins.
    pub fins: &'a Fins,
    /// The commands (rad), before saturation.
    pub commands: [f64; 2],
}

impl Steering<'_> {
    /// The saturated commands.
    pub fn saturated(&self) -> [f64; 2] {
        [
            self.fins.rudder.saturate(self.commands[0]),
            self.fins.stern_planes.saturate(self.commands[1]),
        ]
    }
}

impl Steering<'_> {
    /// For fin `fin` (0 the rudder, 1 the stern planes) with a lag and a rate limit: the lag's
    /// rate squared less the limit squared, whose sign changes where the limit starts or stops
    /// acting (a kink in δ̇ the run locates as an event); `None` for a fin without both.
    pub fn rate_margin(&self, fin: usize, state: &[f64; 15]) -> Option<f64> {
        let gear = [self.fins.rudder, self.fins.stern_planes][fin];
        let (lag, max) = (gear.time_constant?, gear.max_rate?);
        let rate = (self.saturated()[fin] - state[13 + fin]) / lag;
        Some(rate * rate - max * max)
    }
}

impl Loads<f64, 15, 2> for Steering<'_> {
    /// δ̇_r, δ̇_s: each lag's rate toward its saturated command.
    fn at(&self, _t: f64, state: &[f64; 15]) -> [f64; 2] {
        let [r, s] = self.saturated();
        [
            self.fins.rudder.rate(r, state[13]).unwrap_or(0.0),
            self.fins.stern_planes.rate(s, state[14]).unwrap_or(0.0),
        ]
    }
}
