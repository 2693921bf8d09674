//! The autopilots: heading (PID on ψ to the rudder) and depth (depth to pitch to the stern
//! planes, a cascade of two PIDs), sampled as a vehicle's computer runs them.
//!
//! Each autopilot computes its fin's command at the instants t = k·T_s and holds it until the
//! next (a zero-order hold): the run is cut at those instants, so within a stretch the loads
//! are smooth and every method keeps its order, and halving the step refines the motion under
//! the same control law. The integral of each error is the rectangle rule at the same instants,
//! and it is not accumulated while the fin's command is saturated in the error's direction
//! (conditional integration: no windup at the fin's stops).
//!
//! The laws, with every gain positive:
//!
//! ```text
//! heading:  m_ψ = k_p e_ψ + k_i ∫e_ψ − k_d r,          e_ψ = ψ_c − ψ (wrapped to ±180°)
//!           δ_r,c = s_r m_ψ
//! depth:    θ_c = −(k_p e_z + k_i ∫e_z), |θ_c| ≤ θ_max,  e_z = z_c − z (z down)
//!           m_θ = k_p,θ e_θ + k_i,θ ∫e_θ − k_d,θ q,     e_θ = θ_c − θ
//!           δ_s,c = s_s m_θ
//! ```
//!
//! Each acts about the trim its manoeuvre starts from ([`Feedforward`]): the trim's rudder,
//! stern planes and pitch are added to δ_r,c, δ_s,c and θ_c, and the rates r and q are
//! measured from the trim's (a steady helix turns and pitches at a steady rate), so that at
//! zero error the autopilots hold the steady motion the run starts in (all are zero on the
//! straight level cruise of a neutral vehicle).
//!
//! m is the turn the autopilot asks for (positive: towards positive r, or q), and s the sense
//! in which the fin gives it: the sign of ∂ṙ/∂δ_r (or ∂q̇/∂δ_s) of the vehicle's own proved
//! Jacobian at its cruise. So the gains mean the same on every table, whichever way its fins
//! are signed (REMUS's positive rudder turns it to port, and its positive stern planes pitch
//! it nose down), and a fin that does not act on its motion at the cruise is refused. To go
//! deeper the vehicle pitches nose down, hence the minus sign of θ_c.

use super::VehicleError;
use super::model::VehicleModel;
use crate::models::Model;
use std::f64::consts::TAU;

/// The heading autopilot's gains.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeadingGains {
    /// k_p, rad of rudder per rad of heading error.
    pub kp: f64,
    /// k_i, per second.
    pub ki: f64,
    /// k_d, seconds (rad of rudder per rad/s of yaw rate).
    pub kd: f64,
}

/// The depth autopilot's gains: the outer loop (depth to a pitch command) and the inner one
/// (pitch to the stern planes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DepthGains {
    /// k_p, rad of pitch per m of depth error.
    pub kp: f64,
    /// k_i, rad of pitch per m s.
    pub ki: f64,
    /// The largest pitch commanded, rad.
    pub max_pitch: f64,
    /// k_p,θ, rad of stern planes per rad of pitch error.
    pub kp_pitch: f64,
    /// k_i,θ, per second.
    pub ki_pitch: f64,
    /// k_d,θ, seconds.
    pub kd_pitch: f64,
}

/// A scene's autopilots, with the sense of each fin on its vehicle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Autopilots {
    /// T_s, the sampling period, s.
    pub sample: f64,
    /// The heading autopilot, with the rudder's sense.
    pub heading: Option<(HeadingGains, f64)>,
    /// The depth autopilot, with the stern planes' sense.
    pub depth: Option<(DepthGains, f64)>,
}

impl Autopilots {
    /// The autopilots of the given gains on `model`, each fin's sense read from the proved
    /// Jacobian at `cruise`; a fin without effect there is an error naming `key`.
    pub fn new(
        model: &VehicleModel,
        cruise: &[f64; 15],
        sample: f64,
        (heading, depth): (Option<HeadingGains>, Option<DepthGains>),
    ) -> Result<Self, VehicleError> {
        let jacobian = Model::<f64, 15, 2>::state_jacobian(model, cruise, &[0.0; 2]);
        let sense = |row: usize, fin: usize, key: &str, what: &str| {
            let effect = jacobian[row][13 + fin];
            if effect == 0.0 || !effect.is_finite() {
                return Err(VehicleError::invalid(
                    key,
                    format!("the {what} do not act on the vehicle's motion at its cruise"),
                ));
            }
            Ok(effect.signum())
        };
        let rudder = "rudder (∂ṙ/∂δ_r = 0)";
        let planes = "stern planes (∂q̇/∂δ_s = 0)";
        Ok(Autopilots {
            sample,
            heading: match heading {
                Some(g) => Some((g, sense(5, 0, "autopilot.heading", rudder)?)),
                None => None,
            },
            depth: match depth {
                Some(g) => Some((g, sense(4, 1, "autopilot.depth", planes)?)),
                None => None,
            },
        })
    }
}

/// What the autopilots are commanded to hold: from each time on, a heading and a depth
/// (`None`: that autopilot is off, its fin on the manoeuvre's steps); before the first time,
/// the cruise's.
#[derive(Debug, Clone, PartialEq)]
pub struct Setpoints {
    /// Strictly increasing times, s.
    pub times: Vec<f64>,
    /// ψ_c from each time on, degrees, as the scene writes it.
    pub heading_deg: Option<Vec<f64>>,
    /// z_c from each time on, m (down).
    pub depth: Option<Vec<f64>>,
}

impl Setpoints {
    /// The heading (degrees) and depth commanded at `t`, given those of the cruise.
    pub fn at(&self, t: f64, cruise: (f64, f64)) -> (Option<f64>, Option<f64>) {
        let i = self.times.partition_point(|&time| time <= t);
        let pick = |list: &Option<Vec<f64>>, before: f64| {
            list.as_ref()
                .map(|values| if i == 0 { before } else { values[i - 1] })
        };
        (
            pick(&self.heading_deg, cruise.0),
            pick(&self.depth, cruise.1),
        )
    }
}

/// What the autopilots command at zero error: the trim's fins and pitch, rad
/// ([`super::trim`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Feedforward {
    /// δ_r of the trim.
    pub rudder: f64,
    /// δ_s of the trim.
    pub stern_planes: f64,
    /// θ of the trim.
    pub pitch: f64,
    /// q of the trim, rad/s.
    pub pitch_rate: f64,
    /// r of the trim, rad/s.
    pub yaw_rate: f64,
}

/// The autopilots at work: their integrals and the commands they hold, about a trim.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Controller {
    heading_integral: f64,
    depth_integral: f64,
    pitch_integral: f64,
    trim: Feedforward,
}

/// `angle` wrapped to (−half, half] of a turn of `full` (2π, or 360 for degrees).
pub fn wrapped(angle: f64, full: f64) -> f64 {
    let wrapped = angle.rem_euclid(full);
    if wrapped > full / 2.0 {
        wrapped - full
    } else {
        wrapped
    }
}

/// One PID step: the demand from the error and the rate, then the integral advanced unless
/// the command `to_fin(demand)` is saturated (by `saturate`) in the error's direction.
fn pid(
    (kp, ki, kd): (f64, f64, f64),
    (error, rate): (f64, f64),
    integral: &mut f64,
    dt: f64,
    saturated: impl Fn(f64) -> bool,
) -> f64 {
    let demand = kp * error + ki * *integral - kd * rate;
    if !(saturated(demand) && demand * error > 0.0) {
        *integral += error * dt;
    }
    demand
}

/// A fin's command for an autopilot's demand: its trim plus the demand in the fin's sense.
fn about(trim: f64, sense: f64) -> impl Fn(f64) -> f64 + Copy {
    move |demand| trim + sense * demand
}

/// Whether `command` of a demand is at the fin's stop `limit` (never, without one).
fn at_stop(limit: Option<f64>, command: impl Fn(f64) -> f64) -> impl Fn(f64) -> bool {
    move |demand| limit.is_some_and(|max| command(demand).abs() >= max)
}

impl Controller {
    /// The autopilots about the trim `trim`, their integrals zero.
    pub fn about(trim: Feedforward) -> Self {
        Controller {
            trim,
            ..Controller::default()
        }
    }

    /// The fins' commands at a sample instant, rad (`None` for a fin whose autopilot is off),
    /// from the state ([`super::model::STATE`]) and its Euler angles, the commanded heading
    /// (degrees) and depth, the fins' saturation angles and the time since the last sample.
    pub fn commands(
        &mut self,
        autopilots: &Autopilots,
        (state, [_, theta, psi]): (&[f64; 15], [f64; 3]),
        (heading, depth): (Option<f64>, Option<f64>),
        limits: [Option<f64>; 2],
        dt: f64,
    ) -> [Option<f64>; 2] {
        let trim = self.trim;
        let rudder = match (autopilots.heading, heading) {
            (Some((g, sense)), Some(psi_c)) => {
                let error = (
                    wrapped(psi_c.to_radians() - psi, TAU),
                    state[5] - trim.yaw_rate,
                );
                let rudder = about(trim.rudder, sense);
                let demand = pid(
                    (g.kp, g.ki, g.kd),
                    error,
                    &mut self.heading_integral,
                    dt,
                    at_stop(limits[0], rudder),
                );
                Some(rudder(demand))
            }
            _ => None,
        };
        let planes = match (autopilots.depth, depth) {
            (Some((g, sense)), Some(z_c)) => {
                let pitch = |demand: f64| trim.pitch - demand;
                let outer = pid(
                    (g.kp, g.ki, 0.0),
                    (z_c - state[8], 0.0),
                    &mut self.depth_integral,
                    dt,
                    |demand| pitch(demand).abs() >= g.max_pitch,
                );
                let theta_c = pitch(outer).clamp(-g.max_pitch, g.max_pitch);
                let planes = about(trim.stern_planes, sense);
                let demand = pid(
                    (g.kp_pitch, g.ki_pitch, g.kd_pitch),
                    (theta_c - theta, state[4] - trim.pitch_rate),
                    &mut self.pitch_integral,
                    dt,
                    at_stop(limits[1], planes),
                );
                Some(planes(demand))
            }
            _ => None,
        };
        [rudder, planes]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_heading_error_is_the_short_way_round() {
        assert!((wrapped(350f64.to_radians(), TAU) + 10f64.to_radians()).abs() < 1e-15);
        assert!((wrapped(-190f64.to_radians(), TAU) - 170f64.to_radians()).abs() < 1e-15);
        assert_eq!(wrapped(std::f64::consts::PI, TAU), std::f64::consts::PI);
        assert_eq!(wrapped(350.0, 360.0), -10.0);
    }

    #[test]
    fn the_integral_stops_at_the_fin_s_stop_in_the_error_s_direction() {
        let mut integral = 0.0;
        // Saturated, error pushing further: no accumulation.
        pid((1.0, 1.0, 0.0), (2.0, 0.0), &mut integral, 0.1, |_| true);
        assert_eq!(integral, 0.0);
        // Not saturated: the rectangle rule.
        pid((1.0, 1.0, 0.0), (2.0, 0.0), &mut integral, 0.1, |_| false);
        assert!((integral - 0.2).abs() < 1e-15);
    }
}
