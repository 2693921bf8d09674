//! The repository stands alone: no tracked file names a path into a folder beside the
//! checkout, where the published tables and the index of the chapter's equations once were
//! read from. A fresh clone builds, tests and reads its docs with nothing else; the tables are
//! in `data/` (with their sources) and the index is `docs/equations.md`.

use std::path::Path;
use std::process::Command;

/// The way out of the checkout into the folder beside it, written in two pieces so that this
/// file does not hold it.
const BESIDE: &str = concat!("..", "/shared");

/// Every file git tracks, relative to `root`.
fn tracked_files(root: &Path) -> Vec<String> {
    let output = Command::new("git")
        .arg("-C")
        .arg(root)
        .args(["ls-files", "-z"])
        .output()
        .unwrap_or_else(|e| panic!("git ls-files in {}: {e}", root.display()));
    assert!(
        output.status.success(),
        "git ls-files in {}: {}",
        root.display(),
        String::from_utf8_lossy(&output.stderr)
    );
    (output.stdout.split(|&byte| byte == 0))
        .filter(|name| !name.is_empty())
        .map(|name| String::from_utf8_lossy(name).into_owned())
        .collect()
}

/// Each line of the tracked files (as they are in the working tree) that holds `needle`, as
/// `file:line: text`.
fn lines_holding(root: &Path, files: &[String], needle: &str) -> Vec<String> {
    let mut found = Vec::new();
    for file in files {
        // A tracked file deleted in the working tree holds nothing.
        let Ok(bytes) = std::fs::read(root.join(file)) else {
            continue;
        };
        let text = String::from_utf8_lossy(&bytes);
        for (number, line) in text.lines().enumerate() {
            if line.contains(needle) {
                found.push(format!("{file}:{}: {}", number + 1, line.trim()));
            }
        }
    }
    found
}

#[test]
fn no_tracked_file_names_a_folder_beside_the_repository() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files = tracked_files(root);
    // The listing is this repository's: its own sources, docs and published tables are in it.
    for own in [
        "src/lib.rs",
        "tests/standalone.rs",
        "data/README.md",
        "docs/equations.md",
    ] {
        assert!(files.iter().any(|f| f == own), "{own} is not tracked");
    }
    let found = lines_holding(root, &files, BESIDE);
    assert!(
        found.is_empty(),
        "{} line(s) name {BESIDE}; point them to data/ or docs/equations.md:\n{}",
        found.len(),
        found.join("\n")
    );
}
