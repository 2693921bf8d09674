//! `eom sweep-merge DIR`: the shards' tables of a sweep, once every shard is done, as one
//! `sweep.csv` sorted by case.
//!
//! Each shard (`eom run SCENE --shard K/N`) writes `sweep-shard-K-of-N.csv`; the cases of one
//! shard are k ≡ K (mod N), so the tables interleave. The merge checks that every shard of
//! the same N is there and that their headers agree, and refuses while a shard still holds
//! the folder. The table of a sweep over one key gets its plot,
//! `sweep.svg`, as a whole run's does (drawn from the table alone).
//!
//! A Monte Carlo's shards (`uncertainty-shard-K-of-N.csv`, from a scene with an
//! `[uncertainty]`) merge alike into `uncertainty.csv`, and the merge writes from it what one
//! run writes (`uncertainty.json`, `distributions.svg`, `pass_rates.svg`): the same numbers.

use super::run::Usage;
use super::sweep::{SWEEP_PLOT, write_sweep_plot};
use super::uncertainty::{CASES_FILE, REPORT_FILE, write_report};
use anyhow::{Context, Result, bail};
use eom::output::folder::Claim;
use eom::output::summary::write_atomically;
use eom::run::uncertainty::CasesTable;
use eom_cli::plots::distributions::{DISTRIBUTIONS_PLOT, PASS_RATES_PLOT};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Options of `eom sweep-merge`.
#[derive(clap::Args)]
pub struct Args {
    /// The folder the shards ran into.
    dir: PathBuf,
}

/// Runs `eom sweep-merge`: a Monte Carlo's shards where the folder holds them, else a
/// sweep's.
pub fn run(args: Args) -> Result<()> {
    if let Some(shards) = monte_carlo_shards(&args.dir)? {
        return merge_monte_carlo(&args.dir, &shards);
    }
    let shards = shard_tables(&args.dir, SWEEP_SHARD)?;
    let count = shards.len();
    let planned = ["sweep.csv".to_owned(), SWEEP_PLOT.to_owned()];
    let _claim = Claim::add_to(&args.dir, &planned)?;
    let mut header: Option<csv::StringRecord> = None;
    let mut rows: Vec<(usize, csv::StringRecord)> = Vec::new();
    for path in shards.values() {
        let mut reader =
            csv::Reader::from_path(path).with_context(|| format!("reading {}", path.display()))?;
        let this = reader.headers()?.clone();
        if this.is_empty() {
            continue; // a shard with no cases writes an empty table
        }
        match &header {
            Some(first) if *first != this => bail!(
                "{}'s columns differ from the other shards': the shards are not of one sweep",
                path.display()
            ),
            _ => header = Some(this),
        }
        for record in reader.records() {
            let record = record.with_context(|| format!("reading {}", path.display()))?;
            let case = record
                .get(0)
                .and_then(|c| c.parse().ok())
                .with_context(|| format!("{}: a row without a case number", path.display()))?;
            rows.push((case, record));
        }
    }
    rows.sort_by_key(|(case, _)| *case);
    let mut writer = csv::Writer::from_writer(Vec::new());
    if let Some(header) = &header {
        writer.write_record(header)?;
    }
    for (_, record) in &rows {
        writer.write_record(record)?;
    }
    let path = args.dir.join("sweep.csv");
    let table = writer.into_inner()?;
    write_atomically(&path, &table).with_context(|| format!("writing {}", path.display()))?;
    // A ship sweep over one rudder angle: its plot, as the whole run draws it.
    write_sweep_plot(&args.dir, &String::from_utf8_lossy(&table))?;
    println!(
        "merged {count} shards, {} cases, into {}",
        rows.len(),
        eom_cli::shell_path(&path)
    );
    Ok(())
}

/// A sweep's shard tables' names begin so.
const SWEEP_SHARD: &str = "sweep-shard-";
/// A Monte Carlo's shard tables' names begin so.
const MONTE_CARLO_SHARD: &str = "uncertainty-shard-";

/// A Monte Carlo's shard tables, where the folder holds any.
fn monte_carlo_shards(dir: &Path) -> Result<Option<BTreeMap<usize, PathBuf>>> {
    let entries = std::fs::read_dir(dir).with_context(|| format!("reading {}", dir.display()))?;
    let any = (entries.flatten())
        .any(|e| shard_of(&e.file_name().to_string_lossy(), MONTE_CARLO_SHARD).is_some());
    match any {
        true => shard_tables(dir, MONTE_CARLO_SHARD).map(Some),
        false => Ok(None),
    }
}

/// Joins a Monte Carlo's shard tables into `uncertainty.csv` and writes from it what one run
/// writes: `uncertainty.json` and its plots, the same numbers.
fn merge_monte_carlo(dir: &Path, shards: &BTreeMap<usize, PathBuf>) -> Result<()> {
    let planned = [CASES_FILE, REPORT_FILE, DISTRIBUTIONS_PLOT, PASS_RATES_PLOT].map(String::from);
    let _claim = Claim::add_to(dir, &planned)?;
    let mut varied: Option<Vec<String>> = None;
    let mut outcomes = Vec::new();
    for path in shards.values() {
        let text =
            std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
        let (keys, cases) =
            CasesTable::read(&text).with_context(|| format!("reading {}", path.display()))?;
        if cases.is_empty() {
            continue; // a shard with no cases
        }
        match &varied {
            Some(first) if *first != keys => bail!(
                "{}'s varied values differ from the other shards': the shards are not of one \
                 Monte Carlo",
                path.display()
            ),
            _ => varied = Some(keys),
        }
        outcomes.extend(cases);
    }
    outcomes.sort_by_key(|outcome| outcome.index);
    let keys = varied.unwrap_or_default();
    let path = dir.join(CASES_FILE);
    write_atomically(&path, CasesTable::write(&keys, &outcomes).as_bytes())
        .with_context(|| format!("writing {}", path.display()))?;
    let statistics = write_report(dir, &keys, &outcomes)?;
    print!("{}", statistics.report());
    println!(
        "merged {} shards, {} cases, into {}",
        shards.len(),
        outcomes.len(),
        eom_cli::shell_path(&path)
    );
    Ok(())
}

/// The shards' tables (named `prefix` K-of-N.csv) by K, all of one N, every K from 0 to
/// N − 1 present.
fn shard_tables(dir: &Path, prefix: &str) -> Result<BTreeMap<usize, PathBuf>> {
    let entries = std::fs::read_dir(dir).with_context(|| format!("reading {}", dir.display()))?;
    let mut by_count: BTreeMap<usize, BTreeMap<usize, PathBuf>> = BTreeMap::new();
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        if let Some((k, n)) = shard_of(&name, prefix) {
            by_count.entry(n).or_default().insert(k, entry.path());
        }
    }
    let mut counts = by_count.into_iter();
    let Some((n, shards)) = counts.next() else {
        return Err(Usage(format!(
            "{} holds no {prefix}K-of-N.csv: run the shards into it first",
            dir.display()
        ))
        .into());
    };
    if let Some((other, _)) = counts.next() {
        bail!(
            "{} holds shards of {n} and of {other}: two sweeps, or one split twice",
            dir.display()
        );
    }
    let missing: Vec<String> = (0..n)
        .filter(|k| !shards.contains_key(k))
        .map(|k| k.to_string())
        .collect();
    if !missing.is_empty() {
        bail!(
            "shard {} of {n} not yet in {}: run it, then merge",
            missing.join(", "),
            dir.display()
        );
    }
    Ok(shards)
}

/// `(K, N)` of `<prefix>K-of-N.csv` (`sweep-shard-K-of-N.csv`).
fn shard_of(name: &str, prefix: &str) -> Option<(usize, usize)> {
    let middle = name.strip_prefix(prefix)?.strip_suffix(".csv")?;
    let (k, n) = middle.split_once("-of-")?;
    let (k, n) = (k.parse().ok()?, n.parse().ok()?);
    (k < n).then_some((k, n))
}

#[cfg(test)]
mod tests {
    use super::{MONTE_CARLO_SHARD, SWEEP_SHARD, shard_of};

    #[test]
    fn shard_tables_are_named_k_of_n() {
        assert_eq!(
            shard_of("sweep-shard-3-of-8.csv", SWEEP_SHARD),
            Some((3, 8))
        );
        assert_eq!(shard_of("sweep-shard-8-of-8.csv", SWEEP_SHARD), None);
        assert_eq!(shard_of("sweep.csv", SWEEP_SHARD), None);
        assert_eq!(shard_of("sweep-shard-a-of-8.csv", SWEEP_SHARD), None);
        let monte_carlo = "uncertainty-shard-1-of-2.csv";
        assert_eq!(shard_of(monte_carlo, MONTE_CARLO_SHARD), Some((1, 2)));
        assert_eq!(shard_of(monte_carlo, SWEEP_SHARD), None);
    }
}
