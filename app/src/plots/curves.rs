//! Curves of one quantity against another, each a line through its points with the points
//! marked: a spiral's r–δ curve (`spiral.svg`), a sweep's figures against its key
//! (`sweep.svg`). The axes through zero are drawn where zero is in range, so
//! that a loop about δ = 0, r = 0 shows where it sits.

use super::scale::{axis_range, tick_label};
use super::{
    COLOURS, FONT, LABEL_FONT, PlotError, TITLE_FONT, WIDTH, emit, fitted_caption, render,
};
use eom::output::text::printable;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// One curve: its name for the legend and its points (x, y), joined in their order.
pub struct Curve<'a> {
    /// Its name.
    pub name: &'a str,
    /// Its points.
    pub points: &'a [(f64, f64)],
}

/// A plot of curves.
pub struct Curves<'a> {
    /// The caption.
    pub caption: &'a str,
    /// The x axis' label, with its unit.
    pub x_desc: &'a str,
    /// The y axis' label, with its unit.
    pub y_desc: &'a str,
    /// The curves, drawn in order (up to six colours, then again).
    pub curves: &'a [Curve<'a>],
}

/// The range of the finite values of `values`, with room around them.
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let extent = values.filter(|v| v.is_finite()).fold(None, |e, v| match e {
        None => Some((v, v)),
        Some((lo, hi)) => Some((f64::min(lo, v), f64::max(hi, v))),
    });
    axis_range(extent)
}

/// Draws `plot` into `dir/file`.
pub fn write_curves(dir: &Path, file: &str, plot: &Curves) -> Result<PathBuf, PlotError> {
    let all = || plot.curves.iter().flat_map(|c| c.points.iter().copied());
    let x = range(all().map(|p| p.0));
    let y = range(all().map(|p| p.1));
    let ticks = 8;
    let x_label = |v: &f64| tick_label(*v, x, ticks);
    let y_label = |v: &f64| tick_label(*v, y, ticks);
    let (caption, caption_size) = fitted_caption(&printable(plot.caption), TITLE_FONT, WIDTH);
    emit(dir, file, |svg| {
        render(svg, (WIDTH, 560), |root, _| {
            let mut chart = ChartBuilder::on(root)
                .caption(&caption, (FONT, caption_size))
                .margin(16)
                .x_label_area_size(48)
                .y_label_area_size(80)
                .build_cartesian_2d(x.0..x.1, y.0..y.1)?;
            chart
                .configure_mesh()
                .x_labels(ticks)
                .y_labels(ticks)
                .x_label_formatter(&x_label)
                .y_label_formatter(&y_label)
                .light_line_style(TRANSPARENT)
                .label_style((FONT, LABEL_FONT))
                .x_desc(plot.x_desc)
                .y_desc(plot.y_desc)
                .draw()?;
            let axis = BLACK.mix(0.4).stroke_width(1);
            if x.0 < 0.0 && x.1 > 0.0 {
                chart.draw_series(LineSeries::new([(0.0, y.0), (0.0, y.1)], axis))?;
            }
            if y.0 < 0.0 && y.1 > 0.0 {
                chart.draw_series(LineSeries::new([(x.0, 0.0), (x.1, 0.0)], axis))?;
            }
            for (k, curve) in plot.curves.iter().enumerate() {
                let colour = curve_colour(k);
                let finite: Vec<(f64, f64)> = (curve.points.iter().copied())
                    .filter(|p| p.0.is_finite() && p.1.is_finite())
                    .collect();
                chart
                    .draw_series(LineSeries::new(finite.clone(), colour.stroke_width(2)))?
                    .label(curve.name)
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                    });
                chart.draw_series(
                    (finite.into_iter()).map(|p| Circle::new(p, 3, colour.filled())),
                )?;
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK.mix(0.3))
                .label_font((FONT, LABEL_FONT))
                .draw()?;
            Ok(())
        })
    })
}

/// The colour of the `k`th curve: the three of every plot, then the same darker.
fn curve_colour(k: usize) -> RGBColor {
    let RGBColor(r, g, b) = COLOURS[k % COLOURS.len()];
    if (k / COLOURS.len()).is_multiple_of(2) {
        RGBColor(r, g, b)
    } else {
        RGBColor(r / 2, g / 2, b / 2)
    }
}
