//! `eom derive` prints the derivation report: every equation proved, the same bytes each run.

use eom_test_support::cli::eom_command;

fn derive() -> std::process::Output {
    eom_command()
        .arg("derive")
        .output()
        .expect("the eom binary runs")
}

#[test]
fn derive_prints_a_repeatable_report_with_every_equation_proved() {
    let (first, second) = (derive(), derive());
    assert!(first.status.success());
    assert_eq!(first.stdout, second.stdout);
    let report = String::from_utf8(first.stdout).unwrap();
    for number in [
        "(4.9)",
        "(4.23)",
        "(4.46)",
        "(4.51)",
        "(4.57) EᵀE",
        "(4.60)",
    ] {
        assert!(report.contains(number), "{number} missing from the report");
    }
    assert!(!report.contains("not proved"));
}

#[test]
fn derive_timing_goes_to_stderr_only() {
    let output = eom_command().args(["derive", "--timing"]).output().unwrap();
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert!(stderr.contains("derived and proved"), "{stderr}");
    assert_eq!(output.stdout, derive().stdout);
}
