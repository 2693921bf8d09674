//! `eom run` and `eom linear` on an aircraft scene, end to end through the binary: the F-16
//! of `scenes/f16.toml` trimmed at 502 ft/s and its manoeuvres into a folder, its linear model
//! at the trim, a sweep over its centre of gravity, `eom new aircraft`, and bad input refused
//! by key.

use eom_test_support::cli::{eom, folder, run_into, scene, scene_arg, succeeded};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Output;

fn json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn number(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v}"))
}

/// `scenes/f16.toml` with each `(from, to)` replaced once; each must be in it.
fn f16_with(edits: &[(&str, &str)]) -> String {
    let mut text = std::fs::read_to_string(scene("f16.toml")).unwrap();
    for (from, to) in edits {
        assert!(text.contains(from), "{from}");
        text = text.replacen(from, to, 1);
    }
    text
}

/// `eom run` of scene `text`, written beside the fresh output folder of `test`, into that
/// folder: what the command did, and the folder.
fn run_text(test: &str, text: &str) -> (Output, PathBuf) {
    let out = folder(test);
    let file = out.with_extension("toml");
    std::fs::write(&file, text).unwrap();
    let output = eom(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    (output, out)
}

/// The pull-up held for 20 s at 10°, into a loop or a departure.
const PULLED: (&str, &str) = (
    "amount = 3.0\nstart_s = 1.0\nduration_s = 4.0",
    "amount = 10.0\nstart_s = 1.0\nduration_s = 20.0",
);

/// The attitude in a quaternion.
const QUATERNION: (&str, &str) = (
    "aerodynamics = \"stevens-lewis\"\n",
    "aerodynamics = \"stevens-lewis\"\nkinematics = \"quaternion\"\n",
);

/// The F-16 runs its five manoeuvres from the level trim at 502 ft/s, x_cg = 0.35 c̄: the trim
/// is Table 3.6-3's first column to its printed digits, every manoeuvre writes its rows, and
/// the rudder kick's Dutch roll, read from the yaw rate's swings, has the linear model's
/// period to 1 % and its damping to 2 % (measured: 0.2 % and 0.5 %; the rest is the
/// response's nonlinearity and the roll and spiral modes that ride on the yaw rate).
#[test]
fn the_f16_runs_its_manoeuvres_from_its_trim() {
    let out = folder("f16");
    let stdout = run_into(&scene("f16.toml"), &out, None);
    assert!(stdout.contains("trim: V = 502 ft/s"), "{stdout}");
    let summary = json(&out.join("summary.json"));
    assert_eq!(summary["kind"], "aircraft");
    assert_eq!(summary["units"]["vt"], "ft/s");
    assert_eq!(summary["units"]["elevator"], "deg");
    let trim = &summary["trim"];
    assert!(
        (number(&trim["state"]["alpha"]) - 0.03691).abs() <= 0.5e-5,
        "{trim}"
    );
    assert!((number(&trim["controls"]["throttle"]) - 0.1385).abs() <= 0.5e-4);
    assert!((number(&trim["controls"]["elevator"]) + 0.7588).abs() <= 0.5e-4);
    assert!(number(&trim["residual"]) < 1e-10);
    for name in [
        "elevator_doublet",
        "aileron_step",
        "rudder_kick",
        "throttle_step",
        "pull_up",
    ] {
        let csv = std::fs::read_to_string(out.join(name).join("trajectory.csv")).unwrap();
        let header = csv.lines().next().unwrap();
        assert!(
            header.starts_with("t[s],vt[ft/s],alpha[rad],beta[rad],"),
            "{header}"
        );
        assert!(header.contains(",elevator[deg],"), "{header}");
        assert!(
            header.ends_with(",load_factor[g],kinetic_energy[ft lbf]"),
            "{header}"
        );
        assert!(csv.lines().count() > 50, "{name}");
        for drawn in ["angles.svg", "rates.svg", "load_factor.svg", "view.html"] {
            assert!(out.join(name).join(drawn).exists(), "{name}/{drawn}");
        }
        assert!(summary["manoeuvre"][name]["figures"]["peak_load_factor_g"].is_number());
    }
    // A 3° pull-up pulls more than 1 g; the aileron step rolls.
    let pull_up = &summary["manoeuvre"]["pull_up"]["figures"];
    assert!(number(&pull_up["peak_load_factor_g"]) > 2.0, "{pull_up}");
    let roll = &summary["manoeuvre"]["aileron_step"]["figures"];
    assert!(number(&roll["roll_rate_peak_deg_s"]) > 5.0, "{roll}");
    let kick = &summary["manoeuvre"]["rudder_kick"]["figures"];
    let (period, linear) = (
        number(&kick["dutch_roll_period_s"]),
        number(&kick["dutch_roll_period_linear_s"]),
    );
    assert!((period / linear - 1.0).abs() < 0.01, "{kick}");
    assert_dutch_roll_read_as_linear(kick);
}

/// The Dutch roll read from a rudder kick's response against the linear model's: the period
/// to 1 %, the damping ratio to 2 %.
fn assert_dutch_roll_read_as_linear(kick: &Value) {
    let ratio = |read: &str, linear: &str| number(&kick[read]) / number(&kick[linear]) - 1.0;
    let period = ratio("dutch_roll_period_s", "dutch_roll_period_linear_s");
    let damping = ratio("dutch_roll_damping", "dutch_roll_damping_linear");
    assert!(period.abs() < 0.01, "{kick}");
    assert!(damping.abs() < 0.02, "{kick}");
}

/// The Navion on its stability derivatives (`aircraft.aerodynamics = "derivatives"`) runs as
/// the F-16 on its tables does: trimmed at 176 ft/s, every manoeuvre written, the rudder
/// kick's Dutch roll read from the response as the linear model gives it (the yaw rate drifts
/// after the kick, a spiral's, which the reading takes out), and `eom linear` names its five
/// modes and keeps the power lag apart.
#[test]
fn the_navion_runs_on_its_derivatives() {
    let out = folder("navion");
    let stdout = run_into(&scene("navion.toml"), &out, None);
    assert!(stdout.contains("trim: V = 176 ft/s"), "{stdout}");
    let summary = json(&out.join("summary.json"));
    for name in [
        "elevator_doublet",
        "aileron_step",
        "rudder_kick",
        "throttle_step",
    ] {
        assert!(out.join(name).join("trajectory.csv").exists(), "{name}");
    }
    assert_dutch_roll_read_as_linear(&summary["manoeuvre"]["rudder_kick"]["figures"]);
    // The view draws the aircraft from its geometry: the fuselage its 27.5 ft long and a
    // tenth of that across (it was the cylinder of the mass and principal moments, which the
    // wing's inertia swells: 26 m across a 747).
    let view = std::fs::read_to_string(out.join("rudder_kick/view.html")).unwrap();
    let shape =
        r#""shape":{"kind":"aircraft","length":27.5,"diameter":2.75,"span":33.4,"chord":5.7"#;
    assert!(
        view.contains(shape),
        "{}",
        &view[view.find("\"shape\"").unwrap_or(0)..][..120]
    );
    let stdout = succeeded(&eom(&["linear", &scene_arg("navion.toml"), "--json"]));
    let linear: Value = serde_json::from_str(&stdout).unwrap();
    let names: Vec<&str> = (linear["modes"].as_array().unwrap().iter())
        .filter_map(|m| m["name"].as_str())
        .collect();
    for mode in [
        "short period",
        "phugoid",
        "roll subsidence",
        "Dutch roll",
        "spiral",
        "power lag",
    ] {
        assert!(names.contains(&mode), "{mode} not in {names:?}");
    }
}

/// The Boeing 747 on Etkin & Reid's table (speed derivatives, C_Lα̇, the products of inertia
/// typed as the book prints them) runs its manoeuvres, its report echoes the inertia tensor
/// eom uses (the book's I_zx = ∫zx dm = −0.212e7 kg m² as the tensor's +2.12e6), and
/// `eom linear` names its modes (the height mode as such), the short period, phugoid, roll and
/// Dutch roll decaying.
#[test]
fn the_747_runs_on_its_jet_derivatives_and_echoes_its_tensor() {
    let out = folder("b747");
    let stdout = run_into(&scene("b747.toml"), &out, None);
    assert!(stdout.contains("trim: V = 235.9 m/s"), "{stdout}");
    let tensor = "inertia about G, the tensor eom uses (kg m²; off-diagonal entries −∫xz dm): \
                  [[2.47e7, 0e0, 2.12e6], [0e0, 4.49e7, 0e0], [2.12e6, 0e0, 6.73e7]]";
    assert!(stdout.contains(tensor), "{stdout}");
    let summary = json(&out.join("summary.json"));
    assert_dutch_roll_read_as_linear(&summary["manoeuvre"]["rudder_kick"]["figures"]);
    let stdout = succeeded(&eom(&["linear", &scene_arg("b747.toml"), "--json"]));
    let linear: Value = serde_json::from_str(&stdout).unwrap();
    let modes = linear["modes"].as_array().unwrap();
    let names: Vec<&str> = modes.iter().filter_map(|m| m["name"].as_str()).collect();
    for mode in [
        "short period",
        "phugoid",
        "roll subsidence",
        "Dutch roll",
        "spiral",
    ] {
        assert!(names.contains(&mode), "{mode} not in {names:?}");
    }
    // The slow real root of the density's fall with height is the height mode (its α and θ
    // move together, which once named it a short period split in two).
    let count = |name: &str| names.iter().filter(|n| **n == name).count();
    assert_eq!(count("short period"), 1, "{names:?}");
    assert_eq!(count("height"), 1, "{names:?}");
    assert_eq!(count("short period, aperiodic"), 0, "{names:?}");
    for name in ["short period", "phugoid", "roll subsidence", "Dutch roll"] {
        let mode = modes.iter().find(|m| m["name"] == name).unwrap();
        assert!(mode["time_to_double_s"].is_null(), "{mode}");
    }
}

/// `eom linear` at the shipped trim: the operating point under the state's and controls'
/// names (α in rad, the elevator in degrees), each unit said, the eigenvalues, and the modes
/// named as flight people name them. At x_cg = 0.35 c̄ the unaugmented F-16 is unstable in
/// pitch: a real root grows (time to double about 7 s), as the doublet's departure shows.
#[test]
fn the_f16_linearises_at_its_trim_and_names_its_modes() {
    let stdout = succeeded(&eom(&["linear", &scene_arg("f16.toml"), "--json"]));
    let linear: Value = serde_json::from_str(&stdout).unwrap();
    let point = &linear["operating_point"];
    assert!(
        (number(&point["alpha"]) - 0.03691).abs() <= 0.5e-5,
        "{point}"
    );
    assert!(
        (number(&point["elevator"]) + 0.7588).abs() <= 0.5e-4,
        "{point}"
    );
    assert!(
        (number(&point["throttle"]) - 0.1385).abs() <= 0.5e-4,
        "{point}"
    );
    let names: Vec<&str> = linear["x_names"]
        .as_array()
        .unwrap()
        .iter()
        .map(|n| n.as_str().unwrap())
        .collect();
    let units: Vec<&str> = linear["x_units"]
        .as_array()
        .unwrap()
        .iter()
        .map(|n| n.as_str().unwrap())
        .collect();
    assert_eq!(names[0], "vt");
    assert_eq!(units[0], "ft/s");
    assert!(
        !names.contains(&"north") && !names.contains(&"psi"),
        "{names:?}"
    );
    assert_eq!(
        linear["u_names"],
        serde_json::json!(["throttle", "elevator", "aileron", "rudder"])
    );
    let modes = linear["modes"].as_array().unwrap();
    let named: Vec<&str> = modes.iter().filter_map(|m| m["name"].as_str()).collect();
    for name in ["Dutch roll", "roll subsidence", "spiral", "power lag"] {
        assert!(named.contains(&name), "{name} in {named:?}");
    }
    let dutch = modes.iter().find(|m| m["name"] == "Dutch roll").unwrap();
    assert!((number(&dutch["period_s"]) - 2.05).abs() < 0.01, "{dutch}");
    assert_eq!(linear["verdict"], "unstable");
    let growing = modes.iter().find(|m| number(&m["re"]) > 0.0).unwrap();
    assert!(
        (number(&growing["time_to_double_s"]) - 6.76).abs() < 0.01,
        "{growing}"
    );
}

/// A sweep over the centre of gravity runs each case into its table; at x_cg = 0.30 c̄ the
/// F-16 is stable and its modes carry the book's names: the short period at −1.20 ± 1.49i.
#[test]
fn a_sweep_over_the_centre_of_gravity_runs_each_case() {
    let text = f16_with(&[(
        "# eom linear: at the trim",
        "[sweep]\n\"geometry.xcg\" = [0.30, 0.35]\n\n# eom linear: at the trim",
    )]);
    let (output, out) = run_text("f16_sweep", &text);
    succeeded(&output);
    let table = std::fs::read_to_string(out.join("sweep.csv")).unwrap();
    let mut lines = table.lines();
    let header = lines.next().unwrap();
    assert!(header.contains("geometry.xcg"), "{header}");
    assert!(
        header.contains("rudder_kick.dutch_roll_period_s"),
        "{header}"
    );
    assert_eq!(lines.count(), 2, "{table}");
    let stable = text_with_xcg(&std::fs::read_to_string(scene("f16.toml")).unwrap(), "0.30");
    let file = out.with_file_name("f16_030.toml");
    std::fs::write(&file, stable).unwrap();
    let stdout = succeeded(&eom(&["linear", file.to_str().unwrap(), "--json"]));
    let linear: Value = serde_json::from_str(&stdout).unwrap();
    let modes = linear["modes"].as_array().unwrap();
    let short = modes.iter().find(|m| m["name"] == "short period").unwrap();
    assert!((number(&short["re"]) + 1.2038).abs() < 1e-3, "{short}");
    assert!((number(&short["im"]) - 1.4920).abs() < 1e-3, "{short}");
    assert_eq!(
        linear["verdict"], "stable",
        "every mode decays (the heading set aside)"
    );
}

fn text_with_xcg(text: &str, xcg: &str) -> String {
    text.replace("xcg = 0.35 # fraction", &format!("xcg = {xcg} # fraction"))
}

/// The template `eom new aircraft` writes runs: it trims and flies its doublet.
#[test]
fn eom_new_aircraft_writes_a_scene_that_runs() {
    let template = succeeded(&eom(&["new", "aircraft"]));
    let stdout = succeeded(&run_text("new_aircraft", &template).0);
    assert!(stdout.contains("elevator_doublet"), "{stdout}");
}

/// A pull-up held into a loop stops where the pitch comes within 1° of 90° (the Euler angles'
/// singularity), saying so (exit 5), rather than writing rates that are not the aircraft's.
#[test]
fn a_loop_stops_at_the_euler_angles_singularity_saying_so() {
    let (output, _) = run_text("f16_loop", &f16_with(&[PULLED]));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(5), "{stderr}");
    assert!(stderr.contains("manoeuvre pull_up"), "{stderr}");
    assert!(stderr.contains("within 1° of ±90°"), "{stderr}");
    assert!(stderr.contains("kinematics = \"quaternion\""), "{stderr}");
}

/// A failed manoeuvre keeps what finished: the F-16 trimmed at 1500 ft/s with its doublet
/// moved last. Three manoeuvres dive through θ = −89° (the throttle step, the pull-up and the
/// doublet); the aileron step and the rudder kick finish. The run still exits 5, and its
/// summary.json holds the two finished manoeuvres' figures, with each failure in `error`.
#[test]
fn a_failed_manoeuvre_keeps_the_finished_figures_and_the_rest_still_run() {
    let doublet = "[[manoeuvre]]\nkind = \"elevator_doublet\"\namount = 1.0 # deg\nstart_s = 1.0\n\
                   width_s = 1.0\nduration_s = 5.0\n\n";
    let text = f16_with(&[
        ("speed = 502.0 # ft/s", "speed = 1500.0 # ft/s"),
        (doublet, ""),
        ("[integrator]", &format!("{doublet}[integrator]")),
    ]);
    let (output, out) = run_text("f16_fast_doublet_last", &text);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(5), "{stderr}");
    let summary = json(&out.join("summary.json"));
    let finished: Vec<&String> = summary["manoeuvre"].as_object().unwrap().keys().collect();
    assert_eq!(finished, ["aileron_step", "rudder_kick"], "{stderr}");
    for name in finished {
        let figures = &summary["manoeuvre"][name]["figures"];
        assert!(
            figures["peak_load_factor_g"].is_number(),
            "{name}: {figures}"
        );
    }
    let error = summary["error"].as_str().unwrap();
    for failed in ["throttle_step", "pull_up", "elevator_doublet"] {
        assert!(error.contains(&format!("manoeuvre {failed}: ")), "{error}");
    }
    assert!(error.contains("within 1° of ±90°"), "{error}");
    assert!(
        stderr.contains("the 2 runs that finished (aileron_step, rudder_kick)"),
        "{stderr}"
    );
}

/// A departure: the unaugmented F-16 at x_cg = 0.35 c̄ pulling 10° of elevator for 20 s, in a
/// quaternion so that the pitch does not stop it, tumbles past the tables' 45° of α. The run
/// goes on (the F-16's code extends its tables linearly, and so does eom), and its summary
/// says that the rows beyond are that extension, not data.
#[test]
fn a_departure_beyond_the_tables_says_so() {
    let (output, out) = run_text("f16_departure", &f16_with(&[PULLED, QUATERNION]));
    succeeded(&output);
    let summary = json(&out.join("summary.json"));
    let notes = summary["manoeuvre"]["pull_up"]["notes"].to_string();
    assert!(
        notes.contains("beyond the range the aerodynamics holds"),
        "{notes}"
    );
    let doublet = summary["manoeuvre"]["elevator_doublet"]["notes"].to_string();
    assert!(!doublet.contains("beyond the range"), "{doublet}");
}

/// With `aircraft.kinematics = "quaternion"` a loop flies through the vertical: the F-16 at
/// x_cg = 0.30 c̄ (stable in pitch) trimmed at 800 ft/s pulls 3° of elevator for 30 s, over
/// the top, its pitch past ±89° on rows, and on to the end, every row finite.
#[test]
fn a_loop_flies_through_the_vertical_in_a_quaternion() {
    let looping = f16_with(&[
        (
            "amount = 3.0\nstart_s = 1.0\nduration_s = 4.0",
            "amount = 3.0\nstart_s = 1.0\nduration_s = 30.0",
        ),
        QUATERNION,
        ("xcg = 0.35 #", "xcg = 0.30 #"),
        ("speed = 502.0", "speed = 800.0"),
    ]);
    let (output, out) = run_text("f16_loop_quaternion", &looping);
    succeeded(&output);
    let csv = std::fs::read_to_string(out.join("pull_up").join("trajectory.csv")).unwrap();
    let theta = csv
        .lines()
        .next()
        .unwrap()
        .split(',')
        .position(|c| c == "theta[rad]");
    let theta = theta.expect("a theta column");
    let rows: Vec<Vec<f64>> = (csv.lines().skip(1))
        .map(|line| line.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    assert!(rows.iter().all(|row| row.iter().all(|x| x.is_finite())));
    let vertical = rows
        .iter()
        .position(|row| row[theta].abs() > 89f64.to_radians());
    let vertical = vertical.expect("a row past 89° of pitch");
    assert!(
        rows.len() > vertical + 100,
        "the run went on past the vertical"
    );
    assert!(
        (rows.last().unwrap()[0] - 30.0).abs() < 1e-9,
        "it ran to its end"
    );
}

/// Bad input is refused naming its key (exit 3), never run.
#[test]
fn bad_aircraft_input_is_refused_by_key() {
    let cases: [(&str, &str, &str); 6] = [
        (
            "[aerodynamics.cz]\nalpha_deg = [-10.0, -5.0, 0.0,",
            "[aerodynamics.cz]\nalpha_deg = [-10.0, -5.0, -5.0,",
            "aerodynamics.cz.alpha_deg",
        ),
        (
            "inertia = [9496.0, 55814.0, 63100.0]",
            "inertia = [9496.0, 55814.0, 80000.0]",
            "body.inertia",
        ),
        ("speed = 502.0", "speed = 0.0", "trim.speed"),
        ("amount = 3.0", "amount = 30.0", "manoeuvre[4].amount"),
        ("mass = ", "mass = -", "body.mass"),
        ("speed = 502.0", "speed = 2502.0", "trim"),
    ];
    for (from, to, key) in cases {
        let (output, out) = run_text("f16_bad", &f16_with(&[(from, to)]));
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(3), "{key}: {stderr}");
        assert!(stderr.contains(key), "{key}: {stderr}");
        assert!(!out.join("summary.json").exists(), "{key}");
        // Numbers as a reader writes them: the elevator the pull-up asks for is the trim's
        // plus the amount, which was printed with every digit (−30.75877986738379°).
        let longest = (stderr.split(|c: char| !c.is_ascii_digit() && c != '.'))
            .map(|number| number.chars().filter(char::is_ascii_digit).count())
            .max();
        assert!(longest <= Some(9), "{key}: {stderr}");
    }
}

/// A trim beyond the engine's tables (the F-16's thrust is tabled to Mach 1; 1500 ft/s at
/// sea level is Mach 1.34) is warned of, by `eom linear` and by `eom run`, as a run beyond the
/// aerodynamic tables' α is; at the shipped 502 ft/s (Mach 0.45) nothing is said.
#[test]
fn a_trim_beyond_the_engine_tables_is_warned_of() {
    let dir = folder("f16_mach");
    for (speed, warned) in [("502.0", false), ("1500.0", true)] {
        let text = f16_with(&[("speed = 502.0", &format!("speed = {speed}"))]);
        let file = dir.join(format!("f16_{speed}.toml"));
        std::fs::write(&file, text).unwrap();
        let linear = eom(&["linear", file.to_str().unwrap()]);
        let printed = succeeded(&linear);
        let said = printed.contains("warning: the trim is at Mach 1.34")
            && printed.contains("beyond the thrust tables' 0 to 1");
        assert_eq!(said, warned, "{speed}: {printed}");
        assert_eq!(printed.contains("warning"), warned, "{speed}: {printed}");
    }
}

/// `eom tradeoff` judges only the figures that have a target, and says which it did not
/// judge (an aircraft's load factors, damping ratios, its speed and height in the scene's
/// units); a target set by a figure's whole key judges it.
#[test]
fn tradeoff_says_which_figures_it_did_not_judge() {
    let navion = scene_arg("navion.toml");
    let json = succeeded(&eom(&["tradeoff", navion.as_str(), "--json"]));
    let value: Value = serde_json::from_str(&json).unwrap();
    let all: Vec<&str> = (value["not_judged"].as_array().unwrap().iter())
        .map(|key| key.as_str().unwrap())
        .collect();
    for key in ["peak_load_factor_g", "dutch_roll_damping", "final_speed"] {
        assert!(all.contains(&key), "{key}: {all:?}");
    }
    let targeted = [
        "tradeoff",
        navion.as_str(),
        "--figure-target",
        "g=0.01",
        "--figure-target",
        "dutch_roll_damping=0.001",
    ];
    let text = succeeded(&eom(&targeted));
    let line = (text.lines())
        .find(|line| line.starts_with("not judged, no target for their unit"))
        .unwrap_or_else(|| panic!("{text}"));
    let rest = line.rsplit_once(": ").unwrap().1;
    assert!(rest.contains("final_speed"), "{line}");
    assert!(
        !rest.contains("_g") && !rest.contains("dutch_roll_damping,"),
        "{line}"
    );
    assert!(
        text.contains("every figure with a target within it"),
        "{text}"
    );
}
