//! A Monte Carlo's plots: each figure's distribution over the cases, a histogram per panel
//! (`distributions.svg`), and each verdict's pass rate with its 95 % Wilson interval
//! (`pass_rates.svg`).
//!
//! A histogram has ⌈√n⌉ bins (at most 40, at least 5) evenly over the figure's range; its
//! panel is titled with the figure's name, and says n, the mean and the standard deviation.
//! A figure that no case gave, or that every case gave alike, is named in its panel rather
//! than drawn as one bar.

use super::scale::{axis_range, tick_label};
use super::{FONT, LABEL_FONT, PlotError, TITLE_FONT, WIDTH, emit, fitted_caption, render};
use eom::output::text::printable;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// The distributions' plot.
pub const DISTRIBUTIONS_PLOT: &str = "distributions.svg";
/// The pass rates' plot.
pub const PASS_RATES_PLOT: &str = "pass_rates.svg";

/// Panels side by side.
const COLUMNS: usize = 3;
/// A panel's height, px.
const PANEL_HEIGHT: u32 = 230;

/// One figure's values over the cases.
pub struct Distribution<'a> {
    /// Its name (`turning_circle_35/port/advance_m`).
    pub name: &'a str,
    /// The values the cases gave.
    pub values: &'a [f64],
}

/// One verdict's pass rate.
pub struct PassRate<'a> {
    /// Its name.
    pub name: &'a str,
    /// The rate, and its 95 % Wilson interval.
    pub rate: (f64, f64, f64),
}

/// The bins of `values` (sorted or not): (lower edge, upper edge, count), over their range.
fn bins(values: &[f64]) -> Vec<(f64, f64, usize)> {
    let (lo, hi) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    let count = ((values.len() as f64).sqrt().ceil() as usize).clamp(5, 40);
    let width = (hi - lo) / count as f64;
    let mut bins: Vec<(f64, f64, usize)> = (0..count)
        .map(|i| (lo + width * i as f64, lo + width * (i + 1) as f64, 0))
        .collect();
    for &v in values {
        let at = (((v - lo) / width) as usize).min(count - 1);
        bins[at].2 += 1;
    }
    bins
}

/// Draws every figure's histogram into `dir/DISTRIBUTIONS_PLOT`, under `caption`.
pub fn write_distributions(
    dir: &Path,
    caption: &str,
    figures: &[Distribution],
) -> Result<PathBuf, PlotError> {
    let rows = figures.len().div_ceil(COLUMNS).max(1);
    let height = 60 + PANEL_HEIGHT * rows as u32;
    let (caption, size) = fitted_caption(&printable(caption), TITLE_FONT, WIDTH);
    emit(dir, DISTRIBUTIONS_PLOT, |svg| {
        render(svg, (WIDTH, height), |root, _| {
            let body = root.titled(&caption, (FONT, size))?;
            let panels = body.split_evenly((rows, COLUMNS));
            for (panel, figure) in panels.iter().zip(figures) {
                histogram(panel, figure)?;
            }
            Ok(())
        })
    })
}

/// One figure's histogram on `panel`.
fn histogram<DB: DrawingBackend>(
    panel: &DrawingArea<DB, plotters::coord::Shift>,
    figure: &Distribution,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let finite: Vec<f64> = figure
        .values
        .iter()
        .copied()
        .filter(|v| v.is_finite())
        .collect();
    let n = finite.len();
    let mean = finite.iter().sum::<f64>() / n as f64;
    let std =
        (finite.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n.max(2) - 1) as f64).sqrt();
    let spread = finite.iter().any(|&v| v != finite[0]);
    let title = match (n, spread) {
        (0, _) => format!("{}: no case gave it", figure.name),
        (_, false) => format!("{}: {} in all {n}", figure.name, finite[0]),
        _ => figure.name.to_owned(),
    };
    let title = printable(&title);
    if n == 0 || !spread {
        panel.titled(&title, (FONT, LABEL_FONT))?;
        return Ok(());
    }
    let bins = bins(&finite);
    let x = axis_range(Some((bins[0].0, bins[bins.len() - 1].1)));
    let tallest = bins.iter().map(|b| b.2).max().unwrap_or(1) as f64;
    let ticks = 4;
    let x_label = |v: &f64| tick_label(*v, x, ticks);
    let mut chart = ChartBuilder::on(panel)
        .caption(&title, (FONT, LABEL_FONT))
        .margin(6)
        .x_label_area_size(28)
        .y_label_area_size(44)
        .build_cartesian_2d(x.0..x.1, 0.0..tallest * 1.1)?;
    chart
        .configure_mesh()
        .x_labels(ticks)
        .y_labels(3)
        .x_label_formatter(&x_label)
        .y_label_formatter(&|v: &f64| format!("{v:.0}"))
        .light_line_style(TRANSPARENT)
        .label_style((FONT, LABEL_FONT - 3))
        .draw()?;
    let fill = RGBColor(31, 119, 180).mix(0.7).filled();
    chart.draw_series(
        (bins.iter()).map(|&(lo, hi, count)| Rectangle::new([(lo, 0.0), (hi, count as f64)], fill)),
    )?;
    let said = format!("n {n}, mean {mean:.4e}, std {std:.2e}");
    chart.draw_series([Text::new(
        said,
        (x.0, tallest * 1.08),
        (FONT, LABEL_FONT - 4).into_font(),
    )])?;
    Ok(())
}

/// Draws each verdict's pass rate with its interval into `dir/PASS_RATES_PLOT`.
pub fn write_pass_rates(
    dir: &Path,
    caption: &str,
    rates: &[PassRate],
) -> Result<PathBuf, PlotError> {
    let (caption, size) = fitted_caption(&printable(caption), TITLE_FONT, WIDTH);
    let count = rates.len().max(1);
    let height = 120 + 34 * count as u32;
    emit(dir, PASS_RATES_PLOT, |svg| {
        render(svg, (WIDTH, height), |root, _| {
            let names: Vec<String> = rates
                .iter()
                .map(|r| printable(r.name).into_owned())
                .collect();
            let y_label = |v: &f64| {
                let at = v.round();
                match (at - v).abs() < 1e-9 && at >= 0.0 {
                    true => names.get(at as usize).cloned().unwrap_or_default(),
                    false => String::new(),
                }
            };
            let mut chart = ChartBuilder::on(root)
                .caption(&caption, (FONT, size))
                .margin(16)
                .x_label_area_size(40)
                .y_label_area_size(260)
                .build_cartesian_2d(0.0..1.0, -0.5..count as f64 - 0.5)?;
            chart
                .configure_mesh()
                .x_labels(11)
                .y_labels(count * 2 + 1)
                .y_label_formatter(&y_label)
                .x_label_formatter(&|v: &f64| format!("{v:.1}"))
                .light_line_style(TRANSPARENT)
                .label_style((FONT, LABEL_FONT))
                .x_desc("pass rate, with its 95 % Wilson interval")
                .draw()?;
            let colour = RGBColor(31, 119, 180);
            for (at, rate) in rates.iter().enumerate() {
                let (p, low, high) = rate.rate;
                if !p.is_finite() {
                    continue;
                }
                let y = at as f64;
                chart.draw_series(LineSeries::new(
                    [(low, y), (high, y)],
                    colour.stroke_width(3),
                ))?;
                chart.draw_series([Circle::new((p, y), 5, colour.filled())])?;
            }
            Ok(())
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bins_hold_every_value_once() {
        let values: Vec<f64> = (0..1000).map(|i| (i as f64 * 0.37).sin()).collect();
        let bins = bins(&values);
        assert_eq!(bins.len(), 32);
        assert_eq!(bins.iter().map(|b| b.2).sum::<usize>(), 1000);
        assert_eq!(
            bins[0].0,
            values.iter().copied().fold(f64::INFINITY, f64::min)
        );
    }
}
