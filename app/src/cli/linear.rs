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
use eom::linear::{Linearisation, Mode, Stability, StateSpace, newton_steps};
use eom::output::folder::{Claim, Writer};
use eom::output::mat::mat_file;
use eom::output::summary::write_atomically;
use eom_cli::plots::poles::{POLES, write_pole_plot};
use serde_json::{Map, Value, json};
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
    let mut report = report(&space, &linear)?;
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
    let poles: Vec<(f64, f64)> = linear.eigenvalues.iter().map(|l| (l.re, l.im)).collect();
    write_pole_plot(out, title, &poles, linear.growth_tolerance)?;
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

/// The JSON report: the linearisation, and the state-space model as control tools read it
/// (its keys [`StateSpace`]'s: `scene`, `title`, `A`, `B`, `C`, `D`, `x_names`, …).
pub fn report(space: &StateSpace, linear: &Linearisation) -> Result<Value> {
    let mut point = Map::new();
    for (name, value) in linear.state_names.iter().zip(&linear.state) {
        point.insert((*name).into(), json!(value));
    }
    for (name, value) in linear.input_names.iter().zip(&linear.inputs) {
        point.insert((*name).into(), json!(value));
    }
    let residual: Map<String, Value> = linear
        .reduced_names()
        .iter()
        .zip(&linear.residual)
        .map(|(name, r)| ((*name).to_owned(), json!(r)))
        .collect();
    let mut report = json!({
        "model": linear.model,
        "operating_point": point,
        "equilibrium": linear.equilibrium,
        "residual": residual,
        "trim": linear.trimmed.as_ref().map(|(values, steps)| json!({
            "values": values.iter().map(|(n, v)| (n.clone(), json!(v))).collect::<Map<_, _>>(),
            "newton_steps": steps,
        })),
        "reduced_state": linear.reduced_names(),
        "inputs": linear.input_names,
        "eigenvalues": linear.eigenvalues.iter().map(|l| json!({"re": l.re, "im": l.im})).collect::<Vec<_>>(),
        "modes": linear.modes.iter().map(mode_json).collect::<Vec<_>>(),
        "stable": linear.stability.and_then(Stability::is_stable),
        "verdict": linear.stability.map(Stability::word),
        "stability": verdict(linear),
        "growth_tolerance_per_s": linear.growth_tolerance,
        "note": linear.note,
    });
    if let (Some(report), Value::Object(space)) =
        (report.as_object_mut(), serde_json::to_value(space)?)
    {
        report.extend(space);
    }
    Ok(report)
}

fn mode_json(mode: &Mode) -> Value {
    json!({
        "re": mode.eigenvalue.re,
        "im": mode.eigenvalue.im,
        "period_s": mode.period_s,
        "period_in_turning_axes_s": mode.period_in_turning_axes_s,
        "damping_ratio": mode.damping_ratio,
        "time_to_double_s": mode.time_to_double_s,
        "time_to_half_s": mode.time_to_half_s,
        "dominant": mode.dominant,
        "name": mode.name,
        "frequency_in_space_rad_s": mode.frequency_in_space,
    })
}

/// A number to six decimals (no sign on a zero), or `-`.
fn number(value: Option<f64>) -> String {
    value.map_or_else(|| "-".into(), |v| eom::fixed(v, 6))
}

/// The report as text, as `eom linear` prints it and `--out` keeps it.
pub fn text_report(title: &str, linear: &Linearisation) -> String {
    let mut out = String::new();
    let text = &mut out;
    line(text, format!("{title}: linearised ({})", linear.model));
    let point: Vec<String> = linear
        .state_names
        .iter()
        .zip(&linear.state)
        .chain(linear.input_names.iter().zip(&linear.inputs))
        .map(|(n, v)| format!("{n} = {}", eom::fixed(*v, 6)))
        .collect();
    line(text, format!("  operating point: {}", point.join(", ")));
    let set_aside = linear.set_aside_names();
    let aside = if set_aside.is_empty() {
        "nothing".to_owned()
    } else {
        set_aside.join(", ")
    };
    line(
        text,
        format!(
            "  reduced state: {}; set aside (they grow, or only integrate the rest): {aside}",
            linear.reduced_names().join(", ")
        ),
    );
    if let Some((values, steps)) = &linear.trimmed {
        let values: Vec<String> = values
            .iter()
            .map(|(n, v)| format!("{n} = {}", eom::fixed(*v, 9)))
            .collect();
        line(
            text,
            format!(
                "  trimmed in {}: {}",
                newton_steps(*steps),
                values.join(", ")
            ),
        );
    }
    print_equilibrium(text, linear);
    line(text, format!("  A and B: {}", linear.jacobians));
    print_matrix(
        text,
        "A",
        &linear.a,
        &linear.reduced_names(),
        &linear.reduced_names(),
    );
    print_matrix(
        text,
        "B",
        &linear.b,
        &linear.reduced_names(),
        &linear.input_names,
    );
    print_modes(text, linear);
    line(text, format!("  verdict: {}", verdict(linear)));
    if let Some(note) = &linear.note {
        line(text, format!("  note: {note}"));
    }
    out
}

/// Appends `content` and a newline to `text`.
pub fn line(text: &mut String, content: String) {
    text.push_str(&content);
    text.push('\n');
}

/// The verdict in words, or why there is none: at a point that is not an equilibrium, A
/// describes no motion that stays near it.
fn verdict(linear: &Linearisation) -> String {
    match linear.stability {
        Some(stability) => format!(
            "{} (real parts within {:.1e} 1/s of zero count as zero)",
            stability.describe(),
            linear.growth_tolerance
        ),
        None => format!(
            "none: the point is not an equilibrium ({}), so its modes say nothing of stability; \
             name free variables in linear.trim to solve for one",
            largest_residual(linear)
        ),
    }
}

/// The reduced state's largest rate at the point, as `dx/dt = value`.
fn largest_residual(linear: &Linearisation) -> String {
    let (index, rate) = linear
        .residual
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        .expect("the reduced state is not empty");
    format!("d{}/dt = {rate:.6e}", linear.reduced_names()[index])
}

fn print_equilibrium(text: &mut String, linear: &Linearisation) {
    let said = if linear.equilibrium {
        "  the point is an equilibrium of the reduced state".to_owned()
    } else {
        format!(
            "  the point is NOT an equilibrium of the reduced state: {} there",
            largest_residual(linear)
        )
    };
    line(text, said);
}

fn print_matrix(
    text: &mut String,
    name: &str,
    matrix: &eom::nalgebra::DMatrix<f64>,
    rows: &[&str],
    columns: &[&str],
) {
    line(
        text,
        format!(
            "  {name} (rows: the rates of the reduced state; columns: {}):",
            columns.join(", ")
        ),
    );
    for (row, label) in matrix.row_iter().zip(rows) {
        let cells: Vec<String> = row.iter().map(|v| format!("{v:>13.6e}")).collect();
        line(text, format!("    {label:>10} {}", cells.join(" ")));
    }
}

fn print_modes(text: &mut String, linear: &Linearisation) {
    line(
        text,
        format!(
            "  modes:\n    {:>28} {:>12} {:>10} {:>14} {:>12}  {:<18} name",
            "eigenvalue [1/s]", "period [s]", "damping", "to double [s]", "to half [s]", "dominant"
        ),
    );
    for mode in &linear.modes {
        // + 0.0: a real part of −0 is printed as 0.
        let l = mode.eigenvalue + eom::nalgebra::Complex::new(0.0, 0.0);
        let eigenvalue = if l.im > 0.0 {
            format!("{:.6e} ± {:.6e}i", l.re, l.im)
        } else {
            format!("{:.6e}", l.re)
        };
        line(
            text,
            format!(
                "    {eigenvalue:>28} {:>12} {:>10} {:>14} {:>12}  {:<18} {}",
                number(mode.period_s),
                number(mode.damping_ratio),
                number(mode.time_to_double_s),
                number(mode.time_to_half_s),
                mode.dominant.join(", "),
                mode.name.unwrap_or("")
            ),
        );
    }
    let turning: Vec<String> = (linear.modes.iter())
        .filter_map(|mode| Some((mode.name?, mode.period_in_turning_axes_s?)))
        .map(|(name, period)| format!("{name} {period:.6} s"))
        .collect();
    if !turning.is_empty() {
        line(
            text,
            format!(
                "    periods as seen in space; in the axes of roll and pitch, which turn with \
                 the heading: {}",
                turning.join(", ")
            ),
        );
    }
}
