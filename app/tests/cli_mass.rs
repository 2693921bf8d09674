//! `eom mass` and `eom swing` as a user runs them: the example body file, JSON that parses,
//! and clear errors with a non-zero exit for bad input.

use eom_test_support::cli::{eom_command, root};
use std::process::Output;

fn eom(args: &[&str]) -> Output {
    eom_command()
        .args(args)
        .current_dir(root())
        .output()
        .unwrap()
}

fn json(args: &[&str]) -> serde_json::Value {
    let output = eom(args);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).unwrap()
}

fn failure(args: &[&str]) -> String {
    let output = eom(args);
    assert!(!output.status.success(), "{args:?} should fail");
    assert!(output.stdout.is_empty());
    String::from_utf8(output.stderr).unwrap()
}

const SHIP: &str = "scenes/bodies/ship_blocks.toml";

#[test]
fn example_body_adds_up_by_hand() {
    let report = json(&["mass", SHIP, "--json", "--about", "0,0,0"]);
    // Hull 9000 + engine 1500 + shaft 200 + point 300, and the deckhouse: a prism 3 m wide over
    // a trapezoid of parallel sides 4 and 3.5 m, 2.5 m apart, at 120 kg/m³: 120 · 28.125.
    assert_eq!(report["mass"], 14375.0);
    assert_eq!(report["parts"][3]["mass"], 3375.0);
    assert_eq!(report["parts"][3]["name"], "deckhouse");
    // Only the crane (300 kg at y = 1.5, x = 3, z = −2) is off the centreline, so about the
    // origin Ixy = −300 · 3 · 1.5 and Iyz = −300 · 1.5 · (−2) (4.14, 4.23).
    let about = &report["about"]["inertia"];
    let ixy = about[0][1].as_f64().unwrap();
    let iyz = about[1][2].as_f64().unwrap();
    // Absolute 1e-9: sums of terms up to 5e5 in f64.
    assert!((ixy + 1350.0).abs() < 1e-9, "{ixy}");
    assert!((iyz - 900.0).abs() < 1e-9, "{iyz}");
    assert_eq!(about[0][1], about[1][0]);
}

#[test]
fn plain_output_names_every_quantity() {
    let output = eom(&["mass", SHIP]);
    assert!(output.status.success());
    let text = String::from_utf8(output.stdout).unwrap();
    for expected in [
        "Mass M",
        "14375",
        "Centre of gravity G",
        "about G",
        "κxx",
        "Principal",
        "deckhouse",
    ] {
        assert!(text.contains(expected), "missing {expected:?} in\n{text}");
    }
}

#[test]
fn bad_body_files_fail_with_the_part_and_key() {
    let dir = std::env::temp_dir().join(format!("eom-cli-mass-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("bad.toml");
    std::fs::write(&file, "[[part]]\nkind = \"box\"\nmass = 2\nsize = [1, 1]\n").unwrap();
    let message = failure(&["mass", file.to_str().unwrap()]);
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(
        message.contains("part 1") && message.contains("size"),
        "{message}"
    );
    let message = failure(&["mass", "no/such/body.toml"]);
    assert!(message.contains("cannot read body file"), "{message}");
    let message = failure(&["mass", SHIP, "--about", "1,2"]);
    assert!(message.contains("three numbers"), "{message}");
}

#[test]
fn swing_json_follows_4_28_and_4_29() {
    let report = json(&[
        "swing",
        "--period",
        "1.45",
        "--pivot-to-cg",
        "0.12",
        "--mass",
        "20",
        "--json",
    ]);
    let kappa = 1.45 / (2.0 * std::f64::consts::PI) * (9.80665_f64 * 0.12).sqrt();
    let kappa_g = (kappa * kappa - 0.12 * 0.12).sqrt();
    // Relative 1e-15: the same formula, evaluated in the same order or nearly.
    assert!((report["kappa_pivot"].as_f64().unwrap() - kappa).abs() < 1e-15 * kappa);
    assert!((report["kappa_g"].as_f64().unwrap() - kappa_g).abs() < 1e-15 * kappa_g);
    assert_eq!(report["amplitude_correction"], 0.0);
    assert!(report["kappa_g_uncorrected"].is_null());
}

#[test]
fn swing_amplitude_shortens_the_small_swing_period() {
    let report = json(&[
        "swing",
        "--period",
        "1.45",
        "--pivot-to-cg",
        "0.12",
        "--mass",
        "20",
        "--amplitude-deg",
        "15",
        "--json",
    ]);
    let correction = report["amplitude_correction"].as_f64().unwrap();
    // θ₀²/16 + 11θ₀⁴/3072 at 15° is 4.30e-3; the next term, 173θ₀⁶/737280, is 8e-8.
    let theta = 15f64.to_radians();
    assert!((correction - (theta.powi(2) / 16.0 + 11.0 * theta.powi(4) / 3072.0)).abs() < 1e-6);
    let t0 = report["small_amplitude_period"].as_f64().unwrap();
    assert!((t0 * (1.0 + correction) - 1.45).abs() < 1e-15);
    assert!(report["kappa_g_uncorrected"].as_f64().unwrap() > report["kappa_g"].as_f64().unwrap());
}

#[test]
fn bad_swing_arguments_fail_clearly() {
    let base = ["swing", "--pivot-to-cg", "0.12", "--mass", "20"];
    let cases: [(&[&str], &str); 6] = [
        (&["--period", "-1"], "'--period <PERIOD>': must be positive"),
        (
            &["--period", "NaN"],
            "'--period <PERIOD>': must be positive",
        ),
        (&["--period", "1.4", "--amplitude-deg", "180"], "below 180°"),
        (&["--period", "1.4", "--amplitude-deg", "-3"], "at least 0°"),
        (&["--period", "0.3"], "imaginary"),
        (&["--period", "fast"], "invalid value 'fast'"),
    ];
    for (extra, expected) in cases {
        let message = failure(&[&base[..], extra].concat());
        assert!(message.contains(expected), "{extra:?}: {message}");
    }
    let message = failure(&[
        "swing",
        "--period",
        "1",
        "--pivot-to-cg",
        "0",
        "--mass",
        "1",
    ]);
    assert!(
        message.contains("'--pivot-to-cg <PIVOT_TO_CG>': must be positive"),
        "{message}"
    );
    let message = failure(&[
        "swing",
        "--period",
        "1",
        "--pivot-to-cg",
        "0.1",
        "--mass",
        "-2",
    ]);
    assert!(
        message.contains("'--mass <MASS>': must be positive"),
        "{message}"
    );
}
