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
#![deny(missing_docs)]

pub mod eval;
pub mod plots;
pub mod view;
