//! The propeller and what it does to the rudder: the thrust law's coefficients, the induced
//! velocity behind the propeller and the rudder's inflow speed, the rate at the approach, and
//! the engine's rate limit.
//!
//! After Abkowitz's model of the Esso Osaka (Trans. SNAME 88, 1980), in the prime system:
//! the propeller rate n (rev/s) is an input of the model, whose proved program carries the
//! thrust law and the rudder's terms on its inflow speed c (`eom_codegen::model::ship`); what
//! is not a polynomial, this module computes from u and n beside U:
//!
//! ```text
//! u_A = −(1 − w) u + √((1 − w)² u² + (8/π) K_T (n⁺ d)²)       (momentum theory, far behind)
//! c²  = (A_p/A_R) ((1 − w) u + k u_A)² + (1 − A_p/A_R) ((1 − w) u)²
//! ```
//!
//! with n⁺ = max(n, 0): the slipstream over the rudder is the propeller's ahead; astern it
//! blows forward, away from the rudder, which then sees the wake alone. c² is the mean of the
//! squared speeds over the rudder, weighted by the share of its area in the slipstream (A_p/A_R,
//! the propeller's disk over the rudder's area) and outside it.

use super::ShipError;
use simba::simd::SimdRealField;
use std::f64::consts::PI;

/// A ship's propeller, its thrust law, and the rudder in its slipstream; every number as the
/// scene gives it (the prime system's, where a number has units of the table).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Propulsion {
    /// d, m.
    pub diameter: f64,
    /// A_R, the rudder's area, m².
    pub rudder_area: f64,
    /// w, the wake fraction at the propeller.
    pub wake_fraction: f64,
    /// K_T of the momentum theory's induced velocity.
    pub thrust_coefficient: f64,
    /// k, the share of the induced velocity that reaches the rudder.
    pub slipstream_factor: f64,
    /// x_R′ = x_R/L, the rudder's position ahead of midship (negative aft).
    pub rudder_position: f64,
    /// T′_uu, T′_un, T′_nn: the thrust law ½ρL²(T′_uu u² + T′_un L n u + T′_nn L² n|n|).
    pub thrust: [f64; 3],
    /// C_R, the resistance coefficient on the wetted surface.
    pub resistance: f64,
    /// S, the wetted surface, m².
    pub wetted_surface: f64,
    /// The engine's rate limit, rev/s², on a change of the propeller rate's command.
    pub max_rate: f64,
    /// n₀, rev/s: the rate at which thrust and resistance balance at U₀ on a straight course.
    pub approach_rate: f64,
    /// c₀, m/s: the rudder's inflow speed at U₀ and n₀.
    pub approach_inflow: f64,
}

/// What the model reads of the propeller at a state, beside U: u_A, c and their derivatives
/// by u and by n.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Inflow<T> {
    /// u_A, m/s.
    pub induced: T,
    /// c, m/s.
    pub speed: T,
    /// (∂u_A/∂u, ∂u_A/∂n).
    pub induced_by: [T; 2],
    /// (∂c/∂u, ∂c/∂n).
    pub speed_by: [T; 2],
}

impl Propulsion {
    /// The resistance as the thrust law's coefficient of −u² over ½ρL²: C_R S/L².
    pub fn resistance_prime(&self, length: f64) -> f64 {
        self.resistance * self.wetted_surface / (length * length)
    }

    /// Solves the rate at the approach, n₀, from the balance of thrust and resistance at U₀
    /// (T′_nn L² n² + T′_un L U₀ n + (T′_uu − R′_uu) U₀² = 0, the positive root), and c₀ there.
    pub fn at_approach(mut self, design_speed: f64, length: f64) -> Result<Self, ShipError> {
        let [t_uu, t_un, t_nn] = self.thrust;
        let a = t_nn * length * length;
        let b = t_un * length * design_speed;
        let c = (t_uu - self.resistance_prime(length)) * design_speed * design_speed;
        let discriminant = b * b - 4.0 * a * c;
        let root = (-b + discriminant.sqrt()) / (2.0 * a);
        if !(a > 0.0 && root.is_finite() && root > 0.0) {
            return Err(ShipError::invalid(
                "propulsion.thrust",
                format!(
                    "the thrust law balances the resistance at U₀ = {design_speed} m/s at no \
                     positive propeller rate (T′_nn L² = {a:e}, T′_un L U₀ = {b:e}, \
                     (T′_uu − C_R S/L²) U₀² = {c:e})"
                ),
            ));
        }
        self.approach_rate = root;
        self.approach_inflow = self.inflow(design_speed, root).speed;
        Ok(self)
    }

    /// u_A and c at the surge speed `u` and the propeller rate `n`, with their derivatives.
    pub(crate) fn inflow<T: SimdRealField + Copy>(&self, u: T, n: T) -> Inflow<T> {
        let value = |x: f64| T::from_subset(&x);
        let half = value(0.5);
        let wake = value(1.0 - self.wake_fraction);
        let disk = PI * self.diameter * self.diameter / 4.0;
        let share = value(disk / self.rudder_area);
        let k = value(self.slipstream_factor);
        let q = value(8.0 / PI * self.thrust_coefficient * self.diameter * self.diameter);
        let ahead = (n + n.simd_abs()) * half;
        let dahead = (value(1.0) + n.simd_signum()) * half;
        let wake_speed = wake * u;
        let root = (wake_speed * wake_speed + q * ahead * ahead).simd_sqrt();
        let induced = root - wake_speed;
        let induced_by = [wake * wake_speed / root - wake, q * ahead * dahead / root];
        let slipstream = wake_speed + k * induced;
        let speed = (share * slipstream * slipstream
            + (value(1.0) - share) * wake_speed * wake_speed)
            .simd_sqrt();
        let speed_by = [
            (share * slipstream * (wake + k * induced_by[0])
                + (value(1.0) - share) * wake_speed * wake)
                / speed,
            share * slipstream * k * induced_by[1] / speed,
        ];
        Inflow {
            induced,
            speed,
            induced_by,
            speed_by,
        }
    }
}

/// The propeller-rate command of a manoeuvre: n₀ until `execute`, then toward `target` at the
/// engine's rate limit, held once there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RateCommand {
    /// n₀, rev/s.
    pub from: f64,
    /// The rate commanded at the execute, rev/s.
    pub target: f64,
    /// When the command changes, s.
    pub execute: f64,
    /// The engine's rate limit, rev/s².
    pub max_rate: f64,
}

impl RateCommand {
    /// n at `t`.
    pub fn rate(&self, t: f64) -> f64 {
        if t <= self.execute {
            return self.from;
        }
        let change = self.max_rate * (t - self.execute);
        if self.target < self.from {
            (self.from - change).max(self.target)
        } else {
            (self.from + change).min(self.target)
        }
    }

    /// The instants the command's form changes, after the execute: where n passes zero (the
    /// slipstream leaves the rudder) and where it reaches its target. The run steps onto each.
    pub fn breakpoints(&self) -> Vec<f64> {
        let ramp = (self.target - self.from).abs() / self.max_rate;
        let mut times = Vec::new();
        if self.from * self.target < 0.0 {
            times.push(self.execute + self.from.abs() / self.max_rate);
        }
        times.push(self.execute + ramp);
        times
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn esso() -> Propulsion {
        Propulsion {
            diameter: 9.1,
            rudder_area: 119.817,
            wake_fraction: 0.2,
            thrust_coefficient: 0.59,
            slipstream_factor: 0.95,
            rudder_position: -0.5,
            thrust: [-0.962e-5, -0.446e-5, 0.0309e-5],
            resistance: 0.00226,
            wetted_surface: 26_319.8,
            max_rate: 0.01,
            approach_rate: 0.0,
            approach_inflow: 0.0,
        }
    }

    /// The derivatives of u_A and c against central differences of the values (step 1e-6,
    /// agreement to 1e-7 relative: the differences' truncation and round-off).
    #[test]
    fn the_inflow_derivatives_are_those_of_its_values() {
        let p = esso();
        for (u, n) in [(4.1, 0.64), (2.0, 0.3), (1.0, -0.2), (3.0, 0.05)] {
            let at = p.inflow(u, n);
            let h = 1e-6;
            let du = |f: fn(&Inflow<f64>) -> f64| {
                (f(&p.inflow(u + h, n)) - f(&p.inflow(u - h, n))) / (2.0 * h)
            };
            let dn = |f: fn(&Inflow<f64>) -> f64| {
                (f(&p.inflow(u, n + h)) - f(&p.inflow(u, n - h))) / (2.0 * h)
            };
            let pairs = [
                (at.induced_by[0], du(|i| i.induced)),
                (at.induced_by[1], dn(|i| i.induced)),
                (at.speed_by[0], du(|i| i.speed)),
                (at.speed_by[1], dn(|i| i.speed)),
            ];
            for (exact, difference) in pairs {
                let scale = exact.abs().max(1.0);
                assert!(
                    (exact - difference).abs() < 1e-7 * scale,
                    "{u} {n}: {exact} {difference}"
                );
            }
        }
    }

    /// Astern the rudder sees the wake alone: u_A = 0, c = (1 − w) u.
    #[test]
    fn astern_the_slipstream_leaves_the_rudder() {
        let at = esso().inflow(3.0_f64, -0.4);
        assert_eq!(at.induced, 0.0);
        assert!((at.speed - 0.8 * 3.0).abs() < 1e-15);
    }

    /// The balance at the approach: thrust equals resistance at U₀ and n₀, to round-off.
    #[test]
    fn the_approach_rate_balances_thrust_and_resistance() {
        let (speed, length) = (4.1156, 325.0);
        let p = esso().at_approach(speed, length).unwrap();
        let [t_uu, t_un, t_nn] = p.thrust;
        let n = p.approach_rate;
        let surge = (t_uu - p.resistance_prime(length)) * speed * speed
            + t_un * length * n * speed
            + t_nn * length * length * n * n;
        assert!(surge.abs() < 1e-15, "{surge:e}");
        assert!((0.6..0.7).contains(&n), "{n}");
    }

    #[test]
    fn the_rate_command_ramps_at_the_engines_limit_and_holds() {
        let command = RateCommand {
            from: 0.6,
            target: -0.6,
            execute: 10.0,
            max_rate: 0.01,
        };
        assert_eq!(command.rate(5.0), 0.6);
        assert!((command.rate(40.0) - 0.3).abs() < 1e-15);
        assert_eq!(command.rate(500.0), -0.6);
        let times = command.breakpoints();
        assert_eq!(times.len(), 2);
        assert!((times[0] - 70.0).abs() < 1e-12 && (times[1] - 130.0).abs() < 1e-12);
    }
}
