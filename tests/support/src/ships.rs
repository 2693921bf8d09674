//! Ship scenes the tests build from the shipped ones: the Mariner in a wind.

use crate::cli::scene;

/// The Mariner's windage for Isherwood's regression (`tests/support/mariner_windage.toml`,
/// which says where its numbers come from).
pub const MARINER_WINDAGE: &str = include_str!("../mariner_windage.toml");

/// `scenes/mariner.toml` without its spiral (refused in a wind), with `environment` (an
/// `[environment]` table's lines) and [`MARINER_WINDAGE`].
pub fn mariner_in(environment: &str) -> String {
    let text = std::fs::read_to_string(scene("mariner.toml")).unwrap();
    let start = text.find("# Dieudonné's direct spiral").unwrap();
    let end = text.find("# `eom linear` about").unwrap();
    let text = format!("{}{}", &text[..start], &text[end..]);
    let added = format!("[environment]\n{environment}\n{MARINER_WINDAGE}\n[integrator]");
    text.replacen("[integrator]", &added, 1)
}
