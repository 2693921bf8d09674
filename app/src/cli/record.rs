//! The command's recorder: what `eom run` does with the runs of a scene of any kind. Each
//! run's rows go into `trajectory.csv` in its folder under the output (by the trajectory
//! writer every run uses), and are kept for its plots; each run's drawings, once the kind
//! says them, are drawn into the same folder (the SVG plots, `view.html`). A signal stops the
//! run at its next row. The kind names the runs and what they draw; this module names no kind.

use super::run::{progress_bar, signal_received};
use anyhow::{Context, Result};
use eom::InertiaTensor;
use eom::models::euler_angles_of_quaternion;
use eom::nalgebra::Matrix3;
use eom::output::drawing::{
    Attitude, Curves, Drawing, EnergyDrift, Mark, Orientation, Panels, Polhode, Profile, Reading,
    RunDrawings, Series, Track,
};
use eom::output::text::printable;
use eom::output::trajectory::{Columns, TrajectoryWriter};
use eom::run::record::{RecordError, Recorder, RunStart};
use eom::run::{Row, Sink};
use eom_cli::plots;
use eom_cli::plots::curves::{Curve, write_curves};
use eom_cli::plots::shapes::{
    OutlinePlot, SeriesPlot, TrackPlot, energy_drift, leaves_the_plane, track_not_drawn,
    write_attitude, write_energy_drift, write_panels, write_polhode, write_profile, write_series,
    write_track,
};
use eom_cli::plots::{Polhode as PolhodePlot, in_principal_axes};
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
        Drawing::Track(Track { title, .. })
        | Drawing::Series(Series { title, .. })
        | Drawing::Panels(Panels { title, .. })
        | Drawing::Attitude(Attitude { title, .. })
        | Drawing::Profile(Profile { title, .. })
        | Drawing::EnergyDrift(EnergyDrift { title })
        | Drawing::Polhode(Polhode { title, .. }) => *title = titled(title),
        Drawing::View(view) => view.title = titled(&view.title),
        Drawing::Curves(Curves { caption, .. }) => *caption = titled(caption),
    }
    drawing
}

/// Draws `drawing` of a run whose rows are `kept` into its `folder`: the files written, and
/// each plot left out although the run has its data, with why. A plot whose data says nothing
/// (a level profile, an energy with no scale, a tensor no body has) is left out unsaid.
fn draw(folder: &Path, drawing: &Drawing, kept: &Kept) -> Result<(Vec<PathBuf>, Vec<String>)> {
    let file = match drawing {
        Drawing::Track(track) => {
            let (across, up) = (kept.column(&track.across.0)?, kept.column(&track.up.0)?);
            if let Some(why) = track_not_drawn(across, up) {
                return Ok((Vec::new(), vec![why]));
            }
            Some(draw_track(folder, track, kept)?)
        }
        Drawing::Series(series) => Some(draw_series(folder, series, kept)?),
        Drawing::Panels(panels) => {
            let columns = (panels.columns.iter())
                .map(|name| Ok((name.as_str(), kept.column(name)?)))
                .collect::<Result<Vec<_>>>()?;
            let title = printable(&panels.title);
            Some(write_panels(folder, &title, &kept.columns.time, &columns)?)
        }
        Drawing::Attitude(attitude) => {
            let degrees = attitude_degrees(kept, &attitude.orientation)?;
            let [roll, pitch, yaw] = [0, 1, 2].map(|k| degrees[k].as_slice());
            let title = printable(&attitude.title);
            Some(write_attitude(
                folder,
                &title,
                &kept.columns.time,
                [roll, pitch, yaw],
            )?)
        }
        Drawing::Profile(profile) => {
            let [x, y, z] = [0, 1, 2].map(|k| kept.column(&profile.position[k]));
            let (x, y, z) = (x?, y?, z?);
            let title = printable(&profile.title);
            (profile.when_level || leaves_the_plane(x, y, z))
                .then(|| write_profile(folder, &title, (x, y, z)))
                .transpose()?
        }
        Drawing::EnergyDrift(drift) => {
            let columns = &kept.columns;
            let title = printable(&drift.title);
            (energy_drift(&columns.energy, &columns.kinetic))
                .map(|drift| write_energy_drift(folder, &title, &columns.time, &drift))
                .transpose()?
        }
        Drawing::Polhode(polhode) => draw_polhode(folder, polhode, kept)?,
        Drawing::View(view) => Some(super::view::write(folder, view, kept)?),
        Drawing::Curves(curves) => Some(draw_curves(folder, curves)?),
    };
    Ok((file.into_iter().collect(), Vec::new()))
}

/// Roll, pitch and yaw in degrees of every row, as `orientation` reads them: a quaternion's
/// turned into Euler angles (z–y–x), a heading's or a pitch's with the other two angles zero.
fn attitude_degrees(kept: &Kept, orientation: &Orientation) -> Result<[Vec<f64>; 3]> {
    let zero = || vec![0.0; kept.columns.time.len()];
    let degrees = |name: &str| read(kept, name, Reading::Degrees);
    Ok(match orientation {
        Orientation::EulerAngles([phi, theta, psi]) => {
            [degrees(phi)?, degrees(theta)?, degrees(psi)?]
        }
        Orientation::Heading(psi) => [zero(), zero(), degrees(psi)?],
        Orientation::Pitch(theta) => [zero(), degrees(theta)?, zero()],
        Orientation::Quaternion(names) | Orientation::QuaternionAsIs(names) => {
            let [q0, q1, q2, q3] = [0, 1, 2, 3].map(|k| kept.column(&names[k]));
            let q = [q0?, q1?, q2?, q3?];
            let mut angles: [Vec<f64>; 3] = Default::default();
            for row in 0..q[0].len() {
                let value = euler_angles_of_quaternion(q.map(|column| column[row]));
                for (angle, value) in angles.iter_mut().zip(value) {
                    angle.push(value.to_degrees());
                }
            }
            angles
        }
    })
}

/// `polhode.svg`, ω turned into the tensor's principal axes; none where the tensor is not a
/// body's.
fn draw_polhode(folder: &Path, polhode: &Polhode, kept: &Kept) -> Result<Option<PathBuf>> {
    let inertia = polhode.spin.inertia_about_g;
    let matrix = Matrix3::from_fn(|r, c| inertia[r][c]);
    let Ok(tensor) = InertiaTensor::from_matrix(matrix) else {
        return Ok(None);
    };
    let [p, q, r] = [0, 1, 2].map(|k| kept.column(&polhode.spin.omega[k]));
    let (moments, [w1, w2, w3]) = in_principal_axes(&tensor, [p?, q?, r?]);
    let plot = PolhodePlot {
        moments,
        omega: [&w1, &w2, &w3],
    };
    Ok(Some(write_polhode(
        folder,
        &printable(&polhode.title),
        &plot,
    )?))
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

#[cfg(test)]
mod tests {
    use super::*;
    use eom::nalgebra::UnitQuaternion;

    /// Rows of the columns `names`, each given as its values.
    fn kept(columns: &[(&str, Vec<f64>)]) -> Kept {
        let rows = columns.first().map_or(0, |(_, values)| values.len());
        Kept {
            names: columns.iter().map(|(name, _)| (*name).to_owned()).collect(),
            columns: Columns {
                time: (0..rows).map(|row| row as f64).collect(),
                state: columns.iter().map(|(_, values)| values.clone()).collect(),
                energy: Vec::new(),
                kinetic: Vec::new(),
            },
        }
    }

    /// A quaternion body's attitude is its quaternion's roll, pitch and yaw, whatever its
    /// length (a run's quaternion drifts from unit length), and the same as the Euler
    /// angles' of the same turn.
    #[test]
    fn a_quaternion_s_attitude_is_its_roll_pitch_and_yaw() {
        let turns = [(0.3, -0.4, 1.1), (-1.2, 0.7, -2.9), (0.0, 0.0, 0.0)];
        let quaternions = turns.map(|(r, p, y)| UnitQuaternion::from_euler_angles(r, p, y));
        // Each row's quaternion off unit length by its own factor.
        let scaled = |part: fn(&UnitQuaternion<f64>) -> f64| {
            (quaternions.iter().zip([1.0, 1.0 + 1e-9, 0.5]))
                .map(|(q, factor)| factor * part(q))
                .collect::<Vec<_>>()
        };
        let q = kept(&[
            ("q0", scaled(|q| q.w)),
            ("q1", scaled(|q| q.i)),
            ("q2", scaled(|q| q.j)),
            ("q3", scaled(|q| q.k)),
        ]);
        let names = ["q0", "q1", "q2", "q3"].map(String::from);
        let angle = |k: usize| turns.map(|turn| [turn.0, turn.1, turn.2][k]).to_vec();
        let euler = kept(&[("phi", angle(0)), ("theta", angle(1)), ("psi", angle(2))]);
        let from_euler = attitude_degrees(
            &euler,
            &Orientation::EulerAngles(["phi", "theta", "psi"].map(String::from)),
        )
        .unwrap();
        for orientation in [
            Orientation::Quaternion(names.clone()),
            Orientation::QuaternionAsIs(names.clone()),
        ] {
            let degrees = attitude_degrees(&q, &orientation).unwrap();
            for (k, turn) in turns.iter().enumerate() {
                let expected = [turn.0, turn.1, turn.2].map(f64::to_degrees);
                for angle in 0..3 {
                    let (got, euler) = (degrees[angle][k], from_euler[angle][k]);
                    assert!((got - expected[angle]).abs() < 1e-9, "{got} {expected:?}");
                    assert!((got - euler).abs() < 1e-9, "{got} {euler}");
                }
            }
        }
    }

    /// A heading turns about z alone, a pitch about y alone: the other angles are zero.
    #[test]
    fn a_heading_or_a_pitch_has_the_other_angles_zero() {
        let rows = kept(&[("psi", vec![0.5, -1.0]), ("theta", vec![0.25, 0.0])]);
        let heading = attitude_degrees(&rows, &Orientation::Heading("psi".into())).unwrap();
        assert_eq!(heading[0], [0.0, 0.0]);
        assert_eq!(heading[1], [0.0, 0.0]);
        assert_eq!(heading[2], [0.5f64.to_degrees(), -(1.0f64.to_degrees())]);
        let pitch = attitude_degrees(&rows, &Orientation::Pitch("theta".into())).unwrap();
        assert_eq!(pitch[1], [0.25f64.to_degrees(), 0.0]);
        assert_eq!([&pitch[0], &pitch[2]], [&[0.0, 0.0], &[0.0, 0.0]]);
        // A column the run does not give is an error, not a plot of another.
        let error = attitude_degrees(&rows, &Orientation::Heading("yaw".into())).unwrap_err();
        assert!(error.to_string().contains("yaw"), "{error}");
    }
}
