//! The keys a serde schema accepts, found by walking it: a deserializer that answers every
//! struct with all of its fields, every list with one element and every number with zero,
//! and writes down the path of each value that is not itself a table. Paths are written as
//! the scene reference writes them: `integrator.step`, `sweep.*` for a table of any names,
//! `manoeuvre[].kind` for a key of each table in an array of tables.
//!
//! Also [`set`], which puts a value at such a path in a TOML table.

use serde::Deserialize;
use serde::de::value::StrDeserializer;
use serde::de::{self, DeserializeSeed, Deserializer, IntoDeserializer, MapAccess, SeqAccess};
use std::cell::RefCell;
use std::collections::BTreeSet;
use std::fmt;

/// Every key path `T` accepts.
pub fn keys<T: for<'de> Deserialize<'de>>() -> BTreeSet<String> {
    let found = RefCell::new(BTreeSet::new());
    let walker = Walker {
        path: String::new(),
        leaf: None,
        found: &found,
    };
    if let Err(error) = T::deserialize(walker) {
        panic!("the schema walk failed: {error}");
    }
    found.into_inner()
}

/// Why a walk could not go on: a type the walker does not answer.
#[derive(Debug)]
pub struct Stop(String);

impl fmt::Display for Stop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Stop {}

impl de::Error for Stop {
    fn custom<T: fmt::Display>(message: T) -> Self {
        Stop(message.to_string())
    }
}

/// One value of the walk: `path` for what is inside it, `leaf` the path written down if it
/// turns out to be a plain value (none for the entries of a fixed-size array, whose array is
/// the key).
struct Walker<'a> {
    path: String,
    leaf: Option<String>,
    found: &'a RefCell<BTreeSet<String>>,
}

impl<'a> Walker<'a> {
    fn child(&self, path: String, leaf: Option<String>) -> Walker<'a> {
        Walker {
            path,
            leaf,
            found: self.found,
        }
    }

    fn field(&self, name: &str) -> Walker<'a> {
        let path = if self.path.is_empty() {
            name.to_owned()
        } else {
            format!("{}.{name}", self.path)
        };
        self.child(path.clone(), Some(path))
    }

    fn record(&self) {
        if let Some(leaf) = &self.leaf {
            self.found.borrow_mut().insert(leaf.clone());
        }
    }
}

impl<'de> Deserializer<'de> for Walker<'_> {
    type Error = Stop;

    /// A value read by its own visitor, as a constant or a time table (`eom::kinds::body::file::
    /// Timed`): the key itself is recorded, and the table's fields are walked unrecorded (the
    /// reference describes the table form under the key).
    fn deserialize_any<V: de::Visitor<'de>>(self, visitor: V) -> Result<V::Value, Stop> {
        self.record();
        visitor.visit_map(Fields {
            walker: self.child(self.path.clone(), None),
            fields: &["times", "values", "interpolation"],
            next: 0,
            recorded: false,
        })
    }

    fn deserialize_bool<V: de::Visitor<'de>>(self, visitor: V) -> Result<V::Value, Stop> {
        self.record();
        visitor.visit_bool(false)
    }

    fn deserialize_f64<V: de::Visitor<'de>>(self, visitor: V) -> Result<V::Value, Stop> {
        self.record();
        visitor.visit_f64(0.0)
    }

    fn deserialize_u64<V: de::Visitor<'de>>(self, visitor: V) -> Result<V::Value, Stop> {
        self.record();
        visitor.visit_u64(0)
    }

    fn deserialize_str<V: de::Visitor<'de>>(self, visitor: V) -> Result<V::Value, Stop> {
        self.record();
        visitor.visit_str("")
    }

    fn deserialize_string<V: de::Visitor<'de>>(self, visitor: V) -> Result<V::Value, Stop> {
        self.deserialize_str(visitor)
    }

    fn deserialize_option<V: de::Visitor<'de>>(self, visitor: V) -> Result<V::Value, Stop> {
        visitor.visit_some(self)
    }

    fn deserialize_tuple<V: de::Visitor<'de>>(
        self,
        len: usize,
        visitor: V,
    ) -> Result<V::Value, Stop> {
        self.record();
        let entry = self.child(self.path.clone(), None);
        visitor.visit_seq(Entries {
            walker: Some(entry),
            left: len,
        })
    }

    fn deserialize_seq<V: de::Visitor<'de>>(self, visitor: V) -> Result<V::Value, Stop> {
        // One element: its keys are `path[].…`, and a plain element makes the list the key.
        let element = self.child(format!("{}[]", self.path), self.leaf.clone());
        visitor.visit_seq(Entries {
            walker: Some(element),
            left: 1,
        })
    }

    fn deserialize_map<V: de::Visitor<'de>>(self, visitor: V) -> Result<V::Value, Stop> {
        self.found.borrow_mut().insert(format!("{}.*", self.path));
        visitor.visit_map(Fields {
            walker: self,
            fields: &[],
            next: 0,
            recorded: true,
        })
    }

    fn deserialize_struct<V: de::Visitor<'de>>(
        self,
        _: &'static str,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, Stop> {
        visitor.visit_map(Fields {
            walker: self,
            fields,
            next: 0,
            recorded: true,
        })
    }

    serde::forward_to_deserialize_any! {
        i8 i16 i32 i64 i128 u8 u16 u32 u128 f32 char bytes byte_buf unit unit_struct
        newtype_struct tuple_struct enum identifier ignored_any
    }
}

/// The entries of a list or an array: `left` more, each walked alike.
struct Entries<'a> {
    walker: Option<Walker<'a>>,
    left: usize,
}

impl<'de> SeqAccess<'de> for Entries<'_> {
    type Error = Stop;

    fn next_element_seed<T: DeserializeSeed<'de>>(
        &mut self,
        seed: T,
    ) -> Result<Option<T::Value>, Stop> {
        if self.left == 0 {
            return Ok(None);
        }
        self.left -= 1;
        let Some(walker) = &self.walker else {
            return Ok(None);
        };
        let entry = walker.child(walker.path.clone(), walker.leaf.clone());
        seed.deserialize(entry).map(Some)
    }
}

/// A struct's fields, every one given; `recorded`: whether their paths are keys.
struct Fields<'a> {
    walker: Walker<'a>,
    fields: &'static [&'static str],
    next: usize,
    recorded: bool,
}

impl<'de> MapAccess<'de> for Fields<'_> {
    type Error = Stop;

    fn next_key_seed<K: DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, Stop> {
        let Some(field) = self.fields.get(self.next) else {
            return Ok(None);
        };
        let name: StrDeserializer<'_, Stop> = field.into_deserializer();
        seed.deserialize(name).map(Some)
    }

    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value, Stop> {
        let field = self.fields[self.next];
        self.next += 1;
        let mut walker = self.walker.field(field);
        if !self.recorded {
            walker.leaf = None;
        }
        seed.deserialize(walker)
    }
}

/// Sets `value` at a reference path in `table`: `a.b` a key of a table, `a[].b` a key of the
/// first table of an array (made if absent), `a.*` the names of `value`'s table merged into
/// table `a`.
pub fn set(table: &mut toml::Table, path: &str, value: toml::Value) {
    let (head, rest) = match path.split_once('.') {
        Some((head, rest)) => (head, Some(rest)),
        None => (path, None),
    };
    match rest {
        None if head == "*" => {
            if let toml::Value::Table(entries) = value {
                table.extend(entries);
            }
        }
        None => {
            table.insert(head.to_owned(), value);
        }
        Some(rest) => {
            let inner = match head.strip_suffix("[]") {
                Some(array) => first_table(table, array),
                None => table
                    .entry(head)
                    .or_insert_with(|| toml::Value::Table(toml::Table::new()))
                    .as_table_mut()
                    .expect("a table at the path"),
            };
            set(inner, rest, value);
        }
    }
}

/// The first table of the array of tables `name`, made if absent.
fn first_table<'a>(table: &'a mut toml::Table, name: &str) -> &'a mut toml::Table {
    let array = table
        .entry(name)
        .or_insert_with(|| toml::Value::Array(Vec::new()))
        .as_array_mut()
        .expect("an array of tables at the path");
    if array.is_empty() {
        array.push(toml::Value::Table(toml::Table::new()));
    }
    array[0].as_table_mut().expect("a table in the array")
}
