//! The envelope every scene whose own table defines its model shares, whatever its kind: the
//! `[model]` that names the family, the `[integrator]` and `[output]` of its manoeuvres, and a
//! steering gear's table; and the `[linear]` table every scene may give. Each is read and
//! checked here, once, so that a ship's rudder and a vehicle's fins are checked by one
//! function and every kind's method by the checker of every scene's `[integrator]`. Its
//! `stop_when` is read by the checker every kind reads it with (`check.rs`), against the names
//! its trajectory.csv gives its columns, so that a condition means on a manoeuvre what it
//! means on a catalog body's run: the first instant its row satisfies it.

use super::check::{Checker, MethodKeys};
use super::{Problem, SceneError};
use crate::integrate::{Method, Stepper};
use crate::manoeuvring::Rudder;
use serde::Deserialize;

/// `[model]` of a scene whose own table defines its model: only the family, for the model
/// is the table's.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FamilyTable {
    /// `planar-midship` (a ship's) or `vehicle`.
    pub family: String,
}

/// A steering gear's table: a ship's `[rudder]`, a vehicle's `[rudder]` and `[stern_planes]`;
/// every key optional.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SteeringGearTable {
    /// δ_max, degrees.
    pub max_deg: Option<f64>,
    /// δ̇_max, degrees per second.
    pub max_rate_deg_s: Option<f64>,
    /// The lag's time constant, s.
    pub time_constant_s: Option<f64>,
}

/// `[integrator]`: the keys of every scene's but the end time (each manoeuvre gives its
/// duration).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct IntegratorTable {
    /// `euler`, `symplectic-euler`, `rk4`, `dopri5` or `dop853`.
    pub method: String,
    /// The largest step of a fixed-step method, s.
    pub step: Option<f64>,
    /// Relative tolerance (adaptive methods).
    pub rtol: Option<f64>,
    /// Absolute tolerance (adaptive methods).
    pub atol: Option<f64>,
    /// The most steps (accepted and rejected) a manoeuvre may take.
    pub max_steps: Option<u64>,
    /// A condition on a manoeuvre's row that ends it where it first holds (`u < 1`).
    pub stop_when: Option<String>,
}

/// `[output]`.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputTable {
    /// A trajectory row every this many seconds (every step where absent).
    pub every: Option<f64>,
}

/// `[linear]`: the operating point of `eom linear`, by default the initial state.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinearTable {
    /// State entries and inputs at the point, by the model's names, SI and radians.
    pub at: Option<std::collections::BTreeMap<String, f64>>,
    /// The free variables solved for so that the reduced state is in equilibrium.
    pub trim: Option<Vec<String>>,
    /// The outputs y = C x of the linear model, state entries by name (by default every entry
    /// of the reduced state).
    pub outputs: Option<Vec<String>>,
}

// Read by the kinds with manoeuvres (feature `ship`); a build without them has no reader.
#[cfg_attr(
    not(feature = "ship"),
    expect(dead_code, reason = "the kinds that read them are feature `ship`'s")
)]
impl Checker<'_> {
    /// The steering gear `table` (`rudder`, `stern_planes`) describes: its limits in radians
    /// and seconds, each positive; a rate limit needs the lag it acts on.
    pub(crate) fn steering_gear(
        &self,
        table: &str,
        gear: &SteeringGearTable,
    ) -> Result<Rudder, SceneError> {
        let key = |k: &str| format!("{table}.{k}");
        let angle = |k: &str, value: Option<f64>| {
            value
                .map(|v| self.positive(&key(k), v).map(f64::to_radians))
                .transpose()
        };
        let max_angle = angle("max_deg", gear.max_deg)?;
        let max_rate = angle("max_rate_deg_s", gear.max_rate_deg_s)?;
        let time_constant = (gear.time_constant_s)
            .map(|t| self.positive(&key("time_constant_s"), t))
            .transpose()?;
        if max_rate.is_some() && time_constant.is_none() {
            return Err(self.invalid(
                &key("max_rate_deg_s"),
                format!("a rate limit acts on the lag's rate: give {table}.time_constant_s too"),
            ));
        }
        Ok(Rudder {
            max_angle,
            max_rate,
            time_constant,
        })
    }

    /// The method of a scene-defined model's manoeuvres (a ship's, a vehicle's: `what` names
    /// it in the message, `kicked` are its velocities), read by the checker of every scene's
    /// `[integrator]` over the longest manoeuvre, and the rows' interval: `output.every`, or
    /// the step where absent (an adaptive method has none, so it needs `output.every`).
    pub(crate) fn stepping(
        &self,
        (integrator, output): (&IntegratorTable, &OutputTable),
        longest: f64,
        (what, kicked): (&str, std::ops::Range<usize>),
    ) -> Result<(Stepper, f64), SceneError> {
        let t = integrator;
        let keys = MethodKeys {
            method: &t.method,
            step: t.step,
            rtol: t.rtol,
            atol: t.atol,
            max_steps: t.max_steps,
        };
        let settings = self.method_settings(&keys, longest)?;
        if settings.method == Method::LieMidpoint {
            return Err(self.invalid(
                "integrator.method",
                format!(
                    "lie-midpoint integrates a free body's rotation alone; {what} takes euler, \
                     symplectic-euler, rk4, dopri5 or dop853"
                ),
            ));
        }
        let every = match (output.every, settings.step) {
            (Some(every), _) => self.positive("output.every", every)?,
            (None, Some(step)) => step,
            (None, None) => {
                return Err(self.error(
                    "output.every",
                    Problem::Missing(format!(
                        "the rows' interval, s: {} chooses its own steps",
                        settings.method.name()
                    )),
                ));
            }
        };
        let stepper = Stepper {
            method: settings.method,
            step: settings.step,
            adaptive: settings.adaptive,
            kicked,
        };
        Ok((stepper, every))
    }
}
