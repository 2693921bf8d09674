//! `eom eval` run as a user runs it: the built binary, the JSON input on standard input.

use std::io::Write;
use std::process::Stdio;

/// What one `eom eval` printed, and whether it succeeded.
pub struct Run {
    pub ok: bool,
    pub stdout: String,
    pub stderr: String,
}

/// `eom eval ARGS --input -` with `input` on standard input.
pub fn eval(args: &[&str], input: &str) -> Run {
    let mut child = crate::cli::eom_command()
        .arg("eval")
        .args(args)
        .args(["--input", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the eom binary runs");
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    Run {
        ok: out.status.success(),
        stdout: String::from_utf8(out.stdout).unwrap(),
        stderr: String::from_utf8(out.stderr).unwrap(),
    }
}
