//! Lines at sub-pixel precision. plotters' SVG backend writes every coordinate as a whole
//! pixel, so a smooth curve comes out stair-stepped and zooming in shows the steps. The data
//! lines are therefore written here, with two decimals: plotters draws the chart (axes,
//! ticks, labels, legend), and where a line belongs in the drawing order it draws a
//! placeholder text with a unique marker; once the SVG is complete each placeholder is
//! replaced by the line's `<polyline>`. The axes map data to pixels as plotters does, without
//! its rounding down, so a line sits within a pixel of where plotters would have put it.

use super::{Area, DrawError, FONT};
use plotters::prelude::*;
use std::ops::Range;

/// Where a chart's plotting area lies, in pixels, and the axis ranges it shows.
pub(super) struct PixelFrame {
    x: (f64, f64),
    y: (f64, f64),
    left: f64,
    right: f64,
    bottom: f64,
    top: f64,
}

impl PixelFrame {
    /// The frame of a plotting area of `pixels` (as `get_pixel_range` gives it) showing `x` and
    /// `y`: plotters maps the range onto the first to the last pixel, y upwards.
    pub(super) fn new(pixels: (Range<i32>, Range<i32>), x: (f64, f64), y: (f64, f64)) -> Self {
        PixelFrame {
            x,
            y,
            left: f64::from(pixels.0.start),
            right: f64::from(pixels.0.end - 1),
            bottom: f64::from(pixels.1.end - 1),
            top: f64::from(pixels.1.start),
        }
    }

    /// A point in axis units to pixels.
    pub(super) fn at(&self, (x, y): (f64, f64)) -> (f64, f64) {
        let along = |v: f64, (lo, hi): (f64, f64), from: f64, to: f64| {
            if hi == lo {
                (from + to) / 2.0
            } else {
                from + (v - lo) / (hi - lo) * (to - from)
            }
        };
        (
            along(x, self.x, self.left, self.right),
            along(y, self.y, self.bottom, self.top),
        )
    }
}

/// The lines of one SVG, each waiting for its placeholder to be replaced.
#[derive(Default)]
pub(super) struct Overlay {
    lines: Vec<(String, String)>,
}

impl Overlay {
    /// Draws a placeholder for a line through `points` (pixels) onto `area`, and keeps the
    /// line.
    pub(super) fn line(
        &mut self,
        area: &Area,
        points: impl IntoIterator<Item = (f64, f64)>,
        colour: RGBColor,
        width: u32,
    ) -> Result<(), DrawError> {
        self.push(area, points, colour, width, "")
    }

    /// As [`line`](Self::line), dashed: `dash` pixels drawn, then as many left out.
    pub(super) fn dashed(
        &mut self,
        area: &Area,
        points: impl IntoIterator<Item = (f64, f64)>,
        (colour, width): (RGBColor, u32),
        dash: u32,
    ) -> Result<(), DrawError> {
        let pattern = format!(" stroke-dasharray=\"{dash} {dash}\"");
        self.push(area, points, colour, width, &pattern)
    }

    /// Draws the placeholder and keeps the line, with `extra` attributes.
    fn push(
        &mut self,
        area: &Area,
        points: impl IntoIterator<Item = (f64, f64)>,
        colour: RGBColor,
        width: u32,
        extra: &str,
    ) -> Result<(), DrawError> {
        // The closing "-end" keeps line 1's marker from matching line 10's.
        let marker = format!("eom-precise-line-{}-end", self.lines.len());
        area.draw(&Text::new(marker.clone(), (0, 0), (FONT, 1)))?;
        let mut coordinates = String::new();
        for (x, y) in points {
            coordinates.push_str(&format!("{x:.2},{y:.2} "));
        }
        let RGBColor(r, g, b) = colour;
        let element = format!(
            "<polyline fill=\"none\" stroke=\"#{r:02X}{g:02X}{b:02X}\" stroke-width=\"{width}\"{extra} \
             stroke-linejoin=\"round\" points=\"{}\"/>",
            coordinates.trim_end()
        );
        self.lines.push((marker, element));
        Ok(())
    }

    /// Replaces each placeholder in the finished `svg` with its line.
    pub(super) fn splice(self, svg: &mut String) {
        for (marker, element) in self.lines {
            // plotters writes the text element around its content on lines of their own.
            let Some(at) = svg.find(&marker) else {
                continue;
            };
            let (Some(start), Some(close)) = (svg[..at].rfind("<text"), svg[at..].find("</text>"))
            else {
                continue;
            };
            svg.replace_range(start..at + close + "</text>".len(), &element);
        }
    }
}
