//! Time series: one panel of lines against time, the state plot (a panel per component) and
//! the attitude plot (roll, pitch and yaw on one panel).

use super::precise::{Overlay, PixelFrame};
use super::scale::{axis_range, bounded, decimate, extent, tick_label};
use super::{
    Area, COLOURS, DrawError, FONT, LABEL_FONT, PANEL_FONT, TITLE_FONT, WIDTH, fitted_caption,
    render,
};
use eom::models::state_unit;
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
/// The value range raised so that a legend of `entries` lines in the upper corner sits above
/// the curves instead of on them: each line of the legend takes about a ninth of the panel.
fn with_room_for_legend(range: (f64, f64), entries: Option<usize>) -> (f64, f64) {
    match entries {
        Some(n) if n > 0 => {
            let share = (n as f64 / 9.0).min(0.5);
            (
                range.0,
                range.1 + (range.1 - range.0) * share / (1.0 - share),
            )
        }
        _ => range,
    }
}

pub(super) fn time_panel(
    area: &Area,
    overlay: &mut Overlay,
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
    let value_range = with_room_for_legend(
        axis_range(extent(points.iter().flatten().map(|p| p.1))),
        style.legend.then_some(lines.len()),
    );
    let value_ticks = 5;
    let x_label = |v: &f64| tick_label(*v, time_range, style.time_ticks);
    let y_label = |v: &f64| tick_label(*v, value_range, value_ticks);

    let (caption, caption_size) =
        fitted_caption(style.caption, style.caption_size, area.dim_in_pixel().0);
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, caption_size))
        .margin(8)
        .x_label_area_size(if style.time_desc { 50 } else { 24 })
        .y_label_area_size(if style.y_desc.is_empty() { 80 } else { 96 })
        .build_cartesian_2d(time_range.0..time_range.1, value_range.0..value_range.1)?;
    let mut mesh = chart.configure_mesh();
    mesh.x_labels(style.time_ticks)
        .y_labels(value_ticks)
        .x_label_formatter(&x_label)
        .y_label_formatter(&y_label)
        .light_line_style(TRANSPARENT)
        .label_style((FONT, LABEL_FONT))
        .axis_desc_style((FONT, LABEL_FONT));
    if style.time_desc {
        mesh.x_desc("t [s]");
    }
    if !style.y_desc.is_empty() {
        mesh.y_desc(style.y_desc);
    }
    mesh.draw()?;
    let frame = PixelFrame::new(
        chart.plotting_area().get_pixel_range(),
        time_range,
        value_range,
    );
    for (line, points) in lines.iter().zip(points) {
        let colour = line.colour;
        overlay.line(area, points.into_iter().map(|p| frame.at(p)), colour, 1)?;
        let series = chart.draw_series(std::iter::empty::<PathElement<(f64, f64)>>())?;
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
            .label_font((FONT, LABEL_FONT))
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

/// Whether a series is zero at every sample (and has samples): such a component is named in
/// the state plot's caption instead of given a panel.
fn identically_zero(values: &[f64]) -> bool {
    !values.is_empty() && values.iter().all(|v| *v == 0.0)
}

/// The state plot: one small panel per component (its name, its values against `time`) that
/// is not zero throughout, titled with its name, its value axis labelled with its unit, all
/// over the same time range; the components left out are named in the caption. Up to four
/// panels are stacked in one column; more are laid out two to a row, so that the plot stays
/// 830 px wide with readable labels.
pub(super) fn draw_state(
    svg: &mut String,
    title: &str,
    time: &[f64],
    state: &[(&str, &[f64])],
) -> Result<(), DrawError> {
    let (zero, mut shown): (Vec<_>, Vec<_>) = state
        .iter()
        .partition(|(_, values)| identically_zero(values));
    if shown.is_empty() {
        // Nothing moves: draw every component rather than an empty plot.
        shown = zero.clone();
    }
    let n = shown.len();
    let (columns, panel) = if n <= 4 {
        (1, (WIDTH, 210))
    } else {
        (2, (WIDTH / 2, 220))
    };
    let rows = n.div_ceil(columns);
    let title_height = 40;
    let size = (
        columns as u32 * panel.0,
        title_height + rows as u32 * panel.1,
    );
    let time_range = time_range(time);
    let caption = match zero.len() {
        0 => format!("{title}: state"),
        _ if zero.len() == state.len() => format!("{title}: state, zero throughout"),
        _ => format!(
            "{title}: state ({} zero throughout, not drawn)",
            zero.iter()
                .map(|(name, _)| *name)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    render(svg, size, |root, overlay| {
        let (caption, size) = fitted_caption(&caption, TITLE_FONT, WIDTH);
        let body = root.titled(&caption, (FONT, size))?;
        let panels = body.split_evenly((rows, columns));
        for (&(name, values), area) in shown.iter().zip(&panels) {
            let y_desc = match state_unit(name) {
                Some(unit) => format!("{name} [{unit}]"),
                None => name.to_string(),
            };
            let style = PanelStyle {
                caption: name,
                caption_size: PANEL_FONT,
                y_desc: &y_desc,
                time_desc: true,
                time_ticks: if columns == 1 { 8 } else { 5 },
                legend: false,
            };
            let line = Line {
                name,
                values,
                colour: COLOURS[0],
            };
            time_panel(area, overlay, &style, time, time_range, &[line])?;
        }
        Ok(())
    })
}

/// Roll, pitch and yaw in degrees made continuous, so that a tumbling body draws lines
/// without jumps: each sample is written as whichever of its two equivalent triples, (φ, θ, ψ)
/// or (φ + 180°, 180° − θ, ψ + 180°), plus whole turns on each angle, lies nearest the
/// sample before it. A body spinning about its y-axis then shows θ running on through ±90°
/// where the principal values would jump φ and ψ by 180° and fold θ back. The first sample
/// keeps its principal values.
pub(super) fn continuous_euler_deg(angles: [&[f64]; 3]) -> [Vec<f64>; 3] {
    let mut out: [Vec<f64>; 3] = Default::default();
    let mut last: Option<[f64; 3]> = None;
    let samples = angles[0].iter().zip(angles[1]).zip(angles[2]);
    for ((&r, &p), &y) in samples {
        let chosen = match last {
            Some(previous) if r.is_finite() && p.is_finite() && y.is_finite() => {
                let near = |triple: [f64; 3]| {
                    let shifted = [0, 1, 2]
                        .map(|k| triple[k] + 360.0 * ((previous[k] - triple[k]) / 360.0).round());
                    let distance: f64 = (0..3).map(|k| (shifted[k] - previous[k]).abs()).sum();
                    (shifted, distance)
                };
                let (a, da) = near([r, p, y]);
                let (b, db) = near([r + 180.0, 180.0 - p, y + 180.0]);
                if db < da { b } else { a }
            }
            _ => [r, p, y],
        };
        if chosen.iter().all(|v| v.is_finite()) {
            last = Some(chosen);
        }
        for (column, value) in out.iter_mut().zip(chosen) {
            column.push(value);
        }
    }
    out
}

/// The attitude plot: roll, pitch and yaw in degrees, made continuous
/// ([`continuous_euler_deg`]), on one panel, with a legend.
pub(super) fn draw_attitude(
    svg: &mut String,
    title: &str,
    time: &[f64],
    angles: [&[f64]; 3],
) -> Result<(), DrawError> {
    let unwrapped = continuous_euler_deg(angles);
    render(svg, (WIDTH, 420), |root, overlay| {
        let caption = format!("{title}: attitude (Euler angles, continuous, no wraps)");
        let style = PanelStyle {
            caption: &caption,
            caption_size: TITLE_FONT,
            y_desc: "angle [deg]",
            time_desc: true,
            time_ticks: 8,
            legend: true,
        };
        let lines: Vec<Line> = ["roll φ", "pitch θ", "yaw ψ"]
            .into_iter()
            .zip(&unwrapped)
            .zip(COLOURS)
            .map(|((name, values), colour)| Line {
                name,
                values,
                colour,
            })
            .collect();
        time_panel(root, overlay, &style, time, time_range(time), &lines)
    })
}

#[cfg(test)]
mod tests {
    use super::with_room_for_legend;

    #[test]
    fn a_legend_gets_room_above_the_curves() {
        // Three lines take a third of the panel: the data keep the lower two thirds.
        let (low, high) = with_room_for_legend((-10.0, 20.0), Some(3));
        assert_eq!(low, -10.0);
        assert!(((20.0 - low) / (high - low) - 2.0 / 3.0).abs() < 1e-12);
        assert_eq!(with_room_for_legend((-10.0, 20.0), None), (-10.0, 20.0));
    }
}
