//! The `eom` binary as a user runs it, and the places its tests read and write: the example
//! scenes of the repository and a fresh folder per test under the target directory.
//!
//! Cargo tells a test crate where the binary and its scratch folder are only at compile time
//! (`env!("CARGO_BIN_EXE_eom")`, `env!("CARGO_TARGET_TMPDIR")`), which a helper crate does not
//! see. Both are found where cargo puts them: the test runs from `target/<profile>/deps/`, the
//! binary is `target/<profile>/eom`, the scratch folder `target/tmp`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The repository's root, where `scenes/` and `docs/` are.
pub fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
}

/// An example scene of the repository, `scenes/NAME`.
pub fn scene(name: &str) -> PathBuf {
    root().join("scenes").join(name)
}

/// An example scene as a command-line argument.
pub fn scene_arg(name: &str) -> String {
    scene(name).display().to_string()
}

/// The folder of the running test's executable, `target/<profile>/deps/`.
fn deps() -> PathBuf {
    let test = std::env::current_exe().expect("the test's own path");
    test.parent()
        .expect("a test runs from a folder")
        .to_path_buf()
}

/// The `eom` binary cargo built for the application's tests.
pub fn binary() -> PathBuf {
    let profile = deps()
        .parent()
        .expect("target/<profile>/deps/")
        .to_path_buf();
    let binary = profile.join(format!("eom{}", std::env::consts::EXE_SUFFIX));
    assert!(
        binary.is_file(),
        "{} is not built: the tests that run it are eom-cli's (app/tests/)",
        binary.display()
    );
    binary
}

/// `eom`, to be given its arguments.
pub fn eom_command() -> Command {
    Command::new(binary())
}

/// `eom ARGS`, waited for.
pub fn eom(args: &[&str]) -> Output {
    eom_command().args(args).output().unwrap()
}

/// What a command that must succeed printed on standard output; its standard error is the
/// message if it failed.
pub fn succeeded(output: &Output) -> String {
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8(output.stdout.clone()).unwrap()
}

/// `eom run SCENE --out OUT [--shard S]`, which must succeed: what it printed.
pub fn run_into(scene: &Path, out: &Path, shard: Option<&str>) -> String {
    let mut args = vec![
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend(shard.map(|s| ["--shard", s]).into_iter().flatten());
    succeeded(&eom(&args))
}

/// A fresh, empty folder for one test's output, `target/tmp/<test crate>/<test>`.
pub fn folder(test: &str) -> PathBuf {
    let dir = scratch().join(test_crate()).join(test);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Cargo's scratch folder for tests, `target/tmp` (what `CARGO_TARGET_TMPDIR` names).
pub fn scratch() -> PathBuf {
    let deps = deps();
    let target = deps.ancestors().nth(2).expect("target/<profile>/deps/");
    target.join("tmp")
}

/// The running test crate's name: its executable's name without cargo's `-<hash>`.
fn test_crate() -> String {
    let test = std::env::current_exe().expect("the test's own path");
    let stem = test.file_stem().expect("an executable has a name");
    let stem = stem.to_string_lossy();
    match stem.rsplit_once('-') {
        Some((name, _hash)) => name.to_owned(),
        None => stem.into_owned(),
    }
}
