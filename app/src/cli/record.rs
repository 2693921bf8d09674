//! The command's recorder: what `eom run` does with the runs of a scene of any kind. Each
//! run's rows go into `trajectory.csv` in its folder under the output (by the trajectory
//! writer every run uses), and are kept for its plots; each run's drawings, once the kind
//! says them, are drawn into the same folder (the SVG plots, `view.html`). A signal stops the
//! run at its next row. The kind names the runs and what they draw; this module names no kind.

use super::run::{progress_bar, signal_received};
use anyhow::{Context, Result};
use eom::output::drawing::{
    Curves, Drawing, Flight, Mark, PlaneManoeuvre, RigidBody, RunDrawings, SpaceManoeuvre,
};
use eom::output::trajectory::{Columns, TrajectoryWriter};
use eom::run::record::{RecordError, Recorder, RunStart};
use eom::run::{Row, Sink};
use eom_cli::plots;
use eom_cli::plots::curves::{Curve, write_curves};
use eom_cli::plots::plane_manoeuvre::{ManoeuvrePlot, write_manoeuvre_plots};
use eom_cli::plots::space_manoeuvre::{SpacePlot, write_space_plots};
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
        | Drawing::PlaneManoeuvre(PlaneManoeuvre { title, .. })
        | Drawing::SpaceManoeuvre(SpaceManoeuvre { title, .. })
        | Drawing::Flight(Flight { title, .. }) => *title = titled(title),
        Drawing::Curves(Curves { caption, .. }) => *caption = titled(caption),
    }
    drawing
}

/// Draws `drawing` of a run whose rows are `kept` into its `folder`: the files written, and
/// each plot left out although the run has its data, with why.
fn draw(folder: &Path, drawing: &Drawing, kept: &Kept) -> Result<(Vec<PathBuf>, Vec<String>)> {
    let mut files = Vec::new();
    let mut not_drawn = Vec::new();
    match drawing {
        Drawing::RigidBody(body) => {
            let (plots, left_out) = super::plots::write(body, kept, folder)?;
            files.extend(plots);
            not_drawn = left_out;
            files.push(super::view::write(body, kept, folder)?);
        }
        Drawing::PlaneManoeuvre(plane) => {
            files.extend(draw_plane(folder, plane, kept)?);
            files.push(super::view::write_plane(folder, plane, kept)?);
        }
        Drawing::SpaceManoeuvre(space) => {
            files.extend(draw_space(folder, space, kept)?);
            files.push(super::view::write_space(folder, space, kept)?);
        }
        Drawing::Curves(curves) => files.push(draw_curves(folder, curves)?),
        Drawing::Flight(flight) => files.push(super::view::write_flight(folder, flight, kept)?),
    }
    Ok((files, not_drawn))
}

/// The marks as the track plots take them: (east, north).
fn marks(marks: &[Mark]) -> Vec<plots::Mark> {
    (marks.iter())
        .map(|mark| plots::Mark {
            label: mark.label.clone(),
            point: (mark.at[1], mark.at[0]),
        })
        .collect()
}

/// `track.svg` with the hull along it, and the heading and the rudder against time.
fn draw_plane(folder: &Path, plane: &PlaneManoeuvre, kept: &Kept) -> Result<Vec<PathBuf>> {
    let time = &kept.columns.time;
    let psi = kept.column("psi")?;
    let psi0 = (time.iter().zip(psi))
        .find(|(t, _)| **t >= plane.execute_s)
        .map_or(0.0, |(_, psi)| *psi);
    let degrees = |column: &[f64], from: f64| -> Vec<f64> {
        column.iter().map(|x| (x - from).to_degrees()).collect()
    };
    let heading = degrees(psi, psi0);
    let rudder = degrees(kept.column("delta")?, 0.0);
    let command = degrees(kept.column("command")?, 0.0);
    let plot = ManoeuvrePlot {
        title: &plane.title,
        time,
        north: kept.column("x")?,
        east: kept.column("y")?,
        heading_change_deg: &heading,
        heading_rad: psi,
        rudder_deg: &rudder,
        command_deg: &command,
        marks: &marks(&plane.marks),
        hull: plane.hull,
    };
    Ok(write_manoeuvre_plots(folder, &plot)?)
}

/// The track in plan, the profile, the attitude and the fins with their commands.
fn draw_space(folder: &Path, space: &SpaceManoeuvre, kept: &Kept) -> Result<Vec<PathBuf>> {
    let column = |name: &str| kept.column(name);
    let plot = SpacePlot {
        title: &space.title,
        time: &kept.columns.time,
        position: [column("x")?, column("y")?, column("z")?],
        attitude: [column("phi")?, column("theta")?, column("psi")?],
        fins: [
            column("dr")?,
            column("ds")?,
            column("dr_command")?,
            column("ds_command")?,
        ],
        marks: &marks(&space.marks),
    };
    Ok(write_space_plots(folder, &plot)?)
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
