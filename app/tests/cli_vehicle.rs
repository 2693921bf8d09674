//! `eom run` on a vehicle scene, end to end through the binary: REMUS's Chapter 8 turn into
//! its folder (trajectory.csv, the plots, the 3-D view, summary.json with the folded table and
//! the figures), and `eom linear` on it: A, B and the modes at the cruise.

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
    // The run in 3-D: the solid cylinder of REMUS's mass and moments about G (I_xx = M R²/2,
    // I_yy = M(3R² + L²)/12, the mean of the two transverse moments), every row of the
    // trajectory, in every manoeuvre's folder.
    let view = std::fs::read_to_string(out.join("rudder_4/view.html")).unwrap();
    let (mass, axial, transverse) = remus_moments_about_g();
    let r2 = 2.0 * axial / mass;
    let (length, diameter) = (
        (12.0 * transverse / mass - 3.0 * r2).sqrt(),
        2.0 * r2.sqrt(),
    );
    let drawn = |key: &str| -> f64 {
        let at = view
            .find("\"shape\":{\"kind\":\"cylinder\"")
            .expect("a cylinder");
        let from = at + view[at..].find(&format!("\"{key}\":")).unwrap() + key.len() + 3;
        let to = from + view[from..].find([',', '}']).unwrap();
        view[from..to].parse().unwrap()
    };
    // The view turns the tensor about O into the one about G and into principal axes: a few
    // roundings of numbers of order 1.
    for (key, expected) in [("length", length), ("diameter", diameter)] {
        let value = drawn(key);
        assert!(
            (value - expected).abs() < 1e-12 * expected,
            "the view draws REMUS's cylinder {key} {value} against {expected}"
        );
    }
    assert!(view.contains("\"rows\":801"));
    for manoeuvre in summary["manoeuvre"].as_object().unwrap().keys() {
        assert!(
            out.join(manoeuvre).join("view.html").is_file(),
            "{manoeuvre}"
        );
    }
}

#[test]
fn eom_linear_linearises_a_vehicle_at_its_cruise_and_writes_its_matrices() {
    let out = folder("remus100_linear");
    let stdout = succeeded(&eom(&[
        "linear",
        &scene_arg("remus100.toml"),
        "--json",
        "--out",
        out.to_str().unwrap(),
    ]));
    let report: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(report["model"], "vehicle");
    assert_eq!(report["equilibrium"], true);
    assert_eq!(
        report["reduced_state"],
        serde_json::json!(["u", "v", "w", "p", "q", "r", "phi", "theta"])
    );
    assert_eq!(
        report["set_aside"],
        serde_json::json!(["x", "y", "z", "psi"])
    );
    assert_eq!(report["inputs"], serde_json::json!(["dr", "ds"]));
    assert_eq!(report["stable"], false);
    let names: Vec<&str> = (report["modes"].as_array().unwrap().iter())
        .filter_map(|m| m["name"].as_str())
        .collect();
    for plane in ["surge", "sway and yaw", "heave and pitch", "roll"] {
        assert!(names.contains(&plane), "{names:?}");
    }
    let csv = std::fs::read_to_string(out.join("A.csv")).unwrap();
    assert_eq!(csv.lines().next(), Some("u,v,w,p,q,r,phi,theta"));
    assert_eq!(csv.lines().count(), 1 + 8);
    assert!(
        csv.lines().all(|line| line.split(',').count() == 8),
        "{csv}"
    );
    assert!(out.join("B.csv").is_file() && out.join("poles.svg").is_file());
}

/// REMUS's mass and its moments about G, along its axis and across it (the mean of the two),
/// from the tensor about O its scene gives, by Steiner (4.23): I_G = I_O − M(|r_G|² 𝟙 − r_G r_Gᵀ).
fn remus_moments_about_g() -> (f64, f64, f64) {
    let path = std::path::PathBuf::from(scene_arg("remus100.toml"));
    let text = std::fs::read_to_string(&path).unwrap();
    let table = match eom::scene::AnyScene::parse(&text, "remus100.toml", path.parent().unwrap()) {
        Ok(eom::scene::AnyScene::Vehicle(scene)) => scene.table,
        _ => panic!("remus100.toml is read as a vehicle"),
    };
    assert_eq!(table.inertia_about, eom::vehicle::InertiaAbout::Origin);
    let (m, r, i) = (table.mass, table.centre_of_gravity, table.inertia);
    let squared: f64 = r.iter().map(|x| x * x).sum();
    let about_g = |k: usize| i[k][k] - m * (squared - r[k] * r[k]);
    (m, about_g(0), (about_g(1) + about_g(2)) / 2.0)
}
