//! `eom linear` on catalog scenes, as a user runs it: the JSON report's keys and values (the
//! pendulum against √(Mgh/I₀)), the files `--out` writes and the folder rules they obey, and
//! the exit codes of a bad `[linear]` table (3) and of a trim that does not converge (5).

use eom_test_support::cli::{eom, folder, root, succeeded};
use std::path::Path;

/// The repository's pendulum scene with `extra` appended, written into `dir`.
fn pendulum(dir: &Path, extra: &str) -> String {
    let scenes = root().join("scenes");
    let text = std::fs::read_to_string(scenes.join("pendulum.toml")).unwrap();
    let path = dir.join("pendulum.toml");
    std::fs::write(&path, text + extra).unwrap();
    path.display().to_string()
}

#[test]
fn the_json_report_has_every_key_and_the_pendulum_swings_at_its_closed_form() {
    let dir = folder("json");
    let scene = pendulum(&dir, "\n[linear]\nat = { theta = 0.0 }\n");
    let report: serde_json::Value =
        serde_json::from_str(&succeeded(&eom(&["linear", &scene, "--json"]))).unwrap();
    for key in [
        "scene",
        "operating_point",
        "reduced_state",
        "set_aside",
        "inputs",
        "A",
        "B",
        "eigenvalues",
        "modes",
        "stable",
    ] {
        assert!(report.get(key).is_some(), "{key} missing: {report}");
    }
    assert_eq!(
        report["reduced_state"],
        serde_json::json!(["theta", "theta_dot"])
    );
    assert_eq!(report["operating_point"]["theta"], 0.0);
    let omega = (3.0f64 * 9.81 * 0.5 / 2.0).sqrt();
    let im = report["eigenvalues"][0]["im"].as_f64().unwrap().abs();
    assert!((im - omega).abs() <= 1e-9 * omega, "{im} against {omega}");
    let mode = &report["modes"][0];
    assert_eq!(mode["name"], "the pendulum's swing");
    for key in [
        "re",
        "im",
        "period_s",
        "damping_ratio",
        "time_to_double_s",
        "time_to_half_s",
        "dominant",
    ] {
        assert!(mode.get(key).is_some(), "{key} missing: {mode}");
    }
    // Undamped, the swing neither grows nor decays: marginal, which the linear model cannot
    // call stable or unstable.
    assert_eq!(report["verdict"], "marginal");
    assert_eq!(report["stable"], serde_json::Value::Null);
}

#[test]
fn out_writes_the_matrices_and_the_pole_plot_and_keeps_the_folder_rules() {
    let dir = folder("out");
    let scene = pendulum(&dir, "");
    let out = dir.join("linear");
    let out_text = out.display().to_string();
    let report: serde_json::Value = serde_json::from_str(&succeeded(&eom(&[
        "linear", &scene, "--json", "--out", &out_text,
    ])))
    .unwrap();
    let a = std::fs::read_to_string(out.join("A.csv")).unwrap();
    assert_eq!(
        a.lines().next(),
        Some("theta,theta_dot"),
        "a header of state names"
    );
    let read: Vec<Vec<f64>> = a
        .lines()
        .skip(1)
        .map(|line| line.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    let json: Vec<Vec<f64>> = serde_json::from_value(report["A"].clone()).unwrap();
    assert_eq!(read, json, "A.csv holds the report's A, to the last bit");
    assert_eq!(
        std::fs::read_to_string(out.join("B.csv"))
            .unwrap()
            .lines()
            .collect::<Vec<_>>(),
        ["M_O", "0e0", "5e-1"],
        "B.csv: a header of input names, then ∂θ̇/∂M_O = 0 and ∂θ̈/∂M_O = 1/I₀"
    );
    // The text report is kept beside the matrices, as the command prints it.
    let printed = succeeded(&eom(&["linear", &scene]));
    let kept = std::fs::read_to_string(out.join("report.txt")).unwrap();
    assert_eq!(kept, printed);
    assert!(
        std::fs::read_to_string(out.join("poles.svg"))
            .unwrap()
            .contains("<svg")
    );
    // The folder now holds a run: without --force it is kept (exit 4), with it replaced.
    let again = eom(&["linear", &scene, "--out", &out_text]);
    assert_eq!(
        again.status.code(),
        Some(4),
        "{}",
        String::from_utf8_lossy(&again.stderr)
    );
    succeeded(&eom(&["linear", &scene, "--out", &out_text, "--force"]));
    // A folder with someone else's file is refused.
    let foreign = dir.join("foreign");
    std::fs::create_dir_all(&foreign).unwrap();
    std::fs::write(foreign.join("A.csv"), "mine").unwrap();
    let refused = eom(&["linear", &scene, "--out", &foreign.display().to_string()]);
    assert_eq!(refused.status.code(), Some(4));
    assert_eq!(
        std::fs::read_to_string(foreign.join("A.csv")).unwrap(),
        "mine"
    );
}

#[test]
fn a_name_the_model_does_not_have_is_a_scene_error_naming_the_key() {
    let dir = folder("unknown");
    let scene = pendulum(&dir, "\n[linear]\ntrim = [\"psi\"]\n");
    let output = eom(&["linear", &scene]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(3), "{stderr}");
    assert!(
        stderr.contains("linear.trim[0]") && stderr.contains("theta, theta_dot"),
        "{stderr}"
    );
}

#[test]
fn a_trim_that_does_not_converge_says_so_and_exits_5() {
    let dir = folder("diverges");
    // θ cannot stop a pendulum turning at 1 rad/s: θ's own rate is θ̇.
    let scene = pendulum(
        &dir,
        "\n[linear]\nat = { theta_dot = 1.0 }\ntrim = [\"theta\"]\n",
    );
    let output = eom(&["linear", &scene]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(5), "{stderr}");
    assert!(stderr.contains("the trim did not converge"), "{stderr}");
    // It names the state whose rate is left, says it once, and counts its steps in English.
    assert!(stderr.contains("dtheta/dt is still"), "{stderr}");
    assert_eq!(stderr.matches("did not converge").count(), 1, "{stderr}");
    assert!(!stderr.contains("1 Newton steps"), "{stderr}");
}

#[test]
fn a_point_that_is_not_an_equilibrium_is_said_with_by_how_much() {
    let dir = folder("not_equilibrium");
    let text = succeeded(&eom(&["linear", &pendulum(&dir, "")]));
    // Released at 150°: θ̈ = −Mgh sin θ / I₀ = −3.67875 rad/s².
    assert!(
        text.contains("NOT an equilibrium") && text.contains("-3.678750e0"),
        "{text}"
    );
    // No verdict rests on it, and no mode is named as if it were a motion about the point.
    assert!(
        text.contains("verdict: none: the point is not an equilibrium"),
        "{text}"
    );
    assert!(
        !text.contains("UNSTABLE") && !text.contains("swing"),
        "{text}"
    );
    let report: serde_json::Value =
        serde_json::from_str(&succeeded(&eom(&["linear", &pendulum(&dir, ""), "--json"]))).unwrap();
    assert_eq!(report["equilibrium"], false);
    assert_eq!(report["stable"], serde_json::Value::Null);
    assert_eq!(report["verdict"], serde_json::Value::Null);
    let why = report["stability"].as_str().unwrap();
    assert!(
        why.contains("not an equilibrium") && why.contains("linear.trim"),
        "{why}"
    );
}

/// Every example scene: a verdict only at an equilibrium, and none that rests on round-off
/// (a free body at rest is marginal; no mode's doubling time is beyond 10⁹ s).
#[test]
fn every_example_scene_gets_a_verdict_that_holds() {
    let scenes = root().join("scenes");
    for entry in std::fs::read_dir(&scenes).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let output = eom(&["linear", path.to_str().unwrap(), "--json"]);
        let stdout = String::from_utf8_lossy(&output.stdout);
        let Ok(report) = serde_json::from_str::<serde_json::Value>(&stdout) else {
            panic!(
                "{}: {}",
                path.display(),
                String::from_utf8_lossy(&output.stderr)
            );
        };
        let name = path.file_name().unwrap().to_string_lossy();
        let equilibrium = report["equilibrium"].as_bool().unwrap();
        assert_eq!(report["verdict"].is_null(), !equilibrium, "{name}");
        if !equilibrium {
            assert!(report["stable"].is_null(), "{name}");
        }
        for mode in report["modes"].as_array().unwrap() {
            let double = mode["time_to_double_s"].as_f64().unwrap_or(0.0);
            assert!(
                double < 1e9,
                "{name}: a doubling time of {double} s is round-off"
            );
        }
        if name == "thruster_burn.toml" {
            assert_eq!(report["verdict"], "marginal", "a free body at rest");
            let reduced = report["reduced_state"].as_array().unwrap();
            assert!(
                !reduced.iter().any(|n| n == "q0"),
                "no quaternion: {reduced:?}"
            );
        }
    }
}
