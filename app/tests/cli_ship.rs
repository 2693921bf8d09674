//! `eom run` and `eom linear` on ship scenes, end to end through the binary: the summary's
//! figures, IMO verdicts and convergence, the files of each manoeuvre, and the errors.

use eom_test_support::child;
use eom_test_support::cli::{eom, folder, root, run_into, scene_arg, succeeded};
use std::path::Path;

#[test]
fn the_mariner_runs_its_manoeuvres_and_is_judged() {
    let out = folder("mariner");
    let stdout = succeeded(&eom(&[
        "run",
        &scene_arg("mariner.toml"),
        "--out",
        out.to_str().unwrap(),
    ]));
    assert!(stdout.contains("IMO MSC.137(76)"), "{stdout}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let manoeuvre = &summary["manoeuvre"];
    let turn = &manoeuvre["turning_circle_35"];
    for key in [
        "advance_90_m",
        "transfer_90_m",
        "tactical_diameter_m",
        "steady_turning_radius_m",
        "steady_speed_m_s",
        "t_90_s",
        "t_180_s",
    ] {
        let value = turn[key]
            .as_f64()
            .unwrap_or_else(|| panic!("{key}: {turn}"));
        assert!(value > 0.0, "{key} = {value}");
        // The scene's method is adaptive: how far the figure moves with the tolerances a
        // hundred times tighter.
        let moved = turn["tolerance_difference"][key].as_f64().unwrap();
        assert!(
            moved < 0.01,
            "{key} moves {moved} when the tolerances tighten"
        );
    }
    // Both sides ran: the figures shown are the worse side's, the larger tactical diameter.
    assert_eq!(turn["side"], "port");
    let sides = &turn["sides"];
    let diameter = |side: &str| sides[side]["tactical_diameter_m"].as_f64().unwrap();
    assert!(diameter("port") >= diameter("starboard"), "{sides}");
    assert_eq!(turn["tactical_diameter_m"].as_f64(), Some(diameter("port")));
    assert_eq!(sides["port"]["side"], "port");
    assert_eq!(sides["starboard"]["side"], "starboard");
    // Each side's rudder as it ran: the Mariner's table turns to port with δ > 0.
    assert_eq!(sides["port"]["rudder_deg"], 35.0, "{sides}");
    assert_eq!(sides["starboard"]["rudder_deg"], -35.0, "{sides}");
    // The turn went ahead, one way, and settled: no note qualifies a figure.
    assert_eq!(turn["notes"], serde_json::json!([]), "{turn}");
    // The transfer at 180° is more than the transfer at 90°, and the steady diameter is near
    // the tactical diameter (the turn has settled well before its third half-circle).
    let number = |v: &serde_json::Value| v.as_f64().unwrap();
    assert!(number(&turn["tactical_diameter_m"]) > number(&turn["transfer_90_m"]));
    for name in ["zigzag_10_10", "zigzag_20_20"] {
        let zigzag = &manoeuvre[name];
        for key in [
            "first_overshoot_deg",
            "second_overshoot_deg",
            "reach_time_s",
            "period_s",
        ] {
            assert!(number(&zigzag[key]) > 0.0, "{name} {key}: {zigzag}");
        }
    }
    let imo = manoeuvre["imo"].as_array().unwrap();
    let names: Vec<&str> = imo
        .iter()
        .map(|c| c["criterion"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "advance",
            "tactical_diameter",
            "initial_turning",
            "first_overshoot_10_10",
            "second_overshoot_10_10",
            "first_overshoot_20_20",
            "track_reach"
        ]
    );
    // Stopping is listed, not judged: the Mariner's table has no propulsion model.
    let (stopping, imo) = imo.split_last().unwrap();
    assert_eq!(stopping["judged"], false, "{stopping}");
    assert!(stopping["pass"].is_null() && stopping["value"].is_null());
    let why = stopping["not_judged_because"].as_str().unwrap();
    assert!(why.contains("no propulsion model"), "{why}");
    for criterion in imo {
        assert_eq!(criterion["judged"], true, "{criterion}");
        let pass = number(&criterion["value"]) <= number(&criterion["limit"]);
        assert_eq!(criterion["pass"].as_bool(), Some(pass), "{criterion}");
        // Judged on both sides: the value is the worse (larger) of the two, and its side.
        let (port, starboard) = (
            number(&criterion["sides"]["port"]),
            number(&criterion["sides"]["starboard"]),
        );
        assert_eq!(
            number(&criterion["value"]),
            port.max(starboard),
            "{criterion}"
        );
        let worse = if starboard > port {
            "starboard"
        } else {
            "port"
        };
        assert_eq!(criterion["side"], worse, "{criterion}");
    }
    // The bias makes the 10°/10° first overshoot differ by side, and the verdict reads the
    // worse: the report prints both.
    let first_10 = &manoeuvre["zigzag_10_10"]["sides"];
    let overshoot = |side: &str| number(&first_10[side]["first_overshoot_deg"]);
    assert!((overshoot("port") - overshoot("starboard")).abs() > 1.0);
    assert!(stdout.contains("(port 3.45, starboard 4.95)"), "{stdout}");
    // L/V = 20.85 s: the 10°/10° first-overshoot limit is 5 + ½ L/V degrees.
    let first = imo
        .iter()
        .find(|c| c["criterion"] == "first_overshoot_10_10")
        .unwrap();
    assert!((number(&first["limit"]) - (5.0 + 0.5 * 160.93 / 7.7175)).abs() < 1e-12);
    assert!(summary["model"]["conversion"].as_array().unwrap().len() == 6);
    assert_eq!(summary["linear"]["course_stable"], true);
    for name in ["turning_circle_35", "zigzag_10_10", "zigzag_20_20"]
        .into_iter()
        .flat_map(|name| [format!("{name}/port"), format!("{name}/starboard")])
    {
        let dir = out.join(name);
        let csv = std::fs::read_to_string(dir.join("trajectory.csv")).unwrap();
        assert!(
            csv.starts_with(
                "t[s],u[m/s],v[m/s],r[rad/s],x[m],y[m],psi[rad],delta[rad],command[rad],distance[m],\
                 kinetic_energy[J]\n"
            ),
            "{}",
            csv.lines().next().unwrap_or_default()
        );
        for svg in ["track.svg", "heading.svg"] {
            let text = std::fs::read_to_string(dir.join(svg)).unwrap();
            let document = roxmltree::Document::parse(&text).unwrap();
            assert!(document.descendants().any(|n| n.has_tag_name("polyline")));
        }
    }
    let track = std::fs::read_to_string(out.join("turning_circle_35/port/track.svg")).unwrap();
    assert!(
        track.contains("tactical diameter"),
        "the 180° point is marked"
    );
    // The spiral: no loop on the course-stable Mariner, and its plot.
    let spiral = &manoeuvre["spiral"];
    assert_eq!(spiral["kind"], "spiral");
    assert_eq!(
        spiral["spiral"]["course_stable_by_spiral"], true,
        "{spiral}"
    );
    assert_eq!(number(&spiral["loop_width_deg"]), 0.0);
    let points = spiral["spiral"]["points"].as_array().unwrap();
    assert_eq!(points.len(), 2 * 9 - 1);
    let svg = std::fs::read_to_string(out.join("spiral/spiral.svg")).unwrap();
    let document = roxmltree::Document::parse(&svg).unwrap();
    assert!(document.descendants().any(|n| n.has_tag_name("polyline")));
    assert!(
        svg.contains("no loop"),
        "the caption says what the curve shows"
    );
}

/// The Esso Osaka, course-unstable: both spirals find a loop about δ = 0, the summary gives
/// its width and height, and spiral.svg draws both passes; beside them, the steady-turn curve
/// and its two folds, and the report sets the loop from the settled points (its width, its
/// bounds and the spiral's rudder step) beside the folds.
#[test]
fn the_esso_osakas_spirals_show_its_loop() {
    let out = folder("esso_osaka");
    let stdout = succeeded(&eom(&[
        "run",
        &scene_arg("esso_osaka.toml"),
        "--out",
        out.to_str().unwrap(),
    ]));
    assert!(stdout.contains("NO (a loop)"), "{stdout}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    for name in ["spiral", "reverse_spiral"] {
        let spiral = &summary["manoeuvre"][name];
        assert_eq!(
            spiral["spiral"]["course_stable_by_spiral"], false,
            "{spiral}"
        );
        let width = spiral["loop_width_deg"].as_f64().unwrap();
        let height = spiral["loop_height_deg_s"].as_f64().unwrap();
        assert!(width > 0.0 && height > 0.0, "{name}: {width} {height}");
        let svg = std::fs::read_to_string(out.join(name).join("spiral.svg")).unwrap();
        assert!(
            svg.contains("° wide ×"),
            "{name}: the caption gives the loop"
        );
    }
    let svg = std::fs::read_to_string(out.join("spiral/spiral.svg")).unwrap();
    assert!(svg.contains("first pass") && svg.contains("back"));
    assert!(
        svg.contains("steady turns"),
        "the curve is drawn beside the points"
    );
    let spiral = &summary["manoeuvre"]["spiral"];
    let found = &spiral["spiral"]["loop"];
    let degrees = |v: &serde_json::Value| v.as_f64().unwrap();
    assert!(
        (degrees(&found["rudder_step_deg"]) - 0.25).abs() < 1e-12,
        "{found}"
    );
    let steady = &spiral["spiral"]["steady_turns"];
    let folds = steady["folds"].as_array().unwrap();
    assert_eq!(folds.len(), 2, "{steady}");
    let width = degrees(&steady["loop_width_deg"]);
    assert_eq!(degrees(&spiral["steady_loop_width_deg"]), width);
    assert!(degrees(&found["least_width_deg"]) <= width);
    assert!(width <= degrees(&found["most_width_deg"]));
    for said in [
        "loop from the settled points",
        "rudder step 0.250°",
        "folds at δ = ",
    ] {
        assert!(stdout.contains(said), "{said}: {stdout}");
    }
}

/// A course-stable ship is not called a loop by a spiral that cannot tell: the S-175 on
/// Clarke's linear derivatives (C′ > 0 by `eom linear`) at the default settling is
/// "undetermined", with the settling that would tell, and its steady-turn curve has no fold.
#[test]
fn the_s175s_spiral_is_not_called_a_loop() {
    let linear = succeeded(&eom(&["linear", &scene_arg("s175.toml"), "--json"]));
    let linear: serde_json::Value = serde_json::from_str(&linear).unwrap();
    assert_eq!(linear["course_stable"], true, "{linear}");
    assert!(linear["stability_index"].as_f64().unwrap() > 0.0);
    let out = folder("s175");
    let stdout = succeeded(&eom(&[
        "run",
        &scene_arg("s175.toml"),
        "--out",
        out.to_str().unwrap(),
    ]));
    assert!(!stdout.contains("NO (a loop)"), "{stdout}");
    assert!(stdout.contains("undetermined"), "{stdout}");
    assert!(
        stdout.contains("no fold: one steady turn at each δ"),
        "{stdout}"
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let spiral = &summary["manoeuvre"]["spiral"];
    assert!(
        spiral["spiral"]["course_stable_by_spiral"].is_null(),
        "{spiral}"
    );
    assert_eq!(spiral["spiral"]["verdict"], "undetermined");
    let why = spiral["spiral"]["undetermined_because"].as_str().unwrap();
    assert!(why.contains("settle_window_s = "), "{why}");
    assert!(spiral["loop_width_deg"].is_null());
    assert_eq!(spiral["steady_loop_width_deg"], 0.0);
}

/// A workboat on a crude made-up table whose turn drags it to a stop and astern.
const ASTERN_WORKBOAT: &str = r#"
title = "Made-up workboat (a crude table)"
[model]
family = "planar-midship"
[body]
length = 20.0
mass_prime = 0.02
izz_midship_prime = 0.0012
x_g_prime = 0.0
[hydrodynamics]
units = "prime"
rigid_body_terms = "separate"
density = 1025.0
design_speed = 5.0
[hydrodynamics.coefficients]
Xudot = -0.001
Yvdot = -0.02
Nrdot = -0.001
Xu = -0.002
Xrr = -0.03
Yv = -0.03
Yr = 0.005
Yd = 0.008
Nv = -0.01
Nr = -0.005
Nd = -0.004
[rudder]
max_deg = 35.0
max_rate_deg_s = 5.0
time_constant_s = 1.0
[integrator]
method = "rk4"
step = 0.05
[output]
every = 1.0
[[manoeuvre]]
name = "turning_circle_35"
kind = "turning_circle"
rudder_deg = 35.0
duration_s = 600.0
"#;

#[test]
fn a_turn_that_goes_astern_gives_no_steady_figures_and_no_verdict_on_them() {
    let dir = folder("astern");
    let path = dir.join("workboat.toml");
    std::fs::write(&path, ASTERN_WORKBOAT).unwrap();
    let out = dir.join("out");
    let stdout = succeeded(&eom(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]));
    let csv = std::fs::read_to_string(out.join("turning_circle_35/port/trajectory.csv")).unwrap();
    let u: Vec<f64> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(1).unwrap().parse().unwrap())
        .collect();
    // The run itself: it goes astern, and the heading still turns past 540°.
    assert!(u.iter().any(|&u| u < -0.5), "the boat never went astern");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let turn = &summary["manoeuvre"]["turning_circle_35"];
    for key in [
        "advance_90_m",
        "transfer_90_m",
        "tactical_diameter_m",
        "steady_turning_radius_m",
        "steady_speed_m_s",
    ] {
        assert!(turn[key].is_null(), "{key}: {turn}");
    }
    let notes: Vec<&str> = turn["notes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|n| n.as_str().unwrap())
        .collect();
    for said in ["went astern (u < 0)", "stopped", "no steady turn"] {
        assert!(notes.iter().any(|n| n.contains(said)), "{said}: {notes:?}");
    }
    for criterion in summary["manoeuvre"]["imo"].as_array().unwrap() {
        assert_eq!(criterion["judged"], false, "{criterion}");
        assert!(criterion["pass"].is_null() && criterion["value"].is_null());
    }
    assert!(!stdout.contains("pass"), "{stdout}");
    assert!(stdout.contains("not judged"), "{stdout}");
}

#[test]
fn eom_linear_says_the_esso_osaka_is_course_unstable() {
    let stdout = succeeded(&eom(&["linear", &scene_arg("esso_osaka.toml"), "--json"]));
    let linear: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(linear["course_stable"], false, "{linear}");
    assert!(linear["stability_index"].as_f64().unwrap() < 0.0);
    assert!(linear["largest_relative_difference"].as_f64().unwrap() < 1e-9);
    // Every scene's report beside the Nomoto block: the reduced state, the modes, the verdict.
    assert_eq!(linear["reduced_state"], serde_json::json!(["u", "v", "r"]));
    assert_eq!(linear["set_aside"], serde_json::json!(["X", "Y", "psi"]));
    assert_eq!(linear["inputs"], serde_json::json!(["delta"]));
    assert_eq!(linear["stable"], false, "{linear}");
    let growing = linear["modes"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|m| m["re"].as_f64().unwrap() > 0.0 && m["name"] == "sway and yaw");
    assert_eq!(growing.count(), 1, "{linear}");
    // --out writes A and B on the reduced state (u, v, r) and the poles, as for any scene.
    let out = folder("linear").join("out");
    let out_arg = out.to_str().unwrap();
    succeeded(&eom(&[
        "linear",
        &scene_arg("mariner.toml"),
        "--out",
        out_arg,
    ]));
    let a = std::fs::read_to_string(out.join("A.csv")).unwrap();
    let b = std::fs::read_to_string(out.join("B.csv")).unwrap();
    assert_eq!(a.lines().next(), Some("u,v,r"), "{a}");
    assert_eq!(a.lines().count(), 1 + 3, "{a}");
    assert!(a.lines().all(|l| l.split(',').count() == 3), "{a}");
    assert_eq!(b.lines().next(), Some("delta"), "{b}");
    assert_eq!(b.lines().count(), 1 + 3, "{b}");
    let report = std::fs::read_to_string(out.join("report.txt")).unwrap();
    assert!(report.contains("Nomoto, closed form"), "{report}");
    assert!(out.join("poles.svg").exists());
    let text = succeeded(&eom(&["linear", &scene_arg("mariner.toml")]));
    assert!(text.contains(": stable"), "{text}");
}

#[test]
fn a_bad_ship_scene_exits_3_naming_the_key() {
    let dir = folder("bad");
    let text = std::fs::read_to_string(scene_arg("mariner.toml"))
        .unwrap()
        .replace("Yvvr = ", "Yvvq = ");
    let path = dir.join("bad.toml");
    std::fs::write(&path, text).unwrap();
    let output = eom(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(3));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("hydrodynamics.coefficients.Yvvq"),
        "{stderr}"
    );
    assert!(
        !dir.join("out").exists(),
        "nothing is written for a scene that cannot run"
    );
}

/// Ctrl-C ends a ship run at its next step: the manoeuvre finished before it keeps its folder,
/// summary.json says so, and the exit code is 130.
#[cfg(unix)]
#[test]
fn ctrl_c_ends_a_ship_run_keeping_the_finished_manoeuvres() {
    use std::time::{Duration, Instant};
    let dir = folder("sigint");
    let text = std::fs::read_to_string(scene_arg("mariner.toml")).unwrap();
    // The first manoeuvre short, the second far too long to finish (10⁸ steps: past the
    // default limit, which the scene raises).
    let text = text
        .replacen("duration_s = 1500.0", "duration_s = 300.0", 1)
        .replacen("duration_s = 800.0", "duration_s = 1.0e7", 1)
        .replacen("step = 0.1 ", "max_steps = 200_000_000\nstep = 0.1 ", 1);
    let path = dir.join("long.toml");
    std::fs::write(&path, text).unwrap();
    let out = dir.join("out");
    // The second's trajectory would be 2 GB: it says --large-output, and is ended long before.
    let mut child = child::spawn_run_with(&path, &out, &["--large-output"]);
    let first = out.join("turning_circle_35/starboard/heading.svg");
    let clock = Instant::now();
    while !first.exists() {
        assert!(
            clock.elapsed() < Duration::from_secs(120),
            "the first manoeuvre never ended"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    std::thread::sleep(Duration::from_millis(200));
    let pid = libc::pid_t::try_from(child.id()).unwrap();
    // SAFETY: kill(2) on the child's own pid, which has not been waited for yet.
    assert_eq!(unsafe { libc::kill(pid, libc::SIGINT) }, 0);
    let status = child::wait_for_exit(&mut child);
    let stderr = child::stderr(&mut child);
    assert_eq!(status.code(), Some(130), "{stderr}");
    assert!(stderr.contains("interrupted by"), "{stderr}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["interrupted"], true);
    assert!(
        summary["manoeuvre"]["turning_circle_35"]["advance_90_m"]
            .as_f64()
            .is_some()
    );
    assert!(summary["manoeuvre"]["zigzag_10_10"].is_null());
}

/// The Mariner's turning circle over three rudder angles: one sweep run whole and as two
/// shards gives the same table, case for case, with each case's figures and IMO verdicts.
#[test]
fn a_ship_sweep_over_the_rudder_runs_whole_or_in_shards_alike() {
    let dir = folder("sweep");
    let text = std::fs::read_to_string(scene_arg("mariner.toml")).unwrap();
    let approach = &text[..text.find("[[manoeuvre]]").unwrap()];
    let text = format!(
        "{approach}[[manoeuvre]]\nname = \"turn\"\nkind = \"turning_circle\"\nrudder_deg = 35.0\n\
         duration_s = 450.0\n\n[sweep]\n\"manoeuvre[0].rudder_deg\" = [15.0, 25.0, 35.0]\n"
    );
    let path = dir.join("sweep.toml");
    std::fs::write(&path, text).unwrap();
    let run = |out: &Path, shard: Option<&str>| run_into(&path, out, shard);
    let whole = dir.join("whole");
    run(&whole, None);
    let table = std::fs::read_to_string(whole.join("sweep.csv")).unwrap();
    let mut lines = table.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(
        &header[..3],
        ["case", "manoeuvre[0].rudder_deg", "turn.advance_90_m"]
    );
    assert!(header.contains(&"imo.tactical_diameter.pass"), "{header:?}");
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 3);
    // The harder the rudder, the tighter the turn.
    let diameter: Vec<f64> = rows
        .iter()
        .map(|r| r[column("turn.tactical_diameter_m")].parse().unwrap())
        .collect();
    assert!(
        diameter[0] > diameter[1] && diameter[1] > diameter[2],
        "{diameter:?}"
    );
    for k in 0..3 {
        assert!(whole.join(format!("case-{k:04}/summary.json")).exists());
    }
    // Each side's figures and verdicts have their columns.
    for column in [
        "turn.port.tactical_diameter_m",
        "turn.starboard.tactical_diameter_m",
        "imo.tactical_diameter.port",
        "imo.tactical_diameter.starboard",
    ] {
        assert!(header.contains(&column), "{column}: {header:?}");
    }
    // The plot of the diameters against the rudder angle, beside the table.
    let plot = std::fs::read_to_string(whole.join("sweep.svg")).unwrap();
    let document = roxmltree::Document::parse(&plot).unwrap();
    assert!(document.descendants().any(|n| n.has_tag_name("polyline")));
    assert!(plot.contains("tactical diameter") && plot.contains("steady turning radius"));
    let sharded = dir.join("sharded");
    run(&sharded, Some("0/2"));
    run(&sharded, Some("1/2"));
    succeeded(&eom(&["sweep-merge", sharded.to_str().unwrap()]));
    let merged = std::fs::read_to_string(sharded.join("sweep.csv")).unwrap();
    assert_eq!(merged, table);
    assert_eq!(
        std::fs::read_to_string(sharded.join("sweep.svg")).unwrap(),
        plot,
        "the merge draws the same plot"
    );
}

/// A sweep over the rudder angle of a turning circle the scene does not name (README's and
/// `eom new ship`'s own example): its default name is made from the swept angle, so its
/// columns are named by its position, `manoeuvre[0]`, the same in every case. Run whole and
/// as two shards merged, the tables are equal, and every case has its figures.
#[test]
fn a_sweep_over_an_unnamed_turns_rudder_keeps_every_cases_figures() {
    let dir = folder("sweep_unnamed");
    let text = std::fs::read_to_string(scene_arg("mariner.toml")).unwrap();
    let approach = &text[..text.find("[[manoeuvre]]").unwrap()];
    let text = format!(
        "{approach}[[manoeuvre]]\nkind = \"turning_circle\"\nrudder_deg = 35.0\n\
         duration_s = 450.0\n\n[sweep]\n\"manoeuvre[0].rudder_deg\" = [15.0, 25.0, 35.0]\n"
    );
    let path = dir.join("sweep.toml");
    std::fs::write(&path, text).unwrap();
    let run = |out: &Path, shard: Option<&str>| run_into(&path, out, shard);
    let whole = dir.join("whole");
    run(&whole, None);
    let table = std::fs::read_to_string(whole.join("sweep.csv")).unwrap();
    let mut reader = csv::Reader::from_reader(table.as_bytes());
    let header = reader.headers().unwrap().clone();
    assert_eq!(header.get(1), Some("manoeuvre[0].rudder_deg"));
    assert!(
        !header.iter().any(|c| c.starts_with("turning_circle_")),
        "{header:?}"
    );
    let rows: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), 3);
    let column = |key: &str| {
        (header.iter().position(|c| c == key)).unwrap_or_else(|| panic!("{key}: {header:?}"))
    };
    for key in [
        "manoeuvre[0].advance_90_m",
        "manoeuvre[0].tactical_diameter_m",
        "manoeuvre[0].port.tactical_diameter_m",
        "manoeuvre[0].starboard.tactical_diameter_m",
    ] {
        for row in &rows {
            let value: f64 =
                (row[column(key)].parse()).unwrap_or_else(|_| panic!("{key}: {row:?}"));
            assert!(value > 0.0, "{key}: {row:?}");
        }
    }
    // The turning criteria rest on the 35° turn alone: judged in that case, with each side's
    // figure, and not in the others, whose columns are there, empty.
    for (row, judged) in rows.iter().zip([false, false, true]) {
        for key in [
            "imo.advance",
            "imo.advance.pass",
            "imo.tactical_diameter.port",
        ] {
            assert_eq!(!row[column(key)].is_empty(), judged, "{key}: {row:?}");
        }
    }
    // The plot over the rudder angle finds the one swept key and the turn's columns.
    let plot = std::fs::read_to_string(whole.join("sweep.svg")).unwrap();
    assert!(plot.contains("manoeuvre[0] tactical diameter") || plot.contains("tactical diameter"));
    let sharded = dir.join("sharded");
    run(&sharded, Some("0/2"));
    run(&sharded, Some("1/2"));
    succeeded(&eom(&["sweep-merge", sharded.to_str().unwrap()]));
    let merged = std::fs::read_to_string(sharded.join("sweep.csv")).unwrap();
    assert_eq!(merged, table);
}

/// `eom new ship` runs as printed and gives figures: its turning circle is long enough for its
/// 325 m tanker to pass 180° and settle, so every turning figure is there and the IMO turning
/// criteria are judged, each naming the turn.
#[test]
fn the_ship_template_runs_as_printed_and_gives_its_figures() {
    let dir = folder("ship_template");
    let template = succeeded(&eom(&["new", "ship"]));
    let path = dir.join("ship.toml");
    std::fs::write(&path, template).unwrap();
    let out = dir.join("out");
    let stdout = succeeded(&eom(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let (name, turn) = (summary["manoeuvre"].as_object().unwrap().iter())
        .find(|(_, m)| m["kind"] == "turning_circle")
        .unwrap();
    for key in [
        "advance_90_m",
        "transfer_90_m",
        "tactical_diameter_m",
        "steady_turning_radius_m",
        "steady_speed_m_s",
        "t_90_s",
        "t_180_s",
    ] {
        assert!(turn[key].as_f64().is_some_and(|v| v > 0.0), "{key}: {turn}");
    }
    for criterion in ["advance", "tactical_diameter"] {
        let line = (stdout.lines())
            .find(|l| l.trim_start().starts_with(&format!("{criterion} ")))
            .unwrap_or_else(|| panic!("{criterion}: {stdout}"));
        assert!(line.contains("pass") || line.contains("FAIL"), "{line}");
        assert!(line.contains(&format!("on {name}")), "{line}");
    }
}

/// `integrator.stop_when` through the binary: the Mariner's turn and a zig-zag under `psi >
/// 2.5`. The turn to starboard stops where its heading passes 2.5 rad (its trajectory's last
/// row there), the one to port runs to its end (`stopped_at` null), and the zig-zag, whose
/// heading stays within 20°, is not stopped; summary.json says the condition, each side's
/// `stopped_at` with every digit, and the note; the stopped side gives no tactical diameter.
/// A condition on a name the ship's row does not have exits 3 naming the key.
#[test]
fn a_stop_condition_ends_a_ships_manoeuvre_and_summary_json_says_where() {
    let dir = folder("stop_when");
    let mariner = std::fs::read_to_string(scene_arg("mariner.toml")).unwrap();
    let approach = &mariner[..mariner.find("[[manoeuvre]]").unwrap()];
    let scene = |stop: &str| {
        approach.replace(
            "[integrator]\n",
            &format!("[integrator]\nstop_when = \"{stop}\"\n"),
        ) + "[[manoeuvre]]\nname = \"turn\"\nkind = \"turning_circle\"\nrudder_deg = 35.0\n\
               duration_s = 1500.0\n\n[[manoeuvre]]\nname = \"zigzag\"\nkind = \"zigzag\"\n\
               rudder_deg = 20.0\nheading_deg = 20.0\nduration_s = 300.0\n"
    };
    let path = dir.join("stop.toml");
    std::fs::write(&path, scene("psi > 2.5")).unwrap();
    let out = dir.join("out");
    let stdout = succeeded(&eom(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]));
    assert!(stdout.contains("where `psi > 2.5` first held"), "{stdout}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["stop_when"], "psi > 2.5");
    let sides = &summary["manoeuvre"]["turn"]["sides"];
    let (port, starboard) = (&sides["port"], &sides["starboard"]);
    assert!(port["stopped_at"].is_null(), "{port}");
    assert!(port["tactical_diameter_m"].as_f64().is_some(), "{port}");
    let at = starboard["stopped_at"].as_f64().unwrap();
    assert!(starboard["tactical_diameter_m"].is_null(), "{starboard}");
    assert!(starboard["advance_90_m"].as_f64().is_some(), "{starboard}");
    let note = starboard["notes"][0].as_str().unwrap();
    assert!(
        note.contains("before the run gave tactical_diameter_m"),
        "{note}"
    );
    let zigzag = &summary["manoeuvre"]["zigzag"];
    for side in ["port", "starboard"] {
        let run = &zigzag["sides"][side];
        assert!(
            run["stopped_at"].is_null() && run.get("stopped_at").is_some(),
            "{run}"
        );
    }
    // The stopped side's trajectory ends at the stop, every digit of it as written there.
    let csv = std::fs::read_to_string(out.join("turn/starboard/trajectory.csv")).unwrap();
    let last: Vec<f64> = (csv.lines().last().unwrap().split(','))
        .map(|x| x.parse().unwrap())
        .collect();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let psi = header.iter().position(|c| *c == "psi[rad]").unwrap();
    assert_eq!(last[0], at);
    assert!(last[psi] > 2.5, "ψ = {} at the last row", last[psi]);

    std::fs::write(&path, scene("heading > 1")).unwrap();
    let output = eom(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        dir.join("refused").to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(3));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("integrator.stop_when") && stderr.contains("unknown name `heading`"),
        "{stderr}"
    );
}

/// `eom tradeoff` on a ship compares every setting on the figures of its manoeuvres against
/// DOP853 at 1e-12: RK4's errors fall as h⁴ where they stand above round-off, and the setting
/// it recommends meets every figure's target, as do the tighter settings of its method.
#[test]
fn eom_tradeoff_compares_a_ships_settings_on_its_figures() {
    let dir = folder("tradeoff");
    let mariner = std::fs::read_to_string(scene_arg("mariner.toml")).unwrap();
    let approach = &mariner[..mariner.find("[[manoeuvre]]").unwrap()];
    // One turn, rows 5 s apart: RK4 from a step of 5 s down to 0.05 s.
    let scene = approach.replace("every = 1.0 ", "every = 5.0 ")
        + "[[manoeuvre]]\nname = \"turn\"\nkind = \"turning_circle\"\nrudder_deg = 35.0\n\
           duration_s = 400.0\n";
    let path = dir.join("turn.toml");
    std::fs::write(&path, scene).unwrap();
    let stdout = succeeded(&eom(&["tradeoff", path.to_str().unwrap(), "--json"]));
    let value: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(value["reference"], "DOP853 at rtol = atol = 1e-12");
    let rows = value["rows"].as_array().unwrap();
    let rk4: Vec<&serde_json::Value> = rows.iter().filter(|r| r["method"] == "rk4").collect();
    assert_eq!(rk4.len(), 7);
    // The tactical diameter's error, step by step (5, 2.5, 1, 0.5, 0.25, 0.1, 0.05 s): from 1 s
    // to 0.5 s and to 0.25 s, each a halving, a fourth-order method's error falls about 16-fold
    // (at least 8-fold is asked: the events' location adds its own small part); below 1e-6 m
    // the reference's own error and the round-off of a 1 km figure take over.
    let diameter = |row: &serde_json::Value| row["errors"]["tactical_diameter_m"].as_f64();
    let errors: Vec<f64> = rk4.iter().map(|r| diameter(r).unwrap()).collect();
    for pair in [(2, 3), (3, 4)] {
        let (coarse, fine) = (errors[pair.0], errors[pair.1]);
        assert!(coarse > 1e-6 && coarse / fine >= 8.0, "{errors:?}");
    }
    // Every figure the turn gives is compared, per side.
    for key in ["advance_90_m", "transfer_90_m", "t_90_s", "t_180_s"] {
        assert!(
            rk4[3]["errors"][key].as_f64().is_some(),
            "{key}: {}",
            rk4[3]
        );
    }
    // The recommendation meets every target, and so does each tighter setting of its method.
    let targets = &value["targets"];
    let target = |key: &str| {
        let unit = ["deg_s", "m_s", "m", "deg", "s"]
            .into_iter()
            .find(|unit| key.ends_with(&format!("_{unit}")))?;
        targets[unit].as_f64()
    };
    let meets = |row: &serde_json::Value| {
        (row["errors"].as_object().unwrap().iter())
            .all(|(key, error)| target(key).is_none_or(|t| error.as_f64().is_some_and(|e| e <= t)))
    };
    let recommended = &value["recommended"];
    assert!(meets(recommended), "{recommended}");
    let at = rows.iter().position(|r| r == recommended).unwrap();
    let method = &recommended["method"];
    assert!(
        rows[at..]
            .iter()
            .filter(|r| r["method"] == *method)
            .all(meets)
    );
    // A figure's target is set by its unit: a tighter one on lengths recommends no cheaper a
    // setting.
    let tight = succeeded(&eom(&[
        "tradeoff",
        path.to_str().unwrap(),
        "--json",
        "--figure-target",
        "m=1e-5",
    ]));
    let tight: serde_json::Value = serde_json::from_str(&tight).unwrap();
    assert_eq!(tight["targets"]["m"].as_f64(), Some(1e-5));
    let evals = |v: &serde_json::Value| v["recommended"]["rhs_evals"].as_u64().unwrap();
    assert!(
        evals(&tight) >= evals(&value),
        "{} < {}",
        evals(&tight),
        evals(&value)
    );
    // `--figure` adds a column of one figure's errors; a figure the runs do not give is a
    // usage error that names those they give.
    let text = succeeded(&eom(&[
        "tradeoff",
        path.to_str().unwrap(),
        "--figure",
        "tactical_diameter_m",
    ]));
    assert!(
        text.contains("| of target | tactical_diameter_m |"),
        "{text}"
    );
    let output = eom(&["tradeoff", path.to_str().unwrap(), "--figure", "nope_m"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("the scene's runs give advance_90_m"),
        "{stderr}"
    );
    // A scene whose manoeuvres measure nothing has nothing to compare: a usage error.
    let series = approach.to_owned()
        + "[[manoeuvre]]\nname = \"series\"\nkind = \"rudder_series\"\n\
           times_s = [0.0, 10.0]\nseries_deg = [0.0, 5.0]\nduration_s = 30.0\n";
    let path = dir.join("series.toml");
    std::fs::write(&path, series).unwrap();
    let output = eom(&["tradeoff", path.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("gives none"), "{stderr}");
}

/// The Mariner in a current: its turning circle drifts (the figures say how far per turn and
/// toward where), and no IMO criterion is judged, since the criteria are for calm water.
#[test]
fn a_ship_in_a_current_drifts_and_is_not_judged() {
    let dir = folder("current");
    let text = std::fs::read_to_string(root().join("scenes/mariner.toml")).unwrap();
    let text = text.replacen(
        "[integrator]",
        "[environment]\ncurrent_m_s = 0.5\ncurrent_toward_deg = 90.0\n\n[integrator]",
        1,
    );
    let path = dir.join("mariner_current.toml");
    std::fs::write(&path, text).unwrap();
    let out = dir.join("out");
    let stdout = succeeded(&eom(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let turn = &summary["manoeuvre"]["turning_circle_35"];
    for side in ["port", "starboard"] {
        let figures = &turn["sides"][side];
        let drift = figures["drift_m_per_turn"].as_f64().unwrap();
        let period = figures["turn_period_s"].as_f64().unwrap();
        assert!((drift - 0.5 * period).abs() < 1e-6 * drift, "{figures}");
    }
    for criterion in summary["manoeuvre"]["imo"].as_array().unwrap() {
        assert_eq!(criterion["judged"], false, "{criterion}");
    }
    assert!(stdout.contains("judges trials in calm water"), "{stdout}");
    assert!(stdout.contains("drift_m_per_turn"), "{stdout}");
    let environment = &summary["model"]["environment"];
    assert_eq!(environment["current"]["speed_m_s"], 0.5, "{environment}");
    assert_eq!(environment["current"]["toward_deg"], 90.0, "{environment}");
    assert!(
        environment["figures"]
            .as_str()
            .unwrap()
            .contains("over ground")
    );
    assert!(stdout.contains("the figures are over ground"), "{stdout}");
}
