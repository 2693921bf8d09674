//! `eom eval`: one evaluation of a model's right-hand side at a state given in JSON.
//!
//! This is how a user (or a script) checks a single point by hand: the generated model and the
//! generic nalgebra form are both evaluated and their derivatives printed as JSON objects under
//! the keys `"generated"` and `"generic"`, one key per state derivative, in the order of the
//! state. The input is read and evaluated by [`eom_cli::eval`]; everything it gets wrong (a
//! missing or unknown key, a number out of range, an impossible body, a product of inertia
//! that the chosen symmetry class says is zero) is an error naming it.

use anyhow::{Context, Result};
use eom::models::{Family, Kinematics, Symmetry};
use eom_cli::eval::evaluate;
use serde::Serialize as SerializeDerive;
use serde::ser::{Serialize, SerializeMap, Serializer};
use std::io::Read;
use std::path::PathBuf;

/// Options of `eom eval`.
#[derive(clap::Args)]
pub struct Args {
    /// Which equations to evaluate: the model family.
    #[arg(long, value_parser = super::values::family())]
    model: Family,
    /// Symmetry class of a spatial body; the products it says are zero must be zero.
    #[arg(long, value_parser = super::values::symmetry(), default_value = "full")]
    symmetry: Symmetry,
    /// Attitude kinematics of a spatial body.
    #[arg(long, value_parser = super::values::kinematics(), default_value = "euler")]
    kinematics: Kinematics,
    /// The JSON input file, or `-` for standard input.
    #[arg(long)]
    input: PathBuf,
}

/// Evaluates the chosen model and prints the derivative.
pub fn run(args: Args) -> Result<()> {
    let text = read_input(&args.input)?;
    let derivative = evaluate(&text, args.model, args.symmetry, args.kinematics)?;
    let output = Output {
        generated: Ordered(&derivative.generated),
        generic: Ordered(&derivative.generic),
    };
    println!("{}", serde_json::to_string_pretty(&output)?);
    Ok(())
}

fn read_input(path: &PathBuf) -> Result<String> {
    let mut text = String::new();
    if path.as_os_str() == "-" {
        std::io::stdin()
            .read_to_string(&mut text)
            .context("reading the input from standard input")?;
    } else {
        text = std::fs::read_to_string(path)
            .with_context(|| format!("reading the input file {}", path.display()))?;
    }
    Ok(text)
}

/// The printed object; a second key can sit beside `generic`.
#[derive(SerializeDerive)]
struct Output<'a> {
    generated: Ordered<'a>,
    generic: Ordered<'a>,
}

/// Named values serialised as a JSON object in the order given (the state's order).
struct Ordered<'a>(&'a [(&'static str, f64)]);

impl Serialize for Ordered<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        // Keys are in the state's order, which is why this is not a BTreeMap.
        for (key, value) in self.0 {
            map.serialize_entry(key, value)?;
        }
        map.end()
    }
}
