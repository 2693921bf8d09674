//! The pole plot of a linear model: its eigenvalues in the complex plane, the imaginary axis
//! (the edge of stability) drawn through zero, so that a pole to its right is a mode that
//! grows. The poles whose real part is beyond the verdict's tolerance are drawn apart (a red
//! ring, "grows" in the legend), so that a reader sees which modes made the verdict.

use super::scale::tick_label;
use super::{
    COLOURS, FONT, LABEL_FONT, PlotError, TITLE_FONT, WIDTH, emit, fitted_caption, render,
};
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// A pole, (Re λ, Im λ).
type Pole = (f64, f64);

/// The file of the pole plot.
pub const POLES: &str = "poles.svg";

/// Draws the eigenvalues `(re, im)` into `dir/poles.svg`, titled `title`; a pole with a real
/// part above `growth_tolerance` (1/s) is marked as one that grows.
pub fn write_pole_plot(
    dir: &Path,
    title: &str,
    eigenvalues: &[(f64, f64)],
    growth_tolerance: f64,
) -> Result<PathBuf, PlotError> {
    let finite: Vec<(f64, f64)> = eigenvalues
        .iter()
        .copied()
        .filter(|(re, im)| re.is_finite() && im.is_finite())
        .collect();
    // One scale on both axes, with zero inside and a tenth of room around the poles.
    let reach = finite
        .iter()
        .fold(0.0f64, |m, (re, im)| m.max(re.abs()).max(im.abs()));
    let half = if reach > 0.0 { 1.1 * reach } else { 1.0 };
    let range = (-half, half);
    let ticks = 8;
    let label = |v: &f64| tick_label(*v, range, ticks);
    let (caption, caption_size) = fitted_caption(
        &format!("{title}: poles (eigenvalues of A)"),
        TITLE_FONT,
        WIDTH,
    );
    emit(dir, POLES, |svg| {
        render(svg, (WIDTH, WIDTH), |root, _| {
            let mut chart = ChartBuilder::on(root)
                .caption(&caption, (FONT, caption_size))
                .margin(16)
                .x_label_area_size(48)
                .y_label_area_size(72)
                .build_cartesian_2d(-half..half, -half..half)?;
            chart
                .configure_mesh()
                .x_labels(ticks)
                .y_labels(ticks)
                .x_label_formatter(&label)
                .y_label_formatter(&label)
                .light_line_style(TRANSPARENT)
                .label_style((FONT, LABEL_FONT))
                .x_desc("Re λ [1/s]")
                .y_desc("Im λ [rad/s]")
                .draw()?;
            let axis = BLACK.mix(0.5).stroke_width(1);
            chart.draw_series(LineSeries::new([(0.0, -half), (0.0, half)], axis))?;
            chart.draw_series(LineSeries::new([(-half, 0.0), (half, 0.0)], axis))?;
            let grows = |(re, _): &(f64, f64)| *re > growth_tolerance;
            let (growing, others): (Vec<Pole>, Vec<Pole>) = finite.iter().copied().partition(grows);
            let colour = COLOURS[0];
            chart
                .draw_series(
                    (others.iter()).map(|&point| Cross::new(point, 6, colour.stroke_width(2))),
                )?
                .label("decays, or neither grows nor decays")
                .legend(move |(x, y)| Cross::new((x + 10, y), 6, colour.stroke_width(2)));
            if !growing.is_empty() {
                chart
                    .draw_series(
                        (growing.iter()).map(|&point| Circle::new(point, 7, RED.stroke_width(3))),
                    )?
                    .label("grows (unstable)")
                    .legend(|(x, y)| Circle::new((x + 10, y), 7, RED.stroke_width(3)));
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperLeft)
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK.mix(0.3))
                .label_font((FONT, LABEL_FONT))
                .draw()?;
            Ok(())
        })
    })
}
