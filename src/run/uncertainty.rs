//! A Monte Carlo of a scene of any kind: each case of its `[uncertainty]`
//! ([`crate::scene::uncertainty`]) run to its figures and verdicts, the rows dropped, and what
//! the cases give together: each figure's mean, standard deviation and percentiles, each
//! verdict's pass rate with its 95 % Wilson interval.
//!
//! The statistics are computed from the cases' outcomes alone, in the order of their numbers,
//! and the outcomes go through a table that keeps every digit ([`CasesTable`]): so the shards
//! of a Monte Carlo (`--shard K/N`), merged, give the same numbers as one run of it, bit for
//! bit.
//!
//! A case runs as its kind runs any scene ([`crate::kinds::Kind::run`]), once: its runs are
//! not run again refined ([`crate::run::record::Recorder::refines`]), since what a Monte Carlo
//! reads is the cases' spread, which the scene's method is chosen to resolve (`eom tradeoff`).
//!
//! ```
//! use eom::run::uncertainty::{Statistics, run_cases};
//! use eom::scene::uncertainty::Uncertainty;
//!
//! let text = std::fs::read_to_string("scenes/pendulum.toml")?
//!     + "\n[uncertainty]\ncases = 8\nseed = 1\n[uncertainty.vary]\n\
//!        \"initial.theta_deg\" = { distribution = \"uniform\", low = 10, high = 20 }\n";
//! let uncertainty = Uncertainty::parse(&text, "pendulum.toml")?;
//! let cases: Vec<usize> = (0..uncertainty.cases).collect();
//! let outcomes = run_cases(&uncertainty, &cases, ("pendulum.toml", ".".as_ref()), &|| false);
//! let statistics = Statistics::of(&outcomes, &[5.0, 50.0, 95.0]);
//! let period = statistics.figures.iter().find(|f| f.name == "period_s").unwrap();
//! assert_eq!(period.count, 8);
//! assert!(period.min < period.mean && period.mean < period.max);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod failures;

pub use failures::{FailureGroup, group_failures, refuse_contradicting_laws};

use super::Row;
use super::record::{RecordError, Recorder, RunStart};
use crate::output::drawing::RunDrawings;
use crate::scene::AnyScene;
use crate::scene::uncertainty::Uncertainty;
use rayon::prelude::*;
use serde::Serialize;
use std::path::Path;

/// The percentiles a report gives by default.
pub const PERCENTILES: [f64; 3] = [5.0, 50.0, 95.0];

/// The normal quantile of a two-sided 95 % interval.
const Z_95: f64 = 1.959_963_984_540_054;

/// What one case gave.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseOutcome {
    /// The case's number.
    pub index: usize,
    /// Its values, in the order of [`Uncertainty::varied`].
    pub values: Vec<f64>,
    /// Each figure of each run, by `run/key` (`turning_circle_35/port/advance_m`; the key
    /// alone for a scene's one run), `None` where the run did not give it.
    pub figures: Vec<(String, Option<f64>)>,
    /// Each verdict by its name: passed, failed, or not judged (`None`).
    pub verdicts: Vec<(String, Option<bool>)>,
    /// Why the case failed, if it did (its figures are then those it gave before).
    pub error: Option<String>,
}

/// A recorder for a case: keeps nothing, runs nothing again refined, stops when asked.
struct CaseRecorder<'a> {
    stop: &'a (dyn Fn() -> bool + Sync),
}

impl Recorder for CaseRecorder<'_> {
    fn begin(&mut self, _: RunStart) -> Result<(), RecordError> {
        Ok(())
    }

    fn row(&mut self, _: &Row) -> bool {
        true
    }

    fn end(&mut self) -> Result<(), RecordError> {
        Ok(())
    }

    fn drawn(&mut self, _: RunDrawings) -> Result<(), RecordError> {
        Ok(())
    }

    fn stop_asked(&self) -> bool {
        (self.stop)()
    }

    fn refines(&self) -> bool {
        false
    }

    fn keeps_rows(&self) -> bool {
        false
    }
}

/// Runs case `index` of `uncertainty` (`name` is the scene's file as errors and summaries
/// name it, `base` the folder a file it names is found in), its scene read from its tables
/// with the case's values set; `stop` says when to stop.
pub fn run_case(
    uncertainty: &Uncertainty,
    index: usize,
    scene: (&str, &Path),
    stop: &(dyn Fn() -> bool + Sync),
) -> CaseOutcome {
    run_case_from(uncertainty, index, (None, scene), stop)
}

/// Runs case `index`, its values set into `nominal` (the scene as read, where its kind takes
/// numbers so: [`crate::kinds::Kind::with_numbers`]) or its scene read again from its tables.
fn run_case_from(
    uncertainty: &Uncertainty,
    index: usize,
    (nominal, (name, base)): (Option<&AnyScene>, (&str, &Path)),
    stop: &(dyn Fn() -> bool + Sync),
) -> CaseOutcome {
    let values = uncertainty.values(index);
    let mut outcome = CaseOutcome {
        index,
        values,
        figures: Vec::new(),
        verdicts: Vec::new(),
        error: None,
    };
    let numbers: Vec<(&str, f64)> = (uncertainty.varied.iter())
        .zip(&outcome.values)
        .map(|(number, value)| (number.key.as_str(), *value))
        .collect();
    let taken = nominal.and_then(|nominal| nominal.as_kind().with_numbers(name, &numbers));
    let scene = match taken {
        Some(scene) => scene,
        None => {
            let table = uncertainty.table_with(&outcome.values);
            AnyScene::from_table(table, name, base).map(AnyScene::into_kind)
        }
    };
    let scene = match scene {
        Ok(scene) => scene,
        Err(error) => {
            outcome.error = Some(error.to_string());
            return outcome;
        }
    };
    let mut recorder = CaseRecorder { stop };
    let finished = match scene.run(name, &mut recorder) {
        Ok(finished) => finished,
        Err(error) => {
            outcome.error = Some(error.to_string());
            return outcome;
        }
    };
    let (runs, verdicts) = finished.figures();
    for run in runs {
        for figure in &run.figures {
            let name = match run.run.is_empty() {
                true => figure.key.clone(),
                false => format!("{}/{}", run.run, figure.key),
            };
            outcome.figures.push((name, figure.value));
        }
    }
    outcome.verdicts = (verdicts.iter())
        .map(|verdict| (verdict.name.clone(), verdict.pass))
        .collect();
    outcome.error = match (finished.stopped(), finished.failure()) {
        (true, _) => Some("interrupted".to_owned()),
        (false, Some(error)) => Some(error.to_string()),
        (false, None) => None,
    };
    outcome
}

/// Runs the cases `indices` on every core, their outcomes in the order of `indices`. The
/// scene is read once, and each case's values set into it where its kind takes numbers so;
/// a case that fails leaves the others running; once `stop` holds, the cases not begun are
/// not run and say so.
pub fn run_cases(
    uncertainty: &Uncertainty,
    indices: &[usize],
    scene: (&str, &Path),
    stop: &(dyn Fn() -> bool + Sync),
) -> Vec<CaseOutcome> {
    let (name, base) = scene;
    let nominal = AnyScene::from_table(uncertainty.nominal().clone(), name, base).ok();
    indices
        .par_iter()
        .map(|&index| match stop() {
            true => CaseOutcome {
                index,
                values: uncertainty.values(index),
                figures: Vec::new(),
                verdicts: Vec::new(),
                error: Some("not run: the Monte Carlo was interrupted".to_owned()),
            },
            false => run_case_from(uncertainty, index, (nominal.as_ref(), scene), stop),
        })
        .collect()
}

/// `uncertainty.json`'s bytes: the varied keys, the `percentiles` `statistics` was computed
/// with, and `statistics`; nothing
/// that differs between one run and its shards merged (no wall time), so that the two files
/// are the same bytes.
pub fn report_json(varied: &[String], percentiles: &[f64], statistics: &Statistics) -> Vec<u8> {
    #[derive(Serialize)]
    struct Report<'a> {
        /// The varied keys, in the order each case draws them.
        varied: &'a [String],
        /// The percentiles each figure gives.
        percentiles: &'a [f64],
        #[serde(flatten)]
        statistics: &'a Statistics,
    }
    let report = Report {
        varied,
        percentiles,
        statistics,
    };
    // Plain data: serialising it cannot fail.
    let mut bytes = serde_json::to_vec_pretty(&report).unwrap_or_default();
    bytes.push(b'\n');
    bytes
}

/// One figure over the cases that gave it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FigureStatistics {
    /// `run/key`, as [`CaseOutcome::figures`] names it.
    pub name: String,
    /// How many cases gave it.
    pub count: usize,
    /// How many cases ran without error but did not give it (their runs' notes say why).
    pub missing: usize,
    /// The mean.
    pub mean: f64,
    /// The sample standard deviation (n − 1; zero for one case).
    pub std: f64,
    /// The smallest value.
    pub min: f64,
    /// The largest value.
    pub max: f64,
    /// (p, the p-th percentile), linear between order statistics (Hyndman & Fan's type 7,
    /// numpy's default).
    pub percentiles: Vec<(f64, f64)>,
}

/// One verdict over the cases that judged it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct VerdictRate {
    /// Its name.
    pub name: String,
    /// How many cases judged it.
    pub judged: usize,
    /// How many of them passed.
    pub passed: usize,
    /// How many cases ran without error but could not judge it.
    pub not_judged: usize,
    /// passed / judged.
    pub rate: f64,
    /// The 95 % Wilson score interval of the rate.
    pub wilson_95: (f64, f64),
}

/// What the cases give together.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Statistics {
    /// How many cases ran.
    pub cases: usize,
    /// The cases that failed, with why (their figures and verdicts are not counted).
    pub failed: Vec<(usize, String)>,
    /// The same cases by reason, the most frequent first.
    pub failure_reasons: Vec<FailureGroup>,
    /// Each figure, in the order the first case that gave figures lists them.
    pub figures: Vec<FigureStatistics>,
    /// Each verdict, in the same order.
    pub verdicts: Vec<VerdictRate>,
}

impl Statistics {
    /// The statistics of `outcomes`, taken in the order of their case numbers (so that the
    /// shards of a Monte Carlo, merged, give the numbers of one run), with the `percentiles`
    /// (each in [0, 100]).
    pub fn of(outcomes: &[CaseOutcome], percentiles: &[f64]) -> Self {
        let (ran, failed) = in_order(outcomes);
        let figures = (columns(&ran, figures_of).into_iter())
            .map(|(name, values)| FigureStatistics::of(name, &values, percentiles))
            .collect();
        let verdicts = (columns(&ran, verdicts_of).into_iter())
            .map(|(name, verdicts)| VerdictRate::of(name, &verdicts))
            .collect();
        let failed: Vec<(usize, String)> = (failed.iter())
            .map(|o| (o.index, o.error.clone().unwrap_or_default()))
            .collect();
        Statistics {
            cases: outcomes.len(),
            failure_reasons: group_failures(&failed),
            failed,
            figures,
            verdicts,
        }
    }

    /// The report as the command prints it: each figure's spread, each verdict's rate.
    pub fn report(&self) -> String {
        use std::fmt::Write;
        let mut out = String::new();
        let width = (self.figures.iter().map(|f| f.name.chars().count()))
            .chain(self.verdicts.iter().map(|v| v.name.chars().count()))
            .max()
            .unwrap_or(6)
            .max(6);
        let ran = self.cases - self.failed.len();
        let _ = writeln!(out, "{ran} of {} cases ran", self.cases);
        // A figure the same in every case that gave it (one the varied values do not reach)
        // has no spread to show: it is said once, after the table.
        let (varying, constant): (Vec<&FigureStatistics>, Vec<&FigureStatistics>) =
            (self.figures.iter()).partition(|figure| !figure.is_constant());
        if !varying.is_empty() {
            let _ = write!(
                out,
                "  {:<width$} {:>7} {:>12} {:>11}",
                "figure", "cases", "mean", "std"
            );
            if let Some(figure) = varying.first() {
                for (p, _) in &figure.percentiles {
                    let _ = write!(out, " {:>11}", format!("p{p}"));
                }
            }
            out.push('\n');
            for figure in &varying {
                let shown = |value: f64| match figure.count {
                    0 => "—".to_owned(),
                    _ => significant(value),
                };
                let _ = write!(
                    out,
                    "  {:<width$} {:>7} {:>12} {:>11}",
                    figure.name,
                    figure.count,
                    shown(figure.mean),
                    shown(figure.std)
                );
                for (_, value) in &figure.percentiles {
                    let _ = write!(out, " {:>11}", shown(*value));
                }
                if figure.missing > 0 {
                    let _ = write!(out, "  ({} cases did not give it)", figure.missing);
                }
                out.push('\n');
            }
        }
        if !constant.is_empty() {
            let said: Vec<String> = (constant.iter())
                .map(|figure| format!("{} = {}", figure.name, crate::Short(figure.min)))
                .collect();
            let _ = writeln!(out, "  the same in every case: {}", said.join(", "));
        }
        if !self.verdicts.is_empty() {
            let _ = writeln!(
                out,
                "  {:<width$} {:>7} {:>7} {:>8}   95% Wilson interval",
                "verdict", "judged", "pass", "rate"
            );
            for verdict in &self.verdicts {
                let note = match verdict.not_judged {
                    0 => String::new(),
                    n => format!("  ({n} not judged)"),
                };
                if verdict.judged == 0 {
                    let _ = writeln!(
                        out,
                        "  {:<width$} {:>7} {:>7} {:>8}{note}",
                        verdict.name, 0, 0, "—"
                    );
                    continue;
                }
                let (low, high) = verdict.wilson_95;
                let _ = writeln!(
                    out,
                    "  {:<width$} {:>7} {:>7} {:>8.4}   [{low:.4}, {high:.4}]{note}",
                    verdict.name, verdict.judged, verdict.passed, verdict.rate
                );
            }
        }
        for group in &self.failure_reasons {
            let _ = match group.count {
                1 => writeln!(out, "  case {} failed: {}", group.first_case, group.example),
                n => writeln!(
                    out,
                    "  {n} cases failed so, the first case {}: {}",
                    group.first_case, group.example
                ),
            };
        }
        out
    }
}

/// Each figure's values over the cases that ran and gave it, in the order of
/// [`Statistics::figures`]: what a plot of their distributions draws.
pub fn figure_values(outcomes: &[CaseOutcome]) -> Vec<(&str, Vec<f64>)> {
    let (ran, _) = in_order(outcomes);
    (columns(&ran, figures_of).into_iter())
        .map(|(name, values)| (name, values.into_iter().flatten().collect()))
        .collect()
}

/// The cases that ran and those that failed, each in the order of their case numbers (so that
/// the shards of a Monte Carlo, merged, give the numbers of one run).
fn in_order(outcomes: &[CaseOutcome]) -> (Vec<&CaseOutcome>, Vec<&CaseOutcome>) {
    let mut ordered: Vec<&CaseOutcome> = outcomes.iter().collect();
    ordered.sort_by_key(|outcome| outcome.index);
    ordered.into_iter().partition(|o| o.error.is_none())
}

/// A case's figures or verdicts: each by its name, `None` where the case did not give it.
type Named<T> = [(String, Option<T>)];

fn figures_of(outcome: &CaseOutcome) -> &Named<f64> {
    &outcome.figures
}

fn verdicts_of(outcome: &CaseOutcome) -> &Named<bool> {
    &outcome.verdicts
}

/// Each entry of the cases' lists (`list`: their figures or their verdicts) by its name, in
/// the order the first case lists them, with each case's value: `None` where the case did not
/// give it, or lists another name at its place (every case of a scene lists them alike).
fn columns<'a, T: Copy + 'a>(
    ran: &[&'a CaseOutcome],
    list: fn(&CaseOutcome) -> &Named<T>,
) -> Vec<(&'a str, Vec<Option<T>>)> {
    let first = ran.first().map_or(&[][..], |outcome| list(outcome));
    (first.iter().enumerate())
        .map(|(at, (name, _))| {
            let values = (ran.iter())
                .map(|o| list(o).get(at).filter(|(n, _)| n == name).and_then(|e| e.1))
                .collect();
            (name.as_str(), values)
        })
        .collect()
}

/// A number with six significant digits, as a report prints it.
fn significant(value: f64) -> String {
    if value == 0.0 || !value.is_finite() {
        return format!("{value}");
    }
    let digits = 5 - value.abs().log10().floor() as i32;
    match (0..=9).contains(&digits) {
        true => format!("{value:.*}", digits as usize),
        false => format!("{value:.5e}"),
    }
}

impl FigureStatistics {
    /// Whether every case that gave it gave the same value (and at least one did).
    pub fn is_constant(&self) -> bool {
        self.count > 0 && self.min == self.max
    }

    /// The statistics of one figure's `values` over the cases (`None`: not given).
    fn of(name: &str, values: &[Option<f64>], percentiles: &[f64]) -> Self {
        let given: Vec<f64> = values.iter().flatten().copied().collect();
        let n = given.len();
        let mean = given.iter().sum::<f64>() / n as f64;
        let variance = match n {
            0 => f64::NAN,
            1 => 0.0,
            _ => given.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64,
        };
        let mut sorted = given.clone();
        sorted.sort_by(f64::total_cmp);
        FigureStatistics {
            name: name.to_owned(),
            count: n,
            missing: values.len() - n,
            mean,
            std: variance.sqrt(),
            min: sorted.first().copied().unwrap_or(f64::NAN),
            max: sorted.last().copied().unwrap_or(f64::NAN),
            percentiles: (percentiles.iter())
                .map(|&p| (p, percentile(&sorted, p)))
                .collect(),
        }
    }
}

/// The `p`-th percentile of `sorted` (type 7: linear between the order statistics at
/// (n − 1)·p/100); NaN for no values.
pub fn percentile(sorted: &[f64], p: f64) -> f64 {
    let Some(last) = sorted.len().checked_sub(1) else {
        return f64::NAN;
    };
    let at = last as f64 * (p / 100.0).clamp(0.0, 1.0);
    let below = at.floor() as usize;
    let above = (below + 1).min(last);
    let fraction = at - below as f64;
    sorted[below] + fraction * (sorted[above] - sorted[below])
}

impl VerdictRate {
    /// The rate of one verdict over the cases (`None`: not judged).
    fn of(name: &str, verdicts: &[Option<bool>]) -> Self {
        let judged = verdicts.iter().flatten().count();
        let passed = verdicts.iter().filter(|v| **v == Some(true)).count();
        VerdictRate {
            name: name.to_owned(),
            judged,
            passed,
            not_judged: verdicts.len() - judged,
            rate: passed as f64 / judged as f64,
            wilson_95: wilson(passed, judged, Z_95),
        }
    }
}

/// The Wilson score interval of `passed` in `n` at the normal quantile `z`: it stays within
/// [0, 1] and keeps its coverage near 0 and 1, where the normal approximation's does not.
/// NaN for n = 0.
pub fn wilson(passed: usize, n: usize, z: f64) -> (f64, f64) {
    if n == 0 {
        return (f64::NAN, f64::NAN);
    }
    let n = n as f64;
    let p = passed as f64 / n;
    let centre = p + z * z / (2.0 * n);
    let spread = z * (p * (1.0 - p) / n + z * z / (4.0 * n * n)).sqrt();
    let scale = 1.0 + z * z / n;
    ((centre - spread) / scale, (centre + spread) / scale)
}

/// The cases' outcomes as a CSV table that keeps every digit: `case`, each varied value
/// (`value:<key>`), each figure (`figure:<run/key>`, empty where not given), each verdict
/// (`pass:<name>`: `true`, `false`, or empty where not judged), `error`. What a shard writes
/// and what merging shards reads back.
pub struct CasesTable;

/// The cell of the entry `name` of a case's figures or verdicts: its value every digit kept
/// (Rust's shortest round trip), empty where the case did not give it.
fn cell<T: ToString>(list: &Named<T>, name: &str) -> String {
    (list.iter().find(|(n, _)| n == name))
        .and_then(|(_, value)| value.as_ref().map(T::to_string))
        .unwrap_or_default()
}

/// A cases table that cannot be read back.
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct TableError(String);

impl CasesTable {
    /// The table of `outcomes` (in their order), its columns those of `varied` and of the
    /// first case that gave figures.
    pub fn write(varied: &[String], outcomes: &[CaseOutcome]) -> String {
        let first = outcomes
            .iter()
            .find(|o| !o.figures.is_empty() || !o.verdicts.is_empty());
        let figures: Vec<&str> = (first.into_iter().flat_map(|o| &o.figures))
            .map(|(n, _)| n.as_str())
            .collect();
        let verdicts: Vec<&str> = (first.into_iter().flat_map(|o| &o.verdicts))
            .map(|(n, _)| n.as_str())
            .collect();
        let mut header = vec!["case".to_owned()];
        header.extend(varied.iter().map(|k| format!("value:{k}")));
        header.extend(figures.iter().map(|f| format!("figure:{f}")));
        header.extend(verdicts.iter().map(|v| format!("pass:{v}")));
        header.push("error".to_owned());
        let mut writer = csv::Writer::from_writer(Vec::new());
        let _ = writer.write_record(&header);
        for outcome in outcomes {
            let mut row = vec![outcome.index.to_string()];
            row.extend(outcome.values.iter().map(|v| v.to_string()));
            row.extend(figures.iter().map(|name| cell(&outcome.figures, name)));
            row.extend(verdicts.iter().map(|name| cell(&outcome.verdicts, name)));
            row.push(outcome.error.clone().unwrap_or_default());
            let _ = writer.write_record(&row);
        }
        String::from_utf8(writer.into_inner().unwrap_or_default()).unwrap_or_default()
    }

    /// The varied keys and the outcomes of a table [`CasesTable::write`] wrote. A case that
    /// failed reads back without the figures it had not given.
    pub fn read(text: &str) -> Result<(Vec<String>, Vec<CaseOutcome>), TableError> {
        let mut reader = csv::Reader::from_reader(text.as_bytes());
        let header = reader
            .headers()
            .map_err(|e| TableError(e.to_string()))?
            .clone();
        if header.is_empty() {
            return Ok((Vec::new(), Vec::new()));
        }
        let column = |prefix: &str| -> Vec<(usize, String)> {
            (header.iter().enumerate())
                .filter_map(|(i, h)| h.strip_prefix(prefix).map(|n| (i, n.to_owned())))
                .collect()
        };
        let (values, figures, verdicts) = (column("value:"), column("figure:"), column("pass:"));
        let error_column = header.iter().position(|h| h == "error");
        if header.get(0) != Some("case") || error_column.is_none() {
            return Err(TableError("not a table of a Monte Carlo's cases".into()));
        }
        let mut outcomes = Vec::new();
        for (line, record) in reader.records().enumerate() {
            let record = record.map_err(|e| TableError(e.to_string()))?;
            let wrong = |what: &str| TableError(format!("line {}: {what}", line + 2));
            let cell = |i: usize| record.get(i).unwrap_or_default();
            let index = cell(0).parse().map_err(|_| wrong("no case number"))?;
            let number = |i: usize| match cell(i) {
                "" => Ok(None),
                text => text.parse::<f64>().map(Some).map_err(|_| wrong(text)),
            };
            let error = error_column.map(cell).filter(|e| !e.is_empty());
            let failed = error.is_some();
            let mut outcome = CaseOutcome {
                index,
                values: (values.iter())
                    .map(|(i, _)| number(*i).map(|v| v.unwrap_or(f64::NAN)))
                    .collect::<Result<_, _>>()?,
                figures: Vec::new(),
                verdicts: Vec::new(),
                error: error.map(str::to_owned),
            };
            for (i, name) in &figures {
                let value = number(*i)?;
                if !(failed && value.is_none()) {
                    outcome.figures.push((name.clone(), value));
                }
            }
            for (i, name) in &verdicts {
                let verdict = match cell(*i) {
                    "true" => Some(true),
                    "false" => Some(false),
                    "" => None,
                    other => return Err(wrong(other)),
                };
                if !(failed && verdict.is_none()) {
                    outcome.verdicts.push((name.clone(), verdict));
                }
            }
            outcomes.push(outcome);
        }
        let varied = values.into_iter().map(|(_, key)| key).collect();
        Ok((varied, outcomes))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outcome(index: usize, value: Option<f64>, pass: Option<bool>) -> CaseOutcome {
        CaseOutcome {
            index,
            values: vec![index as f64 * 0.1],
            figures: vec![("turn/advance_m".into(), value)],
            verdicts: vec![("advance".into(), pass)],
            error: None,
        }
    }

    #[test]
    fn percentiles_are_numpys_default() {
        // numpy.percentile([1, 2, 3, 4, 10], [0, 5, 50, 95, 100]) = [1, 1.2, 3, 8.8, 10].
        let sorted = [1.0, 2.0, 3.0, 4.0, 10.0];
        let got: Vec<f64> = [0.0, 5.0, 50.0, 95.0, 100.0]
            .iter()
            .map(|&p| percentile(&sorted, p))
            .collect();
        for (got, want) in got.iter().zip([1.0, 1.2, 3.0, 8.8, 10.0]) {
            assert!((got - want).abs() < 1e-12, "{got} {want}");
        }
        assert!(percentile(&[], 50.0).is_nan());
    }

    #[test]
    fn wilson_intervals_match_their_published_values() {
        // Newcombe (1998), Statistics in Medicine 17, 857–872, Table I: 81/263 gives
        // 0.2553–0.3662; 15/148, 0.0624–0.1605; 0/20, 0–0.1611.
        let cases = [
            ((81, 263), (0.2553, 0.3662)),
            ((15, 148), (0.0624, 0.1605)),
            ((0, 20), (0.0, 0.1611)),
        ];
        for ((passed, n), (low, high)) in cases {
            let (l, h) = wilson(passed, n, Z_95);
            assert!(
                (l - low).abs() < 5e-5 && (h - high).abs() < 5e-5,
                "{passed}/{n}: {l} {h}"
            );
        }
    }

    #[test]
    fn statistics_count_what_was_given_and_judged() {
        let outcomes = vec![
            outcome(2, Some(3.0), Some(true)),
            outcome(0, Some(1.0), Some(false)),
            outcome(1, None, None),
            CaseOutcome {
                error: Some("diverged".into()),
                ..outcome(3, Some(100.0), Some(true))
            },
            outcome(4, Some(2.0), Some(true)),
        ];
        let statistics = Statistics::of(&outcomes, &PERCENTILES);
        assert_eq!(statistics.cases, 5);
        assert_eq!(statistics.failed, vec![(3, "diverged".to_owned())]);
        let advance = &statistics.figures[0];
        assert_eq!((advance.count, advance.missing), (3, 1));
        assert_eq!((advance.mean, advance.std), (2.0, 1.0));
        assert_eq!((advance.min, advance.max), (1.0, 3.0));
        assert_eq!(advance.percentiles[1], (50.0, 2.0));
        let rate = &statistics.verdicts[0];
        assert_eq!((rate.judged, rate.passed, rate.not_judged), (3, 2, 1));
        assert!(statistics.report().contains("case 3 failed: diverged"));
        // What the plot draws: the values given by the cases that ran, in case order.
        let drawn = figure_values(&outcomes);
        assert_eq!(drawn, vec![("turn/advance_m", vec![1.0, 3.0, 2.0])]);
    }

    #[test]
    fn a_figure_the_same_in_every_case_is_said_once_not_tabled() {
        let outcomes: Vec<CaseOutcome> = (0..4)
            .map(|index| {
                let mut case = outcome(index, Some(index as f64), Some(true));
                case.figures.push(("turn/rudder_deg".into(), Some(35.0)));
                case
            })
            .collect();
        let report = Statistics::of(&outcomes, &PERCENTILES).report();
        let tabled: Vec<&str> = report.lines().filter(|l| l.contains("turn/")).collect();
        assert_eq!(tabled.len(), 2, "{report}");
        assert!(
            tabled[0].trim_start().starts_with("turn/advance_m"),
            "{report}"
        );
        assert_eq!(
            tabled[1].trim(),
            "the same in every case: turn/rudder_deg = 35",
            "{report}"
        );
    }

    #[test]
    fn the_table_reads_back_to_the_same_outcomes_and_statistics() {
        let outcomes = vec![
            outcome(0, Some(0.1 + 0.2), Some(true)),
            outcome(1, None, None),
            outcome(2, Some(1.0 / 3.0), Some(false)),
            CaseOutcome {
                figures: Vec::new(),
                verdicts: Vec::new(),
                error: Some("the scene's \"x\", refused".into()),
                ..outcome(3, None, None)
            },
        ];
        let text = CasesTable::write(&["body.mass".to_owned()], &outcomes);
        let (varied, read) = CasesTable::read(&text).unwrap();
        assert_eq!(varied, ["body.mass"]);
        assert_eq!(read, outcomes);
        // Two shards' tables, merged in any order, give the whole run's statistics.
        let (a, b): (Vec<_>, Vec<_>) = outcomes.iter().cloned().partition(|o| o.index % 2 == 0);
        let mut merged = CasesTable::read(&CasesTable::write(&varied, &b)).unwrap().1;
        merged.extend(CasesTable::read(&CasesTable::write(&varied, &a)).unwrap().1);
        assert_eq!(
            Statistics::of(&merged, &PERCENTILES),
            Statistics::of(&outcomes, &PERCENTILES)
        );
        assert!(CasesTable::read("a,b\n1,2\n").is_err());
    }
}
