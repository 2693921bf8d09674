//! `eom mass`: the mass properties of a body described in a TOML file.

use anyhow::Context;
use eom::mass::{BodyFile, MassReport};
use std::path::PathBuf;

/// Options of `eom mass`.
#[derive(clap::Args)]
pub struct Args {
    /// The body file: a TOML list of `[[part]]`s (box, sphere, ellipsoid, cylinder,
    /// hollow_cylinder, point, mesh, tensor), each with its mass, size, offset and rotation.
    file: PathBuf,
    /// Also give the inertia tensor about this point of the body axes, by Steiner's theorem
    /// (4.23), e.g. `--about 0,0,0` for the body origin.
    #[arg(long, value_parser = parse_point, allow_hyphen_values = true)]
    about: Option<[f64; 3]>,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

/// Computes and prints the mass properties of the body file.
pub fn run(args: Args) -> anyhow::Result<()> {
    let body = BodyFile::load(&args.file)?;
    let properties = body.mass_properties()?;
    let report = MassReport::new(&body, &properties, args.about)
        .context("--about: the tensor about that point")?;
    if args.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        print_text(&args.file, &report);
    }
    Ok(())
}

fn print_text(file: &std::path::Path, r: &MassReport) {
    println!("Body {} ({} parts)", file.display(), r.parts.len());
    println!("  part  kind             mass          G (x, y, z)");
    for p in &r.parts {
        let name = p
            .name
            .as_deref()
            .map_or(String::new(), |n| format!("  {n}"));
        println!(
            "  {:<4}  {:<15}  {:>12}  {}{name}",
            p.index,
            p.kind,
            number(p.mass),
            vector(&p.centre_of_gravity)
        );
    }
    println!("Mass M                        {}", number(r.mass));
    println!(
        "Centre of gravity G           {}",
        vector(&r.centre_of_gravity)
    );
    println!("Inertia tensor about G (4.12; products Ixy = −∫xy dm, 4.14):");
    print_matrix(&r.inertia_about_g);
    println!("Radii of gyration about G (4.16–4.17):");
    println!(
        "  κxx {}  κyy {}  κzz {}",
        number(r.radii_of_gyration[0]),
        number(r.radii_of_gyration[1]),
        number(r.radii_of_gyration[2])
    );
    println!("Principal moments about G, axes (in body axes) and radii of gyration:");
    for i in 0..3 {
        println!(
            "  I{} = {:>12}  axis {}  κ = {}",
            i + 1,
            number(r.principal_moments[i]),
            vector(&r.principal_axes[i]),
            number(r.principal_radii_of_gyration[i])
        );
    }
    if let Some(about) = &r.about {
        println!("Inertia tensor about {} (4.23):", vector(&about.point));
        print_matrix(&about.inertia);
    }
}

fn print_matrix(m: &[[f64; 3]; 3]) {
    for row in m {
        println!(
            "  [{:>13} {:>13} {:>13} ]",
            number(row[0]),
            number(row[1]),
            number(row[2])
        );
    }
}

fn vector(v: &[f64; 3]) -> String {
    format!("({}, {}, {})", number(v[0]), number(v[1]), number(v[2]))
}

/// Reads `x,y,z` as three numbers.
fn parse_point(text: &str) -> Result<[f64; 3], String> {
    let values: Vec<f64> = text
        .split(',')
        .map(|v| v.trim().parse::<f64>().map_err(|e| format!("{v:?}: {e}")))
        .collect::<Result<_, _>>()?;
    <[f64; 3]>::try_from(values)
        .map_err(|v| format!("expected three numbers x,y,z, got {}", v.len()))
}

/// A number to 7 significant digits without trailing zeros, in plain notation for magnitudes from 1e-4 to 1e9 and in
/// scientific notation otherwise; tiny round-off residues (below 1e-300) print as 0.
pub(super) fn number(x: f64) -> String {
    let magnitude = x.abs();
    if magnitude < 1e-300 {
        "0".to_string()
    } else if (1e-4..1e9).contains(&magnitude) {
        let decimals = (6 - magnitude.log10().floor() as i32).max(0) as usize;
        let text = format!("{x:.decimals$}");
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            text
        }
    } else {
        format!("{x:.6e}")
    }
}
