//! `eom run` end to end: every example scene runs through the binary, and what it writes is
//! checked against physics — the pendulum's period against 4K(m)√(I₀/Mgh), the free bodies'
//! energy and |H|, the steady turn's yaw rate against the equations at rest, the tennis
//! racket's flips against Jacobi's solution — and the SVGs parse as XML with their series.
//! Bad scene files each give an error that names the key and a non-zero exit.

use eom_test_support::child;
use eom_test_support::cli::{eom, eom_command, folder, run_into, scene, succeeded};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// `eom run SCENE --out OUT`, waited for.
fn eom_run(scene: &Path, out: &Path) -> Output {
    eom_command()
        .args([
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap()
}

fn run_scene(name: &str, out: &Path) -> Output {
    let output = eom_run(&scene(name), out);
    assert!(
        output.status.success(),
        "{name}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    output
}

/// trajectory.csv as a header (each column `name[unit]`) and rows of numbers.
fn trajectory(out: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(|x| x.parse::<f64>().unwrap()).collect())
        .collect();
    (header, rows)
}

/// A header field's name without its unit: `u` of `u[m/s]`.
fn name_of(field: &str) -> &str {
    field.split_once('[').map_or(field, |(name, _)| name)
}

/// The index of the column named `name` (whatever its unit).
fn index_of(header: &[String], name: &str) -> usize {
    header
        .iter()
        .position(|h| name_of(h) == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
}

fn column(header: &[String], rows: &[Vec<f64>], name: &str) -> Vec<f64> {
    let i = index_of(header, name);
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
/// The plots drawn only for some motions: each is checked absent where it is not expected.
const CONDITIONAL_PLOTS: [&str; 3] = ["polhode.svg", "profile.svg", "track.svg"];

fn check_svgs(out: &Path, expected: &[&str]) {
    for name in CONDITIONAL_PLOTS {
        assert_eq!(
            out.join(name).exists(),
            expected.contains(&name),
            "{name} in {}",
            out.display()
        );
    }
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
    assert_eq!(header[..3], ["t[s]", "theta[rad]", "theta_dot[rad/s]"]);
    assert_eq!(
        header[3..],
        [
            "kinetic_energy[J]",
            "potential_energy[J]",
            "total_energy[J]"
        ]
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
    let output = run_scene("tennis_racket.toml", &out);
    // It turns in place: no empty track plot, and the listing says why.
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        stdout.contains("(track.svg not drawn: the body does not translate, it stays at (0, 0) m)"),
        "{stdout}"
    );
    let (header, rows) = trajectory(&out);
    let expected: Vec<&str> = "t[s],u[m/s],v[m/s],w[m/s],p[rad/s],q[rad/s],r[rad/s],x[m],y[m],\
                               z[m],q0[-],q1[-],q2[-],q3[-],kinetic_energy[J]"
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
    check_svgs(&out, &["state.svg", "attitude.svg", "polhode.svg"]);
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
    // Thrown forward and up, it climbs: a profile beside the plan.
    check_svgs(
        &out,
        &[
            "state.svg",
            "attitude.svg",
            "track.svg",
            "polhode.svg",
            "profile.svg",
        ],
    );
}

#[test]
fn the_steady_turn_settles_at_the_yaw_rate_of_the_equations_at_rest() {
    let out = folder("steady_turn");
    run_scene("steady_turn.toml", &out);
    let (header, rows) = trajectory(&out);
    assert_eq!(
        header[..7],
        [
            "t[s]", "u[m/s]", "v[m/s]", "r[rad/s]", "x[m]", "y[m]", "psi[rad]"
        ]
    );
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
            &["state.svg", "attitude.svg", "track.svg", "profile.svg"][..],
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
    let output = eom_run(&path, &dir.join("out"));
    (
        output.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

#[test]
fn bad_scene_files_name_the_key_and_exit_with_the_scene_code() {
    let cases: [(&str, &str, &str, &str); 10] = [
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
        (
            "tolerance_below_f64",
            "rtol = 1e-10",
            "rtol = 1e-16",
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
    let again = eom_run(&scene("looping.toml"), &out);
    assert_eq!(again.status.code(), Some(4));
    assert!(String::from_utf8_lossy(&again.stderr).contains("--force"));
    let forced = eom_command()
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

/// The pendulum's period runs again refined, and the summary says how far it moved: with
/// DOP853 at tolerances / 100 (`tolerance_difference`), with RK4 at half the step actually
/// taken (`half_step_difference`), which shrinks as the step does.
#[test]
fn the_pendulum_s_period_says_how_far_it_moves_when_the_run_is_refined() {
    let dir = folder("pendulum_refined");
    let text = std::fs::read_to_string(scene("pendulum.toml")).unwrap();
    let adaptive = dir.join("adaptive");
    run_scene("pendulum.toml", &adaptive);
    let s = summary(&adaptive);
    let moved = s["tolerance_difference"]["period_s"].as_f64().unwrap();
    // DOP853 at 1e-11 keeps the phase to ~1e-9 s (the test above); a hundred times tighter
    // moves the period by no more than that, and by something.
    assert!(moved > 0.0 && moved < 1e-8, "{moved}");
    assert!(s.get("half_step_difference").is_none(), "{s}");
    let fixed = |step: f64, every: f64| -> f64 {
        let path = dir.join(format!("rk4_{step}_{every}.toml"));
        let text = text
            .replace(
                "method = \"dop853\"",
                &format!("method = \"rk4\"\nstep = {step}"),
            )
            .replace("rtol = 1e-11\n", "")
            .replace("atol = 1e-11\n", "")
            .replace("every = 0.005", &format!("every = {every}"));
        std::fs::write(&path, text).unwrap();
        let out = dir.join(format!("rk4_{step}_{every}"));
        let output = eom_run(&path, &out);
        assert!(output.status.success(), "{output:?}");
        let s = summary(&out);
        assert!(s.get("tolerance_difference").is_none(), "{s}");
        s["half_step_difference"]["period_s"].as_f64().unwrap()
    };
    // Rows every 5 ms cut a step of 20 ms to 5 ms: the refined run halves that, so the
    // period moves (halving 20 ms alone would change nothing, and say 0).
    assert!(fixed(0.02, 0.005) > 0.0);
    // RK4 is of order 4: halving the step shrinks the difference about 16 times; 8 allows for
    // a step not yet small enough for the order to show.
    let (coarse, fine) = (fixed(0.02, 0.1), fixed(0.01, 0.1));
    assert!(coarse > 8.0 * fine && fine > 0.0, "{coarse} then {fine}");
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
        run_into(&path, out, shard);
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
    let header: Vec<&str> = table.lines().next().unwrap().split(',').collect();
    let period = header.iter().position(|h| *h == "period_s").unwrap();
    let mut missing = 0;
    for (k, line) in table.lines().skip(1).enumerate() {
        // Numbers as trajectory.csv writes them: a small one in e-notation, not 0.0000…
        assert!(!line.contains("0.0000"), "{line}");
        let summary =
            std::fs::read_to_string(all.join(format!("case-{k:04}")).join("summary.json")).unwrap();
        let summary: serde_json::Value = serde_json::from_str(&summary).unwrap();
        // A period the run does not give (the 170° swing is slower than 2 s) says why.
        if line.split(',').nth(period) == Some("") {
            missing += 1;
            let warnings = summary["warnings"].to_string();
            assert!(warnings.contains("period_s is not given"), "{warnings}");
        } else {
            assert!(summary["period_s"].is_f64(), "{summary}");
        }
    }
    assert!(missing > 0, "the test needs a case without a period");
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

/// Every registered kind's example scene swept over one key of its integrator (its fixed
/// step, or its relative tolerance), whole and as two shards merged: the merged table the
/// whole run's but the wall times, and `sweep.svg` (the figures the kind names for its sweeps
/// against the key) the same bytes, drawn for every kind whose example gives one of them
/// (every kind's does). Each example cut to its first run, briefly, as the titles test cuts
/// them.
#[test]
fn every_kinds_sweep_runs_whole_or_in_shards_and_draws_its_figures_alike() {
    for kind in eom::kinds::REGISTRY {
        let dir = folder(&format!("sweep_every_kind_{}", kind.name));
        let text = std::fs::read_to_string(scene(kind.example)).unwrap();
        let table: toml::Table = toml::from_str(&text).unwrap();
        let integrator = table["integrator"].as_table().unwrap();
        let (key, values) = match integrator.get("step").and_then(toml::Value::as_float) {
            Some(step) => ("integrator.step", [step, step / 2.0]),
            None => {
                let rtol = integrator["rtol"].as_float().unwrap();
                ("integrator.rtol", [rtol, rtol * 10.0])
            }
        };
        let text = format!(
            "{text}\n[sweep]\n\"{key}\" = [{:?}, {:?}]\n",
            values[0], values[1]
        );
        let path = dir.join("sweep.toml");
        std::fs::write(&path, &text).unwrap();
        let run = |out: &Path, shard: Option<&str>| run_into(&path, out, shard);
        let (whole, sharded) = (dir.join("whole"), dir.join("sharded"));
        run(&whole, None);
        run(&sharded, Some("0/2"));
        run(&sharded, Some("1/2"));
        succeeded(&eom(&["sweep-merge", sharded.to_str().unwrap()]));
        let without_wall_times = |folder: &Path| -> Vec<String> {
            let table = std::fs::read_to_string(folder.join("sweep.csv")).unwrap();
            let header: Vec<&str> = table.lines().next().unwrap().split(',').collect();
            let timed: Vec<usize> = (0..header.len())
                .filter(|&k| header[k].ends_with("wall_seconds"))
                .collect();
            (table.lines())
                .map(|line| {
                    let fields = line.split(',').enumerate();
                    let kept = fields.filter(|(k, _)| !timed.contains(k)).map(|(_, f)| f);
                    kept.collect::<Vec<_>>().join(",")
                })
                .collect()
        };
        assert_eq!(
            without_wall_times(&sharded),
            without_wall_times(&whole),
            "{}",
            kind.name
        );
        let plot = std::fs::read_to_string(whole.join("sweep.svg"))
            .unwrap_or_else(|_| panic!("{}: no sweep.svg", kind.name));
        assert!(
            plot.contains(key),
            "{}: the key is not on the plot",
            kind.name
        );
        // The kind's own figures, not another kind's of the same name's end.
        let first = kind.swept_figures.names[0].trim_start_matches("*.");
        let label = first.rsplit_once('_').unwrap().0.replace('_', " ");
        assert!(
            plot.contains(&label),
            "{}: {label} is not on the plot",
            kind.name
        );
        assert_eq!(
            std::fs::read_to_string(sharded.join("sweep.svg")).unwrap(),
            plot,
            "{}: the merge draws the same plot",
            kind.name
        );
    }
}

/// `eom tradeoff --json` of every registered kind's example scene: a row per setting
/// compared, and a recommendation or why there is none.
#[test]
fn every_kinds_example_gets_a_tradeoff() {
    for kind in eom::kinds::REGISTRY {
        let output = eom_command()
            .args(["tradeoff", scene(kind.example).to_str().unwrap(), "--json"])
            .output()
            .unwrap();
        assert!(
            output.status.success(),
            "{}: {}",
            kind.name,
            String::from_utf8_lossy(&output.stderr)
        );
        let report: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
        let rows = report["rows"].as_array().unwrap();
        assert!(!rows.is_empty(), "{}: {report}", kind.name);
        let why_not = report["why_not"].as_str().unwrap_or("");
        assert!(
            !report["recommended"].is_null() || !why_not.is_empty(),
            "{}: neither a recommendation nor why not: {report}",
            kind.name
        );
    }
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
    let output = eom_command()
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
    assert_eq!(value["converged"], true);
    // It is the fastest of the rows that meet the target where every tighter setting of the
    // same method meets it too.
    let meets = |r: &serde_json::Value| r["error"].as_f64().is_some_and(|e| e <= 1e-6);
    let fastest = (0..rows.len())
        .filter(|&i| meets(&rows[i]))
        .filter(|&i| {
            (rows[i..].iter())
                .filter(|r| r["method"] == rows[i]["method"] && r["error"].is_f64())
                .all(meets)
        })
        .map(|i| rows[i]["seconds"].as_f64().unwrap())
        .fold(f64::INFINITY, f64::min);
    assert_eq!(recommended["seconds"].as_f64(), Some(fastest));
}

/// A body spun about its intermediate principal axis, the axis written in decimals (the tensor
/// turned 30° about x): round-off starts the flip, which amplifies it by e^(2.45 t), so RK4's
/// end state jumps as the step shrinks (1.2e-4 at 300 steps, then 2.0 from 3000 on). No setting
/// is recommended, the output says why, and the table's header is not read as an error.
#[test]
fn tradeoff_recommends_nothing_where_the_errors_do_not_converge() {
    let dir = folder("tradeoff_unconverged");
    let text = std::fs::read_to_string(scene("tennis_racket.toml"))
        .unwrap()
        .replace(
            "inertia = [[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 4.5]]",
            "inertia = [[2.0, 0.0, 0.0], [0.0, 3.3749999999999996, -0.6495190528383289], \
             [0.0, -0.6495190528383289, 4.125]]",
        )
        .replace(
            "rates = [0.001, 6.0, 0.002]",
            "rates = [0.0, 5.196152422706632, 2.9999999999999996]",
        )
        .replace("max_steps = 1_000_000", "max_steps = 10_000");
    assert!(text.contains("2.9999999999999996") && text.contains("max_steps = 10_000"));
    let path = dir.join("intermediate.toml");
    std::fs::write(&path, text).unwrap();
    let tradeoff = |json: bool| {
        let mut command = eom_command();
        command.args(["tradeoff", path.to_str().unwrap(), "--target", "1e-2"]);
        if json {
            command.arg("--json");
        }
        command.output().unwrap()
    };
    let output = tradeoff(false);
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(!output.status.success(), "{stdout}");
    assert!(
        stderr.contains("the errors grow as the setting tightens"),
        "{stderr}"
    );
    assert!(stdout.contains("no setting is recommended"), "{stdout}");
    assert!(stdout.lines().all(|l| !l.starts_with("error")), "{stdout}");
    let value: serde_json::Value = serde_json::from_slice(&tradeoff(true).stdout).unwrap();
    assert_eq!(value["converged"], false);
    assert_eq!(value["recommended"], serde_json::Value::Null);
    assert!(value["why_not"].as_str().unwrap().contains("round-off"));
}

#[test]
fn the_puck_in_the_wind_keeps_its_energy_and_spin() {
    let out = folder("puck");
    run_scene("puck_in_wind.toml", &out);
    let (header, rows) = trajectory(&out);
    assert_eq!(
        header[..7],
        [
            "t[s]",
            "x[m]",
            "y[m]",
            "psi[rad]",
            "x_dot[m/s]",
            "y_dot[m/s]",
            "psi_dot[rad/s]"
        ]
    );
    assert_eq!(
        header[7..],
        [
            "kinetic_energy[J]",
            "potential_energy[J]",
            "total_energy[J]"
        ]
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
    assert_eq!(
        header[..8],
        [
            "t[s]", "p[rad/s]", "q[rad/s]", "r[rad/s]", "q0[-]", "q1[-]", "q2[-]", "q3[-]"
        ]
    );
    assert_eq!(
        header[8..],
        [
            "kinetic_energy[J]",
            "potential_energy[J]",
            "total_energy[J]"
        ]
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

/// A run into `out` that is expected to fail: its exit code and standard error.
fn run_failing(scene: &Path, out: &Path) -> (i32, String) {
    let output = eom_run(scene, out);
    (
        output.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

/// The unit quaternion (scalar first) of roll φ, pitch θ, yaw ψ (E = Rz(ψ)Ry(θ)Rx(φ)).
fn quaternion_of(phi: f64, theta: f64, psi: f64) -> [f64; 4] {
    let q = nalgebra::UnitQuaternion::from_euler_angles(phi, theta, psi);
    [q.w, q.i, q.j, q.k]
}

#[test]
fn euler_angles_stop_at_gimbal_lock_where_the_quaternion_goes_on_and_agree_before_it() {
    let dir = folder("gimbal_lock");
    let text = std::fs::read_to_string(scene("looping.toml")).unwrap();
    let euler = dir.join("looping_euler.toml");
    std::fs::write(
        &euler,
        text.replace("kinematics = \"quaternion\"", "kinematics = \"euler\""),
    )
    .unwrap();
    let (code, stderr) = run_failing(&euler, &dir.join("euler"));
    assert_eq!(code, 5, "{stderr}");
    for needed in ["gimbal lock", "crossed ±90°", "kinematics = \"quaternion\""] {
        assert!(stderr.contains(needed), "no `{needed}` in: {stderr}");
    }
    assert!(!stderr.contains("panicked"), "{stderr}");
    // A pure pitch under a constant moment: q = 2t rad/s, θ = t², 90° at t = √(π/2) =
    // 1.2533 s. RK4 at 1 ms checks every step: it stops at the step that crossed.
    let s = summary(&dir.join("euler"));
    let error = s["error"].as_str().unwrap();
    assert!(error.contains("gimbal lock at t = 1.254 s"), "{error}");
    assert_eq!(s["interrupted"], false);
    let (header, rows) = trajectory(&dir.join("euler"));
    let last = rows.last().unwrap()[0];
    assert_eq!(
        last, 1.25,
        "rows stop at the last one before the step that crossed"
    );
    assert_eq!(s["final_time"].as_f64(), Some(last));
    check_svgs(
        &dir.join("euler"),
        &["state.svg", "attitude.svg", "track.svg"],
    );
    // The same scene with a quaternion goes on through 90° (the_looping_body_passes_pitch_90
    // checks where it ends) and agrees with every Euler-angle row: the same RK4 steps of the
    // same dynamics, the attitude compared as quaternions (which stay well conditioned at
    // 90°). Both integrate to about 1e-12 here; they agree to 1e-10 of each entry's size.
    let quaternion = dir.join("quaternion");
    run_scene("looping.toml", &quaternion);
    let (q_header, q_rows) = trajectory(&quaternion);
    assert!(q_rows.last().unwrap()[0] == 2.0 && q_rows.len() > rows.len());
    let at = |names: &[String], row: &[f64], name: &str| row[index_of(names, name)];
    for (e, q) in rows.iter().zip(&q_rows) {
        assert_eq!(e[0], q[0]);
        for name in ["u", "v", "w", "p", "q", "r", "x", "y", "z"] {
            let (a, b) = (at(&header, e, name), at(&q_header, q, name));
            assert!(
                (a - b).abs() <= 1e-10 * a.abs().max(1.0),
                "{name} at t = {}: {a} against {b}",
                e[0]
            );
        }
        let from_angles = quaternion_of(
            at(&header, e, "phi"),
            at(&header, e, "theta"),
            at(&header, e, "psi"),
        );
        for (k, name) in ["q0", "q1", "q2", "q3"].iter().enumerate() {
            let b = at(&q_header, q, name);
            assert!(
                (from_angles[k] - b).abs() <= 1e-10,
                "{name} at t = {}: {} against {b}",
                e[0],
                from_angles[k]
            );
        }
    }
    // A run that starts at the pole fails at once, and a top tipping over in Euler angles
    // fails as the spatial body does.
    let upright = dir.join("at_the_pole.toml");
    std::fs::write(
        &upright,
        text.replace("kinematics = \"quaternion\"", "kinematics = \"euler\"")
            .replace("[initial]", "[initial]\nattitude_deg = [0.0, 90.0, 0.0]"),
    )
    .unwrap();
    let (code, stderr) = run_failing(&upright, &dir.join("at_the_pole"));
    assert_eq!(code, 5, "{stderr}");
    assert!(
        stderr.contains("gimbal lock at t = 0 s") && stderr.contains("from ±90°"),
        "{stderr}"
    );
    let top = dir.join("top.toml");
    std::fs::write(
        &top,
        std::fs::read_to_string(scene("heavy_top.toml"))
            .unwrap()
            .replace("kinematics = \"quaternion\"", "kinematics = \"euler\"")
            .replace("rates = [0.0, 0.0, 20.0]", "rates = [0.0, 0.0, 0.0]")
            .replace(
                "attitude_deg = [28.6, 0.0, 0.0]",
                "attitude_deg = [0.0, 80.0, 0.0]",
            ),
    )
    .unwrap();
    let (code, stderr) = run_failing(&top, &dir.join("top"));
    assert_eq!(code, 5, "{stderr}");
    assert!(stderr.contains("gimbal lock"), "{stderr}");
}

/// A sweep of a body whose every case fails (gimbal lock) keeps each case's rows, plots and
/// summary (with its `case`), and its table has every column, each case's variant and its
/// error: the columns are the scene's, not borrowed from a case that ran to its end.
#[test]
fn a_sweep_whose_every_case_fails_keeps_its_columns_and_says_each_error() {
    let dir = folder("sweep_failing");
    let text = std::fs::read_to_string(scene("looping.toml"))
        .unwrap()
        .replace("kinematics = \"quaternion\"", "kinematics = \"euler\"")
        + "\n[sweep]\n\"body.mass\" = [10.0, 20.0]\n";
    let path = dir.join("looping_sweep.toml");
    std::fs::write(&path, text).unwrap();
    let out = dir.join("out");
    let (code, stderr) = run_failing(&path, &out);
    assert_eq!(code, 5, "{stderr}");
    assert!(stderr.contains("2 of 2 cases failed"), "{stderr}");
    let table = std::fs::read_to_string(out.join("sweep.csv")).unwrap();
    let mut reader = csv::Reader::from_reader(table.as_bytes());
    let header: Vec<String> = reader.headers().unwrap().iter().map(String::from).collect();
    for column in ["variant", "steps", "energy_drift", "final_theta", "error"] {
        assert!(
            header.iter().any(|h| h == column),
            "no {column} in {header:?}"
        );
    }
    let at = |name: &str| header.iter().position(|h| h == name).unwrap();
    let rows: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), 2);
    for (k, row) in rows.iter().enumerate() {
        assert!(!row[at("variant")].is_empty(), "{row:?}");
        assert_eq!(
            &row[at("steps")],
            "",
            "a failed case gives no figure: {row:?}"
        );
        assert!(
            row[at("error")].contains("gimbal lock at t = 1.254 s"),
            "{row:?}"
        );
        let case = out.join(format!("case-{k:04}"));
        let s = summary(&case);
        assert_eq!(s["case"]["index"], k, "{s}");
        assert_eq!(s["case"]["values"]["body.mass"], [10.0, 20.0][k], "{s}");
        assert!(s["error"].as_str().unwrap().contains("gimbal lock"), "{s}");
        // The case's plots say its values in their title.
        let plot = std::fs::read_to_string(case.join("state.svg")).unwrap();
        let label = format!("body.mass = {}", ["10.0", "20.0"][k]);
        assert!(plot.contains(&label), "no `{label}` in state.svg");
    }
}

/// A free body spinning about its z-axis at `rate` rad/s, with `method` and `step`, and
/// `extra` lines in its [loads].
fn spinning(
    dir: &Path,
    name: &str,
    (method, step): (&str, f64),
    rate: f64,
    loads: &str,
) -> PathBuf {
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(
        &path,
        format!(
            "title = \"Spinning\"\n[body]\nmass = 1.0\n\
             inertia = [[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 4.5]]\n\
             [model]\nfamily = \"spatial\"\n[initial]\nvelocity = [1.0, 0.0, 0.0]\n\
             rates = [0.0, 0.0, {rate:?}]\n[loads]\n{loads}\n[integrator]\n\
             method = \"{method}\"\nstep = {step:?}\nend_time = 2.0\n[output]\nevery = 0.01\n"
        ),
    )
    .unwrap();
    path
}

#[test]
fn a_fixed_step_too_long_for_the_rate_of_turn_stops_the_run_or_warns() {
    let dir = folder("step_against_rate");
    // At 5000 rad/s a 1 ms RK4 step is h·|ω| = 5, beyond 2√2: the run stops before its
    // first step.
    let fast = spinning(&dir, "fast", ("rk4", 1e-3), 5000.0, "");
    let (code, stderr) = run_failing(&fast, &dir.join("fast"));
    assert_eq!(code, 5, "{stderr}");
    for needed in [
        "t = 0 s",
        "h·|ω| = 0.001 s × 5000.000 rad/s",
        "rk4",
        "2.8284",
    ] {
        assert!(stderr.contains(needed), "no `{needed}` in: {stderr}");
    }
    // Spun up by 1000 rad/s² from 1000 rad/s, it passes 2√2/h = 2828 rad/s at t = 1.83 s:
    // the run stops at the step past it, its rows up to the last before.
    let spun_up = spinning(
        &dir,
        "spun_up",
        ("rk4", 1e-3),
        1000.0,
        "moment_body = [0.0, 0.0, 4500.0]",
    );
    let (code, stderr) = run_failing(&spun_up, &dir.join("spun_up"));
    assert_eq!(code, 5, "{stderr}");
    let s = summary(&dir.join("spun_up"));
    let error = s["error"].as_str().unwrap();
    assert!(
        error.contains("at t = 1.829 s") && error.contains("2829.000 rad/s"),
        "{error}"
    );
    assert_eq!(s["final_time"].as_f64(), Some(1.82));
    // Symplectic Euler on a pendulum (ω₀ = √(Mgh/I₀) = 2.71 rad/s) beyond h·ω₀ = 2, its
    // rows 0.8 s apart so that the step taken is the 0.8 s written (between rows 0.005 s
    // apart it would take steps of 0.005 s, well inside the limit).
    let text = std::fs::read_to_string(scene("pendulum.toml"))
        .unwrap()
        .replace("every = 0.005", "every = 0.8");
    let coarse = dir.join("coarse_pendulum.toml");
    let method = text.find("method").unwrap();
    let end = text[method..].find("end_time").unwrap() + method;
    std::fs::write(
        &coarse,
        format!(
            "{}method = \"symplectic-euler\"\nstep = 0.8\n{}",
            &text[..method],
            &text[end..]
        ),
    )
    .unwrap();
    let (code, stderr) = run_failing(&coarse, &dir.join("coarse_pendulum"));
    assert_eq!(code, 5, "{stderr}");
    assert!(
        stderr.contains("h·ω₀") && stderr.contains("symplectic-euler's stability limit 2.0000"),
        "{stderr}"
    );
    // Explicit Euler has no stability limit on the imaginary axis: its run goes on, and the
    // summary and standard error warn with the largest h·|ω| and the step that would do.
    let euler = spinning(&dir, "euler", ("euler", 1e-4), 1000.0, "");
    let output = eom_run(&euler, &dir.join("euler"));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    let warnings = summary(&dir.join("euler"))["warnings"].clone();
    let warning = warnings[0].as_str().unwrap();
    assert!(
        warning.contains("h·|ω| reached 0.1000") && warning.contains("step ≤ 3.183e-5 s"),
        "{warning}"
    );
    assert!(stderr.contains(warning), "{stderr}");
    // A step that does not divide the rows' 0.01 s: each interval in 67 equal steps of
    // 1.4925e-4 s, not the 1.5e-4 s written, and the warning says the step taken.
    let uneven = spinning(&dir, "uneven", ("euler", 1.5e-4), 1000.0, "");
    let output = eom_run(&uneven, &dir.join("uneven"));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    let warnings = summary(&dir.join("uneven"))["warnings"].clone();
    let warning = warnings[0].as_str().unwrap();
    assert!(
        warning.contains("h·|ω| reached 0.1493 ")
            && warning.contains(
                "h = 0.000149254 s, the step taken: `integrator.step` = 0.00015 s written"
            ),
        "{warning}"
    );
}

#[test]
fn a_state_or_a_load_that_is_not_finite_is_named_with_its_time() {
    let dir = folder("non_finite_values");
    // Explicit Euler three times past h·|ω| = 1 grows the body's velocity tenfold a step
    // until it overflows: the state component is named.
    let state = spinning(&dir, "state", ("euler", 3e-3), 1000.0, "");
    let (code, stderr) = run_failing(&state, &dir.join("state"));
    assert_eq!(code, 5, "{stderr}");
    assert!(
        stderr.contains("the run failed at t = 0.9")
            && stderr.contains("the state component x is not finite"),
        "{stderr}"
    );
    let s = summary(&dir.join("state"));
    assert!(s["error"].as_str().unwrap().contains("state component x"));
    // Quadratic damping far too strong for the step: u goes 10, −990, 9.8e6, … and at
    // u ≈ −5e254 (the row at 0.07 s) the damping force −d·u|u| overflows at a finite state.
    // The load is named, not the state it would poison next.
    let load = dir.join("load.toml");
    std::fs::write(
        &load,
        "title = \"Overdamped\"\n[body]\nmass = 1.0\nizz = 1.0\n[model]\nfamily = \"planar-g\"\n\
         [initial]\nu = 10.0\n[loads]\nquadratic_damping = [1000.0, 0.0, 0.0]\n[integrator]\n\
         method = \"euler\"\nstep = 0.01\nend_time = 1.0\n[output]\nevery = 0.01\n",
    )
    .unwrap();
    let (code, stderr) = run_failing(&load, &dir.join("load"));
    assert_eq!(code, 5, "{stderr}");
    assert!(
        stderr.contains("the run failed at t = 0.07")
            && stderr.contains("the load input F_x is inf at a finite state"),
        "{stderr}"
    );
    let (_, rows) = trajectory(&dir.join("load"));
    assert_eq!(rows.last().unwrap()[0], 0.07);
    // Every state written is finite (its kinetic energy ½Mu² overflowed long before).
    assert!(
        rows.iter()
            .all(|row| row[1..7].iter().all(|x| x.is_finite()))
    );
}

#[test]
fn an_output_folder_that_cannot_be_written_is_named_with_exit_code_4() {
    let dir = folder("unwritable");
    let file = dir.join("a_file");
    std::fs::write(&file, "").unwrap();
    for out in [file.join("sub"), file.clone()] {
        let (code, stderr) = run_failing(&scene("pendulum.toml"), &out);
        assert_eq!(code, 4, "{stderr}");
        assert!(
            stderr.contains(&format!(
                "the output folder {} cannot be written",
                out.display()
            )),
            "{stderr}"
        );
    }
    #[cfg(unix)]
    read_only_folder(&dir);
}

/// A read-only folder. Root writes through permission bits, so there the folder is made
/// immutable instead where the file system allows (chattr +i); where neither can be arranged
/// this case is left out, and says so.
#[cfg(unix)]
fn read_only_folder(dir: &Path) {
    use std::os::unix::fs::PermissionsExt;
    let read_only = dir.join("read_only");
    std::fs::create_dir(&read_only).unwrap();
    let set_mode = |mode: u32| {
        std::fs::set_permissions(&read_only, std::fs::Permissions::from_mode(mode)).unwrap();
    };
    set_mode(0o555);
    /// Undoes `chattr +i` however the test ends, so the folder can be removed.
    struct Immutable<'a>(&'a Path, bool);
    impl Drop for Immutable<'_> {
        fn drop(&mut self) {
            if self.1 {
                let _ = Command::new("chattr").arg("-i").arg(self.0).status();
            }
        }
    }
    let probe = read_only.join("probe");
    let mut immutable = Immutable(&read_only, false);
    if std::fs::write(&probe, "").is_ok() {
        std::fs::remove_file(&probe).unwrap();
        immutable.1 = Command::new("chattr")
            .arg("+i")
            .arg(&read_only)
            .status()
            .is_ok_and(|s| s.success());
    }
    if std::fs::write(&probe, "").is_err() {
        let (code, stderr) = run_failing(&scene("pendulum.toml"), &read_only);
        assert_eq!(code, 4, "{stderr}");
        assert!(
            stderr.contains(&format!(
                "the output folder {} cannot be written",
                read_only.display()
            )),
            "{stderr}"
        );
    } else {
        eprintln!("a read-only folder cannot be made here; that case is not checked");
    }
    drop(immutable);
    set_mode(0o755);
}

/// A run of the tennis racket that would take hours, started in the background (its
/// trajectory would be 30 GB, so it says `--large-output`; the tests end it long before).
#[cfg(unix)]
fn long_run(dir: &Path, out: &Path) -> std::process::Child {
    let path = dir.join("long.toml");
    let text = std::fs::read_to_string(scene("tennis_racket.toml"))
        .unwrap()
        .replace("end_time = 20.0", "end_time = 1.0e6")
        .replace("max_steps = 1_000_000", "max_steps = 1_000_000_000");
    std::fs::write(&path, text).unwrap();
    child::spawn_run_with(&path, out, &["--large-output"])
}

/// Waits until `out/trajectory.csv` holds at least `lines` lines.
#[cfg(unix)]
fn wait_for_rows(child: &mut std::process::Child, out: &Path, lines: usize) {
    let start = std::time::Instant::now();
    loop {
        let text = std::fs::read_to_string(out.join("trajectory.csv")).unwrap_or_default();
        if text.lines().count() >= lines {
            return;
        }
        if let Some(status) = child.try_wait().unwrap() {
            let mut stderr = String::new();
            let _ = std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut stderr);
            panic!("the run ended before its rows: {status}, {stderr}");
        }
        assert!(start.elapsed().as_secs() < 120, "no rows after two minutes");
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
}

/// The rows of a trajectory that may end in a line cut short: every line that ends in a
/// newline must be a whole row of numbers; what follows the last newline, if anything, is
/// the cut line, returned apart.
#[cfg(unix)]
fn complete_rows(out: &Path) -> (Vec<Vec<f64>>, String) {
    let text = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let end = text.rfind('\n').map_or(0, |i| i + 1);
    let (whole, cut) = text.split_at(end);
    let mut lines = whole.lines();
    let fields = lines.next().unwrap().split(',').count();
    let rows: Vec<Vec<f64>> = lines
        .map(|line| {
            let row: Vec<f64> = line
                .split(',')
                .map(|x| x.parse().unwrap_or_else(|_| panic!("`{x}` in `{line}`")))
                .collect();
            assert_eq!(
                row.len(),
                fields,
                "an incomplete row before the end: {line}"
            );
            row
        })
        .collect();
    assert!(cut.split(',').count() <= fields, "{cut}");
    (rows, cut.to_owned())
}

#[cfg(unix)]
#[test]
fn ctrl_c_or_sigterm_end_a_run_with_every_row_its_summary_and_plots() {
    for (signal, code, name) in [
        (libc::SIGINT, 130, "sigint"),
        (libc::SIGTERM, 143, "sigterm"),
    ] {
        let dir = folder(name);
        let out = dir.join("out");
        let mut child = long_run(&dir, &out);
        wait_for_rows(&mut child, &out, 200);
        let pid = libc::pid_t::try_from(child.id()).unwrap();
        // SAFETY: kill(2) on the child's own pid, which has not been waited for yet.
        assert_eq!(unsafe { libc::kill(pid, signal) }, 0);
        let status = child::wait_for_exit(&mut child);
        let stderr = child::stderr(&mut child);
        assert_eq!(status.code(), Some(code), "{name}: {stderr}");
        assert!(stderr.contains("interrupted by"), "{stderr}");
        // A clean end: the file ends with a whole row, and the summary is its.
        let (rows, cut) = complete_rows(&out);
        assert!(
            cut.is_empty(),
            "{name}: a cut line after a clean end: {cut}"
        );
        assert!(rows.len() >= 199, "{name}: {} rows", rows.len());
        let last = rows.last().unwrap();
        let s = summary(&out);
        assert_eq!(s["interrupted"], true, "{name}");
        assert!(s["error"].is_null(), "{name}");
        assert_eq!(s["final_time"].as_f64(), Some(last[0]), "{name}");
        assert_eq!(s["final_state"]["q"].as_f64(), Some(last[5]), "{name}");
        check_svgs(&out, &["state.svg", "attitude.svg", "polhode.svg"]);
    }
}

#[cfg(unix)]
#[test]
fn a_killed_run_leaves_every_complete_row_readable() {
    let dir = folder("sigkill");
    let out = dir.join("out");
    let mut child = long_run(&dir, &out);
    wait_for_rows(&mut child, &out, 200);
    // SIGKILL: no handler runs, nothing is flushed. What the file holds was handed to it
    // whole, so every line that ends in a newline is a complete row; at most the last line
    // can be cut (by a write the kernel cut short), and then it has no newline.
    child.kill().unwrap();
    let status = child.wait().unwrap();
    assert!(!status.success());
    let (rows, cut) = complete_rows(&out);
    assert!(rows.len() >= 199, "{} rows", rows.len());
    assert!(rows.windows(2).all(|w| w[1][0] > w[0][0]));
    if !cut.is_empty() {
        eprintln!("the kill cut the last line: {cut}");
    }
    assert!(!out.join("summary.json").exists());
}

/// Every SVG in `out` (and its subfolders) parses as XML, and its text holds none of the
/// characters XML forbids.
fn every_svg_is_xml(out: &Path) -> usize {
    let mut svgs = 0;
    for entry in std::fs::read_dir(out).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            svgs += every_svg_is_xml(&path);
        } else if path.extension().is_some_and(|e| e == "svg") {
            let text = std::fs::read_to_string(&path).unwrap();
            roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            svgs += 1;
        }
    }
    svgs
}

/// `text` without its `[[manoeuvre]]` tables after the first (and their subtables).
fn first_manoeuvre_only(text: &str) -> String {
    let (mut seen, mut dropping, mut kept) = (0, false, String::new());
    for line in text.lines() {
        let line_start = line.trim_start();
        if line_start.starts_with("[[manoeuvre]]") {
            seen += 1;
            dropping = seen > 1;
        } else if line_start.starts_with('[') && !line_start.starts_with("[manoeuvre.") {
            dropping = false;
        }
        if !dropping {
            kept.push_str(line);
            kept.push('\n');
        }
    }
    kept
}

#[test]
fn titles_with_control_characters_are_written_safely_everywhere() {
    // A bell, a line break, a terminal escape, XML's own specials and a noncharacter.
    let title = r#"title = "Bell \u0007, line\nbreak, \u001b[31mred <&> \"quoted\" \uFFFF""#;
    let exact = "Bell \u{7}, line\nbreak, \u{1b}[31mred <&> \"quoted\" \u{ffff}";
    let dir = folder("control_title");
    // Every registered kind's example scene (a scene of manoeuvres cut to its first), the
    // pendulum's as a sweep, and the tennis racket: every writer of a title.
    let examples = eom::kinds::REGISTRY.iter().map(|kind| kind.example);
    let names: Vec<&str> = std::iter::once("tennis_racket.toml")
        .chain(examples)
        .collect();
    assert!(names.contains(&"pendulum.toml"), "{names:?}");
    for name in names {
        let text = std::fs::read_to_string(scene(name)).unwrap();
        let old_title = text.lines().find(|l| l.starts_with("title = ")).unwrap();
        let mut text =
            (text.replacen(old_title, title, 1)).replacen("end_time = 20.0", "end_time = 1.0", 1);
        if name == "pendulum.toml" {
            text += "\n[sweep]\n\"body.mass\" = [1.0, 2.0]\n";
        }
        let text = first_manoeuvre_only(&text);
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        let out = dir.join(name.trim_end_matches(".toml"));
        let output = eom_run(&path, &out);
        let stdout = String::from_utf8_lossy(&output.stdout);
        assert!(
            output.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&output.stderr)
        );
        // The terminal is shown the title, not driven by it.
        assert!(!stdout.contains(['\u{7}', '\u{1b}']), "{name}: {stdout:?}");
        assert!(every_svg_is_xml(&out) >= 2, "{name}: too few plots");
        // summary.json is valid JSON and keeps the title exactly; every CSV reads.
        let summaries = if name == "pendulum.toml" {
            vec![out.join("case-0000"), out.join("case-0001")]
        } else {
            vec![out.clone()]
        };
        for folder in summaries {
            assert_eq!(summary(&folder)["title"], exact, "{name}");
        }
        for csv in ["trajectory.csv", "sweep.csv"] {
            if out.join(csv).exists() {
                let text = std::fs::read_to_string(out.join(csv)).unwrap();
                let fields = text.lines().next().unwrap().split(',').count();
                assert!(
                    text.lines().all(|l| l.split(',').count() == fields),
                    "{csv}"
                );
            }
        }
    }
    // The tennis racket's state plot shows the title with its characters made visible.
    let state = std::fs::read_to_string(dir.join("tennis_racket/state.svg")).unwrap();
    let document = roxmltree::Document::parse(&state).unwrap();
    // (The caption goes on to name the series left out for being zero throughout.)
    let shown = "Bell ␇, line break, ␛[31mred <&> \"quoted\" \u{fffd}: state";
    assert!(
        document
            .descendants()
            .any(|n| n.text().is_some_and(|t| t.trim().starts_with(shown))),
        "no caption {shown:?}"
    );
}

#[test]
fn the_tossed_box_stops_where_it_has_fallen_ten_metres_and_says_so() {
    let out = folder("tossed_box");
    let output = run_scene("tossed_box.toml", &out);
    let stdout = String::from_utf8_lossy(&output.stdout);
    // Thrown up at 4 m/s from z = 0, Z down: z = −4t + ½gt² = 10 at t = (4 + √(16 + 20g))/g.
    let g: f64 = 9.81;
    let exact = (4.0 + (16.0 + 20.0 * g).sqrt()) / g;
    let s = summary(&out);
    assert_eq!(s["stop_when"], "z > 10");
    let stopped = s["stopped_at"].as_f64().unwrap();
    assert!((stopped - exact).abs() < 1e-12, "{stopped} against {exact}");
    assert_eq!(s["final_time"].as_f64(), Some(stopped));
    // The terminal says it to six digits; summary.json keeps every one.
    let said = format!(
        "stopped at t = {} s, where `z > 10` first held",
        eom::Short(exact)
    );
    assert!(stdout.contains(&said), "{said}: {stdout}");
    let (header, rows) = trajectory(&out);
    let t = column(&header, &rows, "t");
    assert_eq!(*t.last().unwrap(), stopped);
    // Free of moments about G, the box flips as the racket does, and T + V is kept.
    assert!(s["energy_drift"].as_f64().unwrap() < 1e-12);
    assert!(!sign_changes(&t, &column(&header, &rows, "q")).is_empty());
    check_svgs(
        &out,
        &[
            "state.svg",
            "attitude.svg",
            "track.svg",
            "energy.svg",
            "polhode.svg",
            "profile.svg",
        ],
    );
}

#[test]
fn the_thruster_burn_yaws_the_satellite_by_the_moment_of_its_offset() {
    let out = folder("thruster_burn");
    run_scene("thruster_burn.toml", &out);
    let final_state = &summary(&out)["final_state"];
    // 2 N at 0.1 m to starboard for 2 s: ṙ = −0.2/0.6 while it burns, so r = −2/3 rad/s
    // after it, exactly (the run is cut at the switches); nothing else turns.
    let r = final_state["r"].as_f64().unwrap();
    assert!((r + 2.0 / 3.0).abs() < 1e-12, "r = {r}");
    for name in ["p", "q", "w"] {
        assert_eq!(final_state[name].as_f64(), Some(0.0), "{name}");
    }
    let (header, rows) = trajectory(&out);
    let u = column(&header, &rows, "u");
    // At rest until the burn starts at 1 s (row 100), pushed from then on.
    assert!(u[..=100].iter().all(|u| *u == 0.0) && u[101] > 0.0);
    check_svgs(&out, &["state.svg", "attitude.svg", "track.svg"]);
}

/// A path the run prints for the user to paste is quoted where a shell would split it.
#[test]
fn printed_paths_paste_into_a_shell() {
    let dir = folder("pasteable");
    let out = dir.join("my runs");
    let output = eom_command()
        .args(["run", scene("pendulum.toml").to_str().unwrap(), "--out"])
        .arg(&out)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{stdout}");
    let quoted = format!("'{}/view.html'", out.display());
    assert!(
        stdout.contains(&format!("open {quoted} in a browser")),
        "{stdout}"
    );
    assert!(
        stdout.contains(&format!("wrote into '{}':", out.display())),
        "{stdout}"
    );
}

/// A run that takes every step `integrator.max_steps` allows fails with its time said once,
/// finite and short, for a body, a ship and an aircraft.
#[test]
fn a_run_out_of_steps_says_when_once() {
    let dir = folder("out_of_steps");
    for (name, method) in [
        ("pendulum.toml", "method = \"dop853\""),
        ("mariner.toml", "method = \"dopri5\""),
        ("navion.toml", "method = \"dopri5\""),
    ] {
        let text = std::fs::read_to_string(scene(name)).unwrap();
        assert!(text.contains(method), "{name}");
        let path = dir.join(name);
        let limited = text.replacen(method, &format!("{method}\nmax_steps = 40"), 1);
        std::fs::write(&path, limited).unwrap();
        let (code, stderr) = run_failing(&path, &dir.join(name.replace(".toml", "")));
        assert_eq!(code, 5, "{name}: {stderr}");
        assert!(
            stderr.contains("`integrator.max_steps`"),
            "{name}: {stderr}"
        );
        // The time once (the integrator's own "exceeded at t = …" repeated it), finite, and
        // as a reader writes it (the aircraft's had every digit: 8.988855340171176 s).
        assert!(!stderr.contains("NaN"), "{name}: {stderr}");
        assert!(!stderr.contains("exceeded at"), "{name}: {stderr}");
        let longest = (stderr.split(|c: char| !c.is_ascii_digit() && c != '.'))
            .map(|number| number.chars().filter(char::is_ascii_digit).count())
            .max();
        assert!(longest <= Some(9), "{name}: {stderr}");
    }
}
