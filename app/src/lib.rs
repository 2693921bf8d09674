//! # eom-cli — the `eom` command's own modules
//!
//! The application apart from the library: what only the command needs, and the crates that
//! come with it (clap, anyhow, plotters, indicatif, signal-hook), which a user of the `eom`
//! library does not build. The subcommands themselves are the binary's (`src/cli/`); this
//! library holds what they draw and read, so that it can be tested without a process:
//!
//! | what | where |
//! |---|---|
//! | the JSON inputs of `eom eval`, read to the nearest binary64 | [`eval`] |
//! | the SVG plots of a run, of a linearisation and of a ship's manoeuvres | [`plots`] |
//! | a run seen in 3-D, one self-contained HTML page | [`view`] |
//! | a path as the user pastes it into a shell | [`shell_path`] |
#![deny(missing_docs)]

pub mod eval;
pub mod plots;
pub mod view;

/// `path` as a POSIX shell reads it back: as it is where it has nothing the shell treats
/// specially, else quoted (`'my runs/a b'`), so that a printed path can be pasted into a
/// command. A path that is not UTF-8 or holds a NUL is shown as Rust displays it.
pub fn shell_path(path: &std::path::Path) -> String {
    let shown = path.display().to_string();
    match path.to_str().map(shlex::try_quote) {
        Some(Ok(quoted)) => quoted.into_owned(),
        _ => shown,
    }
}
