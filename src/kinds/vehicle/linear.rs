//! The vehicle linearised: the linearisation of every scene ([`crate::linear`]) on the
//! vehicle's own proved program.
//!
//! The model runs in quaternions, whose four components hold three angles: the constraint
//! |q| = 1 would be a mode of A that means nothing, and the heading, on which nothing but the
//! position depends, is spread over all four, so it could not be set aside. The plant is
//! therefore the Euler-angle twin of the same table (4.57–4.60 with φ, θ, ψ), derived and
//! proved as the running model is, with its own proved Jacobians: the operating point, given
//! in quaternions, is read as the same attitude in Euler angles, where the twin and the model
//! are the same equations. A cruise has θ = 0, far from the twin's singularity at θ = ±90°,
//! and a point within 1° of it is refused rather than linearised in angles that do not hold.
//!
//! The fins' angles δ_r, δ_s are the plant's inputs, held where they are put, as Nomoto's
//! models hold a ship's rudder (the steering gear's lag and limits left out); a `[linear]`
//! table may call them `rudder` and `stern_planes`. The propeller is the table's constant
//! thrust and torque (a law's ε and a cross-flow drag are computed beside the twin as beside
//! the model, their derivatives in its Jacobian). At a cruise the position x, y, z and the
//! heading ψ are set aside (the loads read none of them), and A is on (u, v, w, p, q, r, φ, θ).

use super::model::{EULER_STATE, Proved};
use super::{VehicleError, VehicleScene, VehicleTable};
use crate::defined::engine::Kinematics;
use crate::linear::{
    Evaluation, LinearError, LinearPlant, Linearisation, Naming, Reading, linearise, set_at,
};
use crate::models::Family;
use nalgebra::DMatrix;

/// The number of the twin's body states (ν, the position, φ, θ, ψ).
pub(crate) const BODY: usize = 12;

/// The fins, by their scene names as well as their state names.
pub(crate) const ALIASES: [(&str, &str); 2] = [("rudder", "dr"), ("stern_planes", "ds")];

/// A vehicle as the linearisation reads it (see the module docs).
#[derive(Debug, Clone)]
pub struct VehiclePlant {
    twin: Proved,
    /// L, m: what a position is read against when the modes compare what moves (the prime
    /// system's L, else the cross-flow strips' total length; zero where the table gives
    /// neither, and a position is then read in metres, as the model has it).
    length: f64,
}

impl VehiclePlant {
    /// Derives and proves the Euler-angle twin of `table`.
    pub fn new(table: &VehicleTable) -> Result<Self, VehicleError> {
        let (twin, _) = Proved::new(table, Kinematics::Euler)?;
        debug_assert_eq!(twin.body(), BODY);
        let strips = (table.cross_flow.as_ref()).map(|c| c.lengths.iter().sum::<f64>());
        let length = (table.prime.map(|p| p.length)).or(strips).unwrap_or(0.0);
        Ok(VehiclePlant { twin, length })
    }
}

impl LinearPlant for VehiclePlant {
    fn name(&self) -> &'static str {
        "vehicle"
    }

    /// A vehicle is the catalog's spatial body with its table's loads.
    fn family(&self) -> Family {
        Family::Spatial
    }

    fn naming(&self) -> Naming {
        Naming::Planes
    }

    /// A velocity over the speed at the point, a rate by the mode's time, a position over
    /// L, an angle as it is.
    fn readings(&self, state: &[f64]) -> Vec<Reading> {
        let speed = state[..3].iter().map(|v| v * v).sum::<f64>().sqrt();
        (EULER_STATE[..BODY].iter())
            .map(|name| {
                let unit = crate::models::state_unit(name).unwrap_or("");
                Reading::by_unit(unit, speed, self.length)
            })
            .collect()
    }

    fn state_names(&self) -> Vec<&'static str> {
        EULER_STATE[..BODY].to_vec()
    }

    fn input_names(&self) -> Vec<&'static str> {
        EULER_STATE[BODY..].to_vec()
    }

    fn aliases(&self) -> &'static [(&'static str, &'static str)] {
        &ALIASES
    }

    fn inputs(&self, _state: &[f64], extra: &[f64]) -> Vec<f64> {
        extra.to_vec()
    }

    fn evaluate(&self, state: &[f64], extra: &[f64]) -> Result<Evaluation, LinearError> {
        if state[10].abs() > crate::linear::EULER_PITCH_LIMIT {
            return Err(LinearError::NotFinite(format!(
                "the pitch θ = {}° is within 1° of ±90°, where Euler angles do not hold",
                state[10].to_degrees()
            )));
        }
        let full: Vec<f64> = state.iter().chain(extra).copied().collect();
        let rates: Vec<f64> = self.twin.rates(&full).collect();
        let mut a = DMatrix::zeros(BODY, BODY);
        let mut b = DMatrix::zeros(BODY, extra.len());
        self.twin.state_jacobian(&full, |row, column, value| {
            if column < BODY {
                a[(row, column)] += value;
            } else {
                b[(row, column - BODY)] += value;
            }
        });
        if !(rates.iter().chain(a.iter()).chain(b.iter())).all(|v| v.is_finite()) {
            return Err(LinearError::NotFinite(format!("the vehicle at {full:?}")));
        }
        Ok(Evaluation { rates, a, b })
    }

    fn pattern(&self) -> Vec<(usize, usize)> {
        (self.twin.state_pattern().into_iter())
            .filter(|&(_, column)| column < BODY)
            .collect()
    }

    fn jacobians(&self) -> &'static str {
        "proved: the Euler-angle twin's Jacobian programs, derived and proved equal to the \
         exact derivatives of its equations when the scene was read, with the chain rule \
         through what is computed beside them (absolute values, the propeller's law, the \
         cross-flow drag)"
    }
}

/// The vehicle of `scene` linearised about the point its `[linear]` table names, by default
/// the trim every run starts from: the states set aside, A and B on the rest, the modes
/// (surge, sway and yaw, heave and pitch, roll) and the verdict.
pub fn linearise_vehicle(scene: &VehicleScene) -> Result<Linearisation, VehicleError> {
    let plant = VehiclePlant::new(&scene.table)?;
    let start = scene.start()?;
    let mut state = start[..9].to_vec();
    state.extend(crate::models::euler_angles(
        crate::models::Kinematics::Quaternion,
        &start[9..13],
    ));
    let mut extra = start[13..].to_vec();
    let names = (
        &plant.state_names()[..],
        &plant.input_names()[..],
        &ALIASES[..],
    );
    set_at(&scene.linear, names, (&mut state, &mut extra))?;
    let mut linearisation = linearise(&plant, (state, extra), &scene.linear)?;
    linearisation.note = Some(
        "a vehicle is linearised as the Euler-angle twin of its table (its quaternion's four \
         components hold three angles)"
            .into(),
    );
    Ok(linearisation)
}
