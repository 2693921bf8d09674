//! A scene's own text — its title — as the outputs show it.
//!
//! A title is whatever the scene file says, and TOML lets a string hold any character by its
//! escape (`"\u0007"`, `"\n"`, `"\u001b"`). The scene is not refused for it: such a
//! character matters only to how the title is shown, and refusing would stop a run for a
//! caption. Each output instead keeps the title in the form its format can hold:
//!
//! - `summary.json` keeps it exactly; JSON escapes every control character (`\u0007`).
//! - The SVG plots and the terminal show it [`printable`]: XML 1.0 forbids U+0000–U+001F
//!   other than tab, line feed and carriage return, and U+FFFE and U+FFFF, even written as
//!   character references, so one such character would make the file unreadable; and an
//!   escape sequence printed to a terminal would drive the terminal rather than be read.
//! - No CSV holds a title; the CSV writers quote any field they are given.

use std::borrow::Cow;

/// `text` with every control character replaced by something a reader can see: tab, line
/// feed, carriage return and the other line breaks by a space (a caption is one line), any
/// other C0 control by its Unicode control picture (U+0007 by ␇, U+001B by ␛, DEL by ␡),
/// and a C1 control or the noncharacters U+FFFE, U+FFFF by U+FFFD �. Text without them is
/// returned as it is.
///
/// ```
/// use eom::output::text::printable;
/// assert_eq!(printable("bell\u{7} and\nnewline \u{1b}[31m"), "bell␇ and newline ␛[31m");
/// assert_eq!(printable("Tennis-racket flip"), "Tennis-racket flip");
/// ```
pub fn printable(text: &str) -> Cow<'_, str> {
    if !text.chars().any(needs_replacing) {
        return Cow::Borrowed(text);
    }
    Cow::Owned(text.chars().map(replacement).collect())
}

fn needs_replacing(c: char) -> bool {
    c.is_control() || matches!(c, '\u{fffe}' | '\u{ffff}')
}

fn replacement(c: char) -> char {
    match c {
        '\t' | '\n' | '\u{b}' | '\u{c}' | '\r' | '\u{85}' => ' ',
        '\u{0}'..='\u{1f}' => char::from_u32(0x2400 + c as u32).unwrap_or('\u{fffd}'),
        '\u{7f}' => '\u{2421}',
        c if needs_replacing(c) => '\u{fffd}',
        c => c,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_control_character_becomes_visible_and_nothing_else_changes() {
        for code in (0..0x2500).chain([0xfffe, 0xffff]) {
            let Some(c) = char::from_u32(code) else {
                continue;
            };
            let shown = printable(&c.to_string()).into_owned();
            let kept = shown == c.to_string();
            assert_eq!(kept, !needs_replacing(c), "U+{code:04X} → {shown:?}");
            assert!(
                !shown.chars().any(needs_replacing),
                "U+{code:04X} → {shown:?}"
            );
        }
    }
}
