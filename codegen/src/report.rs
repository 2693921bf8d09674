//! The derivation report: every equation, its derived and reference forms, and the verdict.
//!
//! Markdown with `$…$` LaTeX, which GitHub renders. Nothing in it depends on time, paths or
//! hash order, so the same equations always give the same bytes.

use crate::check::{Component, Equation};
use crate::symbolic::{latex, parse_tree};
use std::fmt::Write;

/// The verdict on one component.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Verdict {
    /// derived − reference reduced to zero.
    Proved,
    /// What was left, or why the reference could not be read.
    Failed(String),
}

impl Verdict {
    /// Judges one component.
    pub fn of(component: &Component) -> Self {
        match component.residual() {
            Ok(r) if r.is_zero() => Verdict::Proved,
            Ok(r) => Verdict::Failed(format!("residual ${}$", latex::expr(&r))),
            Err(e) => Verdict::Failed(e.to_string()),
        }
    }

    fn text(&self) -> String {
        match self {
            Verdict::Proved => "proved".into(),
            Verdict::Failed(why) => format!("**not proved**: {why}"),
        }
    }
}

/// The whole report as Markdown.
pub fn markdown(equations: &[Equation]) -> String {
    let mut out = String::new();
    out.push_str("# Derivation report\n\n");
    out.push_str(
        "Each equation of the chapter is computed by `eom-codegen` from its vector or matrix \
         definition and proved equal to the book's form: derived − reference reduces to zero in \
         the canonical form (polynomials in the symbols and in sin, cos of the angles, with \
         sin² = 1 − cos²). `terms` counts the terms of the derived forms.\n\n",
    );
    summary(&mut out, equations);
    for equation in equations {
        details(&mut out, equation);
    }
    out
}

fn verdict_of(equation: &Equation) -> Verdict {
    equation
        .components
        .iter()
        .map(Verdict::of)
        .find(|v| *v != Verdict::Proved)
        .unwrap_or(Verdict::Proved)
}

fn summary(out: &mut String, equations: &[Equation]) {
    out.push_str("| equation | what | components | terms | verdict |\n|---|---|---|---|---|\n");
    for e in equations {
        let _ = writeln!(
            out,
            "| {} | {} | {} | {} | {} |",
            display_number(e.number),
            e.description,
            e.components.len(),
            e.term_count(),
            verdict_of(e).text()
        );
    }
    let proved = equations
        .iter()
        .filter(|e| verdict_of(e) == Verdict::Proved)
        .count();
    let _ = writeln!(out, "\n{proved} of {} equations proved.\n", equations.len());
}

fn details(out: &mut String, equation: &Equation) {
    let _ = writeln!(
        out,
        "## {} {}\n",
        display_number(equation.number),
        equation.description
    );
    out.push_str(
        "| component | derived | reference (book) | terms | verdict |\n|---|---|---|---|---|\n",
    );
    for c in &equation.components {
        let reference = parse_tree(&c.reference_text)
            .map(|tree| latex::reference(&tree))
            .unwrap_or_else(|_| c.reference_text.clone());
        let _ = writeln!(
            out,
            "| {} | ${}$ | ${}$ | {} | {} |",
            c.label,
            latex::expr(&c.derived),
            reference,
            c.derived.term_count(),
            Verdict::of(c).text()
        );
    }
    out.push('\n');
}

/// `4.51` → `(4.51)`; a variant keeps its tag outside: `4.51 xz` → `(4.51) xz`.
fn display_number(number: &str) -> String {
    match number.split_once(' ') {
        Some((n, variant)) => format!("({n}) {variant}"),
        None => format!("({number})"),
    }
}
