//! The SVG plots of a run: the state's time series, the attitude, the track, the profile, the
//! energy drift and the polhode, drawn with plotters' SVG backend from columns sampled at the same times.
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
//! continuous so that a tumbling body's angles do not wrap; `track.svg` has a track in a plane
//! at one scale on both axes, the start a ring and the end a dot (a track that is one point to
//! round-off is not drawn, and [`shapes::track_not_drawn`] says so); `profile.svg` a track in
//! space, its height against the distance run (see `profile.rs`); `polhode.svg`, for a body
//! turning free of moments, ω in principal axes on the energy and momentum ellipsoids (see
//! `polhode.rs`); `energy.svg` has the relative drift on a symmetric logarithmic axis,
//! `sign(d)·log₁₀(1 + |d|/10⁻¹⁶)`: linear through zero within round-off, a decade per unit
//! above it, so that a drift of 10⁻¹⁴ and one of 10⁻³ both read on the same axis, with their
//! sign.
//!
//! Non-finite values (NaN, ±∞) are skipped: a sample whose time or value is not finite is not
//! drawn, and the line joins its finite neighbours across it; the axis ranges are taken from
//! the finite values only. A series with no finite value draws an empty panel. Values beyond
//! ±10³⁰⁰ are drawn at that bound, so that an axis range stays finite.
//!
//! - **Sub-pixel lines.** plotters' SVG backend writes whole pixels; the data lines are
//!   written by [`precise`] with two decimals, so that curves are smooth when zoomed.
//!
//! A title is drawn as it is handed in, which the caller makes
//! [`printable`](eom::output::text::printable): XML cannot hold most control characters (see
//! [`text`](eom::output::text)).
//!
//! The output is deterministic: the same input gives the same bytes (the SVG holds no
//! timestamp, and every coordinate is written to a fixed number of decimals).
//!
//! Here: the errors, and writing each plot atomically. `scale` decides which samples are drawn
//! and where the axes run; `series`, `track`, `profile`, `polhode` and `energy` draw the plots;
//! `shapes` draws the library's drawing shapes from them (a track with an outline along it, a
//! series, the state's panels, an attitude, a profile, the energy drift, a polhode), `poles` a
//! linear model's eigenvalues,
//! `curves` one quantity against another (a spiral's r–δ curve, a rudder sweep's diameters),
//! `distributions` a Monte Carlo's figures and pass rates.

use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use plotters::coord::Shift;
use plotters::prelude::*;
use thiserror::Error;

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

pub use polhode::{Polhode, in_principal_axes};
use precise::Overlay;
pub use track::Mark;

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
/// Every file of a fixed name the [`shapes`] may write, for the output folder's manifest.
pub const PLOT_FILES: [&str; 6] = [STATE, ATTITUDE, TRACK, ENERGY, POLHODE, PROFILE];

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
