//! `eom models`: every generated variant and what one call of it costs.

use eom::models::{CATALOG, ModelInfo};

/// Options of `eom models`.
#[derive(clap::Args)]
pub struct Args {}

/// Prints a Markdown table of the variants with their operation counts.
pub fn run(_args: Args) -> anyhow::Result<()> {
    println!("| model | add | mul | div | sqrt | trig | what |");
    println!("|---|---|---|---|---|---|---|");
    for info in &CATALOG {
        let o = info.operations;
        println!(
            "| {} | {} | {} | {} | {} | {} | {} |",
            info.name, o.add, o.mul, o.div, o.sqrt, o.trig, info.title
        );
    }
    println!();
    for info in CATALOG.iter().filter(|info| info.symmetry.is_some()) {
        let full = info.full_variant();
        if full.name == info.name {
            continue;
        }
        println!("{}", saving(info, full));
    }
    Ok(())
}

/// `spatial_xz_euler: 68 arithmetic operations, 21 % fewer than spatial_full_euler (86)`.
fn saving(info: &ModelInfo, full: &ModelInfo) -> String {
    let (pruned, all) = (info.operations.arithmetic(), full.operations.arithmetic());
    let saved = 100.0 * f64::from(all - pruned) / f64::from(all);
    format!(
        "{}: {pruned} arithmetic operations, {saved:.0} % fewer than {} ({all})",
        info.name, full.name
    )
}
