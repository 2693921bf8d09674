//! Time series: one panel of lines against time, the state plot (a panel per component) and
//! the attitude plot (roll, pitch and yaw on one panel).

use super::scale::{axis_range, bounded, decimate, extent, tick_label};
use super::{Area, COLOURS, DrawError, FONT, PlotInput, render};
use plotters::prelude::*;

/// One line of a time-series panel.
pub(super) struct Line<'a> {
    /// Its name, for the legend.
    pub(super) name: &'a str,
    /// Its values, one per sample time.
    pub(super) values: &'a [f64],
    /// Its colour.
    pub(super) colour: RGBColor,
}

/// How a time-series panel is laid out.
pub(super) struct PanelStyle<'a> {
    /// The caption above the panel.
    pub(super) caption: &'a str,
    /// The caption's font size.
    pub(super) caption_size: u32,
    /// The label of the value axis.
    pub(super) y_desc: &'a str,
    /// Whether to label the time axis (only the bottom panels of a grid do).
    pub(super) time_desc: bool,
    /// About how many ticks on the time axis.
    pub(super) time_ticks: usize,
    /// Whether to draw a legend of the lines' names.
    pub(super) legend: bool,
}

/// Draws the lines against `time` onto `area`, over the time range `time_range`.
pub(super) fn time_panel(
    area: &Area,
    style: &PanelStyle,
    time: &[f64],
    time_range: (f64, f64),
    lines: &[Line],
) -> Result<(), DrawError> {
    // About one window per pixel column: the decimated line covers the same pixels.
    let windows = area.dim_in_pixel().0 as usize;
    let points: Vec<Vec<(f64, f64)>> = lines
        .iter()
        .map(|line| {
            let finite = |i: usize| time[i].is_finite() && line.values[i].is_finite();
            decimate(time.len(), windows, finite, &[line.values])
                .into_iter()
                .map(|i| (bounded(time[i]), bounded(line.values[i])))
                .collect()
        })
        .collect();
    let value_range = axis_range(extent(points.iter().flatten().map(|p| p.1)));
    let value_ticks = 5;
    let x_label = |v: &f64| tick_label(*v, time_range, style.time_ticks);
    let y_label = |v: &f64| tick_label(*v, value_range, value_ticks);

    let mut chart = ChartBuilder::on(area)
        .caption(style.caption, (FONT, style.caption_size))
        .margin(8)
        .x_label_area_size(if style.time_desc { 40 } else { 24 })
        .y_label_area_size(if style.y_desc.is_empty() { 80 } else { 96 })
        .build_cartesian_2d(time_range.0..time_range.1, value_range.0..value_range.1)?;
    let mut mesh = chart.configure_mesh();
    mesh.x_labels(style.time_ticks)
        .y_labels(value_ticks)
        .x_label_formatter(&x_label)
        .y_label_formatter(&y_label)
        .light_line_style(TRANSPARENT)
        .label_style((FONT, 12));
    if style.time_desc {
        mesh.x_desc("t [s]");
    }
    if !style.y_desc.is_empty() {
        mesh.y_desc(style.y_desc);
    }
    mesh.draw()?;
    for (line, points) in lines.iter().zip(points) {
        let colour = line.colour;
        let series = chart.draw_series(LineSeries::new(points, colour.stroke_width(1)))?;
        if style.legend {
            series.label(line.name).legend(move |(x, y)| {
                Rectangle::new([(x, y - 1), (x + 16, y + 1)], colour.filled())
            });
        }
    }
    if style.legend {
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((FONT, 13))
            .draw()?;
    }
    Ok(())
}

/// The time axis's range: the finite times, widened as any axis is.
pub(super) fn time_range(time: &[f64]) -> (f64, f64) {
    axis_range(extent(
        time.iter().copied().filter(|t| t.is_finite()).map(bounded),
    ))
}

/// The state plot: one small panel per component, titled with its name, all over the same
/// time range. Up to four components are stacked in one column; more are laid out three to a
/// row, so that the spatial states (u v w / p q r / x y z / angles or quaternion) fall into
/// rows of three.
pub(super) fn draw_state(svg: &mut String, input: &PlotInput) -> Result<(), DrawError> {
    let n = input.state.len();
    let (columns, panel) = if n <= 4 {
        (1, (1000, 220))
    } else {
        (3, (440, 210))
    };
    let rows = n.div_ceil(columns);
    let title_height = 40;
    let size = (
        columns as u32 * panel.0,
        title_height + rows as u32 * panel.1,
    );
    let time_range = time_range(input.time);
    render(svg, size, |root| {
        let body = root.titled(&format!("{}: state", input.title), (FONT, 22))?;
        let panels = body.split_evenly((rows, columns));
        for (k, (&(name, values), area)) in input.state.iter().zip(&panels).enumerate() {
            // The bottom panel of each column labels the time axis.
            let bottom = k + columns >= n;
            let style = PanelStyle {
                caption: name,
                caption_size: 16,
                y_desc: "",
                time_desc: bottom,
                time_ticks: if columns == 1 { 10 } else { 5 },
                legend: false,
            };
            let line = Line {
                name,
                values,
                colour: COLOURS[0],
            };
            time_panel(area, &style, input.time, time_range, &[line])?;
        }
        Ok(())
    })
}

/// The attitude plot: roll, pitch and yaw in degrees on one panel, with a legend.
pub(super) fn draw_attitude(
    svg: &mut String,
    title: &str,
    time: &[f64],
    angles: [&[f64]; 3],
) -> Result<(), DrawError> {
    render(svg, (1000, 500), |root| {
        let caption = format!("{title}: attitude (Euler angles)");
        let style = PanelStyle {
            caption: &caption,
            caption_size: 22,
            y_desc: "angle [deg]",
            time_desc: true,
            time_ticks: 10,
            legend: true,
        };
        let lines: Vec<Line> = ["roll φ", "pitch θ", "yaw ψ"]
            .into_iter()
            .zip(angles)
            .zip(COLOURS)
            .map(|((name, values), colour)| Line {
                name,
                values,
                colour,
            })
            .collect();
        time_panel(root, &style, time, time_range(time), &lines)
    })
}
