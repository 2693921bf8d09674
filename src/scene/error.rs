//! Why a scene cannot run: every error names the file and the key, by its path in the file
//! (`integrator.step`), and says what is wrong with it.

use crate::mass::BodyFileError;
use std::path::PathBuf;
use thiserror::Error;

/// A scene that cannot be read or run as written.
#[derive(Debug, Error)]
#[error("{file}: {}{problem}", key_prefix(.key))]
pub struct SceneError {
    /// The scene file (or `<scene>` for text given directly).
    pub file: String,
    /// The key's path in the file, `integrator.step`; empty for the file as a whole.
    pub key: String,
    /// What is wrong.
    pub problem: Problem,
}

fn key_prefix(key: &str) -> String {
    if key.is_empty() {
        String::new()
    } else {
        format!("`{key}`: ")
    }
}

/// What is wrong with a scene, by class: the command line maps each class to its own exit
/// code.
#[derive(Debug, Error)]
pub enum Problem {
    /// The file cannot be read.
    #[error("cannot read it: {0}")]
    Read(#[source] std::io::Error),
    /// The file is not TOML.
    #[error("not valid TOML: {0}")]
    Syntax(String),
    /// A key the scene format does not have, or a value of the wrong type.
    #[error("{0}")]
    Schema(String),
    /// A key the scene needs is absent.
    #[error("missing: {0}")]
    Missing(String),
    /// A value out of its range, or keys that contradict each other.
    #[error("{0}")]
    Invalid(String),
    /// The body file named by `body.file` cannot be used.
    #[error(transparent)]
    BodyFile(Box<BodyFileError>),
}

/// The longest line the TOML reader's message may echo from the file, in characters: it
/// quotes the offending line, and a generated scene's line may be 200 KB long.
pub const MESSAGE_LINE: usize = 120;
/// The longest line of a schema message (serde's), in characters: long enough for its list
/// of the keys a table has, short enough to cut a value it echoes.
const SCHEMA_LINE: usize = 320;

impl SceneError {
    /// An error about `key` of `file`. What the TOML reader and serde echo from the file is
    /// cut: each line of a syntax error to `MESSAGE_LINE` characters, of a schema error to
    /// 320; eom's own messages are kept whole.
    pub fn new(file: &str, key: &str, problem: Problem) -> Self {
        Self {
            file: file.to_owned(),
            key: cut_lines(key, SCHEMA_LINE),
            problem: problem.cut(),
        }
    }
}

impl Problem {
    fn cut(self) -> Self {
        match self {
            Problem::Syntax(text) => Problem::Syntax(cut_lines(&text, MESSAGE_LINE)),
            Problem::Schema(text) => Problem::Schema(cut_lines(&text, SCHEMA_LINE)),
            other => other,
        }
    }
}

/// Each line cut to `width` characters, the cut marked with "…".
fn cut_lines(text: &str, width: usize) -> String {
    let cut = |line: &str| match line.char_indices().nth(width - 1) {
        Some((end, _)) => format!("{}…", &line[..end]),
        None => line.to_owned(),
    };
    let lines: Vec<String> = text.split('\n').map(cut).collect();
    lines.join("\n")
}

/// The scene file's display name.
pub(crate) fn display_name(path: &std::path::Path) -> String {
    PathBuf::from(path).display().to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_echoed_line_is_cut_to_the_message_width() {
        let line = format!("x = [{}", "[".repeat(100_000));
        let error = SceneError::new("deep.toml", "", Problem::Syntax(format!("at\n{line}\n^")));
        let message = error.to_string();
        assert!(
            message
                .lines()
                .all(|l| l.chars().count() <= MESSAGE_LINE + 30)
        );
        assert!(message.contains("…") && message.len() < 400, "{message}");
        let value = format!("\"{}\"", "x".repeat(100_000));
        let error = SceneError::new("s.toml", "title", Problem::Schema(value));
        assert!(error.to_string().len() < 400);
        let own = "a sentence of eom's own ".repeat(10);
        let error = SceneError::new("s.toml", "k", Problem::Invalid(own.clone()));
        assert!(
            error.to_string().ends_with(&own),
            "eom's own message is kept whole"
        );
    }
}
