//! `eom new FAMILY`: print a scene template with every key of the family, commented, that
//! runs as printed; `eom new --reference` prints the reference page, docs/scenes.md.
//!
//! Both come from the one key table of `eom::scene::reference`, so a template, the page and
//! the scene checker cannot disagree. The family is checked by clap against that table's
//! families: an unknown one is a usage error (exit 2) that lists them.

use anyhow::Result;
use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use eom::scene::reference::{SceneFamily, markdown, template};

/// Options of `eom new`.
#[derive(clap::Args)]
pub struct Args {
    /// The family to write a template of.
    #[arg(value_parser = family())]
    family: Option<SceneFamily>,
    /// Print the reference of every key of every family (Markdown; docs/scenes.md) instead.
    #[arg(long, conflicts_with = "family")]
    reference: bool,
}

/// A parser for a family's name, each with its one-line doc as help.
fn family() -> impl TypedValueParser<Value = SceneFamily> {
    let values = SceneFamily::all()
        .into_iter()
        .map(|f| PossibleValue::new(f.name()).help(f.doc()));
    PossibleValuesParser::new(values)
        .map(|name| SceneFamily::from_name(&name).expect("clap accepts only the families' names"))
}

/// Runs `eom new`: the template or the page, to standard output; without either, a usage
/// error that lists the families (clap's own "required argument" names none of them).
pub fn run(args: Args) -> Result<()> {
    let text = match (args.family, args.reference) {
        (Some(family), _) => template(family),
        (None, true) => markdown(),
        (None, false) => {
            let families: Vec<String> = (SceneFamily::all().iter())
                .map(|f| format!("  {:<16} {}", f.name(), f.doc()))
                .collect();
            let message = format!(
                "eom new takes the family to write a template of (or --reference):\n{}\n\
                 for example: eom new spatial > my_body.toml",
                families.join("\n")
            );
            return Err(super::run::Usage(message).into());
        }
    };
    print!("{text}");
    Ok(())
}
