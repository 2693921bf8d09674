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
//! `energy` draw the plots; `plane_manoeuvre` and `space_manoeuvre` draw a manoeuvre's (in the plane, in space), `poles` a linear model's eigenvalues,
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
pub mod plane_manoeuvre;
pub mod poles;
mod polhode;
mod precise;
mod profile;
mod scale;
mod series;
pub mod space_manoeuvre;
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
            draw_track(svg, &caption, axes, (x, y), &[], &[])
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

    /// The names of a spatial quaternion state, as trajectory.csv names them without their units.
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
                depth: None,
                energy_drift: Some(&self.drift),
                polhode: None,
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
        fn series(&self) -> Vec<Vec<(f64, f64)>> {
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
    fn a_long_title_is_fitted_to_the_plot_not_cut_off_at_its_edge() {
        let folder = Folder::new("long-title");
        let run = Run::spatial(1_000);
        let title = "A REMUS 100 with 6.5 kg of payload forward of its centre of buoyancy, \
                     trimmed nose-down at 1.5 m/s, on Prestero's table with the fins at 15°";
        let written = write_plots(&folder.0, &run.input(title, true)).unwrap();
        assert_eq!(written.len(), 4);
        for file in written {
            let svg = Svg::read(&file);
            let captions = svg.elements("text", |n| {
                let size: f64 = n.attribute("font-size").unwrap_or("0").parse().unwrap();
                (n.text().unwrap_or("").trim().to_string(), size)
            });
            let (caption, size) = captions
                .iter()
                .find(|(text, _)| text.starts_with("A REMUS 100"))
                .unwrap_or_else(|| panic!("{}: no caption in {captions:?}", file.display()));
            // Drawn within the width at 0.6 em a character, the estimate `fitted_caption`
            // makes (sans-serif's average character is narrower).
            let drawn = caption.chars().count() as f64 * 0.6 * size;
            assert!(
                drawn <= f64::from(WIDTH) - 24.0,
                "{}: {caption:?} at {size} px is {drawn:.0} px wide",
                file.display()
            );
            // Shortened in the title, so that what the plot is stays legible.
            assert!(caption.contains('…'), "{caption}");
            let what = file.file_stem().unwrap().to_str().unwrap();
            let what = if what == "track" {
                "track in space axes"
            } else {
                what
            };
            assert!(caption.contains(what), "{}: {caption}", file.display());
        }
    }

    #[test]
    fn a_caption_that_fits_is_kept_whole_at_the_largest_size_it_fits() {
        assert_eq!(
            fitted_caption("tennis racket: state", TITLE_FONT, WIDTH),
            ("tennis racket: state".to_string(), TITLE_FONT)
        );
        let long = "x".repeat(90);
        assert_eq!(
            fitted_caption(&long, TITLE_FONT, WIDTH),
            (long.clone(), PANEL_FONT)
        );
        assert_eq!(fitted_caption(&long, PANEL_FONT, WIDTH).1, PANEL_FONT);
        let longer = format!("{}: attitude", "y".repeat(300));
        let (shortened, size) = fitted_caption(&longer, TITLE_FONT, WIDTH);
        assert_eq!(size, LABEL_FONT);
        assert!(shortened.ends_with("…: attitude"), "{shortened}");
        assert!(shortened.starts_with("yyy"), "{shortened}");
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

        // v, w and z are zero throughout: named in the caption, not drawn.
        let state = Svg::read(&folder.0.join("state.svg"));
        assert_eq!(state.series().len(), 10);
        let texts = state.texts();
        assert!(
            texts
                .contains(&"tennis racket: state (v, w, z zero throughout, not drawn)".to_string()),
            "{texts:?}"
        );
        for name in SPATIAL {
            let panel = texts.contains(&name.to_string());
            assert_eq!(panel, !["v", "w", "z"].contains(&name), "panel {name}");
        }
        // Every value axis carries its unit.
        for label in ["u [m/s]", "p [rad/s]", "x [m]", "q0 [-]"] {
            assert!(texts.contains(&label.to_string()), "no axis {label}");
        }

        let attitude = Svg::read(&folder.0.join("attitude.svg"));
        assert_eq!(attitude.series().len(), 3);
        let texts = attitude.texts();
        for text in [
            "tennis racket: attitude (Euler angles, continuous, no wraps)",
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
        let (xs, ys): (Vec<f64>, Vec<f64>) = track.iter().copied().unzip();
        let spread = |v: &[f64]| {
            v.iter().copied().fold(f64::MIN, f64::max) - v.iter().copied().fold(f64::MAX, f64::min)
        };
        let (width, height) = (spread(&xs), spread(&ys));
        assert!(width > 500.0, "the circle fills the plot: {width} px");
        assert!((width - height).abs() <= 1.0, "{width} × {height} px");
        // Drawn at sub-pixel precision: most points fall between whole pixels.
        let fractional = track.iter().filter(|(x, _)| x.fract() != 0.0).count();
        assert!(
            fractional * 2 > track.len(),
            "{fractional} of {}",
            track.len()
        );
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
        let lowest_of_top = top.iter().map(|p| p.1).fold(f64::MIN, f64::max);
        let highest_of_bottom = bottom.iter().map(|p| p.1).fold(f64::MAX, f64::min);
        assert!(lowest_of_top < highest_of_bottom);
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
        for (path, lines) in written.iter().zip([10, 3, 1, 1]) {
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
        // A state of nothing but NaN (w) draws an empty panel, and v with an infinity is not
        // zero throughout: 11 lines for 12 panels, z alone left out.
        assert_eq!(Svg::read(&written[0]).series().len(), 11);

        // No samples at all.
        let empty = PlotInput {
            title: "empty",
            time: &[],
            state: vec![("u", &[])],
            attitude_deg: Some([&[], &[], &[]]),
            track: Some((&[], &[])),
            depth: Some(&[]),
            energy_drift: Some(&[]),
            polhode: Some(Polhode {
                moments: [1.0, 2.0, 3.0],
                omega: [&[], &[], &[]],
            }),
        };
        assert_eq!(write_plots(&folder.0, &empty).unwrap().len(), 5);
        assert_eq!(folder.names().len(), 5);
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
    fn a_tumbling_body_s_attitude_has_no_jumps() {
        // A spin about body y at 1 rad/s: the principal values fold pitch back at ±90° and
        // jump roll and yaw by 180°; the continuous angles run pitch on and hold the others.
        let (mut roll, mut pitch, mut yaw) = (vec![], vec![], vec![]);
        for i in 0..2_000 {
            let rotation = nalgebra::Rotation3::from_euler_angles(0.0, i as f64 * 0.01, 0.0)
                * nalgebra::Rotation3::from_euler_angles(0.0, 0.0, 0.0);
            let (r, p, y) = rotation.euler_angles();
            roll.push(r.to_degrees());
            pitch.push(p.to_degrees());
            yaw.push(y.to_degrees());
        }
        assert!(
            roll.windows(2).any(|w| (w[1] - w[0]).abs() > 170.0),
            "principal values jump"
        );
        let [r, p, y] = series::continuous_euler_deg([&roll, &pitch, &yaw]);
        let largest_step = |v: &[f64]| {
            v.windows(2)
                .map(|w| (w[1] - w[0]).abs())
                .fold(0.0, f64::max)
        };
        for column in [&r, &p, &y] {
            assert!(largest_step(column) < 1.0, "{}", largest_step(column));
        }
        assert!(
            (p[1_999] - 19.99f64.to_degrees()).abs() < 1e-6,
            "{}",
            p[1_999]
        );
    }

    /// A spinning plate's ω, I₁ = I₂ = 1, I₃ = 2: (3 cos t, 3 sin t, 4) over `n` samples.
    fn plate(n: usize) -> [Vec<f64>; 3] {
        let t = (0..n).map(|i| i as f64 * 1e-2);
        [
            t.clone().map(|t| 3.0 * t.cos()).collect(),
            t.clone().map(|t| 3.0 * t.sin()).collect(),
            t.map(|_| 4.0).collect(),
        ]
    }

    /// Writes the plots of a pendulum of as many rows as `omega`, with `omega` as its polhode.
    fn write_polhode(folder: &Folder, omega: &[Vec<f64>; 3]) -> Vec<PathBuf> {
        let run = Run::pendulum(omega[0].len());
        let mut input = run.input("plate", false);
        input.polhode = Some(Polhode {
            moments: [1.0, 1.0, 2.0],
            omega: [&omega[0], &omega[1], &omega[2]],
        });
        write_plots(&folder.0, &input).unwrap()
    }

    #[test]
    fn the_polhode_draws_the_run_and_the_dashed_curve_in_three_projections() {
        let folder = Folder::new("polhode");
        let written = write_polhode(&folder, &plate(700));
        assert_eq!(written.last(), Some(&folder.0.join("polhode.svg")));
        let svg = Svg::read(&folder.0.join("polhode.svg"));
        let dashed = svg.elements("polyline", |n| n.attribute("stroke-dasharray").is_some());
        // Per projection: the run, the polhode (dashed) and the ellipsoid's outline, clipped
        // to the window; one dashed sample in the legend.
        assert_eq!(dashed.iter().filter(|d| **d).count(), 3 + 1);
        assert!(svg.series().len() >= 3 * 3, "{}", svg.series().len());
        let texts = svg.texts();
        for text in ["ω₁–ω₂", "ω₂–ω₃", "ω₃–ω₁", "the run's ω", "T = 20.5 J"]
        {
            assert!(texts.contains(&text.to_string()), "no {text} in {texts:?}");
        }
        assert!(
            texts.contains(&"the loop goes round ω₃".to_string()),
            "{texts:?}"
        );

        // One row, nothing, a row of NaN first: a plot, and no panic.
        let mut broken = plate(10);
        broken[1][0] = f64::NAN;
        for omega in [plate(1), plate(0), broken] {
            write_polhode(&folder, &omega);
            let text = fs::read_to_string(folder.0.join("polhode.svg")).unwrap();
            assert!(!text.contains("NaN"));
        }
    }

    #[test]
    fn a_track_in_place_is_said_to_be_one_and_a_climb_gets_a_profile() {
        let folder = Folder::new("profile");
        let mut run = Run::spatial(2_000);
        let still = vec![0.0; 2_000];
        // Turning in place: the track is a point, not drawn as an empty frame, and said so.
        let mut input = run.input("in place", true);
        input.track = Some((&still, &still));
        input.depth = Some(&still);
        let written = write_plots(&folder.0, &input).unwrap();
        assert!(!written.contains(&folder.0.join("profile.svg")));
        assert!(!written.contains(&folder.0.join("track.svg")));
        assert!(!folder.0.join("track.svg").exists());
        assert_eq!(
            not_drawn(&input),
            ["track.svg not drawn: the body does not translate, it stays at (0, 0) m"]
        );
        assert!(not_drawn(&run.input("circle", true)).is_empty());

        // Climbing 30 m on the 50 m circle (3 % of its 100 m span): a profile, the height
        // against the distance run, which ends at 1/10 of the circumference.
        run.x = (0..2_000)
            .map(|i| 50.0 * (i as f64 * TAU / 20_000.0).cos())
            .collect();
        run.y = (0..2_000)
            .map(|i| 50.0 * (i as f64 * TAU / 20_000.0).sin())
            .collect();
        let climb: Vec<f64> = (0..2_000).map(|i| -0.015 * i as f64).collect();
        let mut input = run.input("climb", true);
        input.depth = Some(&climb);
        let written = write_plots(&folder.0, &input).unwrap();
        assert_eq!(written.last(), Some(&folder.0.join("profile.svg")));
        let profile = Svg::read(&folder.0.join("profile.svg"));
        let line = &profile.series()[0];
        // Up to the right: the height grows as the distance does.
        assert!(line[0].0 < line[line.len() - 1].0 && line[0].1 > line[line.len() - 1].1);
        let texts = profile.texts();
        for text in ["horizontal distance run [m]", "height −z [m]", "30"] {
            assert!(texts.contains(&text.to_string()), "no {text} in {texts:?}");
        }
        // A z column of the wrong length is refused before anything is drawn.
        input.depth = Some(&climb[1..]);
        let error = write_plots(&folder.0, &input).unwrap_err();
        assert!(error.to_string().contains("profile.svg"), "{error}");
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
}
