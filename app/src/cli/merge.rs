//! `eom sweep-merge DIR`: the shards' tables of a sweep, once every shard is done, as one
//! `sweep.csv` sorted by case.
//!
//! Each shard (`eom run SCENE --shard K/N`) writes `sweep-shard-K-of-N.csv`; the cases of one
//! shard are k ≡ K (mod N), so the tables interleave. The merge checks that every shard of
//! the same N is there and that their headers agree, and refuses while a shard still holds
//! the folder. The table of a ship sweep over one rudder angle gets its plot,
//! `rudder_sweep.svg`, as a whole run's does (drawn from the table alone).

use super::run::Usage;
use super::sweep::{SWEEP_PLOT, write_sweep_plot};
use anyhow::{Context, Result, bail};
use eom::output::folder::Claim;
use eom::output::summary::write_atomically;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Options of `eom sweep-merge`.
#[derive(clap::Args)]
pub struct Args {
    /// The folder the shards ran into.
    dir: PathBuf,
}

/// Runs `eom sweep-merge`.
pub fn run(args: Args) -> Result<()> {
    let shards = shard_tables(&args.dir)?;
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

/// The shards' tables by K, all of one N, every K from 0 to N − 1 present.
fn shard_tables(dir: &Path) -> Result<BTreeMap<usize, PathBuf>> {
    let entries = std::fs::read_dir(dir).with_context(|| format!("reading {}", dir.display()))?;
    let mut by_count: BTreeMap<usize, BTreeMap<usize, PathBuf>> = BTreeMap::new();
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        if let Some((k, n)) = shard_of(&name) {
            by_count.entry(n).or_default().insert(k, entry.path());
        }
    }
    let mut counts = by_count.into_iter();
    let Some((n, shards)) = counts.next() else {
        return Err(Usage(format!(
            "{} holds no sweep-shard-K-of-N.csv: run the shards into it first",
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

/// `(K, N)` of `sweep-shard-K-of-N.csv`.
fn shard_of(name: &str) -> Option<(usize, usize)> {
    let middle = name.strip_prefix("sweep-shard-")?.strip_suffix(".csv")?;
    let (k, n) = middle.split_once("-of-")?;
    let (k, n) = (k.parse().ok()?, n.parse().ok()?);
    (k < n).then_some((k, n))
}

#[cfg(test)]
mod tests {
    use super::shard_of;

    #[test]
    fn shard_tables_are_named_k_of_n() {
        assert_eq!(shard_of("sweep-shard-3-of-8.csv"), Some((3, 8)));
        assert_eq!(shard_of("sweep-shard-8-of-8.csv"), None);
        assert_eq!(shard_of("sweep.csv"), None);
        assert_eq!(shard_of("sweep-shard-a-of-8.csv"), None);
    }
}
