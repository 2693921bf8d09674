//! A manoeuvre's plots: `track.svg`, midship's track as a chart (east across, north up, one
//! scale) with the manoeuvre's points marked (for a turning circle the 90° and 180° points,
//! with the advance, transfer and tactical diameter) and the hull's waterline drawn at
//! midship's position and heading every tenth of the distance run, so that the drift angle,
//! the hull turned across its own track, shows; and `heading.svg`, the heading change, the
//! rudder angle and its command over time (a zig-zag's plot).
//!
//! The waterline is the one view.html draws: a pointed bow over the fore fifth, parallel sides,
//! a rounded stern, of length L and beam B.

use super::profile::distance_run;
use super::series::{Line, PanelStyle, time_panel, time_range};
use super::track::draw_track;
use super::{COLOURS, DrawError, Mark, PlotError, TITLE_FONT, WIDTH, emit, render};
use eom::Short;
use eom::output::text::printable;
use std::path::{Path, PathBuf};

/// The columns of one manoeuvre, sampled at the same times.
#[derive(Clone, Copy)]
pub struct ManoeuvrePlot<'a> {
    /// The scene's title and the manoeuvre's name, for the captions.
    pub title: &'a str,
    /// t, s.
    pub time: &'a [f64],
    /// North X and east Y of midship, m.
    pub north: &'a [f64],
    /// East Y, m.
    pub east: &'a [f64],
    /// ψ − ψ₀, degrees.
    pub heading_change_deg: &'a [f64],
    /// The heading ψ, radians, for the hull drawn along the track.
    pub heading_rad: &'a [f64],
    /// δ, degrees.
    pub rudder_deg: &'a [f64],
    /// The command after saturation, degrees.
    pub command_deg: &'a [f64],
    /// Points to mark on the track, in (east, north).
    pub marks: &'a [Mark],
    /// The hull drawn along the track.
    pub hull: Hull,
}

/// The hull's size, for its waterline drawn along the track (the library's, as the kind
/// says it).
pub use eom::output::drawing::Hull;

/// How many times the hull is drawn along the track, evenly by distance run, besides the start.
const HULLS: usize = 10;

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

/// The hull's waterline at midship's position and heading at the start and at every
/// [`HULLS`]th of the distance run, in (east, north); none where L or B is not positive.
fn hulls(plot: &ManoeuvrePlot) -> Vec<Vec<(f64, f64)>> {
    let Hull { length, beam, .. } = plot.hull;
    if !(length > 0.0 && beam > 0.0 && length.is_finite() && beam.is_finite()) {
        return Vec::new();
    }
    let run = distance_run(plot.east, plot.north);
    let total = run
        .iter()
        .copied()
        .filter(|d| d.is_finite())
        .fold(0.0, f64::max);
    let shape = waterline(length, beam);
    let mut rows: Vec<usize> = (0..=HULLS)
        .filter_map(|k| {
            let at = total * k as f64 / HULLS as f64;
            (0..run.len()).find(|&i| run[i] >= at && plot.heading_rad[i].is_finite())
        })
        .collect();
    rows.dedup();
    rows.into_iter()
        .map(|i| {
            let (east, north, psi) = (plot.east[i], plot.north[i], plot.heading_rad[i]);
            let (sin, cos) = psi.sin_cos();
            // Body x forward along ψ from north, y to starboard.
            shape
                .iter()
                .map(|&(x, y)| (east + x * sin + y * cos, north + x * cos - y * sin))
                .collect()
        })
        .collect()
}

/// Writes `track.svg` and `heading.svg` into `dir`.
pub fn write_manoeuvre_plots(dir: &Path, plot: &ManoeuvrePlot) -> Result<Vec<PathBuf>, PlotError> {
    let columns = [
        ("north", plot.north.len()),
        ("east", plot.east.len()),
        ("heading change", plot.heading_change_deg.len()),
        ("heading", plot.heading_rad.len()),
        ("rudder", plot.rudder_deg.len()),
        ("command", plot.command_deg.len()),
    ];
    if let Some((column, len)) = columns.iter().find(|(_, len)| *len != plot.time.len()) {
        return Err(PlotError::Length {
            file: dir.join("track.svg"),
            column: (*column).into(),
            len: *len,
            times: plot.time.len(),
        });
    }
    // The title as XML can hold it (see `output::text`).
    let title = printable(plot.title);
    let plot = &ManoeuvrePlot {
        title: &title,
        ..*plot
    };
    let Hull {
        length,
        beam,
        beam_assumed,
    } = plot.hull;
    let beam_note = if beam_assumed {
        format!(" (B = L/{} assumed)", Short(length / beam))
    } else {
        String::new()
    };
    let caption = format!(
        "{}: track, hull every 1/{HULLS} of the run{beam_note}",
        plot.title
    );
    let axes = ("east Y [m]", "north X [m]");
    let outlines = hulls(plot);
    let track = emit(dir, "track.svg", |svg| {
        draw_track(
            svg,
            &caption,
            axes,
            (plot.east, plot.north),
            plot.marks,
            &outlines,
        )
    })?;
    let heading = emit(dir, "heading.svg", |svg| draw_heading(svg, plot))?;
    Ok(vec![track, heading])
}

fn draw_heading(svg: &mut String, plot: &ManoeuvrePlot) -> Result<(), DrawError> {
    let caption = format!("{}: heading and rudder", plot.title);
    let style = PanelStyle {
        caption: &caption,
        caption_size: TITLE_FONT,
        y_desc: "[deg]",
        time_desc: true,
        time_ticks: 8,
        legend: true,
    };
    let lines = [
        Line {
            name: "heading change ψ − ψ₀",
            values: plot.heading_change_deg,
            colour: COLOURS[0],
        },
        Line {
            name: "rudder δ",
            values: plot.rudder_deg,
            colour: COLOURS[1],
        },
        Line {
            name: "command",
            values: plot.command_deg,
            colour: COLOURS[2],
        },
    ];
    let range = time_range(plot.time);
    render(svg, (WIDTH, 420), |root, overlay| {
        time_panel(root, overlay, &style, plot.time, range, &lines)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hull_is_drawn_at_midship_along_its_heading() {
        // Heading north, then turned to east while running 1 km east.
        let time: Vec<f64> = (0..101).map(f64::from).collect();
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
        let zero = vec![0.0; 101];
        let plot = ManoeuvrePlot {
            title: "t",
            time: &time,
            north: &north,
            east: &east,
            heading_change_deg: &zero,
            heading_rad: &psi,
            rudder_deg: &zero,
            command_deg: &zero,
            marks: &[],
            hull: Hull {
                length: 140.0,
                beam: 20.0,
                beam_assumed: true,
            },
        };
        let outlines = hulls(&plot);
        // The start and every tenth of the 1 000 m run.
        assert_eq!(outlines.len(), 11);
        let span = |o: &[(f64, f64)], f: fn(&(f64, f64)) -> f64| {
            let values: Vec<f64> = o.iter().map(f).collect();
            let lo = values.iter().copied().fold(f64::MAX, f64::min);
            let hi = values.iter().copied().fold(f64::MIN, f64::max);
            (lo, hi)
        };
        // At the start the bow points north: L along north, B across, about midship.
        let (n0, n1) = span(&outlines[0], |p| p.1);
        let (e0, e1) = span(&outlines[0], |p| p.0);
        assert!(
            (n0 + 70.0).abs() < 1e-9 && (n1 - 70.0).abs() < 1e-9,
            "{n0} {n1}"
        );
        assert!(
            (e0 + 10.0).abs() < 1e-9 && (e1 - 10.0).abs() < 1e-9,
            "{e0} {e1}"
        );
        // At 500 m, heading east: L along east about 500 m.
        let (e0, e1) = span(&outlines[5], |p| p.0);
        assert!(
            (e0 - 430.0).abs() < 1e-9 && (e1 - 570.0).abs() < 1e-9,
            "{e0} {e1}"
        );
        // No hull where L or B is not positive.
        let mut bad = plot;
        bad.hull.beam = f64::NAN;
        assert!(hulls(&bad).is_empty());
    }
}
