//! A linearisation as `eom linear` reports it, for every caller that reports one (the
//! command, a binding): the text report (what `eom linear` prints and `--out` keeps as
//! report.txt) and the JSON report (what `--json` prints and `--out` keeps as linear.json).

use super::{Linearisation, Mode, Stability, StateSpace, newton_steps};
use serde_json::{Map, Value, json};

/// The JSON report: the linearisation, and the state-space model as control tools read it
/// (its keys [`StateSpace`]'s: `scene`, `title`, `A`, `B`, `C`, `D`, `x_names`, …).
pub fn json_report(space: &StateSpace, linear: &Linearisation) -> Value {
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
    // A StateSpace serialises to an object: its fields are numbers, strings and matrices.
    if let (Some(report), Ok(Value::Object(space))) =
        (report.as_object_mut(), serde_json::to_value(space))
    {
        report.extend(space);
    }
    report
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
    value.map_or_else(|| "-".into(), |v| crate::fixed(v, 6))
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
        .map(|(n, v)| format!("{n} = {}", crate::fixed(*v, 6)))
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
            .map(|(n, v)| format!("{n} = {}", crate::fixed(*v, 9)))
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
fn line(text: &mut String, content: String) {
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
    matrix: &nalgebra::DMatrix<f64>,
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
    // The dominant states' column is 18 wide, or as wide as its longest entry, so that the
    // names stay in one column.
    let width = (linear.modes.iter())
        .map(|mode| mode.dominant.join(", ").chars().count())
        .fold(18, usize::max);
    line(
        text,
        format!(
            "  modes:\n    {:>28} {:>12} {:>10} {:>14} {:>12}  {:<width$} name",
            "eigenvalue [1/s]", "period [s]", "damping", "to double [s]", "to half [s]", "dominant"
        ),
    );
    for mode in &linear.modes {
        // + 0.0: a real part of −0 is printed as 0.
        let l = mode.eigenvalue + nalgebra::Complex::new(0.0, 0.0);
        let eigenvalue = if l.im > 0.0 {
            format!("{:.6e} ± {:.6e}i", l.re, l.im)
        } else {
            format!("{:.6e}", l.re)
        };
        line(
            text,
            format!(
                "    {eigenvalue:>28} {:>12} {:>10} {:>14} {:>12}  {:<width$} {}",
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
