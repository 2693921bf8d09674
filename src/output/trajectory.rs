//! `trajectory.csv`: one row per sample time, streamed as the run goes.
//!
//! The header is `t`, the model's state names as its layout names them (in identifiers:
//! `x` for X), then `kinetic_energy`, and `potential_energy`, `total_energy` where the loads
//! have a potential; each name carries its unit in brackets, `t[s]`, `u[m/s]`, `psi[rad]`,
//! `q0[-]`, `kinetic_energy[J]` ([`crate::models::with_unit`], the states' units from
//! [`crate::models::state_unit`]), so that a file read alone says what it holds.
//! Numbers are written in Rust's shortest form that reads back to the same bits (`NaN`, `inf`
//! and `-inf` as Rust writes them).
//!
//! What survives a run that is cut short: rows are gathered whole in the writer's own buffer
//! and handed to the file only whole, at least every quarter of a second and whenever 64 KiB
//! have gathered, so once the process is gone (Ctrl-C, `kill -9`, a crash) the file holds
//! every row up to the last hand-over, each ending in a newline. Only a write that the kernel
//! itself cuts short (a kill in the middle of a large write, a full disk) can leave a last line
//! without its newline, and a reader can tell it is partial by that: every complete row ends
//! with `\n`. What reached the file survives the process, not the machine losing power (it is
//! not synced to the disk).

use crate::models::{ENERGY_UNIT, TIME_UNIT, state_with_unit, with_unit};
use crate::run::{Row, Sink};
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// How often the rows gathered are handed to the file while a run goes on.
const FLUSH_EVERY: Duration = Duration::from_millis(250);

/// How many bytes of rows are gathered at most before they are handed to the file.
const BUFFER_BYTES: usize = 64 * 1024;

/// Writes trajectory rows to a CSV file, and keeps the columns the plots need.
pub struct TrajectoryWriter {
    path: PathBuf,
    file: File,
    /// Whole rows not yet handed to the file.
    buffer: Vec<u8>,
    with_potential: bool,
    last_flush: Instant,
    error: Option<std::io::Error>,
    kept: Columns,
    /// Keep every `stride`-th row for the plots.
    stride: usize,
    rows: usize,
    /// The last row written, when the stride did not keep it (t, energy, kinetic energy, and
    /// its state in `last_state`): added to the columns at the end, so that the plots always
    /// reach the run's last row, a run stopped early included.
    last_unkept: Option<(f64, f64, f64)>,
    last_state: Vec<f64>,
    /// Called with the time of each row (a progress bar).
    on_row: Option<Box<dyn FnMut(f64)>>,
}

/// The rows kept for the plots: every `stride`-th, and the last.
#[derive(Debug, Default, Clone)]
pub struct Columns {
    /// The times.
    pub time: Vec<f64>,
    /// One vector per state entry.
    pub state: Vec<Vec<f64>>,
    /// The total energy (kinetic plus potential), where the loads have a potential, else the
    /// kinetic energy.
    pub energy: Vec<f64>,
    /// The kinetic energy.
    pub kinetic: Vec<f64>,
}

impl TrajectoryWriter {
    /// Creates `path` and writes the header. `expected_rows` sets how many rows are kept for
    /// the plots (at most about 200 000, evenly spaced).
    pub fn create(
        path: &Path,
        state_names: &[String],
        (with_potential, energy_unit): (bool, &str),
        expected_rows: usize,
    ) -> std::io::Result<Self> {
        let mut file = File::create(path)?;
        let header = header_in(state_names, with_potential, energy_unit);
        file.write_all(format!("{}\n", header.join(",")).as_bytes())?;
        Ok(Self {
            path: path.to_owned(),
            file,
            buffer: Vec::with_capacity(BUFFER_BYTES + 4096),
            with_potential,
            last_flush: Instant::now(),
            error: None,
            kept: Columns {
                state: vec![Vec::new(); state_names.len()],
                ..Columns::default()
            },
            stride: expected_rows.div_ceil(200_000).max(1),
            rows: 0,
            last_unkept: None,
            last_state: vec![0.0; state_names.len()],
            on_row: None,
        })
    }

    /// Calls `f` with the time of each row (for a progress bar).
    pub fn on_row(&mut self, f: impl FnMut(f64) + 'static) {
        self.on_row = Some(Box::new(f));
    }

    /// Hands what is left to the file and returns the kept columns, or the first write error.
    pub fn finish(mut self) -> std::io::Result<Columns> {
        if let Some(error) = self.error.take() {
            return Err(error);
        }
        self.flush()?;
        if let Some((t, energy, kinetic)) = self.last_unkept.take() {
            let state = std::mem::take(&mut self.last_state);
            self.push_kept(t, &state, energy, kinetic);
        }
        Ok(self.kept)
    }

    /// The file written.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The first write error, if a row could not be written.
    pub fn error(&self) -> Option<&std::io::Error> {
        self.error.as_ref()
    }

    /// The first write error, taken whole (its kind kept: a full disk stays `StorageFull`).
    pub fn take_error(&mut self) -> Option<std::io::Error> {
        self.error.take()
    }

    /// The rows gathered, handed to the file in one write.
    fn flush(&mut self) -> std::io::Result<()> {
        self.last_flush = Instant::now();
        let result = self.file.write_all(&self.buffer);
        self.buffer.clear();
        result
    }

    fn write(&mut self, row: &Row) -> std::io::Result<()> {
        let mut number = ryu::Buffer::new();
        let buffer = &mut self.buffer;
        let mut field = |x: f64| {
            push_number(buffer, &mut number, x);
            buffer.push(b',');
        };
        field(row.t);
        for &x in row.state {
            field(x);
        }
        field(row.kinetic_energy);
        if self.with_potential {
            let potential = row.potential_energy.unwrap_or(f64::NAN);
            field(potential);
            field(row.kinetic_energy + potential);
        }
        // The last field's comma becomes the row's end.
        if let Some(last) = self.buffer.last_mut() {
            *last = b'\n';
        }
        if self.buffer.len() >= BUFFER_BYTES || self.last_flush.elapsed() >= FLUSH_EVERY {
            self.flush()?;
        }
        Ok(())
    }

    fn keep(&mut self, row: &Row) {
        let energy = row.kinetic_energy + row.potential_energy.unwrap_or(0.0);
        if self.rows.is_multiple_of(self.stride) {
            self.push_kept(row.t, row.state, energy, row.kinetic_energy);
            self.last_unkept = None;
        } else {
            self.last_state.copy_from_slice(row.state);
            self.last_unkept = Some((row.t, energy, row.kinetic_energy));
        }
        self.rows += 1;
    }

    fn push_kept(&mut self, t: f64, state: &[f64], energy: f64, kinetic: f64) {
        self.kept.time.push(t);
        for (column, &x) in self.kept.state.iter_mut().zip(state) {
            column.push(x);
        }
        self.kept.energy.push(energy);
        self.kept.kinetic.push(kinetic);
    }
}

impl Sink for TrajectoryWriter {
    fn row(&mut self, row: &Row) -> bool {
        if let Err(e) = self.write(row) {
            self.error = Some(e);
            return false;
        }
        self.keep(row);
        if let Some(on_row) = self.on_row.as_mut() {
            on_row(row.t);
        }
        true
    }
}

/// The columns of `trajectory.csv` as [`TrajectoryWriter`] labels them: `t`, each state
/// entry by its name, `kinetic_energy`, and `potential_energy`, `total_energy` where
/// `with_potential`, each with its unit.
pub fn header(state_names: &[impl AsRef<str>], with_potential: bool) -> Vec<String> {
    header_in(state_names, with_potential, ENERGY_UNIT)
}

/// [`header`] with the energies in `energy_unit`; a state name that already says its unit
/// (`vt[ft/s]`, a model in a scene's own units) is written as given.
pub fn header_in(
    state_names: &[impl AsRef<str>],
    with_potential: bool,
    energy_unit: &str,
) -> Vec<String> {
    let mut header = vec![with_unit("t", TIME_UNIT)];
    header.extend(state_names.iter().map(|name| {
        let name = name.as_ref();
        match name.contains('[') {
            true => name.to_owned(),
            false => state_with_unit(name),
        }
    }));
    header.push(with_unit("kinetic_energy", energy_unit));
    if with_potential {
        header.extend(["potential_energy", "total_energy"].map(|n| with_unit(n, energy_unit)));
    }
    header
}

/// Appends `x` as every trajectory file writes a number: in Rust's shortest form that reads
/// back to the same bits, `NaN`, `inf` and `-inf` as Rust writes them.
pub fn push_number(line: &mut Vec<u8>, number: &mut ryu::Buffer, x: f64) {
    if x.is_finite() {
        line.extend_from_slice(number.format_finite(x).as_bytes());
    } else {
        line.extend_from_slice(x.to_string().as_bytes());
    }
}

/// `x` as every trajectory file writes a number ([`push_number`]): for the tables beside them
/// (`sweep.csv`), so that one number reads the same in each.
pub fn number_text(x: f64) -> String {
    let mut line = Vec::new();
    push_number(&mut line, &mut ryu::Buffer::new(), x);
    String::from_utf8(line).expect("ryu writes ASCII")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A run stopped long before its expected end (a signal, a failure) still gives the plots
    /// its first and its last row, however coarse the stride of the run it was meant to be.
    #[test]
    fn the_kept_columns_end_at_the_last_row_written() {
        let path = std::env::temp_dir().join(format!("eom-kept-{}.csv", std::process::id()));
        let names = ["theta".to_owned(), "theta_dot".to_owned()];
        let mut writer =
            TrajectoryWriter::create(&path, &names, (false, "J"), 100_000_000).unwrap();
        assert_eq!(writer.stride, 500);
        for k in 0..300 {
            let state = [k as f64, 0.0];
            let row = Row {
                t: k as f64 * 0.01,
                state: &state,
                kinetic_energy: 1.0,
                potential_energy: None,
            };
            assert!(writer.row(&row));
        }
        let kept = writer.finish().unwrap();
        let _ = std::fs::remove_file(&path);
        assert_eq!(kept.time, [0.0, 2.99]);
        assert_eq!(kept.state[0], [0.0, 299.0]);
        assert_eq!(kept.kinetic.len(), 2);
    }
}
