//! `eom run` in the background, for the tests that signal a run: started with its stderr
//! piped, and waited for.

use std::path::Path;
use std::process::{Child, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// `eom run SCENE --out OUT`, started in the background.
pub fn spawn_run(scene: &Path, out: &Path) -> Child {
    spawn_run_with(scene, out, &[])
}

/// `eom run SCENE --out OUT EXTRA…`, started in the background.
pub fn spawn_run_with(scene: &Path, out: &Path, extra: &[&str]) -> Child {
    crate::cli::eom_command()
        .args([
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .args(extra)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

/// The child's exit status, within a minute (then it is killed and the test fails).
pub fn wait_for_exit(child: &mut Child) -> ExitStatus {
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        if start.elapsed().as_secs() > 60 {
            let _ = child.kill();
            panic!("the run did not end within a minute of its signal");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// The child's stderr, once it has exited.
pub fn stderr(child: &mut Child) -> String {
    let mut text = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut text).unwrap();
    text
}
