//! The scene reference: every key a scene file takes, defined once.
//!
//! A key's path, the families that read it, its type, unit, axes, default, whether it is
//! required and what it means stand in one static table (the `KEYS` of each kind of the
//! registry, in its folder, chained; those every scene takes defined once, here). Three things
//! are made from it, so that they cannot disagree: the family check of a scene file (a key
//! another family reads is refused, [`table_keys`]), the commented TOML template `eom new
//! FAMILY` prints ([`template`]), and the reference page `docs/scenes.md` ([`markdown`],
//! printed by `eom new --reference`). The tests keep the table and each kind's serde schema
//! in step, both ways, and run every template.

mod markdown;
mod shared;
mod template;

pub use markdown::{REGENERATE, markdown};
pub use template::template;

use crate::models::{Family, Kinematics, Symmetry};
use crate::scene::Method;

/// What `eom new` makes a template of: a catalog family, or a kind of the registry
/// ([`crate::kinds::REGISTRY`]), whose own table defines its model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SceneFamily {
    /// A scene of one of the catalog's families (`model.family`).
    Catalog(Family),
    /// A scene of the registered kind of this name (`ship`).
    Kind(&'static str),
}

impl SceneFamily {
    /// Every family, each kind's in the registry's order.
    pub fn all() -> Vec<SceneFamily> {
        (crate::kinds::REGISTRY.iter())
            .flat_map(|kind| kind.reference.families.iter().copied())
            .collect()
    }

    /// Its name on the command line: the catalog family's own, or the kind's (`ship`).
    pub const fn name(self) -> &'static str {
        match self {
            SceneFamily::Catalog(family) => family.name(),
            SceneFamily::Kind(name) => name,
        }
    }

    /// What it is, in one line.
    pub fn doc(self) -> &'static str {
        match self {
            SceneFamily::Catalog(family) => family.doc(),
            SceneFamily::Kind(name) => {
                crate::kinds::named(name).map_or("", |kind| kind.reference.doc)
            }
        }
    }

    /// The family of this name, if there is one.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::all().into_iter().find(|f| f.name() == name)
    }
}

/// One key of a scene file, for the families that read it. A path may have several entries
/// where families read it differently (a force of 3 entries or of 2); their families never
/// overlap.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Key {
    /// The key's path in the file: `integrator.step`; `*` stands for any name in a table of
    /// names (`sweep.*`), `[]` for each table of an array of tables (`manoeuvre[].kind`).
    pub path: &'static str,
    /// The families that read it.
    pub families: &'static [SceneFamily],
    /// What is written: a number, three numbers, a string of a few choices, …
    pub kind: Kind,
    /// Its unit (`kg m²`, `rad/s`, `deg`); `-` for a dimensionless number, empty where a unit
    /// does not apply (a name, a choice).
    pub unit: &'static str,
    /// The axes a vector (or a component of one) is in.
    pub frame: Frame,
    /// What the key is when the file leaves it out; empty where it has no default.
    pub default: &'static str,
    /// Whether the file must give it.
    pub required: Required,
    /// What it means, in a sentence or a few.
    pub description: &'static str,
    /// A value that runs, as TOML: the templates write it (`{family}` stands for the
    /// family's name). A `*` key's example is whole lines, `name = value`.
    pub example: &'static str,
    /// Whether a template sets the key or shows it commented out.
    pub shown: Shown,
    /// Whether the key is one every scene takes, defined once ([`Key::shared`]): this entry
    /// says only where the family's template writes it, and with what example.
    pub shared: bool,
}

impl Key {
    /// What every field is unless an entry says otherwise.
    pub const BLANK: Key = Key {
        path: "",
        families: &[],
        kind: Kind::Number,
        unit: "",
        frame: Frame::None,
        default: "",
        required: Required::No,
        description: "",
        example: "",
        shown: Shown::Set,
        shared: false,
    };

    /// A key every scene takes (`shared.rs`, [`shared_keys`]), where `families` write it: its
    /// place in their list, the example their template sets, and whether it shows it
    /// commented out. Its meaning is the shared definition's.
    pub const fn shared(
        path: &'static str,
        families: &'static [SceneFamily],
        example: &'static str,
        shown: Shown,
    ) -> Key {
        Key {
            path,
            families,
            example,
            shown,
            shared: true,
            ..Key::BLANK
        }
    }

    /// The key as a family reads it: a shared key's definition with the family's place,
    /// example and showing; any other key as it is.
    fn resolved(&self) -> Key {
        match (self.shared, shared::definition(self.path)) {
            (true, Some(definition)) => Key {
                families: self.families,
                example: self.example,
                shown: self.shown,
                shared: true,
                ..*definition
            },
            _ => *self,
        }
    }

    /// The table the key is in: `integrator` of `integrator.step`, empty for a top-level key.
    pub fn table(&self) -> &'static str {
        self.path.rsplit_once('.').map_or("", |(table, _)| table)
    }

    /// The key's name in its table: `step` of `integrator.step`.
    pub fn name(&self) -> &'static str {
        self.path
            .rsplit_once('.')
            .map_or(self.path, |(_, name)| name)
    }

    /// Whether `family` reads it.
    pub fn is_of(&self, family: SceneFamily) -> bool {
        self.families.contains(&family)
    }

    /// The example with the family's name put in.
    pub fn example_for(&self, family: SceneFamily) -> String {
        self.example.replace("{family}", family.name())
    }
}

/// The type of a key's value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A string: free text, or one of a few names.
    Text(Choices),
    /// A number.
    Number,
    /// A whole number.
    Integer,
    /// An array of numbers; the text says how many and what each is (`3: x, y, z`).
    Numbers(&'static str),
    /// A 3×3 array of numbers.
    Tensor,
    /// A table of names and values.
    Table(&'static str),
    /// An array of names; the text says of what.
    Names(&'static str),
}

impl Kind {
    /// How the reference writes the type.
    pub fn describe(&self) -> String {
        match self {
            Kind::Text(Choices::Free) => "string".into(),
            Kind::Text(choices) => format!("string: {}", choices.names().join(" | ")),
            Kind::Number => "number".into(),
            Kind::Integer => "integer".into(),
            Kind::Numbers(what) => format!("array of {what}"),
            Kind::Tensor => "3×3 array of numbers".into(),
            Kind::Table(what) => format!("table of {what}"),
            Kind::Names(what) => format!("array of names of {what}"),
        }
    }
}

/// The values a string key takes, named where the code names them, so that the reference
/// lists exactly what the scene reader accepts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Choices {
    /// Any text.
    Free,
    /// A catalog family's name ([`Family::ALL`]).
    Families,
    /// `auto` or a symmetry class ([`Symmetry::ALL`]).
    Symmetries,
    /// An attitude kinematics ([`Kinematics::ALL`]).
    Kinematics,
    /// An integration method ([`Method::ALL`]).
    Methods,
    /// These names.
    These(&'static [&'static str]),
}

impl Choices {
    /// The names accepted, in the code's order.
    pub fn names(&self) -> Vec<&'static str> {
        match self {
            Choices::Free => Vec::new(),
            Choices::Families => Family::ALL.map(Family::name).to_vec(),
            Choices::Symmetries => {
                let mut names = vec!["auto"];
                names.extend(Symmetry::ALL.map(Symmetry::name));
                names
            }
            Choices::Kinematics => Kinematics::ALL.map(Kinematics::name).to_vec(),
            Choices::Methods => Method::ALL.map(|(_, name)| name).to_vec(),
            Choices::These(names) => names.to_vec(),
        }
    }
}

/// The axes a vector is given in (space X north, Y east, Z down; body x forward, y to
/// starboard, z down; the top's own space axes have Z up).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Frame {
    /// Not a vector, or not a component of one.
    None,
    /// Body axes.
    Body,
    /// Space axes.
    Space,
    /// An attitude: the body axes' orientation in space axes.
    Attitude,
}

impl Frame {
    /// How the reference writes it; empty for [`Frame::None`].
    pub fn describe(&self) -> &'static str {
        match self {
            Frame::None => "",
            Frame::Body => "body axes",
            Frame::Space => "space axes",
            Frame::Attitude => "body axes from space axes",
        }
    }
}

/// Whether a scene must give a key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Required {
    /// Always.
    Yes,
    /// Never: it has a default, or is one of alternatives.
    No,
    /// Under a condition, said in words: `for a fixed-step method`.
    When(&'static str),
}

impl Required {
    /// How the reference writes it.
    pub fn describe(&self) -> String {
        match self {
            Required::Yes => "required".into(),
            Required::No => "optional".into(),
            Required::When(condition) => format!("required {condition}"),
        }
    }
}

/// How a template shows a key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shown {
    /// Set to its example: the template runs with it.
    Set,
    /// Commented out: an alternative to a key set (`body.file` for `body.mass` and
    /// `body.inertia`), or an option the template's run does not use.
    Commented,
}

/// Every key of every scene file, kind by kind in the registry's order, each kind's in the
/// order a template writes them; a key every scene takes is given with each family's entry
/// of it.
pub fn keys() -> impl Iterator<Item = Key> {
    (crate::kinds::REGISTRY.iter())
        .flat_map(|kind| kind.reference.keys())
        .map(Key::resolved)
}

/// The keys `family` reads, in template order.
pub fn keys_of(family: SceneFamily) -> impl Iterator<Item = Key> {
    keys().filter(move |key| key.is_of(family))
}

/// The keys every scene takes, each defined once, for the reference page.
pub fn shared_keys() -> &'static [Key] {
    shared::KEYS
}

/// The names of the keys a catalog family reads in `table` (`body`, `initial`, …): what the
/// scene checker allows there.
pub fn table_keys(family: Family, table: &str) -> Vec<&'static str> {
    keys_of(SceneFamily::Catalog(family))
        .filter(|key| key.table() == table)
        .map(|key| key.name())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{DEFAULT_MAX_STEPS, DEFAULT_ROWS, DEFAULT_TOLERANCE};

    fn key(family: SceneFamily, path: &str) -> Key {
        keys_of(family)
            .find(|k| k.path == path)
            .unwrap_or_else(|| panic!("no {path} for {}", family.name()))
    }

    #[test]
    fn no_family_reads_a_path_twice() {
        for family in SceneFamily::all() {
            let mut paths: Vec<&str> = keys_of(family).map(|k| k.path).collect();
            let all = paths.len();
            paths.sort_unstable();
            paths.dedup();
            assert_eq!(paths.len(), all, "{}", family.name());
        }
    }

    #[test]
    fn the_defaults_are_the_checkers_constants() {
        let spatial = SceneFamily::Catalog(Family::Spatial);
        for path in ["integrator.rtol", "integrator.atol"] {
            let default: f64 = key(spatial, path).default.parse().unwrap();
            assert_eq!(default, DEFAULT_TOLERANCE, "{path}");
        }
        let steps: usize = key(spatial, "integrator.max_steps")
            .default
            .replace('_', "")
            .parse()
            .unwrap();
        assert_eq!(steps, DEFAULT_MAX_STEPS);
        let rows = format!("end_time/{DEFAULT_ROWS}");
        assert_eq!(key(spatial, "output.every").default, rows);
    }

    /// A key every scene takes is taken by every family, each entry of it names a shared
    /// definition, and no family defines it on its own.
    #[test]
    fn every_family_takes_every_shared_key_as_it_is_defined_once() {
        let raw = crate::kinds::REGISTRY
            .iter()
            .flat_map(|k| k.reference.keys());
        for key in raw {
            let definition = shared::definition(key.path);
            assert_eq!(
                definition.is_some(),
                key.shared,
                "{}: shared or its own",
                key.path
            );
        }
        for family in SceneFamily::all() {
            for shared in shared::KEYS {
                let taken = key(family, shared.path);
                assert!(taken.shared, "{} {}", family.name(), shared.path);
                assert_eq!(taken.description, shared.description);
                assert!(
                    !taken.example.is_empty(),
                    "{} {}",
                    family.name(),
                    shared.path
                );
            }
        }
    }

    #[test]
    fn every_family_is_named_and_found_by_its_name() {
        for family in SceneFamily::all() {
            assert_eq!(SceneFamily::from_name(family.name()), Some(family));
            assert!(keys_of(family).any(|k| k.path == "title"));
        }
        assert_eq!(SceneFamily::from_name("planar"), None);
    }

    #[test]
    fn every_choice_list_names_what_the_code_accepts() {
        assert_eq!(Choices::Symmetries.names()[0], "auto");
        assert_eq!(Choices::Methods.names().len(), Method::ALL.len());
        assert!(Choices::Families.names().contains(&"planar-space"));
    }
}
