//! Which scenes a command serves: a command given a scene it does not serve says what it
//! serves, instead of failing on the first key its reader does not know.

use super::run::Usage;
use anyhow::Result;
use eom::kinds::Kind;
use eom::scene::{AnyScene, Problem, SceneError};
use std::path::Path;

/// The `[model] family` the scene names, for messages.
fn family(text: &str) -> String {
    text.parse::<toml::Table>()
        .ok()
        .and_then(|t| t.get("model")?.get("family")?.as_str().map(str::to_owned))
        .unwrap_or_else(|| "catalog".into())
}

/// The one scene a command of one scene (`eom linear`, `eom tradeoff`) reads, of any kind; a
/// swept scene is refused, since it is many (`doing` says what the command does to one).
pub fn single(path: &Path, doing: &str) -> Result<Box<dyn Kind>> {
    let name = path.display().to_string();
    let text =
        std::fs::read_to_string(path).map_err(|e| SceneError::new(&name, "", Problem::Read(e)))?;
    if eom::scene::sweep::is_swept(&text) {
        return Err(Usage(format!(
            "{doing} one scene; {} (a {} scene) has a [sweep]: run it without the [sweep], \
             with one case's values",
            path.display(),
            family(&text)
        ))
        .into());
    }
    let base = path.parent().unwrap_or(Path::new("."));
    Ok(AnyScene::parse(&text, &name, base)?.into_kind())
}
