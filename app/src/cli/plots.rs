//! The plots of a rigid body's run: its kept columns handed to [`eom_cli::plots`].

use super::record::Kept;
use anyhow::{Context, Result};
use eom::InertiaTensor;
use eom::models::euler_angles;
use eom::models::{Family, Kinematics};
use eom::nalgebra::Matrix3;
use eom::output::drawing::{BodyShape, RigidBody};
use eom::output::trajectory::Columns;
use eom_cli::plots::{PlotInput, Polhode, in_principal_axes, not_drawn, write_plots};
use std::path::{Path, PathBuf};

/// Draws the state, the attitude, the track (and a spatial body's profile), the energy drift
/// and, for a spatial body free of moments about G, the polhode of a run into `out`, under
/// `title`. Returns the files written and, for a plot left out although the run has its data,
/// why.
pub fn write(body: &RigidBody, kept: &Kept, out: &Path) -> Result<(Vec<PathBuf>, Vec<String>)> {
    let (names, columns) = (&kept.names, &kept.columns);
    let attitude = match (body.family, body.kinematics) {
        (Family::Spatial, Some(kinematics)) => Some(attitude_deg(columns, kinematics, 9)),
        (Family::Top, Some(kinematics)) => Some(attitude_deg(columns, kinematics, 3)),
        _ => None,
    };
    let track = match body.family {
        Family::Pendulum | Family::Top => None,
        Family::PlanarSpaceFixed => Some((0, 1)),
        Family::PlanarAtG | Family::PlanarMidship => Some((3, 4)),
        Family::Spatial => Some((6, 7)),
    };
    // The drift relative to the larger of |E₀| and the largest kinetic energy, as the summary's
    // energy_drift (a potential's zero is a convention, so E₀ alone may be 0).
    let scale = columns.kinetic.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    let drift: Option<Vec<f64>> = (columns.energy.first())
        .filter(|_| body.conserves_energy)
        .map(|&e0| e0.abs().max(scale))
        .filter(|scale| *scale > 0.0)
        .map(|scale| {
            let e0 = columns.energy[0];
            columns.energy.iter().map(|e| (e - e0) / scale).collect()
        });
    let principal = free_rotation(body, columns);
    let input = PlotInput {
        title: &body.title,
        time: &columns.time,
        state: names
            .iter()
            .map(String::as_str)
            .zip(columns.state.iter().map(Vec::as_slice))
            .collect(),
        attitude_deg: attitude
            .as_ref()
            .map(|[r, p, y]| [r.as_slice(), p.as_slice(), y.as_slice()]),
        track: track.map(|(x, y)| (columns.state[x].as_slice(), columns.state[y].as_slice())),
        depth: (body.family == Family::Spatial)
            .then(|| columns.state.get(8).map(Vec::as_slice))
            .flatten(),
        energy_drift: drift.as_deref(),
        polhode: principal.as_ref().map(|(moments, [w1, w2, w3])| Polhode {
            moments: *moments,
            omega: [w1, w2, w3],
        }),
    };
    let written = write_plots(out, &input)
        .with_context(|| format!("drawing the plots into {}", out.display()))?;
    Ok((written, not_drawn(&input)))
}

/// Roll, pitch and yaw in degrees of every kept row, the attitude from state entry `first`.
fn attitude_deg(columns: &Columns, kinematics: Kinematics, first: usize) -> [Vec<f64>; 3] {
    let mut angles: [Vec<f64>; 3] = Default::default();
    let mut state = vec![0.0; columns.state.len()];
    for row in 0..columns.time.len() {
        for (entry, column) in state.iter_mut().zip(&columns.state) {
            *entry = column[row];
        }
        for (angle, value) in angles
            .iter_mut()
            .zip(euler_angles(kinematics, &state[first..]))
        {
            angle.push(value.to_degrees());
        }
    }
    angles
}

/// The principal moments and ω in principal axes of a spatial body that turns free of moments
/// about G (no loads, or uniform gravity at G alone), for the polhode; `None` for any other.
fn free_rotation(body: &RigidBody, columns: &Columns) -> Option<([f64; 3], [Vec<f64>; 3])> {
    match body.shape {
        BodyShape::Spatial {
            inertia,
            free_of_moments: true,
            ..
        } if columns.state.len() >= 6 => {
            let tensor = InertiaTensor::from_matrix(Matrix3::from_fn(|r, c| inertia[r][c])).ok()?;
            let [p, q, r] = [3, 4, 5].map(|k| columns.state[k].as_slice());
            Some(in_principal_axes(&tensor, [p, q, r]))
        }
        _ => None,
    }
}
