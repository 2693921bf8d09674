//! The aircraft linearised: the linearisation of every scene ([`crate::linear`]) on the
//! aircraft's proved program, at its trim by default.
//!
//! A and B are the proved Jacobians composed with the slopes of what is computed beside the
//! program (the tables' segments, the air's and the engine's laws), so a point on a table's
//! breakpoint takes the segment above it. The position north and east and the heading are
//! set aside (nothing but the track depends on them); the altitude stays (the air's density
//! changes with it, a slow height mode), and so does the power, whose lag is a mode of its
//! own. The controls are the plant's inputs: throttle (0 to 1), elevator, aileron, rudder
//! (deg). Modes are named as flight-dynamics texts name them ([`Naming::Flight`]), by what
//! moves in each: the eigenvector's speed over the trim's V, its angles in radians, its rates
//! by the mode's own time 1/|λ|, its altitude (and north, east) over V²/g, where trading speed
//! for height (g Δh = −V ΔV) makes the two the same size, and its power over full power.

use super::model::{AircraftModel, CONTROLS, STATE};
use super::scene::AircraftScene;
use crate::linear::{
    Evaluation, LinearError, LinearPlant, Linearisation, Naming, Reading, linearise, set_at,
};
use crate::models::{Family, Model};
use nalgebra::DMatrix;

/// An aircraft as the linearisation reads it.
#[derive(Debug, Clone)]
pub struct AircraftPlant<'a> {
    model: &'a AircraftModel,
    /// The scene's unit system (`us`, `si`).
    units: &'static str,
}

impl LinearPlant for AircraftPlant<'_> {
    fn name(&self) -> &'static str {
        "aircraft"
    }

    /// An aircraft is the catalog's spatial body with its tables' loads.
    fn family(&self) -> Family {
        Family::Spatial
    }

    fn naming(&self) -> Naming {
        Naming::Flight
    }

    /// The speed over the point's airspeed V, a length over V²/g, the angles as they are,
    /// the rates by the mode's time, the power over full power (see the module docs).
    fn readings(&self, state: &[f64]) -> Vec<Reading> {
        let speed = state.first().copied().unwrap_or(0.0);
        let length = speed * speed / self.model.gravity();
        let units = super::scene::units(self.units);
        (STATE.iter())
            .map(|name| {
                let unit = units
                    .iter()
                    .find(|(n, _)| n == name)
                    .map_or("", |(_, u)| *u);
                Reading::by_unit(unit, speed, length)
            })
            .collect()
    }

    fn state_names(&self) -> Vec<&'static str> {
        STATE.to_vec()
    }

    fn input_names(&self) -> Vec<&'static str> {
        CONTROLS.to_vec()
    }

    fn inputs(&self, _state: &[f64], extra: &[f64]) -> Vec<f64> {
        extra.to_vec()
    }

    fn evaluate(&self, state: &[f64], extra: &[f64]) -> Result<Evaluation, LinearError> {
        let (Ok(x), Ok(u)) = (<[f64; 13]>::try_from(state), <[f64; 4]>::try_from(extra)) else {
            return Err(LinearError::NotFinite(format!("the aircraft at {state:?}")));
        };
        if x[4].abs() > crate::linear::EULER_PITCH_LIMIT {
            return Err(LinearError::NotFinite(format!(
                "the pitch θ = {}° is within 1° of ±90°, where Euler angles do not hold",
                x[4].to_degrees()
            )));
        }
        let rates = self.model.rates(&x, &u).to_vec();
        let (by_state, by_controls) = self.model.jacobians(&x, &u);
        let a = DMatrix::from_fn(13, 13, |i, j| by_state[i][j]);
        let b = DMatrix::from_fn(13, 4, |i, j| by_controls[i][j]);
        if !(rates.iter().chain(a.iter()).chain(b.iter())).all(|v| v.is_finite()) {
            return Err(LinearError::NotFinite(format!("the aircraft at {state:?}")));
        }
        Ok(Evaluation { rates, a, b })
    }

    fn pattern(&self) -> Vec<(usize, usize)> {
        <AircraftModel as Model<f64, 13, 4>>::STATE_JACOBIAN.to_vec()
    }

    /// Every entry's unit in the scene's system.
    fn units(&self) -> Vec<(&'static str, &'static str)> {
        super::scene::units(self.units).to_vec()
    }

    fn jacobians(&self) -> &'static str {
        "proved: the aircraft's Jacobian programs, derived and proved equal to the exact \
         derivatives of its equations, with the chain rule through what is computed beside \
         them (the tables' segment slopes, the atmosphere's, the thrust tables' and the power \
         lag's)"
    }
}

/// The aircraft of `scene` linearised about the point its `[linear]` table names, by default
/// its trim.
pub fn linearise_aircraft(scene: &AircraftScene) -> Result<Linearisation, LinearError> {
    let plant = AircraftPlant {
        model: &scene.model,
        units: scene.units,
    };
    let mut state = scene.trim.state.to_vec();
    let mut extra = scene.trim.controls.to_vec();
    set_at(
        &scene.linear,
        (&STATE, &CONTROLS, &[]),
        (&mut state, &mut extra),
    )?;
    linearise(&plant, (state, extra), &scene.linear)
}
