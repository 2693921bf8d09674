//! The plots of a run: its kept columns handed to [`eom_cli::plots`].

use anyhow::{Context, Result};
use eom::models::{Family, Kinematics};
use eom::output::trajectory::Columns;
use eom::scene::{Body, Scene, euler_angles};
use eom_cli::plots::{PlotInput, Polhode, in_principal_axes, not_drawn, write_plots};
use std::path::{Path, PathBuf};

/// Draws the state, the attitude, the track (and a spatial body's profile), the energy drift
/// and, for a spatial body free of moments about G, the polhode of a run into `out`, under
/// `title`. Returns the files written and, for a plot left out although the run has its data,
/// why.
pub fn write(
    scene: &Scene,
    title: &str,
    columns: &Columns,
    out: &Path,
) -> Result<(Vec<PathBuf>, Vec<String>)> {
    let names = scene.state_names();
    let info = scene.selection.info;
    let attitude = match (info.family, info.kinematics) {
        (Family::Spatial, Some(kinematics)) => Some(attitude_deg(columns, kinematics, 9)),
        (Family::Top, Some(kinematics)) => Some(attitude_deg(columns, kinematics, 3)),
        _ => None,
    };
    let track = match info.family {
        Family::Pendulum | Family::Top => None,
        Family::PlanarSpaceFixed => Some((0, 1)),
        Family::PlanarAtG | Family::PlanarMidship => Some((3, 4)),
        Family::Spatial => Some((6, 7)),
    };
    // The drift relative to the larger of |E₀| and the largest kinetic energy, as the summary's
    // energy_drift (a potential's zero is a convention, so E₀ alone may be 0).
    let scale = columns.kinetic.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    let drift: Option<Vec<f64>> = scene
        .loads
        .potential_energy(&scene.initial)
        .and(columns.energy.first())
        .map(|&e0| e0.abs().max(scale))
        .filter(|scale| *scale > 0.0)
        .map(|scale| {
            let e0 = columns.energy[0];
            columns.energy.iter().map(|e| (e - e0) / scale).collect()
        });
    let principal = free_rotation(scene, columns);
    let input = PlotInput {
        title,
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
        depth: (info.family == Family::Spatial)
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
fn free_rotation(scene: &Scene, columns: &Columns) -> Option<([f64; 3], [Vec<f64>; 3])> {
    let torque_free = scene.loads.is_free() || scene.loads.uniform_gravity_only().is_some();
    match &scene.body {
        Body::Spatial { inertia, .. } if torque_free && columns.state.len() >= 6 => {
            let [p, q, r] = [3, 4, 5].map(|k| columns.state[k].as_slice());
            Some(in_principal_axes(inertia, [p, q, r]))
        }
        _ => None,
    }
}
