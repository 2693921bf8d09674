//! Trim: the state and controls at which an aircraft flies steadily, as Stevens & Lewis pose
//! it (§3.6). Six unknowns — throttle, elevator, α, aileron, rudder, β — make the six
//! accelerations V̇, α̇, β̇, ṗ, q̇, ṙ zero, while the rest of the state follows from the
//! condition:
//!
//! - the climb angle γ fixes θ (the rate-of-climb constraint, their 3.6-3);
//! - a turn rate ψ̇ fixes φ for a coordinated turn (their 3.6-5: no lateral acceleration in
//!   body axes) and the body rates p = −ψ̇ sin θ, q = ψ̇ sin φ cos θ, r = ψ̇ cos φ cos θ;
//! - a pull-up rate sets q, with φ = 0, p = r = 0 and θ = α + γ at the instant;
//! - the power is the throttle's geared command (the lag at rest).
//!
//! The six equations are solved by Newton's method with central-difference Jacobians and
//! a halving line search, from wings level, and by continuation in the turn or pull-up rate
//! and the climb angle. A trim is given with its residual; a condition the aircraft cannot
//! meet inside its tables and limits is an error naming what is exceeded.

use super::model::AircraftModel;
use thiserror::Error;

/// A steady flight condition.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Condition {
    /// True airspeed V (the model's length unit per second).
    pub speed: f64,
    /// Altitude (the model's length unit).
    pub altitude: f64,
    /// Flight-path angle γ (rad), positive climbing.
    pub climb_angle: f64,
    /// Turn rate ψ̇ (rad/s) of a coordinated turn, positive to the right.
    pub turn_rate: f64,
    /// Pitch rate q (rad/s) of a pull-up (with no turn).
    pub pull_up_rate: f64,
}

impl Condition {
    /// Straight and level flight at `speed` and `altitude`.
    pub fn level(speed: f64, altitude: f64) -> Self {
        Condition {
            speed,
            altitude,
            climb_angle: 0.0,
            turn_rate: 0.0,
            pull_up_rate: 0.0,
        }
    }
}

/// Where the controls and the tables end: a trim outside them is refused.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// α's range where the tables hold data (rad).
    pub alpha: (f64, f64),
    /// The elevator's, aileron's and rudder's deflection limits (deg, ±).
    pub surfaces: [f64; 3],
}

/// A trim: the state, the controls and how well the six accelerations vanish.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trim {
    /// The state (see [`super::STATE`]), north and east zero, heading zero.
    pub state: [f64; 13],
    /// Throttle, elevator, aileron, rudder.
    pub controls: [f64; 4],
    /// The largest of |V̇|, |α̇|, |β̇|, |ṗ|, |q̇|, |ṙ| at the trim.
    pub residual: f64,
    /// Newton iterations taken (summed over the continuation).
    pub iterations: usize,
}

/// Why a condition could not be trimmed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TrimError {
    /// The condition itself is not one (a speed that is not positive, a non-finite number).
    #[error("trim: {0}")]
    Condition(String),
    /// Newton's method stopped without the accelerations vanishing.
    #[error(
        "trim did not converge: the largest acceleration left is {residual:e} after \
         {iterations} iterations (at throttle {throttle:.4}, α {alpha_deg:.3}°)"
    )]
    NoConvergence {
        /// The largest acceleration left.
        residual: f64,
        /// Iterations taken.
        iterations: usize,
        /// Where it stopped.
        throttle: f64,
        /// Where it stopped.
        alpha_deg: f64,
    },
    /// The trim needs more than full throttle, or less than none.
    #[error("trim needs throttle {throttle:.4}, beyond its range 0 to 1")]
    Throttle {
        /// The throttle the equations ask for.
        throttle: f64,
    },
    /// The trim's α is beyond the tables' range.
    #[error(
        "trim needs α = {alpha_deg:.3}°, beyond the tables' {}° to {}°",
        crate::Short(*low_deg),
        crate::Short(*high_deg)
    )]
    Alpha {
        /// The angle of attack the equations ask for.
        alpha_deg: f64,
        /// The tables' lowest α.
        low_deg: f64,
        /// Their highest.
        high_deg: f64,
    },
    /// A surface beyond its limit.
    #[error("trim needs {surface} {value:.3}°, beyond its limit ±{}°", crate::Short(*limit))]
    Surface {
        /// Which.
        surface: &'static str,
        /// The deflection asked for.
        value: f64,
        /// Its limit.
        limit: f64,
    },
}

/// The six unknowns: throttle, elevator, α, aileron, rudder, β.
type Unknowns = [f64; 6];

/// The state and controls of `unknowns` at `condition`.
fn flight(model: &Rates, condition: &Condition, unknowns: &Unknowns) -> ([f64; 13], [f64; 4]) {
    let gravity = model.gravity;
    let [throttle, elevator, alpha, aileron, rudder, beta] = *unknowns;
    let gamma = condition.climb_angle;
    let turn = condition.turn_rate;
    let phi = coordinated_roll(condition, gravity, alpha, beta);
    let theta = if condition.pull_up_rate != 0.0 {
        alpha + gamma
    } else {
        climb_pitch(alpha, beta, phi, gamma)
    };
    let (p, q, r) = if condition.pull_up_rate != 0.0 {
        (0.0, condition.pull_up_rate, 0.0)
    } else {
        (
            -turn * theta.sin(),
            turn * phi.sin() * theta.cos(),
            turn * phi.cos() * theta.cos(),
        )
    };
    let power = (model.steady_power)(throttle);
    let state = [
        condition.speed,
        alpha,
        beta,
        phi,
        theta,
        0.0,
        p,
        q,
        r,
        0.0,
        0.0,
        condition.altitude,
        power,
    ];
    (state, [throttle, elevator, aileron, rudder])
}

/// θ from the rate-of-climb constraint (Stevens & Lewis 3.6-3).
fn climb_pitch(alpha: f64, beta: f64, phi: f64, gamma: f64) -> f64 {
    let a = alpha.cos() * beta.cos();
    let b = phi.sin() * beta.sin() + phi.cos() * alpha.sin() * beta.cos();
    let sg = gamma.sin();
    ((a * b + sg * (a * a - sg * sg + b * b).sqrt()) / (a * a - sg * sg)).atan()
}

/// φ of a coordinated turn at the condition's turn rate (Stevens & Lewis 3.6-5); 0 without a
/// turn.
fn coordinated_roll(condition: &Condition, gravity: f64, alpha: f64, beta: f64) -> f64 {
    if condition.turn_rate == 0.0 {
        return 0.0;
    }
    let g = condition.turn_rate * condition.speed / gravity;
    let (ta, ca, cb, sb) = (alpha.tan(), alpha.cos(), beta.cos(), beta.sin());
    let sg = condition.climb_angle.sin();
    let a = 1.0 - g * ta * sb;
    let b = sg / cb;
    let c = 1.0 + g * g * cb * cb;
    let root = (c * (1.0 - b * b) + g * g * sb * sb).sqrt();
    let numerator = (a - b * b) + b * ta * root;
    let denominator = a * a - b * b * (1.0 + c * ta * ta);
    (g * cb / ca * numerator / denominator).atan()
}

/// The rates of an aircraft's state under its controls.
pub type RatesOf<'a> = dyn Fn(&[f64; 13], &[f64; 4]) -> [f64; 13] + 'a;

/// The power (percent) the engine settles at under a throttle.
pub type SteadyPower<'a> = dyn Fn(f64) -> f64 + 'a;

/// What is trimmed: the rates of a state under controls, gravity (for the turn's
/// coordination) and the engine's steady power.
struct Rates<'a> {
    rates: &'a RatesOf<'a>,
    gravity: f64,
    steady_power: &'a SteadyPower<'a>,
}

/// The six accelerations at `unknowns`.
fn accelerations(model: &Rates, condition: &Condition, unknowns: &Unknowns) -> [f64; 6] {
    let (state, controls) = flight(model, condition, unknowns);
    let rates = (model.rates)(&state, &controls);
    [rates[0], rates[1], rates[2], rates[6], rates[7], rates[8]]
}

fn largest(values: &[f64; 6]) -> f64 {
    values
        .iter()
        .map(|v| if v.is_nan() { f64::INFINITY } else { v.abs() })
        .fold(0.0, f64::max)
}

/// Newton's method from `start`; the unknowns and the iterations taken.
fn newton(model: &Rates, condition: &Condition, start: Unknowns) -> (Unknowns, f64, usize) {
    const STEPS: [f64; 6] = [1e-6, 1e-5, 1e-7, 1e-5, 1e-5, 1e-7];
    let mut z = start;
    let mut f = accelerations(model, condition, &z);
    let mut size = largest(&f);
    let mut iterations = 0;
    while iterations < 60 && size > 1e-13 {
        iterations += 1;
        let mut jacobian = nalgebra::Matrix6::<f64>::zeros();
        for (j, h) in STEPS.iter().enumerate() {
            let (mut up, mut down) = (z, z);
            up[j] += h;
            down[j] -= h;
            let (fu, fd) = (
                accelerations(model, condition, &up),
                accelerations(model, condition, &down),
            );
            for i in 0..6 {
                jacobian[(i, j)] = (fu[i] - fd[i]) / (2.0 * h);
            }
        }
        let Some(step) = jacobian.lu().solve(&nalgebra::Vector6::from(f)) else {
            break;
        };
        let mut scale = 1.0;
        let improved = loop {
            let trial: Unknowns = std::array::from_fn(|k| z[k] - scale * step[k]);
            let ft = accelerations(model, condition, &trial);
            if largest(&ft) < size || scale < 1e-4 {
                break (largest(&ft) < size).then_some((trial, ft));
            }
            scale *= 0.5;
        };
        let Some((trial, ft)) = improved else {
            break;
        };
        z = trial;
        f = ft;
        size = largest(&f);
    }
    (z, size, iterations)
}

/// Trims `model` at `condition`, within `limits`.
pub fn trim(
    model: &AircraftModel,
    condition: &Condition,
    limits: &Limits,
) -> Result<Trim, TrimError> {
    trim_rates(
        &|x, u| model.rates(x, u),
        model.gravity(),
        &|throttle| model.engine().steady_power(throttle),
        condition,
        limits,
    )
}

/// Trims the aircraft whose rates `rates` gives (of the state of [`super::STATE`] under the
/// controls of [`super::CONTROLS`]) at `condition` under `gravity`, its engine settling at
/// `steady_power(throttle)`, within `limits`: for a variant of a model (the same model with a
/// source's rounded constants, say).
pub fn trim_rates(
    rates: &RatesOf,
    gravity: f64,
    steady_power: &SteadyPower,
    condition: &Condition,
    limits: &Limits,
) -> Result<Trim, TrimError> {
    let model = &Rates {
        rates,
        gravity,
        steady_power,
    };
    let numbers = [
        condition.speed,
        condition.altitude,
        condition.climb_angle,
        condition.turn_rate,
        condition.pull_up_rate,
    ];
    if numbers.iter().any(|x| !x.is_finite()) || condition.speed <= 0.0 {
        return Err(TrimError::Condition(format!(
            "the speed must be positive and every number finite, not {condition:?}"
        )));
    }
    if condition.turn_rate != 0.0 && condition.pull_up_rate != 0.0 {
        return Err(TrimError::Condition(
            "a turn and a pull-up at once is not a steady condition".into(),
        ));
    }
    let level = Condition {
        climb_angle: 0.0,
        turn_rate: 0.0,
        pull_up_rate: 0.0,
        ..*condition
    };
    let (mut z, mut residual, mut iterations) =
        newton(model, &level, [0.5, 0.0, 0.1, 0.0, 0.0, 0.0]);
    // Continuation from level flight toward the condition in tenths.
    if level != *condition {
        for step in 1..=10 {
            let f = step as f64 / 10.0;
            let towards = Condition {
                climb_angle: condition.climb_angle * f,
                turn_rate: condition.turn_rate * f,
                pull_up_rate: condition.pull_up_rate * f,
                ..*condition
            };
            let (next, size, taken) = newton(model, &towards, z);
            (z, residual) = (next, size);
            iterations += taken;
        }
    }
    let (state, controls) = flight(model, condition, &z);
    if residual.is_nan() || residual > 1e-9 {
        return Err(TrimError::NoConvergence {
            residual,
            iterations,
            throttle: controls[0],
            alpha_deg: state[1].to_degrees(),
        });
    }
    check_limits(&state, &controls, limits)?;
    Ok(Trim {
        state,
        controls,
        residual,
        iterations,
    })
}

fn check_limits(state: &[f64; 13], controls: &[f64; 4], limits: &Limits) -> Result<(), TrimError> {
    if !(0.0..=1.0).contains(&controls[0]) {
        return Err(TrimError::Throttle {
            throttle: controls[0],
        });
    }
    let (low, high) = limits.alpha;
    if !(low..=high).contains(&state[1]) {
        return Err(TrimError::Alpha {
            alpha_deg: state[1].to_degrees(),
            low_deg: low.to_degrees(),
            high_deg: high.to_degrees(),
        });
    }
    for ((surface, value), limit) in ["elevator", "aileron", "rudder"]
        .into_iter()
        .zip(&controls[1..])
        .zip(limits.surfaces)
    {
        if value.abs() > limit {
            return Err(TrimError::Surface {
                surface,
                value: *value,
                limit,
            });
        }
    }
    Ok(())
}
