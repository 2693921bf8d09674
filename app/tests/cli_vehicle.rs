//! `eom run` on a vehicle scene, end to end through the binary: REMUS's Chapter 8 turn into
//! its folder (trajectory.csv, the plots, the 3-D view, summary.json with the folded table and
//! the figures), and `eom linear` on it: A, B and the modes at the cruise. A REMUS out of trim
//! runs its trials from its trim, one without a trim ahead runs nothing, and commands and
//! bodies it could not run as labelled are refused by key.

use eom_test_support::cli::{eom, folder, run_into, scene, scene_arg, succeeded};
use std::path::{Path, PathBuf};

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
    // The keys every kind's summary shares: its kind, its file, and the steps of every
    // manoeuvre's run with the scene's method.
    assert_eq!(summary["kind"], "vehicle");
    assert_eq!(summary["scene"], scene_arg("remus100.toml"));
    let manoeuvres = summary["manoeuvre"].as_object().unwrap().values();
    let steps: u64 = manoeuvres.map(|m| m["steps_taken"].as_u64().unwrap()).sum();
    assert_eq!(summary["integrator"]["steps"].as_u64(), Some(steps));
    assert!(summary["wall_seconds"].as_f64().unwrap() > 0.0);
    // The cruise at 1500 rpm: √(X_prop/−X_u|u|) and the roll trim, both to the closed forms.
    let cruise = &summary["cruise"];
    let speed = number(&cruise["speed_m_s"]);
    assert!((speed - number(&cruise["speed_closed_form_m_s"])).abs() < 1e-11);
    assert!((number(&cruise["roll_deg"]) - number(&cruise["roll_closed_form_deg"])).abs() < 1e-9);
    // The +4° turn's yaw rate where the rudder reverses, against the thesis's −9.0 °/s read
    // off its figure (to 0.5 °/s). The scene's RK4 at 0.05 s is what `eom tradeoff` recommends:
    // every figure within its target of DOP853 at 1e-12, the largest share the roll's 4.4e-4°
    // of 0.001°; half the step moves no figure by more than that target (4.2e-4 measured).
    let run = &summary["manoeuvre"]["rudder_4"];
    let turn = &run["steps"][1];
    assert_eq!(number(&turn["rudder_deg"]), 4.0);
    assert!(
        (number(&turn["yaw_rate_deg_s"]) + 9.0).abs() < 0.5,
        "{turn}"
    );
    assert!(number(&run["refined_difference"]) < 1e-3, "{run}");
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
    // The turning circle's track marks its 90° and 180° points as a ship's does.
    let track = std::fs::read_to_string(out.join("turning_circle/track.svg")).unwrap();
    for mark in [
        "execute",
        "90°: advance 7.8 m, transfer 6.3 m",
        "180°: tactical diameter 13.3 m",
    ] {
        assert!(track.contains(mark), "{mark}");
    }
    // No figure is printed or written as a negative zero (the cruise's pitch of −2.5e-14°
    // after 10 s, an autopilot's rudder of −0).
    let negative_zero = |text: &str| {
        text.split(|c: char| c.is_whitespace() || c == ',')
            .any(|word| {
                word.starts_with("-0") && word.trim_start_matches(['-', '0', '.']).is_empty()
            })
    };
    assert!(!negative_zero(&stdout), "{stdout}");
    let json = std::fs::read_to_string(out.join("summary.json")).unwrap();
    assert!(!negative_zero(&json), "summary.json");
    // Nor with the rounding of its making: the settling times read at the autopilot's samples
    // (k · 0.1 s less 5 s), the folded table's differences (5.22 − (−0.93)).
    let autopilot = &summary["manoeuvre"]["turn_and_dive"]["autopilot"];
    assert_eq!(autopilot[0]["settling_time_s"], 16.2, "{autopilot}");
    assert_eq!(autopilot[1]["settling_time_s"], 18.7, "{autopilot}");
    let yur = kirchhoff
        .iter()
        .find(|row| row["coefficient"] == "Yur")
        .unwrap();
    assert_eq!(yur["difference"], 6.15, "{yur}");
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
    let scene = eom::scene::AnyScene::parse(&text, "remus100.toml", path.parent().unwrap());
    let table = match scene
        .ok()
        .and_then(|s| s.downcast::<eom::kinds::vehicle::VehicleScene>())
    {
        Some(scene) => scene.table,
        None => panic!("remus100.toml is read as a vehicle"),
    };
    assert_eq!(
        table.inertia_about,
        eom::kinds::vehicle::InertiaAbout::Origin
    );
    let (m, r, i) = (table.mass, table.centre_of_gravity, table.inertia);
    let squared: f64 = r.iter().map(|x| x * x).sum();
    let about_g = |k: usize| i[k][k] - m * (squared - r[k] * r[k]);
    (m, about_g(0), (about_g(1) + about_g(2)) / 2.0)
}

/// REMUS's scene with `edits` (from, to) made, written into `dir`.
fn remus_edited(dir: &Path, edits: &[(&str, &str)]) -> PathBuf {
    let mut text = std::fs::read_to_string(scene("remus100.toml")).unwrap();
    for (from, to) in edits {
        assert!(text.contains(from), "{from}");
        text = text.replacen(from, to, 1);
    }
    let path = dir.join("remus_edited.toml");
    std::fs::write(&path, text).unwrap();
    path
}

/// The edits that give REMUS the body `mass` (kg), `weight` (N), G at `x_g` m from O.
fn payload(mass: &str, weight: &str, x_g: &str) -> [(String, String); 3] {
    [
        ("mass = 30.48 ".into(), format!("mass = {mass} ")),
        ("weight = 299.0 ".into(), format!("weight = {weight} ")),
        (
            "centre_of_gravity = [0.0, 0.0, 0.0196]".into(),
            format!("centre_of_gravity = [{x_g}, 0.0, 0.0196]"),
        ),
    ]
}

/// The edits as the borrowed pairs `remus_edited` takes.
fn pairs(edits: &[(String, String)]) -> Edits<'_> {
    edits
        .iter()
        .map(|(a, b)| (a.as_str(), b.as_str()))
        .collect()
}

/// Edits of a scene's text: (from, to).
type Edits<'a> = Vec<(&'a str, &'a str)>;

/// `eom run` of a scene that must be refused: its exit code, and its message.
fn refused(scene: &Path, out: &Path) -> (Option<i32>, String) {
    let output = eom(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    (output.status.code(), stderr)
}

#[test]
fn commands_thrusts_and_bodies_a_run_could_not_hold_are_refused_naming_their_keys() {
    let dir = folder("remus_refused");
    let heavy = payload("36.98", "362.8", "-0.01");
    let cases: Vec<(Edits, Vec<&str>)> = vec![
        // A 30° command on a 15° fin would run at 15° under a 30° label.
        (
            vec![("rudder_deg = [10.0]", "rudder_deg = [30.0]")],
            vec!["manoeuvre[3].rudder_deg[0]", "rudder.max_deg"],
        ),
        (
            vec![(
                "plane = \"vertical\"\nfin_deg = 10.0",
                "plane = \"vertical\"\nfin_deg = 30.0",
            )],
            vec!["manoeuvre[5].fin_deg", "stern_planes.max_deg"],
        ),
        // Astern on a table identified ahead, and at rest.
        (
            vec![("thrust = 3.86", "thrust = -3.86")],
            vec!["propeller.thrust", "astern"],
        ),
        (
            vec![("thrust = 3.86", "thrust = 0.0")],
            vec!["propeller.thrust", "zero thrust"],
        ),
        // 6.5 kg of payload in the weight only.
        (
            vec![("weight = 299.0 ", "weight = 362.8 ")],
            vec!["body.mass", "body.weight"],
        ),
        // And in both, aft: no steady motion ahead, so no manoeuvre runs.
        (pairs(&heavy), vec!["`body`", "no trim ahead", "63.8 N"]),
    ];
    // Every case is tried, and those not refused as they should be are listed together.
    let mut wrong = Vec::new();
    for (edits, keys) in cases {
        let scene = remus_edited(&dir, &edits);
        let out = dir.join("out");
        let (code, message) = refused(&scene, &out);
        let named = keys.iter().all(|key| message.contains(key));
        if code != Some(3) || !named || out.join("summary.json").exists() {
            wrong.push(format!("{edits:?}: exit {code:?}, {message}"));
        }
        let _ = std::fs::remove_dir_all(&out);
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// A column of `trajectory.csv` by its header's name, with the times.
fn column(csv: &str, name: &str) -> Vec<(f64, f64)> {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let index = header
        .iter()
        .position(|h| h.starts_with(&format!("{name}[")))
        .unwrap();
    lines
        .map(|line| {
            let values: Vec<f64> = line.split(',').map(|v| v.parse().unwrap()).collect();
            (values[0], values[index])
        })
        .collect()
}

#[test]
fn a_remus_out_of_trim_runs_each_trial_from_its_trim() {
    // 0.5 kg of payload 1 cm aft of the centre of buoyancy: started level, REMUS pitches up
    // by tens of degrees before its first command.
    let dir = folder("remus_out_of_trim");
    let scene = remus_edited(&dir, &pairs(&payload("30.98", "303.9", "-0.01")));
    let out = dir.join("out");
    let stdout = succeeded(&eom(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]));
    // Before each trial's execute (5 s) its pitch and speed stay those it starts with: a
    // trim, to the rounding of 500 RK4 steps (1e-9°, 1e-9 m/s; measured 1e-12).
    for trial in ["turning_circle", "zigzag_10_10", "vertical_zigzag_10_10"] {
        let csv = std::fs::read_to_string(out.join(trial).join("trajectory.csv")).unwrap();
        for name in ["theta", "u", "w"] {
            let values = column(&csv, name);
            let start = values[0].1;
            for (t, value) in values.iter().filter(|(t, _)| *t <= 5.0) {
                assert!(
                    (value - start).abs() < 1e-9,
                    "{trial}: {name} at {t} s: {value} from {start}"
                );
            }
        }
    }
    assert!(stdout.contains("trimmed in every state but the position and the heading"));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let cruise = &summary["cruise"];
    assert_eq!(cruise["trimmed"].as_array().unwrap().len(), 8, "{cruise}");
    // The closed forms are those of the straight level course, which this is not.
    assert!(cruise["speed_closed_form_m_s"].is_null(), "{cruise}");
    // Where the trial's pitch never reaches its switch, no figures, and why.
    let vertical = &summary["manoeuvre"]["vertical_zigzag_10_10"]["trial"];
    assert_eq!(vertical["switches_s"], serde_json::json!([]));
    let why = vertical["no_figures_because"].as_str().unwrap();
    assert!(why.contains("from the trim's"), "{why}");
    assert!(
        stdout.contains("Vertical zig-zag 10°/10°: no figures"),
        "{stdout}"
    );
}

#[test]
fn a_command_of_7_5_degrees_is_reported_as_7_5() {
    let dir = folder("remus_7_5");
    let text = std::fs::read_to_string(scene("remus100.toml")).unwrap();
    let own = text.find("[[manoeuvre]]").unwrap();
    let trials = "[[manoeuvre]]\nkind = \"turning_circle\"\ntimes_s = [1.0]\nrudder_deg = [7.5]\n\
        duration_s = 20.0\n\n[[manoeuvre]]\nkind = \"zigzag\"\nfin_deg = 7.5\nswitch_deg = 7.5\n\
        times_s = [1.0]\nduration_s = 20.0\n";
    let path = dir.join("seven_and_a_half.toml");
    std::fs::write(&path, format!("{}{trials}", &text[..own])).unwrap();
    let out = dir.join("out");
    let stdout = succeeded(&eom(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]));
    assert!(stdout.contains("turning circle at 7.5°"), "{stdout}");
    assert!(stdout.contains("zig-zag 7.5°/7.5°"), "{stdout}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let manoeuvres = &summary["manoeuvre"];
    assert_eq!(manoeuvres["turning_circle"]["trial"]["rudder_deg"], 7.5);
    assert_eq!(manoeuvres["turning_circle"]["steps"][1]["rudder_deg"], 7.5);
    assert_eq!(manoeuvres["zigzag"]["trial"]["fin_deg"], 7.5);
    assert_eq!(manoeuvres["zigzag"]["trial"]["switch_deg"], 7.5);
}

/// A vehicle scene takes a `[sweep]` as every scene does: REMUS's turning circle over its fin
/// lift `Nuudr` (the thesis's −6.15 and 20 % either side), run whole and as two shards merged
/// by `eom sweep-merge`, gives the same table, and each case's line carries its trial figures.
/// A stronger rudder moment turns tighter, so the tactical diameter falls as |Nuudr| grows.
#[test]
fn a_vehicle_sweep_over_a_coefficient_runs_whole_or_in_shards_alike() {
    let dir = folder("vehicle_sweep");
    let text = std::fs::read_to_string(scene("remus100.toml")).unwrap();
    let approach = &text[..text.find("[[manoeuvre]]").unwrap()];
    let turn_at = text.find("name = \"turning_circle\"").unwrap();
    let turn_end = turn_at + text[turn_at..].find("\n\n").unwrap();
    let text = format!(
        "{approach}[[manoeuvre]]\n{}\n\n[sweep]\n\"hydrodynamics.coefficients.Nuudr\" = \
         [-4.92, -6.15, -7.38]\n",
        &text[turn_at..turn_end]
    );
    let path = dir.join("remus_sweep.toml");
    std::fs::write(&path, text).unwrap();
    let run = |out: &Path, shard: Option<&str>| run_into(&path, out, shard);
    let whole = dir.join("whole");
    run(&whole, None);
    let table = std::fs::read_to_string(whole.join("sweep.csv")).unwrap();
    let mut reader = csv::Reader::from_reader(table.as_bytes());
    let header = reader.headers().unwrap().clone();
    assert_eq!(header.get(1), Some("hydrodynamics.coefficients.Nuudr"));
    assert_eq!(header.get(header.len() - 1), Some("error"));
    let rows: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), 3);
    let column = |key: &str| {
        (header.iter().position(|c| c == key)).unwrap_or_else(|| panic!("{key}: {header:?}"))
    };
    let diameters: Vec<f64> = rows
        .iter()
        .map(|row| {
            assert_eq!(&row[column("error")], "", "{row:?}");
            let value = &row[column("turning_circle.tactical_diameter_m")];
            value
                .parse()
                .unwrap_or_else(|_| panic!("{value:?} in {row:?}"))
        })
        .collect();
    assert!(
        diameters[0] > diameters[1] && diameters[1] > diameters[2],
        "{diameters:?}"
    );
    // The middle case is the scene as shipped: its line is its own run's figure, every digit.
    let alone: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(whole.join("case-0001/summary.json")).unwrap(),
    )
    .unwrap();
    let figure = &alone["manoeuvre"]["turning_circle"]["trial"]["tactical_diameter_m"];
    assert_eq!(figure.as_f64(), Some(diameters[1]));
    // Its summary says which case it is, as a body's case's does.
    assert_eq!(alone["case"]["index"], 1, "{}", alone["case"]);
    let nuudr = &alone["case"]["values"]["hydrodynamics.coefficients.Nuudr"];
    assert_eq!(nuudr.as_f64(), Some(-6.15));
    for key in [
        "turning_circle.advance_m",
        "turning_circle.refined_difference",
        "turning_circle.steps_taken",
    ] {
        assert!(!rows[0][column(key)].is_empty(), "{key}: {:?}", rows[0]);
    }
    let sharded = dir.join("sharded");
    run(&sharded, Some("0/2"));
    run(&sharded, Some("1/2"));
    succeeded(&eom(&["sweep-merge", sharded.to_str().unwrap()]));
    let merged = std::fs::read_to_string(sharded.join("sweep.csv")).unwrap();
    assert_eq!(merged, table);
}
