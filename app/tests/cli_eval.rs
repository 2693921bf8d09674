//! `eom eval` as a user runs it: the built binary, JSON on standard input or in a file, the
//! derivative printed as JSON, and a clear error (never a panic) for every bad input.

use eom_test_support::cli::eom_command;
use serde_json::Value;

use eom_test_support::eval::{Run, eval};

/// The `generic` object of a successful run, as (key, value) pairs in printed order.
fn generic(run: &Run) -> Vec<(String, f64)> {
    section(run, "generic")
}

fn section(run: &Run, name: &str) -> Vec<(String, f64)> {
    assert!(run.ok, "eom eval failed: {}", run.stderr);
    let text = run.stdout.trim();
    // serde_json's map is sorted, so the printed order is read from the text itself.
    let parsed: Value = serde_json::from_str(text).unwrap();
    let object = parsed[name].as_object().expect("an object per form");
    let mut keys: Vec<&String> = object.keys().collect();
    keys.sort_by_key(|k| text.find(&format!("\"{k}\"")).unwrap());
    keys.into_iter()
        .map(|k| (k.clone(), object[k].as_f64().unwrap()))
        .collect()
}

fn value(pairs: &[(String, f64)], key: &str) -> f64 {
    pairs
        .iter()
        .find(|(k, _)| k == key)
        .map(|(_, v)| *v)
        .unwrap()
}

fn fails_naming(args: &[&str], input: &str, needle: &str) {
    let run = eval(args, input);
    assert!(!run.ok, "expected a failure, got {}", run.stdout);
    assert!(
        run.stderr.contains(needle),
        "{needle:?} not in {:?}",
        run.stderr
    );
    assert!(!run.stderr.contains("panicked"), "{}", run.stderr);
}

const PRINCIPAL: &str = r#"{"mass": 2.0, "inertia": [[2,0,0],[0,3,0],[0,0,4]],
  "state": {"u": 1, "v": 0, "w": 0, "p": 0, "q": 0, "r": 0.5, "phi": 0, "theta": 0, "psi": 0},
  "force": [2, 0, 0], "moment": [0, 0, 4]}"#;

const TILTED: &str = r#"{"mass": 2.0, "inertia": [[2,0,-0.1],[0,3,0],[-0.1,0,4]],
  "state": {"u": 1, "v": 0.5, "w": -0.2, "p": 0.1, "q": 0.2, "r": 0.3,
            "phi": 0.1, "theta": 0.2, "psi": 0.3},
  "force": [1, 0, 0], "moment": [0, 0, 0.5]}"#;

#[test]
fn spatial_euler_prints_hand_computed_rates_in_state_order() {
    let pairs = generic(&eval(
        &["--model", "spatial", "--symmetry", "principal"],
        PRINCIPAL,
    ));
    // v̇ = F/M − ω×v with ω×v = (0, 0.5, 0); ṙ = N/Izz; track and ψ̇ = r at zero attitude.
    // All exact in binary floating point.
    let expected = [
        ("u_dot", 1.0),
        ("v_dot", -0.5),
        ("w_dot", 0.0),
        ("p_dot", 0.0),
        ("q_dot", 0.0),
        ("r_dot", 1.0),
        ("x_dot", 1.0),
        ("y_dot", 0.0),
        ("z_dot", 0.0),
        ("phi_dot", 0.0),
        ("theta_dot", 0.0),
        ("psi_dot", 0.5),
    ];
    let got: Vec<(&str, f64)> = pairs.iter().map(|(k, v)| (k.as_str(), *v)).collect();
    assert_eq!(got, expected);
}

#[test]
fn spatial_quaternion_shares_the_euler_rates_and_gives_half_q_omega() {
    let euler = generic(&eval(&["--model", "spatial", "--symmetry", "xz"], TILTED));
    let quat = generic(&eval(
        &["--model", "spatial", "--kinematics", "quaternion"],
        TILTED,
    ));
    let keys: Vec<&str> = quat.iter().map(|(k, _)| k.as_str()).collect();
    assert_eq!(&keys[9..12], ["phi_dot", "theta_dot", "psi_dot"]);
    assert_eq!(&keys[12..], ["q0_dot", "q1_dot", "q2_dot", "q3_dot"]);
    // The accelerations come from one code path; the position rates from a matrix and a
    // quaternion rotation of one attitude, equal to a few ulps of |v| ≈ 1.1.
    for (e, q) in euler.iter().zip(&quat).take(12) {
        assert_eq!(e.0, q.0);
        assert!((e.1 - q.1).abs() <= 1e-15, "{e:?} vs {q:?}");
    }
    // At zero attitude q = 1, so q̇ = ½ (0, p, q, r) exactly.
    let level = PRINCIPAL
        .replace("\"r\": 0.5", "\"p\": 0.5, \"q\": -1, \"r\": 0.25")
        .replace("\"p\": 0, \"q\": 0, ", "");
    let at_rest = generic(&eval(
        &["--model", "spatial", "--kinematics", "quaternion"],
        &level,
    ));
    let q_dot: Vec<f64> = at_rest[12..].iter().map(|(_, v)| *v).collect();
    assert_eq!(q_dot, [0.0, 0.25, -0.5, 0.125]);
}

#[test]
fn pendulum_at_ninety_degrees_feels_full_gravity_moment() {
    let input = r#"{"i0": 2, "mass": 3, "g": 9.81, "h": 0.5, "moment": 1,
        "state": {"theta": 1.5707963267948966, "theta_dot": 1.5}}"#;
    let pairs = generic(&eval(&["--model", "pendulum"], input));
    // θ̈ = (−M g h sin θ + moment)/I₀ = (−14.715 + 1)/2; sin(π/2) rounds to 1 exactly.
    assert_eq!(value(&pairs, "theta_dot"), 1.5);
    assert!((value(&pairs, "theta_ddot") - (-13.715 / 2.0)).abs() <= 1e-14);
}

#[test]
fn planar_midship_with_g_at_midship_equals_planar_g() {
    let state = r#""state": {"u": 2, "v": -0.5, "r": 0.3, "x": 0, "y": 0, "psi": 0.7},
        "force": [10, -4], "moment": 3"#;
    let at_g = generic(&eval(
        &["--model", "planar-g"],
        &format!(r#"{{"mass": 5, "izz": 20, {state}}}"#),
    ));
    let mid = format!(r#"{{"mass": 5, "izz": 20, "x_g": 0, {state}}}"#);
    let midship = generic(&eval(&["--model", "planar-midship"], &mid));
    // Only the 2×2 inverse differs; relative 1e-15 on O(1) values.
    for (g, m) in at_g.iter().zip(&midship) {
        assert_eq!(g.0, m.0);
        assert!(
            (g.1 - m.1).abs() <= 1e-15 * (1.0 + g.1.abs()),
            "{g:?} vs {m:?}"
        );
    }
    assert_eq!(value(&at_g, "u_dot"), 10.0 / 5.0 + -0.5 * 0.3);
}

#[test]
fn planar_space_accelerations_are_force_over_mass() {
    let input = r#"{"mass": 4, "izz": 8, "force": [2, -6], "moment": 1,
        "state": {"x": 1, "y": 2, "psi": 3, "x_dot": 4, "y_dot": 5, "psi_dot": 6}}"#;
    let pairs = generic(&eval(&["--model", "planar-space"], input));
    let values: Vec<f64> = pairs.iter().map(|(_, v)| *v).collect();
    assert_eq!(values, [4.0, 5.0, 6.0, 0.5, -1.5, 0.125]);
}

#[test]
fn bad_inputs_fail_with_errors_that_name_the_culprit() {
    let spatial = ["--model", "spatial"];
    fails_naming(&spatial, r#"{"mass": 2}"#, "inertia");
    fails_naming(
        &spatial,
        &PRINCIPAL.replace("\"force\"", "\"forse\""),
        "forse",
    );
    fails_naming(
        &spatial,
        &PRINCIPAL.replace("\"mass\": 2.0", "\"mass\": -2"),
        "mass must be positive and finite, got -2",
    );
    fails_naming(
        &spatial,
        &PRINCIPAL.replace("\"mass\": 2.0", "\"mass\": 1e999"),
        "line 1",
    );
    fails_naming(
        &spatial,
        &PRINCIPAL.replace("[2,0,0]", "[9,0,0]"),
        "triangle",
    );
    fails_naming(
        &spatial,
        &PRINCIPAL.replace("[2,0,0],[0,3,0]", "[2,0,0],[0.1,3,0]"),
        "symmetric",
    );
    fails_naming(
        &["--model", "spatial", "--symmetry", "principal"],
        TILTED,
        "inertia Ixz = -0.1 must be zero for the principal",
    );
    fails_naming(&spatial, "{not json", "parsing the input JSON");
    let pitched = TILTED.replace("\"theta\": 0.2", "\"theta\": 1.5707963267948966");
    fails_naming(&spatial, &pitched, "--kinematics quaternion");
    assert!(
        eval(
            &["--model", "spatial", "--kinematics", "quaternion"],
            &pitched
        )
        .ok
    );
    let pendulum =
        r#"{"i0": 1, "mass": 1, "g": 9.81, "h": 2, "state": {"theta": 0, "theta_dot": 0}}"#;
    fails_naming(
        &["--model", "pendulum"],
        pendulum,
        "i0 must be at least mass · h²",
    );
    let planar = r#"{"mass": 1, "izz": 1, "force": [0, 0], "moment": 0,
        "state": {"u": 0, "v": 0, "r": 0, "x": 0, "y": 0, "psi": 0}}"#;
    fails_naming(&["--model", "planar-midship"], planar, "x_g");
}

#[test]
fn missing_input_file_is_named() {
    let out = eom_command()
        .args([
            "eval",
            "--model",
            "pendulum",
            "--input",
            "/nonexistent/eval.json",
        ])
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("/nonexistent/eval.json"));
}

#[test]
fn generated_and_generic_forms_agree_for_every_spatial_variant() {
    for symmetry in ["full", "xz"] {
        for kinematics in ["euler", "quaternion"] {
            let args = [
                "--model",
                "spatial",
                "--symmetry",
                symmetry,
                "--kinematics",
                kinematics,
            ];
            let run = eval(&args, TILTED);
            let (generated, generic) = (section(&run, "generated"), section(&run, "generic"));
            assert_eq!(generated.len(), generic.len());
            // Two f64 forms of one formula on values of order one: a few ulps, well below 1e-13.
            for (g, n) in generated.iter().zip(&generic) {
                assert_eq!(g.0, n.0);
                assert!(
                    (g.1 - n.1).abs() <= 1e-13 * (1.0 + n.1.abs()),
                    "{symmetry} {kinematics}: {g:?} vs {n:?}"
                );
            }
        }
    }
}

#[test]
fn quaternion_variant_at_ninety_degrees_pitch_omits_only_the_euler_rates() {
    let vertical = TILTED.replace(&TILTED[TILTED.find("\"theta\"").unwrap()..], "\"theta\": 1.5707963267948966, \"psi\": 0.3}, \"force\": [1, 0, 0], \"moment\": [0, 0, 0.5]}");
    let run = eval(
        &["--model", "spatial", "--kinematics", "quaternion"],
        &vertical,
    );
    let keys: Vec<String> = section(&run, "generated")
        .into_iter()
        .map(|(k, _)| k)
        .collect();
    assert!(!keys.iter().any(|k| k == "theta_dot"), "{keys:?}");
    assert_eq!(keys.len(), 13);
    let refused = eval(&["--model", "spatial", "--kinematics", "euler"], &vertical);
    assert!(
        !refused.ok && refused.stderr.contains("quaternion"),
        "{}",
        refused.stderr
    );
}

#[test]
fn the_top_family_is_refused_with_a_reason_not_a_panic() {
    fails_naming(
        &["--model", "top"],
        "{}",
        "eval does not cover the top family yet",
    );
}
