//! `integrator.stop_when`: a condition on the state that ends a run where it first holds.
//!
//! The condition is one comparison, `NAME OP NUMBER`: NAME is `t` or an entry of the model's
//! state as trajectory.csv names it (`z`, `theta_dot`, `q0`), OP one of `<`, `>`, `<=`, `>=`,
//! and NUMBER a finite number as TOML writes one (`10`, `-2.5`, `1e-3`). It is parsed here,
//! once, into a [`StopCondition`] that reads one state entry; the run evaluates it at the end
//! of every step and, on the step where it first holds, finds the first time it holds on that
//! step (see [`crate::run`]). Anything else — an unknown name, another operator, a second
//! comparison — is an error listing what is allowed, so a condition is never silently
//! misread.

use crate::validate::Requirement;
use std::fmt;

/// One comparison of a state entry, or of the time, with a number.
#[derive(Debug, Clone, PartialEq)]
pub struct StopCondition {
    /// The condition as the scene wrote it, for the summary.
    pub text: String,
    /// The state entry compared, or `None` for the time t.
    pub index: Option<usize>,
    /// The comparison.
    pub comparison: Comparison,
    /// The number compared with.
    pub value: f64,
}

/// The comparisons a condition can make.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Comparison {
    /// `<`
    Less,
    /// `>`
    Greater,
    /// `<=`
    LessOrEqual,
    /// `>=`
    GreaterOrEqual,
}

impl Comparison {
    /// Every comparison by its symbol, the two-character ones first (so that `<=` is not
    /// read as `<`).
    const ALL: [(Comparison, &'static str); 4] = [
        (Comparison::LessOrEqual, "<="),
        (Comparison::GreaterOrEqual, ">="),
        (Comparison::Less, "<"),
        (Comparison::Greater, ">"),
    ];

    fn holds(self, x: f64, value: f64) -> bool {
        match self {
            Comparison::Less => x < value,
            Comparison::Greater => x > value,
            Comparison::LessOrEqual => x <= value,
            Comparison::GreaterOrEqual => x >= value,
        }
    }
}

impl StopCondition {
    /// Parses `text` against the state's entry names; the error says what is wrong.
    pub fn parse(text: &str, state_names: &[String]) -> Result<Self, String> {
        let (name, comparison, number) = split(text)?;
        let index = match name {
            "t" => None,
            _ => Some(
                state_names
                    .iter()
                    .position(|n| n == name)
                    .ok_or_else(|| unknown_name(name, state_names))?,
            ),
        };
        let value: f64 = number
            .replace('_', "")
            .parse()
            .map_err(|_| format!("`{number}` is not a number; {FORM}"))?;
        let value = Requirement::Finite
            .check(value)
            .map_err(|violation| format!("the number {violation}"))?;
        Ok(Self {
            text: text.trim().to_owned(),
            index,
            comparison,
            value,
        })
    }

    /// Whether the condition holds at time `t` and state `state`. A value that is NaN makes
    /// it false, as every comparison with NaN is.
    pub fn holds(&self, t: f64, state: &[f64]) -> bool {
        let x = self.index.map_or(t, |i| state[i]);
        self.comparison.holds(x, self.value)
    }
}

impl fmt::Display for StopCondition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

/// How a condition is written, for the errors.
const FORM: &str = "write NAME OP NUMBER, OP one of <, >, <=, >= (\"z > 10\")";

/// The name, the comparison and the number of `text`.
fn split(text: &str) -> Result<(&str, Comparison, &str), String> {
    let (at, comparison, symbol) = Comparison::ALL
        .iter()
        .filter_map(|(c, s)| text.find(s).map(|at| (at, *c, *s)))
        .min_by_key(|(at, _, s)| (*at, std::cmp::Reverse(s.len())))
        .ok_or_else(|| format!("no comparison in `{text}`; {FORM}"))?;
    let name = text[..at].trim();
    let number = text[at + symbol.len()..].trim();
    let is_name = !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !is_name {
        return Err(format!("`{name}` is not a name; {FORM}"));
    }
    if number.is_empty() || number.contains(['<', '>', '=', ' ']) {
        return Err(format!("`{number}` is not one number; {FORM}"));
    }
    Ok((name, comparison, number))
}

fn unknown_name(name: &str, state_names: &[String]) -> String {
    let mut names = vec!["t"];
    names.extend(state_names.iter().map(String::as_str));
    format!("unknown name `{name}`; one of {}", names.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names() -> Vec<String> {
        ["u", "z", "theta_dot"].map(String::from).to_vec()
    }

    #[test]
    fn comparisons_parse_to_the_entry_they_read() {
        let parse = |text: &str| StopCondition::parse(text, &names()).unwrap();
        let c = parse("z > 10");
        assert_eq!(
            (c.index, c.comparison, c.value),
            (Some(1), Comparison::Greater, 10.0)
        );
        let c = parse("theta_dot<=-2.5e-1");
        assert_eq!(
            (c.index, c.comparison, c.value),
            (Some(2), Comparison::LessOrEqual, -0.25)
        );
        let c = parse("  t >= 1_000 ");
        assert_eq!(
            (c.index, c.comparison, c.value),
            (None, Comparison::GreaterOrEqual, 1000.0)
        );
        assert_eq!(c.text, "t >= 1_000");
        assert!(parse("u < 0").holds(0.0, &[-1.0, 0.0, 0.0]));
        assert!(!parse("u < 0").holds(0.0, &[f64::NAN, 0.0, 0.0]));
        assert!(parse("t >= 2").holds(2.0, &[0.0; 3]) && !parse("t > 2").holds(2.0, &[0.0; 3]));
    }

    #[test]
    fn what_is_not_a_comparison_is_refused_saying_why() {
        let cases = [
            ("zz > 1", "unknown name `zz`; one of t, u, z, theta_dot"),
            ("z == 1", "no comparison in `z == 1`"),
            ("z 1", "no comparison"),
            ("> 1", "`` is not a name"),
            ("z > 1 < 2", "is not one number"),
            ("z > ten", "`ten` is not a number"),
            ("z > inf", "must be finite"),
            ("z + 1 > 2", "`z + 1` is not a name"),
        ];
        for (text, expected) in cases {
            let error = StopCondition::parse(text, &names()).unwrap_err();
            assert!(error.contains(expected), "{text}: {error}");
        }
    }
}
