//! A sweep of a scene with manoeuvres, whatever its kind: every case run in parallel into its
//! own folder (`case-NNNN/`, holding what a single run of it holds), and one line per case in
//! the sweep's table, the case's swept values then its figures by column name.
//!
//! What a kind gives is its run and its cells ([`SweptCase`]); the running, the order of the
//! columns, the failed cases and the table are written once here, so that a table of any kind
//! reads alike and its shards merge alike (`eom sweep-merge`).

use super::run::signal_received;
use anyhow::Result;
use eom::scene::sweep::TableCase;
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A checked scene with manoeuvres, of a kind the command runs: what it writes, how it runs
/// into its folder, and what its line of a sweep's table holds.
pub trait SweptCase: Sync {
    /// What a case's run gave.
    type Run: Send;

    /// Its manoeuvres' folders, in the order they run.
    fn folders(&self) -> Vec<String>;

    /// About how many bytes its trajectories take, for the output-size guard.
    fn trajectory_bytes(&self) -> f64;

    /// Runs the scene alone into `out` (not as a case of a sweep) and prints its report.
    fn execute(&self, name: &str, out: &Path) -> Result<()>;

    /// Runs the case into `out`, a folder made and found writable, writing there what a
    /// single run of the scene writes.
    fn run_into(&self, name: &str, out: &Path) -> Result<Self::Run>;

    /// Each column of the table after the case and its swept values, with its value in `run`
    /// (empty where the run gave none), in the table's order.
    fn cells(&self, case: &TableCase, run: &Self::Run) -> Vec<(String, String)>;
}

/// Runs every case in parallel, each into the folder `folder_of` makes for its index, and
/// returns the sweep's table (`case, <swept keys…>, <cells…>, error`) and each case's error,
/// if it failed. A case that fails leaves the others running; after a signal the cases not
/// yet started are not run, and say so.
pub fn run_cases<C: SweptCase>(
    cases: &[(TableCase, C)],
    name: &str,
    folder_of: impl Fn(usize) -> Result<PathBuf> + Sync,
) -> (String, Vec<(usize, Option<String>)>) {
    let runs: Vec<Result<C::Run>> = cases
        .par_iter()
        .map(|(case, scene)| {
            if signal_received().is_some() {
                anyhow::bail!("not run: the sweep was interrupted");
            }
            scene.run_into(name, &folder_of(case.index)?)
        })
        .collect();
    let failures = cases
        .iter()
        .zip(&runs)
        .map(|((case, _), run)| (case.index, run.as_ref().err().map(|e| format!("{e:#}"))))
        .collect();
    (table(cases, &runs), failures)
}

/// The columns after the case and its values, from the first case that ran (every case has
/// the same manoeuvres, and names their columns alike).
fn columns<C: SweptCase>(cases: &[(TableCase, C)], runs: &[Result<C::Run>]) -> Vec<String> {
    let first = cases
        .iter()
        .zip(runs)
        .find_map(|((case, scene), run)| run.as_ref().ok().map(|run| scene.cells(case, run)));
    first
        .unwrap_or_default()
        .into_iter()
        .map(|(column, _)| column)
        .collect()
}

/// `case, <swept keys…>, <cells…>, error`, one line per case.
fn table<C: SweptCase>(cases: &[(TableCase, C)], runs: &[Result<C::Run>]) -> String {
    let Some((first, _)) = cases.first() else {
        return String::new();
    };
    let columns = columns(cases, runs);
    let mut header = vec!["case".to_owned()];
    header.extend(first.values.iter().map(|(k, _)| k.clone()));
    header.extend(columns.iter().cloned());
    header.push("error".into());
    let mut writer = csv::Writer::from_writer(Vec::new());
    let _ = writer.write_record(&header);
    for ((case, scene), run) in cases.iter().zip(runs) {
        let mut row = vec![case.index.to_string()];
        row.extend(case.values.iter().map(|(_, v)| v.to_string()));
        match run {
            Ok(run) => {
                let mut values: BTreeMap<String, String> =
                    scene.cells(case, run).into_iter().collect();
                row.extend(columns.iter().map(|c| values.remove(c).unwrap_or_default()));
                row.push(String::new());
            }
            Err(error) => {
                row.extend(std::iter::repeat_n(String::new(), columns.len()));
                row.push(format!("{error:#}"));
            }
        }
        let _ = writer.write_record(&row);
    }
    String::from_utf8(writer.into_inner().unwrap_or_default()).unwrap_or_default()
}

/// What each manoeuvre's columns are named by: its name, unless a swept key of its entry
/// may make it (`manoeuvre[0].rudder_deg` in `zigzag_10_10`, or its `name` itself) and the
/// scene does not give it one, then its position, `manoeuvre[0]`: a name made from a swept
/// value would give each case columns of its own, and shards that could not be merged.
/// `named_from` lists the keys a kind makes its names from.
pub fn manoeuvre_columns<'a>(
    case: &TableCase,
    names: impl Iterator<Item = &'a str>,
    named_from: &[&str],
) -> Vec<String> {
    let given = |index: usize| {
        let entry = case.table.get("manoeuvre").and_then(|m| m.get(index));
        entry.is_some_and(|m| m.get("name").is_some())
    };
    names
        .enumerate()
        .map(|(index, name)| {
            let swept = |key: &str| {
                let path = format!("manoeuvre[{index}].{key}");
                case.values.iter().any(|(k, _)| *k == path)
            };
            let named = given(index) && !swept("name");
            let made_from_swept = swept("name") || named_from.iter().any(|key| swept(key));
            match named || !made_from_swept {
                true => name.to_owned(),
                false => format!("manoeuvre[{index}]"),
            }
        })
        .collect()
}
