//! `eom models`: every generated variant and what one call of it costs.

use eom::models::generated::CATALOG;

/// Options of `eom models`.
#[derive(clap::Args)]
pub struct Args {}

/// Prints a Markdown table of the variants with their operation counts.
pub fn run(_args: Args) -> anyhow::Result<()> {
    println!("| model | add | mul | div | sqrt | trig | what |");
    println!("|---|---|---|---|---|---|---|");
    for (name, title, operations) in CATALOG {
        let counts: Vec<String> = operations.iter().map(|(_, n)| n.to_string()).collect();
        println!("| {name} | {} | {title} |", counts.join(" | "));
    }
    println!();
    for kinematics in ["euler", "quaternion"] {
        let full = arithmetic(&format!("spatial_full_{kinematics}"));
        for symmetry in ["xz", "principal"] {
            let pruned = arithmetic(&format!("spatial_{symmetry}_{kinematics}"));
            let saved = 100.0 * (full - pruned) as f64 / full as f64;
            println!(
                "spatial_{symmetry}_{kinematics}: {pruned} arithmetic operations, {saved:.0} % fewer than spatial_full_{kinematics} ({full})"
            );
        }
    }
    Ok(())
}

/// Additions, multiplications and divisions of one call.
fn arithmetic(name: &str) -> u32 {
    CATALOG
        .iter()
        .find(|(n, _, _)| *n == name)
        .map(|(_, _, ops)| {
            ops.iter()
                .filter(|(kind, _)| matches!(*kind, "add" | "mul" | "div"))
                .map(|(_, n)| n)
                .sum()
        })
        .unwrap_or(0)
}
