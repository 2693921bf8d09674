//! `eom tradeoff SCENE`: what each integrator costs on this scene, and the cheapest setting
//! that meets a target error: on the end state for a scene whose kind compares its
//! integrators so (a catalog body's, [`eom::kinds::Kind::tradeoff`], [`eom::run::tradeoff`]),
//! on each run's figures for every other (a ship's, a vehicle's manoeuvres,
//! [`eom::run::figure_tradeoff`]).

use anyhow::{Context, Result, bail};
use eom::run::figure_tradeoff::{
    self, FigureRecommendation, FigureRow, FigureTradeoff, FigureTradeoffError, Targets,
};
use eom::run::tradeoff::{REPEATS, Recommendation, Tradeoff, TradeoffRow};
use eom::scene::{Problem, SceneError};
use serde_json::json;
use std::path::{Path, PathBuf};

/// Options of `eom tradeoff`.
#[derive(clap::Args)]
pub struct Args {
    /// The scene file (TOML).
    scene: PathBuf,
    /// The largest acceptable end-state error (relative; see the table's note), for a scene
    /// compared on its end state (a catalog body's).
    #[arg(long, default_value_t = 1e-6, value_parser = super::values::positive)]
    target: f64,
    /// A figure's target error by its unit, `UNIT=VALUE` (`m=0.05`, `deg=0.01`, `g=0.001`), or
    /// by its whole key (`dutch_roll_damping=0.001`), for a scene compared on its figures;
    /// repeat for each (defaults: m=0.01, deg=0.001, s=0.01, deg_s=1e-4, m_s=1e-4). A figure
    /// with no target is compared and shown, not judged.
    #[arg(long = "figure-target", value_parser = unit_target)]
    figure_targets: Vec<(String, f64)>,
    /// A figure whose error at each setting the table shows in a column of its own
    /// (`tactical_diameter_m`, or a vehicle's fin step's `step_2.roll_deg`); repeat for each,
    /// for a scene compared on its figures.
    #[arg(long = "figure")]
    figures: Vec<String>,
    /// Print JSON: {"target", "reference", "rows": [...], "recommended": {...}}, or for a
    /// scene compared on its figures {"targets", "reference", "rows": [... "errors": {...}],
    /// "recommended": {...}} (docs/tradeoff.md).
    #[arg(long)]
    json: bool,
}

/// `UNIT=VALUE`, the value positive and finite.
fn unit_target(text: &str) -> Result<(String, f64), String> {
    let (unit, value) =
        (text.split_once('=')).ok_or_else(|| format!("write UNIT=VALUE (m=0.01), not `{text}`"))?;
    let unit = unit.trim();
    if unit.is_empty() || !unit.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(format!(
            "`{unit}` is not a unit as a figure's key ends in (m, deg_s)"
        ));
    }
    Ok((unit.to_owned(), super::values::positive(value)?))
}

/// Runs `eom tradeoff`.
pub fn run(args: Args) -> Result<()> {
    let scene = super::serves::single(&args.scene, "eom tradeoff compares the integrators on")?;
    let Some(result) = scene.tradeoff() else {
        return figures(&args, scene.title());
    };
    let result = result.context("running the reference")?;
    let recommendation = result.recommend(args.target);
    if args.json {
        let value = json!({
            "target": args.target,
            "error_measure": "relative: the largest end-state difference from the reference over max(1, the largest reference entry)",
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
            "recommended for a relative error of at most {target:e}: {} with {} (error {:.2e}, {:.2e} s, {} rhs evals)",
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

/// A scene compared on its runs' figures.
fn figures(args: &Args, title: &str) -> Result<()> {
    let name = args.scene.display().to_string();
    let text = std::fs::read_to_string(&args.scene)
        .map_err(|e| SceneError::new(&name, "", Problem::Read(e)))?;
    let table: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| SceneError::new(&name, "", Problem::Syntax(e.to_string())))?;
    let base = args.scene.parent().unwrap_or(Path::new("."));
    let every = figure_tradeoff::rows_interval(&table).ok_or_else(|| {
        SceneError::new(
            &name,
            "output.every",
            Problem::Missing("the rows' interval, s".into()),
        )
    })?;
    let compared = match figure_tradeoff::compare(&table, (&name, base), every, &args.figures) {
        Ok(compared) => compared,
        // Each cause keeps its exit code: the scene's key (3), the reference run's failure (5).
        Err(FigureTradeoffError::Scene(error)) => return Err(error.into()),
        Err(FigureTradeoffError::Reference(error)) => {
            return Err(anyhow::Error::new(error).context("the reference run (DOP853 at 1e-12)"));
        }
        Err(FigureTradeoffError::UnknownFigure { key, known }) => {
            let given = known.join(", ");
            let message = format!("--figure {key}: the scene's runs give {given}");
            return Err(super::run::Usage(message).into());
        }
        Err(FigureTradeoffError::NoFigures) => {
            return Err(super::run::Usage(format!(
                "eom tradeoff compares a scene's figures; {} gives none (its manoeuvres measure \
                 nothing)",
                args.scene.display()
            ))
            .into());
        }
    };
    let mut targets = Targets::default();
    for (unit, target) in &args.figure_targets {
        targets.set(unit, *target);
    }
    let recommendation = compared.recommend(&targets);
    if args.json {
        let by_unit: serde_json::Map<String, serde_json::Value> = (targets.0.iter())
            .map(|(unit, target)| (unit.clone(), json!(target)))
            .collect();
        let value = json!({
            "targets": by_unit,
            "reference": compared.reference,
            "reference_steps": compared.reference_cost.0,
            "reference_rhs_evals": compared.reference_cost.1,
            "reference_seconds": compared.reference_cost.2,
            "rows": compared.rows.iter().map(figure_row_json).collect::<Vec<_>>(),
            "recommended": match &recommendation {
                FigureRecommendation::Setting(row) => figure_row_json(row),
                FigureRecommendation::None(_) => serde_json::Value::Null,
            },
            "why_not": match &recommendation {
                FigureRecommendation::Setting(_) => None,
                FigureRecommendation::None(why) => Some(why),
            },
            "not_judged": compared.not_judged(&targets),
        });
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        let shown = (&targets, args.figures.as_slice());
        print_figures(title, &compared, shown, &recommendation);
    }
    match recommendation {
        FigureRecommendation::Setting(_) => Ok(()),
        FigureRecommendation::None(why) => bail!("no setting is recommended: {why}"),
    }
}

fn figure_row_json(row: &FigureRow) -> serde_json::Value {
    let errors: serde_json::Map<String, serde_json::Value> = (row.errors.iter())
        .map(|figure| (figure.key.clone(), json!(figure.error)))
        .collect();
    json!({
        "method": row.setting.method.name(),
        "setting": row.setting.describe(),
        "steps": row.steps,
        "rhs_evals": row.rhs_evals,
        "seconds": if row.seconds.is_finite() { json!(row.seconds) } else { json!(null) },
        "errors": errors,
        "failure": row.failure,
    })
}

/// The table of a scene compared on its figures: per setting its cost, the figure furthest
/// from its target, and each of `shown`'s figures' errors.
fn print_figures(
    title: &str,
    compared: &FigureTradeoff,
    (targets, shown): (&Targets, &[String]),
    recommendation: &FigureRecommendation,
) {
    let (steps, evals, seconds) = compared.reference_cost;
    println!(
        "{title}: every run's figures against {} ({steps} steps, {} rhs evals, {seconds:.2e} s)",
        compared.reference,
        counted(evals)
    );
    let said: Vec<String> = (targets.0.iter())
        .map(|(unit, t)| format!("{t:e} {unit}"))
        .collect();
    println!(
        "each figure's error is its largest difference from the reference over the runs, in \
         the figure's unit; the targets, by unit: {}; the cost is the rhs evals of the runs; \
         the time is the scene's whole run, its refined runs included, timed once, so that it \
         moves with the machine's load: compare settings by their rhs evals",
        said.join(", ")
    );
    println!();
    let extra: String = shown.iter().map(|key| format!(" {key} |")).collect();
    println!(
        "| method | setting | steps | rhs evals | seconds | furthest from its target | error | \
         of target |{extra}"
    );
    println!(
        "|---|---|---|---|---|---|---|---|{}",
        "---|".repeat(shown.len())
    );
    for row in &compared.rows {
        let (method, setting) = (row.setting.method.name(), row.setting.describe());
        let error_of = |key: &str| {
            let figure = row.errors.iter().find(|figure| figure.key == key);
            figure.map_or(String::new(), |figure| error_text(figure.error))
        };
        let columns: String = shown
            .iter()
            .map(|key| format!(" {} |", error_of(key)))
            .collect();
        match (&row.failure, row.worst(targets)) {
            (Some(failure), _) => println!(
                "| {method} | {setting} | failed: {failure} | | | | | |{}",
                " |".repeat(shown.len())
            ),
            (None, Some((key, error, ratio))) => println!(
                "| {method} | {setting} | {} | {} | {:.2e} | {key} | {} | {ratio:.2} |{columns}",
                row.steps,
                counted(row.rhs_evals),
                row.seconds,
                error_text(error)
            ),
            (None, None) => println!(
                "| {method} | {setting} | {} | {} | {:.2e} | | | |{columns}",
                row.steps,
                counted(row.rhs_evals),
                row.seconds
            ),
        }
    }
    println!();
    let not_judged = compared.not_judged(targets);
    if !not_judged.is_empty() {
        println!(
            "not judged, no target for their unit (--figure-target UNIT=VALUE or \
             FIGURE=VALUE sets one): {}",
            not_judged.join(", ")
        );
    }
    match recommendation {
        FigureRecommendation::Setting(row) => println!(
            "recommended: {} with {} ({} steps, {} rhs evals, {:.2e} s), every figure with a \
             target within it{}",
            row.setting.method.name(),
            row.setting.describe(),
            row.steps,
            counted(row.rhs_evals),
            row.seconds,
            match not_judged.len() {
                0 => String::new(),
                n => format!(" ({n} not judged)"),
            }
        ),
        FigureRecommendation::None(why) => println!("no setting is recommended: {why}"),
    }
}

/// A figure's error as the table writes it: `not given` where the run did not give the figure.
fn error_text(error: Option<f64>) -> String {
    error.map_or("not given".into(), |error| format!("{error:.2e}"))
}

/// A count the kind may not give, as the table writes it.
fn counted(count: Option<u64>) -> String {
    count.map_or("—".into(), |count| count.to_string())
}
