//! `eom linear` on catalog scenes, as a user runs it: the JSON report's keys and values (the
//! pendulum against √(Mgh/I₀)), the files `--out` writes and the folder rules they obey (the
//! state-space model in linear.json and linear.mat, C and D by `linear.outputs`), and the exit
//! codes of a bad `[linear]` table (3) and of a trim that does not converge (5).

use eom_test_support::cli::{eom, folder, root, succeeded};
use serde_json::Value;
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

/// A planar hull pushed against its damping at 2 m/s, with `linear` as its `[linear]` table,
/// written into `dir`: its track and heading are set aside, (u, v, r) reduced, three inputs.
fn hull(dir: &Path, linear: &str) -> String {
    let text = format!(
        "title = \"A damped hull, ψ₀ = 0°\"\n[body]\nmass = 1000.0\nizz = 2.0e5\n[model]\n\
         family = \"planar-g\"\n[initial]\nu = 2.0\n[loads]\nforce_body = [200.0, 0.0]\n\
         linear_damping = [100.0, 400.0, 8.0e4]\n[integrator]\nmethod = \"dop853\"\nend_time = 1.0\n{linear}"
    );
    let path = dir.join("hull.toml");
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// A JSON array of rows as a matrix.
fn matrix(value: &Value) -> Vec<Vec<f64>> {
    serde_json::from_value(value.clone()).unwrap()
}

/// A JSON array of strings.
fn names(value: &Value) -> Vec<String> {
    serde_json::from_value(value.clone()).unwrap()
}

/// A CSV file's header and rows of numbers.
fn csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|line| line.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    (header, rows)
}

#[test]
fn out_writes_the_state_space_model_as_linear_json_beside_the_matrices() {
    let dir = folder("linear_json");
    let scene = hull(&dir, "");
    let out = dir.join("out");
    let printed = succeeded(&eom(&["linear", &scene, "--out", out.to_str().unwrap()]));
    assert!(
        printed.contains("linear.json, linear.mat"),
        "the files are listed as written: {printed}"
    );
    let manifest = std::fs::read_to_string(out.join(".eom-run")).unwrap();
    for file in ["linear.json", "linear.mat"] {
        assert!(manifest.lines().any(|l| l == file), "{file}: {manifest}");
    }
    let model: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("linear.json")).unwrap()).unwrap();
    // The object `--json` prints, to the last bit of every number.
    let printed: Value =
        serde_json::from_str(&succeeded(&eom(&["linear", &scene, "--json"]))).unwrap();
    assert_eq!(model, printed);
    assert_eq!(model["scene"], scene.as_str(), "the scene file as given");
    assert_eq!(model["title"], "A damped hull, ψ₀ = 0°");
    // x is the reduced state, named as A.csv's header; u the inputs, as B.csv's.
    let (a_header, a_rows) = csv(&out.join("A.csv"));
    let (b_header, b_rows) = csv(&out.join("B.csv"));
    assert_eq!(names(&model["x_names"]), ["u", "v", "r"]);
    assert_eq!(names(&model["x_names"]), a_header);
    assert_eq!(names(&model["u_names"]), b_header);
    assert_eq!(names(&model["x_names"]), names(&model["reduced_state"]));
    assert_eq!(names(&model["u_names"]), names(&model["inputs"]));
    assert_eq!(names(&model["x_units"]), ["m/s", "m/s", "rad/s"]);
    assert_eq!(names(&model["u_units"]), ["N", "N", "N m"]);
    let (a, b) = (matrix(&model["A"]), matrix(&model["B"]));
    assert_eq!(a, a_rows, "A.csv holds linear.json's A");
    assert_eq!(b, b_rows, "B.csv holds linear.json's B");
    let (n, m) = (3, 3);
    assert!(a.len() == n && a.iter().all(|row| row.len() == n));
    assert!(b.len() == n && b.iter().all(|row| row.len() == m));
    // By default y is the whole reduced state: C the identity, D zero.
    let identity: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| f64::from(u8::from(i == j))).collect())
        .collect();
    assert_eq!(matrix(&model["C"]), identity);
    assert_eq!(matrix(&model["D"]), vec![vec![0.0; m]; n]);
    assert_eq!(model["y_names"], model["x_names"]);
    assert_eq!(model["y_units"], model["x_units"]);
    // The point: the reduced state and the inputs there.
    let x0: Vec<f64> = serde_json::from_value(model["x0"].clone()).unwrap();
    let u0: Vec<f64> = serde_json::from_value(model["u0"].clone()).unwrap();
    assert_eq!(x0, [2.0, 0.0, 0.0]);
    assert_eq!(u0.len(), m);
    assert_eq!(x0[0], model["operating_point"]["u"].as_f64().unwrap());
    // What was set aside, its values and why; how A and B were obtained.
    assert_eq!(names(&model["set_aside"]), ["X", "Y", "psi"]);
    assert_eq!(
        model["set_aside_values"],
        serde_json::json!([0.0, 0.0, 0.0])
    );
    assert_eq!(
        names(&model["set_aside_why"]),
        ["only integrates the rest"; 3]
    );
    let jacobians = model["jacobians"].as_str().unwrap();
    assert!(jacobians.starts_with("emitted and proved"), "{jacobians}");
    let text = std::fs::read_to_string(out.join("report.txt")).unwrap();
    assert!(text.contains(&format!("A and B: {jacobians}")), "{text}");
}

#[test]
fn linear_outputs_pick_the_rows_of_c() {
    let dir = folder("linear_outputs");
    let scene = hull(&dir, "[linear]\noutputs = [\"r\", \"v\"]\n");
    let model: Value =
        serde_json::from_str(&succeeded(&eom(&["linear", &scene, "--json"]))).unwrap();
    assert_eq!(names(&model["y_names"]), ["r", "v"]);
    assert_eq!(names(&model["y_units"]), ["rad/s", "m/s"]);
    assert_eq!(
        matrix(&model["C"]),
        [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0]],
        "2 × n: each row picks its output from x = (u, v, r)"
    );
    assert_eq!(matrix(&model["D"]), vec![vec![0.0; 3]; 2]);
}

#[test]
fn an_output_that_is_not_a_state_entry_is_refused_naming_the_key() {
    let dir = folder("linear_outputs_unknown");
    let scene = hull(&dir, "[linear]\noutputs = [\"u\", \"speed\"]\n");
    let output = eom(&["linear", &scene]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(3), "{stderr}");
    assert!(
        stderr.contains("linear.outputs[1]")
            && stderr.contains("`speed`")
            && stderr.contains("u, v, r, X, Y, psi"),
        "{stderr}"
    );
    // A state set aside at the point has no row in A: refused too, and why.
    let scene = hull(&dir, "[linear]\noutputs = [\"psi\"]\n");
    let output = eom(&["linear", &scene, "--out", dir.join("out").to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(3), "{stderr}");
    assert!(
        stderr.contains("linear.outputs[0]") && stderr.contains("`psi` is set aside"),
        "{stderr}"
    );
    assert!(!dir.join("out").exists(), "nothing written");
}

/// One variable of a MAT-file, as the test reads it.
#[derive(Debug)]
struct Variable {
    class: u32,
    dimensions: Vec<usize>,
    /// A double array's entries, column by column, as bits.
    doubles: Vec<u64>,
    /// A char array's text.
    text: String,
    /// A cell array's cells.
    cells: Vec<Variable>,
}

/// The u32 at `at`, little-endian.
fn word(bytes: &[u8], at: usize) -> u32 {
    u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap())
}

/// The data elements of `bytes` (tag and data, each padded to 8 bytes), as (type, data).
fn elements(bytes: &[u8]) -> Vec<(u32, &[u8])> {
    let mut found = Vec::new();
    let mut at = 0;
    while at < bytes.len() {
        let (kind, size) = (word(bytes, at), word(bytes, at + 4) as usize);
        found.push((kind, &bytes[at + 8..at + 8 + size]));
        at += 8 + size.next_multiple_of(8);
    }
    assert_eq!(at, bytes.len(), "the elements fill the bytes exactly");
    found
}

/// A `miMATRIX` element's data: flags, dimensions, name, and its class's data.
fn variable(data: &[u8]) -> (String, Variable) {
    let parts = elements(data);
    assert_eq!(
        (parts[0].0, parts[1].0, parts[2].0),
        (6, 5, 1),
        "array flags (miUINT32), dimensions (miINT32), name (miINT8)"
    );
    let class = word(parts[0].1, 0) & 0xff;
    let dimensions = (parts[1].1.chunks(4))
        .map(|d| i32::from_le_bytes(d.try_into().unwrap()) as usize)
        .collect();
    let name = String::from_utf8(parts[2].1.to_vec()).unwrap();
    let mut read = Variable {
        class,
        dimensions,
        doubles: Vec::new(),
        text: String::new(),
        cells: Vec::new(),
    };
    match class {
        // mxDOUBLE_CLASS, its data miDOUBLE.
        6 => {
            assert_eq!(parts[3].0, 9);
            read.doubles = (parts[3].1.chunks(8))
                .map(|d| u64::from_le_bytes(d.try_into().unwrap()))
                .collect();
        }
        // mxCHAR_CLASS, its data miUTF16.
        4 => {
            assert_eq!(parts[3].0, 17);
            let units: Vec<u16> = (parts[3].1.chunks(2))
                .map(|d| u16::from_le_bytes(d.try_into().unwrap()))
                .collect();
            read.text = String::from_utf16(&units).unwrap();
        }
        // mxCELL_CLASS: a miMATRIX per cell, unnamed.
        1 => {
            for (kind, cell) in &parts[3..] {
                assert_eq!(*kind, 14);
                let (name, cell) = variable(cell);
                assert!(name.is_empty());
                read.cells.push(cell);
            }
        }
        other => panic!("class {other}"),
    }
    (name, read)
}

#[test]
fn linear_mat_holds_the_same_model_for_matlab() {
    let dir = folder("linear_mat");
    let scene = hull(&dir, "[linear]\noutputs = [\"r\", \"v\"]\n");
    let out = dir.join("out");
    succeeded(&eom(&["linear", &scene, "--out", out.to_str().unwrap()]));
    let model: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("linear.json")).unwrap()).unwrap();
    let bytes = std::fs::read(out.join("linear.mat")).unwrap();
    // The Level 5 header: text, no subsystem data, version 0x0100, little-endian ("IM").
    assert!(bytes.starts_with(b"MATLAB 5.0 MAT-file"));
    assert_eq!(&bytes[116..124], &[0; 8]);
    assert_eq!(&bytes[124..128], &[0x00, 0x01, b'I', b'M']);
    let variables: Vec<(String, Variable)> = elements(&bytes[128..])
        .into_iter()
        .map(|(kind, data)| {
            assert_eq!(kind, 14, "each variable a miMATRIX");
            variable(data)
        })
        .collect();
    let get = |name: &str| {
        &(variables.iter().find(|(n, _)| n == name))
            .unwrap_or_else(|| panic!("no {name}"))
            .1
    };
    // Every key of the state-space model is a variable.
    for key in [
        "A",
        "B",
        "C",
        "D",
        "x_names",
        "u_names",
        "y_names",
        "x_units",
        "u_units",
        "y_units",
        "x0",
        "u0",
        "set_aside",
        "set_aside_values",
        "set_aside_why",
        "jacobians",
        "scene",
        "title",
    ] {
        get(key);
    }
    // The matrices: doubles of linear.json's shape, column by column, to the bit.
    for key in ["A", "B", "C", "D"] {
        let rows = matrix(&model[key]);
        let read = get(key);
        assert_eq!(read.class, 6, "{key}");
        assert_eq!(read.dimensions, [rows.len(), rows[0].len()], "{key}");
        let columns: Vec<u64> = (0..rows[0].len())
            .flat_map(|j| rows.iter().map(move |row| row[j].to_bits()))
            .collect();
        assert_eq!(read.doubles, columns, "{key}");
    }
    assert_eq!(get("C").dimensions, [2, 3]);
    // x0 as a column; the names as a column of cells of text.
    let x0: Vec<f64> = serde_json::from_value(model["x0"].clone()).unwrap();
    assert_eq!(get("x0").dimensions, [3, 1]);
    assert_eq!(
        get("x0").doubles,
        x0.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
    );
    for key in [
        "x_names",
        "u_names",
        "y_names",
        "x_units",
        "set_aside",
        "set_aside_why",
    ] {
        let read = get(key);
        assert_eq!(read.class, 1, "{key}");
        let texts: Vec<&str> = read.cells.iter().map(|c| c.text.as_str()).collect();
        assert_eq!(texts, names(&model[key]), "{key}");
        for cell in &read.cells {
            assert_eq!(cell.class, 4);
            assert_eq!(cell.dimensions, [1, cell.text.encode_utf16().count()]);
        }
    }
    // A title beyond ASCII, whole: one dimension per UTF-16 unit.
    assert_eq!(get("title").text, "A damped hull, ψ₀ = 0°");
    assert_eq!(get("title").dimensions, [1, 22]);
    assert_eq!(get("scene").text, scene);
    assert_eq!(get("jacobians").text, model["jacobians"].as_str().unwrap());
}
