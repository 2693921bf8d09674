//! The command's recorder: what `eom run` does with the runs of a scene of any kind. Each
//! run's rows go into `trajectory.csv` in its folder under the output (by the trajectory
//! writer every run uses), and are kept for its plots; each run's drawings, once the kind
//! says them, are drawn into the same folder (the SVG plots, `view.html`). A signal stops the
//! run at its next row. The kind names the runs and what they draw; this module names no kind.

use super::run::{progress_bar, signal_received};
use anyhow::{Context, Result};
use eom::output::drawing::{
    Attitude, Curves, Drawing, Mark, Profile, Reading, RigidBody, RunDrawings, Series, Track, View,
};
use eom::output::text::printable;
use eom::output::trajectory::{Columns, TrajectoryWriter};
use eom::run::record::{RecordError, Recorder, RunStart};
use eom::run::{Row, Sink};
use eom_cli::plots;
use eom_cli::plots::curves::{Curve, write_curves};
use eom_cli::plots::shapes::{
    OutlinePlot, SeriesPlot, TrackPlot, write_attitude, write_profile, write_series, write_track,
};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A run's rows as kept for its plots, with their columns' names.
pub struct Kept {
    /// The state columns' names, as the run gave them.
    pub names: Vec<String>,
    /// The rows.
    pub columns: Columns,
}

impl Kept {
    /// The column `name`; a drawing that names a column the run did not give is an error,
    /// not a plot of the wrong column.
    pub fn column(&self, name: &str) -> Result<&[f64]> {
        let index = (self.names.iter().position(|n| n == name)).with_context(|| {
            format!("a drawing reads the column {name}, which the run does not give")
        })?;
        Ok(&self.columns.state[index])
    }
}

/// The run being recorded: its folder and its file.
struct Current {
    path: String,
    file: PathBuf,
    names: Vec<String>,
    writer: TrajectoryWriter,
}

/// Each run into its folder under `out`.
pub struct FolderRecorder<'a> {
    out: &'a Path,
    /// Whether each run shows a progress bar (a scene run alone, not a sweep's case).
    progress: bool,
    current: Option<Current>,
    /// The rows of each run that ended, until its drawings are drawn.
    kept: BTreeMap<String, Kept>,
    /// A sweep case's values, `key = value, …`, which each drawing's title adds.
    case: Option<String>,
    /// The files written at the top of `out` (by a run recorded there), in order.
    pub written: Vec<PathBuf>,
    /// The plots left out although a run has their data, each with why.
    pub not_drawn: Vec<String>,
}

impl<'a> FolderRecorder<'a> {
    /// Runs into folders under `out`, a folder already claimed and found writable; with
    /// `progress`, each run shows a bar over its time (on a terminal, after a second); for a
    /// sweep's case, `case` its values as its drawings' titles say them.
    pub fn new(out: &'a Path, progress: bool, case: Option<String>) -> Self {
        FolderRecorder {
            out,
            progress,
            current: None,
            kept: BTreeMap::new(),
            case,
            written: Vec::new(),
            not_drawn: Vec::new(),
        }
    }

    /// `title`, with the case's values for a sweep's case (its summary keeps the scene's
    /// title exactly, and says the values under `case`).
    fn titled(&self, title: &str) -> String {
        match &self.case {
            Some(case) => format!("{title} — {case}"),
            None => title.to_owned(),
        }
    }
}

impl Recorder for FolderRecorder<'_> {
    fn begin(&mut self, run: RunStart) -> Result<(), RecordError> {
        let folder = self.out.join(run.path);
        std::fs::create_dir_all(&folder)
            .with_context(|| format!("creating {}", folder.display()))?;
        let file = folder.join("trajectory.csv");
        if run.path.is_empty() {
            self.written.push(file.clone());
        }
        let mut writer = TrajectoryWriter::create(
            &file,
            run.columns,
            (run.potential, run.energy_unit),
            run.expected_rows,
        )
        .with_context(|| format!("creating {}", file.display()))?;
        if self.progress {
            writer.on_row(progress_bar(run.end_time));
        }
        self.current = Some(Current {
            path: run.path.to_owned(),
            file,
            names: run.columns.to_vec(),
            writer,
        });
        Ok(())
    }

    /// After a signal, refuses the row: the last row written is the last the run reports.
    fn row(&mut self, row: &Row) -> bool {
        signal_received().is_none()
            && (self.current.as_mut()).is_some_and(|current| current.writer.row(row))
    }

    fn end(&mut self) -> Result<(), RecordError> {
        let Some(mut current) = self.current.take() else {
            return Ok(());
        };
        let writing = || format!("writing {}", current.file.display());
        if let Some(error) = current.writer.take_error() {
            return Err(anyhow::Error::new(error).context(writing()).into());
        }
        let columns = current.writer.finish().with_context(writing)?;
        let kept = Kept {
            names: current.names,
            columns,
        };
        self.kept.insert(current.path, kept);
        Ok(())
    }

    fn drawn(&mut self, run: RunDrawings) -> Result<(), RecordError> {
        let kept = (self.kept.remove(&run.path))
            .with_context(|| format!("{} was drawn before its rows were kept", run.path))?;
        let folder = self.out.join(&run.path);
        for drawing in &run.drawings {
            let drawing = retitled(drawing, |title| self.titled(title));
            let (files, not_drawn) = draw(&folder, &drawing, &kept)?;
            if run.path.is_empty() {
                self.written.extend(files);
            }
            self.not_drawn.extend(not_drawn);
        }
        Ok(())
    }

    fn stop_asked(&self) -> bool {
        signal_received().is_some()
    }
}

/// `drawing` with its title as `titled` makes it.
fn retitled(drawing: &Drawing, titled: impl Fn(&str) -> String) -> Drawing {
    let mut drawing = drawing.clone();
    match &mut drawing {
        Drawing::RigidBody(RigidBody { title, .. })
        | Drawing::Track(Track { title, .. })
        | Drawing::Series(Series { title, .. })
        | Drawing::Attitude(Attitude { title, .. })
        | Drawing::Profile(Profile { title, .. })
        | Drawing::View(View { title, .. }) => *title = titled(title),
        Drawing::Curves(Curves { caption, .. }) => *caption = titled(caption),
    }
    drawing
}

/// Draws `drawing` of a run whose rows are `kept` into its `folder`: the files written, and
/// each plot left out although the run has its data, with why.
fn draw(folder: &Path, drawing: &Drawing, kept: &Kept) -> Result<(Vec<PathBuf>, Vec<String>)> {
    let file = match drawing {
        Drawing::RigidBody(body) => {
            let (mut files, not_drawn) = super::plots::write(body, kept, folder)?;
            files.push(super::view::write(body, kept, folder)?);
            return Ok((files, not_drawn));
        }
        Drawing::Track(track) => draw_track(folder, track, kept)?,
        Drawing::Series(series) => draw_series(folder, series, kept)?,
        Drawing::Attitude(attitude) => {
            let degrees = attitude
                .angles
                .iter()
                .map(|name| read(kept, name, Reading::Degrees))
                .collect::<Result<Vec<_>>>()?;
            let [roll, pitch, yaw] = [0, 1, 2].map(|k| degrees[k].as_slice());
            let title = printable(&attitude.title);
            write_attitude(folder, &title, &kept.columns.time, [roll, pitch, yaw])?
        }
        Drawing::Profile(profile) => {
            let [x, y, z] = [0, 1, 2].map(|k| kept.column(&profile.position[k]));
            write_profile(folder, &printable(&profile.title), (x?, y?, z?))?
        }
        Drawing::View(view) => super::view::write_drawn(folder, view, kept)?,
        Drawing::Curves(curves) => draw_curves(folder, curves)?,
    };
    Ok((vec![file], Vec::new()))
}

/// The column `name` of `kept` as `reading` reads it.
fn read(kept: &Kept, name: &str, reading: Reading) -> Result<Vec<f64>> {
    let column = kept.column(name)?;
    let degrees = |from: f64| column.iter().map(|x| (x - from).to_degrees()).collect();
    Ok(match reading {
        Reading::AsIs => column.to_vec(),
        Reading::Degrees => degrees(0.0),
        Reading::DegreesSince { from_s } => {
            let start = (kept.columns.time.iter().zip(column))
                .find(|(t, _)| **t >= from_s)
                .map_or(0.0, |(_, x)| *x);
            degrees(start)
        }
    })
}

/// The marks as the track plots take them: (across, up).
fn marks(marks: &[Mark]) -> Vec<plots::Mark> {
    (marks.iter())
        .map(|mark| plots::Mark {
            label: mark.label.clone(),
            point: (mark.at[1], mark.at[0]),
        })
        .collect()
}

/// `track.svg`, with its outline along it.
fn draw_track(folder: &Path, track: &Track, kept: &Kept) -> Result<PathBuf> {
    let caption = format!("{}: {}", printable(&track.title), track.what);
    let outline = match &track.outline {
        Some(outline) => Some((outline, kept.column(&outline.heading)?)),
        None => None,
    };
    let plot = TrackPlot {
        caption: &caption,
        axes: (&track.across.1, &track.up.1),
        across: kept.column(&track.across.0)?,
        up: kept.column(&track.up.0)?,
        marks: &marks(&track.marks),
        outline: outline.map(|(outline, heading)| OutlinePlot {
            length: outline.length,
            beam: outline.beam,
            heading,
            times: outline.times,
            label: &outline.label,
        }),
    };
    Ok(write_track(folder, &plot)?)
}

/// A series' file: its columns as its lines read them.
fn draw_series(folder: &Path, series: &Series, kept: &Kept) -> Result<PathBuf> {
    let caption = format!("{}: {}", printable(&series.title), series.what);
    let values = (series.lines.iter())
        .map(|line| read(kept, &line.column, line.reading))
        .collect::<Result<Vec<_>>>()?;
    let lines: Vec<(&str, &[f64])> = (series.lines.iter().zip(&values))
        .map(|(line, values)| (line.label.as_str(), values.as_slice()))
        .collect();
    let plot = SeriesPlot {
        file: &series.file,
        caption: &caption,
        y_desc: &series.y_desc,
        time: &kept.columns.time,
        lines: &lines,
    };
    Ok(write_series(folder, &plot)?)
}

/// Named curves into their own file.
fn draw_curves(folder: &Path, drawing: &Curves) -> Result<PathBuf> {
    let curves: Vec<Curve> = (drawing.curves.iter())
        .map(|(name, points)| Curve { name, points })
        .collect();
    let plot = plots::curves::Curves {
        caption: &drawing.caption,
        x_desc: &drawing.x_desc,
        y_desc: &drawing.y_desc,
        curves: &curves,
    };
    Ok(write_curves(folder, &drawing.file, &plot)?)
}
