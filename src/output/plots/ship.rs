//! A manoeuvre's plots: `track.svg`, midship's track as a chart (east across, north up, one
//! scale) with the manoeuvre's points marked (for a turning circle the 90° and 180° points,
//! with the advance, transfer and tactical diameter); and `heading.svg`, the heading change,
//! the rudder angle and its command over time (a zig-zag's plot).

use super::series::{Line, PanelStyle, time_panel, time_range};
use super::track::draw_track;
use super::{COLOURS, DrawError, Mark, PlotError, emit, render};
use crate::output::text::printable;
use std::path::{Path, PathBuf};

/// The columns of one manoeuvre, sampled at the same times.
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
    /// δ, degrees.
    pub rudder_deg: &'a [f64],
    /// The command after saturation, degrees.
    pub command_deg: &'a [f64],
    /// Points to mark on the track, in (east, north).
    pub marks: &'a [Mark],
}

/// Writes `track.svg` and `heading.svg` into `dir`.
pub fn write_manoeuvre_plots(dir: &Path, plot: &ManoeuvrePlot) -> Result<Vec<PathBuf>, PlotError> {
    let columns = [
        ("north", plot.north.len()),
        ("east", plot.east.len()),
        ("heading change", plot.heading_change_deg.len()),
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
    let caption = format!("{}: track of midship", plot.title);
    let axes = ("east Y [m]", "north X [m]");
    let track = emit(dir, "track.svg", |svg| {
        draw_track(svg, &caption, axes, (plot.east, plot.north), plot.marks)
    })?;
    let heading = emit(dir, "heading.svg", |svg| draw_heading(svg, plot))?;
    Ok(vec![track, heading])
}

fn draw_heading(svg: &mut String, plot: &ManoeuvrePlot) -> Result<(), DrawError> {
    let caption = format!("{}: heading and rudder", plot.title);
    let style = PanelStyle {
        caption: &caption,
        caption_size: 22,
        y_desc: "[deg]",
        time_desc: true,
        time_ticks: 10,
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
    render(svg, (1000, 500), |root, overlay| {
        time_panel(root, overlay, &style, plot.time, range, &lines)
    })
}
