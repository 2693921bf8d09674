//! `eom linear SCENE`: a scene linearised about the point its `[linear]` table names (by
//! default its initial state); a ship about its approach, with its Nomoto models beside
//! (`ship.rs`).
//!
//! It prints the reduced state and what was set aside, whether the point is an equilibrium
//! (and by how much it is not), the trim, A and B, the modes and the verdict; `--json`
//! prints the same as one object, with the state-space model as control tools read it
//! (`eom::linear::StateSpace`: A, B, C, D, the names and units of x, u and y, the point).
//! With `--out DIR` it also writes `A.csv`, `B.csv` (plain numbers, rows and columns in the
//! order of `reduced_state` and `inputs`, as a control toolbox reads them), `poles.svg`, the
//! text report, `linear.json` (the object `--json` prints) and `linear.mat` (the state-space
//! model as MATLAB variables), into a folder taken as `eom run` takes one.

use anyhow::Result;
use eom::linear::report::{json_report, text_report};
use eom::linear::{Linearisation, StateSpace};
use eom::output::folder::{Claim, Writer};
use eom::output::mat::mat_file;
use eom::output::summary::write_atomically;
use eom_cli::plots::poles::{POLES, PlottedMode, write_pole_plot};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Options of `eom linear`.
#[derive(clap::Args)]
pub struct Args {
    /// A scene: a catalog, ship or vehicle scene.
    pub scene: PathBuf,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Also write A.csv, B.csv, poles.svg, report.txt, linear.json and linear.mat into this
    /// folder.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Replace an earlier run in --out, or write into a folder eom did not make.
    #[arg(long)]
    pub force: bool,
}

/// The files `--out` writes.
const FILES: [&str; 6] = ["A.csv", "B.csv", POLES, REPORT, JSON, MAT];

/// The text report, as `eom linear` prints it.
const REPORT: &str = "report.txt";

/// The JSON report, as `eom linear --json` prints it.
const JSON: &str = "linear.json";

/// The state-space model as MATLAB variables.
const MAT: &str = "linear.mat";

/// Runs `eom linear`.
pub fn run(args: Args) -> Result<()> {
    let scene = super::serves::single(&args.scene, "eom linear linearises")?;
    let linearised = scene.linear()?;
    let (title, linear) = (scene.title().to_owned(), linearised.linearisation);
    let (extra_text, extra_json) = (linearised.text, linearised.json);
    let space = state_space(&args, &title, &linear);
    // Every scene's report, with what its kind adds beside it (a ship's Nomoto models).
    let mut text = text_report(&title, &linear);
    text.push_str(&extra_text);
    let mut report = json_report(&space, &linear);
    if let Some(report) = report.as_object_mut() {
        report.extend(extra_json);
    }
    write_out(&args, (&space, &linear), &text, &report)?;
    show(&args, &text, &report)
}

/// The state-space model of `linear`, of the scene `args` names as it was given.
pub fn state_space(args: &Args, title: &str, linear: &Linearisation) -> StateSpace {
    StateSpace::new(&args.scene.display().to_string(), title, linear)
}

/// Prints the JSON report with `--json`, else the text and, with `--out`, the files written.
pub fn show(args: &Args, text: &str, report: &Value) -> Result<()> {
    if args.json {
        println!("{}", serde_json::to_string_pretty(report)?);
    } else {
        print!("{text}");
        if let Some(out) = &args.out {
            let out = eom_cli::shell_path(out);
            println!("  written to {out}: {}", FILES.join(", "));
        }
    }
    Ok(())
}

/// With `--out`, A.csv, B.csv, poles.svg, the text report, the JSON report and the MAT-file
/// into a folder taken as `eom run` takes one.
pub fn write_out(
    args: &Args,
    (space, linear): (&StateSpace, &Linearisation),
    text: &str,
    report: &Value,
) -> Result<()> {
    if let Some(out) = &args.out {
        let planned: Vec<String> = FILES.map(String::from).to_vec();
        let _claim = Claim::take(out, args.force, &Writer::Whole, &planned)?;
        write_files(out, (space, linear), text, report)?;
    }
    Ok(())
}

fn write_files(
    out: &Path,
    (space, linear): (&StateSpace, &Linearisation),
    text: &str,
    report: &Value,
) -> Result<()> {
    let title = &space.title;
    let reduced = linear.reduced_names();
    write_atomically(&out.join("A.csv"), csv(&reduced, &linear.a).as_bytes())?;
    write_atomically(
        &out.join("B.csv"),
        csv(&linear.input_names, &linear.b).as_bytes(),
    )?;
    write_pole_plot(out, title, &plotted_modes(linear), linear.growth_tolerance)?;
    write_atomically(&out.join(REPORT), text.as_bytes())?;
    let mut json = serde_json::to_string_pretty(report)?;
    json.push('\n');
    write_atomically(&out.join(JSON), json.as_bytes())?;
    write_atomically(&out.join(MAT), &mat_file(&space.mat_variables())?)?;
    Ok(())
}

/// A matrix as CSV: a header row naming its columns, then one line per row, numbers in Rust's
/// shortest round-trip form (the rows are the rates of the reduced state, in its order).
fn csv(columns: &[&str], matrix: &eom::nalgebra::DMatrix<f64>) -> String {
    let mut text = columns.join(",");
    text.push('\n');
    for row in matrix.row_iter() {
        let cells: Vec<String> = row.iter().map(|v| format!("{v:e}")).collect();
        text.push_str(&cells.join(","));
        text.push('\n');
    }
    text
}

/// Each mode as the pole plot draws it: its name (`mode k` where the kind gives none) and its
/// eigenvalue.
fn plotted_modes(linear: &Linearisation) -> Vec<PlottedMode> {
    (linear.modes.iter().enumerate())
        .map(|(k, mode)| PlottedMode {
            name: match &mode.name {
                Some(name) if !name.is_empty() => name.to_string(),
                _ => format!("mode {}", k + 1),
            },
            eigenvalue: (mode.eigenvalue.re, mode.eigenvalue.im),
        })
        .collect()
}
