//! A sweep of a scene of any kind (a body's, a ship's, a vehicle's): every case run in
//! parallel into its own folder (`case-NNNN/`, holding what a single run of it holds), and one
//! line per case in the sweep's table, the case's swept values then its figures by column name.
//!
//! What a kind gives is its run and its cells ([`eom::kinds::Finished::cells`]); the running,
//! the order of the columns, the failed cases and the table are written once here, so that a
//! table of any kind reads alike and its shards merge alike (`eom sweep-merge`). A sweep over
//! one rudder angle gets its plot beside the table, drawn from the table alone so that a
//! whole run and the merge of its shards draw the same.

use super::run::{failed, run_into, signal_received};
use anyhow::Result;
use eom::kinds::Kind;
use eom::scene::reference::keys;
use eom::scene::sweep::TableCase;
use eom_cli::plots::curves::{Curve, Curves, write_curves};
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One case as the table says it: its cells, and why it failed if it did.
struct CaseRun {
    /// Each column after the case and its values, with its value (none for a case that did
    /// not run).
    cells: Vec<(String, String)>,
    /// Why it failed or stopped, if it did.
    error: Option<String>,
}

/// Runs every case in parallel, each into the folder `folder_of` makes for its index, and
/// returns the sweep's table (`case, <swept keys…>, <cells…>, error`) and each case's error,
/// if it failed. A case that fails leaves the others running; after a signal the cases not
/// yet started are not run, and say so.
pub fn run_cases(
    cases: &[(TableCase, Box<dyn Kind>)],
    name: &str,
    folder_of: impl Fn(usize) -> Result<PathBuf> + Sync,
) -> (String, Vec<(usize, Option<String>)>) {
    let runs: Vec<CaseRun> = cases
        .par_iter()
        .map(|(case, scene)| {
            run_case(scene.as_ref(), case, name, &folder_of).unwrap_or_else(|error| CaseRun {
                cells: Vec::new(),
                error: Some(format!("{error:#}")),
            })
        })
        .collect();
    let failures = (cases.iter().zip(&runs))
        .map(|((case, _), run)| (case.index, run.error.clone()))
        .collect();
    (table(cases, &runs), failures)
}

/// Runs one case into its folder: its cells, and why it failed or stopped where it kept what
/// it ran.
fn run_case(
    scene: &dyn Kind,
    case: &TableCase,
    name: &str,
    folder_of: impl Fn(usize) -> Result<PathBuf>,
) -> Result<CaseRun> {
    if signal_received().is_some() {
        anyhow::bail!("not run: the sweep was interrupted");
    }
    let folder = folder_of(case.index)?;
    let (finished, _) = run_into(scene, name, (&folder, false, Some(case)))?;
    let error = match finished.stopped() {
        true => Some(format!(
            "interrupted: {}, in {}",
            finished.kept(),
            folder.display()
        )),
        false => failed(finished.as_ref(), name, &folder).map(|error| format!("{error:#}")),
    };
    Ok(CaseRun {
        cells: finished.cells(case),
        error,
    })
}

/// The columns after the case and its values, from the first case that gave cells (every
/// case of a scene names its columns alike).
fn columns(runs: &[CaseRun]) -> Vec<String> {
    let first = runs.iter().find(|run| !run.cells.is_empty());
    (first.into_iter().flat_map(|run| &run.cells))
        .map(|(column, _)| column.clone())
        .collect()
}

/// `case, <swept keys…>, <cells…>, error`, one line per case.
fn table(cases: &[(TableCase, Box<dyn Kind>)], runs: &[CaseRun]) -> String {
    let Some((first, _)) = cases.first() else {
        return String::new();
    };
    let columns = columns(runs);
    let mut header = vec!["case".to_owned()];
    header.extend(first.values.iter().map(|(k, _)| k.clone()));
    header.extend(columns.iter().cloned());
    header.push("error".into());
    let mut writer = csv::Writer::from_writer(Vec::new());
    let _ = writer.write_record(&header);
    for ((case, _), run) in cases.iter().zip(runs) {
        let mut row = vec![case.index.to_string()];
        row.extend(case.values.iter().map(|(_, v)| v.to_string()));
        let mut values: BTreeMap<&str, &str> = (run.cells.iter())
            .map(|(k, v)| (k.as_str(), v.as_str()))
            .collect();
        row.extend(
            (columns.iter()).map(|c| values.remove(c.as_str()).unwrap_or_default().to_owned()),
        );
        row.push(run.error.clone().unwrap_or_default());
        let _ = writer.write_record(&row);
    }
    String::from_utf8(writer.into_inner().unwrap_or_default()).unwrap_or_default()
}

/// A sweep's plot over one key, beside its table.
pub const SWEEP_PLOT: &str = "sweep.svg";

/// Whether a column of a sweep's table is a swept key (a key path of the scene: a key of an
/// entry of an array, `manoeuvre[0].rudder_deg`, or a key of one of its tables), not a figure
/// (`manoeuvre[0].tactical_diameter_m`, a manoeuvre's figure named by its position).
fn is_key_path(column: &str) -> bool {
    // `manoeuvre[0].rudder_deg` is the reference's `manoeuvre[].rudder_deg`.
    let path = match column.split_once('[') {
        Some((array, rest)) => match rest.split_once(']') {
            Some((_, key)) => format!("{array}[]{key}"),
            None => return false,
        },
        None => column.to_owned(),
    };
    // A key of any kind's reference, `hydrodynamics.coefficients.*` standing for every name.
    keys().any(|key| match key.path.strip_suffix('*') {
        Some(table) => path.starts_with(table),
        None => key.path == path,
    })
}

/// `sweep.svg` in `dir`, from a sweep's table (`sweep.csv`'s text), when the sweep varies one
/// key: each figure a registered kind names for its sweeps ([`eom::kinds::SweptFigures`]:
/// a turning circle's tactical diameter, a pendulum's period) against the key, a curve for
/// each manoeuvre the table gives it for (each side's where a turn ran to both). Draws nothing
/// for a sweep over several keys or a table with none of the figures. The table alone
/// decides, so that a whole run and the merge of its shards draw the same plot.
pub fn write_sweep_plot(dir: &Path, table: &str) -> Result<()> {
    let mut reader = csv::Reader::from_reader(table.as_bytes());
    let Ok(header) = reader.headers().cloned() else {
        return Ok(());
    };
    let swept: Vec<&str> = header
        .iter()
        .skip(1)
        .take_while(|c| is_key_path(c))
        .collect();
    let [key] = swept.as_slice() else {
        return Ok(());
    };
    let rows: Vec<csv::StringRecord> = reader.records().filter_map(Result::ok).collect();
    // The kind whose figures the table has most of (a ship's and a vehicle's turning circles
    // share the tactical diameter), the first listed of equals.
    let found = (eom::kinds::REGISTRY.iter().rev()).map(|kind| {
        let figures = kind.swept_figures;
        (figures, swept_lines(&header, &rows, figures.names))
    });
    let Some((figures, lines)) = found
        .max_by_key(|(_, lines)| lines.len())
        .filter(|(_, lines)| !lines.is_empty())
    else {
        return Ok(());
    };
    let curves: Vec<Curve> = (lines.iter())
        .map(|line| Curve {
            name: &line.what,
            points: &line.points,
        })
        .collect();
    let names: Vec<String> = (figures.names.iter())
        .map(|pattern| figure_of(pattern))
        .filter(|figure| lines.iter().any(|line| line.figure == *figure))
        .map(label)
        .collect();
    let caption = format!("{} against {key}", names.join(", "));
    let y_desc = format!("{} [{}]", names.join(", "), figures.unit);
    let plot = Curves {
        caption: &caption,
        x_desc: key,
        y_desc: &y_desc,
        curves: &curves,
    };
    write_curves(dir, SWEEP_PLOT, &plot)?;
    Ok(())
}

/// The figure a column pattern names: `*.tactical_diameter_m`'s `tactical_diameter_m`.
fn figure_of(pattern: &str) -> &str {
    pattern.strip_prefix("*.").unwrap_or(pattern)
}

/// The run a column is of where it is the figure `pattern` names (`turn.port` of
/// `turn.port.tactical_diameter_m` for `*.tactical_diameter_m`; empty for `period_s` itself).
fn run_of<'a>(pattern: &str, column: &'a str) -> Option<&'a str> {
    match pattern.strip_prefix("*.") {
        Some(figure) => column.strip_suffix(figure)?.strip_suffix('.'),
        None => (column == pattern).then_some(""),
    }
}

/// A figure's name as a reader says it, its unit's suffix off: `tactical_diameter_m` as
/// `tactical diameter`.
fn label(figure: &str) -> String {
    let name = figure.rsplit_once('_').map_or(figure, |(name, _)| name);
    name.replace('_', " ")
}

/// One figure's column of a sweep's table, as its plot draws it.
struct SweptLine<'a> {
    /// The figure (`tactical_diameter_m`).
    figure: &'a str,
    /// What the curve is (`turn port tactical diameter`).
    what: String,
    /// (the swept value, the figure) of every case that gave it, by the swept value.
    points: Vec<(f64, f64)>,
}

/// Each column of `figures` in the table, sorted by the swept value: a turn run to both sides
/// by its sides' columns, not the worse side's.
fn swept_lines<'a>(
    header: &csv::StringRecord,
    rows: &[csv::StringRecord],
    figures: &[&'a str],
) -> Vec<SweptLine<'a>> {
    let number = |row: &csv::StringRecord, i: usize| row.get(i)?.parse::<f64>().ok();
    let mut lines = Vec::new();
    for (i, column) in header.iter().enumerate() {
        let Some((figure, run)) = (figures.iter())
            .find_map(|pattern| Some((figure_of(pattern), run_of(pattern, column)?)))
        else {
            continue;
        };
        let sided = ["port", "starboard"]
            .iter()
            .any(|side| header.iter().any(|c| c == format!("{run}.{side}.{figure}")));
        if sided {
            continue;
        }
        let mut points: Vec<(f64, f64)> = rows
            .iter()
            .filter_map(|row| Some((number(row, 1)?, number(row, i)?)))
            .collect();
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        let what = format!("{} {}", run.replace('.', " "), label(figure));
        lines.push(SweptLine {
            figure,
            what: what.trim().to_owned(),
            points,
        });
    }
    lines
}
