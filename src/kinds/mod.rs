//! The kinds of scene: what a scene is, beyond the envelope every scene shares.
//!
//! A catalog body's scene selects a variant the build generated (`crate::scene`); a ship's
//! and a vehicle's define their model by their own table, derived and proved when the scene is
//! read. Each kind lives in its folder here, with its tables, keys, manoeuvres and figures,
//! and none imports another: what two kinds share is in the layers below them
//! ([`crate::manoeuvring`]: the steering gear, the course; [`crate::scene::envelope`]: the
//! tables every scene with manoeuvres writes; [`crate::output::summary`]: the method's
//! summary).

#[cfg(feature = "ship")]
pub mod ship;
#[cfg(feature = "ship")]
pub mod vehicle;

#[cfg(test)]
mod tidy {
    //! The map's rules about kinds, held by reading the sources, as a linter would: a rule
    //! written only in ARCHITECTURE.md is broken by the next change that does not read it.

    use std::path::{Path, PathBuf};

    /// Every `.rs` file under `dir`, sorted.
    fn sources(dir: &Path) -> Vec<PathBuf> {
        let mut found = Vec::new();
        let mut stack = vec![dir.to_owned()];
        while let Some(dir) = stack.pop() {
            let entries = std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{dir:?}: {e}"));
            for entry in entries.flatten() {
                let path = entry.path();
                if path.is_dir() {
                    stack.push(path);
                } else if path.extension().is_some_and(|e| e == "rs") {
                    found.push(path);
                }
            }
        }
        found.sort();
        found
    }

    /// The kinds: the folders under `src/kinds/`.
    fn kinds(root: &Path) -> Vec<String> {
        let mut kinds: Vec<String> = std::fs::read_dir(root)
            .unwrap_or_else(|e| panic!("{root:?}: {e}"))
            .flatten()
            .filter(|entry| entry.path().is_dir())
            .map(|entry| entry.file_name().to_string_lossy().into_owned())
            .collect();
        kinds.sort();
        kinds
    }

    #[test]
    fn no_kind_imports_another() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/kinds");
        let kinds = kinds(&root);
        assert!(kinds.len() >= 2, "the kinds' folders: {kinds:?}");
        let mut found = Vec::new();
        for kind in &kinds {
            for file in sources(&root.join(kind)) {
                let text = std::fs::read_to_string(&file).unwrap_or_default();
                for other in kinds.iter().filter(|other| *other != kind) {
                    let paths = [format!("kinds::{other}"), format!("super::super::{other}")];
                    for (number, line) in text.lines().enumerate() {
                        if paths.iter().any(|path| line.contains(path.as_str())) {
                            found.push(format!("{}:{}: {line}", file.display(), number + 1));
                        }
                    }
                }
            }
        }
        assert!(
            found.is_empty(),
            "a kind names another; move what they share into a shared layer:\n{}",
            found.join("\n")
        );
    }
}
