//! `trajectory.csv`: one row per sample time, streamed as the run goes.
//!
//! The header is `t`, the model's state names as its layout names them (in identifiers:
//! `x` for X), then `kinetic_energy`, and `potential_energy`, `total_energy` where the loads
//! have a potential. Numbers are written in Rust's shortest form that reads back to the same
//! bits. The file is flushed at least every quarter of a second, so an interrupted run leaves
//! every complete row readable; a row is never split across a flush of the CSV writer's own
//! buffer, since the writer is flushed only between rows.

use crate::run::{Row, Sink};
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// How often the file is flushed while a run goes on.
const FLUSH_EVERY: Duration = Duration::from_millis(250);

/// Writes trajectory rows to a CSV file, and keeps the columns the plots need.
pub struct TrajectoryWriter {
    path: PathBuf,
    writer: csv::Writer<BufWriter<File>>,
    with_potential: bool,
    record: csv::ByteRecord,
    last_flush: Instant,
    error: Option<std::io::Error>,
    kept: Columns,
    /// Keep every `stride`-th row for the plots.
    stride: usize,
    rows: usize,
    /// Called with the time of each row (a progress bar).
    on_row: Option<Box<dyn FnMut(f64)>>,
}

/// The rows kept for the plots: every `stride`-th.
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
        with_potential: bool,
        expected_rows: usize,
    ) -> std::io::Result<Self> {
        let file = File::create(path)?;
        let mut writer = csv::Writer::from_writer(BufWriter::new(file));
        let mut header: Vec<&str> = vec!["t"];
        header.extend(state_names.iter().map(String::as_str));
        header.push("kinetic_energy");
        if with_potential {
            header.extend(["potential_energy", "total_energy"]);
        }
        writer.write_record(&header).map_err(std::io::Error::from)?;
        writer.flush()?;
        Ok(Self {
            path: path.to_owned(),
            writer,
            with_potential,
            record: csv::ByteRecord::new(),
            last_flush: Instant::now(),
            error: None,
            kept: Columns {
                state: vec![Vec::new(); state_names.len()],
                ..Columns::default()
            },
            stride: expected_rows.div_ceil(200_000).max(1),
            rows: 0,
            on_row: None,
        })
    }

    /// Calls `f` with the time of each row (for a progress bar).
    pub fn on_row(&mut self, f: impl FnMut(f64) + 'static) {
        self.on_row = Some(Box::new(f));
    }

    /// Flushes what is left and returns the kept columns, or the first write error.
    pub fn finish(mut self) -> std::io::Result<Columns> {
        if let Some(error) = self.error.take() {
            return Err(error);
        }
        self.writer.flush()?;
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

    fn write(&mut self, row: &Row) -> std::io::Result<()> {
        let mut number = ryu::Buffer::new();
        let mut field = |record: &mut csv::ByteRecord, x: f64| {
            if x.is_finite() {
                record.push_field(number.format_finite(x).as_bytes());
            } else {
                record.push_field(x.to_string().as_bytes());
            }
        };
        self.record.clear();
        field(&mut self.record, row.t);
        for &x in row.state {
            field(&mut self.record, x);
        }
        field(&mut self.record, row.kinetic_energy);
        if self.with_potential {
            let potential = row.potential_energy.unwrap_or(f64::NAN);
            field(&mut self.record, potential);
            field(&mut self.record, row.kinetic_energy + potential);
        }
        self.writer.write_byte_record(&self.record)?;
        if self.last_flush.elapsed() >= FLUSH_EVERY {
            self.writer.flush()?;
            self.last_flush = Instant::now();
        }
        Ok(())
    }

    fn keep(&mut self, row: &Row) {
        if self.rows % self.stride == 0 {
            self.kept.time.push(row.t);
            for (column, &x) in self.kept.state.iter_mut().zip(row.state) {
                column.push(x);
            }
            self.kept
                .energy
                .push(row.kinetic_energy + row.potential_energy.unwrap_or(0.0));
            self.kept.kinetic.push(row.kinetic_energy);
        }
        self.rows += 1;
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
