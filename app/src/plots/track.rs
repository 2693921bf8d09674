//! The track plot: one coordinate against the other at one scale on both axes, its ends and
//! any marked points shown. A track that is a single point (a body turning in place, as the
//! tennis racket does) is said to be one in the caption rather than drawn as a dot that
//! could be mistaken for a short path: its x and y spans are both within 10⁻⁹ of the
//! largest |coordinate| (or of 1 m), round-off.

use super::precise::PixelFrame;
use super::scale::{axis_range, bounded, decimate, extent, tick_label};
use super::{
    Area, COLOURS, DrawError, FONT, LABEL_FONT, TITLE_FONT, WIDTH, fitted_caption, render,
};
use eom::Short;
use plotters::prelude::*;

/// Where the legend covers the fewest of the track's points and marks: a corner, or the
/// middle (inside a turning circle). A candidate's box is taken as 45 % of the width by 30 %
/// of the height; ties go to the first of upper right, upper left, lower right, lower left,
/// middle.
fn legend_place(
    points: &[(f64, f64)],
    marks: &[Mark],
    x_range: (f64, f64),
    y_range: (f64, f64),
) -> SeriesLabelPosition {
    let unit = |(x, y): (f64, f64)| {
        (
            (x - x_range.0) / (x_range.1 - x_range.0),
            (y - y_range.0) / (y_range.1 - y_range.0),
        )
    };
    let places = [
        (SeriesLabelPosition::UpperRight, (0.55, 0.7)),
        (SeriesLabelPosition::UpperLeft, (0.0, 0.7)),
        (SeriesLabelPosition::LowerRight, (0.55, 0.0)),
        (SeriesLabelPosition::LowerLeft, (0.0, 0.0)),
        (SeriesLabelPosition::MiddleMiddle, (0.275, 0.35)),
    ];
    let all: Vec<(f64, f64)> = points
        .iter()
        .copied()
        .chain(marks.iter().map(|m| m.point))
        .map(unit)
        .collect();
    let covered = |(x0, y0): (f64, f64)| {
        all.iter()
            .filter(|(x, y)| (x0..=x0 + 0.45).contains(x) && (y0..=y0 + 0.3).contains(y))
            .count()
    };
    let mut best = (usize::MAX, SeriesLabelPosition::UpperRight);
    for (place, corner) in places {
        let count = covered(corner);
        if count < best.0 {
            best = (count, place);
        }
    }
    best.1
}

/// The colour of a hull's outline.
const OUTLINE_GREY: RGBColor = RGBColor(110, 110, 110);

/// The chart builder of the track plot, the same for the layout pass and the drawing.
fn track_builder<'a, 'b>(
    area: &'a Area<'b>,
    caption: &str,
) -> ChartBuilder<'a, 'b, SVGBackend<'b>> {
    let (caption, size) = fitted_caption(caption, TITLE_FONT, area.dim_in_pixel().0);
    let mut builder = ChartBuilder::on(area);
    builder
        .caption(caption, (FONT, size))
        .margin(12)
        .x_label_area_size(52)
        .y_label_area_size(96);
    builder
}

/// Where a track of samples `x`, `y` stays, if it is one point to round-off (see
/// [`single_point`]); non-finite samples are left out, and a track with no finite one is
/// not one point.
pub(super) fn stays_at(x: &[f64], y: &[f64]) -> Option<(f64, f64)> {
    let points: Vec<(f64, f64)> = x
        .iter()
        .zip(y)
        .map(|(&x, &y)| (x, y))
        .filter(|p| p.0.is_finite() && p.1.is_finite())
        .collect();
    single_point(&points).then(|| points[0])
}

/// Whether the points (some) are one point to round-off: both spans within 10⁻⁹ of the
/// largest |coordinate|, or of 1 m.
fn single_point(points: &[(f64, f64)]) -> bool {
    let largest = points
        .iter()
        .fold(1.0f64, |m, p| m.max(p.0.abs()).max(p.1.abs()));
    let spans = (
        extent(points.iter().map(|p| p.0)),
        extent(points.iter().map(|p| p.1)),
    );
    match spans {
        (Some(x), Some(y)) => x.1 - x.0 <= 1e-9 * largest && y.1 - y.0 <= 1e-9 * largest,
        _ => false,
    }
}

/// A point marked on a track, with its legend entry.
pub struct Mark {
    /// The legend entry: what the point is, with its figure.
    pub label: String,
    /// Where, in the plot's (horizontal, vertical) coordinates.
    pub point: (f64, f64),
}

/// The track plot: the vertical coordinate against the horizontal with one scale on both axes
/// (a circle is drawn round), the start and the end marked, `marks` as crosses and `outlines`
/// (an outline drawn along the track, a hull's waterline) as thin grey lines under it, under
/// their legend entry.
pub(super) fn draw_track(
    svg: &mut String,
    caption: &str,
    (x_desc, y_desc): (&str, &str),
    (x, y): (&[f64], &[f64]),
    marks: &[Mark],
    (outline_label, outlines): (&str, &[Vec<(f64, f64)>]),
) -> Result<(), DrawError> {
    let size = (WIDTH, WIDTH);
    // The size of the plotting area does not depend on the ranges: lay out once on a scratch
    // string to learn it, then choose the ranges for equal scales.
    let (width, height) = {
        let mut scratch = String::new();
        let root = SVGBackend::with_string(&mut scratch, size).into_drawing_area();
        let chart = track_builder(&root, caption).build_cartesian_2d(0.0..1.0, 0.0..1.0)?;
        let (w, h) = chart.plotting_area().dim_in_pixel();
        (f64::from(w.max(1)), f64::from(h.max(1)))
    };
    let finite = |i: usize| x[i].is_finite() && y[i].is_finite();
    let points: Vec<(f64, f64)> = decimate(x.len(), (width + height) as usize, finite, &[x, y])
        .into_iter()
        .map(|i| (bounded(x[i]), bounded(y[i])))
        .collect();
    let outlines: Vec<Vec<(f64, f64)>> = outlines
        .iter()
        .map(|o| {
            o.iter()
                .filter(|p| p.0.is_finite() && p.1.is_finite())
                .map(|p| (bounded(p.0), bounded(p.1)))
                .collect()
        })
        .collect();
    let everything = || points.iter().chain(outlines.iter().flatten());
    let x_range = axis_range(extent(everything().map(|p| p.0)));
    let y_range = axis_range(extent(everything().map(|p| p.1)));
    let still = single_point(&points);
    let caption = match (still, points.first()) {
        (true, Some((x, y))) => format!(
            "{caption}: a single point throughout, ({}, {}) m",
            Short(*x),
            Short(*y)
        ),
        _ => caption.to_string(),
    };
    let caption = caption.as_str();
    let points = if still { Vec::new() } else { points };
    // One scale: the units per pixel of the axis that needs more, on both, centred.
    let per_pixel = ((x_range.1 - x_range.0) / width).max((y_range.1 - y_range.0) / height);
    let equal = |(lo, hi): (f64, f64), pixels: f64| {
        let (centre, half) = (lo / 2.0 + hi / 2.0, per_pixel * pixels / 2.0);
        (centre - half, centre + half)
    };
    let (x_range, y_range) = (equal(x_range, width), equal(y_range, height));
    let ticks = 8;
    let x_label = |v: &f64| tick_label(*v, x_range, ticks);
    let y_label = |v: &f64| tick_label(*v, y_range, ticks);

    render(svg, size, |root, overlay| {
        let mut chart = track_builder(root, caption)
            .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)?;
        chart
            .configure_mesh()
            .x_labels(ticks)
            .y_labels(ticks)
            .x_label_formatter(&x_label)
            .y_label_formatter(&y_label)
            .light_line_style(TRANSPARENT)
            .label_style((FONT, LABEL_FONT))
            .axis_desc_style((FONT, LABEL_FONT))
            .x_desc(x_desc)
            .y_desc(y_desc)
            .draw()?;
        let colour = COLOURS[0];
        let frame = PixelFrame::new(chart.plotting_area().get_pixel_range(), x_range, y_range);
        for outline in &outlines {
            overlay.line(root, outline.iter().map(|p| frame.at(*p)), OUTLINE_GREY, 1)?;
        }
        if !outlines.is_empty() {
            chart
                .draw_series(std::iter::empty::<PathElement<(f64, f64)>>())?
                .label(outline_label)
                .legend(|(x, y)| Rectangle::new([(x, y - 4), (x + 16, y + 4)], OUTLINE_GREY));
        }
        overlay.line(root, points.iter().map(|p| frame.at(*p)), colour, 2)?;
        chart
            .draw_series(std::iter::empty::<PathElement<(f64, f64)>>())?
            .label("track")
            .legend(move |(x, y)| Rectangle::new([(x, y - 1), (x + 16, y + 1)], colour.filled()));
        // The start a ring, the end a dot inside it: both show when the track closes.
        let ends = [
            ("start", points.first(), COLOURS[2].stroke_width(2), 7),
            ("end", points.last(), RGBColor(214, 39, 40).filled(), 4),
        ];
        for (name, point, style, radius) in ends {
            if let Some(&point) = point {
                chart
                    .draw_series([Circle::new(point, radius, style)])?
                    .label(name)
                    .legend(move |(x, y)| Circle::new((x + 8, y), radius.min(5), style));
            }
        }
        for (mark, colour) in marks.iter().zip(COLOURS.iter().cycle().skip(1)) {
            let style = colour.stroke_width(2);
            let point = (bounded(mark.point.0), bounded(mark.point.1));
            chart
                .draw_series([Cross::new(point, 8, style)])?
                .label(mark.label.as_str())
                .legend(move |(x, y)| Cross::new((x + 8, y), 5, style));
        }
        chart
            .configure_series_labels()
            .position(legend_place(&points, marks, x_range, y_range))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((FONT, LABEL_FONT))
            .draw()?;
        Ok(())
    })
}
