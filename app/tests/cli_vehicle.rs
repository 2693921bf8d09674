//! `eom run` on a vehicle scene, end to end through the binary: REMUS's Chapter 8 turn into
//! its folder (trajectory.csv, the plots, summary.json with the folded table and the
//! figures), and a vehicle scene refused by the commands that do not serve it yet.

use eom_test_support::cli::{eom, folder, scene_arg, succeeded};

#[test]
fn remus_runs_its_rudder_steps_into_a_folder() {
    let out = folder("remus100");
    let stdout = succeeded(&eom(&[
        "run",
        &scene_arg("remus100.toml"),
        "--out",
        out.to_str().unwrap(),
    ]));
    assert!(
        stdout.contains("the folded table against its added mass"),
        "{stdout}"
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let number = |v: &serde_json::Value| v.as_f64().unwrap_or_else(|| panic!("{v}"));
    assert_eq!(summary["model"]["family"], "vehicle");
    assert_eq!(summary["model"]["convention"], "prestero");
    assert_eq!(summary["model"]["terms"], 34);
    assert_eq!(summary["integrator"]["method"], "rk4");
    // The cruise at 1500 rpm: √(X_prop/−X_u|u|) and the roll trim, both to the closed forms.
    let cruise = &summary["cruise"];
    let speed = number(&cruise["speed_m_s"]);
    assert!((speed - number(&cruise["speed_closed_form_m_s"])).abs() < 1e-11);
    assert!((number(&cruise["roll_deg"]) - number(&cruise["roll_closed_form_deg"])).abs() < 1e-9);
    // The +4° turn's yaw rate where the rudder reverses, against the thesis's −9.0 °/s read
    // off its figure (to 0.5 °/s), converged to 1e-6 at half the step.
    let run = &summary["manoeuvre"]["rudder_4"];
    let turn = &run["steps"][1];
    assert_eq!(number(&turn["rudder_deg"]), 4.0);
    assert!(
        (number(&turn["yaw_rate_deg_s"]) + 9.0).abs() < 0.5,
        "{turn}"
    );
    assert!(number(&run["refined_difference"]) < 1e-6, "{run}");
    assert_eq!(run["refinement"], "half the step");
    // Every folded coefficient of Prestero's table, printed against implied.
    let kirchhoff = summary["kirchhoff"].as_array().unwrap();
    let mrp = kirchhoff
        .iter()
        .find(|row| row["coefficient"] == "Mrp")
        .unwrap();
    assert!((number(&mrp["difference"]) - 0.0504).abs() < 1e-12, "{mrp}");
    assert_eq!(
        kirchhoff
            .iter()
            .filter(|r| r["printed"].is_number())
            .count(),
        18
    );
    // The trajectory: a row every 0.1 s from 0 to 80 s, with the header of ROW.
    let csv = std::fs::read_to_string(out.join("rudder_4/trajectory.csv")).unwrap();
    let mut lines = csv.lines();
    let header = lines.next().unwrap();
    assert!(header.starts_with("t[s],u[m/s],v[m/s],w[m/s]") && header.contains("dr[rad]"));
    assert!(header.ends_with("psi[rad],kinetic_energy[J]"), "{header}");
    assert_eq!(lines.count(), 801);
    for plot in ["track.svg", "profile.svg", "attitude.svg", "fins.svg"] {
        assert!(out.join("rudder_4").join(plot).is_file(), "{plot}");
    }
}

#[test]
fn eom_linear_refuses_a_vehicle_scene_saying_why() {
    let output = eom(&["linear", &scene_arg("remus100.toml")]);
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("vehicle scene"), "{stderr}");
}
