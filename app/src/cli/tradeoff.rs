//! `eom tradeoff SCENE`: what each integrator costs on this scene, and the cheapest setting
//! that meets a target error (see [`eom::run::tradeoff`]), for a scene whose kind compares
//! its integrators ([`eom::kinds::Kind::tradeoff`]).

use anyhow::{Context, Result, bail};
use eom::run::tradeoff::{REPEATS, Recommendation, Tradeoff, TradeoffRow};
use serde_json::json;
use std::path::PathBuf;

/// Options of `eom tradeoff`.
#[derive(clap::Args)]
pub struct Args {
    /// The scene file (TOML).
    scene: PathBuf,
    /// The largest acceptable end-state error (relative; see the table's note).
    #[arg(long, default_value_t = 1e-6, value_parser = super::values::positive)]
    target: f64,
    /// Print JSON: {"target", "reference", "rows": [...], "recommended": {...}}.
    #[arg(long)]
    json: bool,
}

/// Runs `eom tradeoff`.
pub fn run(args: Args) -> Result<()> {
    let scene = super::serves::single(&args.scene, "eom tradeoff compares the integrators on")?;
    let Some(result) = scene.tradeoff() else {
        return Err(super::serves::not_compared(&args.scene, scene.kind()).into());
    };
    let result = result.context("running the reference")?;
    let recommendation = result.recommend(args.target);
    if args.json {
        let value = json!({
            "target": args.target,
            "reference": result.reference,
            "reference_spread": result.reference_spread(),
            "rows": result.rows.iter().map(row_json).collect::<Vec<_>>(),
            "recommended": recommendation.setting().map(row_json),
            "converged": !matches!(recommendation, Recommendation::NotConverged(_)),
            "why_not": why_not(&recommendation, args.target),
        });
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        print_table(scene.title(), &result, args.target, &recommendation);
    }
    match why_not(&recommendation, args.target) {
        Some(why) => bail!("{why}"),
        None => Ok(()),
    }
}

/// Why no setting is recommended, if none is.
fn why_not(recommendation: &Recommendation, target: f64) -> Option<String> {
    match recommendation {
        Recommendation::Setting(_) => None,
        Recommendation::NotConverged(why) => Some(format!("no setting is recommended: {why}")),
        Recommendation::NoneMeets => Some(format!("no setting met the target error {target:e}")),
    }
}

fn row_json(row: &TradeoffRow) -> serde_json::Value {
    json!({
        "method": row.method,
        "setting": row.setting,
        "error": row.error,
        "rhs_evals": row.rhs_evals,
        "seconds": if row.seconds.is_finite() { json!(row.seconds) } else { json!(null) },
        "failure": row.failure,
    })
}

fn print_table(title: &str, result: &Tradeoff, target: f64, recommendation: &Recommendation) {
    println!("{title}: {}", result.run);
    println!(
        "the error is the largest end-state difference from {}, over max(1, the largest reference entry); the time is the best of {REPEATS}",
        result.reference
    );
    println!();
    println!("| method | setting | error | rhs evals | seconds |");
    println!("|---|---|---|---|---|");
    for row in &result.rows {
        match (&row.error, &row.failure) {
            (Some(error), _) => println!(
                "| {} | {} | {error:.2e} | {} | {:.2e} |",
                row.method, row.setting, row.rhs_evals, row.seconds
            ),
            (None, failure) => println!(
                "| {} | {} | failed: {} | | |",
                row.method,
                row.setting,
                failure.as_deref().unwrap_or("")
            ),
        }
    }
    println!();
    match recommendation {
        Recommendation::Setting(row) => println!(
            "recommended for an error of at most {target:e}: {} with {} (error {:.2e}, {:.2e} s, {} rhs evals)",
            row.method,
            row.setting,
            row.error.unwrap_or(f64::NAN),
            row.seconds,
            row.rhs_evals
        ),
        Recommendation::NotConverged(why) => {
            println!("no setting is recommended for an error of {target:e}: {why}")
        }
        Recommendation::NoneMeets => println!("no setting meets an error of {target:e}"),
    }
}
