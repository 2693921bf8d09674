//! Bad input never panics: scene files (catalog bodies, ships, vehicles, aircraft), `eom eval`
//! inputs, body files and STL meshes, mutated
//! from the shipped examples or made at random, through every parser and validator.
//!
//! Each input is fed with its panics caught (`catch_unwind`), so that a panic fails the test
//! with the input that caused it. Every failure must be the crate's typed error with a message
//! that says something; a scene that is accepted must build its model, and a sample of them is
//! run for a short time. Mutations work on the document tree (set a value to a random number —
//! NaN, ±inf, huge, tiny, negative, zero — or to a string, an array of the wrong length or a
//! nested table; scale a number; remove, insert, move or rename a key; resize an array) and
//! then on the text (delete, duplicate or swap lines, replace a value or a key, insert a line,
//! change a byte, cut the text short).
//!
//! A panic is caught, but a process abort (an allocation that fails) is not: the input that
//! was being tried is then in `target/tmp/fuzz_inputs/<test>.txt`.
//!
//! The inputs are the same on every run (a fixed seed); `PROPTEST_RNG_SEED=<n>` explores
//! others and `PROPTEST_CASES=<n>` sets the number of inputs per parser. Longer runs:
//! `cargo fuzz` in `fuzz/` (docs/fuzzing.md).

use eom::kinds::aircraft::AircraftScene;
use eom::kinds::aircraft::manoeuvre::{AircraftManoeuvre, run as run_aircraft};
use eom::kinds::body::BodyScene;
use eom::kinds::ship::linear::LinearModel;
use eom::kinds::ship::manoeuvre::{Manoeuvre, run as run_manoeuvre};
use eom::kinds::ship::{ShipModel, ShipScene};
use eom::kinds::vehicle::VehicleScene;
use eom::kinds::vehicle::manoeuvre::{VehicleManoeuvre, run as run_vehicle};
use eom::mass::{BodyFile, BodyFileError, Mesh, MeshMass};
use eom::models::{Family, Kinematics, Symmetry};
use eom::run::{Row, Sink};
use eom::scene::{AnyScene, Problem, SceneError, sweep};
use eom_cli::eval::evaluate;
use eom_test_support::cli::root;
use nalgebra::Vector3;
use proptest::prelude::*;
use proptest::sample::{Index, select};
use proptest::test_runner::{Config, RngSeed, TestCaseError, TestRunner};
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::Cursor;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};

// ---------------------------------------------------------------------------------------------
// How many inputs each parser gets in CI.

const SCENE_CASES: u32 = 6000;
const EVAL_CASES: u32 = 3000;
const BODY_CASES: u32 = 2000;
const STL_CASES: u32 = 2000;
const BYTES_CASES: u32 = 1000;
/// Fewer: a vehicle scene that reads has its model derived and proved (a few tenths of a
/// second each).
const VEHICLE_CASES: u32 = 120;
/// An aircraft scene that reads is trimmed (its model is proved once per process).
const AIRCRAFT_CASES: u32 = 600;

fn config(cases: u32) -> Config {
    let mut config = Config::with_cases(
        std::env::var("PROPTEST_CASES")
            .ok()
            .and_then(|n| n.parse().ok())
            .unwrap_or(cases),
    );
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(0x0e0e_2024);
    }
    // A failure prints its input; nothing is written into the source tree.
    config.failure_persistence = None;
    config.max_shrink_iters = 2000;
    config
}

/// Runs `test` on `cases` values of `strategy`, then prints what the inputs came to.
fn fuzz<S: Strategy>(
    name: &str,
    cases: u32,
    strategy: S,
    test: impl Fn(S::Value, &mut Tally) -> Result<(), TestCaseError>,
) where
    S::Value: std::fmt::Debug,
{
    let tally = RefCell::new(Tally::default());
    let mut runner = TestRunner::new(config(cases));
    let start = std::time::Instant::now();
    let result = runner.run(&strategy, |value| test(value, &mut tally.borrow_mut()));
    let seconds = start.elapsed().as_secs_f64();
    eprintln!("{name} ({seconds:.1} s): {}", tally.borrow());
    if let Err(error) = result {
        panic!("{name}: {error}");
    }
}

/// Outcomes by kind, to see that the inputs reach past the first check.
#[derive(Default)]
struct Tally(BTreeMap<String, usize>);

impl Tally {
    fn count(&mut self, what: impl Into<String>) {
        *self.0.entry(what.into()).or_default() += 1;
    }
}

impl std::fmt::Display for Tally {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let total: usize = self
            .0
            .iter()
            .filter(|(k, _)| k.starts_with("input"))
            .map(|(_, n)| n)
            .sum();
        write!(f, "{total} inputs;")?;
        for (what, n) in &self.0 {
            if !what.starts_with("input") {
                write!(f, " {what} {n},")?;
            }
        }
        Ok(())
    }
}

/// The first `n` words of a message, for the tally.
fn words(message: &str, n: usize) -> String {
    message
        .split_whitespace()
        .take(n)
        .collect::<Vec<_>>()
        .join(" ")
}

/// An error's variant name, for the tally.
fn variant(error: &impl std::fmt::Debug) -> String {
    let debug = format!("{error:?}");
    debug
        .split(|c: char| !c.is_alphanumeric())
        .next()
        .unwrap_or_default()
        .to_owned()
}

/// Calls `f`, turning a panic into a test failure that shows the input.
fn guarded<T>(what: &str, input: &str, f: impl FnOnce() -> T) -> Result<T, TestCaseError> {
    catch_unwind(AssertUnwindSafe(f)).map_err(|panic| {
        let message = panic
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "(not a string)".into());
        TestCaseError::fail(format!(
            "{what} panicked: {message}\n--- input ---\n{input}\n--- end of input ---"
        ))
    })
}

fn failure(what: &str, input: &str, problem: impl std::fmt::Display) -> TestCaseError {
    TestCaseError::fail(format!(
        "{what}: {problem}\n--- input ---\n{input}\n--- end of input ---"
    ))
}

/// Writes the input about to be tried where it survives a process abort (a failed allocation
/// cannot be caught): `target/tmp/fuzz_inputs/<test>.txt`.
fn remember(input: &[u8]) {
    let folder = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fuzz_inputs");
    let test = std::thread::current()
        .name()
        .unwrap_or("main")
        .replace("::", "-");
    let _ = std::fs::create_dir_all(&folder);
    let _ = std::fs::write(folder.join(format!("{test}.txt")), input);
}

// ---------------------------------------------------------------------------------------------
// Documents: one tree for TOML and JSON, rendered by hand so that a mutation can write what
// serde would refuse to (NaN in JSON, 1e400, a date, a table where a number goes).

#[derive(Debug, Clone, PartialEq)]
enum Node {
    Num(f64),
    Int(i64),
    Str(String),
    Bool(bool),
    Null,
    /// Literal text, written as it is.
    Raw(String),
    Arr(Vec<Node>),
    Obj(Vec<(String, Node)>),
}

impl Node {
    fn from_toml(value: &toml::Value) -> Node {
        match value {
            toml::Value::String(s) => Node::Str(s.clone()),
            toml::Value::Integer(i) => Node::Int(*i),
            toml::Value::Float(x) => Node::Num(*x),
            toml::Value::Boolean(b) => Node::Bool(*b),
            toml::Value::Datetime(d) => Node::Raw(d.to_string()),
            toml::Value::Array(a) => Node::Arr(a.iter().map(Node::from_toml).collect()),
            toml::Value::Table(t) => Node::Obj(
                t.iter()
                    .map(|(k, v)| (k.clone(), Node::from_toml(v)))
                    .collect(),
            ),
        }
    }

    fn from_json(value: &serde_json::Value) -> Node {
        use serde_json::Value;
        match value {
            Value::Null => Node::Null,
            Value::Bool(b) => Node::Bool(*b),
            Value::Number(n) => match n.as_i64() {
                Some(i) => Node::Int(i),
                None => Node::Num(n.as_f64().unwrap_or(f64::NAN)),
            },
            Value::String(s) => Node::Str(s.clone()),
            Value::Array(a) => Node::Arr(a.iter().map(Node::from_json).collect()),
            Value::Object(o) => Node::Obj(
                o.iter()
                    .map(|(k, v)| (k.clone(), Node::from_json(v)))
                    .collect(),
            ),
        }
    }

    fn is_table(&self) -> bool {
        matches!(self, Node::Obj(_))
    }
}

/// One step from a node to a child.
#[derive(Debug, Clone, PartialEq)]
enum Step {
    Key(usize),
    Elem(usize),
}

/// Every node's path (the root excluded), depth first.
fn paths(node: &Node) -> Vec<Vec<Step>> {
    fn walk(node: &Node, prefix: &mut Vec<Step>, out: &mut Vec<Vec<Step>>) {
        let children: Vec<(Step, &Node)> = match node {
            Node::Arr(a) => a
                .iter()
                .enumerate()
                .map(|(i, n)| (Step::Elem(i), n))
                .collect(),
            Node::Obj(o) => o
                .iter()
                .enumerate()
                .map(|(i, (_, n))| (Step::Key(i), n))
                .collect(),
            _ => Vec::new(),
        };
        for (step, child) in children {
            prefix.push(step);
            out.push(prefix.clone());
            walk(child, prefix, out);
            prefix.pop();
        }
    }
    let mut out = Vec::new();
    walk(node, &mut Vec::new(), &mut out);
    out
}

fn at_mut<'a>(node: &'a mut Node, path: &[Step]) -> Option<&'a mut Node> {
    let Some((first, rest)) = path.split_first() else {
        return Some(node);
    };
    let child = match (node, first) {
        (Node::Arr(a), Step::Elem(i)) => a.get_mut(*i)?,
        (Node::Obj(o), Step::Key(i)) => &mut o.get_mut(*i)?.1,
        _ => return None,
    };
    at_mut(child, rest)
}

fn at<'a>(node: &'a Node, path: &[Step]) -> Option<&'a Node> {
    let Some((first, rest)) = path.split_first() else {
        return Some(node);
    };
    let child = match (node, first) {
        (Node::Arr(a), Step::Elem(i)) => a.get(*i)?,
        (Node::Obj(o), Step::Key(i)) => &o.get(*i)?.1,
        _ => return None,
    };
    at(child, rest)
}

/// Takes the node at `path` out of its parent: its key (if it had one) and the node.
fn take(root: &mut Node, path: &[Step]) -> Option<(Option<String>, Node)> {
    let (last, parent) = path.split_last()?;
    match (at_mut(root, parent)?, last) {
        (Node::Arr(a), Step::Elem(i)) if *i < a.len() => Some((None, a.remove(*i))),
        (Node::Obj(o), Step::Key(i)) if *i < o.len() => {
            let (k, v) = o.remove(*i);
            Some((Some(k), v))
        }
        _ => None,
    }
}

/// Sets `key` in a table, replacing an entry of that name.
fn put(table: &mut Vec<(String, Node)>, key: String, value: Node) {
    match table.iter_mut().find(|(k, _)| *k == key) {
        Some(entry) => entry.1 = value,
        None => table.push((key, value)),
    }
}

/// A change to the document tree.
#[derive(Debug, Clone)]
enum TreeEdit {
    /// Replace any node.
    Set(Index, Node),
    /// Set a number to another.
    Number(Index, f64),
    /// Set a number to an integer.
    Integer(Index, i64),
    /// Set a string to one of the formats' words (a family, a method, a part's kind, a path).
    Word(Index, String),
    /// Multiply a number.
    Scale(Index, f64),
    /// Multiply every number under a node (a whole tensor, a whole table).
    ScaleAll(Index, f64),
    /// Remove any node.
    Remove(Index),
    /// Insert a key into a table (the root included).
    Insert(Index, String, Node),
    /// Move a key into another table.
    Move(Index, Index),
    /// Rename a key.
    Rename(Index, String),
    /// Make an array this long, by cutting it or repeating its entries.
    Resize(Index, usize),
}

fn apply_tree(root: &mut Node, edit: &TreeEdit) {
    let all = paths(root);
    let select_where = |index: &Index, keep: &dyn Fn(&Node, &[Step]) -> bool| {
        let chosen: Vec<&Vec<Step>> = all
            .iter()
            .filter(|p| at(root, p).is_some_and(|n| keep(n, p)))
            .collect();
        (!chosen.is_empty()).then(|| chosen[index.index(chosen.len())].clone())
    };
    match edit {
        TreeEdit::Set(i, value) => {
            if let Some(path) = select_where(i, &|_, _| true) {
                *at_mut(root, &path).unwrap() = value.clone();
            }
        }
        TreeEdit::Number(i, x) => {
            let number = |n: &Node, _: &[Step]| matches!(n, Node::Num(_) | Node::Int(_));
            if let Some(path) = select_where(i, &number) {
                *at_mut(root, &path).unwrap() = Node::Num(*x);
            }
        }
        TreeEdit::Integer(i, n) => {
            let number = |n: &Node, _: &[Step]| matches!(n, Node::Num(_) | Node::Int(_));
            if let Some(path) = select_where(i, &number) {
                *at_mut(root, &path).unwrap() = Node::Int(*n);
            }
        }
        TreeEdit::Word(i, word) => {
            let string = |n: &Node, _: &[Step]| matches!(n, Node::Str(_));
            if let Some(path) = select_where(i, &string) {
                *at_mut(root, &path).unwrap() = Node::Str(word.clone());
            }
        }
        TreeEdit::ScaleAll(i, factor) => {
            fn scale(node: &mut Node, factor: f64) {
                match node {
                    Node::Num(x) => *x *= factor,
                    Node::Int(n) => *node = Node::Num(*n as f64 * factor),
                    Node::Arr(a) => a.iter_mut().for_each(|n| scale(n, factor)),
                    Node::Obj(o) => o.iter_mut().for_each(|(_, n)| scale(n, factor)),
                    _ => {}
                }
            }
            if let Some(path) = select_where(i, &|_, _| true) {
                scale(at_mut(root, &path).unwrap(), *factor);
            }
        }
        TreeEdit::Scale(i, factor) => {
            let number = |n: &Node, _: &[Step]| matches!(n, Node::Num(_) | Node::Int(_));
            if let Some(path) = select_where(i, &number) {
                let node = at_mut(root, &path).unwrap();
                *node = match &*node {
                    Node::Num(x) => Node::Num(*x * factor),
                    Node::Int(n) => Node::Num(*n as f64 * factor),
                    other => other.clone(),
                };
            }
        }
        TreeEdit::Remove(i) => {
            if let Some(path) = select_where(i, &|_, _| true) {
                take(root, &path);
            }
        }
        TreeEdit::Insert(i, key, value) => {
            let mut tables: Vec<Vec<Step>> = vec![Vec::new()];
            tables.extend(
                all.iter()
                    .filter(|p| at(root, p).is_some_and(Node::is_table))
                    .cloned(),
            );
            let path = &tables[i.index(tables.len())];
            if let Some(Node::Obj(table)) = at_mut(root, path) {
                put(table, key.clone(), value.clone());
            }
        }
        TreeEdit::Move(from, to) => {
            let keyed = |_: &Node, p: &[Step]| matches!(p.last(), Some(Step::Key(_)));
            let Some(path) = select_where(from, &keyed) else {
                return;
            };
            let Some((Some(key), value)) = take(root, &path) else {
                return;
            };
            let mut tables: Vec<Vec<Step>> = vec![Vec::new()];
            tables.extend(
                paths(root)
                    .into_iter()
                    .filter(|p| at(root, p).is_some_and(Node::is_table)),
            );
            let path = tables[to.index(tables.len())].clone();
            if let Some(Node::Obj(table)) = at_mut(root, &path) {
                put(table, key, value);
            }
        }
        TreeEdit::Rename(i, key) => {
            let keyed = |_: &Node, p: &[Step]| matches!(p.last(), Some(Step::Key(_)));
            if let Some(path) = select_where(i, &keyed) {
                let (Some(Step::Key(k)), parent) = (path.last(), &path[..path.len() - 1]) else {
                    return;
                };
                if let Some(Node::Obj(table)) = at_mut(root, parent) {
                    let value = table.remove(*k).1;
                    put(table, key.clone(), value);
                }
            }
        }
        TreeEdit::Resize(i, len) => {
            let array = |n: &Node, _: &[Step]| matches!(n, Node::Arr(_));
            if let Some(path) = select_where(i, &array)
                && let Some(Node::Arr(a)) = at_mut(root, &path)
            {
                let fill = a.first().cloned().unwrap_or(Node::Num(0.0));
                a.resize(*len, fill);
            }
        }
    }
}

fn is_bare_key(key: &str) -> bool {
    !key.is_empty()
        && key
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
}

fn quoted(s: &str) -> String {
    serde_json::to_string(s).unwrap()
}

fn toml_key(key: &str) -> String {
    if is_bare_key(key) {
        key.to_owned()
    } else {
        quoted(key)
    }
}

fn toml_float(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf".into() } else { "-inf".into() }
    } else {
        format!("{x:?}")
    }
}

fn json_float(x: f64) -> String {
    if x.is_nan() {
        "NaN".into()
    } else if x.is_infinite() {
        if x > 0.0 {
            "1e400".into()
        } else {
            "-1e400".into()
        }
    } else {
        format!("{x:?}")
    }
}

/// A node as an inline TOML value.
fn toml_inline(node: &Node) -> String {
    match node {
        Node::Num(x) => toml_float(*x),
        Node::Int(i) => i.to_string(),
        Node::Str(s) => quoted(s),
        Node::Bool(b) => b.to_string(),
        Node::Null => "[]".into(),
        Node::Raw(r) => r.clone(),
        Node::Arr(a) => format!(
            "[{}]",
            a.iter().map(toml_inline).collect::<Vec<_>>().join(", ")
        ),
        Node::Obj(o) => format!(
            "{{ {} }}",
            o.iter()
                .map(|(k, v)| format!("{} = {}", toml_key(k), toml_inline(v)))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// A document as TOML: the root's plain keys, then a `[table]` per table and a `[[table]]`
/// per entry of an array of tables, each entry on its own line.
fn to_toml(root: &Node) -> String {
    let Node::Obj(entries) = root else {
        return toml_inline(root);
    };
    let mut text = String::new();
    let is_table_array =
        |n: &Node| matches!(n, Node::Arr(a) if !a.is_empty() && a.iter().all(Node::is_table));
    for (k, v) in entries {
        if !v.is_table() && !is_table_array(v) {
            writeln!(text, "{} = {}", toml_key(k), toml_inline(v)).unwrap();
        }
    }
    for (k, v) in entries {
        let section = |text: &mut String, header: String, table: &[(String, Node)]| {
            writeln!(text, "\n{header}").unwrap();
            for (k, v) in table {
                writeln!(text, "{} = {}", toml_key(k), toml_inline(v)).unwrap();
            }
        };
        match v {
            Node::Obj(table) => section(&mut text, format!("[{}]", toml_key(k)), table),
            Node::Arr(a) if is_table_array(v) => {
                for entry in a {
                    if let Node::Obj(table) = entry {
                        section(&mut text, format!("[[{}]]", toml_key(k)), table);
                    }
                }
            }
            _ => {}
        }
    }
    text
}

/// A document as JSON, one entry per line.
fn to_json(node: &Node, indent: usize) -> String {
    let pad = "  ".repeat(indent + 1);
    match node {
        Node::Num(x) => json_float(*x),
        Node::Int(i) => i.to_string(),
        Node::Str(s) => quoted(s),
        Node::Bool(b) => b.to_string(),
        Node::Null => "null".into(),
        Node::Raw(r) => r.clone(),
        Node::Arr(a) => format!(
            "[{}]",
            a.iter()
                .map(|n| to_json(n, indent + 1))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Node::Obj(o) => {
            let entries: Vec<String> = o
                .iter()
                .map(|(k, v)| format!("{pad}{}: {}", quoted(k), to_json(v, indent + 1)))
                .collect();
            format!("{{\n{}\n{}}}", entries.join(",\n"), "  ".repeat(indent))
        }
    }
}

/// A change to the text.
#[derive(Debug, Clone)]
enum LineEdit {
    Delete(Index),
    Duplicate(Index),
    Swap(Index, Index),
    /// Replace what follows the line's `=` (TOML) or `:` (JSON).
    Value(Index, Node),
    /// Replace what precedes it.
    Key(Index, String),
    Insert(Index, String),
    Byte(Index, u8),
    Truncate(Index),
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Format {
    Toml,
    Json,
}

fn apply_line(text: &str, edit: &LineEdit, format: Format) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    if lines.is_empty() {
        lines.push(String::new());
    }
    let n = lines.len();
    let separator = if format == Format::Toml { '=' } else { ':' };
    match edit {
        LineEdit::Delete(i) => {
            lines.remove(i.index(n));
        }
        LineEdit::Duplicate(i) => {
            let line = lines[i.index(n)].clone();
            lines.insert(i.index(n), line);
        }
        LineEdit::Swap(a, b) => lines.swap(a.index(n), b.index(n)),
        LineEdit::Value(i, node) => {
            let line = &mut lines[i.index(n)];
            if let Some(at) = line.find(separator) {
                let comma = if line.trim_end().ends_with(',') {
                    ","
                } else {
                    ""
                };
                let value = match format {
                    Format::Toml => toml_inline(node),
                    Format::Json => to_json(node, 0),
                };
                *line = format!("{}{separator} {value}{comma}", &line[..at]);
            }
        }
        LineEdit::Key(i, key) => {
            let line = &mut lines[i.index(n)];
            if let Some(at) = line.find(separator) {
                let key = match format {
                    Format::Toml => toml_key(key),
                    Format::Json => quoted(key),
                };
                *line = format!("{key} {}", &line[at..]);
            }
        }
        LineEdit::Insert(i, line) => lines.insert(i.index(n + 1), line.clone()),
        LineEdit::Byte(i, byte) => {
            let mut bytes = lines.join("\n").into_bytes();
            if !bytes.is_empty() {
                let at = i.index(bytes.len());
                bytes[at] = *byte;
            }
            return String::from_utf8_lossy(&bytes).into_owned();
        }
        LineEdit::Truncate(i) => {
            let text = lines.join("\n");
            let mut at = i.index(text.len() + 1);
            while !text.is_char_boundary(at) {
                at -= 1;
            }
            return text[..at].to_owned();
        }
    }
    lines.join("\n") + "\n"
}

// ---------------------------------------------------------------------------------------------
// Strategies.

/// Every key of the scene, body and eval formats, so that a key lands in the wrong table or
/// the wrong family.
const KEYS: &[&str] = &[
    "title",
    "body",
    "model",
    "initial",
    "loads",
    "integrator",
    "output",
    "sweep",
    "mass",
    "inertia",
    "file",
    "i0",
    "g",
    "h",
    "izz",
    "x_g",
    "family",
    "symmetry",
    "kinematics",
    "velocity",
    "rates",
    "position",
    "attitude_deg",
    "theta_deg",
    "theta_dot",
    "u",
    "v",
    "w",
    "p",
    "q",
    "r",
    "x",
    "y",
    "psi",
    "phi",
    "theta",
    "psi_deg",
    "x_dot",
    "y_dot",
    "psi_dot",
    "gravity",
    "buoyancy",
    "buoyancy_centre",
    "force_body",
    "force_space",
    "moment_body",
    "moment_space",
    "moment",
    "force",
    "state",
    "linear_damping",
    "quadratic_damping",
    "method",
    "rtol",
    "atol",
    "step",
    "end_time",
    "max_steps",
    "every",
    "part",
    "name",
    "kind",
    "density",
    "size",
    "radius",
    "inner_radius",
    "length",
    "path",
    "offset",
    "rotation_deg",
    "from",
    "to",
    "count",
    "body.mass",
    "body.inertia",
    "initial.theta_deg",
    "integrator.end_time",
    "integrator.method",
    "model.family",
    "loads.gravity",
    "body.",
    ".",
    "",
];

const WORDS: &[&str] = &[
    "pendulum",
    "planar-g",
    "planar-midship",
    "planar-space",
    "spatial",
    "top",
    "auto",
    "full",
    "xz",
    "principal",
    "euler",
    "quaternion",
    "symplectic-euler",
    "rk4",
    "dopri5",
    "dop853",
    "lie-midpoint",
    "box",
    "sphere",
    "ellipsoid",
    "cylinder",
    "hollow_cylinder",
    "point",
    "mesh",
    "tensor",
    "deckhouse.stl",
    "bodies/ship_blocks.toml",
    "bodies/deckhouse.stl",
    "ship_blocks.toml",
    "missing.stl",
    "open.stl",
    "inside_out.stl",
    "flat.stl",
    "binary.stl",
    "garbage.stl",
    ".",
    "..",
    "",
];

fn special_f64() -> impl Strategy<Value = f64> {
    select(vec![
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        0.0,
        -0.0,
        1.0,
        -1.0,
        f64::MAX,
        -f64::MAX,
        f64::MIN_POSITIVE,
        5e-324,
        1e-300,
        -1e-300,
        1e300,
        1e-12,
        1.1e-12,
        1e-13,
        1e12,
        1e-7,
        1e154,
        1e-154,
        9.81,
        90.0,
        -90.0,
        std::f64::consts::FRAC_PI_2,
    ])
}

fn number() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -10.0..10.0f64,
        3 => special_f64(),
        1 => any::<f64>(),
        1 => -1e6..1e6f64,
    ]
}

fn integer() -> impl Strategy<Value = i64> {
    prop_oneof![
        3 => -5..5i64,
        1 => any::<i64>(),
        1 => select(vec![0, 1, 2, i64::MAX, i64::MIN, 1_000_000_000_000, 4_294_967_296]),
    ]
}

fn key() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => select(KEYS).prop_map(str::to_owned),
        1 => "[a-z_]{1,8}",
        1 => "\\PC{0,6}",
    ]
}

fn raw() -> impl Strategy<Value = String> {
    select(vec![
        "1e400",
        "-1e400",
        "1e-400",
        "nan",
        "+inf",
        "-nan",
        "NaN",
        "Infinity",
        "-Infinity",
        "1_000",
        "0x1F",
        "0o17",
        "0b101",
        "123456789012345678901234567890",
        "-123456789012345678901234567890",
        "1979-05-27T07:32:00Z",
        "1979-05-27",
        "07:32:00",
        "'literal'",
        "\"\"\"multi\nline\"\"\"",
        "[",
        "{",
        "]",
        "}",
        "[[]]",
        "[{}]",
        "",
    ])
    .prop_map(str::to_owned)
}

fn leaf() -> impl Strategy<Value = Node> {
    prop_oneof![
        6 => number().prop_map(Node::Num),
        2 => integer().prop_map(Node::Int),
        3 => prop_oneof![
            3 => select(WORDS).prop_map(str::to_owned),
            1 => "\\PC{0,12}",
        ]
        .prop_map(Node::Str),
        1 => any::<bool>().prop_map(Node::Bool),
        1 => Just(Node::Null),
        1 => raw().prop_map(Node::Raw),
    ]
}

fn node() -> impl Strategy<Value = Node> {
    let vector = prop::collection::vec(number().prop_map(Node::Num), 0..8).prop_map(Node::Arr);
    let matrix = prop::collection::vec(
        prop::collection::vec(number().prop_map(Node::Num), 0..5).prop_map(Node::Arr),
        0..5,
    )
    .prop_map(Node::Arr);
    let range = (number(), number(), integer()).prop_map(|(from, to, count)| {
        Node::Obj(vec![
            ("from".into(), Node::Num(from)),
            ("to".into(), Node::Num(to)),
            ("count".into(), Node::Int(count)),
        ])
    });
    let nested = leaf().prop_recursive(3, 16, 4, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..4).prop_map(Node::Arr),
            prop::collection::vec((key(), inner), 0..4).prop_map(Node::Obj),
        ]
    });
    prop_oneof![
        8 => leaf(),
        3 => vector,
        1 => matrix,
        1 => range,
        2 => nested,
    ]
}

fn factor() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => select(vec![
            0.0, -1.0, 2.0, 0.5, 1e-300, 1e300, 1e-12, 1e12, 1e-6, 1e6, 1e-150, 1e150,
            1.0 + 1e-15, 1.0 - 1e-15, 1e-320, f64::NAN, f64::INFINITY,
        ]),
        1 => -3.0..3.0f64,
    ]
}

/// Edits that keep the document's shape: numbers and words change, keys stay.
fn value_edit() -> impl Strategy<Value = TreeEdit> {
    prop_oneof![
        6 => (any::<Index>(), number()).prop_map(|(i, x)| TreeEdit::Number(i, x)),
        1 => (any::<Index>(), integer()).prop_map(|(i, n)| TreeEdit::Integer(i, n)),
        2 => (any::<Index>(), select(WORDS)).prop_map(|(i, w)| TreeEdit::Word(i, w.to_owned())),
        3 => (any::<Index>(), factor()).prop_map(|(i, f)| TreeEdit::Scale(i, f)),
        2 => (any::<Index>(), factor()).prop_map(|(i, f)| TreeEdit::ScaleAll(i, f)),
    ]
}

fn tree_edit() -> impl Strategy<Value = TreeEdit> {
    prop_oneof![
        6 => value_edit(),
        2 => (any::<Index>(), node()).prop_map(|(i, n)| TreeEdit::Set(i, n)),
        2 => any::<Index>().prop_map(TreeEdit::Remove),
        2 => (any::<Index>(), key(), node()).prop_map(|(i, k, n)| TreeEdit::Insert(i, k, n)),
        1 => (any::<Index>(), any::<Index>()).prop_map(|(a, b)| TreeEdit::Move(a, b)),
        1 => (any::<Index>(), key()).prop_map(|(i, k)| TreeEdit::Rename(i, k)),
        1 => (any::<Index>(), 0..8usize).prop_map(|(i, n)| TreeEdit::Resize(i, n)),
    ]
}

fn line() -> impl Strategy<Value = String> {
    prop_oneof![
        (key(), node()).prop_map(|(k, n)| format!("{} = {}", toml_key(&k), toml_inline(&n))),
        key().prop_map(|k| format!("[{}]", toml_key(&k))),
        key().prop_map(|k| format!("[[{}]]", toml_key(&k))),
        "\\PC{0,20}",
    ]
}

fn line_edit() -> impl Strategy<Value = LineEdit> {
    prop_oneof![
        2 => any::<Index>().prop_map(LineEdit::Delete),
        1 => any::<Index>().prop_map(LineEdit::Duplicate),
        1 => (any::<Index>(), any::<Index>()).prop_map(|(a, b)| LineEdit::Swap(a, b)),
        3 => (any::<Index>(), node()).prop_map(|(i, n)| LineEdit::Value(i, n)),
        1 => (any::<Index>(), key()).prop_map(|(i, k)| LineEdit::Key(i, k)),
        2 => (any::<Index>(), line()).prop_map(|(i, l)| LineEdit::Insert(i, l)),
        1 => (any::<Index>(), any::<u8>()).prop_map(|(i, b)| LineEdit::Byte(i, b)),
        1 => any::<Index>().prop_map(LineEdit::Truncate),
    ]
}

/// How one input is made from a seed file.
#[derive(Debug, Clone)]
struct Mutation {
    seed: Index,
    /// Whole tables set before the tree's edits (scenes: `[sweep]`, `[integrator]`,
    /// `[model]`).
    tables: Vec<(String, Node)>,
    tree: Vec<TreeEdit>,
    lines: Vec<LineEdit>,
}

/// Edits of the values alone, of the tree, of the text, or of both.
fn mutation() -> impl Strategy<Value = Mutation> {
    let values = |n: std::ops::Range<usize>| prop::collection::vec(value_edit(), n);
    let tree = |n: std::ops::Range<usize>| prop::collection::vec(tree_edit(), n);
    let lines = |n: std::ops::Range<usize>| prop::collection::vec(line_edit(), n);
    let edits = prop_oneof![
        4 => (values(1..5), lines(0..1)),
        3 => (tree(1..4), lines(0..1)),
        2 => (tree(0..1), lines(1..3)),
        1 => (tree(1..3), lines(1..2)),
    ];
    (any::<Index>(), edits).prop_map(|(seed, (tree, lines))| Mutation {
        seed,
        tables: Vec::new(),
        tree,
        lines,
    })
}

/// A seed file: its text and its tree.
struct Seed {
    text: String,
    tree: Node,
}

impl Mutation {
    /// The mutated text of one of `seeds`. With no tree edit the seed's own text is kept, its
    /// comments and layout included.
    fn apply(&self, seeds: &[Seed], format: Format) -> String {
        let seed = &seeds[self.seed.index(seeds.len())];
        let mut text = if self.tree.is_empty() && self.tables.is_empty() {
            seed.text.clone()
        } else {
            let mut tree = seed.tree.clone();
            if let Node::Obj(root) = &mut tree {
                for (key, table) in &self.tables {
                    let mut table = table.clone();
                    // A table without a family keeps the seed's.
                    let old = root.iter().find(|(k, _)| k == key).map(|(_, v)| v);
                    if let (Node::Obj(new), Some(Node::Obj(old))) = (&mut table, old)
                        && key == "model"
                        && !new.iter().any(|(k, _)| k == "family")
                    {
                        new.extend(old.iter().filter(|(k, _)| k == "family").cloned());
                    }
                    put(root, key.clone(), table);
                }
            }
            for edit in &self.tree {
                apply_tree(&mut tree, edit);
            }
            match format {
                Format::Toml => to_toml(&tree),
                Format::Json => to_json(&tree, 0),
            }
        };
        for edit in &self.lines {
            text = apply_line(&text, edit, format);
        }
        text
    }
}

fn toml_seed(text: String) -> Seed {
    let table: toml::Table = text.parse().expect("a seed parses");
    Seed {
        tree: Node::from_toml(&toml::Value::Table(table)),
        text,
    }
}

fn json_seed(text: &str) -> Seed {
    let value: serde_json::Value = serde_json::from_str(text).expect("a seed parses");
    Seed {
        tree: Node::from_json(&value),
        text: text.to_owned(),
    }
}

// ---------------------------------------------------------------------------------------------
// Scenes.

/// A pendulum with a sweep, and a spatial body read from a body file: the two ways a scene
/// reaches beyond its own tables.
const EXTRA_SCENES: &[&str] = &[
    r#"title = "swept pendulum"
[body]
i0 = 2.0
mass = 1.0
g = 9.81
h = 0.5
[model]
family = "pendulum"
[integrator]
method = "rk4"
step = 0.01
end_time = 1.0
[sweep]
"body.mass" = [1.0, 2.0]
"initial.theta_deg" = { from = 10.0, to = 30.0, count = 3 }
"#,
    r#"title = "ship from its blocks"
[body]
file = "bodies/ship_blocks.toml"
[model]
family = "spatial"
[initial]
rates = [0.1, 0.0, 0.2]
[loads]
gravity = 9.81
buoyancy = 141018.75
buoyancy_centre = [0.0, 0.0, -0.2]
[integrator]
method = "dopri5"
end_time = 5.0
"#,
];

fn scene_seeds() -> Vec<Seed> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(root().join("scenes"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 8, "the example scenes are found");
    let mut seeds: Vec<Seed> = files
        .iter()
        .map(|p| toml_seed(std::fs::read_to_string(p).unwrap()))
        .collect();
    seeds.extend(EXTRA_SCENES.iter().map(|t| toml_seed(t.to_string())));
    seeds
}

/// A scene error must say what is wrong, and be of the right class.
fn check_scene_error(
    error: &SceneError,
    text: &str,
    tally: &mut Tally,
) -> Result<(), TestCaseError> {
    let what = |problem: &str| failure("scene error", text, format!("{problem}: {error}"));
    let message = match &error.problem {
        Problem::Read(e) => e.to_string(),
        Problem::Syntax(m) | Problem::Schema(m) | Problem::Missing(m) | Problem::Invalid(m) => {
            m.clone()
        }
        Problem::BodyFile(e) => e.to_string(),
    };
    if message.trim().is_empty() {
        return Err(what("an empty message"));
    }
    let class = match &error.problem {
        Problem::Read(_) => "read",
        Problem::Syntax(_) => "syntax",
        Problem::Schema(_) => "schema",
        Problem::Missing(_) => "missing",
        Problem::Invalid(_) => "invalid",
        Problem::BodyFile(_) => "body file",
    };
    tally.count(format!("refused ({class})"));
    // The reverse does not hold: the scene's reader decodes a value only when it reaches it,
    // so a value that does not decode (1e400, a 30-digit integer) is refused as a type error
    // that names its key.
    match &error.problem {
        Problem::Syntax(_) if text.parse::<toml::Table>().is_ok() => {
            Err(what("valid TOML refused as a syntax error"))
        }
        Problem::Invalid(_) | Problem::BodyFile(_) if error.key.is_empty() => {
            Err(what("a value refused without naming its key"))
        }
        _ => Ok(()),
    }
}

/// Counts the rows of a run and checks each is finite in time.
struct Rows(usize);

impl Sink for Rows {
    fn row(&mut self, row: &Row) -> bool {
        assert!(row.t.is_finite(), "a row at t = {}", row.t);
        self.0 += 1;
        true
    }
}

/// The scene cut to a short run: at most 0.05 s, 20 rows and 2000 steps.
fn shortened(scene: &BodyScene) -> BodyScene {
    let mut short = scene.clone();
    let spec = &mut short.integrator;
    spec.end_time = spec.end_time.min(0.05);
    spec.max_steps = spec.max_steps.min(2000);
    if let Some(options) = &mut spec.adaptive {
        options.max_steps = options.max_steps.min(2000);
    }
    if let Some(step) = &mut spec.step {
        *step = step.max(spec.end_time / 2000.0);
    }
    short.every = short.every.clamp(spec.end_time / 20.0, spec.end_time);
    short
}

/// An accepted scene: its values are in range, its model builds, and (when asked) it runs.
fn check_scene(
    scene: &BodyScene,
    text: &str,
    run: bool,
    tally: &mut Tally,
) -> Result<(), TestCaseError> {
    let spec = &scene.integrator;
    let sane = scene.initial.iter().all(|x| x.is_finite())
        && scene.initial.len() == scene.selection.info.state.len()
        && spec.end_time.is_finite()
        && spec.end_time > 0.0
        && scene.every > 0.0
        && scene.every <= spec.end_time
        && spec.step.is_none_or(|h| h.is_finite() && h > 0.0)
        && spec.step.is_some() != spec.adaptive.is_some();
    if !sane {
        return Err(failure("an accepted scene", text, format!("{scene:?}")));
    }
    guarded("Scene::model", text, || scene.model())?;
    tally.count("accepted");
    tally.count(format!(
        "accepted {} {}",
        scene.selection.info.name,
        scene.integrator.method.name()
    ));
    if run {
        let short = shortened(scene);
        let mut rows = Rows(0);
        match guarded("eom::kinds::body::run", text, || {
            eom::kinds::body::run(&short, &mut rows)
        })? {
            Ok(report) => {
                tally.count("ran");
                if report.final_state.len() != scene.initial.len() || rows.0 == 0 {
                    return Err(failure("a run", text, format!("{report:?}")));
                }
            }
            Err(error) => {
                tally.count("run failed");
                if error.to_string().trim().is_empty() {
                    return Err(failure("a run error", text, "an empty message"));
                }
            }
        }
    }
    Ok(())
}

/// One scene text through `BodyScene::parse` and through the sweep's cases.
fn scene_text(text: &str, run: bool, tally: &mut Tally) -> Result<(), TestCaseError> {
    tally.count("input");
    remember(text.as_bytes());
    let base = root().join("scenes");
    match guarded("BodyScene::parse", text, || {
        BodyScene::parse(text, "fuzz.toml", &base)
    })? {
        Ok(scene) => check_scene(&scene, text, run, tally)?,
        Err(error) => check_scene_error(&error, text, tally)?,
    }
    match guarded("sweep::cases", text, || sweep::cases(text, "fuzz.toml"))? {
        Ok(cases) => {
            for case in cases.iter().take(4) {
                let scene = guarded("BodyScene::from_file", text, || {
                    BodyScene::from_table(case.table.clone(), "fuzz.toml", &base)
                })?;
                match scene {
                    Ok(scene) => check_scene(&scene, text, false, tally)?,
                    Err(error) => check_scene_error(&error, text, tally)?,
                }
            }
        }
        Err(error) => check_scene_error(&error, text, tally)?,
    }
    ship_scene_text(text, run, tally)
}

/// The same text as a ship scene: read, and where it reads, its model built and proved, its
/// linear model taken and (for `run`) twenty seconds of its first manoeuvre run.
fn ship_scene_text(text: &str, run: bool, tally: &mut Tally) -> Result<(), TestCaseError> {
    let scene = match guarded("ShipScene::parse", text, || {
        ShipScene::parse(text, "fuzz.toml")
    })? {
        Ok(scene) => scene,
        Err(error) => return check_scene_error(&error, text, tally),
    };
    tally.count("ship scene read");
    let model = guarded("ShipModel::new", text, || ShipModel::new(&scene.table))?;
    let model = match model {
        Ok(model) => model,
        Err(error) if !error.to_string().is_empty() => return Ok(()),
        Err(_) => return Err(failure("ship model", text, "an empty error")),
    };
    guarded("LinearModel", text, || {
        let linear = LinearModel::closed_form(&scene.table);
        (
            linear.nomoto(),
            linear.pivot_point(),
            linear.stability_index(),
        )
    })?;
    if run {
        let first = &scene.manoeuvres[0];
        let short = Manoeuvre {
            duration: first.duration.min(first.execute + 20.0),
            ..first.clone()
        };
        // At most 10⁴ steps and rows: the run is for panics, not for figures.
        let mut stepper = scene.stepper.clone();
        stepper.step = stepper.step.map(|step| step.max(short.duration / 1e4));
        let every = scene.every.max(short.duration / 1e4);
        let result = guarded("ship run", text, || {
            run_manoeuvre(
                &model,
                &scene.rudder,
                &short,
                scene.start(),
                (&stepper, every),
                |_| true,
            )
        })?;
        tally.count(if result.is_ok() {
            "ship run ok"
        } else {
            "ship run stopped"
        });
    }
    Ok(())
}

/// Keys a sweep may name: scene values by their path, and paths that lead nowhere.
const SWEPT: &[&str] = &[
    "body.mass",
    "body.inertia",
    "body.i0",
    "body.file",
    "initial.theta_deg",
    "initial.rates",
    "initial.u",
    "integrator.end_time",
    "integrator.step",
    "integrator.method",
    "integrator.max_steps",
    "model.family",
    "model.symmetry",
    "loads.gravity",
    "loads.force_body",
    "output.every",
    "title",
    "body",
    "sweep",
    "sweep.body.mass",
    "body.",
    ".mass",
    "title.x",
    "a.b.c",
    "",
];

/// A `[sweep]` table: lists of values and ranges, some of them far too long.
fn sweep_table() -> impl Strategy<Value = Node> {
    let count = prop_oneof![
        4 => -1..6i64,
        1 => select(vec![100_001, 1_000_000_000_000, i64::MAX]),
    ];
    let range = (number(), number(), count).prop_map(|(from, to, count)| {
        Node::Obj(vec![
            ("from".into(), Node::Num(from)),
            ("to".into(), Node::Num(to)),
            ("count".into(), Node::Int(count)),
        ])
    });
    let axis = prop_oneof![
        3 => prop::collection::vec(node(), 0..4).prop_map(Node::Arr),
        2 => range,
        1 => node(),
    ];
    let entry = (select(SWEPT).prop_map(str::to_owned), axis);
    prop_oneof![
        6 => prop::collection::vec(entry, 1..4),
        // Many keys of two values: 2^n cases, more than a sweep may have (the limit itself is
        // tested in found_inputs.rs; 10⁵ cases take a second here).
        1 => (17..70usize).prop_map(|n| {
            (0..n)
                .map(|i| (format!("initial.theta_deg{i}"), Node::Arr(vec![Node::Num(1.0), Node::Num(2.0)])))
                .collect()
        }),
    ]
    .prop_map(Node::Obj)
}

/// An `[integrator]` table of any method: a step for a fixed-step method and tolerances (or
/// none) for an adaptive one, three times in four; else a step, tolerances, both or neither.
fn integrator_table() -> impl Strategy<Value = Node> {
    let methods = vec![
        "euler",
        "symplectic-euler",
        "rk4",
        "dopri5",
        "dop853",
        "lie-midpoint",
    ];
    let time = || prop_oneof![3 => 0.001..5.0f64, 1 => number()];
    (
        select(methods),
        time(),
        time(),
        prop_oneof![3 => 1e-12..1e-3f64, 1 => number()],
        prop::option::weighted(0.2, integer()),
        prop::bool::weighted(0.75),
        any::<(bool, bool)>(),
    )
        .prop_map(
            |(method, end, h, tol, max_steps, consistent, (step, tolerances))| {
                let adaptive = method.starts_with("dop");
                let (step, tolerances) = if consistent {
                    (!adaptive, adaptive && tolerances)
                } else {
                    (step, tolerances)
                };
                let mut table = vec![
                    ("method".to_owned(), Node::Str(method.into())),
                    ("end_time".to_owned(), Node::Num(end)),
                ];
                if step {
                    table.push(("step".into(), Node::Num(h / 100.0)));
                }
                if tolerances {
                    table.push(("rtol".into(), Node::Num(tol)));
                    table.push(("atol".into(), Node::Num(tol)));
                }
                if let Some(n) = max_steps {
                    table.push(("max_steps".into(), Node::Int(n)));
                }
                Node::Obj(table)
            },
        )
}

/// A `[model]` table: a symmetry and a kinematics, or neither, for the seed's family (another
/// family one time in five).
fn model_table() -> impl Strategy<Value = Node> {
    let families = Family::ALL.map(Family::name).to_vec();
    let symmetries = vec!["auto", "full", "xz", "principal"];
    let kinematics = Kinematics::ALL.map(Kinematics::name).to_vec();
    (
        prop::option::weighted(0.2, select(families)),
        prop::option::weighted(0.6, select(symmetries)),
        prop::option::weighted(0.6, select(kinematics)),
    )
        .prop_map(|(family, symmetry, kinematics)| {
            let named = [
                ("family", family),
                ("symmetry", symmetry),
                ("kinematics", kinematics),
            ];
            Node::Obj(
                named
                    .into_iter()
                    .filter_map(|(key, value)| Some((key.to_owned(), Node::Str(value?.into()))))
                    .collect(),
            )
        })
}

#[test]
fn mutated_scenes_never_panic() {
    let seeds = scene_seeds();
    let tables = (
        prop::option::weighted(0.2, sweep_table()),
        prop::option::weighted(0.3, integrator_table()),
        prop::option::weighted(0.2, model_table()),
    );
    let with_tables = (mutation(), tables).prop_map(|(mut m, (sweep, integrator, model))| {
        let named = [
            ("sweep", sweep),
            ("integrator", integrator),
            ("model", model),
        ];
        m.tables = named
            .into_iter()
            .filter_map(|(key, table)| Some((key.to_owned(), table?)))
            .collect();
        m
    });
    let strategy = (with_tables, prop::bool::weighted(0.3));
    fuzz("scenes", SCENE_CASES, strategy, |(m, run), tally| {
        scene_text(&m.apply(&seeds, Format::Toml), run, tally)
    });
}

/// A vehicle scene's text through the one reader: where it reads, its model was built and
/// proved; for `run`, the cruise found and two seconds of its first manoeuvre run.
fn vehicle_scene_text(text: &str, run: bool, tally: &mut Tally) -> Result<(), TestCaseError> {
    tally.count("input");
    remember(text.as_bytes());
    let base = root().join("scenes");
    let read = guarded("AnyScene::parse", text, || {
        AnyScene::parse(text, "fuzz.toml", &base)
    })?;
    let scene = match read {
        Ok(scene) => match scene.downcast::<VehicleScene>() {
            Some(scene) => *scene,
            None => return Ok(()),
        },
        Err(error) => return check_scene_error(&error, text, tally),
    };
    tally.count("vehicle scene read");
    if run {
        let first = &scene.manoeuvres[0];
        let short = VehicleManoeuvre {
            duration: first.duration.min(2.0),
            ..first.clone()
        };
        // At most 10⁴ steps and rows: the run is for panics, not for figures.
        let mut stepper = scene.stepper.clone();
        stepper.step = stepper.step.map(|step| step.max(short.duration / 1e4));
        let every = scene.every.max(short.duration / 1e4);
        let result = guarded("vehicle run", text, || {
            let start = scene.start()?;
            run_vehicle(
                &scene.model,
                &scene.fins,
                &short,
                start,
                (&stepper, every),
                |_| true,
            )
        })?;
        match result {
            Ok(_) => tally.count("vehicle run ok"),
            Err(error) if !error.to_string().trim().is_empty() => {
                tally.count("vehicle run stopped")
            }
            Err(_) => return Err(failure("a vehicle run", text, "an empty error")),
        }
    }
    Ok(())
}

#[test]
fn mutated_vehicle_scenes_never_panic() {
    // REMUS in SI, the NPS AUV II in the prime system.
    let seeds: Vec<Seed> = ["remus100.toml", "nps_auv2.toml"]
        .iter()
        .map(|name| toml_seed(std::fs::read_to_string(root().join("scenes").join(name)).unwrap()))
        .collect();
    let strategy = (mutation(), prop::bool::weighted(0.3));
    fuzz(
        "vehicle scenes",
        VEHICLE_CASES,
        strategy,
        |(m, run), tally| vehicle_scene_text(&m.apply(&seeds, Format::Toml), run, tally),
    );
}

/// An aircraft scene's text through the one reader: where it reads, its model was built and
/// trimmed; for `run`, two seconds of its first manoeuvre from the trim.
fn aircraft_scene_text(text: &str, run: bool, tally: &mut Tally) -> Result<(), TestCaseError> {
    tally.count("input");
    remember(text.as_bytes());
    let base = root().join("scenes");
    let read = guarded("AnyScene::parse", text, || {
        AnyScene::parse(text, "fuzz.toml", &base)
    })?;
    let scene = match read {
        Ok(scene) => match scene.downcast::<AircraftScene>() {
            Some(scene) => *scene,
            None => return Ok(()),
        },
        Err(error) => return check_scene_error(&error, text, tally),
    };
    tally.count("aircraft scene read");
    if !scene
        .trim
        .state
        .iter()
        .chain(&scene.trim.controls)
        .all(|x| x.is_finite())
    {
        return Err(failure(
            "an aircraft's trim",
            text,
            "a trim that is not finite",
        ));
    }
    if run {
        let first = &scene.manoeuvres[0];
        let short = AircraftManoeuvre {
            duration: first.duration.min(2.0),
            ..first.clone()
        };
        // At most 10⁴ steps and rows: the run is for panics, not for figures.
        let mut stepper = scene.stepper.clone();
        stepper.step = stepper.step.map(|step| step.max(short.duration / 1e4));
        let every = scene.every.max(short.duration / 1e4);
        let result = guarded("aircraft run", text, || {
            let trim = (&scene.trim.state, &scene.trim.controls);
            run_aircraft(
                &scene.model,
                scene.kinematics,
                &short,
                trim,
                (&stepper, every),
                None,
                |_| true,
            )
        })?;
        match result {
            Ok(_) => tally.count("aircraft run ok"),
            Err(error) if !error.to_string().trim().is_empty() => {
                tally.count("aircraft run stopped")
            }
            Err(_) => return Err(failure("an aircraft run", text, "an empty error")),
        }
    }
    Ok(())
}

#[test]
fn mutated_aircraft_scenes_never_panic() {
    let seeds: Vec<Seed> = ["f16.toml", "navion.toml"]
        .iter()
        .map(|name| toml_seed(std::fs::read_to_string(root().join("scenes").join(name)).unwrap()))
        .collect();
    let strategy = (mutation(), prop::bool::weighted(0.3));
    fuzz(
        "aircraft scenes",
        AIRCRAFT_CASES,
        strategy,
        |(m, run), tally| aircraft_scene_text(&m.apply(&seeds, Format::Toml), run, tally),
    );
}

// ---------------------------------------------------------------------------------------------
// `eom eval`.

const EVAL_SEEDS: &[&str] = &[
    r#"{"i0": 2, "mass": 3, "g": 9.81, "h": 0.5, "moment": 1,
        "state": {"theta": 1.5707963267948966, "theta_dot": 1.5}}"#,
    r#"{"mass": 5, "izz": 20, "force": [1, -2], "moment": 0.5,
        "state": {"u": 2, "v": -0.5, "r": 0.3, "x": 0, "y": 0, "psi": 0.7}}"#,
    r#"{"mass": 5, "izz": 20, "x_g": 0.3, "force": [1, -2], "moment": 0.5,
        "state": {"u": 2, "v": -0.5, "r": 0.3, "x": 0, "y": 0, "psi": 0.7}}"#,
    r#"{"mass": 4, "izz": 8, "force": [2, -6], "moment": 1,
        "state": {"x": 1, "y": 2, "psi": 3, "x_dot": 4, "y_dot": 5, "psi_dot": 6}}"#,
    r#"{"mass": 2.0, "inertia": [[2,0,0],[0,3,0],[0,0,4]],
        "state": {"u": 1, "v": 0, "w": 0, "p": 0, "q": 0, "r": 0.5, "phi": 0, "theta": 0, "psi": 0},
        "force": [2, 0, 0], "moment": [0, 0, 4]}"#,
    r#"{"mass": 2.0, "inertia": [[2,0,-0.1],[0,3,0],[-0.1,0,4]],
        "state": {"u": 1, "v": 0.5, "w": -0.2, "p": 0.1, "q": 0.2, "r": 0.3,
                  "phi": 0.1, "theta": 0.2, "psi": 0.3},
        "force": [1, 0, 0], "moment": [0, 0, 0.5]}"#,
    r#"{"mass": 2.0, "inertia": [[2,0.2,-0.1],[0.2,3,0.05],[-0.1,0.05,4]],
        "state": {"u": 1, "v": 0.5, "w": -0.2, "p": 0.1, "q": 0.2, "r": 0.3,
                  "phi": 0.1, "theta": 1.5707963267948966, "psi": 0.3},
        "force": [1, 0, 0], "moment": [0, 0, 0.5]}"#,
];

/// The model `eom eval` is asked for: seed `i`'s own family most of the time.
#[derive(Debug, Clone)]
struct EvalCase {
    mutation: Mutation,
    family: Option<Family>,
    symmetry: Symmetry,
    kinematics: Kinematics,
}

fn seed_family(seed: usize) -> Family {
    [
        Family::Pendulum,
        Family::PlanarAtG,
        Family::PlanarMidship,
        Family::PlanarSpaceFixed,
    ]
    .get(seed)
    .copied()
    .unwrap_or(Family::Spatial)
}

#[test]
fn mutated_eval_inputs_never_panic() {
    let seeds: Vec<Seed> = EVAL_SEEDS.iter().map(|s| json_seed(s)).collect();
    let strategy = (
        mutation(),
        prop::option::weighted(0.2, select(Family::ALL.to_vec())),
        select(Symmetry::ALL.to_vec()),
        select(Kinematics::ALL.to_vec()),
    )
        .prop_map(|(mutation, family, symmetry, kinematics)| EvalCase {
            mutation,
            family,
            symmetry,
            kinematics,
        });
    fuzz("eval", EVAL_CASES, strategy, |case, tally| {
        let text = case.mutation.apply(&seeds, Format::Json);
        let seed = case.mutation.seed.index(seeds.len());
        let family = case.family.unwrap_or(seed_family(seed));
        eval_text(&text, family, case.symmetry, case.kinematics, tally)
    });
}

fn eval_text(
    text: &str,
    family: Family,
    symmetry: Symmetry,
    kinematics: Kinematics,
    tally: &mut Tally,
) -> Result<(), TestCaseError> {
    tally.count("input");
    remember(text.as_bytes());
    let result = guarded("eval::evaluate", text, || {
        evaluate(text, family, symmetry, kinematics)
    })?;
    match result {
        Ok(evaluation) => {
            tally.count("evaluated");
            let values = evaluation.generated.iter().chain(&evaluation.generic);
            let same_keys = evaluation
                .generated
                .iter()
                .map(|(k, _)| k)
                .eq(evaluation.generic.iter().map(|(k, _)| k));
            if evaluation.generated.is_empty()
                || !same_keys
                || values.into_iter().any(|(_, x)| !x.is_finite())
            {
                return Err(failure("an evaluation", text, format!("{evaluation:?}")));
            }
        }
        Err(error) => {
            let cause = error.root_cause().to_string();
            tally.count(format!("refused ({})", words(&cause, 2)));
            if error
                .chain()
                .any(|cause| cause.to_string().trim().is_empty())
            {
                return Err(failure("an eval error", text, format!("{error:#}")));
            }
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Body files.

const EXTRA_BODIES: &[&str] = &[
    r#"[[part]]
name = "payload"
kind = "tensor"
mass = 12.0
inertia = [2.0, 3.0, 4.0, 0.1, -0.2, 0.05]
offset = [0.5, 0.0, -0.1]
rotation_deg = [10.0, 20.0, 30.0]
[[part]]
kind = "ellipsoid"
mass = 3.0
size = [2.0, 1.0, 0.5]
rotation_deg = [0.0, 0.0, 45.0]
[[part]]
kind = "sphere"
mass = 1.0
radius = 0.25
offset = [-1.0, 0.2, 0.0]
"#,
    r#"[[part]]
kind = "point"
mass = 1.0
offset = [1.0, 0.0, 0.0]
[[part]]
kind = "point"
mass = 1.0
offset = [0.0, 1.0, 0.0]
[[part]]
kind = "point"
mass = 1.0
offset = [0.0, 0.0, 1.0]
"#,
    r#"[[part]]
kind = "mesh"
path = "deckhouse.stl"
mass = 800.0
rotation_deg = [0.0, 0.0, 90.0]
"#,
];

fn body_seeds() -> Vec<Seed> {
    let ship = std::fs::read_to_string(root().join("scenes/bodies/ship_blocks.toml")).unwrap();
    std::iter::once(ship)
        .chain(EXTRA_BODIES.iter().map(|s| s.to_string()))
        .map(toml_seed)
        .collect()
}

/// A folder with the shipped deckhouse and a few broken meshes beside it, for the bodies'
/// `path`s.
fn mesh_folder() -> PathBuf {
    let folder = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fuzz_inputs_meshes");
    std::fs::create_dir_all(&folder).unwrap();
    let deckhouse = std::fs::read(root().join("scenes/bodies/deckhouse.stl")).unwrap();
    std::fs::write(folder.join("deckhouse.stl"), &deckhouse).unwrap();
    let tetra = tetrahedron();
    let write = |name: &str, triangles: &[[[f32; 3]; 3]], binary: bool| {
        let bytes = if binary {
            binary_stl(triangles, None, false)
        } else {
            ascii_stl(triangles).into_bytes()
        };
        std::fs::write(folder.join(name), bytes).unwrap();
    };
    write("open.stl", &tetra[1..], false);
    let inside_out: Vec<_> = tetra.iter().map(|&[a, b, c]| [a, c, b]).collect();
    write("inside_out.stl", &inside_out, true);
    let flat: Vec<_> = tetra
        .iter()
        .map(|t| t.map(|[x, y, _]| [x, y, 0.0]))
        .collect();
    write("flat.stl", &flat, false);
    write("binary.stl", &tetra, true);
    std::fs::write(folder.join("garbage.stl"), b"solid x\nfacet normal\n").unwrap();
    folder
}

fn body_text(text: &str, base: &Path, tally: &mut Tally) -> Result<(), TestCaseError> {
    tally.count("input");
    remember(text.as_bytes());
    let body = match guarded("BodyFile::parse", text, || BodyFile::parse(text, base))? {
        Ok(body) => body,
        Err(error) => {
            tally.count(format!("refused ({})", variant(&error)));
            return body_error(&error, text);
        }
    };
    match guarded("BodyFile::mass_properties", text, || body.mass_properties())? {
        Ok(properties) => {
            tally.count("accepted");
            // What `eom mass` prints of it.
            let (principal, radii, about) = guarded("MassProperties", text, || {
                (
                    properties.principal(),
                    properties.radii_of_gyration(),
                    properties.inertia_about(&Vector3::new(1.0, -2.0, 3.0)),
                )
            })?;
            let finite = properties.mass().is_finite()
                && properties.centre_of_gravity().iter().all(|x| x.is_finite())
                && principal.moments.iter().all(|x| x.is_finite())
                && radii.iter().all(|x| x.is_finite());
            if !finite {
                return Err(failure("mass properties", text, format!("{properties:?}")));
            }
            if let Err(error) = about {
                tally.count("refused about a point");
                if error.to_string().trim().is_empty() {
                    return Err(failure("inertia_about", text, "an empty message"));
                }
            }
            Ok(())
        }
        Err(error) => {
            tally.count("refused as a whole");
            body_error(&error, text)
        }
    }
}

fn body_error(error: &BodyFileError, text: &str) -> Result<(), TestCaseError> {
    let inner = match error {
        BodyFileError::Part { error, .. } => error.to_string(),
        other => other.to_string(),
    };
    if inner.trim().is_empty() {
        return Err(failure(
            "body file error",
            text,
            format!("an empty message: {error}"),
        ));
    }
    // Syntax is the class of text that is not TOML, a key beside `part`, or a `part` that is
    // not a list; everything else is a part's fault, or the parts' together.
    let syntax = match text.parse::<toml::Table>() {
        Err(_) => true,
        Ok(table) => {
            table.keys().any(|k| k != "part")
                || !matches!(table.get("part"), None | Some(toml::Value::Array(_)))
        }
    };
    if matches!(error, BodyFileError::Syntax(_)) != syntax {
        return Err(failure(
            "body file error",
            text,
            format!("of the wrong class: {error}"),
        ));
    }
    Ok(())
}

#[test]
fn mutated_body_files_never_panic() {
    let seeds = body_seeds();
    let base = mesh_folder();
    fuzz("body files", BODY_CASES, mutation(), |m, tally| {
        body_text(&m.apply(&seeds, Format::Toml), &base, tally)
    });
}

// ---------------------------------------------------------------------------------------------
// STL meshes.

fn tetrahedron() -> Vec<[[f32; 3]; 3]> {
    let v = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
        .iter()
        .map(|t: &[usize; 3]| t.map(|i| v[i]))
        .collect()
}

fn cube() -> Vec<[[f32; 3]; 3]> {
    let v = |i: usize| [(i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32];
    // Each face as two triangles, counter-clockwise seen from outside.
    let faces = [
        [0, 2, 3, 1], // z = 0
        [4, 5, 7, 6], // z = 1
        [0, 1, 5, 4], // y = 0
        [2, 6, 7, 3], // y = 1
        [0, 4, 6, 2], // x = 0
        [1, 3, 7, 5], // x = 1
    ];
    faces
        .iter()
        .flat_map(|[a, b, c, d]| [[v(*a), v(*b), v(*c)], [v(*a), v(*c), v(*d)]])
        .collect()
}

fn octahedron() -> Vec<[[f32; 3]; 3]> {
    let v = [
        [1.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
    ];
    let mut triangles = Vec::new();
    for (x, y) in [(0, 2), (2, 1), (1, 3), (3, 0)] {
        triangles.push([v[x], v[y], v[4]]);
        triangles.push([v[y], v[x], v[5]]);
    }
    triangles
}

fn ascii_stl(triangles: &[[[f32; 3]; 3]]) -> String {
    let mut text = String::from("solid fuzz\n");
    for t in triangles {
        text += "  facet normal 0 0 0\n    outer loop\n";
        for [x, y, z] in t {
            writeln!(text, "      vertex {x:e} {y:e} {z:e}").unwrap();
        }
        text += "    endloop\n  endfacet\n";
    }
    text + "endsolid fuzz\n"
}

fn binary_stl(triangles: &[[[f32; 3]; 3]], count: Option<u32>, solid_header: bool) -> Vec<u8> {
    let mut bytes = vec![0u8; 80];
    if solid_header {
        bytes[..6].copy_from_slice(b"solid ");
    }
    let count = count.unwrap_or(triangles.len() as u32);
    bytes.extend(count.to_le_bytes());
    for t in triangles {
        bytes.extend([0u8; 12]);
        for coordinate in t.iter().flatten() {
            bytes.extend(coordinate.to_le_bytes());
        }
        bytes.extend([0u8; 2]);
    }
    bytes
}

/// A change to a mesh before it is written.
#[derive(Debug, Clone)]
enum MeshEdit {
    /// Scale and move every vertex.
    Affine(f32, f32),
    /// Set one coordinate of one corner.
    Coordinate(Index, u8, f32),
    /// Put one corner onto another.
    Collapse(Index, Index),
    /// Reverse a triangle's winding.
    Flip(Index),
    Drop(Index),
    Duplicate(Index),
}

#[derive(Debug, Clone)]
enum Encoding {
    Ascii(Vec<LineEdit>),
    Binary {
        count: Option<u32>,
        solid_header: bool,
        bytes: Vec<(Index, u8)>,
        cut: Option<Index>,
    },
}

#[derive(Debug, Clone)]
struct StlCase {
    shape: usize,
    soup: Vec<[[f32; 3]; 3]>,
    edits: Vec<MeshEdit>,
    encoding: Encoding,
    mass: MeshMass,
}

fn special_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        3 => -2.0..2.0f32,
        2 => select(vec![
            0.0, -0.0, 1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY, f32::MAX, -f32::MAX,
            f32::MIN_POSITIVE, 1e-45, 1e-20, 1e20, 1e30, 1e38,
        ]),
        1 => any::<f32>(),
    ]
}

fn stl_case() -> impl Strategy<Value = StlCase> {
    let corner = || [special_f32(), special_f32(), special_f32()];
    let soup = prop::collection::vec([corner(), corner(), corner()], 1..6);
    let edit = prop_oneof![
        (special_f32(), special_f32()).prop_map(|(s, o)| MeshEdit::Affine(s, o)),
        (any::<Index>(), 0..3u8, special_f32()).prop_map(|(i, c, x)| MeshEdit::Coordinate(i, c, x)),
        (any::<Index>(), any::<Index>()).prop_map(|(a, b)| MeshEdit::Collapse(a, b)),
        any::<Index>().prop_map(MeshEdit::Flip),
        any::<Index>().prop_map(MeshEdit::Drop),
        any::<Index>().prop_map(MeshEdit::Duplicate),
    ];
    let encoding = prop_oneof![
        prop_oneof![
            2 => Just(Vec::new()),
            1 => prop::collection::vec(line_edit(), 1..3),
        ]
        .prop_map(Encoding::Ascii),
        (
            prop::option::weighted(0.2, prop_oneof![0..10u32, Just(u32::MAX)]),
            prop::bool::weighted(0.1),
            prop::collection::vec((any::<Index>(), any::<u8>()), 0..2),
            prop::option::weighted(0.1, any::<Index>()),
        )
            .prop_map(|(count, solid_header, bytes, cut)| Encoding::Binary {
                count,
                solid_header,
                bytes,
                cut,
            }),
    ];
    let mass = prop_oneof![
        (0.0..1e4f64).prop_map(MeshMass::Density),
        (0.0..1e4f64).prop_map(MeshMass::Total),
        special_f64().prop_map(MeshMass::Density),
        special_f64().prop_map(MeshMass::Total),
    ];
    (
        prop_oneof![3 => 0..3usize, 1 => Just(3usize)],
        soup,
        prop::collection::vec(edit, 0..3),
        encoding,
        mass,
    )
        .prop_map(|(shape, soup, edits, encoding, mass)| StlCase {
            shape,
            soup,
            edits,
            encoding,
            mass,
        })
}

impl StlCase {
    fn bytes(&self) -> Vec<u8> {
        let mut triangles = match self.shape {
            0 => tetrahedron(),
            1 => cube(),
            2 => octahedron(),
            _ => self.soup.clone(),
        };
        for edit in &self.edits {
            let n = triangles.len();
            if n == 0 {
                break;
            }
            match edit {
                MeshEdit::Affine(scale, offset) => {
                    for x in triangles.iter_mut().flatten().flatten() {
                        *x = *x * scale + offset;
                    }
                }
                MeshEdit::Coordinate(i, c, x) => {
                    let at = i.index(n * 3);
                    triangles[at / 3][at % 3][*c as usize] = *x;
                }
                MeshEdit::Collapse(a, b) => {
                    let (a, b) = (a.index(n * 3), b.index(n * 3));
                    triangles[a / 3][a % 3] = triangles[b / 3][b % 3];
                }
                MeshEdit::Flip(i) => triangles[i.index(n)].swap(1, 2),
                MeshEdit::Drop(i) => {
                    triangles.remove(i.index(n));
                }
                MeshEdit::Duplicate(i) => {
                    let t = triangles[i.index(n)];
                    triangles.push(t);
                }
            }
        }
        match &self.encoding {
            Encoding::Ascii(edits) => {
                let mut text = ascii_stl(&triangles);
                for edit in edits {
                    text = apply_line(&text, edit, Format::Toml);
                }
                text.into_bytes()
            }
            Encoding::Binary {
                count,
                solid_header,
                bytes: changes,
                cut,
            } => {
                let mut bytes = binary_stl(&triangles, *count, *solid_header);
                for (i, byte) in changes {
                    let at = i.index(bytes.len());
                    bytes[at] = *byte;
                }
                if let Some(cut) = cut {
                    bytes.truncate(cut.index(bytes.len()));
                }
                bytes
            }
        }
    }
}

fn stl_bytes(bytes: &[u8], mass: MeshMass, tally: &mut Tally) -> Result<(), TestCaseError> {
    tally.count("input");
    remember(bytes);
    let shown = || {
        if bytes.is_ascii() {
            String::from_utf8_lossy(bytes).into_owned()
        } else {
            format!("{bytes:?}")
        }
    };
    let mesh = match guarded("Mesh::read_stl", &shown(), || {
        Mesh::read_stl(&mut Cursor::new(bytes))
    })? {
        Ok(mesh) => mesh,
        Err(error) => {
            tally.count(format!("refused ({})", variant(&error)));
            if error.to_string().trim().is_empty() {
                return Err(failure("a mesh error", &shown(), "an empty message"));
            }
            return Ok(());
        }
    };
    tally.count("read");
    let (properties, written) = guarded("Mesh", &shown(), || {
        let _ = mesh.volume();
        let mut written = Vec::new();
        mesh.write_stl(&mut written).unwrap();
        (mesh.mass_properties(mass), written)
    })?;
    match properties {
        Ok(p) => {
            tally.count("solid");
            if !(p.mass() > 0.0 && p.centre_of_gravity().iter().all(|x| x.is_finite())) {
                return Err(failure("mesh mass properties", &shown(), format!("{p:?}")));
            }
        }
        Err(error) => {
            tally.count(format!("not a solid ({})", variant(&error)));
            if error.to_string().trim().is_empty() {
                return Err(failure("a mesh error", &shown(), "an empty message"));
            }
        }
    }
    // What is written reads back as the same mesh, to binary STL's f32 coordinates: the
    // triangles survive, and each vertex is the one read, rounded to f32 (an ASCII mesh is read
    // to f64, so two vertices that differ beyond f32 may merge when written).
    let rounded = |v: &nalgebra::Vector3<f64>| v.map(|x| f64::from(x as f32));
    match guarded("Mesh::read_stl (written)", &shown(), || {
        Mesh::read_stl(&mut Cursor::new(&written))
    })? {
        Ok(again)
            if again.triangle_count() == mesh.triangle_count()
                && again
                    .vertices()
                    .iter()
                    .all(|v| mesh.vertices().iter().any(|w| rounded(w) == *v)) =>
        {
            Ok(())
        }
        other => Err(failure(
            "a written mesh",
            &shown(),
            format!("reads back as {other:?}"),
        )),
    }
}

#[test]
fn random_stl_meshes_never_panic() {
    fuzz("STL meshes", STL_CASES, stl_case(), |case, tally| {
        stl_bytes(&case.bytes(), case.mass, tally)?;
        // The same corners through Mesh::new, unmerged: indices as they come.
        let triangles = match case.shape {
            3 => case.soup.clone(),
            _ => tetrahedron(),
        };
        let vertices: Vec<Vector3<f64>> = triangles
            .iter()
            .flatten()
            .map(|v| Vector3::from(v.map(f64::from)))
            .collect();
        let indices: Vec<[usize; 3]> = (0..triangles.len())
            .map(|t| {
                [
                    3 * t,
                    3 * t + 1,
                    (3 * t + 2 + case.shape) % (vertices.len() + 2),
                ]
            })
            .collect();
        let text = format!("{vertices:?} {indices:?}");
        if let Ok(mesh) = guarded("Mesh::new", &text, || Mesh::new(vertices, indices))? {
            guarded("Mesh::mass_properties", &text, || {
                mesh.mass_properties(case.mass)
            })?
            .ok();
        }
        Ok(())
    });
}

// ---------------------------------------------------------------------------------------------
// Random bytes, into every parser.

#[test]
fn random_bytes_never_panic() {
    let base = mesh_folder();
    let strategy = prop_oneof![
        prop::collection::vec(any::<u8>(), 0..300),
        "\\PC{0,200}".prop_map(String::into_bytes),
        // TOML-looking and JSON-looking noise.
        prop::collection::vec(line(), 0..12).prop_map(|l| l.join("\n").into_bytes()),
        prop::collection::vec(
            select(vec![
                "{", "}", "[", "]", ":", ",", "\"mass\"", "1", "-0.5e3", "null", " "
            ]),
            0..40
        )
        .prop_map(|t| t.concat().into_bytes()),
    ];
    fuzz("random bytes", BYTES_CASES, strategy, |bytes, tally| {
        let text = String::from_utf8_lossy(&bytes);
        scene_text(&text, false, tally)?;
        body_text(&text, &base, tally)?;
        for family in Family::ALL {
            eval_text(&text, family, Symmetry::Full, Kinematics::Quaternion, tally)?;
        }
        stl_bytes(&bytes, MeshMass::Density(1.0), tally)
    });
}
