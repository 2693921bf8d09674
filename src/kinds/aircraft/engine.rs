//! The engine: thrust from tables in altitude and Mach at idle, military and maximum power,
//! the throttle's gearing to a commanded power, and the power's first-order lag as a state,
//! as Stevens & Lewis give the F-16's (`tgear`, `pdot`, `rtau`, `thrust`); or, for an
//! aircraft described by its stability derivatives, a thrust that does not change with speed
//! or altitude, with a first-order lag ([`ConstantThrust`]).
//!
//! The lag is piecewise (an afterburner threshold at 50 %, a time constant that depends on
//! how far the power has to go), so it is computed here, beside the proved program, as the
//! lag's target p_c and gain k that the program's ṗ = k (p_c − p) reads, each with its
//! derivatives in the power and the throttle.

use super::tables::Table2;
use crate::Short;

/// The thrust tables, `values[i][j]` at altitude i and Mach j.
#[derive(Debug, Clone, PartialEq)]
pub struct Engine {
    /// Thrust at idle power.
    pub idle: Table2,
    /// Thrust at military power (100 % dry).
    pub military: Table2,
    /// Thrust at maximum power (full afterburner).
    pub maximum: Table2,
}

/// The thrust with its derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Thrust {
    /// The thrust along body x.
    pub value: f64,
    /// ∂T/∂(power, percent).
    pub by_power: f64,
    /// ∂T/∂(altitude).
    pub by_altitude: f64,
    /// ∂T/∂(Mach).
    pub by_mach: f64,
}

/// The lag's target and gain, ṗ = gain · (command − p), with their derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerLag {
    /// The power the lag aims at (percent).
    pub command: f64,
    /// d(command)/d(throttle).
    pub command_by_throttle: f64,
    /// d(command)/d(power).
    pub command_by_power: f64,
    /// The lag's reciprocal time constant (1/s).
    pub gain: f64,
    /// d(gain)/d(throttle).
    pub gain_by_throttle: f64,
    /// d(gain)/d(power).
    pub gain_by_power: f64,
}

impl Engine {
    /// The thrust at `power` (percent), `altitude` and `mach`: idle to military below 50 %,
    /// military to maximum above, each interpolated in the tables.
    pub fn thrust(&self, power: f64, altitude: f64, mach: f64) -> Thrust {
        let military = self.military.at(altitude, mach);
        let (other, fraction, by_power) = if power < 50.0 {
            let idle = self.idle.at(altitude, mach);
            (idle, 1.0 - power * 0.02, -0.02)
        } else {
            (self.maximum.at(altitude, mach), (power - 50.0) * 0.02, 0.02)
        };
        // T = T_mil + (T_other − T_mil)·fraction, fraction from 50 % toward the other table.
        let blend = |m: f64, o: f64| m + (o - m) * fraction;
        Thrust {
            value: blend(military.value, other.value),
            by_power: (other.value - military.value) * by_power,
            by_altitude: blend(military.by_x, other.by_x),
            by_mach: blend(military.by_y, other.by_y),
        }
    }
}

/// An engine whose thrust does not change with speed or altitude, as textbooks' small-
/// perturbation models of a light aircraft take it (C_Tu = 0): T = T_max · power/100, the
/// power lagging 100 · throttle with one time constant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConstantThrust {
    /// The thrust at full power (throttle 1).
    pub maximum: f64,
    /// The power's time constant, s.
    pub time_constant: f64,
}

/// What drives the aircraft: the thrust tables of the Stevens & Lewis form, or a constant
/// thrust.
#[derive(Debug, Clone, PartialEq)]
pub enum Propulsion {
    /// Thrust tables in altitude and Mach, the F-16's gearing and lag.
    Tables(Engine),
    /// Thrust proportional to the power, the same at every speed and altitude.
    Constant(ConstantThrust),
}

impl From<Engine> for Propulsion {
    fn from(engine: Engine) -> Self {
        Propulsion::Tables(engine)
    }
}

impl From<ConstantThrust> for Propulsion {
    fn from(engine: ConstantThrust) -> Self {
        Propulsion::Constant(engine)
    }
}

impl Propulsion {
    /// The thrust at `power` (percent), `altitude` and `mach`.
    pub fn thrust(&self, power: f64, altitude: f64, mach: f64) -> Thrust {
        match self {
            Propulsion::Tables(engine) => engine.thrust(power, altitude, mach),
            Propulsion::Constant(engine) => Thrust {
                value: engine.maximum * power / 100.0,
                by_power: engine.maximum / 100.0,
                by_altitude: 0.0,
                by_mach: 0.0,
            },
        }
    }

    /// Where (`altitude`, `mach`) lies beyond the thrust tables' breakpoints, each such
    /// argument said with the range the tables hold (none for a constant thrust, which has no
    /// tables): the thrust there is the tables' linear extension past their ends.
    pub fn beyond_tables(&self, altitude: f64, mach: f64) -> Vec<String> {
        let Propulsion::Tables(engine) = self else {
            return Vec::new();
        };
        let [altitudes, machs] = engine.military.extent();
        let mut beyond = Vec::new();
        for (what, value, (low, high)) in [("altitude", altitude, altitudes), ("Mach", mach, machs)]
        {
            if !(low..=high).contains(&value) {
                beyond.push(format!(
                    "{what} {}, beyond the thrust tables' {} to {}",
                    Short(value),
                    Short(low),
                    Short(high)
                ));
            }
        }
        beyond
    }

    /// The power's lag at `power` under `throttle`.
    pub fn lag(&self, power: f64, throttle: f64) -> PowerLag {
        match self {
            Propulsion::Tables(_) => power_lag(power, throttle),
            Propulsion::Constant(engine) => PowerLag {
                command: 100.0 * throttle,
                command_by_throttle: 100.0,
                command_by_power: 0.0,
                gain: 1.0 / engine.time_constant,
                gain_by_throttle: 0.0,
                gain_by_power: 0.0,
            },
        }
    }

    /// The power (percent) the lag settles at under `throttle`.
    pub fn steady_power(&self, throttle: f64) -> f64 {
        match self {
            Propulsion::Tables(_) => throttle_gearing(throttle).0,
            Propulsion::Constant(_) => 100.0 * throttle,
        }
    }
}

/// The throttle's gearing to a commanded power (percent), and its slope: 64.94 δ_t up to
/// δ_t = 0.77, 217.38 δ_t − 117.38 above (the afterburner's range).
pub fn throttle_gearing(throttle: f64) -> (f64, f64) {
    if throttle <= 0.77 {
        (64.94 * throttle, 64.94)
    } else {
        (217.38 * throttle - 117.38, 217.38)
    }
}

/// The lag's reciprocal time constant for a change of `dp` percent, and its slope.
fn reciprocal_time_constant(dp: f64) -> (f64, f64) {
    if dp <= 25.0 {
        (1.0, 0.0)
    } else if dp >= 50.0 {
        (0.1, 0.0)
    } else {
        (1.9 - 0.036 * dp, -0.036)
    }
}

/// The lag at `power` under `throttle`: toward the geared command, except across the
/// afterburner's threshold at 50 %, where it aims at 60 % (going up) or 40 % (going down)
/// until the power crosses, with the gain 5/s on the afterburner's side and the reciprocal
/// time constant of the change otherwise.
pub fn power_lag(power: f64, throttle: f64) -> PowerLag {
    let (geared, geared_by_throttle) = throttle_gearing(throttle);
    let fixed = |command: f64, gain: f64| PowerLag {
        command,
        command_by_throttle: 0.0,
        command_by_power: 0.0,
        gain,
        gain_by_throttle: 0.0,
        gain_by_power: 0.0,
    };
    let by_change = |command: f64, command_by_throttle: f64| {
        let (gain, slope) = reciprocal_time_constant(command - power);
        PowerLag {
            command,
            command_by_throttle,
            command_by_power: 0.0,
            gain,
            gain_by_throttle: slope * command_by_throttle,
            gain_by_power: -slope,
        }
    };
    match (geared >= 50.0, power >= 50.0) {
        (true, true) => PowerLag {
            command_by_throttle: geared_by_throttle,
            ..fixed(geared, 5.0)
        },
        (true, false) => by_change(60.0, 0.0),
        (false, true) => fixed(40.0, 5.0),
        (false, false) => by_change(geared, geared_by_throttle),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Stevens & Lewis's `pdot` at the book's test point: power 90 %, throttle 0.9, rate
    /// −58.68999 %/s (Table 3.5-2's last entry); exactly, 5·(217.38·0.9 − 117.38 − 90) =
    /// −58.69. The book's code computes in single precision (f32 carries 217.38·0.9 to about
    /// 1e-5), so the printed digits are held to 2e-5.
    #[test]
    fn the_power_lag_gives_the_books_rate() {
        let lag = power_lag(90.0, 0.9);
        let rate = lag.gain * (lag.command - 90.0);
        assert!((rate - -58.69).abs() < 1e-12, "{rate}");
        assert!((rate - -58.68999).abs() < 2e-5, "{rate}");
    }

    /// Each branch's derivatives against central differences, away from the branches' edges.
    #[test]
    fn the_lags_derivatives_are_its_slopes() {
        for (power, throttle) in [
            (30.0, 0.3),
            (30.0, 0.95),
            (70.0, 0.2),
            (70.0, 0.9),
            (10.0, 0.6),
        ] {
            let at = power_lag(power, throttle);
            let h = 1e-6;
            let dp = |f: fn(&PowerLag) -> f64| {
                (f(&power_lag(power + h, throttle)) - f(&power_lag(power - h, throttle)))
                    / (2.0 * h)
            };
            let dt = |f: fn(&PowerLag) -> f64| {
                (f(&power_lag(power, throttle + h)) - f(&power_lag(power, throttle - h)))
                    / (2.0 * h)
            };
            assert!(
                (dp(|l| l.gain) - at.gain_by_power).abs() < 1e-6,
                "{power} {throttle}"
            );
            assert!((dt(|l| l.gain) - at.gain_by_throttle).abs() < 1e-5);
            assert!((dt(|l| l.command) - at.command_by_throttle).abs() < 1e-5);
            assert_eq!(at.command_by_power, 0.0);
        }
    }
}
