//! The SVG plots of a run: the state's time series, the attitude, the track and the energy
//! drift, drawn with plotters' SVG backend from columns sampled at the same times.
//!
//! Three choices shape this module:
//!
//! - **Decimation.** A run may keep 10⁶ samples, far more than a plot has pixels. Each series
//!   is cut into windows of consecutive samples, as many as its panel is pixels wide, and
//!   only the first, last, smallest and largest sample of each window are drawn, in their
//!   order. For evenly spaced samples a window is a pixel column, so the line covers the
//!   pixels the full series would: a one-sample spike stays visible, and a file stays small
//!   (tens to a few hundred kilobytes) however long the run, and is drawn in a fraction of a
//!   second. The track keeps the extremes of both x and y in each window, and always its
//!   first and last point.
//! - **No fonts.** plotters is built without its `ttf` and `ab_glyph` features, so it loads
//!   no font and links no system font library (none is needed on a machine without
//!   fontconfig). With the SVG backend text does not need one: a title, an axis label or a
//!   tick label is written as an SVG `<text>` element with `font-family="sans-serif"`, and the
//!   viewer draws it with its own fonts. plotters only estimates the width of a text to lay
//!   out the labels (0.7 em per byte), which is why the label areas here are sized with room
//!   to spare.
//! - **Atomic writes.** A plot is drawn into memory, written to a temporary file beside its
//!   target in the same folder, synced, and renamed over the target. A reader (or a crash)
//!   never sees a half-written file, and a failed write removes its temporary file.
//!
//! The plots: `state.svg` has one small panel per state component, titled with its name,
//! over one time range (stacked for up to four components, else three to a row);
//! `attitude.svg` has roll, pitch and yaw on one panel with a legend; `track.svg` has y
//! against x at one scale on both axes, the start a ring and the end a dot; `energy.svg` has
//! the relative drift on a symmetric logarithmic axis, `sign(d)·log₁₀(1 + |d|/10⁻¹⁶)`: linear
//! through zero within round-off, a decade per unit above it, so that a drift of 10⁻¹⁴
//! and one of 10⁻³ both read on the same axis, with their sign.
//!
//! Non-finite values (NaN, ±∞) are skipped: a sample whose time or value is not finite is not
//! drawn, and the line joins its finite neighbours across it; the axis ranges are taken from
//! the finite values only. A series with no finite value draws an empty panel. Values beyond
//! ±10³⁰⁰ are drawn at that bound, so that an axis range stays finite.
//!
//! The output is deterministic: the same input gives the same bytes (the SVG holds no
//! timestamp, and pixel coordinates are integers).

use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use plotters::coord::Shift;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, KeyPointWeight};
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use thiserror::Error;

pub mod ship;

/// What a run hands to the plots: columns sampled at the same times.
///
/// Every column has one value per entry of [`time`](Self::time); a column of another length
/// is an error ([`PlotError::Length`]).
pub struct PlotInput<'a> {
    /// The scene's title, for the plot titles.
    pub title: &'a str,
    /// The sample times, ascending.
    pub time: &'a [f64],
    /// Every state component, named as in trajectory.csv (`u`, `theta_dot`, `q0`, …).
    pub state: Vec<(&'a str, &'a [f64])>,
    /// Roll, pitch and yaw in degrees, where the model has an attitude.
    pub attitude_deg: Option<[&'a [f64]; 3]>,
    /// The track (x, y) in space axes, where the model has a position in the plane.
    pub track: Option<(&'a [f64], &'a [f64])>,
    /// The relative energy drift (E − E₀)/|E₀| at each time, where the run has an energy.
    pub energy_drift: Option<&'a [f64]>,
}

/// Why a plot could not be drawn or written: each variant names the file.
#[derive(Debug, Error)]
pub enum PlotError {
    /// A column's length differs from the number of sample times.
    #[error("{}: column {column} has {len} values, but there are {times} sample times", .file.display())]
    Length {
        /// The plot the column belongs to.
        file: PathBuf,
        /// The column, e.g. `"q0"`, `"roll"`, `"track x"`, `"energy drift"`.
        column: String,
        /// Its length.
        len: usize,
        /// The number of sample times.
        times: usize,
    },
    /// plotters could not draw the plot.
    #[error("{}: could not draw the plot: {source}", .file.display())]
    Draw {
        /// The plot.
        file: PathBuf,
        /// What plotters reported.
        #[source]
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// The plot could not be written to its temporary file or renamed over the target.
    #[error("{}: could not write the plot: {source}", .file.display())]
    Write {
        /// The plot.
        file: PathBuf,
        /// The failed file operation.
        #[source]
        source: io::Error,
    },
}

/// The file of the state plot.
const STATE: &str = "state.svg";
/// The file of the attitude plot.
const ATTITUDE: &str = "attitude.svg";
/// The file of the track plot.
const TRACK: &str = "track.svg";
/// The file of the energy drift plot.
const ENERGY: &str = "energy.svg";

/// Draws every plot the input has data for into `dir` and returns the files written:
/// `state.svg`, `attitude.svg`, `track.svg`, `energy.svg`.
///
/// `state.svg` is written when the input has a state component, the others when their
/// `Option` is `Some`; each replaces a file of the same name. `dir` must exist. Every column's
/// length is checked before anything is drawn, so a malformed input writes no file.
pub fn write_plots(dir: &Path, input: &PlotInput) -> Result<Vec<PathBuf>, PlotError> {
    check_lengths(dir, input)?;
    let mut written = Vec::new();
    if !input.state.is_empty() {
        written.push(emit(dir, STATE, |svg| draw_state(svg, input))?);
    }
    if let Some(angles) = input.attitude_deg {
        written.push(emit(dir, ATTITUDE, |svg| {
            draw_attitude(svg, input.title, input.time, angles)
        })?);
    }
    if let Some((x, y)) = input.track {
        let caption = format!("{}: track in space axes", input.title);
        let axes = ("x [m]", "y [m]");
        written.push(emit(dir, TRACK, |svg| {
            draw_track(svg, &caption, axes, (x, y), &[])
        })?);
    }
    if let Some(drift) = input.energy_drift {
        written.push(emit(dir, ENERGY, |svg| {
            draw_energy(svg, input.title, input.time, drift)
        })?);
    }
    Ok(written)
}

/// Checks that every column has one value per sample time.
fn check_lengths(dir: &Path, input: &PlotInput) -> Result<(), PlotError> {
    let times = input.time.len();
    let mut columns: Vec<(&str, String, usize)> = input
        .state
        .iter()
        .map(|(name, values)| (STATE, name.to_string(), values.len()))
        .collect();
    if let Some(angles) = input.attitude_deg {
        for (name, values) in ["roll", "pitch", "yaw"].into_iter().zip(angles) {
            columns.push((ATTITUDE, name.to_string(), values.len()));
        }
    }
    if let Some((x, y)) = input.track {
        columns.push((TRACK, "track x".to_string(), x.len()));
        columns.push((TRACK, "track y".to_string(), y.len()));
    }
    if let Some(drift) = input.energy_drift {
        columns.push((ENERGY, "energy drift".to_string(), drift.len()));
    }
    match columns.into_iter().find(|(_, _, len)| *len != times) {
        Some((file, column, len)) => Err(PlotError::Length {
            file: dir.join(file),
            column,
            len,
            times,
        }),
        None => Ok(()),
    }
}

/// A drawing area of the SVG backend, drawing into a string.
type Area<'b> = DrawingArea<SVGBackend<'b>, Shift>;
/// What drawing on an [`Area`] can fail with.
type DrawError = DrawingAreaErrorKind<io::Error>;

/// Draws one plot with `draw` and writes it atomically to `dir/name`.
fn emit(
    dir: &Path,
    name: &str,
    draw: impl FnOnce(&mut String) -> Result<(), DrawError>,
) -> Result<PathBuf, PlotError> {
    let file = dir.join(name);
    let mut svg = String::new();
    if let Err(e) = draw(&mut svg) {
        return Err(PlotError::Draw {
            file,
            source: Box::new(e),
        });
    }
    match write_atomically(dir, name, svg.as_bytes()) {
        Ok(()) => Ok(file),
        Err(source) => Err(PlotError::Write { file, source }),
    }
}

/// Writes `bytes` to a temporary file in `dir`, syncs it and renames it to `dir/name`; on
/// failure removes the temporary file.
fn write_atomically(dir: &Path, name: &str, bytes: &[u8]) -> io::Result<()> {
    // Unique among processes (the id) and among calls in this process (the counter), so two
    // runs writing into one folder do not share a temporary file.
    static CALLS: AtomicU64 = AtomicU64::new(0);
    let call = CALLS.fetch_add(1, Ordering::Relaxed);
    let temporary = dir.join(format!(".{name}.{}-{call}.tmp", std::process::id()));
    let result = File::options()
        .write(true)
        .create_new(true)
        .open(&temporary)
        .and_then(|mut file| {
            file.write_all(bytes)?;
            file.sync_all()
        })
        .and_then(|()| fs::rename(&temporary, dir.join(name)));
    if result.is_err() {
        // The temporary file may not exist (creating it failed); there is nothing to report.
        let _ = fs::remove_file(&temporary);
    }
    result
}

/// Draws onto an SVG of `size` pixels with a white background, into `svg`.
fn render(
    svg: &mut String,
    size: (u32, u32),
    draw: impl FnOnce(&Area) -> Result<(), DrawError>,
) -> Result<(), DrawError> {
    let root = SVGBackend::with_string(svg, size).into_drawing_area();
    root.fill(&WHITE)?;
    draw(&root)?;
    root.present()
}

/// The indices of the samples to draw out of `len`, in order: all of them if there are few,
/// else, in each of `windows` runs of consecutive samples, the first, the last and, for each
/// column of `extremes`, the smallest and the largest. Samples that `finite` rejects are
/// never kept. At most `(2 + 2·extremes.len())·windows` indices come back, in one pass.
fn decimate(
    len: usize,
    windows: usize,
    finite: impl Fn(usize) -> bool,
    extremes: &[&[f64]],
) -> Vec<usize> {
    let windows = windows.max(1);
    let per_window = 2 + 2 * extremes.len();
    if len <= per_window * windows {
        return (0..len).filter(|&i| finite(i)).collect();
    }
    let mut kept = Vec::with_capacity(per_window * windows);
    let mut chosen = Vec::with_capacity(per_window);
    for w in 0..windows {
        let (start, end) = (w * len / windows, (w + 1) * len / windows);
        let Some(first) = (start..end).find(|&i| finite(i)) else {
            continue;
        };
        let last = (first..end).rev().find(|&i| finite(i)).unwrap_or(first);
        chosen.clear();
        chosen.extend([first, last]);
        for column in extremes {
            let (mut low, mut high) = (first, first);
            for i in first + 1..=last {
                if finite(i) {
                    if column[i] < column[low] {
                        low = i;
                    }
                    if column[i] > column[high] {
                        high = i;
                    }
                }
            }
            chosen.extend([low, high]);
        }
        chosen.sort_unstable();
        chosen.dedup();
        kept.extend_from_slice(&chosen);
    }
    kept
}

/// The largest magnitude drawn: beyond it a value is drawn at it, so that an axis range and
/// its width stay finite.
const HUGE: f64 = 1e300;

/// Clamps a finite value to ±[`HUGE`].
fn bounded(v: f64) -> f64 {
    v.clamp(-HUGE, HUGE)
}

/// The smallest and largest of the values, if any.
fn extent(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    values.into_iter().fold(None, |range, v| match range {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    })
}

/// An axis range around `extent` with a margin of 5 % each side; a range narrower than
/// 10⁻⁸ of its magnitude (a constant, or round-off on a constant) is widened to that, so that
/// the tick labels tell their ticks apart in ten digits; no extent gives [−1, 1].
fn axis_range(extent: Option<(f64, f64)>) -> (f64, f64) {
    let Some((lo, hi)) = extent else {
        return (-1.0, 1.0);
    };
    let magnitude = lo.abs().max(hi.abs());
    if magnitude == 0.0 {
        return (-1.0, 1.0);
    }
    let centre = lo / 2.0 + hi / 2.0;
    let half = (hi / 2.0 - lo / 2.0).max(magnitude * 0.5e-8);
    (centre - 1.05 * half, centre + 1.05 * half)
}

/// The tick label of `v` on an axis over `range` with about `ticks` ticks: fixed-point with
/// as many decimals as the tick spacing needs, or, on an axis reaching 10⁵ or staying below
/// 10⁻³, scientific with as many digits as the spacing needs at the value's own exponent.
fn tick_label(v: f64, range: (f64, f64), ticks: usize) -> String {
    let step = (range.1 - range.0) / ticks.max(1) as f64;
    if v.abs() < step * 1e-6 {
        return "0".to_string();
    }
    let step_exponent = step.log10().floor() as i32;
    let magnitude = range.0.abs().max(range.1.abs());
    if !(1e-3..1e5).contains(&magnitude) {
        let digits = (v.abs().log10().floor() as i32 - step_exponent).clamp(0, 12) as usize;
        format!("{v:.digits$e}")
    } else {
        let decimals = (-step_exponent).clamp(0, 12) as usize;
        format!("{v:.decimals$}")
    }
}

/// The colours of the lines, in order (colour-blind safe, from the Tableau 10 palette).
const COLOURS: [RGBColor; 3] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
];

/// The font of every text: resolved by the viewer, no font file is loaded.
const FONT: &str = "sans-serif";

/// One line of a time-series panel.
struct Line<'a> {
    /// Its name, for the legend.
    name: &'a str,
    /// Its values, one per sample time.
    values: &'a [f64],
    /// Its colour.
    colour: RGBColor,
}

/// How a time-series panel is laid out.
struct PanelStyle<'a> {
    /// The caption above the panel.
    caption: &'a str,
    /// The caption's font size.
    caption_size: u32,
    /// The label of the value axis.
    y_desc: &'a str,
    /// Whether to label the time axis (only the bottom panels of a grid do).
    time_desc: bool,
    /// About how many ticks on the time axis.
    time_ticks: usize,
    /// Whether to draw a legend of the lines' names.
    legend: bool,
}

/// Draws the lines against `time` onto `area`, over the time range `time_range`.
fn time_panel(
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
fn time_range(time: &[f64]) -> (f64, f64) {
    axis_range(extent(
        time.iter().copied().filter(|t| t.is_finite()).map(bounded),
    ))
}

/// The state plot: one small panel per component, titled with its name, all over the same
/// time range. Up to four components are stacked in one column; more are laid out three to a
/// row, so that the spatial states (u v w / p q r / x y z / angles or quaternion) fall into
/// rows of three.
fn draw_state(svg: &mut String, input: &PlotInput) -> Result<(), DrawError> {
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
fn draw_attitude(
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

/// The chart builder of the track plot, the same for the layout pass and the drawing.
fn track_builder<'a, 'b>(
    area: &'a Area<'b>,
    caption: &str,
) -> ChartBuilder<'a, 'b, SVGBackend<'b>> {
    let mut builder = ChartBuilder::on(area);
    builder
        .caption(caption, (FONT, 22))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(88);
    builder
}

/// A point marked on a track, with its legend entry.
pub struct Mark {
    /// The legend entry: what the point is, with its figure.
    pub label: String,
    /// Where, in the plot's (horizontal, vertical) coordinates.
    pub point: (f64, f64),
}

/// The track plot: the vertical coordinate against the horizontal with one scale on both axes
/// (a circle is drawn round), the start and the end marked, and `marks` as crosses.
fn draw_track(
    svg: &mut String,
    caption: &str,
    (x_desc, y_desc): (&str, &str),
    (x, y): (&[f64], &[f64]),
    marks: &[Mark],
) -> Result<(), DrawError> {
    let size = (900, 900);
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
    let x_range = axis_range(extent(points.iter().map(|p| p.0)));
    let y_range = axis_range(extent(points.iter().map(|p| p.1)));
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

    render(svg, size, |root| {
        let mut chart = track_builder(root, caption)
            .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)?;
        chart
            .configure_mesh()
            .x_labels(ticks)
            .y_labels(ticks)
            .x_label_formatter(&x_label)
            .y_label_formatter(&y_label)
            .light_line_style(TRANSPARENT)
            .label_style((FONT, 12))
            .x_desc(x_desc)
            .y_desc(y_desc)
            .draw()?;
        let colour = COLOURS[0];
        chart
            .draw_series(LineSeries::new(
                points.iter().copied(),
                colour.stroke_width(1),
            ))?
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
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((FONT, 13))
            .draw()?;
        Ok(())
    })
}

/// Below this magnitude the energy axis is linear, above it logarithmic: a few units of
/// double-precision round-off, under which a relative drift means nothing.
const LINEAR_BELOW: f64 = 1e-16;

/// The symmetric logarithm of a drift: `sign(d)·log₁₀(1 + |d|/c)` with `c` =
/// [`LINEAR_BELOW`]. Linear through zero, a decade per unit above `c`: drifts of 10⁻¹⁴ and of
/// 10⁻³ are both told apart from zero and from each other, with either sign.
fn symlog(d: f64) -> f64 {
    d.signum() * (d.abs() / LINEAR_BELOW).ln_1p() / std::f64::consts::LN_10
}

/// The inverse of [`symlog`].
fn symexp(s: f64) -> f64 {
    s.signum() * LINEAR_BELOW * (s.abs() * std::f64::consts::LN_10).exp_m1()
}

/// The energy axis: drifts placed by their [`symlog`] between `low` and `high` (in symlog
/// units), ticked at zero and at the decades ±10ᵏ inside it.
#[derive(Clone)]
struct SymlogAxis {
    /// The bottom of the axis, in symlog units.
    low: f64,
    /// The top of the axis, in symlog units.
    high: f64,
}

impl Ranged for SymlogAxis {
    // The labels come from the chart's formatter ([`decade_label`]).
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, drift: &f64, limit: (i32, i32)) -> i32 {
        RangedCoordf64::from(self.low..self.high).map(&symlog(*drift), limit)
    }

    /// Zero and the decades ±10ᵏ inside the axis, every second or third decade when there
    /// would be more than sixteen; no light points (no minor grid).
    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if let KeyPointWeight::Any = hint.weight() {
            return Vec::new();
        }
        let top = symexp(self.low.abs().max(self.high.abs()));
        // Up to 10³⁰⁸, the largest finite decade (a drift past it is drawn at the top).
        let lowest = LINEAR_BELOW.log10().round() as i32;
        let highest = (top.log10().floor().min(308.0) as i32).max(lowest);
        let inside = |d: &f64| (self.low..=self.high).contains(&symlog(*d));
        let decades: Vec<(i32, f64)> = (lowest..=highest)
            .flat_map(|k| [(k, -10f64.powi(k)), (k, 10f64.powi(k))])
            .filter(|(_, d)| inside(d))
            .collect();
        // At most sixteen decades in all (of either sign), counted down from the top one.
        let stride = decades.len().saturating_sub(1) as i32 / 16 + 1;
        let mut ticks = vec![0.0];
        ticks.extend(
            decades
                .into_iter()
                .filter(|(k, _)| (highest - k) % stride == 0)
                .map(|(_, d)| d),
        );
        ticks.sort_by(f64::total_cmp);
        ticks
    }

    fn range(&self) -> std::ops::Range<f64> {
        symexp(self.low)..symexp(self.high)
    }
}

/// The label of an energy-axis tick: the decade, to one significant digit.
fn decade_label(d: f64) -> String {
    if d == 0.0 {
        "0".to_string()
    } else {
        format!("{d:.0e}")
    }
}

/// The energy plot: the relative drift on a symmetric logarithmic axis ([`symlog`]).
fn draw_energy(
    svg: &mut String,
    title: &str,
    time: &[f64],
    drift: &[f64],
) -> Result<(), DrawError> {
    let size = (1000, 500);
    let time_range = time_range(time);
    let largest = drift
        .iter()
        .filter(|d| d.is_finite())
        .fold(0.0f64, |m, d| m.max(d.abs()));
    let caption = format!("{title}: relative energy drift, largest |ΔE/E₀| = {largest:.1e}");
    render(svg, size, |root| {
        let windows = size.0 as usize;
        let finite = |i: usize| time[i].is_finite() && drift[i].is_finite();
        let points: Vec<(f64, f64)> = decimate(time.len(), windows, finite, &[drift])
            .into_iter()
            .map(|i| (bounded(time[i]), drift[i]))
            .collect();
        // The range holds zero, so that the sign of a drift reads at a glance.
        let range = extent(points.iter().map(|p| symlog(p.1)).chain([0.0]));
        let range = match range {
            Some((lo, hi)) if hi - lo > 0.0 => {
                let pad = 0.05 * (hi - lo);
                (lo - pad, hi + pad)
            }
            _ => (-1.0, 1.0),
        };
        let time_ticks = 10;
        let x_label = |v: &f64| tick_label(*v, time_range, time_ticks);
        let y_label = |d: &f64| decade_label(*d);
        let mut chart = ChartBuilder::on(root)
            .caption(&caption, (FONT, 22))
            .margin(12)
            .x_label_area_size(44)
            .y_label_area_size(96)
            .build_cartesian_2d(
                time_range.0..time_range.1,
                SymlogAxis {
                    low: range.0,
                    high: range.1,
                },
            )?;
        chart
            .configure_mesh()
            .x_labels(time_ticks)
            .x_label_formatter(&x_label)
            .y_label_formatter(&y_label)
            .light_line_style(TRANSPARENT)
            .label_style((FONT, 12))
            .x_desc("t [s]")
            .y_desc("(E − E₀)/|E₀|, symmetric log, linear below 1e-16")
            .draw()?;
        chart.draw_series(LineSeries::new(points, COLOURS[0].stroke_width(1)))?;
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;
    use std::time::Instant;

    /// A fresh, empty folder for one test, removed with everything in it when dropped.
    struct Folder(PathBuf);

    impl Folder {
        fn new(test: &str) -> Self {
            let path =
                std::env::temp_dir().join(format!("eom-plots-{test}-{}", std::process::id()));
            let _ = fs::remove_dir_all(&path);
            fs::create_dir_all(&path).unwrap();
            Folder(path)
        }

        /// The names of the files in the folder, sorted.
        fn names(&self) -> Vec<String> {
            let mut names: Vec<String> = fs::read_dir(&self.0)
                .unwrap()
                .map(|e| e.unwrap().file_name().into_string().unwrap())
                .collect();
            names.sort();
            names
        }
    }

    impl Drop for Folder {
        fn drop(&mut self) {
            let _ = fs::remove_dir_all(&self.0);
        }
    }

    /// The names of a spatial quaternion state, as in trajectory.csv.
    const SPATIAL: [&str; 13] = [
        "u", "v", "w", "p", "q", "r", "x", "y", "z", "q0", "q1", "q2", "q3",
    ];

    /// Owned columns of a synthetic run, sampled every 1 ms.
    struct Run {
        time: Vec<f64>,
        state: Vec<(&'static str, Vec<f64>)>,
        attitude: [Vec<f64>; 3],
        x: Vec<f64>,
        y: Vec<f64>,
        drift: Vec<f64>,
    }

    impl Run {
        /// A quaternion-like 13-state of `n` samples: a body turning steadily about z while
        /// it rolls like a pendulum, on a circle of radius 50 m; its energy drifts linearly
        /// to 10⁻³ with round-off of ±10⁻¹⁴ on top.
        fn spatial(n: usize) -> Run {
            let time: Vec<f64> = (0..n).map(|i| i as f64 * 1e-3).collect();
            let turn = |t: f64| TAU * t / 20.0;
            let roll = |t: f64| 0.3 * (TAU * t / 2.0).sin();
            let column = |f: &dyn Fn(f64) -> f64| time.iter().map(|&t| f(t)).collect::<Vec<_>>();
            let state = SPATIAL
                .iter()
                .map(|&name| {
                    let values = match name {
                        "u" => column(&|_| 5.0 * TAU / 20.0 * 10.0),
                        "v" | "w" | "z" => column(&|_| 0.0),
                        "p" => column(&|t| 0.3 * TAU / 2.0 * (TAU * t / 2.0).cos()),
                        "q" => column(&|t| 1e-3 * (t * 7.0).sin()),
                        "r" => column(&|_| TAU / 20.0),
                        "x" => column(&|t| 50.0 * turn(t).cos()),
                        "y" => column(&|t| 50.0 * turn(t).sin()),
                        "q0" => column(&|t| (roll(t) / 2.0).cos() * (turn(t) / 2.0).cos()),
                        "q1" => column(&|t| (roll(t) / 2.0).sin() * (turn(t) / 2.0).cos()),
                        "q2" => column(&|t| -(roll(t) / 2.0).sin() * (turn(t) / 2.0).sin()),
                        _ => column(&|t| (roll(t) / 2.0).cos() * (turn(t) / 2.0).sin()),
                    };
                    (name, values)
                })
                .collect();
            let end = time.last().copied().unwrap_or(1.0).max(1e-3);
            Run {
                attitude: [
                    column(&|t| roll(t).to_degrees()),
                    column(&|t| 2.0 * (t * 0.5).sin()),
                    column(&|t| (turn(t).to_degrees() + 180.0).rem_euclid(360.0) - 180.0),
                ],
                x: column(&|t| 50.0 * turn(t).cos()),
                y: column(&|t| 50.0 * turn(t).sin()),
                drift: column(&|t| 1e-3 * t / end + 1e-14 * (t * 1e3).sin()),
                state,
                time,
            }
        }

        /// A pendulum: two states, θ a sine of 20° amplitude and its rate; its energy kept
        /// to round-off (drifts of 10⁻¹⁵ to 10⁻¹⁴ of either sign).
        fn pendulum(n: usize) -> Run {
            let time: Vec<f64> = (0..n).map(|i| i as f64 * 1e-3).collect();
            let w = TAU / 2.0;
            let theta = time.iter().map(|t| 0.35 * (w * t).sin()).collect();
            let rate = time.iter().map(|t| 0.35 * w * (w * t).cos()).collect();
            let drift = time.iter().map(|t| 1e-14 * (3.0 * t).sin()).collect();
            Run {
                state: vec![("theta", theta), ("theta_dot", rate)],
                attitude: [vec![], vec![], vec![]],
                x: vec![],
                y: vec![],
                drift,
                time,
            }
        }

        fn input(&self, title: &'static str, spatial: bool) -> PlotInput<'_> {
            PlotInput {
                title,
                time: &self.time,
                state: self.state.iter().map(|(n, v)| (*n, v.as_slice())).collect(),
                attitude_deg: spatial.then(|| {
                    [
                        &self.attitude[0][..],
                        &self.attitude[1][..],
                        &self.attitude[2][..],
                    ]
                }),
                track: spatial.then(|| (&self.x[..], &self.y[..])),
                energy_drift: Some(&self.drift),
            }
        }
    }

    /// A written SVG, parsed.
    struct Svg {
        text: String,
    }

    impl Svg {
        fn read(path: &Path) -> Svg {
            let text = fs::read_to_string(path).unwrap();
            roxmltree::Document::parse(&text)
                .unwrap_or_else(|e| panic!("{} is not XML: {e}", path.display()));
            Svg { text }
        }

        /// The elements named `tag`, mapped by `f`.
        fn elements<T>(&self, tag: &str, f: impl Fn(roxmltree::Node) -> T) -> Vec<T> {
            let doc = roxmltree::Document::parse(&self.text).unwrap();
            doc.descendants()
                .filter(|n| n.tag_name().name() == tag)
                .map(f)
                .collect()
        }

        /// The polylines of the data: plotters draws axes, ticks and grid lines as polylines
        /// of two points, and every line series as one polyline of more.
        fn series(&self) -> Vec<Vec<(i32, i32)>> {
            self.elements("polyline", |n| {
                n.attribute("points")
                    .unwrap()
                    .split_whitespace()
                    .map(|p| {
                        let (x, y) = p.split_once(',').unwrap();
                        (x.parse().unwrap(), y.parse().unwrap())
                    })
                    .collect::<Vec<_>>()
            })
            .into_iter()
            .filter(|p| p.len() > 2)
            .collect()
        }

        /// Every text, trimmed.
        fn texts(&self) -> Vec<String> {
            self.elements("text", |n| n.text().unwrap_or("").trim().to_string())
        }
    }

    #[test]
    fn writes_the_four_plots_with_their_series_and_titles() {
        let folder = Folder::new("four");
        let run = Run::spatial(100_000);
        let written = write_plots(&folder.0, &run.input("tennis racket", true)).unwrap();
        let names = ["attitude.svg", "energy.svg", "state.svg", "track.svg"];
        assert_eq!(
            written,
            ["state.svg", "attitude.svg", "track.svg", "energy.svg"].map(|n| folder.0.join(n))
        );
        // Only the plots are left: no temporary file.
        assert_eq!(folder.names(), names);

        let state = Svg::read(&folder.0.join("state.svg"));
        assert_eq!(state.series().len(), 13);
        let texts = state.texts();
        assert!(
            texts.contains(&"tennis racket: state".to_string()),
            "{texts:?}"
        );
        for name in SPATIAL {
            assert!(texts.contains(&name.to_string()), "no panel titled {name}");
        }

        let attitude = Svg::read(&folder.0.join("attitude.svg"));
        assert_eq!(attitude.series().len(), 3);
        let texts = attitude.texts();
        for text in [
            "tennis racket: attitude (Euler angles)",
            "roll φ",
            "pitch θ",
            "yaw ψ",
        ] {
            assert!(texts.contains(&text.to_string()), "no {text} in {texts:?}");
        }

        let track = Svg::read(&folder.0.join("track.svg"));
        assert_eq!(track.series().len(), 1);
        // The start and the end, each on the plot and in the legend.
        assert_eq!(track.elements("circle", |_| ()).len(), 4);
        let texts = track.texts();
        for text in [
            "tennis racket: track in space axes",
            "track",
            "start",
            "end",
        ] {
            assert!(texts.contains(&text.to_string()), "no {text} in {texts:?}");
        }

        let energy = Svg::read(&folder.0.join("energy.svg"));
        assert_eq!(energy.series().len(), 1);
        let texts = energy.texts();
        assert!(
            texts
                .iter()
                .any(|t| t.starts_with("tennis racket: relative energy drift")),
            "{texts:?}"
        );
        // The symmetric log axis: zero, a decade of round-off and the drift's decade.
        for tick in ["0", "1e-14", "1e-3"] {
            assert!(
                texts.contains(&tick.to_string()),
                "no tick {tick} in {texts:?}"
            );
        }
    }

    #[test]
    fn a_circle_track_is_drawn_round() {
        let folder = Folder::new("round");
        let run = Run::spatial(20_001);
        write_plots(&folder.0, &run.input("circle", true)).unwrap();
        let track = &Svg::read(&folder.0.join("track.svg")).series()[0];
        let (xs, ys): (Vec<i32>, Vec<i32>) = track.iter().copied().unzip();
        let width = xs.iter().max().unwrap() - xs.iter().min().unwrap();
        let height = ys.iter().max().unwrap() - ys.iter().min().unwrap();
        assert!(width > 500, "the circle fills the plot: {width} px");
        assert!((width - height).abs() <= 2, "{width} × {height} px");
    }

    #[test]
    fn a_pendulum_is_stacked_in_one_column() {
        let folder = Folder::new("pendulum");
        let run = Run::pendulum(10_000);
        let written = write_plots(&folder.0, &run.input("pendulum", false)).unwrap();
        assert_eq!(
            written,
            [folder.0.join("state.svg"), folder.0.join("energy.svg")]
        );
        let state = Svg::read(&folder.0.join("state.svg"));
        let series = state.series();
        assert_eq!(series.len(), 2);
        // One above the other, over the same time axis.
        let (top, bottom) = (&series[0], &series[1]);
        assert_eq!(top[0].0, bottom[0].0);
        assert!(top.iter().map(|p| p.1).max() < bottom.iter().map(|p| p.1).min());
        // Drifts of 10⁻¹⁴ either side of zero show.
        let texts = Svg::read(&folder.0.join("energy.svg")).texts();
        for tick in ["1e-14", "-1e-14"] {
            assert!(
                texts.contains(&tick.to_string()),
                "no tick {tick} in {texts:?}"
            );
        }
    }

    #[test]
    fn a_million_samples_make_small_files_quickly() {
        let folder = Folder::new("million");
        let run = Run::spatial(1_000_000);
        let start = Instant::now();
        let written = write_plots(&folder.0, &run.input("a long run", true)).unwrap();
        let seconds = start.elapsed().as_secs_f64();
        for (path, lines) in written.iter().zip([13, 3, 1, 1]) {
            let bytes = fs::metadata(path).unwrap().len();
            println!("{}: {bytes} bytes", path.display());
            assert!(bytes < 1_000_000, "{}: {bytes} bytes", path.display());
            // Still every series, each decimated to a few thousand points.
            let series = Svg::read(path).series();
            assert_eq!(series.len(), lines, "{}", path.display());
            assert!(
                series.iter().all(|s| s.len() <= 6_000),
                "{}",
                path.display()
            );
        }
        println!("drawing 4 plots of 1e6 samples: {seconds:.3} s");
        assert_eq!(written.len(), 4);
    }

    #[test]
    fn non_finite_values_are_skipped() {
        let folder = Folder::new("nan");
        let mut run = Run::spatial(5_000);
        run.time[10] = f64::NAN;
        run.state[0].1[100] = f64::NAN;
        run.state[1].1[200] = f64::INFINITY;
        run.state[2].1.fill(f64::NAN);
        run.state[3].1[300] = f64::MAX;
        run.attitude[0][0] = f64::NEG_INFINITY;
        run.x[4_999] = f64::NAN;
        run.drift.fill(f64::NAN);
        let written = write_plots(&folder.0, &run.input("broken", true)).unwrap();
        assert_eq!(written.len(), 4);
        for path in &written {
            let svg = Svg::read(path);
            assert!(!svg.text.contains("NaN") && !svg.text.contains("inf"));
        }
        // A state of nothing but NaN draws an empty panel: 12 lines for 13 panels.
        assert_eq!(Svg::read(&written[0]).series().len(), 12);

        // No samples at all.
        let empty = PlotInput {
            title: "empty",
            time: &[],
            state: vec![("u", &[])],
            attitude_deg: Some([&[], &[], &[]]),
            track: Some((&[], &[])),
            energy_drift: Some(&[]),
        };
        assert_eq!(write_plots(&folder.0, &empty).unwrap().len(), 4);
        assert_eq!(folder.names().len(), 4);
    }

    #[test]
    fn the_same_input_gives_the_same_bytes() {
        let (a, b) = (Folder::new("same-a"), Folder::new("same-b"));
        let run = Run::spatial(30_000);
        let first = write_plots(&a.0, &run.input("again", true)).unwrap();
        let second = write_plots(&b.0, &run.input("again", true)).unwrap();
        for (p, q) in first.iter().zip(&second) {
            assert_eq!(
                fs::read(p).unwrap(),
                fs::read(q).unwrap(),
                "{}",
                p.display()
            );
        }
    }

    #[test]
    fn a_column_of_the_wrong_length_writes_nothing() {
        let folder = Folder::new("length");
        let mut run = Run::spatial(1_000);
        run.y.pop();
        let error = write_plots(&folder.0, &run.input("short", true)).unwrap_err();
        assert!(
            matches!(&error, PlotError::Length { column, len: 999, times: 1000, .. } if column == "track y")
        );
        assert!(error.to_string().contains("track.svg"), "{error}");
        assert!(folder.names().is_empty());
    }

    #[test]
    fn a_missing_folder_names_the_file() {
        let folder = Folder::new("missing");
        let run = Run::pendulum(100);
        let missing = folder.0.join("no such folder");
        let error = write_plots(&missing, &run.input("pendulum", false)).unwrap_err();
        assert!(matches!(error, PlotError::Write { .. }));
        assert!(error.to_string().contains("state.svg"), "{error}");
    }

    #[test]
    fn decimation_keeps_every_window_s_extremes() {
        // A flat series with one spike of one sample, up and one down.
        let mut y = vec![0.0; 1_000_000];
        y[123_457] = 5.0;
        y[765_433] = -3.0;
        let kept = decimate(y.len(), 500, |i| y[i].is_finite(), &[&y]);
        assert!(kept.len() <= 4 * 500);
        assert!(kept.contains(&123_457) && kept.contains(&765_433));
        assert_eq!((kept[0], kept[kept.len() - 1]), (0, 999_999));
        assert!(kept.windows(2).all(|w| w[0] < w[1]), "in order, once each");
        // Few samples are all kept, less the non-finite.
        let few = [1.0, f64::NAN, 3.0];
        assert_eq!(decimate(3, 500, |i| few[i].is_finite(), &[&few]), [0, 2]);
    }

    #[test]
    fn the_energy_axis_tells_round_off_from_drift() {
        assert_eq!(symlog(0.0), 0.0);
        for d in [1e-16, 1e-14, -1e-14, 1e-3, -0.5] {
            assert!((symexp(symlog(d)) / d - 1.0).abs() < 1e-12, "{d}");
        }
        // A decade per unit above round-off.
        assert!((symlog(1e-3) - symlog(1e-4) - 1.0).abs() < 1e-9);
        let ticks = |low: f64, high: f64| {
            let axis = SymlogAxis {
                low: symlog(low) * 1.05,
                high: symlog(high) * 1.05,
            };
            axis.key_points(plotters::coord::ranged1d::BoldPoints(10))
        };
        // A drift from zero to 10⁻³: every decade from round-off up.
        let drift = ticks(0.0, 1e-3);
        for d in [0.0, 1e-16, 1e-14, 1e-3] {
            assert!(drift.contains(&d), "{d:e} not in {drift:?}");
        }
        // Of either sign: every second decade, the top one kept.
        let both = ticks(-1e-3, 1e-3);
        for d in [-1e-3, -1e-15, 0.0, 1e-15, 1e-3] {
            assert!(both.contains(&d), "{d:e} not in {both:?}");
        }
        assert!(both.len() <= 17, "{both:?}");
        assert_eq!(decade_label(1e-14), "1e-14");
        assert_eq!(decade_label(-1e-3), "-1e-3");
    }

    #[test]
    fn tick_labels_have_the_digits_their_spacing_needs() {
        assert_eq!(tick_label(0.4, (0.0, 1.0), 5), "0.4");
        assert_eq!(tick_label(0.05, (0.0, 0.2), 5), "0.05");
        assert_eq!(tick_label(120.0, (0.0, 1000.0), 5), "120");
        assert_eq!(tick_label(2e-5, (0.0, 1e-4), 5), "2e-5");
        assert_eq!(tick_label(1e-17, (-1.0, 1.0), 5), "0");
        assert_eq!(tick_label(1.2e-4, (0.0, 1e-4), 5), "1.2e-4");
        assert_eq!(tick_label(400_000.0, (0.0, 1e6), 5), "4e5");
        // Round-off on a constant: the range is widened to 10⁻¹⁰ of the value, and the
        // labels tell the ticks apart.
        let range = axis_range(Some((1.0, 1.0 + 1e-15)));
        assert!(range.1 - range.0 > 1e-8);
        assert_eq!(tick_label(1.0 + 2e-9, range, 5), "1.000000002");
    }
}
