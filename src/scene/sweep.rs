//! Sweeps: one scene file, many runs.
//!
//! A `[sweep]` table names scene values by their path and gives each a list of values or a
//! linear range:
//!
//! ```toml
//! [sweep]
//! "body.mass" = [1.0, 2.0, 4.0]
//! "initial.theta_deg" = { from = 10.0, to = 170.0, count = 9 }
//! ```
//!
//! The cases are every combination, in a fixed order (keys sorted, the last key varying
//! fastest), numbered from 0, so that case `k` is the same case on every machine: a batch
//! scheduler can give machine `K` of `N` the cases `k ≡ K (mod N)` (`--shard K/N`) and the
//! per-case summaries concatenate. Each machine makes only its own shard's cases, and the
//! limit of [`MAX_CASES`] applies to them, not to the whole sweep.

use super::{Problem, SceneError};
use toml::{Table, Value};

/// The most cases one run of a sweep may have: the whole sweep, or one shard of it
/// (`--shard K/N`), so that a sweep too large for one machine can be spread over many. The
/// cases are made before the first runs, so a count beyond this is refused rather than tried.
pub const MAX_CASES: usize = 100_000;

/// `key = value, …`.
fn label(values: &[(String, Value)]) -> String {
    let pairs: Vec<String> = values
        .iter()
        .map(|(key, value)| format!("{key} = {value}"))
        .collect();
    pairs.join(", ")
}

/// Whether scene text has a `[sweep]` table (false for text that is not TOML: reading its
/// cases says what is wrong with it).
pub fn is_swept(text: &str) -> bool {
    text.parse::<Table>()
        .is_ok_and(|table| table.contains_key("sweep"))
}

/// The cases of scene text, as tables: one case (the scene as written) when it has no
/// `[sweep]`. Each is read as a scene of its kind by [`super::AnyScene::from_table`].
pub fn cases(text: &str, name: &str) -> Result<Vec<TableCase>, SceneError> {
    shard_tables(text, name, None)
}

/// One case of a sweep as a TOML table, before it is read as a scene of its kind.
#[derive(Debug, Clone)]
pub struct TableCase {
    /// The case's number, from 0.
    pub index: usize,
    /// The swept keys and the values this case gives them.
    pub values: Vec<(String, Value)>,
    /// The scene's table with those values set, its `[sweep]` taken out.
    pub table: Table,
}

impl TableCase {
    /// Each swept key's value as JSON, by key: TOML's numbers, strings, booleans and arrays
    /// as the scene gave them (a summary's `"case"`).
    pub fn values_json(&self) -> std::collections::BTreeMap<String, serde_json::Value> {
        (self.values.iter())
            .map(|(key, value)| {
                let value = serde_json::to_value(value).unwrap_or(serde_json::Value::Null);
                (key.clone(), value)
            })
            .collect()
    }

    /// The case read as a scene file of type `T`, errors naming the key.
    pub fn read<T: serde::de::DeserializeOwned>(&self, name: &str) -> Result<T, SceneError> {
        read_table(self.table.clone(), name)
    }

    /// The case's values as `key = value, …`, for its title and messages.
    pub fn label(&self) -> String {
        label(&self.values)
    }
}

/// The cases of one shard `(K, N)` of scene text, the cases k ≡ K (mod N), or every case
/// with `None`, as tables, for a scene of any kind; at most [`MAX_CASES`] of them, whatever
/// the whole sweep's count. A key may
/// name an entry of an array of tables by its index: `"manoeuvre[0].rudder_deg"`.
pub fn shard_tables(
    text: &str,
    name: &str,
    shard: Option<(usize, usize)>,
) -> Result<Vec<TableCase>, SceneError> {
    let error = |key: &str, problem| SceneError::new(name, key, problem);
    let mut table: Table = text
        .parse()
        .map_err(|e: toml::de::Error| error("", Problem::Syntax(e.to_string())))?;
    let sweep = match table.remove("sweep") {
        None => Table::new(),
        Some(Value::Table(sweep)) => sweep,
        Some(_) => return Err(error("sweep", Problem::Schema("must be a table".into()))),
    };
    let (k, n) = shard.unwrap_or((0, 1));
    let mut axes: Vec<(String, Axis)> = Vec::new();
    let mut count = 1usize;
    for (key, spec) in sweep {
        let path = format!("sweep.{key}");
        let axis = Axis::new(&key, spec).map_err(|p| error(&path, p))?;
        count = count.checked_mul(axis.len()).ok_or_else(|| {
            error(
                &path,
                Problem::Invalid(
                    "with this key the sweep has more cases than can be counted".into(),
                ),
            )
        })?;
        let in_shard = count.saturating_sub(k).div_ceil(n);
        if in_shard > MAX_CASES {
            let message = format!(
                "with this key {} has more than {MAX_CASES} cases; spread it over more shards \
                 (--shard K/N)",
                if shard.is_some() {
                    "the shard"
                } else {
                    "the sweep"
                }
            );
            return Err(error(&path, Problem::Invalid(message)));
        }
        axes.push((key, axis));
    }
    (k..count)
        .step_by(n)
        .map(|index| {
            let values = combination(&axes, index);
            let mut case = table.clone();
            for (key, value) in &values {
                set(&mut case, key, value.clone())
                    .map_err(|p| error(&format!("sweep.{key}"), p))?;
            }
            Ok(TableCase {
                index,
                values,
                table: case,
            })
        })
        .collect()
}

/// The values of one swept key: a list, or `{ from, to, count }` evenly spaced (made when a
/// case asks, so that a range may be as long as the sweep's count allows).
#[derive(Debug)]
enum Axis {
    List(Vec<Value>),
    Range { from: f64, to: f64, count: usize },
}

impl Axis {
    fn new(key: &str, spec: Value) -> Result<Self, Problem> {
        match spec {
            Value::Array(values) if !values.is_empty() => Ok(Axis::List(values)),
            Value::Table(range) => range_axis(&range),
            _ => Err(Problem::Schema(format!(
                "`{key}` must be a non-empty list of values or {{ from, to, count }}"
            ))),
        }
    }

    fn len(&self) -> usize {
        match self {
            Axis::List(values) => values.len(),
            Axis::Range { count, .. } => *count,
        }
    }

    fn get(&self, i: usize) -> Value {
        match self {
            Axis::List(values) => values[i].clone(),
            Axis::Range { from, to, count } => Value::Float(range_point(*from, *to, *count, i)),
        }
    }
}

/// Point `i` of `count` evenly spaced from `from` to `to`, the ends exactly as written: the
/// decimal of fewest significant digits within 10⁻¹² of a step of the evenly spaced point, so
/// that 0 to 1 in 11 gives 0.3 as the user means it, not the 0.30000000000000004 that
/// `0 + 3·0.1` rounds to (a label, a sweep.csv column and the case's scene all read it).
fn range_point(from: f64, to: f64, count: usize, i: usize) -> f64 {
    if i == 0 {
        return from;
    }
    if i + 1 == count {
        return to;
    }
    let intervals = (count - 1) as f64;
    let even = from + (to - from) * (i as f64 / intervals);
    let tolerance = 1e-12 * ((to - from) / intervals).abs();
    (0..17)
        .filter_map(|decimals| format!("{even:.decimals$e}").parse::<f64>().ok())
        .find(|decimal| (decimal - even).abs() <= tolerance)
        .unwrap_or(even)
}

/// `{ from, to, count }`: finite ends and an integer count of at least 2.
fn range_axis(range: &Table) -> Result<Axis, Problem> {
    let number = |k: &str| match range.get(k) {
        Some(Value::Float(x)) => Ok(*x),
        Some(Value::Integer(n)) => Ok(*n as f64),
        _ => Err(Problem::Schema(format!("a range needs a number `{k}`"))),
    };
    let (from, to) = (number("from")?, number("to")?);
    let count = match range.get("count") {
        Some(Value::Integer(n)) if *n >= 2 => *n,
        _ => {
            return Err(Problem::Schema(
                "a range needs an integer `count` of at least 2".into(),
            ));
        }
    };
    let count = usize::try_from(count)
        .map_err(|_| Problem::Invalid(format!("a range of {count} values cannot be counted")))?;
    if let Some(extra) = range
        .keys()
        .find(|k| !["from", "to", "count"].contains(&k.as_str()))
    {
        return Err(Problem::Schema(format!("unknown key `{extra}` in a range")));
    }
    if !(from.is_finite() && to.is_finite()) {
        return Err(Problem::Invalid("a range must have finite ends".into()));
    }
    Ok(Axis::Range { from, to, count })
}

/// The values of case `index`: the last axis varies fastest.
fn combination(axes: &[(String, Axis)], mut index: usize) -> Vec<(String, Value)> {
    let mut values = Vec::with_capacity(axes.len());
    for (key, axis) in axes.iter().rev() {
        values.push((key.clone(), axis.get(index % axis.len())));
        index /= axis.len();
    }
    values.reverse();
    values
}

/// Sets a dotted key (`body.mass`) of a scene table; the tables on the way must exist or are
/// made. A part `name[i]` is the `i`-th table of the array of tables `name`, which must exist
/// (`manoeuvre[0].rudder_deg`). A sweep sets its cases' values by it; a binding, a user's.
pub fn set(table: &mut Table, key: &str, value: Value) -> Result<(), Problem> {
    let mut parts: Vec<&str> = key.split('.').collect();
    let last = parts
        .pop()
        .filter(|p| !p.is_empty())
        .ok_or_else(|| Problem::Schema("an empty key".into()))?;
    let mut current = table;
    for part in parts {
        current = match indexed(part) {
            Some((array, i)) => table_in_array(current, array, i)?,
            None => match current
                .entry(part.to_owned())
                .or_insert_with(|| Value::Table(Table::new()))
            {
                Value::Table(t) => t,
                _ => return Err(Problem::Schema(format!("`{part}` is not a table"))),
            },
        };
    }
    current.insert(last.to_owned(), value);
    Ok(())
}

/// `("manoeuvre", 0)` of `manoeuvre[0]`.
fn indexed(part: &str) -> Option<(&str, usize)> {
    let (name, rest) = part.split_once('[')?;
    let index = rest.strip_suffix(']')?.parse().ok()?;
    Some((name, index))
}

/// The `i`-th table of the array `name` in `table`.
fn table_in_array<'a>(
    table: &'a mut Table,
    name: &str,
    i: usize,
) -> Result<&'a mut Table, Problem> {
    let missing = || Problem::Schema(format!("`{name}` has no table [{i}] to set a value in"));
    match table.get_mut(name) {
        Some(Value::Array(entries)) => match entries.get_mut(i) {
            Some(Value::Table(entry)) => Ok(entry),
            _ => Err(missing()),
        },
        _ => Err(missing()),
    }
}

/// A scene table as a scene file of type `T`, errors naming the key.
/// Reads a scene's tables, as [`super::read_as`] reads its text, each error named by its key.
pub(crate) fn read_table<T: serde::de::DeserializeOwned>(
    table: Table,
    name: &str,
) -> Result<T, SceneError> {
    serde_path_to_error::deserialize(Value::Table(table)).map_err(|e| {
        let key = e.path().to_string();
        let key = if key == "." { String::new() } else { key };
        let message = e.into_inner().message().to_owned();
        SceneError::new(name, &key, Problem::Schema(message))
    })
}

/// Parses `K/N` (shard `K` of `N`, counted from 0).
pub fn parse_shard(text: &str) -> Result<(usize, usize), String> {
    let (k, n) = text
        .split_once('/')
        .ok_or_else(|| format!("a shard is K/N, not `{text}`"))?;
    let (k, n): (usize, usize) = (
        k.trim()
            .parse()
            .map_err(|_| format!("K in K/N is a number, not `{k}`"))?,
        n.trim()
            .parse()
            .map_err(|_| format!("N in K/N is a number, not `{n}`"))?,
    );
    if n == 0 || k >= n {
        return Err(format!("a shard K/N needs 0 ≤ K < N, not {k}/{n}"));
    }
    Ok((k, n))
}

/// What each manoeuvre's columns are named by: its name, unless a swept key of its entry
/// may make it (`manoeuvre[0].rudder_deg` in `zigzag_10_10`, or its `name` itself) and the
/// scene does not give it one, then its position, `manoeuvre[0]`: a name made from a swept
/// value would give each case columns of its own, and shards that could not be merged.
/// `named_from` lists the keys a kind makes its names from.
pub fn manoeuvre_columns<'a>(
    case: &TableCase,
    names: impl Iterator<Item = &'a str>,
    named_from: &[&str],
) -> Vec<String> {
    let given = |index: usize| {
        let entry = case.table.get("manoeuvre").and_then(|m| m.get(index));
        entry.is_some_and(|m| m.get("name").is_some())
    };
    names
        .enumerate()
        .map(|(index, name)| {
            let swept = |key: &str| {
                let path = format!("manoeuvre[{index}].{key}");
                case.values.iter().any(|(k, _)| *k == path)
            };
            let named = given(index) && !swept("name");
            let made_from_swept = swept("name") || named_from.iter().any(|key| swept(key));
            match named || !made_from_swept {
                true => name.to_owned(),
                false => format!("manoeuvre[{index}]"),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCENE: &str = r#"
title = "t"
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
"#;

    /// The number a case sets at `table.key`.
    fn number(case: &TableCase, table: &str, key: &str) -> f64 {
        case.table[table][key].as_float().unwrap()
    }

    #[test]
    fn a_sweep_gives_every_combination_in_a_fixed_order() {
        let cases = cases(SCENE, "s.toml").unwrap();
        assert_eq!(cases.len(), 6);
        let pairs: Vec<(f64, f64)> = cases
            .iter()
            .map(|c| (number(c, "body", "mass"), number(c, "initial", "theta_deg")))
            .collect();
        assert_eq!(
            pairs,
            [
                (1.0, 10.0),
                (1.0, 20.0),
                (1.0, 30.0),
                (2.0, 10.0),
                (2.0, 20.0),
                (2.0, 30.0)
            ]
        );
        assert!(cases.iter().enumerate().all(|(i, c)| c.index == i));
    }

    #[test]
    fn a_range_gives_the_decimals_the_user_means_and_its_ends_as_written() {
        let points = |from, to, count| -> Vec<f64> {
            (0..count)
                .map(|i| range_point(from, to, count, i))
                .collect()
        };
        let tenths: Vec<f64> = (0..=10).map(|k| f64::from(k) / 10.0).collect();
        assert_eq!(points(0.0, 1.0, 11), tenths);
        assert_eq!(points(0.0, 0.3, 4), [0.0, 0.1, 0.2, 0.3]);
        assert_eq!(points(0.0, 30.0, 5), [0.0, 7.5, 15.0, 22.5, 30.0]);
        assert_eq!(points(-35.0, 35.0, 3), [-35.0, 0.0, 35.0]);
        // Thirds have no short decimal: within 10⁻¹² of a step of the even point, itself within
        // a rounding of k/3 (so 2·10⁻¹² of a step of k/3 is asked here).
        let thirds = points(0.0, 1.0, 4);
        for (k, point) in thirds.iter().enumerate() {
            assert!((point - k as f64 / 3.0).abs() <= 2e-12 / 3.0, "{thirds:?}");
        }
        // Ends exactly as written, whatever they are.
        assert_eq!(points(0.1 + 0.2, 1e-300, 3)[0], 0.1 + 0.2);
        assert_eq!(points(0.1 + 0.2, 1e-300, 3)[2], 1e-300);
        let text = SCENE.replace(
            "from = 10.0, to = 30.0, count = 3",
            "from = 0.0, to = 1.0, count = 11",
        );
        let cases = cases(&text, "s.toml").unwrap();
        assert_eq!(number(&cases[3], "initial", "theta_deg"), 0.3);
        assert_eq!(cases[3].label(), "body.mass = 1.0, initial.theta_deg = 0.3");
    }

    #[test]
    fn a_bad_sweep_names_its_key() {
        let text = SCENE.replace("[1.0, 2.0]", "3.0");
        let error = cases(&text, "s.toml").unwrap_err();
        assert_eq!(error.key, "sweep.body.mass");
        let text = SCENE.replace("count = 3", "count = 1");
        assert_eq!(
            cases(&text, "s.toml").unwrap_err().key,
            "sweep.initial.theta_deg"
        );
    }

    #[test]
    fn a_shard_makes_only_its_cases_and_the_cap_is_per_shard() {
        let shard: Vec<usize> = shard_tables(SCENE, "s.toml", Some((1, 4)))
            .unwrap()
            .iter()
            .map(|c| c.index)
            .collect();
        assert_eq!(shard, [1, 5]);
        let big = SCENE.replace("count = 3", &format!("count = {}", 3 * MAX_CASES));
        // 6·10⁵ cases: too many for one run, and for each of five shards; not for eight.
        let refusal = |shard| {
            shard_tables(&big, "s.toml", shard)
                .err()
                .map(|e| e.to_string())
        };
        let whole = refusal(None).unwrap_or_default();
        assert!(whole.contains("the sweep has more than"), "{whole}");
        let spread = refusal(Some((4, 5))).unwrap_or_default();
        assert!(spread.contains("the shard has more than"), "{spread}");
        assert_eq!(
            shard_tables(&big, "s.toml", Some((7, 8))).unwrap().len(),
            75_000
        );
    }

    #[test]
    fn a_key_may_name_a_table_of_an_array_by_its_index() {
        let text = "title = \"t\"\n[[manoeuvre]]\nrudder_deg = 35.0\n[[manoeuvre]]\nrudder_deg = 10.0\n\
                    [sweep]\n\"manoeuvre[1].rudder_deg\" = [5.0, 20.0]\n";
        let cases = shard_tables(text, "s.toml", None).unwrap();
        let rudder = |case: &TableCase, i: usize| {
            case.table["manoeuvre"][i]["rudder_deg"].as_float().unwrap()
        };
        assert_eq!(cases.len(), 2);
        assert_eq!((rudder(&cases[0], 0), rudder(&cases[0], 1)), (35.0, 5.0));
        assert_eq!((rudder(&cases[1], 0), rudder(&cases[1], 1)), (35.0, 20.0));
        let missing = text.replace("manoeuvre[1]", "manoeuvre[2]");
        let error = shard_tables(&missing, "s.toml", None).unwrap_err();
        assert_eq!(error.key, "sweep.manoeuvre[2].rudder_deg");
    }

    #[test]
    fn shards_are_k_of_n() {
        assert_eq!(parse_shard("2/5"), Ok((2, 5)));
        assert!(parse_shard("5/5").is_err());
        assert!(parse_shard("1").is_err());
        assert!(parse_shard("a/2").is_err());
    }
}
