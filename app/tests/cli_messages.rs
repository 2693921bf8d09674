//! What `eom` says when a scene, a command or a value is not what it serves: the command says
//! what it serves and exits 2, numbers in messages are short, an overflow is named as one, an
//! echoed line is cut, a huge output is asked for explicitly; and sweeps that spread over
//! shards, say each case's values and merge into one table.

use eom_test_support::cli::{eom, folder, scene_arg};
use std::path::Path;

/// The exit code and standard error of a command that must fail.
fn failing(args: &[&str]) -> (i32, String) {
    let output = eom(args);
    assert!(!output.status.success(), "{args:?} succeeded");
    let code = output.status.code().unwrap_or(-1);
    (code, String::from_utf8_lossy(&output.stderr).into_owned())
}

/// A pendulum scene edited by `edit`, written into `dir`.
fn pendulum(dir: &Path, file: &str, edit: impl Fn(String) -> String) -> String {
    let text = std::fs::read_to_string(scene_arg("pendulum.toml")).unwrap();
    let path = dir.join(file);
    std::fs::write(&path, edit(text)).unwrap();
    path.display().to_string()
}

#[test]
fn a_command_on_a_scene_it_does_not_serve_says_what_it_serves() {
    let dir = folder("serves");
    let swept = pendulum(&dir, "swept.toml", |t| {
        t + "\n[sweep]\n\"body.mass\" = [1.0, 2.0]\n"
    });
    let (code, stderr) = failing(&["tradeoff", &swept]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("has a [sweep]"), "{stderr}");
    let (code, stderr) = failing(&["linear", &swept]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("eom linear linearises one scene"),
        "{stderr}"
    );
}

#[test]
fn a_shard_without_a_sweep_or_malformed_is_a_usage_error() {
    let dir = folder("shard");
    let out = dir.join("out").display().to_string();
    let plain = scene_arg("pendulum.toml");
    for shard in ["0/2", "5", "2/2", "a/b"] {
        let (code, stderr) = failing(&["run", &plain, "--out", &out, "--shard", shard]);
        assert_eq!(code, 2, "--shard {shard}: {stderr}");
    }
    assert!(!dir.join("out").exists(), "a refused run made its folder");
}

#[test]
fn numbers_in_messages_have_at_most_six_significant_digits() {
    let dir = folder("digits");
    let out = dir.join("out").display().to_string();
    let tiny = pendulum(&dir, "tiny.toml", |t| {
        t.replace("every = 0.005", "every = 1e-300")
    });
    let (code, stderr) = failing(&["run", &tiny, "--out", &out]);
    assert_eq!(code, 3, "{stderr}");
    assert!(stderr.contains("gives 2e301 rows"), "{stderr}");
    // No run of more than six digits anywhere in the message.
    let mut digits = 0;
    for c in stderr.chars() {
        digits = if c.is_ascii_digit() { digits + 1 } else { 0 };
        assert!(digits <= 7, "{stderr}");
    }
}

#[test]
fn an_inertia_tensor_too_large_for_f64_is_named_as_overflow() {
    let dir = folder("overflow");
    let text = std::fs::read_to_string(scene_arg("tennis_racket.toml"))
        .unwrap()
        .replace(
            "inertia = [[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 4.5]]",
            "inertia = [[1e308, 0.0, 0.0], [0.0, 1e308, 0.0], [0.0, 0.0, 1e308]]",
        );
    assert!(text.contains("1e308"));
    let path = dir.join("huge.toml");
    std::fs::write(&path, text).unwrap();
    let out = dir.join("out").display().to_string();
    let (code, stderr) = failing(&["run", path.to_str().unwrap(), "--out", &out]);
    assert_eq!(code, 3, "{stderr}");
    assert!(stderr.contains("too large to check in f64"), "{stderr}");
    assert!(!stderr.contains("products of inertia"), "{stderr}");
}

#[test]
fn a_long_line_is_echoed_cut() {
    let dir = folder("nested");
    let path = dir.join("nested.toml");
    std::fs::write(
        &path,
        format!("title = \"x\"\nbad = {}\n", "[".repeat(200_000)),
    )
    .unwrap();
    let out = dir.join("out").display().to_string();
    let (code, stderr) = failing(&["run", path.to_str().unwrap(), "--out", &out]);
    assert_eq!(code, 3, "{stderr}");
    assert!(stderr.len() < 2_000, "{} bytes on stderr", stderr.len());
}

#[test]
fn a_huge_output_needs_its_own_flag_and_a_loose_tolerance_warns() {
    let dir = folder("huge");
    let out = dir.join("out").display().to_string();
    let dense = pendulum(&dir, "dense.toml", |t| {
        t.replace("every = 0.005", "every = 1e-6")
    });
    let (code, stderr) = failing(&["run", &dense, "--out", &out, "--force"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("MB of trajectory; pass --large-output"),
        "{stderr}"
    );
    assert!(!dir.join("out").exists());

    let loose = pendulum(&dir, "loose.toml", |t| {
        t.replace("rtol = 1e-11", "rtol = 10.0")
            .replace("end_time = 20.0", "end_time = 2.0")
    });
    let output = eom(&["run", &loose, "--out", &out]);
    assert!(output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("integrator.rtol = 1e1 is looser than 1e-3"),
        "{stderr}"
    );
    let summary = std::fs::read_to_string(dir.join("out/summary.json")).unwrap();
    assert!(summary.contains("is looser than"), "{summary}");
}

/// `sweep.csv`'s lines without the wall time, which differs between runs.
fn table_lines(path: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(path).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let wall = header.iter().position(|h| *h == "wall_seconds").unwrap();
    text.lines()
        .map(|line| {
            let mut fields: Vec<&str> = line.split(',').collect();
            fields.remove(wall);
            fields.join(",")
        })
        .collect()
}

#[test]
fn a_sweep_says_each_cases_values_and_its_shards_merge_into_the_whole_table() {
    let dir = folder("sweep");
    let path = pendulum(&dir, "sweep.toml", |t| {
        t.replace("end_time = 20.0", "end_time = 10.0")
            + "\n[sweep]\n\"initial.theta_deg\" = [10.0, 90.0, 170.0]\n\"body.mass\" = [1.0, 3.0]\n"
    });
    let whole = dir.join("whole");
    assert!(
        eom(&["run", &path, "--out", whole.to_str().unwrap()])
            .status
            .success()
    );
    let lines = table_lines(&whole.join("sweep.csv"));
    assert!(
        lines[0].contains(",energy_drift,period_s,final_theta"),
        "{}",
        lines[0]
    );
    // Columns: case, body.mass, initial.theta_deg, variant, steps, rhs_evals, energy_drift,
    // period_s, …; case 0 is the 10° swing of the 1 kg body. Its period is the small-angle
    // 4.27 within its 10° correction (0.19 %). is the small-angle 4.27 within its 10° correction.
    let period: f64 = lines[1].split(',').nth(7).unwrap().parse().unwrap();
    let small_angle = 2.0 * std::f64::consts::PI * (2.0f64 / (1.0 * 9.81 * 0.5)).sqrt();
    assert!(
        (period / small_angle - 1.0).abs() < 0.01,
        "{period} against {small_angle}"
    );
    let summary: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(whole.join("case-0004/summary.json")).unwrap(),
    )
    .unwrap();
    assert_eq!(summary["case"]["index"], 4);
    assert_eq!(summary["case"]["values"]["body.mass"], 3.0);
    assert_eq!(summary["case"]["values"]["initial.theta_deg"], 90.0);
    let state = std::fs::read_to_string(whole.join("case-0004/state.svg")).unwrap();
    assert!(
        state.contains("body.mass = 3.0, initial.theta_deg = 90.0"),
        "the plot's title names the case"
    );

    let sharded = dir.join("sharded");
    let sharded_out = sharded.to_str().unwrap();
    for shard in ["0/4", "2/4", "1/4"] {
        assert!(
            eom(&["run", &path, "--out", sharded_out, "--shard", shard])
                .status
                .success()
        );
    }
    let (code, stderr) = failing(&["sweep-merge", sharded_out]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("shard 3 of 4 not yet in"), "{stderr}");
    assert!(
        eom(&["run", &path, "--out", sharded_out, "--shard", "3/4"])
            .status
            .success()
    );
    let merged = eom(&["sweep-merge", sharded_out]);
    assert!(
        merged.status.success(),
        "{}",
        String::from_utf8_lossy(&merged.stderr)
    );
    assert_eq!(table_lines(&sharded.join("sweep.csv")), lines);
}

/// A bad flag value exits 2 and names the flag as the user typed it (`--pivot-to-cg`, not the
/// field `pivot_to_cg`); so does a pair of values that cannot go together.
#[test]
fn a_bad_flag_value_exits_2_naming_the_flag() {
    let swing = |extra: &[&str]| {
        let mut args = vec!["swing", "--period", "1.2", "--mass", "2.0"];
        args.extend_from_slice(extra);
        failing(&args)
    };
    for (flag, value) in [
        ("--pivot-to-cg", "-1"),
        ("--pivot-to-cg", "nan"),
        ("--gravity", "0"),
        ("--amplitude-deg", "190"),
    ] {
        let mut extra = vec![flag, value];
        if flag != "--pivot-to-cg" {
            extra.extend(["--pivot-to-cg", "0.2"]);
        }
        let (code, stderr) = swing(&extra);
        assert_eq!(code, 2, "{flag} {value}: {stderr}");
        assert!(stderr.contains(flag), "{flag} {value}: {stderr}");
    }
    let (code, stderr) = swing(&["--pivot-to-cg", "5.0"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("--period") && stderr.contains("--pivot-to-cg"),
        "{stderr}"
    );
}

/// A full disk is a failure to write (exit 4), for a catalog scene, a ship and a vehicle alike:
/// the write error reaches the exit code as the I/O error it is. The disk is a 64 KiB tmpfs,
/// which needs the right to mount one (CI runs as root); without it the test says so and
/// checks nothing.
#[test]
fn a_full_disk_exits_4() {
    let dir = folder("full_disk");
    let disk = dir.join("disk");
    std::fs::create_dir_all(&disk).unwrap();
    let mounted = std::process::Command::new("mount")
        .args(["-t", "tmpfs", "-o", "size=64k", "tmpfs"])
        .arg(&disk)
        .output()
        .is_ok_and(|o| o.status.success());
    if !mounted {
        eprintln!("a_full_disk_exits_4: cannot mount a tmpfs here; nothing checked");
        return;
    }
    let mut codes = Vec::new();
    for scene in ["tennis_racket.toml", "mariner.toml", "remus100.toml"] {
        let out = disk.join(scene);
        let (code, stderr) = failing(&["run", &scene_arg(scene), "--out", out.to_str().unwrap()]);
        codes.push((scene, code, stderr));
        let _ = std::fs::remove_dir_all(&out);
    }
    let _ = std::process::Command::new("umount").arg(&disk).output();
    for (scene, code, stderr) in codes {
        assert_eq!(code, 4, "{scene}: {stderr}");
        assert!(stderr.contains("No space left"), "{scene}: {stderr}");
    }
}

/// `eom new` without a family is a usage error that lists the families it takes.
#[test]
fn eom_new_without_a_family_lists_the_families() {
    let (code, stderr) = failing(&["new"]);
    assert_eq!(code, 2, "{stderr}");
    for family in ["pendulum", "spatial", "top", "ship", "vehicle"] {
        assert!(stderr.contains(family), "{family}: {stderr}");
    }
}
