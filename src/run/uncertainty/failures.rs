//! A Monte Carlo's failed cases, before and after they run.
//!
//! Before: a law that moves a number to where the scene refuses it, every other number as
//! written (a mass varied alone against a fixed weight it is checked against), would fail a
//! sixth of the cases or more for that one reason; [`refuse_contradicting_laws`] refuses the
//! scene instead, naming the number, before any case runs.
//!
//! After: cases that failed for the same reason say it once, with how many
//! ([`FailureGroup`]): their messages differ only in the numbers they quote.

use crate::kind::Kind;
use crate::scene::uncertainty::Uncertainty;
use crate::scene::{AnyScene, Problem, SceneError};
use serde::Serialize;
use std::path::Path;

/// Refuses `uncertainty` where the scene refuses one of its numbers moved alone to one of its
/// law's probes ([`crate::scene::uncertainty::Varied::probes`]: a value a sixth of the cases
/// or more draw beyond), the other numbers as written; `nominal` is the scene as written, read
/// (`name` its file, `base` its folder). Each probe reads the scene once, as a case does.
pub fn refuse_contradicting_laws(
    uncertainty: &Uncertainty,
    nominal: &dyn Kind,
    (name, base): (&str, &Path),
) -> Result<(), SceneError> {
    for (number, value) in uncertainty.probes() {
        let one = [(number.key.as_str(), value)];
        let read = match nominal.with_numbers(name, &one) {
            Some(read) => read.map(drop),
            None => {
                let values: Vec<f64> = (uncertainty.varied.iter())
                    .map(|v| {
                        if v.key == number.key {
                            value
                        } else {
                            v.nominal
                        }
                    })
                    .collect();
                AnyScene::from_table(uncertainty.table_with(&values), name, base).map(drop)
            }
        };
        if let Err(refused) = read {
            let refused = match refused.key.is_empty() {
                true => refused.problem.to_string(),
                false => format!("`{}`: {}", refused.key, refused.problem),
            };
            let message = format!(
                "`{key}` varied alone to {value} (from the scene's {nominal}; a sixth of the \
                 cases or more would go further) is refused by the scene: {refused}. Each \
                 varied number is drawn on its own, every other number as the scene writes it, \
                 so a number the scene checks against another cannot vary alone: leave it out \
                 of [uncertainty.vary], or give the scene a value it does not contradict",
                key = number.key,
                nominal = number.nominal,
            );
            return Err(SceneError::new(
                name,
                "uncertainty.vary",
                Problem::Invalid(message),
            ));
        }
    }
    Ok(())
}

/// The cases that failed for one reason.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FailureGroup {
    /// The reason: the message with each number it quotes written `#`.
    pub reason: String,
    /// How many cases failed so.
    pub count: usize,
    /// The first of them, by case number.
    pub first_case: usize,
    /// Its message, numbers and all.
    pub example: String,
}

/// The failed cases of `failed` ((case, why), in the order of the case numbers) grouped by
/// reason, the most frequent first (ties in the order their first case comes).
pub fn group_failures(failed: &[(usize, String)]) -> Vec<FailureGroup> {
    let mut groups: Vec<FailureGroup> = Vec::new();
    for (case, why) in failed {
        let reason = reason_of(why);
        match groups.iter_mut().find(|group| group.reason == reason) {
            Some(group) => group.count += 1,
            None => groups.push(FailureGroup {
                reason,
                count: 1,
                first_case: *case,
                example: why.clone(),
            }),
        }
    }
    // A stable sort: equal counts keep the order of their first case.
    groups.sort_by_key(|group| std::cmp::Reverse(group.count));
    groups
}

/// `message` with each number it quotes (a run of digits not inside a word, with its sign,
/// decimals and exponent) written `#`.
fn reason_of(message: &str) -> String {
    let chars: Vec<char> = message.chars().collect();
    let mut reason = String::with_capacity(message.len());
    let mut i = 0;
    while i < chars.len() {
        let in_word = i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_');
        let starts = |at: usize| chars.get(at).is_some_and(char::is_ascii_digit);
        let signed = matches!(chars[i], '-' | '+' | '−') && starts(i + 1);
        if in_word || !(starts(i) || signed) {
            reason.push(chars[i]);
            i += 1;
            continue;
        }
        i += 1;
        while i < chars.len() {
            let exponent = matches!(chars[i], 'e' | 'E')
                && (starts(i + 1)
                    || (matches!(chars.get(i + 1), Some('-' | '+')) && starts(i + 2)));
            match chars[i] {
                c if c.is_ascii_digit() => i += 1,
                '.' if starts(i + 1) => i += 1,
                _ if exponent => i += 2,
                _ => break,
            }
        }
        reason.push('#');
    }
    reason
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reason_is_its_message_with_the_numbers_written_hash() {
        assert_eq!(
            reason_of("`body.mass`: 30.91 kg contradicts `body.weight` = 299 N: W/M = 9.67e-1"),
            "`body.mass`: # kg contradicts `body.weight` = # N: W/M = #"
        );
        // Digits inside a word (a key, a unit) are the word's.
        assert_eq!(
            reason_of("step h2 of f32 at -1.5E+3 s"),
            "step h2 of f32 at # s"
        );
        assert_eq!(reason_of("t = 12 s."), "t = # s.");
    }

    #[test]
    fn failures_group_by_reason_the_most_frequent_first() {
        let failed = [
            (2, "diverged at t = 3.5 s".to_owned()),
            (3, "mass 31.2 contradicts weight".to_owned()),
            (5, "mass 29.9 contradicts weight".to_owned()),
            (8, "diverged at t = 1 s".to_owned()),
            (9, "mass 30.7 contradicts weight".to_owned()),
            (11, "not finite".to_owned()),
        ];
        let groups = group_failures(&failed);
        let counts: Vec<(usize, usize)> = groups.iter().map(|g| (g.count, g.first_case)).collect();
        assert_eq!(counts, [(3, 3), (2, 2), (1, 11)]);
        assert_eq!(groups[0].reason, "mass # contradicts weight");
        assert_eq!(groups[0].example, "mass 31.2 contradicts weight");
    }
}
