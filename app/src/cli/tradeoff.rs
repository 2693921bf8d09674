//! `eom tradeoff SCENE`: what each integrator costs on this scene, and the cheapest setting
//! that meets a target error (see [`eom::run::tradeoff`]).

use anyhow::{Context, Result, bail};
use eom::run::tradeoff::{REPEATS, Tradeoff, TradeoffRow, tradeoff};
use eom::scene::Scene;
use serde_json::json;
use std::path::PathBuf;

/// Options of `eom tradeoff`.
#[derive(clap::Args)]
pub struct Args {
    /// The scene file (TOML).
    scene: PathBuf,
    /// The largest acceptable end-state error (relative; see the table's note).
    #[arg(long, default_value_t = 1e-6)]
    target: f64,
    /// Print JSON: {"target", "reference", "rows": [...], "recommended": {...}}.
    #[arg(long)]
    json: bool,
}

/// Runs `eom tradeoff`.
pub fn run(args: Args) -> Result<()> {
    if !(args.target.is_finite() && args.target > 0.0) {
        bail!("--target must be positive and finite, got {}", args.target);
    }
    super::serves::require_single_catalog(&args.scene)?;
    let scene = Scene::load(&args.scene)?;
    let result = tradeoff(&scene).context("running the reference")?;
    let recommended = result.recommend(args.target);
    if args.json {
        let value = json!({
            "target": args.target,
            "reference": result.reference,
            "rows": result.rows.iter().map(row_json).collect::<Vec<_>>(),
            "recommended": recommended.map(row_json),
        });
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        print_table(&scene, &result, args.target, recommended);
    }
    if recommended.is_none() {
        bail!("no setting met the target error {:e}", args.target);
    }
    Ok(())
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

fn print_table(scene: &Scene, result: &Tradeoff, target: f64, recommended: Option<&TradeoffRow>) {
    println!(
        "{}: {} to t = {} s",
        scene.title, scene.selection.info.name, scene.integrator.end_time
    );
    println!(
        "error: the largest end-state difference from {}, over max(1, the largest reference entry); time: best of {REPEATS}",
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
    match recommended {
        Some(row) => println!(
            "recommended for an error of at most {target:e}: {} with {} (error {:.2e}, {:.2e} s, {} rhs evals)",
            row.method,
            row.setting,
            row.error.unwrap_or(f64::NAN),
            row.seconds,
            row.rhs_evals
        ),
        None => println!("no setting meets an error of {target:e}"),
    }
}
