//! The Markdown report: one table per problem, the comparison with the peer per tolerance,
//! the model variants of the tennis racket, and the cheapest run for each target accuracy.

use std::fmt::Write;

use super::names::PAIRS;
use super::sweep::{Row, Setting};

/// The model name of the base form of each problem (f64, principal axes, quaternion kinematics
/// where there is an attitude): the rows the main tables show.
pub const BASE: &str = "f64";

/// Formats a number in scientific notation, or "—" when the run failed.
fn sci(x: f64) -> String {
    if x.is_finite() {
        format!("{x:.2e}")
    } else {
        "—".to_string()
    }
}

/// One table row of a run.
fn line(r: &Row) -> String {
    let time = format!("{:.1}", r.seconds * 1e6);
    let note = r.failure.as_deref().unwrap_or("");
    format!(
        "| {} | {} | {} | {} | {} | {} | {} | {} | {} |",
        r.method,
        r.model,
        r.setting,
        sci(r.error),
        sci(r.drift),
        r.stats.rhs_evals,
        r.stats.steps,
        r.stats.rejected,
        if note.is_empty() {
            time
        } else {
            format!("{time} ({note})")
        }
    )
}

const HEADER: &str = "| method | model | setting | error | drift | RHS evals | steps | rejected | time [µs] |\n|---|---|---|---|---|---|---|---|---|\n";

/// The problems in the order they were run, without repetition.
fn problems(rows: &[Row]) -> Vec<&'static str> {
    let mut names: Vec<&'static str> = Vec::new();
    for r in rows {
        if !names.contains(&r.problem) {
            names.push(r.problem);
        }
    }
    names
}

/// The per-problem tables of the base models.
fn problem_tables(rows: &[Row], out: &mut String) {
    for problem in problems(rows) {
        let _ = write!(out, "\n### {problem}\n\n{HEADER}");
        for r in rows
            .iter()
            .filter(|r| r.problem == problem && r.model == BASE)
        {
            let _ = writeln!(out, "{}", line(r));
        }
    }
}

/// The ratio ours/peer of a quantity, as text.
fn ratio(ours: f64, peer: f64) -> String {
    if ours.is_finite() && peer.is_finite() && peer > 0.0 {
        format!("{:.2}", ours / peer)
    } else {
        "—".into()
    }
}

/// Our method against the peer's at every tolerance of every problem.
fn peer_table(rows: &[Row], out: &mut String) {
    out.push_str("\nTimes in this table come from runs of ours and the peer's timed alternately.\n\n| problem | method | rtol | error (ours) | error (ode_solvers) | RHS evals ours/peer | time ours/peer |\n|---|---|---|---|---|---|---|\n");
    for problem in problems(rows) {
        for (ours, theirs) in [
            ("DOPRI5", "ode_solvers Dopri5"),
            ("DOP853", "ode_solvers Dop853"),
        ] {
            let base = |method: &'static str| {
                rows.iter()
                    .filter(move |r| r.problem == problem && r.model == BASE && r.method == method)
            };
            for a in base(ours) {
                let Some(b) = base(theirs).find(|b| b.setting == a.setting) else {
                    continue;
                };
                let Setting::Rtol(rtol) = a.setting else {
                    continue;
                };
                let evals = ratio(a.stats.rhs_evals as f64, b.stats.rhs_evals as f64);
                let _ = writeln!(
                    out,
                    "| {problem} | {ours} | {rtol:.0e} | {} | {} | {evals} ({} / {}) | {} |",
                    sci(a.error),
                    sci(b.error),
                    a.stats.rhs_evals,
                    b.stats.rhs_evals,
                    ratio(b.paired.unwrap_or(a.seconds), b.seconds)
                );
            }
        }
    }
}

/// The settings the variant table shows: two step counts of RK4, two tolerances of the
/// Dormand–Prince methods.
fn shown(r: &Row) -> bool {
    match (r.method, r.setting) {
        ("RK4", Setting::Steps(n)) => n == 1_000 || n == 10_000,
        ("DOPRI5" | "DOP853", Setting::Rtol(rtol)) => rtol == 1e-6 || rtol == 1e-9,
        _ => false,
    }
}

/// The variants of the tennis racket at a few settings, every model.
fn variant_table(rows: &[Row], out: &mut String) {
    out.push_str(HEADER);
    let racket = rows.iter().filter(|r| r.problem == "tennis racket");
    for r in racket.filter(|r| shown(r)) {
        let _ = writeln!(out, "{}", line(r));
    }
}

/// Every run of the tennis racket's variants (every model but the base one).
fn variant_runs(rows: &[Row], out: &mut String) {
    out.push_str(HEADER);
    let racket = rows.iter().filter(|r| r.problem == "tennis racket");
    for r in racket.filter(|r| r.model != BASE) {
        let _ = writeln!(out, "{}", line(r));
    }
}

/// The pairs of [`PAIRS`] side by side: RK4 at every step count, DOP853 at every tolerance
/// both ran; ratios are A/B.
fn pair_table(rows: &[Row], out: &mut String) {
    out.push_str("| comparison (A / B) | method | setting | error A | error B | RHS evals A/B | time A/B | time A [µs] |\n|---|---|---|---|---|---|---|---|\n");
    let racket = |model: &'static str| {
        rows.iter().filter(move |r| {
            r.problem == "tennis racket"
                && r.model == model
                && (r.method == "RK4" || r.method == "DOP853")
        })
    };
    for (what, a_model, b_model) in PAIRS {
        for a in racket(a_model) {
            let Some(b) = racket(b_model).find(|b| b.method == a.method && b.setting == a.setting)
            else {
                continue;
            };
            let evals = ratio(a.stats.rhs_evals as f64, b.stats.rhs_evals as f64);
            let _ = writeln!(
                out,
                "| {what} | {} | {} | {} | {} | {evals} | {} | {:.1} |",
                a.method,
                a.setting,
                sci(a.error),
                sci(b.error),
                ratio(a.seconds, b.seconds),
                a.seconds * 1e6
            );
        }
    }
}

/// For each problem and target error, the fastest of our f64 runs on the base model that
/// reached it.
fn guide(rows: &[Row], out: &mut String) {
    let targets = [1e-3, 1e-6, 1e-9, 1e-12];
    out.push_str("\n| problem | target error | fastest run reaching it | error | time [µs] | RHS evals |\n|---|---|---|---|---|---|\n");
    for problem in problems(rows) {
        for target in targets {
            let ours = rows.iter().filter(|r| {
                r.problem == problem && r.model == BASE && !r.method.starts_with("ode_solvers")
            });
            let best = ours
                .filter(|r| r.error <= target)
                .min_by(|a, b| a.seconds.total_cmp(&b.seconds));
            let _ = match best {
                Some(r) => writeln!(
                    out,
                    "| {problem} | {target:.0e} | {} {} | {} | {:.1} | {} |",
                    r.method,
                    r.setting,
                    sci(r.error),
                    r.seconds * 1e6,
                    r.stats.rhs_evals
                ),
                None => writeln!(out, "| {problem} | {target:.0e} | none of the runs | | | |"),
            };
        }
    }
}

/// The whole report.
pub fn markdown(rows: &[Row]) -> String {
    let mut out = String::from("# Work–precision of the integrators of eom\n\n");
    out.push_str("Error: against the exact solution at the end of the run (each problem's measure, dimensionless). Drift: largest relative change of a conserved quantity between start and end. Time: best of repeated runs, release build, one core.\n");
    out.push_str("\n## Which run to pick for a given accuracy\n");
    guide(rows, &mut out);
    out.push_str("\n## Our Dormand–Prince methods against ode_solvers, per tolerance\n");
    peer_table(rows, &mut out);
    out.push_str("\n## Tennis racket: one difference at a time\n\nEach pair differs in one thing; ratios are A/B (time: best of repeated runs of each). The spatial models are integrated in the racket's own state layout with the translation at rest (see `benches/work_precision/spatial.rs`). \"Turned axes\": the same racket described in body axes turned from its principal axes, so every product of inertia is non-zero; its end state is turned back before judging.\n\n");
    pair_table(rows, &mut out);
    out.push_str("\n## Tennis racket: precision, kinematics, and model form\n\n");
    variant_table(rows, &mut out);
    out.push_str("\n## Every run\n");
    problem_tables(rows, &mut out);
    out.push_str("\n### tennis racket, every variant\n\n");
    variant_runs(rows, &mut out);
    out
}
