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
//! The plots: `state.svg` has one small panel per state component, titled with its name, its
//! value axis labelled with its unit, over one time range (stacked for up to four components,
//! else two to a row); a component zero for the whole run is named in the caption instead
//! of given a panel; `attitude.svg` has roll, pitch and yaw on one panel with a legend, made
//! continuous so that a tumbling body's angles do not wrap; `track.svg` has y
//! against x at one scale on both axes, the start a ring and the end a dot (a track that is one
//! point is said to be in its caption); `profile.svg`, where a spatial body's motion leaves the
//! horizontal plane, its height against the distance run (see `profile.rs`); `polhode.svg`, for a
//! body turning free of moments, ω in principal axes on the energy and momentum ellipsoids
//! (see `polhode.rs`); `energy.svg` has
//! the relative drift on a symmetric logarithmic axis, `sign(d)·log₁₀(1 + |d|/10⁻¹⁶)`: linear
//! through zero within round-off, a decade per unit above it, so that a drift of 10⁻¹⁴
//! and one of 10⁻³ both read on the same axis, with their sign.
//!
//! Non-finite values (NaN, ±∞) are skipped: a sample whose time or value is not finite is not
//! drawn, and the line joins its finite neighbours across it; the axis ranges are taken from
//! the finite values only. A series with no finite value draws an empty panel. Values beyond
//! ±10³⁰⁰ are drawn at that bound, so that an axis range stays finite.
//!
//! - **Sub-pixel lines.** plotters' SVG backend writes whole pixels; the data lines are
//!   written by [`precise`] with two decimals, so that curves are smooth when zoomed.
//!
//! A title is drawn [`printable`]: XML cannot hold most control characters (see
//! [`text`](eom::output::text)).
//!
//! The output is deterministic: the same input gives the same bytes (the SVG holds no
//! timestamp, and every coordinate is written to a fixed number of decimals).
//!
//! Here: the input, the errors, and writing each plot atomically. `scale` decides which
//! samples are drawn and where the axes run; `series`, `track`, `profile`, `polhode` and
//! `energy` draw the plots; `shapes` draws the library's drawing shapes from them (a track with
//! an outline along it, a series, an attitude, a profile), `poles` a linear model's eigenvalues,
//! `curves` one quantity against another (a spiral's r–δ curve, a rudder sweep's diameters),
//! `distributions` a Monte Carlo's figures and pass rates.

use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use plotters::coord::Shift;
use plotters::prelude::*;
use thiserror::Error;

use eom::output::text::printable;

pub mod curves;
pub mod distributions;
mod energy;
pub mod poles;
mod polhode;
mod precise;
mod profile;
mod scale;
mod series;
pub mod shapes;
mod track;

use energy::draw_energy;
use polhode::draw_polhode;
pub use polhode::{Polhode, in_principal_axes};
use precise::Overlay;
use profile::{draw_profile, leaves_the_plane};
use series::{draw_attitude, draw_state};
pub use track::Mark;
use track::draw_track;

/// What a run hands to the plots: columns sampled at the same times.
///
/// Every column has one value per entry of [`time`](Self::time); a column of another length
/// is an error ([`PlotError::Length`]).
pub struct PlotInput<'a> {
    /// The scene's title, for the plot titles.
    pub title: &'a str,
    /// The sample times, ascending.
    pub time: &'a [f64],
    /// Every state component, named as trajectory.csv names it without its unit (`u`,
    /// `theta_dot`, `q0`, …).
    pub state: Vec<(&'a str, &'a [f64])>,
    /// Roll, pitch and yaw in degrees, where the model has an attitude.
    pub attitude_deg: Option<[&'a [f64]; 3]>,
    /// The track (x, y) in space axes, where the model has a position in the plane.
    pub track: Option<(&'a [f64], &'a [f64])>,
    /// z in space axes (down), where the model has a position in space: with the track, the
    /// profile where the motion leaves the horizontal plane.
    pub depth: Option<&'a [f64]>,
    /// The relative energy drift (E − E₀)/|E₀| at each time, where the run has an energy.
    pub energy_drift: Option<&'a [f64]>,
    /// ω in principal axes, where the body turns free of moments about G.
    pub polhode: Option<Polhode<'a>>,
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
/// The file of the polhode plot.
const POLHODE: &str = "polhode.svg";
/// The file of the profile plot.
const PROFILE: &str = "profile.svg";
/// Every file [`write_plots`] may write, for the output folder's manifest.
pub const PLOT_FILES: [&str; 6] = [STATE, ATTITUDE, TRACK, ENERGY, POLHODE, PROFILE];

/// Draws every plot the input has data for into `dir` and returns the files written:
/// `state.svg`, `attitude.svg`, `track.svg`, `energy.svg`, `polhode.svg`, `profile.svg`.
///
/// `state.svg` is written when the input has a state component, `track.svg` when it has a
/// track that is more than one point (see [`not_drawn`]), `profile.svg` when the track
/// and the depth leave the horizontal plane (z varies by more than 1 % of the larger of the x
/// and y spans), the others when their `Option`
/// is `Some`; each replaces a file of the same name. `dir` must exist. Every column's
/// length is checked before anything is drawn, so a malformed input writes no file.
pub fn write_plots(dir: &Path, input: &PlotInput) -> Result<Vec<PathBuf>, PlotError> {
    check_lengths(dir, input)?;
    // The title as XML can hold it (see `output::text`).
    let title = printable(input.title);
    let input = &PlotInput {
        title: &title,
        state: input.state.clone(),
        ..*input
    };
    let mut written = Vec::new();
    if !input.state.is_empty() {
        written.push(emit(dir, STATE, |svg| draw_state(svg, input))?);
    }
    if let Some(angles) = input.attitude_deg {
        written.push(emit(dir, ATTITUDE, |svg| {
            draw_attitude(svg, input.title, input.time, angles)
        })?);
    }
    if let Some((x, y)) = input.track
        && track::stays_at(x, y).is_none()
    {
        let caption = format!("{}: track in space axes", input.title);
        let axes = ("x [m]", "y [m]");
        written.push(emit(dir, TRACK, |svg| {
            draw_track(svg, &caption, axes, (x, y), &[], ("", &[]))
        })?);
    }
    if let Some(drift) = input.energy_drift {
        written.push(emit(dir, ENERGY, |svg| {
            draw_energy(svg, input.title, input.time, drift)
        })?);
    }
    if let Some(polhode) = &input.polhode {
        written.push(emit(dir, POLHODE, |svg| {
            draw_polhode(svg, input.title, polhode)
        })?);
    }
    if let (Some((x, y)), Some(z)) = (input.track, input.depth)
        && leaves_the_plane(x, y, z)
    {
        written.push(emit(dir, PROFILE, |svg| {
            draw_profile(svg, input.title, (x, y, z))
        })?);
    }
    Ok(written)
}

/// The plots [`write_plots`] leaves out although `input` has their data, each with why: the
/// track of a body that does not translate (x and y one point to round-off, as a body turning
/// in place), which would be an empty frame.
pub fn not_drawn(input: &PlotInput) -> Vec<String> {
    let still = input.track.and_then(|(x, y)| track::stays_at(x, y));
    still
        .map(|(x, y)| {
            format!(
                "{TRACK} not drawn: the body does not translate, it stays at ({}, {}) m",
                eom::Short(x),
                eom::Short(y)
            )
        })
        .into_iter()
        .collect()
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
    if let Some(z) = input.depth {
        columns.push((PROFILE, "track z".to_string(), z.len()));
    }
    if let Some(drift) = input.energy_drift {
        columns.push((ENERGY, "energy drift".to_string(), drift.len()));
    }
    if let Some(polhode) = &input.polhode {
        for (name, values) in ["ω₁", "ω₂", "ω₃"].into_iter().zip(polhode.omega) {
            columns.push((POLHODE, name.to_string(), values.len()));
        }
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
pub(crate) fn write_atomically(dir: &Path, name: &str, bytes: &[u8]) -> io::Result<()> {
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

/// Draws onto an SVG of `size` pixels with a white background, into `svg`; the data lines
/// handed to the [`Overlay`] are written at sub-pixel precision once plotters is done.
fn render(
    svg: &mut String,
    size: (u32, u32),
    draw: impl FnOnce(&Area, &mut Overlay) -> Result<(), DrawError>,
) -> Result<(), DrawError> {
    let mut overlay = Overlay::default();
    {
        let root = SVGBackend::with_string(svg, size).into_drawing_area();
        root.fill(&WHITE)?;
        draw(&root, &mut overlay)?;
        root.present()?;
    }
    overlay.splice(svg);
    Ok(())
}

/// The colours of the lines, in order (colour-blind safe, from the Tableau 10 palette).
const COLOURS: [RGBColor; 3] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
];

/// The font of every text: resolved by the viewer, no font file is loaded.
const FONT: &str = "sans-serif";

/// The width of every plot, px: the widest GitHub shows an image in a README (the column of
/// a repository's page, 830 px), so that a plot is shown at its own size there and its texts
/// read at the sizes below. plotters' SVG backend writes a font of size s as s/1.24 px.
const WIDTH: u32 = 830;
/// A plot's title: 17.7 px.
const TITLE_FONT: u32 = 22;
/// A panel's title: 14.5 px.
const PANEL_FONT: u32 = 18;
/// Tick labels, axis labels and legends: 12.1 px, the smallest that reads at a glance.
const LABEL_FONT: u32 = 15;

/// A caption as it is drawn across `width` pixels: at `largest` if it fits, else at the
/// panels' and then the labels' size, and a caption too long even at that keeps its start and
/// what the plot is (the text after its last ": ") with "…" between, so that a long scene
/// title is never cut off at the plot's edge. The full title is in the run's summary.
///
/// The width is estimated at 0.6 em a character (plotters' SVG backend writes a font of size s
/// as s/1.24 px), wider than sans-serif's average, with 24 px of margin.
fn fitted_caption(caption: &str, largest: u32, width: u32) -> (String, u32) {
    let fits = |size: u32| ((f64::from(width) - 24.0) / (0.6 * f64::from(size) / 1.24)) as usize;
    let length = caption.chars().count();
    for size in [TITLE_FONT, PANEL_FONT, LABEL_FONT] {
        if size <= largest && length <= fits(size) {
            return (caption.to_string(), size);
        }
    }
    let size = LABEL_FONT.min(largest);
    (shortened(caption, fits(size)), size)
}

/// `caption` in at most `room` characters: its start, "…", and its end from the last ": ".
fn shortened(caption: &str, room: usize) -> String {
    let chars: Vec<char> = caption.chars().collect();
    let tail_start = caption
        .rfind(": ")
        .map(|byte| caption[..byte].chars().count())
        .filter(|&start| chars.len() - start < room / 2)
        .unwrap_or(chars.len());
    let tail = &chars[tail_start..];
    let head = room.saturating_sub(tail.len() + 1);
    chars[..head]
        .iter()
        .chain(std::iter::once(&'…'))
        .chain(tail)
        .collect()
}

#[cfg(test)]
mod tests;
