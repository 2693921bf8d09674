//! The plots of the library's drawing shapes: a track in a plane (`track.svg`, one scale on
//! both axes, with marks and an outline drawn along it), columns against time on one panel
//! with a legend (a series, `heading.svg`) or a panel each (`state.svg`), an attitude's angles
//! (`attitude.svg`), a track in space seen from the side (`profile.svg`), the drift of the
//! total energy (`energy.svg`) and a free body's polhode (`polhode.svg`). Each reads the
//! columns the command hands it, one value per time, angles already in degrees; each checks
//! their lengths before it draws, so a malformed column writes no file.
//!
//! The outline is the waterline view.html draws: a pointed bow over the fore fifth, parallel
//! sides, a rounded stern, of length L and beam B, at the track's point and heading at the
//! start and every `1/times` of the distance run, so that a drift angle (the body turned
//! across its own track) shows.

use super::energy::draw_energy;
use super::polhode::{Polhode, draw_polhode};
pub use super::profile::leaves_the_plane;
use super::profile::{distance_run, draw_profile};
use super::series::{Line, PanelStyle, draw_attitude, draw_state, time_panel, time_range};
use super::track::{Mark, draw_track, stays_at};
use super::{
    ATTITUDE, COLOURS, ENERGY, POLHODE, PROFILE, PlotError, STATE, TITLE_FONT, TRACK, WIDTH, emit,
    render,
};
use plotters::style::RGBColor;
use std::path::{Path, PathBuf};

/// A series' palette, in its lines' order: the plots' three, and Tableau 10's red.
const PALETTE: [RGBColor; 4] = [COLOURS[0], COLOURS[1], COLOURS[2], RGBColor(214, 39, 40)];

/// An outline drawn along a track.
#[derive(Clone, Copy)]
pub struct OutlinePlot<'a> {
    /// L, in the track's unit.
    pub length: f64,
    /// B.
    pub beam: f64,
    /// The heading ψ of each point (rad, from the vertical axis towards the horizontal).
    pub heading: &'a [f64],
    /// How many times it is drawn besides the start.
    pub times: usize,
    /// Its legend entry.
    pub label: &'a str,
}

/// A track in a plane.
#[derive(Clone, Copy)]
pub struct TrackPlot<'a> {
    /// The caption, the title included.
    pub caption: &'a str,
    /// The horizontal and the vertical axis's descriptions.
    pub axes: (&'a str, &'a str),
    /// The horizontal coordinate of each point.
    pub across: &'a [f64],
    /// The vertical coordinate.
    pub up: &'a [f64],
    /// Points to mark.
    pub marks: &'a [Mark],
    /// What is drawn along it.
    pub outline: Option<OutlinePlot<'a>>,
}

/// Writes `track.svg` into `dir`.
pub fn write_track(dir: &Path, plot: &TrackPlot) -> Result<PathBuf, PlotError> {
    let heading = plot.outline.map(|o| ("heading", o.heading.len()));
    let columns = std::iter::once(("up", plot.up.len())).chain(heading);
    same_lengths(dir, TRACK, plot.across.len(), columns)?;
    let outlines = (plot.outline)
        .map(|outline| outlines(plot.across, plot.up, &outline))
        .unwrap_or_default();
    emit(dir, TRACK, |svg| {
        draw_track(
            svg,
            plot.caption,
            plot.axes,
            (plot.across, plot.up),
            plot.marks,
            (plot.outline.map_or("", |o| o.label), &outlines),
        )
    })
}

/// Columns against time on one panel with a legend.
#[derive(Clone, Copy)]
pub struct SeriesPlot<'a> {
    /// The file, in `dir`.
    pub file: &'a str,
    /// The caption, the title included.
    pub caption: &'a str,
    /// The value axis's description.
    pub y_desc: &'a str,
    /// t, s.
    pub time: &'a [f64],
    /// Each line: its label and its values, one per time.
    pub lines: &'a [(&'a str, &'a [f64])],
}

/// Writes a series' file into `dir`.
pub fn write_series(dir: &Path, plot: &SeriesPlot) -> Result<PathBuf, PlotError> {
    let columns = plot
        .lines
        .iter()
        .map(|(label, values)| (*label, values.len()));
    same_lengths(dir, plot.file, plot.time.len(), columns)?;
    let style = PanelStyle {
        caption: plot.caption,
        caption_size: TITLE_FONT,
        y_desc: plot.y_desc,
        time_desc: true,
        time_ticks: 8,
        legend: true,
    };
    let lines: Vec<Line> = (plot.lines.iter().zip(PALETTE.iter().cycle()))
        .map(|((name, values), colour)| Line {
            name,
            values,
            colour: *colour,
        })
        .collect();
    let range = time_range(plot.time);
    emit(dir, plot.file, |svg| {
        render(svg, (WIDTH, 420), |root, overlay| {
            time_panel(root, overlay, &style, plot.time, range, &lines)
        })
    })
}

/// Writes `attitude.svg` into `dir`: roll, pitch and yaw in degrees against `time`, made
/// continuous.
pub fn write_attitude(
    dir: &Path,
    title: &str,
    time: &[f64],
    degrees: [&[f64]; 3],
) -> Result<PathBuf, PlotError> {
    let columns = degrees.map(|angle| ("an angle", angle.len()));
    same_lengths(dir, ATTITUDE, time.len(), columns)?;
    emit(dir, ATTITUDE, |svg| {
        draw_attitude(svg, title, time, degrees)
    })
}

/// Writes `profile.svg` into `dir`: the height against the distance run, and seen from the
/// east, of a track in north, east and down.
pub fn write_profile(
    dir: &Path,
    title: &str,
    (x, y, z): (&[f64], &[f64], &[f64]),
) -> Result<PathBuf, PlotError> {
    let columns = [y, z].map(|position| ("a position", position.len()));
    same_lengths(dir, PROFILE, x.len(), columns)?;
    emit(dir, PROFILE, |svg| draw_profile(svg, title, (x, y, z)))
}

/// Why `track.svg` is not drawn of a track that is one point to round-off (a body turning in
/// place), which would be an empty frame; `None` for a track drawn.
pub fn track_not_drawn(across: &[f64], up: &[f64]) -> Option<String> {
    let (across, up) = stays_at(across, up)?;
    Some(format!(
        "{TRACK} not drawn: the body does not translate, it stays at ({}, {}) m",
        eom::Short(across),
        eom::Short(up)
    ))
}

/// Writes `state.svg` into `dir`: each column (its name, its values) against `time`, a panel
/// each.
pub fn write_panels(
    dir: &Path,
    title: &str,
    time: &[f64],
    columns: &[(&str, &[f64])],
) -> Result<PathBuf, PlotError> {
    let lengths = columns.iter().map(|(name, values)| (*name, values.len()));
    same_lengths(dir, STATE, time.len(), lengths)?;
    emit(dir, STATE, |svg| draw_state(svg, title, time, columns))
}

/// The drift of the total energy `total` from its first value, relative to the larger of |E₀|
/// and the largest |T| of `kinetic` (a potential's zero is a convention, so E₀ alone may be 0):
/// what `energy.svg` draws, as the summary's `energy_drift` measures it. `None` where there is
/// no energy, or the scale is 0 (or not a number).
pub fn energy_drift(total: &[f64], kinetic: &[f64]) -> Option<Vec<f64>> {
    let largest_kinetic = kinetic.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    let e0 = *total.first()?;
    let scale = e0.abs().max(largest_kinetic);
    (scale > 0.0).then(|| total.iter().map(|e| (e - e0) / scale).collect())
}

/// Writes `energy.svg` into `dir`: the relative drift against `time`.
pub fn write_energy_drift(
    dir: &Path,
    title: &str,
    time: &[f64],
    drift: &[f64],
) -> Result<PathBuf, PlotError> {
    same_lengths(dir, ENERGY, time.len(), [("energy drift", drift.len())])?;
    emit(dir, ENERGY, |svg| draw_energy(svg, title, time, drift))
}

/// Writes `polhode.svg` into `dir`.
pub fn write_polhode(dir: &Path, title: &str, polhode: &Polhode) -> Result<PathBuf, PlotError> {
    let lengths = ["ω₂", "ω₃"].into_iter().zip(&polhode.omega[1..]);
    let lengths = lengths.map(|(name, values)| (name, values.len()));
    same_lengths(dir, POLHODE, polhode.omega[0].len(), lengths)?;
    emit(dir, POLHODE, |svg| draw_polhode(svg, title, polhode))
}

/// Whether every column of `file`, each (its name, its length), has `times` values: the
/// first that has not is an error naming it.
fn same_lengths<'a>(
    dir: &Path,
    file: &str,
    times: usize,
    columns: impl IntoIterator<Item = (&'a str, usize)>,
) -> Result<(), PlotError> {
    match columns.into_iter().find(|(_, len)| *len != times) {
        Some((column, len)) => Err(PlotError::Length {
            file: dir.join(file),
            column: column.into(),
            len,
            times,
        }),
        None => Ok(()),
    }
}

/// The waterline of a hull of `length` and `beam`, in body axes (x forward, y to starboard),
/// closed: the bow over the fore fifth, the stern a rounded eighth.
fn waterline(length: f64, beam: f64) -> Vec<(f64, f64)> {
    let n = 12;
    let half = beam / 2.0;
    let bow = |k: usize| {
        let s = k as f64 / n as f64;
        (0.3 * length + 0.2 * length * s, half * (1.0 - s * s))
    };
    let mut outline: Vec<(f64, f64)> = (0..=n).map(bow).collect();
    outline.extend((0..n).rev().map(|k| {
        let (x, y) = bow(k);
        (x, -y)
    }));
    outline.extend((0..=n).map(|k| {
        let a = std::f64::consts::PI * k as f64 / n as f64;
        (
            -0.5 * length + 0.08 * length * (1.0 - a.sin()),
            -half * a.cos(),
        )
    }));
    outline.push(outline[0]);
    outline
}

/// The outline at the track's point and heading at the start and at every `1/times` of the
/// distance run, in (across, up); none where L or B is not positive.
fn outlines(across: &[f64], up: &[f64], outline: &OutlinePlot) -> Vec<Vec<(f64, f64)>> {
    let OutlinePlot {
        length,
        beam,
        heading,
        times,
        ..
    } = *outline;
    if !(length > 0.0 && beam > 0.0 && length.is_finite() && beam.is_finite()) {
        return Vec::new();
    }
    let run = distance_run(across, up);
    let total = run
        .iter()
        .copied()
        .filter(|d| d.is_finite())
        .fold(0.0, f64::max);
    let shape = waterline(length, beam);
    let mut rows: Vec<usize> = (0..=times)
        .filter_map(|k| {
            let at = total * k as f64 / times as f64;
            (0..run.len()).find(|&i| run[i] >= at && heading[i].is_finite())
        })
        .collect();
    rows.dedup();
    rows.into_iter()
        .map(|i| {
            let (east, north, psi) = (across[i], up[i], heading[i]);
            let (sin, cos) = psi.sin_cos();
            // Body x forward along ψ from the vertical axis, y to its right.
            shape
                .iter()
                .map(|&(x, y)| (east + x * sin + y * cos, north + x * cos - y * sin))
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_outline_is_drawn_at_the_point_along_its_heading() {
        // Heading north, then turned to east while running 1 km east.
        let east: Vec<f64> = (0..101).map(|i| 10.0 * f64::from(i)).collect();
        let north = vec![0.0; 101];
        let psi: Vec<f64> = (0..101)
            .map(|i| {
                if i == 0 {
                    0.0
                } else {
                    std::f64::consts::FRAC_PI_2
                }
            })
            .collect();
        let mut outline = OutlinePlot {
            length: 140.0,
            beam: 20.0,
            heading: &psi,
            times: 10,
            label: "hull",
        };
        let drawn = outlines(&east, &north, &outline);
        // The start and every tenth of the 1 000 m run.
        assert_eq!(drawn.len(), 11);
        let span = |o: &[(f64, f64)], f: fn(&(f64, f64)) -> f64| {
            let values: Vec<f64> = o.iter().map(f).collect();
            let lo = values.iter().copied().fold(f64::MAX, f64::min);
            let hi = values.iter().copied().fold(f64::MIN, f64::max);
            (lo, hi)
        };
        // At the start the bow points north: L along north, B across, about the point.
        let (n0, n1) = span(&drawn[0], |p| p.1);
        let (e0, e1) = span(&drawn[0], |p| p.0);
        assert!(
            (n0 + 70.0).abs() < 1e-9 && (n1 - 70.0).abs() < 1e-9,
            "{n0} {n1}"
        );
        assert!(
            (e0 + 10.0).abs() < 1e-9 && (e1 - 10.0).abs() < 1e-9,
            "{e0} {e1}"
        );
        // At 500 m, heading east: L along east about 500 m.
        let (e0, e1) = span(&drawn[5], |p| p.0);
        assert!(
            (e0 - 430.0).abs() < 1e-9 && (e1 - 570.0).abs() < 1e-9,
            "{e0} {e1}"
        );
        // None where L or B is not positive.
        outline.beam = f64::NAN;
        assert!(outlines(&east, &north, &outline).is_empty());
    }
}
