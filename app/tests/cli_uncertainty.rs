//! `eom run` of a scene with an `[uncertainty]`: a Monte Carlo run whole and as shards merged
//! gives the same table, statistics and plots, byte for byte; a case is the same whatever
//! else runs; and a table that cannot be used is refused by its key before anything runs.

use eom_test_support::cli::{eom, folder, run_into as run, scene_arg, succeeded};
use std::path::{Path, PathBuf};

/// The Mariner's turning circle Monte Carlo, shortened to `cases` cases, written into `dir`.
fn turning_scene(dir: &Path, cases: usize) -> PathBuf {
    let text = std::fs::read_to_string(scene_arg("mariner_turning_uncertainty.toml")).unwrap();
    assert!(text.contains("cases = 100000"));
    let text = text.replace("cases = 100000", &format!("cases = {cases}"));
    let path = dir.join("turns.toml");
    std::fs::write(&path, text).unwrap();
    path
}

/// What a Monte Carlo writes from its table, the same bytes whole and merged from shards.
const FROM_THE_TABLE: [&str; 4] = [
    "uncertainty.csv",
    "uncertainty.json",
    "distributions.svg",
    "pass_rates.svg",
];

/// Asserts that `whole` and `merged` hold [`FROM_THE_TABLE`] the same bytes (`what` the run).
fn assert_same_files(whole: &Path, merged: &Path, what: &str) {
    for file in FROM_THE_TABLE {
        assert!(
            read(whole.join(file)) == read(merged.join(file)),
            "{what}: {file} differs"
        );
    }
}

fn read(path: PathBuf) -> String {
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn a_monte_carlo_run_whole_or_in_shards_gives_the_same_numbers() {
    let dir = folder("whole_and_shards");
    let scene = turning_scene(&dir, 30);
    let whole = dir.join("whole");
    let report = run(&scene, &whole, None);
    // Every figure's spread and each verdict's rate with its interval are reported.
    assert!(report.contains("30 of 30 cases ran"), "{report}");
    assert!(
        report.contains("turning_circle_35/tactical_diameter_m"),
        "{report}"
    );
    assert!(report.contains("95% Wilson interval"), "{report}");
    let sharded = dir.join("sharded");
    let shards = ["0/3", "1/3", "2/3"].map(|s| run(&scene, &sharded, Some(s)));
    assert!(shards[1].contains("shard 1/3: 10 of them"), "{}", shards[1]);
    assert!(!sharded.join("uncertainty.json").exists());
    let merged = succeeded(&eom(&["sweep-merge", sharded.to_str().unwrap()]));
    assert!(merged.contains("merged 3 shards, 30 cases"), "{merged}");
    assert_same_files(&whole, &sharded, "30 turns");
    // The statistics the report printed are those of uncertainty.json.
    let json: serde_json::Value =
        serde_json::from_str(&read(whole.join("uncertainty.json"))).unwrap();
    assert_eq!(json["cases"], 30);
    let advance = &json["verdicts"][0];
    assert_eq!(advance["name"], "advance");
    let (passed, judged) = (
        advance["passed"].as_u64().unwrap(),
        advance["judged"].as_u64().unwrap(),
    );
    assert_eq!(judged, 30);
    let line = report
        .lines()
        .find(|l| l.trim_start().starts_with("advance "))
        .unwrap();
    assert!(line.contains(&format!(" {passed} ")), "{line}");
    // A figure read only at a steady turn, which the stop at 200° never reaches, is said to
    // be missing rather than given as a number.
    let steady = (json["figures"].as_array().unwrap().iter())
        .find(|f| f["name"] == "turning_circle_35/steady_turning_radius_m")
        .unwrap();
    assert_eq!(
        (steady["count"].as_u64(), steady["missing"].as_u64()),
        (Some(0), Some(30))
    );
    assert!(steady["mean"].is_null());
}

/// Every registered kind's example scene as a Monte Carlo of six cases over its integrator's
/// setting (its fixed step, or its relative tolerance, each ±30 % uniform): run whole and as
/// three shards merged, the table, the statistics and both plots the same bytes, and every
/// case run.
#[test]
fn every_kinds_monte_carlo_runs_whole_or_in_shards_alike() {
    for kind in eom::kinds::REGISTRY {
        let dir = folder(&format!("every_kind_{}", kind.name));
        let text = read(PathBuf::from(scene_arg(kind.example)));
        let table: toml::Table = toml::from_str(&text).unwrap();
        let integrator = table["integrator"].as_table().unwrap();
        let key = match integrator.contains_key("step") {
            true => "integrator.step",
            false => "integrator.rtol",
        };
        let text = format!(
            "{text}\n[uncertainty]\ncases = 6\nseed = 7\n\n[uncertainty.vary]\n\
             \"{key}\" = {{ distribution = \"uniform\", relative = 0.3 }}\n"
        );
        let scene = dir.join("scene.toml");
        std::fs::write(&scene, text).unwrap();
        let whole = dir.join("whole");
        let report = run(&scene, &whole, None);
        assert!(
            report.contains("6 of 6 cases ran"),
            "{}: {report}",
            kind.name
        );
        let sharded = dir.join("sharded");
        for shard in ["0/3", "1/3", "2/3"] {
            run(&scene, &sharded, Some(shard));
        }
        succeeded(&eom(&["sweep-merge", sharded.to_str().unwrap()]));
        assert_same_files(&whole, &sharded, kind.name);
    }
}

/// Case k of a Monte Carlo of 12 cases is case k of one of 30: its stream is its own.
#[test]
fn a_case_is_the_same_in_a_smaller_monte_carlo() {
    let dir = folder("smaller");
    let (small, large) = (dir.join("small"), dir.join("large"));
    std::fs::create_dir_all(&small).unwrap();
    std::fs::create_dir_all(&large).unwrap();
    run(&turning_scene(&small, 12), &small.join("out"), None);
    run(&turning_scene(&large, 30), &large.join("out"), None);
    let lines = |dir: &Path| -> Vec<String> {
        read(dir.join("out/uncertainty.csv"))
            .lines()
            .map(String::from)
            .collect()
    };
    let (small, large) = (lines(&small), lines(&large));
    assert_eq!(small.len(), 13);
    assert_eq!(small[..], large[..13]);
}

#[test]
fn an_uncertainty_that_cannot_be_used_is_refused_by_its_key() {
    let dir = folder("refused");
    let text = read(scene_arg("mariner_turning_uncertainty.toml").into());
    let cases = [
        (
            r#""hydrodynamics.coefficients.*" ="#,
            r#""hydrodynamics.coefficient.*" ="#,
            r#"uncertainty.vary."hydrodynamics.coefficient.*""#,
        ),
        ("truncate = 3.0", "truncate = 0.0", "truncate = 0"),
        ("cases = 100000", "cases = 0", "uncertainty.cases"),
        ("seed = 2026", "seed = -1", "uncertainty.seed"),
        (
            "[uncertainty]",
            "[sweep]\n\"body.length\" = [160.0, 170.0]\n\n[uncertainty]",
            "not both",
        ),
    ];
    for (from, to, said) in cases {
        assert!(text.contains(from), "{from}");
        let path = dir.join("bad.toml");
        std::fs::write(&path, text.replacen(from, to, 1)).unwrap();
        let output = eom(&[
            "run",
            path.to_str().unwrap(),
            "--out",
            dir.join("out").to_str().unwrap(),
        ]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(3), "{to}: {stderr}");
        assert!(stderr.contains(said), "{to}: {stderr}");
        assert!(!dir.join("out").exists(), "{to}: nothing is written");
    }
}

/// `eom run SCENE --out OUT` of `text`, written as `scene.toml` into `dir`.
fn run_text(dir: &Path, text: &str) -> std::process::Output {
    let path = dir.join("scene.toml");
    std::fs::write(&path, text).unwrap();
    eom(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ])
}

#[test]
fn a_law_that_contradicts_a_fixed_number_is_refused_before_any_case_runs() {
    // REMUS's mass is checked against its weight (W/M within the Earth's gravity, to the
    // rounding of the two numbers as written): varied alone by ±2 %, most cases would
    // contradict it, each for the same reason.
    let dir = folder("contradicting");
    let text = read(scene_arg("remus100.toml").into())
        + "\n[uncertainty]\ncases = 200\nseed = 1\n\n[uncertainty.vary]\n\
           \"body.mass\" = { distribution = \"uniform\", relative = 0.02 }\n";
    let output = run_text(&dir, &text);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(3), "{stderr}");
    for said in [
        "uncertainty.vary",
        "`body.mass` varied alone",
        "`body.weight`",
    ] {
        assert!(stderr.contains(said), "{said}: {stderr}");
    }
    assert!(!dir.join("out").exists(), "nothing is written: {stderr}");
}

#[test]
fn cases_that_fail_are_counted_by_reason_and_the_command_exits_5() {
    // The pendulum's h drawn on [−0.2, 1] m: a sixth of the draws are below zero, and those
    // above √(I₀/M) = 0.816 m make I₀ less than Mh² (about the pivot, I₀ = I_G + Mh²); both
    // quartiles (0.1 and 0.7 m) are a pendulum the scene takes, so the scene is not refused.
    let dir = folder("failing_cases");
    let text = read(scene_arg("pendulum.toml").into()).replace("end_time = 20.0", "end_time = 1.0")
        + "\n[uncertainty]\ncases = 48\nseed = 3\n\n[uncertainty.vary]\n\
           \"body.h\" = { distribution = \"uniform\", low = -0.2, high = 1.0 }\n";
    let output = run_text(&dir, &text);
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(5), "{stdout}\n{stderr}");
    assert!(stderr.contains("cases failed; "), "{stderr}");
    // Every file is written, the cases that ran counted.
    let report = read(dir.join("out/uncertainty.json"));
    let report: serde_json::Value = serde_json::from_str(&report).unwrap();
    let failed = report["failed"].as_array().unwrap().len();
    let reasons = report["failure_reasons"].as_array().unwrap();
    let counted: u64 = reasons.iter().map(|r| r["count"].as_u64().unwrap()).sum();
    assert_eq!(counted as usize, failed);
    assert_eq!(reasons.len(), 2, "{reasons:?}");
    assert!(failed > 0 && failed < 48, "{failed}");
    // The terminal says each reason once, with its count, not each case.
    let said = stdout.lines().filter(|l| l.contains("failed")).count();
    assert!(said <= 2, "{stdout}");
    assert!(
        stdout.contains("cases failed so, the first case"),
        "{stdout}"
    );
}
