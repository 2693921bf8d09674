//! The output folder end to end: two runs into one folder cannot both write, the shards of one
//! sweep can, and a folder eom did not write (a user's, or `/` through a link) is left as it
//! was.

use eom_test_support::cli::{eom, eom_command, folder, scene, succeeded};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn run_into(scene: &Path, out: &Path, extra: &[&str]) -> Command {
    let mut command = eom_command();
    command
        .args([
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .args(extra);
    command
}

/// Every file under `dir`, with its bytes, sorted: what a refused run must leave unchanged.
fn contents(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut all: Vec<(PathBuf, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| (e.path(), std::fs::read(e.path()).unwrap_or_default()))
        .collect();
    all.sort();
    all
}

/// The tennis racket and the free precession, each writing 10 001 rows of 17 fields.
fn two_scenes(dir: &Path) -> [PathBuf; 2] {
    ["tennis_racket.toml", "free_precession.toml"].map(|name| {
        let text = std::fs::read_to_string(scene(name)).unwrap();
        let text = text
            .lines()
            .map(|line| match line.trim_start().starts_with("end_time") {
                true => "end_time = 20.0",
                false => line,
            })
            .filter(|line| !line.trim_start().starts_with("every"))
            .collect::<Vec<_>>()
            .join("\n");
        let text = text.replace("[output]", "") + "\n[output]\nevery = 0.002\n";
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        path
    })
}

/// Checks that `trajectory.csv` in `out` is one whole run: every row as wide as the header,
/// 10 001 rows, times increasing.
fn assert_well_formed(out: &Path) {
    let text = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let mut lines = text.lines();
    let width = lines.next().unwrap().split(',').count();
    let mut previous = f64::NEG_INFINITY;
    let mut rows = 0;
    for line in lines {
        let fields: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        assert_eq!(fields.len(), width, "a malformed row: {line}");
        assert!(fields[0] > previous, "times out of order at {line}");
        previous = fields[0];
        rows += 1;
    }
    assert_eq!(rows, 10_001);
}

#[test]
fn of_two_runs_started_at_once_into_one_folder_one_runs_and_the_other_is_refused() {
    let dir = folder("race");
    let scenes = two_scenes(&dir);
    let mut busy = 0;
    for trial in 0..20 {
        let out = dir.join(format!("trial-{trial}"));
        let children: Vec<_> = scenes
            .iter()
            .map(|scene| {
                run_into(scene, &out, &[])
                    .stdout(Stdio::null())
                    .stderr(Stdio::piped())
                    .spawn()
                    .unwrap()
            })
            .collect();
        let outputs: Vec<Output> = children
            .into_iter()
            .map(|c| c.wait_with_output().unwrap())
            .collect();
        let ran: Vec<usize> = (0..2).filter(|&i| outputs[i].status.success()).collect();
        assert_eq!(ran.len(), 1, "trial {trial}: {outputs:?}");
        let refused = &outputs[1 - ran[0]];
        let message = String::from_utf8_lossy(&refused.stderr);
        assert_eq!(refused.status.code(), Some(4), "{message}");
        // Started at once, the second finds the first writing; started late, it finds the
        // first's finished run. Either way it writes nothing.
        let by_lock = message.contains("is being written by another eom run (process ");
        assert!(
            by_lock || message.contains("already holds a run"),
            "{message}"
        );
        busy += usize::from(by_lock);
        assert_well_formed(&out);
        let summary = std::fs::read_to_string(out.join("summary.json")).unwrap();
        let survivor = scenes[ran[0]].display().to_string();
        assert!(summary.contains(&survivor), "trial {trial}");
    }
    eprintln!("{busy} of 20 trials met the first run's lock, the rest its finished run");
    // The lock itself must have been met, not only the finished run.
    assert!(busy >= 10, "only {busy} of 20 trials met the lock");
}

#[test]
fn the_shards_of_one_sweep_run_side_by_side_into_one_folder() {
    let dir = folder("shards");
    let text = std::fs::read_to_string(scene("pendulum.toml"))
        .unwrap()
        .replace("end_time = 20.0", "end_time = 2.0")
        + "\n[sweep]\n\"initial.theta_deg\" = [10.0, 50.0, 90.0, 130.0, 170.0]\n";
    let path = dir.join("sweep.toml");
    std::fs::write(&path, &text).unwrap();
    let out = dir.join("out");
    let shards: Vec<_> = ["0/2", "1/2"]
        .iter()
        .map(|shard| {
            run_into(&path, &out, &["--shard", shard])
                .stdout(Stdio::null())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    for shard in shards {
        let output = shard.wait_with_output().unwrap();
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
    }
    for k in 0..5 {
        assert!(out.join(format!("case-{k:04}/summary.json")).exists());
    }
    let rows = |file: &str| {
        std::fs::read_to_string(out.join(file))
            .unwrap()
            .lines()
            .count()
            - 1
    };
    assert_eq!(
        rows("sweep-shard-0-of-2.csv") + rows("sweep-shard-1-of-2.csv"),
        5
    );
    // An unsharded run, or another sweep's shards, may not mix into that folder.
    let other = dir.join("other.toml");
    std::fs::write(&other, text.replace("170.0", "171.0")).unwrap();
    let refused = run_into(&other, &out, &["--shard", "0/2"])
        .output()
        .unwrap();
    assert_eq!(refused.status.code(), Some(4));
    let message = String::from_utf8_lossy(&refused.stderr);
    assert!(
        message.contains("holds the shards of another sweep"),
        "{message}"
    );
}

#[test]
fn a_users_folder_and_a_link_to_the_root_are_refused_and_nothing_is_written() {
    let dir = folder("users");
    let own = dir.join("own");
    std::fs::create_dir(&own).unwrap();
    std::fs::write(own.join("state.svg"), "<svg>my own drawing</svg>").unwrap();
    std::fs::write(own.join("notes.txt"), "mine").unwrap();
    let before = contents(&own);
    let pendulum = scene("pendulum.toml");
    let refused = run_into(&pendulum, &own, &[]).output().unwrap();
    assert_eq!(refused.status.code(), Some(4));
    let message = String::from_utf8_lossy(&refused.stderr);
    assert!(
        message.contains("is not empty and was not written by eom"),
        "{message}"
    );
    // With --force eom would write beside the user's files, but not over them.
    let forced = run_into(&pendulum, &own, &["--force"]).output().unwrap();
    assert_eq!(forced.status.code(), Some(4));
    let message = String::from_utf8_lossy(&forced.stderr);
    assert!(
        message.contains("state.svg was not written by eom, and --force replaces only eom's own"),
        "{message}"
    );
    assert_eq!(contents(&own), before);

    #[cfg(unix)]
    {
        let link = dir.join("root");
        std::os::unix::fs::symlink("/", &link).unwrap();
        let root_before = std::fs::read_dir("/").unwrap().flatten().count();
        for extra in [&[][..], &["--force"][..]] {
            let refused = run_into(&pendulum, &link, extra).output().unwrap();
            assert_eq!(refused.status.code(), Some(4));
            let message = String::from_utf8_lossy(&refused.stderr);
            assert!(
                message.contains("resolves to /, a system folder"),
                "{message}"
            );
        }
        assert!(!Path::new("/trajectory.csv").exists() && !Path::new("/.eom-lock").exists());
        assert_eq!(
            std::fs::read_dir("/").unwrap().flatten().count(),
            root_before
        );
    }
}

#[test]
fn force_replaces_an_earlier_run_whole() {
    let dir = folder("force");
    let out = dir.join("out");
    let text = std::fs::read_to_string(scene("pendulum.toml"))
        .unwrap()
        .replace("end_time = 20.0", "end_time = 1.0");
    let sweep = dir.join("sweep.toml");
    std::fs::write(
        &sweep,
        text.clone() + "\n[sweep]\n\"body.mass\" = [1.0, 2.0]\n",
    )
    .unwrap();
    let single = dir.join("single.toml");
    std::fs::write(&single, text).unwrap();
    assert!(
        run_into(&sweep, &out, &[])
            .output()
            .unwrap()
            .status
            .success()
    );
    std::fs::write(out.join("my-notes.txt"), "kept").unwrap();
    let again = run_into(&single, &out, &[]).output().unwrap();
    assert_eq!(again.status.code(), Some(4));
    assert!(String::from_utf8_lossy(&again.stderr).contains("already holds a run"));
    assert!(
        run_into(&single, &out, &["--force"])
            .output()
            .unwrap()
            .status
            .success()
    );
    // The sweep's cases and table are gone with it; the user's file stays.
    assert!(!out.join("case-0000").exists() && !out.join("sweep.csv").exists());
    assert!(out.join("trajectory.csv").exists());
    assert_eq!(
        std::fs::read_to_string(out.join("my-notes.txt")).unwrap(),
        "kept"
    );
}

/// Bare `eom` takes its folder as `eom run` takes one: it replaces an earlier default run, and
/// refuses (exit 4, nothing touched) a folder of the user's own files or another scene's run,
/// for it has no `--force` to be given.
#[test]
fn the_default_run_replaces_only_an_earlier_default_run() {
    let dir = folder("default_run");
    let out = dir.join("tennis_racket");
    let bare = || eom_command().current_dir(&dir).output().unwrap();
    // A user's own folder of that name.
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    let refused = bare();
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert_eq!(refused.status.code(), Some(4), "{stderr}");
    assert!(stderr.contains("files eom did not write"), "{stderr}");
    let entries: Vec<_> = std::fs::read_dir(&out).unwrap().collect();
    assert_eq!(entries.len(), 1, "only the user's file");
    // Another scene's run there.
    std::fs::remove_dir_all(&out).unwrap();
    let pendulum = scene("pendulum.toml");
    let pendulum = pendulum.to_str().unwrap();
    succeeded(&eom(&["run", pendulum, "--out", out.to_str().unwrap()]));
    let summary = std::fs::read_to_string(out.join("summary.json")).unwrap();
    let refused = bare();
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert_eq!(refused.status.code(), Some(4), "{stderr}");
    assert!(stderr.contains("another scene's run"), "{stderr}");
    assert_eq!(
        std::fs::read_to_string(out.join("summary.json")).unwrap(),
        summary
    );
    // Its own earlier run it replaces, and says so.
    std::fs::remove_dir_all(&out).unwrap();
    succeeded(&bare());
    let again = succeeded(&bare());
    assert!(again.contains("replacing the default run"), "{again}");
}
