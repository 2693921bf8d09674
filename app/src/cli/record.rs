//! The command's recorder: what `eom run` does with the runs of a scene of any kind. Each
//! run's rows go into `trajectory.csv` in its folder under the output (by the trajectory
//! writer every run uses), and are kept for its plots; each run's drawings, once the kind
//! says them, are drawn into the same folder (the SVG plots, `view.html`). A signal stops the
//! run at its next row. The kind names the runs and what they draw; this module names no kind.

use super::run::{progress_bar, signal_received};
use anyhow::{Context, Result};
use eom::output::drawing::{Curves, Drawing, Mark, PlaneManoeuvre, RunDrawings, SpaceManoeuvre};
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
}

impl<'a> FolderRecorder<'a> {
    /// Runs into folders under `out`, a folder already claimed and found writable; with
    /// `progress`, each run shows a bar over its time (on a terminal, after a second).
    pub fn new(out: &'a Path, progress: bool) -> Self {
        FolderRecorder {
            out,
            progress,
            current: None,
            kept: BTreeMap::new(),
        }
    }
}

impl Recorder for FolderRecorder<'_> {
    fn begin(&mut self, run: RunStart) -> Result<(), RecordError> {
        let folder = self.out.join(run.path);
        std::fs::create_dir_all(&folder)
            .with_context(|| format!("creating {}", folder.display()))?;
        let file = folder.join("trajectory.csv");
        let mut writer = TrajectoryWriter::create(&file, run.columns, false, run.expected_rows)
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

    fn row(&mut self, row: &Row) -> bool {
        let written = (self.current.as_mut()).is_some_and(|current| current.writer.row(row));
        written && signal_received().is_none()
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
            draw(&folder, drawing, &kept)?;
        }
        Ok(())
    }

    fn stop_asked(&self) -> bool {
        signal_received().is_some()
    }
}

/// Draws `drawing` of a run whose rows are `kept` into its `folder`.
fn draw(folder: &Path, drawing: &Drawing, kept: &Kept) -> Result<()> {
    match drawing {
        Drawing::PlaneManoeuvre(plane) => {
            draw_plane(folder, plane, kept)?;
            super::view::write_plane(folder, plane, kept)?;
        }
        Drawing::SpaceManoeuvre(space) => {
            draw_space(folder, space, kept)?;
            super::view::write_space(folder, space, kept)?;
        }
        Drawing::Curves(curves) => draw_curves(folder, curves)?,
    }
    Ok(())
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
fn draw_plane(folder: &Path, plane: &PlaneManoeuvre, kept: &Kept) -> Result<()> {
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
    write_manoeuvre_plots(folder, &plot)?;
    Ok(())
}

/// The track in plan, the profile, the attitude and the fins with their commands.
fn draw_space(folder: &Path, space: &SpaceManoeuvre, kept: &Kept) -> Result<()> {
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
    write_space_plots(folder, &plot)?;
    Ok(())
}

/// Named curves into their own file.
fn draw_curves(folder: &Path, drawing: &Curves) -> Result<()> {
    let curves: Vec<Curve> = (drawing.curves.iter())
        .map(|(name, points)| Curve { name, points })
        .collect();
    let plot = plots::curves::Curves {
        caption: &drawing.caption,
        x_desc: &drawing.x_desc,
        y_desc: &drawing.y_desc,
        curves: &curves,
    };
    write_curves(folder, &drawing.file, &plot)?;
    Ok(())
}
