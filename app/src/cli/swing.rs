//! `eom swing`: the swing test (4.24–4.29) from a measured period, with the correction for a
//! finite amplitude.

use super::mass::number;
use eom::swing::{STANDARD_GRAVITY, SwingResult, SwingTest};
use serde::Serialize;

/// Options of `eom swing`.
#[derive(clap::Args)]
pub struct Args {
    /// The measured period T of the swing, in seconds.
    #[arg(long, allow_negative_numbers = true, value_parser = super::values::positive)]
    period: f64,
    /// The distance h from the pivot to the centre of gravity G, in metres.
    #[arg(
        long = "pivot-to-cg",
        allow_negative_numbers = true,
        value_parser = super::values::positive
    )]
    pivot_to_cg: f64,
    /// The mass M, in kilograms.
    #[arg(long, allow_negative_numbers = true, value_parser = super::values::positive)]
    mass: f64,
    /// The amplitude θ₀ of the swing, in degrees; without it, the small-swing formula (4.28).
    #[arg(
        long = "amplitude-deg",
        allow_negative_numbers = true,
        value_parser = super::values::amplitude_deg
    )]
    amplitude_deg: Option<f64>,
    /// Gravity g, in m/s².
    #[arg(
        long,
        default_value_t = STANDARD_GRAVITY,
        allow_negative_numbers = true,
        value_parser = super::values::positive
    )]
    gravity: f64,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Report {
    period: f64,
    pivot_to_cg: f64,
    mass: f64,
    gravity: f64,
    amplitude_deg: f64,
    period_factor: f64,
    amplitude_correction: f64,
    small_amplitude_period: f64,
    kappa_pivot: f64,
    inertia_pivot: f64,
    equivalent_length: f64,
    kappa_g: f64,
    inertia_g: f64,
    kappa_g_uncorrected: Option<f64>,
}

/// Solves the swing test and prints the results.
pub fn run(args: Args) -> anyhow::Result<()> {
    let amplitude_deg = args.amplitude_deg.unwrap_or(0.0);
    let test = SwingTest {
        period: args.period,
        pivot_to_cg: args.pivot_to_cg,
        mass: args.mass,
        gravity: args.gravity,
        amplitude: amplitude_deg.to_radians(),
    };
    // The flags are each checked when read; what is left is a period too short for the
    // distance given, a usage error that names both flags.
    let result = test
        .solve()
        .map_err(|error| super::run::Usage(format!("--period with --pivot-to-cg: {error}")))?;
    // What the small-swing formula alone would say, to show the size of the correction; it can
    // fail (κ ≤ h) where the corrected one does not, and then there is nothing to compare.
    let uncorrected = match args.amplitude_deg {
        Some(_) => SwingTest {
            amplitude: 0.0,
            ..test
        }
        .solve()
        .ok()
        .map(|r| r.kappa_g),
        None => None,
    };
    let report = report(&test, amplitude_deg, &result, uncorrected);
    if args.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        print_text(&report);
    }
    Ok(())
}

fn report(
    test: &SwingTest,
    amplitude_deg: f64,
    r: &SwingResult,
    uncorrected: Option<f64>,
) -> Report {
    Report {
        period: test.period,
        pivot_to_cg: test.pivot_to_cg,
        mass: test.mass,
        gravity: test.gravity,
        amplitude_deg,
        period_factor: r.period_factor,
        amplitude_correction: r.period_factor - 1.0,
        small_amplitude_period: r.small_amplitude_period,
        kappa_pivot: r.kappa_pivot,
        inertia_pivot: r.inertia_pivot,
        equivalent_length: r.equivalent_length,
        kappa_g: r.kappa_g,
        inertia_g: r.inertia_g,
        kappa_g_uncorrected: uncorrected,
    }
}

fn print_text(r: &Report) {
    println!("Swing test (compound pendulum, 4.24–4.29)");
    println!("  measured period T                 {} s", number(r.period));
    println!(
        "  pivot to G, h                     {} m",
        number(r.pivot_to_cg)
    );
    println!("  mass M                            {} kg", number(r.mass));
    println!(
        "  gravity g                         {} m/s²",
        number(r.gravity)
    );
    println!(
        "  amplitude θ₀                      {}°",
        number(r.amplitude_deg)
    );
    println!(
        "  period factor T/T₀ = (2/π)K(m)    {}  (amplitude correction {:+.4} %)",
        number(r.period_factor),
        100.0 * r.amplitude_correction
    );
    println!(
        "  small-amplitude period T₀         {} s",
        number(r.small_amplitude_period)
    );
    println!(
        "  κ about the pivot (4.28)          {} m",
        number(r.kappa_pivot)
    );
    println!(
        "  I₀ = M κ²                         {} kg·m²",
        number(r.inertia_pivot)
    );
    println!(
        "  equivalent length ℓ = κ²/h (4.26) {} m",
        number(r.equivalent_length)
    );
    println!(
        "  κ_G = √(κ² − h²) (4.29)           {} m",
        number(r.kappa_g)
    );
    println!(
        "  I_G = M κ_G² (4.29)               {} kg·m²",
        number(r.inertia_g)
    );
    if let Some(k) = r.kappa_g_uncorrected {
        let off = 100.0 * (k / r.kappa_g - 1.0);
        println!(
            "  κ_G if θ₀ were ignored            {} m ({off:+.4} %)",
            number(k)
        );
    }
}
