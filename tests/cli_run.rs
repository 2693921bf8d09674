//! `eom run` end to end: every example scene runs through the binary, and what it writes is
//! checked against physics — the pendulum's period against 4K(m)√(I₀/Mgh), the free bodies'
//! energy and |H|, the steady turn's yaw rate against the equations at rest, the tennis
//! racket's flips against Jacobi's solution — and the SVGs parse as XML with their series.
//! Bad scene files each give an error that names the key and a non-zero exit.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn eom() -> Command {
    Command::new(env!("CARGO_BIN_EXE_eom"))
}

fn scene(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

/// A fresh folder under the target directory for one test's output.
fn folder(test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_run")
        .join(test);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn run_scene(name: &str, out: &Path) -> Output {
    let output = eom()
        .args([
            "run",
            scene(name).to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{name}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    output
}

/// trajectory.csv as a header and rows of numbers.
fn trajectory(out: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(|x| x.parse::<f64>().unwrap()).collect())
        .collect();
    (header, rows)
}

fn column(header: &[String], rows: &[Vec<f64>], name: &str) -> Vec<f64> {
    let i = header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name}"));
    rows.iter().map(|r| r[i]).collect()
}

fn summary(out: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap()
}

/// Times at which `x` changes sign, by linear interpolation between rows.
fn sign_changes(t: &[f64], x: &[f64]) -> Vec<f64> {
    t.windows(2)
        .zip(x.windows(2))
        .filter(|(_, a)| (a[0] < 0.0) != (a[1] < 0.0))
        .map(|(t, a)| t[0] + (t[1] - t[0]) * a[0] / (a[0] - a[1]))
        .collect()
}

/// Every SVG written parses as XML and holds at least one drawn series.
fn check_svgs(out: &Path, expected: &[&str]) {
    for name in expected {
        let text = std::fs::read_to_string(out.join(name)).unwrap_or_else(|_| panic!("no {name}"));
        let document = roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
        let lines = document
            .descendants()
            .filter(|n| matches!(n.tag_name().name(), "polyline" | "path"))
            .count();
        assert!(lines > 0, "{name} draws no series");
    }
}

#[test]
fn the_pendulum_swings_with_the_period_of_the_elliptic_integral() {
    let out = folder("pendulum");
    run_scene("pendulum.toml", &out);
    let (header, rows) = trajectory(&out);
    assert_eq!(header[..3], ["t", "theta", "theta_dot"]);
    assert_eq!(
        header[3..],
        ["kinetic_energy", "potential_energy", "total_energy"]
    );
    let t = column(&header, &rows, "t");
    let theta = column(&header, &rows, "theta");
    // Released at rest at 150°, every second zero crossing is one period later.
    let crossings = sign_changes(&t, &theta);
    let measured =
        (crossings[crossings.len() - 1] - crossings[0]) / ((crossings.len() - 1) as f64 / 2.0);
    let (i0, mass, g, h, theta0): (f64, f64, f64, f64, f64) =
        (2.0, 3.0, 9.81, 0.5, 150f64.to_radians());
    let m = (0.5 * theta0).sin().powi(2);
    let exact = 4.0 * eom::elliptic::complete_k(m).unwrap() * (i0 / (mass * g * h)).sqrt();
    // Rows every 5 ms; at a crossing θ'' = 0, so linear interpolation errs by O(Δt³θ''') ≈
    // 1e-7 s, and DOP853 at 1e-11 keeps the phase to ~1e-9: 1e-6 relative is the bound.
    assert!(
        ((measured - exact) / exact).abs() < 1e-6,
        "period {measured} against {exact}"
    );
    let s = summary(&out);
    assert_eq!(s["variant"], "pendulum");
    assert!(s["energy_drift"].as_f64().unwrap() < 1e-9);
    let reported = s["period_s"].as_f64().unwrap();
    assert!(
        ((reported - exact) / exact).abs() < 1e-6,
        "summary period {reported}"
    );
    check_svgs(&out, &["state.svg", "energy.svg"]);
}

/// |H| = |[I]ω| of every row, relative to the first.
fn momentum_drift(header: &[String], rows: &[Vec<f64>], inertia: [f64; 3]) -> f64 {
    let [p, q, r] = ["p", "q", "r"].map(|n| column(header, rows, n));
    let h = |i: usize| {
        ((inertia[0] * p[i]).powi(2) + (inertia[1] * q[i]).powi(2) + (inertia[2] * r[i]).powi(2))
            .sqrt()
    };
    (0..rows.len())
        .map(|i| (h(i) / h(0) - 1.0).abs())
        .fold(0.0, f64::max)
}

#[test]
fn the_tennis_racket_flips_as_jacobis_solution_says_and_keeps_energy_and_momentum() {
    let out = folder("tennis_racket");
    run_scene("tennis_racket.toml", &out);
    let (header, rows) = trajectory(&out);
    let expected: Vec<&str> = "t,u,v,w,p,q,r,x,y,z,q0,q1,q2,q3,kinetic_energy"
        .split(',')
        .collect();
    assert_eq!(header, expected);
    let s = summary(&out);
    assert_eq!(s["variant"], "spatial_principal_quaternion");
    assert_eq!(s["operations"]["mul"].as_u64(), Some(56));
    assert_eq!(s["full_operations"]["mul"].as_u64(), Some(71));
    // Free of loads: T and |H| constant. DOP853 at rtol 1e-10 over 20 s: 1e-8 relative.
    let t = column(&header, &rows, "t");
    let kinetic = column(&header, &rows, "kinetic_energy");
    let energy = kinetic
        .iter()
        .map(|e| (e / kinetic[0] - 1.0).abs())
        .fold(0.0, f64::max);
    assert!(energy < 1e-8, "energy drift {energy}");
    assert!(momentum_drift(&header, &rows, [2.0, 3.0, 4.5]) < 1e-8);
    // The flips: q changes sign every 2K(m)/λ (Landau & Lifshitz §37), from the invariants.
    let (i, w) = ([2.0, 3.0, 4.5], [0.001, 6.0, 0.002]);
    let two_t: f64 = (0..3).map(|k| i[k] * w[k] * w[k]).sum();
    let h2: f64 = (0..3).map(|k| (i[k] * w[k]).powi(2)).sum();
    let lambda = ((i[2] - i[1]) * (h2 - two_t * i[0]) / (i[0] * i[1] * i[2])).sqrt();
    let m = (i[1] - i[0]) * (two_t * i[2] - h2) / ((i[2] - i[1]) * (h2 - two_t * i[0]));
    let half_period = 2.0 * eom::elliptic::complete_k(m).unwrap() / lambda;
    let flips = sign_changes(&t, &column(&header, &rows, "q"));
    assert!(flips.len() >= 3, "{} flips in 20 s", flips.len());
    let measured = (flips[flips.len() - 1] - flips[0]) / (flips.len() - 1) as f64;
    // Crossings interpolated between rows 10 ms apart, where q moves fastest: ~1e-5 s.
    assert!(
        ((measured - half_period) / half_period).abs() < 1e-4,
        "{measured} against {half_period}"
    );
    check_svgs(&out, &["state.svg", "attitude.svg", "track.svg"]);
}

#[test]
fn the_free_plate_keeps_its_energy_and_momentum() {
    let out = folder("free_precession");
    run_scene("free_precession.toml", &out);
    let (header, rows) = trajectory(&out);
    assert!(summary(&out)["variant"] == "spatial_principal_quaternion");
    let kinetic = column(&header, &rows, "kinetic_energy");
    let energy = kinetic
        .iter()
        .map(|e| (e / kinetic[0] - 1.0).abs())
        .fold(0.0, f64::max);
    assert!(energy < 1e-8, "energy drift {energy}");
    assert!(momentum_drift(&header, &rows, [0.001, 0.001, 0.002]) < 1e-8);
}

#[test]
fn the_steady_turn_settles_at_the_yaw_rate_of_the_equations_at_rest() {
    let out = folder("steady_turn");
    run_scene("steady_turn.toml", &out);
    let (header, rows) = trajectory(&out);
    assert_eq!(header[..7], ["t", "u", "v", "r", "x", "y", "psi"]);
    let last = rows.last().unwrap();
    let (u, v, r) = (last[1], last[2], last[3]);
    // 4.46 with every rate zero: M(−v r − x_G r²) = X − d_u u, M u r = −d_v v,
    // M x_G u r = N − d_r r; solved by fixed-point iteration from the run's end.
    let (mass, x_g, thrust, moment) = (1.0e5, 2.0, 5.0e4, 2.0e5);
    let (d_u, d_v, d_r) = (1.0e4, 1.0e5, 4.0e7);
    let (mut su, mut sv, mut sr) = (u, v, r);
    for _ in 0..200 {
        sr = moment / (d_r + mass * x_g * su);
        sv = -mass * su * sr / d_v;
        su = (thrust + mass * (sv * sr + x_g * sr * sr)) / d_u;
    }
    // After 400 s the slowest transient (M/d_u = 10 s) has decayed by e⁻⁴⁰.
    assert!(((r - sr) / sr).abs() < 1e-8, "yaw rate {r} against {sr}");
    assert!(((u - su) / su).abs() < 1e-8, "speed {u} against {su}");
    assert!((v - sv).abs() < 1e-8 * su, "sway {v} against {sv}");
    check_svgs(&out, &["state.svg", "track.svg"]);
}

#[test]
fn the_other_example_scenes_run() {
    for (name, variant, plots) in [
        (
            "auv.toml",
            "spatial_xz_euler",
            &["state.svg", "attitude.svg", "track.svg"][..],
        ),
        (
            "looping.toml",
            "spatial_principal_quaternion",
            &["state.svg", "attitude.svg", "track.svg"],
        ),
        (
            "planar_drift.toml",
            "planar_at_g",
            &["state.svg", "track.svg"],
        ),
        (
            "puck_in_wind.toml",
            "planar_space_fixed",
            &["state.svg", "track.svg", "energy.svg"],
        ),
    ] {
        let out = folder(name.trim_end_matches(".toml"));
        run_scene(name, &out);
        assert_eq!(summary(&out)["variant"], variant, "{name}");
        check_svgs(&out, plots);
    }
}

#[test]
fn the_looping_body_passes_pitch_90_degrees() {
    let out = folder("looping_pitch");
    run_scene("looping.toml", &out);
    let (header, rows) = trajectory(&out);
    let [q0, q2] = ["q0", "q2"].map(|n| column(&header, &rows, n));
    // A pure pitch θ has q = (cos θ/2, 0, sin θ/2, 0): past 90° once q2 > q0.
    let last = rows.len() - 1;
    assert!(
        q2[last] > q0[last],
        "pitch stayed below 90°: q0 {}, q2 {}",
        q0[last],
        q2[last]
    );
}

/// A scene file with `edit` applied runs into a fresh folder; returns its exit code and stderr.
fn run_edited(test: &str, base: &str, edit: impl Fn(&str) -> String) -> (i32, String) {
    let dir = folder(test);
    let text = edit(&std::fs::read_to_string(scene(base)).unwrap());
    let path = dir.join("scene.toml");
    std::fs::write(&path, text).unwrap();
    let output = eom()
        .args([
            "run",
            path.to_str().unwrap(),
            "--out",
            dir.join("out").to_str().unwrap(),
        ])
        .output()
        .unwrap();
    (
        output.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

#[test]
fn bad_scene_files_name_the_key_and_exit_with_the_scene_code() {
    let cases: [(&str, &str, &str, &str); 9] = [
        ("malformed", "[integrator\n", "", "not valid TOML"),
        (
            "unknown_key",
            "method = \"dop853\"",
            "method = \"dop853\"\nmethd = 1",
            "integrator.methd",
        ),
        (
            "wrong_type",
            "end_time = 20.0",
            "end_time = \"long\"",
            "integrator.end_time",
        ),
        ("negative_mass", "mass = 1.0 ", "mass = -1.0 ", "body.mass"),
        (
            "impossible_tensor",
            "[0.0, 0.0, 4.5]]",
            "[0.0, 0.0, 6.0]]",
            "body.inertia",
        ),
        (
            "not_finite",
            "end_time = 20.0",
            "end_time = nan",
            "integrator.end_time",
        ),
        (
            "zero_tolerance",
            "rtol = 1e-10",
            "rtol = 0.0",
            "integrator.rtol",
        ),
        ("missing_key", "end_time = 20.0", "", "end_time"),
        (
            "other_family_key",
            "[initial]",
            "[initial]\ntheta_deg = 3.0",
            "initial.theta_deg",
        ),
    ];
    for (test, from, to, key) in cases {
        let (code, stderr) = run_edited(test, "tennis_racket.toml", |text| {
            if test == "malformed" {
                format!("{text}\n{from}")
            } else {
                assert!(text.contains(from), "{test}: the scene has no `{from}`");
                text.replacen(from, to, 1)
            }
        });
        assert_eq!(code, 3, "{test}: exit {code}, {stderr}");
        assert!(
            stderr.contains(key),
            "{test}: `{key}` not named in: {stderr}"
        );
        assert!(!stderr.contains("panicked"), "{test}: {stderr}");
    }
}

#[test]
fn a_zero_step_names_the_key() {
    let (code, stderr) = run_edited("zero_step", "looping.toml", |t| {
        t.replace("step = 0.001", "step = 0.0")
    });
    assert_eq!(code, 3, "{stderr}");
    assert!(stderr.contains("integrator.step"), "{stderr}");
}

#[test]
fn an_output_folder_that_holds_a_run_is_kept_without_force() {
    let out = folder("force");
    run_scene("looping.toml", &out);
    let again = eom()
        .args([
            "run",
            scene("looping.toml").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(again.status.code(), Some(4));
    assert!(String::from_utf8_lossy(&again.stderr).contains("--force"));
    let forced = eom()
        .args([
            "run",
            scene("looping.toml").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--force",
        ])
        .output()
        .unwrap();
    assert!(forced.status.success());
}

#[test]
fn a_sweep_runs_every_case_and_shards_split_them() {
    let dir = folder("sweep");
    let text = std::fs::read_to_string(scene("pendulum.toml"))
        .unwrap()
        .replace("end_time = 20.0", "end_time = 2.0")
        + "\n[sweep]\n\"initial.theta_deg\" = [10.0, 90.0, 170.0]\n\"body.mass\" = [1.0, 3.0]\n";
    let path = dir.join("sweep.toml");
    std::fs::write(&path, &text).unwrap();
    let run = |out: &Path, shard: Option<&str>| {
        let mut command = eom();
        command.args([
            "run",
            path.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        if let Some(shard) = shard {
            command.args(["--shard", shard]);
        }
        let output = command.output().unwrap();
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
    };
    let all = dir.join("all");
    run(&all, None);
    let table = std::fs::read_to_string(all.join("sweep.csv")).unwrap();
    assert_eq!(table.lines().count(), 1 + 6);
    assert!(
        table
            .lines()
            .next()
            .unwrap()
            .starts_with("case,body.mass,initial.theta_deg,variant")
    );
    for k in 0..6 {
        assert!(
            all.join(format!("case-{k:04}"))
                .join("summary.json")
                .exists()
        );
    }
    // Two shards make the same six lines.
    let (a, b) = (dir.join("a"), dir.join("b"));
    run(&a, Some("0/2"));
    run(&b, Some("1/2"));
    let lines = |path: PathBuf| -> Vec<String> {
        std::fs::read_to_string(path)
            .unwrap()
            .lines()
            .skip(1)
            .map(|l| {
                // Drop the wall time, which differs between runs.
                let mut fields: Vec<&str> = l.split(',').collect();
                fields.remove(6);
                fields.join(",")
            })
            .collect()
    };
    let mut sharded = lines(a.join("sweep-shard-0-of-2.csv"));
    sharded.extend(lines(b.join("sweep-shard-1-of-2.csv")));
    sharded.sort();
    let mut whole = lines(all.join("sweep.csv"));
    whole.sort();
    assert_eq!(sharded, whole);
}

#[test]
fn tradeoff_recommends_a_setting_that_meets_the_target() {
    let dir = folder("tradeoff");
    // The pendulum released from rest, over 2 s: its reference is the exact solution. At
    // most 10⁵ steps keeps the sweep short in a debug build.
    let text = std::fs::read_to_string(scene("pendulum.toml"))
        .unwrap()
        .replace("end_time = 20.0", "end_time = 2.0\nmax_steps = 100_000");
    let path = dir.join("pendulum.toml");
    std::fs::write(&path, text).unwrap();
    let output = eom()
        .args([
            "tradeoff",
            path.to_str().unwrap(),
            "--target",
            "1e-6",
            "--json",
        ])
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let value: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(value["target"].as_f64(), Some(1e-6));
    assert!(value["reference"].as_str().unwrap().contains("exact"));
    let rows = value["rows"].as_array().unwrap();
    for method in ["euler", "symplectic-euler", "rk4", "dopri5", "dop853"] {
        assert!(
            rows.iter().any(|r| r["method"] == method),
            "no {method} rows"
        );
    }
    let recommended = &value["recommended"];
    assert!(recommended["error"].as_f64().unwrap() <= 1e-6);
    // It is the fastest of the rows that meet the target.
    let fastest = rows
        .iter()
        .filter(|r| r["error"].as_f64().is_some_and(|e| e <= 1e-6))
        .map(|r| r["seconds"].as_f64().unwrap())
        .fold(f64::INFINITY, f64::min);
    assert_eq!(recommended["seconds"].as_f64(), Some(fastest));
}

#[test]
fn the_puck_in_the_wind_keeps_its_energy_and_spin() {
    let out = folder("puck");
    run_scene("puck_in_wind.toml", &out);
    let (header, rows) = trajectory(&out);
    assert_eq!(
        header[..7],
        ["t", "x", "y", "psi", "x_dot", "y_dot", "psi_dot"]
    );
    assert_eq!(
        header[7..],
        ["kinetic_energy", "potential_energy", "total_energy"]
    );
    // The wind's force is constant in space: the energy T − F·r is conserved, Ẋ does not
    // change and Ẏ grows at F/M. DOPRI5 at 1e-10: 1e-9 relative.
    let s = summary(&out);
    assert!(
        s["energy_drift"].as_f64().unwrap() < 1e-9,
        "{}",
        s["energy_drift"]
    );
    let last = rows.last().unwrap();
    let (t, x_dot, y_dot, spin) = (last[0], last[4], last[5], last[6]);
    assert!((x_dot - 1.5).abs() < 1e-9 && (spin - 12.0).abs() < 1e-9);
    assert!((y_dot - 0.05 / 0.17 * t).abs() < 1e-9, "Ẏ = {y_dot}");
}

#[test]
fn the_heavy_top_keeps_its_energy_spin_and_vertical_momentum() {
    let out = folder("heavy_top");
    run_scene("heavy_top.toml", &out);
    let (header, rows) = trajectory(&out);
    assert_eq!(header[..8], ["t", "p", "q", "r", "q0", "q1", "q2", "q3"]);
    assert_eq!(
        header[8..],
        ["kinetic_energy", "potential_energy", "total_energy"]
    );
    let s = summary(&out);
    assert_eq!(s["variant"], "top_quaternion");
    // DOP853 at 1e-11 over 10 s: the energy to 1e-9 of its size.
    assert!(
        s["energy_drift"].as_f64().unwrap() < 1e-9,
        "{}",
        s["energy_drift"]
    );
    // A symmetric top keeps its spin r (I_xx = I_yy: ṙ = 0 exactly) and H_Z, the vertical
    // component of its angular momentum about the pivot, H_O = I_O ω turned into space.
    let (mass, h) = (1.0, 0.5);
    let i_o = [0.25 + mass * h * h, 0.25 + mass * h * h, 0.2];
    let vertical = |row: &Vec<f64>| {
        let q = nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
            row[4], row[5], row[6], row[7],
        ));
        let momentum = nalgebra::Vector3::new(i_o[0] * row[1], i_o[1] * row[2], i_o[2] * row[3]);
        (q * momentum).z
    };
    let (r0, h0) = (rows[0][3], vertical(&rows[0]));
    for row in &rows {
        assert!(
            (row[3] - r0).abs() < 1e-9 * r0,
            "spin {} at t = {}",
            row[3],
            row[0]
        );
        assert!(
            (vertical(row) - h0).abs() < 1e-9 * h0.abs().max(1.0),
            "H_Z at t = {}",
            row[0]
        );
    }
    check_svgs(&out, &["state.svg", "attitude.svg", "energy.svg"]);
}
