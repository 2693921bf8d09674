//! Loads that change with time, given as a table of (t, value).
//!
//! Any of the loads a scene states as a constant force or moment (`force_body`,
//! `force_space`, `moment_body`, `moment_space`, `moment`) may instead be a table:
//!
//! ```toml
//! [loads.moment_body]            # or inline: moment_body = { times = …, values = …, … }
//! times = [0.0, 1.0]             # s, strictly increasing
//! values = [[0.0, 0.0, 0.0], [0.0, 0.0, 2.0]]
//! interpolation = "step"         # or "linear"
//! ```
//!
//! `"step"` holds each value from its time until the next time (a value switches at its own
//! time, so at t = 1 the torque above is already 2 N m); `"linear"` goes straight from each
//! value to the next, so ramps and piecewise-linear profiles are tables of their corners.
//! Before the first time the first value holds, after the last time the last value: a table
//! is never extrapolated. A torque switched on at 1 s is thus `times = [0, 1]` with a zero
//! first value; `times = [1]` alone would hold its one value from the start.
//!
//! A table's times inside the run are its breakpoints: the run is cut there, and each piece
//! is integrated on its own (the fixed-step methods land on each breakpoint, the adaptive
//! methods start afresh from it), so that no step straddles a jump or a kink and an
//! adaptive method's error estimate never sees one. Within a piece every table is a constant
//! or a straight line, read by the piece itself rather than by the time alone: the stages of
//! a step that ends on a breakpoint see the value before it, and the steps after it the
//! value after it. A scene with a table has no energy drift to report: a load that changes
//! with time has no potential.

use super::file::TableSpec;
use crate::Short;
use crate::validate::Requirement;

/// Which of a scene's loads a table gives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// `force_body`.
    ForceBody,
    /// `force_space`.
    ForceSpace,
    /// `moment_body`.
    MomentBody,
    /// `moment_space`.
    MomentSpace,
    /// `moment`.
    Moment,
}

/// How a table is read between its times.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interpolation {
    /// Each value until the next time.
    Step,
    /// Straight from each value to the next.
    Linear,
}

/// A load's table, checked: times strictly increasing, values finite, each of the load's
/// number of entries (kept in the first entries of a 3-vector).
#[derive(Debug, Clone, PartialEq)]
pub struct TimeTable {
    times: Vec<f64>,
    values: Vec<[f64; 3]>,
    interpolation: Interpolation,
}

/// A load that a table gives.
#[derive(Debug, Clone, PartialEq)]
pub struct TimedLoad {
    /// The load.
    pub target: Target,
    /// Its values.
    pub table: TimeTable,
}

/// Where a time falls in a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Piece {
    /// Before the first time.
    Before,
    /// From time i up to time i + 1 (the last time and after it: `After`).
    From(usize),
    /// At or after the last time.
    After,
}

impl TimeTable {
    /// Checks a table as written for a load of `width` entries; the error names the entry
    /// by its path under `key` (`times[2]`, `values[1][0]`).
    pub(crate) fn new(
        key: &str,
        spec: &TableSpec<Vec<f64>>,
        width: usize,
    ) -> Result<Self, (String, String)> {
        let at = |path: String, message: String| (format!("{key}{path}"), message);
        let interpolation = match spec.interpolation.as_deref() {
            Some("step") => Interpolation::Step,
            Some("linear") => Interpolation::Linear,
            Some(other) => {
                let message = format!("unknown value `{other}`; one of linear, step");
                return Err(at(".interpolation".into(), message));
            }
            None => {
                let message = "missing: how to read between the times, \"linear\" or \"step\"";
                return Err(at(".interpolation".into(), message.into()));
            }
        };
        check_times(&spec.times).map_err(|(i, m)| at(format!(".times[{i}]"), m))?;
        if spec.values.len() != spec.times.len() {
            let message = format!(
                "must have one value per time: {} values for {} times",
                spec.values.len(),
                spec.times.len()
            );
            return Err(at(".values".into(), message));
        }
        let values = spec
            .values
            .iter()
            .enumerate()
            .map(|(i, v)| entries(v, width).map_err(|(p, m)| at(format!(".values[{i}]{p}"), m)))
            .collect::<Result<_, _>>()?;
        Ok(Self {
            times: spec.times.clone(),
            values,
            interpolation,
        })
    }

    /// A table of a scalar load (`moment`): each value one entry.
    pub(crate) fn scalar(key: &str, spec: &TableSpec<f64>) -> Result<Self, (String, String)> {
        let as_lists = TableSpec {
            times: spec.times.clone(),
            values: spec.values.iter().map(|v| vec![*v]).collect(),
            interpolation: spec.interpolation.clone(),
        };
        Self::new(key, &as_lists, 1).map_err(|(path, message)| {
            // A scalar's value is `values[i]`, not `values[i][0]`.
            (path.replace("][0]", "]"), message)
        })
    }

    /// The table's times, where its value jumps (step) or turns (linear).
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// The value at `t`: a step's new value from its own time on, the end values held
    /// outside the table.
    pub fn at(&self, t: f64) -> [f64; 3] {
        self.read(self.piece(t), t)
    }

    /// The value at `t` on the piece of the run from `a` to `b`, an interval no table time
    /// falls inside: the piece is chosen by the interval, not by `t`, so that a stage at
    /// either end of it reads the interval's own constant or line.
    pub fn at_within(&self, t: f64, (a, b): (f64, f64)) -> [f64; 3] {
        self.read(self.piece(a + 0.5 * (b - a)), t)
    }

    fn piece(&self, t: f64) -> Piece {
        let reached = self.times.partition_point(|&time| time <= t);
        match reached {
            0 => Piece::Before,
            n if n == self.times.len() => Piece::After,
            n => Piece::From(n - 1),
        }
    }

    fn read(&self, piece: Piece, t: f64) -> [f64; 3] {
        let i = match piece {
            Piece::Before => return self.values[0],
            Piece::After => return self.values[self.values.len() - 1],
            Piece::From(i) => i,
        };
        match self.interpolation {
            Interpolation::Step => self.values[i],
            Interpolation::Linear => {
                let (t0, t1) = (self.times[i], self.times[i + 1]);
                let (v0, v1) = (self.values[i], self.values[i + 1]);
                let s = (t - t0) / (t1 - t0);
                std::array::from_fn(|k| v0[k] + (v1[k] - v0[k]) * s)
            }
        }
    }
}

/// At least one time, every one finite and each after the one before it.
fn check_times(times: &[f64]) -> Result<(), (usize, String)> {
    if times.is_empty() {
        return Err((0, "a table needs at least one time".into()));
    }
    for (i, t) in times.iter().enumerate() {
        Requirement::Finite
            .check(*t)
            .map_err(|violation| (i, violation.to_string()))?;
        if i > 0 && *t <= times[i - 1] {
            let message = format!(
                "must be after the time before it, {}, got {} (times increase strictly; a \
                 jump is a step table's switch at one time)",
                Short(times[i - 1]),
                Short(*t)
            );
            return Err((i, message));
        }
    }
    Ok(())
}

/// A value of `width` finite entries, padded to three.
fn entries(value: &[f64], width: usize) -> Result<[f64; 3], (String, String)> {
    if value.len() != width {
        let message = format!("must have {width} entries, got {}", value.len());
        return Err((String::new(), message));
    }
    let mut out = [0.0; 3];
    for (i, (o, v)) in out.iter_mut().zip(value).enumerate() {
        *o = Requirement::Finite
            .check(*v)
            .map_err(|violation| (format!("[{i}]"), violation.to_string()))?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(times: &[f64], values: &[f64], interpolation: &str) -> TimeTable {
        let spec = TableSpec {
            times: times.to_vec(),
            values: values.to_vec(),
            interpolation: Some(interpolation.into()),
        };
        TimeTable::scalar("loads.moment", &spec).unwrap()
    }

    #[test]
    fn steps_switch_at_their_time_and_lines_join_their_corners() {
        let step = table(&[1.0, 2.0], &[3.0, 5.0], "step");
        assert_eq!(
            [0.0, 1.0 - 1e-12, 1.0, 1.5, 2.0, 9.0].map(|x| step.at(x)[0]),
            [3.0, 3.0, 3.0, 3.0, 5.0, 5.0]
        );
        let ramp = table(&[1.0, 3.0], &[0.0, 4.0], "linear");
        assert_eq!(
            [0.0, 1.0, 1.5, 2.0, 3.0, 7.0].map(|x| ramp.at(x)[0]),
            [0.0, 0.0, 1.0, 2.0, 4.0, 4.0]
        );
    }

    #[test]
    fn a_piece_reads_its_own_side_of_a_breakpoint() {
        let step = table(&[0.0, 1.0], &[0.0, 2.0], "step");
        // The step ending at t = 1 sees 0 there; the one starting at 1 sees 2.
        assert_eq!(step.at_within(1.0, (0.0, 1.0))[0], 0.0);
        assert_eq!(step.at_within(1.0, (1.0, 5.0))[0], 2.0);
        assert_eq!(step.at(1.0)[0], 2.0);
    }

    #[test]
    fn bad_tables_name_their_entry() {
        let spec = |times: Vec<f64>, values: Vec<f64>, how: Option<&str>| TableSpec {
            times,
            values,
            interpolation: how.map(String::from),
        };
        let cases = [
            (
                spec(vec![0.0, 0.0], vec![1.0, 2.0], Some("step")),
                "loads.moment.times[1]",
            ),
            (spec(vec![], vec![], Some("step")), "loads.moment.times[0]"),
            (
                spec(vec![0.0, f64::NAN], vec![1.0, 2.0], Some("step")),
                "loads.moment.times[1]",
            ),
            (
                spec(vec![0.0], vec![1.0, 2.0], Some("step")),
                "loads.moment.values",
            ),
            (
                spec(vec![0.0, 1.0], vec![1.0, f64::INFINITY], Some("step")),
                "loads.moment.values[1]",
            ),
            (
                spec(vec![0.0], vec![1.0], Some("cubic")),
                "loads.moment.interpolation",
            ),
            (
                spec(vec![0.0], vec![1.0], None),
                "loads.moment.interpolation",
            ),
        ];
        for (spec, key) in cases {
            let (path, message) = TimeTable::scalar("loads.moment", &spec).unwrap_err();
            assert_eq!(path, key, "{message}");
        }
        let wide = TableSpec {
            times: vec![0.0],
            values: vec![vec![1.0, 2.0]],
            interpolation: Some("step".into()),
        };
        let (path, message) = TimeTable::new("loads.moment_body", &wide, 3).unwrap_err();
        assert_eq!(path, "loads.moment_body.values[0]");
        assert!(message.contains("must have 3 entries"));
    }
}
