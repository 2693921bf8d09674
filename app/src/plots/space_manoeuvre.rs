//! A manoeuvre in space (a vehicle's): its plots: the track in plan (north against east, with a turning
//! circle's points marked as a ship's are: the execute, 90° with the advance and transfer,
//! 180° with the tactical diameter), the profile (height against the distance run, and seen
//! from the east), the attitude (roll, pitch, yaw made continuous), and the fins with their
//! commands.

use super::profile::draw_profile;
use super::series::{Line, PanelStyle, draw_attitude, time_panel, time_range};
use super::track::{Mark, draw_track};
use super::{COLOURS, DrawError, PlotError, TITLE_FONT, WIDTH, emit, render};
use eom::output::text::printable;
use plotters::style::RGBColor;
use std::path::{Path, PathBuf};

/// The columns a vehicle's plots read, each in SI (angles in radians), one value per time.
#[derive(Clone, Copy)]
pub struct SpacePlot<'a> {
    /// The plots' title.
    pub title: &'a str,
    /// t, s.
    pub time: &'a [f64],
    /// x, y, z of O in space axes (north, east, down), m.
    pub position: [&'a [f64]; 3],
    /// φ, θ, ψ, rad.
    pub attitude: [&'a [f64]; 3],
    /// δ_r, δ_s and their commands, rad.
    pub fins: [&'a [f64]; 4],
    /// Points to mark on the track, in (east, north).
    pub marks: &'a [Mark],
}

/// Writes `track.svg`, `profile.svg`, `attitude.svg` and `fins.svg` into `dir`.
pub fn write_space_plots(dir: &Path, plot: &SpacePlot) -> Result<Vec<PathBuf>, PlotError> {
    let columns = plot.position.iter().chain(&plot.attitude).chain(&plot.fins);
    if let Some(len) = columns.map(|c| c.len()).find(|len| *len != plot.time.len()) {
        return Err(PlotError::Length {
            file: dir.join("track.svg"),
            column: "a vehicle's column".into(),
            len,
            times: plot.time.len(),
        });
    }
    let title = printable(plot.title);
    let [x, y, z] = plot.position;
    let track = emit(dir, "track.svg", |svg| {
        let caption = format!("{title}: track in plan");
        draw_track(
            svg,
            &caption,
            ("east Y [m]", "north X [m]"),
            (y, x),
            plot.marks,
            &[],
        )
    })?;
    let profile = emit(dir, "profile.svg", |svg| {
        draw_profile(svg, &title, (x, y, z))
    })?;
    // The attitude plot reads degrees, and makes them continuous.
    let degrees = plot
        .attitude
        .map(|c| c.iter().map(|x| x.to_degrees()).collect::<Vec<f64>>());
    let attitude = emit(dir, "attitude.svg", |svg| {
        let [roll, pitch, yaw] = &degrees;
        draw_attitude(svg, &title, plot.time, [roll, pitch, yaw])
    })?;
    let fins = emit(dir, "fins.svg", |svg| draw_fins(svg, &title, plot))?;
    Ok(vec![track, profile, attitude, fins])
}

fn draw_fins(svg: &mut String, title: &str, plot: &SpacePlot) -> Result<(), DrawError> {
    let caption = format!("{title}: fins and their commands");
    let style = PanelStyle {
        caption: &caption,
        caption_size: TITLE_FONT,
        y_desc: "[deg]",
        time_desc: true,
        time_ticks: 8,
        legend: true,
    };
    let degrees: Vec<Vec<f64>> = (plot.fins.iter())
        .map(|c| c.iter().map(|x| x.to_degrees()).collect())
        .collect();
    let names = [
        "rudder δr",
        "stern planes δs",
        "rudder command",
        "stern planes command",
    ];
    // The palette's three, and Tableau 10's red for the fourth.
    let colours = [COLOURS[0], COLOURS[1], COLOURS[2], RGBColor(214, 39, 40)];
    let lines: Vec<Line> = (names.into_iter().zip(&degrees).zip(colours))
        .map(|((name, values), colour)| Line {
            name,
            values,
            colour,
        })
        .collect();
    let range = time_range(plot.time);
    render(svg, (WIDTH, 420), |root, overlay| {
        time_panel(root, overlay, &style, plot.time, range, &lines)
    })
}
