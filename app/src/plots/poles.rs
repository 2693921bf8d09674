//! The pole plot of a linear model: its modes' eigenvalues in the complex plane, the imaginary
//! axis (the edge of stability) drawn through zero, so that a pole to its right is a mode that
//! grows. Each mode has its own colour and its name in the legend with its eigenvalue; a pole
//! whose real part is beyond the verdict's tolerance is ringed in red, so that a reader sees
//! which modes made the verdict. Where the slow modes (a phugoid, a spiral, a height mode)
//! crowd the origin beside a fast one, a second panel shows them at their own scale.

use super::scale::tick_label;
use super::{Area, DrawError, FONT, LABEL_FONT, PANEL_FONT, PlotError, TITLE_FONT, WIDTH};
use super::{emit, fitted_caption, render};
use eom::Short;
use plotters::prelude::*;

use std::path::{Path, PathBuf};

/// The file of the pole plot.
pub const POLES: &str = "poles.svg";

/// One mode as the plot draws it.
#[derive(Debug, Clone, PartialEq)]
pub struct PlottedMode {
    /// What the legend calls it (its name, or `mode k`).
    pub name: String,
    /// Its eigenvalue (Re λ, Im λ): of a pair, the one with Im λ > 0; the conjugate is drawn
    /// too.
    pub eigenvalue: (f64, f64),
}

/// A pole nearer the origin than this fraction of the farthest is drawn again in the panel of
/// the slow modes: at a tenth it is within the cross's size of its neighbours at the origin.
const SLOW: f64 = 0.1;

/// The modes' colours: the Tableau 10 palette without its red (the ring of a mode that grows).
const PALETTE: [RGBColor; 9] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// Draws `modes` into `dir/poles.svg`, titled `title`; a pole with a real part above
/// `growth_tolerance` (1/s) is marked as one that grows.
pub fn write_pole_plot(
    dir: &Path,
    title: &str,
    modes: &[PlottedMode],
    growth_tolerance: f64,
) -> Result<PathBuf, PlotError> {
    let finite: Vec<&PlottedMode> = (modes.iter())
        .filter(|mode| mode.eigenvalue.0.is_finite() && mode.eigenvalue.1.is_finite())
        .collect();
    let all_reach = reach(finite.iter().copied());
    let slow: Vec<&PlottedMode> = (finite.iter().copied())
        .filter(|mode| modulus(mode) < SLOW * all_reach)
        .collect();
    let slow_reach = reach(slow.iter().copied());
    // A second panel where slow poles and a fast one share the plot.
    let zoomed = !slow.is_empty() && slow.len() < finite.len();
    let width = if zoomed { 2 * WIDTH } else { WIDTH };
    let (caption, caption_size) = fitted_caption(
        &format!("{title}: poles (eigenvalues of A)"),
        TITLE_FONT,
        width,
    );
    let panels = Panels {
        modes: &finite,
        growth_tolerance,
    };
    emit(dir, POLES, |svg| {
        render(svg, (width, WIDTH), |root, _| {
            let root = root.titled(&caption, (FONT, caption_size))?;
            if !zoomed {
                return panels.draw(&root, "every mode", all_reach, true);
            }
            let (left, right) = root.split_horizontally(WIDTH);
            panels.draw(&left, "every mode", all_reach, true)?;
            panels.draw(&right, "the slow modes, near the origin", slow_reach, false)
        })
    })
}

/// |λ|.
fn modulus(mode: &PlottedMode) -> f64 {
    mode.eigenvalue.0.hypot(mode.eigenvalue.1)
}

/// The largest |Re λ| or |Im λ| of `modes`.
fn reach<'a>(modes: impl Iterator<Item = &'a PlottedMode>) -> f64 {
    modes.fold(0.0f64, |m, mode| {
        m.max(mode.eigenvalue.0.abs()).max(mode.eigenvalue.1.abs())
    })
}

/// What each panel draws.
struct Panels<'a> {
    modes: &'a [&'a PlottedMode],
    growth_tolerance: f64,
}

impl Panels<'_> {
    /// One panel: the plane to ±1.1 `reach` (one scale on both axes, zero inside), the axes,
    /// the modes within it, and with `legend` every mode's name and eigenvalue.
    fn draw(&self, area: &Area, caption: &str, reach: f64, legend: bool) -> Result<(), DrawError> {
        let half = if reach > 0.0 { 1.1 * reach } else { 1.0 };
        let range = (-half, half);
        let ticks = 8;
        let label = |v: &f64| tick_label(*v, range, ticks);
        let mut chart = ChartBuilder::on(area)
            .caption(caption, (FONT, PANEL_FONT))
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
        let within = |(re, im): (f64, f64)| re.abs() <= half && im.abs() <= half;
        for (k, mode) in self.modes.iter().enumerate() {
            let colour = PALETTE[k % PALETTE.len()];
            let (re, im) = mode.eigenvalue;
            let poles: Vec<(f64, f64)> = match im == 0.0 {
                true => vec![(re, 0.0)],
                false => vec![(re, im), (re, -im)],
            };
            let shown: Vec<(f64, f64)> = poles.into_iter().filter(|p| within(*p)).collect();
            let cross = move |point| Cross::new(point, 6, colour.stroke_width(2));
            let series = chart.draw_series(shown.iter().map(|&point| cross(point)))?;
            if legend {
                let grows = if re > self.growth_tolerance {
                    ", grows"
                } else {
                    ""
                };
                series
                    .label(format!("{}: {}{grows}", mode.name, eigenvalue_text(re, im)))
                    .legend(move |(x, y)| Cross::new((x + 10, y), 6, colour.stroke_width(2)));
            }
            if re > self.growth_tolerance {
                let ring = |&point| Circle::new(point, 9, RED.stroke_width(2));
                chart.draw_series(shown.iter().map(ring))?;
            }
        }
        if legend {
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperLeft)
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK.mix(0.3))
                .label_font((FONT, LABEL_FONT))
                .draw()?;
        }
        Ok(())
    }
}

/// `re ± im i` (or `re` for a real pole), short.
fn eigenvalue_text(re: f64, im: f64) -> String {
    match im == 0.0 {
        true => format!("{}", Short(re)),
        false => format!("{} ± {}i", Short(re), Short(im.abs())),
    }
}
