//! `eom new FAMILY`: a commented scene file with every key of the family, which runs as
//! printed.
//!
//! Each key is written with what it means, then a line of its unit, axes, default and whether
//! it is required, then the key set to its example (or commented out, for an alternative or
//! an option the template's run does not use). The template is short to run on purpose
//! (`integrator.end_time = 1`; a ship's one turn, as long as its tanker needs for every
//! figure): it is a form to fill in that gives figures as printed, and the tests run every
//! one.

use super::{Key, Kind, SceneFamily, Shown, keys_of};

/// The width comment lines are wrapped to.
const WIDTH: usize = 92;

/// The template of `family`: a TOML scene file with every key the family reads, commented.
pub fn template(family: SceneFamily) -> String {
    let keys: Vec<Key> = keys_of(family).collect();
    let mut out = preamble(family);
    let mut table = "";
    for (i, key) in keys.iter().enumerate() {
        if key.table() != table || i == 0 {
            table = key.table();
            let all_commented = keys
                .iter()
                .filter(|k| k.table() == table)
                .all(|k| k.shown == Shown::Commented);
            out.push_str(&header(table, all_commented));
        }
        out.push_str(&entry(key, family));
    }
    out
}

/// The article before `name`: `An` before a vowel (an aircraft), `A` otherwise.
fn article(name: &str) -> &'static str {
    match name.chars().next() {
        Some('a' | 'e' | 'i' | 'o' | 'u') => "An",
        _ => "A",
    }
}

/// What the file is, and the conventions every key follows.
fn preamble(family: SceneFamily) -> String {
    let text = format!(
        "{a} {name} scene, as `eom new {name}` writes it. {doc} Every key {a_lower} {name} scene takes \
         is here, each with what it means, its unit, its axes where it is a vector, its \
         default and whether it is required; a key shown commented out is an alternative or \
         an option this run does not use, and a key left out takes its default. Angles are in \
         degrees here and in radians in every output. Space axes: X north, Y east, Z down; \
         body axes: x forward, y to starboard, z down. The whole reference: docs/scenes.md \
         (`eom new --reference`).",
        name = family.name(),
        doc = family.doc(),
        a = article(family.name()),
        a_lower = article(family.name()).to_lowercase(),
    );
    comment(&text)
}

/// The line that opens a table: `[body]`, `[[manoeuvre]]`; a blank line for the top level.
fn header(table: &str, commented: bool) -> String {
    let line = match table {
        "" => return "\n".into(),
        array if array.ends_with("[]") => format!("[[{}]]", array.trim_end_matches("[]")),
        table => format!("[{table}]"),
    };
    let prefix = if commented { "# " } else { "" };
    format!("\n{prefix}{line}\n")
}

/// One key: its description, its facts, and the key itself.
fn entry(key: &Key, family: SceneFamily) -> String {
    let mut out = comment(key.description);
    out.push_str(&comment(&facts(key)));
    let prefix = match key.shown {
        Shown::Set => "",
        Shown::Commented => "# ",
    };
    let example = key.example_for(family);
    if key.name() == "*" {
        for line in example.lines() {
            out.push_str(&format!("{prefix}{line}\n"));
        }
    } else {
        out.push_str(&format!("{prefix}{} = {example}\n", key.name()));
    }
    out
}

/// The line of facts under a key's description: its choices, unit, axes, default and
/// whether it is required, those that apply.
fn facts(key: &Key) -> String {
    let mut facts = Vec::new();
    if let Kind::Text(choices) = key.kind {
        let names = choices.names();
        if !names.is_empty() {
            facts.push(format!("one of {}", names.join(", ")));
        }
    }
    if let Kind::Numbers(what) = key.kind {
        facts.push(what.to_owned());
    }
    match key.unit {
        "" => {}
        "-" => facts.push("dimensionless".into()),
        unit => facts.push(unit.into()),
    }
    if !key.frame.describe().is_empty() {
        facts.push(key.frame.describe().into());
    }
    if !key.default.is_empty() {
        facts.push(format!("default {}", key.default));
    }
    facts.push(key.required.describe());
    facts.join("; ")
}

/// `text` as `# ` comment lines of at most [`WIDTH`] characters, words kept whole.
fn comment(text: &str) -> String {
    let mut out = String::new();
    let mut line = String::from("#");
    for word in text.split_whitespace() {
        if line.chars().count() + 1 + word.chars().count() > WIDTH && line.len() > 1 {
            out.push_str(&line);
            out.push('\n');
            line = String::from("#");
        }
        line.push(' ');
        line.push_str(word);
    }
    out.push_str(&line);
    out.push('\n');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_wrap_at_the_width_and_keep_every_word() {
        let text = "word ".repeat(60);
        let wrapped = comment(&text);
        assert!(wrapped.lines().count() > 1);
        assert!(wrapped.lines().all(|l| l.chars().count() <= WIDTH));
        let words = wrapped.split_whitespace().filter(|w| *w == "word").count();
        assert_eq!(words, 60);
    }

    #[test]
    fn every_template_names_every_key_of_its_family() {
        for family in SceneFamily::all() {
            let text = template(family);
            for key in keys_of(family) {
                assert!(
                    text.contains(&format!("{} =", key.name())) || key.name() == "*",
                    "{}: {}",
                    family.name(),
                    key.path
                );
            }
            assert!(text.contains(&format!("`eom new {}`", family.name())));
        }
    }

    #[test]
    fn a_table_of_only_commented_keys_has_a_commented_header() {
        let text = template(SceneFamily::all()[0]);
        assert!(text.contains("\n# [sweep]\n"), "{text}");
        assert!(text.contains("\n[body]\n"));
    }
}
