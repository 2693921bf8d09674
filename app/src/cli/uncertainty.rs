//! `eom run` of a scene with an `[uncertainty]`: a Monte Carlo of it, on every core.
//!
//! Each case runs once, its rows dropped, into one line of `uncertainty.csv` (its values,
//! each run's figures, each verdict, every digit kept); then `uncertainty.json` gives each
//! figure's mean, standard deviation and percentiles and each verdict's pass rate with its
//! 95 % Wilson interval, `distributions.svg` and `pass_rates.svg` draw them, and the report
//! says them with the throughput. `--shard K/N` runs the cases k ≡ K (mod N) into
//! `uncertainty-shard-K-of-N.csv` alone; `eom sweep-merge` joins the shards' tables and
//! writes from them what one run writes, with the same numbers, since both are computed from
//! the table ([`eom::run::uncertainty`]).

use super::run::{CasesFailed, Interrupted, signal_received};
use anyhow::{Context, Result};
use eom::output::folder::{Claim, Writer, sweep_identity};
use eom::output::summary::write_atomically;
use eom::run::uncertainty::{
    CaseOutcome, CasesTable, PERCENTILES, Statistics, figure_values, refuse_contradicting_laws,
    report_json, run_cases,
};
use eom::scene::AnyScene;
use eom::scene::uncertainty::Uncertainty;
use eom_cli::plots::distributions::{
    DISTRIBUTIONS_PLOT, Distribution, PASS_RATES_PLOT, PassRate, write_distributions,
    write_pass_rates,
};
use eom_cli::shell_path;
use std::path::Path;
use std::time::Instant;

/// The table of every case.
pub const CASES_FILE: &str = "uncertainty.csv";
/// The statistics.
pub const REPORT_FILE: &str = "uncertainty.json";

/// A shard's table: `uncertainty-shard-K-of-N.csv`.
pub fn shard_file((k, n): (usize, usize)) -> String {
    format!("uncertainty-shard-{k}-of-{n}.csv")
}

/// Runs the Monte Carlo of scene text `text` (`name` its file, `base` its folder) into `out`,
/// or its shard.
pub fn execute(
    text: &str,
    name: &str,
    base: &Path,
    out: &Path,
    (force, shard): (bool, Option<(usize, usize)>),
) -> Result<()> {
    let uncertainty = Uncertainty::parse(text, name)?;
    let indices = uncertainty.shard(shard, name)?;
    // The scene as written, read first: a scene that cannot run fails before any case does,
    // and a kind that derives its model from the table derives it here, once.
    let nominal = AnyScene::from_table(uncertainty.nominal().clone(), name, base)?;
    refuse_contradicting_laws(&uncertainty, nominal.as_kind(), (name, base))?;
    let (planned, writer) = match shard {
        Some((index, count)) => {
            let identity = sweep_identity(name, text, count);
            let writer = Writer::Shard {
                index,
                count,
                sweep: identity,
            };
            (vec![shard_file((index, count))], writer)
        }
        None => {
            let files = [CASES_FILE, REPORT_FILE, DISTRIBUTIONS_PLOT, PASS_RATES_PLOT];
            (files.map(String::from).to_vec(), Writer::Whole)
        }
    };
    let _claim = Claim::take(out, force, &writer, &planned)?;
    let keys: Vec<String> = uncertainty.varied.iter().map(|v| v.key.clone()).collect();
    println!(
        "{}: a Monte Carlo of {} cases{}, seed {}, {} varied",
        nominal.title(),
        uncertainty.cases,
        match shard {
            Some((k, n)) => format!(" (shard {k}/{n}: {} of them)", indices.len()),
            None => String::new(),
        },
        uncertainty.seed,
        match keys.len() {
            1 => "1 value".to_owned(),
            n => format!("{n} values"),
        }
    );
    let clock = Instant::now();
    let stop = || signal_received().is_some();
    let outcomes = run_cases(&uncertainty, &indices, (name, base), &stop);
    let seconds = clock.elapsed().as_secs_f64();
    let table = CasesTable::write(&keys, &outcomes);
    let file = out.join(planned[0].as_str());
    write_atomically(&file, table.as_bytes())
        .with_context(|| format!("writing {}", file.display()))?;
    if shard.is_none() {
        let statistics = write_report(out, &keys, &outcomes)?;
        print!("{}", statistics.report());
    }
    println!("{}", throughput(&outcomes, seconds));
    println!(
        "  one line per case in {}{}",
        shell_path(&file),
        match shard {
            Some(_) => "; `eom sweep-merge` joins the shards once every one has run",
            None => "",
        }
    );
    if let Some(signal) = signal_received() {
        let kept = format!(
            "every case is a line of {}, the cases not run say so",
            file.display()
        );
        return Err(Interrupted { signal, kept }.into());
    }
    let failed = outcomes.iter().filter(|o| o.error.is_some()).count();
    if failed > 0 {
        let table = shell_path(&file);
        let cases = outcomes.len();
        return Err(CasesFailed {
            failed,
            cases,
            table,
        }
        .into());
    }
    Ok(())
}

/// How many cases, and runs, a second.
fn throughput(outcomes: &[CaseOutcome], seconds: f64) -> String {
    // A case's runs: the distinct runs its figures name (`turning_circle_35/port`).
    let runs = |outcome: &CaseOutcome| {
        let mut paths: Vec<&str> = (outcome.figures.iter())
            .map(|(name, _)| name.rsplit_once('/').map_or("", |(run, _)| run))
            .collect();
        paths.dedup();
        paths.len().max(1)
    };
    let ran: Vec<&CaseOutcome> = outcomes.iter().filter(|o| o.error.is_none()).collect();
    let runs: usize = ran.iter().map(|o| runs(o)).sum();
    format!(
        "  {} cases in {seconds:.2} s on {} threads: {:.0} cases/s, {:.0} runs/s",
        outcomes.len(),
        rayon::current_num_threads(),
        outcomes.len() as f64 / seconds,
        runs as f64 / seconds
    )
}

/// Writes `uncertainty.json` and the two plots of `outcomes` (the whole Monte Carlo's) into
/// `dir`; returns the statistics.
pub fn write_report(dir: &Path, keys: &[String], outcomes: &[CaseOutcome]) -> Result<Statistics> {
    let statistics = Statistics::of(outcomes, &PERCENTILES);
    let bytes = report_json(keys, &PERCENTILES, &statistics);
    let path = dir.join(REPORT_FILE);
    write_atomically(&path, &bytes).with_context(|| format!("writing {}", path.display()))?;
    let values = figure_values(outcomes);
    let figures: Vec<Distribution> = (values.iter())
        .map(|(name, values)| Distribution { name, values })
        .collect();
    // Captioned from the table alone, so that a merge of shards draws what one run draws.
    let caption = format!("{} cases: each figure's distribution", statistics.cases);
    write_distributions(dir, &caption, &figures)?;
    let names: Vec<String> = (statistics.verdicts.iter())
        .map(|v| match v.judged {
            0 => format!("{} (not judged)", v.name),
            _ => v.name.clone(),
        })
        .collect();
    let rates: Vec<PassRate> = (statistics.verdicts.iter().zip(&names))
        .map(|(v, name)| PassRate {
            name,
            rate: (v.rate, v.wilson_95.0, v.wilson_95.1),
        })
        .collect();
    let caption = format!("{} cases: each verdict's pass rate", statistics.cases);
    write_pass_rates(dir, &caption, &rates)?;
    Ok(statistics)
}
