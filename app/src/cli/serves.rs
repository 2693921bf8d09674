//! Which scenes a command serves: a command given a scene it does not serve says what it
//! serves, instead of failing on the first key its reader does not know.

use super::run::Usage;
use anyhow::Result;
use eom::scene::{AnyScene, Problem, SceneError};
use std::path::Path;

/// The kinds of scene the commands tell apart.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// A scene of a registered kind (its name): its own table defines its model.
    Registered(&'static str),
    /// A catalog scene, with or without a `[sweep]`.
    Catalog { swept: bool },
}

/// The scene's text, read, and its kind: a swept scene is many; one scene is read and
/// checked by the one reader of every scene ([`AnyScene`]), which says its kind.
fn read(path: &Path) -> Result<(String, Kind)> {
    let name = path.display().to_string();
    let text =
        std::fs::read_to_string(path).map_err(|e| SceneError::new(&name, "", Problem::Read(e)))?;
    if eom::scene::sweep::is_swept(&text) {
        return Ok((text, Kind::Catalog { swept: true }));
    }
    let base = path.parent().unwrap_or(Path::new("."));
    let kind = match AnyScene::parse(&text, &name, base)? {
        AnyScene::Kind(scene) => Kind::Registered(scene.kind()),
        AnyScene::Catalog(_) => Kind::Catalog { swept: false },
    };
    Ok((text, kind))
}

/// The `[model] family` the scene names, for messages.
fn family(text: &str) -> String {
    text.parse::<toml::Table>()
        .ok()
        .and_then(|t| t.get("model")?.get("family")?.as_str().map(str::to_owned))
        .unwrap_or_else(|| "catalog".into())
}

/// The one scene `eom linear` linearises, read; a swept scene is refused, since it is many.
pub fn linearised(path: &Path) -> Result<AnyScene> {
    let name = path.display().to_string();
    let text =
        std::fs::read_to_string(path).map_err(|e| SceneError::new(&name, "", Problem::Read(e)))?;
    if eom::scene::sweep::is_swept(&text) {
        return Err(Usage(format!(
            "eom linear linearises one scene; {} (a {} scene) has a [sweep]: run it without \
             the [sweep], with one case's values",
            path.display(),
            family(&text)
        ))
        .into());
    }
    let base = path.parent().unwrap_or(Path::new("."));
    Ok(AnyScene::parse(&text, &name, base)?)
}

/// Refuses anything but a single catalog scene, for `eom tradeoff`.
pub fn require_single_catalog(path: &Path) -> Result<()> {
    match read(path)?.1 {
        Kind::Catalog { swept: false } => Ok(()),
        Kind::Catalog { swept: true } => Err(Usage(format!(
            "eom tradeoff compares the integrators on one scene; {} has a [sweep]: run it \
             without the [sweep], with one case's values",
            path.display()
        ))
        .into()),
        Kind::Registered(kind) => Err(Usage(format!(
            "eom tradeoff serves catalog scenes (pendulum, planar, spatial, top), whose \
             integrators it compares over one run; {} is a {kind} scene, whose manoeuvres \
             name their method in [integrator]",
            path.display()
        ))
        .into()),
    }
}
