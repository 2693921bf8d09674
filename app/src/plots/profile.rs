//! The profile of a spatial body's track: its height −z against the horizontal distance it
//! has run, and the side view from the east (−z against x, north). The track plot is a plan
//! (y against x); a body that climbs, dives or falls moves in a third coordinate the plan
//! cannot show. The profile shows it along the path, however the path turns (which a side
//! view folds over); the side view shows it in space axes, where it happened.
//!
//! It is drawn when z varies by more than [`PROFILE_FRACTION`] of the horizontal extent (the
//! larger of the x and y spans), and by more than round-off (10⁻⁹ of the largest |z|, or of
//! 1 m): a body that stays in its horizontal plane has no profile worth a file.

use super::precise::{Overlay, PixelFrame};
use super::scale::{axis_range, bounded, decimate, extent, tick_label};
use super::{
    Area, COLOURS, DrawError, FONT, LABEL_FONT, TITLE_FONT, WIDTH, fitted_caption, render,
};
use plotters::prelude::*;

/// How much z must vary, as a fraction of the horizontal extent, for a profile to be drawn.
pub(super) const PROFILE_FRACTION: f64 = 0.01;

/// The span of the finite values, if any.
fn span(values: &[f64]) -> Option<f64> {
    extent(
        values
            .iter()
            .copied()
            .filter(|v| v.is_finite())
            .map(bounded),
    )
    .map(|(lo, hi)| hi - lo)
}

/// Whether the motion leaves the horizontal plane: z varies by more than
/// [`PROFILE_FRACTION`] of the larger of the x and y spans, and by more than round-off.
pub fn leaves_the_plane(x: &[f64], y: &[f64], z: &[f64]) -> bool {
    let Some(z_span) = span(z) else {
        return false;
    };
    let horizontal = span(x).unwrap_or(0.0).max(span(y).unwrap_or(0.0));
    let largest = z
        .iter()
        .filter(|v| v.is_finite())
        .fold(1.0f64, |m, v| m.max(bounded(*v).abs()));
    z_span > PROFILE_FRACTION * horizontal && z_span > 1e-9 * largest
}

/// The horizontal distance run to each sample: the sum of the steps √(Δx² + Δy²) between
/// finite samples (NaN where the sample is not finite).
pub(super) fn distance_run(x: &[f64], y: &[f64]) -> Vec<f64> {
    let mut run = 0.0;
    let mut last: Option<(f64, f64)> = None;
    x.iter()
        .zip(y)
        .map(|(&x, &y)| {
            if !(x.is_finite() && y.is_finite()) {
                return f64::NAN;
            }
            if let Some((lx, ly)) = last {
                run = bounded(run + (x - lx).hypot(y - ly));
            }
            last = Some((x, y));
            run
        })
        .collect()
}

/// The profile plot, in two panels: −z (up) against the horizontal distance run, and the side
/// view seen from the east, −z against X (north), so that a climb, a dive or a fall reads in
/// the run's own length and in space axes alike; the start a ring and the end a dot, each axis
/// to its own scale.
pub(super) fn draw_profile(
    svg: &mut String,
    title: &str,
    (x, y, z): (&[f64], &[f64], &[f64]),
) -> Result<(), DrawError> {
    let along = distance_run(x, y);
    let height: Vec<f64> = z.iter().map(|z| -z).collect();
    let panels = [
        Panel {
            caption: format!("{title}: profile, height against distance run"),
            along: &along,
            height: &height,
            x_desc: "horizontal distance run [m]",
        },
        Panel {
            caption: "side view from the east, height against north".to_owned(),
            along: x,
            height: &height,
            x_desc: "x, north [m]",
        },
    ];
    render(svg, (WIDTH, 2 * PANEL_HEIGHT), |root, overlay| {
        let areas = root.split_evenly((2, 1));
        for (area, panel) in areas.iter().zip(&panels) {
            draw_panel(area, overlay, panel)?;
        }
        Ok(())
    })
}

/// The height of each panel of the profile plot, px.
const PANEL_HEIGHT: u32 = 420;

/// One panel of the profile plot: the height against a horizontal coordinate.
struct Panel<'a> {
    caption: String,
    along: &'a [f64],
    height: &'a [f64],
    x_desc: &'static str,
}

fn draw_panel(area: &Area, overlay: &mut Overlay, panel: &Panel) -> Result<(), DrawError> {
    let (along, height) = (panel.along, panel.height);
    let finite = |i: usize| along[i].is_finite() && height[i].is_finite();
    let points: Vec<(f64, f64)> = decimate(along.len(), WIDTH as usize, finite, &[height])
        .into_iter()
        .map(|i| (bounded(along[i]), bounded(height[i])))
        .collect();
    let x_range = axis_range(extent(points.iter().map(|p| p.0)));
    let y_range = axis_range(extent(points.iter().map(|p| p.1)));
    let ticks = (8, 6);
    let x_label = |v: &f64| tick_label(*v, x_range, ticks.0);
    let y_label = |v: &f64| tick_label(*v, y_range, ticks.1);
    let (caption, size) = fitted_caption(&panel.caption, TITLE_FONT, area.dim_in_pixel().0);
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, size))
        .margin(12)
        .x_label_area_size(52)
        .y_label_area_size(84)
        .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)?;
    chart
        .configure_mesh()
        .x_labels(ticks.0)
        .y_labels(ticks.1)
        .x_label_formatter(&x_label)
        .y_label_formatter(&y_label)
        .light_line_style(TRANSPARENT)
        .label_style((FONT, LABEL_FONT))
        .axis_desc_style((FONT, LABEL_FONT))
        .x_desc(panel.x_desc)
        .y_desc("height −z [m]")
        .draw()?;
    let frame = PixelFrame::new(chart.plotting_area().get_pixel_range(), x_range, y_range);
    overlay.line(area, points.iter().map(|p| frame.at(*p)), COLOURS[0], 2)?;
    if let (Some(&first), Some(&last)) = (points.first(), points.last()) {
        chart.draw_series([
            Circle::new(first, 7, COLOURS[2].stroke_width(2)),
            Circle::new(last, 4, RGBColor(214, 39, 40).filled()),
        ])?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_profile_has_the_distance_run_and_the_side_view_from_the_east() {
        // A climb north then east: the side view sees the climb stop at x = 10, the profile
        // sees it go on along the path.
        let x: Vec<f64> = (0..=20).map(|i| f64::from(i.min(10))).collect();
        let y: Vec<f64> = (0..=20).map(|i| f64::from((i - 10).max(0))).collect();
        let z: Vec<f64> = (0..=20).map(|i| -f64::from(i)).collect();
        let mut svg = String::new();
        draw_profile(&mut svg, "climb", (&x, &y, &z)).unwrap();
        let document = roxmltree::Document::parse(&svg).unwrap();
        let texts: Vec<&str> = document.descendants().filter_map(|n| n.text()).collect();
        for caption in [
            "climb: profile, height against distance run",
            "side view from the east",
        ] {
            assert!(
                texts.iter().any(|t| t.contains(caption)),
                "{caption}: {texts:?}"
            );
        }
        assert!(texts.iter().any(|t| t.contains("x, north [m]")));
    }

    #[test]
    fn a_profile_is_drawn_only_where_z_varies() {
        let x: Vec<f64> = (0..100).map(f64::from).collect();
        let flat = vec![0.0; 100];
        // 1 % of 99 m is 0.99 m: a rise of 0.5 m is in the plane, one of 2 m is not.
        let low: Vec<f64> = (0..100).map(|i| -0.005 * f64::from(i)).collect();
        let high: Vec<f64> = (0..100).map(|i| -0.02 * f64::from(i)).collect();
        assert!(!leaves_the_plane(&x, &flat, &flat));
        assert!(!leaves_the_plane(&x, &flat, &low));
        assert!(leaves_the_plane(&x, &flat, &high));
        // Falling straight down from rest: no horizontal extent at all.
        assert!(leaves_the_plane(&flat, &flat, &high));
        // Round-off on a body at rest is not a profile; no samples are none either.
        let noise: Vec<f64> = (0..100).map(|i| 1e-15 * f64::from(i % 3)).collect();
        assert!(!leaves_the_plane(&flat, &flat, &noise));
        assert!(!leaves_the_plane(&[], &[], &[]));
        assert!(!leaves_the_plane(&[f64::NAN], &[0.0], &[f64::NAN]));
    }

    #[test]
    fn the_distance_run_adds_the_horizontal_steps() {
        let (x, y) = ([0.0, 3.0, f64::NAN, 3.0, 0.0], [0.0, 4.0, 1.0, 8.0, 8.0]);
        let run = distance_run(&x, &y);
        assert_eq!(run[..2], [0.0, 5.0]);
        assert!(run[2].is_nan());
        assert_eq!(run[3..], [9.0, 12.0]);
    }
}
