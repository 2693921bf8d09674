//! `eom derive`: the derivation report, computed afresh.

/// Options of `eom derive`.
#[derive(clap::Args)]
pub struct Args {}

/// Prints the derivation report.
pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("the derivation report is not written yet")
}
