//! Uncertainty: one scene, some of its values drawn from distributions, many cases (a Monte
//! Carlo), written in the scene itself.
//!
//! ```toml
//! [uncertainty]
//! cases = 10000
//! seed = 2026
//!
//! [uncertainty.vary]
//! "hydrodynamics.coefficients.*" = { distribution = "normal", sigma_relative = 0.10, truncate = 3.0 }
//! "hydrodynamics.design_speed" = { distribution = "uniform", low = 7.5, high = 7.9 }
//! ```
//!
//! Each key of `[uncertainty.vary]` is a key path of the scene (an entry of an array of
//! tables by its index, `manoeuvre[0].rudder_deg`), whose last part may be a pattern (`*`
//! stands for any run of characters: `hydrodynamics.coefficients.N*`); it names the numbers
//! the scene writes there, each varied on its own from the value the scene gives it. A path
//! that names no number of the scene, or a number two entries name, is refused: every value
//! varied is one the scene wrote, and by one law.
//!
//! **The laws.** `normal`: the scene's value plus σz, z standard normal, σ given as `sigma`
//! (in the key's unit) or `sigma_relative` (a fraction of the scene's value, so a value of
//! zero stays zero); with `truncate = t`, a z beyond ±t is drawn again (t ≥ 0.1, so that a
//! draw is kept at least once in thirteen). `uniform`: between `low` and `high`, or within
//! ±`relative` of the scene's value (a fraction of it).
//!
//! **The cases.** Case k draws its values from its own stream: ChaCha8 seeded by `seed`, on
//! stream k, the varied numbers in the order of their paths. A case is therefore the same in
//! any shard (`--shard K/N` runs k ≡ K (mod N)), on any number of threads, on any machine.
//! Each case is the scene's tables with its values set, read by the scene's kind as any
//! scene is ([`UncertaintyCase::table`]); a kind that derives its model from a table
//! (a ship's) derives it once per process and takes each case's values into it.

use super::sweep::{TableCase, set};
use super::{Problem, SceneError};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;
use serde::Deserialize;
use toml::{Table, Value};

/// The table that makes a scene a Monte Carlo.
pub const UNCERTAINTY_TABLE: &str = "uncertainty";

/// The most cases one run (or one shard) of a Monte Carlo may have: its outcomes are kept in
/// memory, a line each in its table.
pub const MAX_UNCERTAIN_CASES: usize = 1_000_000;

/// The smallest truncation, in standard deviations: a normal draw is kept with probability
/// 0.08 at 0.1σ, so that redrawing ends.
pub const MIN_TRUNCATION: f64 = 0.1;

/// Whether scene text has an `[uncertainty]` table (false for text that is not TOML).
pub fn is_uncertain(text: &str) -> bool {
    text.parse::<Table>()
        .is_ok_and(|table| table.contains_key(UNCERTAINTY_TABLE))
}

/// `[uncertainty]` as written (every kind's scene file takes it; [`Uncertainty::parse`] checks
/// it).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct UncertaintyTable {
    /// How many cases (required).
    pub cases: Option<usize>,
    /// The seed of every case's stream (required).
    pub seed: Option<u64>,
    /// The laws, by key path or pattern (required).
    pub vary: Option<toml::Table>,
}

/// One entry of `[uncertainty.vary]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct LawTable {
    distribution: String,
    sigma: Option<f64>,
    sigma_relative: Option<f64>,
    truncate: Option<f64>,
    low: Option<f64>,
    high: Option<f64>,
    relative: Option<f64>,
}

/// How one number is drawn, in the key's unit (a relative law already scaled by the scene's
/// value).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Distribution {
    /// The scene's value plus σz, z standard normal, redrawn beyond ±`truncate` where given.
    Normal {
        /// σ.
        sigma: f64,
        /// The truncation, in standard deviations.
        truncate: Option<f64>,
    },
    /// Uniform on [low, high].
    Uniform {
        /// The lower end.
        low: f64,
        /// The upper end.
        high: f64,
    },
}

/// One number the cases vary.
#[derive(Debug, Clone, PartialEq)]
pub struct Varied {
    /// Its key path in the scene (`hydrodynamics.coefficients.Yv`).
    pub key: String,
    /// The scene's value.
    pub nominal: f64,
    /// Its law.
    pub distribution: Distribution,
}

/// A scene's `[uncertainty]`, checked, with the scene's other tables: everything a case needs.
#[derive(Debug, Clone)]
pub struct Uncertainty {
    /// How many cases the whole Monte Carlo has.
    pub cases: usize,
    /// The seed of every case's stream.
    pub seed: u64,
    /// The numbers varied, in the order of their paths (the order each case draws them).
    pub varied: Vec<Varied>,
    /// The scene's tables, `[uncertainty]` taken out.
    table: Table,
}

/// One case of a Monte Carlo: its number and values, and the scene's tables with them set.
pub type UncertaintyCase = TableCase;

impl Uncertainty {
    /// Reads scene text's `[uncertainty]`; `name` is how errors name the file. Scene text
    /// without one, or with a `[sweep]` too, is refused.
    pub fn parse(text: &str, name: &str) -> Result<Self, SceneError> {
        let error = |key: &str, problem| SceneError::new(name, key, problem);
        let mut table: Table = text
            .parse()
            .map_err(|e: toml::de::Error| error("", Problem::Syntax(e.to_string())))?;
        let Some(written) = table.remove(UNCERTAINTY_TABLE) else {
            let missing = Problem::Missing("an [uncertainty] table".into());
            return Err(error(UNCERTAINTY_TABLE, missing));
        };
        if table.contains_key("sweep") {
            let message = "a scene has a [sweep] or an [uncertainty], not both: sweep one \
                           scene file per value of the other"
                .into();
            return Err(error(UNCERTAINTY_TABLE, Problem::Invalid(message)));
        }
        let Value::Table(written) = written else {
            let wrong = Problem::Schema("must be a table".into());
            return Err(error(UNCERTAINTY_TABLE, wrong));
        };
        // Read under its own name, so that an error names `uncertainty.cases`.
        let alone = Table::from_iter([(UNCERTAINTY_TABLE.to_owned(), Value::Table(written))]);
        let written = super::sweep::read_table::<UncertaintyFile>(alone, name)?.uncertainty;
        let missing = |key: &str, what: &str| error(key, Problem::Missing(what.to_owned()));
        let cases =
            (written.cases).ok_or_else(|| missing("uncertainty.cases", "how many cases"))?;
        let seed =
            (written.seed).ok_or_else(|| missing("uncertainty.seed", "the seed of the cases"))?;
        let vary = (written.vary.as_ref())
            .ok_or_else(|| missing("uncertainty.vary", "the values to vary and their laws"))?;
        if cases == 0 {
            let zero = Problem::Invalid("must be at least 1".into());
            return Err(error("uncertainty.cases", zero));
        }
        let mut varied: Vec<(Varied, String)> = Vec::new();
        for (path, law) in vary {
            let key = format!("uncertainty.vary.\"{path}\"");
            let law: LawTable = law
                .clone()
                .try_into()
                .map_err(|e: toml::de::Error| error(&key, Problem::Schema(e.message().into())))?;
            let numbers = numbers_at(&table, path).map_err(|p| error(&key, p))?;
            for (found, nominal) in numbers {
                if let Some((_, earlier)) = varied.iter().find(|(v, _)| v.key == found) {
                    let message =
                        format!("`{found}` is varied by `{earlier}` too: give each number one law");
                    return Err(error(&key, Problem::Invalid(message)));
                }
                let distribution = law.distribution(nominal).map_err(|p| error(&key, p))?;
                let number = Varied {
                    key: found,
                    nominal,
                    distribution,
                };
                varied.push((number, path.clone()));
            }
        }
        if varied.is_empty() {
            let none = Problem::Missing("at least one key path to vary".into());
            return Err(error("uncertainty.vary", none));
        }
        let mut varied: Vec<Varied> = varied.into_iter().map(|(v, _)| v).collect();
        varied.sort_by(|a, b| a.key.cmp(&b.key));
        Ok(Uncertainty {
            cases,
            seed,
            varied,
            table,
        })
    }

    /// The case numbers of shard `(K, N)`, k ≡ K (mod N) (every case with `None`), refused
    /// beyond [`MAX_UNCERTAIN_CASES`].
    pub fn shard(
        &self,
        shard: Option<(usize, usize)>,
        name: &str,
    ) -> Result<Vec<usize>, SceneError> {
        let (k, n) = shard.unwrap_or((0, 1));
        let count = self.cases.saturating_sub(k).div_ceil(n);
        if count > MAX_UNCERTAIN_CASES {
            let message = format!(
                "{count} cases in one run, more than {MAX_UNCERTAIN_CASES}; spread them over \
                 shards (--shard K/N)"
            );
            return Err(SceneError::new(
                name,
                "uncertainty.cases",
                Problem::Invalid(message),
            ));
        }
        Ok((k..self.cases).step_by(n).collect())
    }

    /// Case `index`'s values, each varied number in [`Uncertainty::varied`]'s order.
    pub fn values(&self, index: usize) -> Vec<f64> {
        let mut stream = ChaCha8Rng::seed_from_u64(self.seed);
        stream.set_stream(index as u64);
        (self.varied.iter())
            .map(|number| number.draw(&mut stream))
            .collect()
    }

    /// Case `index`: its values, and the scene's tables with them set, for its kind to read.
    pub fn case(&self, index: usize) -> UncertaintyCase {
        let drawn = self.values(index);
        let table = self.table_with(&drawn);
        let values = (self.varied.iter())
            .zip(drawn)
            .map(|(number, value)| (number.key.clone(), Value::Float(value)))
            .collect();
        TableCase {
            index,
            values,
            table,
        }
    }

    /// The scene's tables with each varied number set to its value in `values` (in the order
    /// of [`Uncertainty::varied`]): a case's tables from values already drawn.
    pub fn table_with(&self, values: &[f64]) -> Table {
        let mut table = self.table.clone();
        for (number, value) in self.varied.iter().zip(values) {
            // Every path was found in this table when it was read.
            let _ = set(&mut table, &number.key, Value::Float(*value));
        }
        table
    }

    /// The scene's tables as written, `[uncertainty]` taken out: the nominal scene.
    pub fn nominal(&self) -> &Table {
        &self.table
    }

    /// Each varied number with the two values one spread from the scene's (its law's
    /// [`Varied::probes`]): what a scene is checked at before its cases run, every other
    /// number as written.
    pub fn probes(&self) -> impl Iterator<Item = (&Varied, f64)> {
        (self.varied.iter())
            .flat_map(|number| {
                number
                    .probes()
                    .into_iter()
                    .map(move |value| (number, value))
            })
            .filter(|(number, value)| *value != number.nominal)
    }
}

/// The scene file as far as `[uncertainty]` goes.
#[derive(Debug, Deserialize)]
struct UncertaintyFile {
    uncertainty: UncertaintyTable,
}

impl Varied {
    /// The values one spread below and above the scene's, which a sixth of the cases or more
    /// draw beyond on each side: the scene's value ∓ σ for a normal law (∓ tσ/2 where it is
    /// truncated at t < 2, so that the truncation leaves a sixth beyond it), the first and the
    /// third quartile for a uniform one (a quarter beyond each).
    pub fn probes(&self) -> [f64; 2] {
        match self.distribution {
            Distribution::Normal { sigma, truncate } => {
                let reach = sigma * truncate.map_or(1.0, |t| (t / 2.0).min(1.0));
                [self.nominal - reach, self.nominal + reach]
            }
            Distribution::Uniform { low, high } => {
                let width = high - low;
                [low + 0.25 * width, low + 0.75 * width]
            }
        }
    }

    /// One draw from its law.
    fn draw(&self, stream: &mut ChaCha8Rng) -> f64 {
        match self.distribution {
            Distribution::Normal { sigma, truncate } => loop {
                let z: f64 = stream.sample(StandardNormal);
                if truncate.is_none_or(|t| z.abs() <= t) {
                    return self.nominal + sigma * z;
                }
            },
            Distribution::Uniform { low, high } => low + (high - low) * stream.random::<f64>(),
        }
    }
}

impl LawTable {
    /// The law for a number whose scene value is `nominal`, every key checked.
    fn distribution(&self, nominal: f64) -> Result<Distribution, Problem> {
        let finite = |what: &str, value: f64| match value.is_finite() && value >= 0.0 {
            true => Ok(value),
            false => Err(Problem::Invalid(format!(
                "{what} = {value}: must be a finite number, at least 0"
            ))),
        };
        let refuse = |keys: &[(&str, Option<f64>)], law: &str| match keys
            .iter()
            .find(|(_, v)| v.is_some())
        {
            Some((key, _)) => Err(Problem::Invalid(format!("`{key}` is not a key of {law}"))),
            None => Ok(()),
        };
        match self.distribution.as_str() {
            "normal" => {
                refuse(
                    &[
                        ("low", self.low),
                        ("high", self.high),
                        ("relative", self.relative),
                    ],
                    "the normal law (sigma or sigma_relative, truncate)",
                )?;
                let sigma = match (self.sigma, self.sigma_relative) {
                    (Some(sigma), None) => finite("sigma", sigma)?,
                    (None, Some(relative)) => finite("sigma_relative", relative)? * nominal.abs(),
                    _ => {
                        let message = "give one of sigma (in the key's unit) and sigma_relative \
                                       (a fraction of the scene's value)";
                        return Err(Problem::Invalid(message.into()));
                    }
                };
                let truncate = match self.truncate {
                    Some(t) if !(t >= MIN_TRUNCATION && t.is_finite()) => {
                        return Err(Problem::Invalid(format!(
                            "truncate = {t}: must be a finite number of standard deviations, \
                             at least {MIN_TRUNCATION}"
                        )));
                    }
                    t => t,
                };
                Ok(Distribution::Normal { sigma, truncate })
            }
            "uniform" => {
                refuse(
                    &[
                        ("sigma", self.sigma),
                        ("sigma_relative", self.sigma_relative),
                        ("truncate", self.truncate),
                    ],
                    "the uniform law (low and high, or relative)",
                )?;
                let (low, high) = match (self.low, self.high, self.relative) {
                    (Some(low), Some(high), None) if low.is_finite() && high.is_finite() => {
                        (low, high)
                    }
                    (None, None, Some(relative)) => {
                        let half = finite("relative", relative)? * nominal.abs();
                        (nominal - half, nominal + half)
                    }
                    _ => {
                        let message = "give finite low and high, or relative (a fraction of \
                                       the scene's value)";
                        return Err(Problem::Invalid(message.into()));
                    }
                };
                if low > high {
                    let message = format!("low = {low} is above high = {high}");
                    return Err(Problem::Invalid(message));
                }
                Ok(Distribution::Uniform { low, high })
            }
            other => Err(Problem::Invalid(format!(
                "distribution `{other}`: give normal or uniform"
            ))),
        }
    }
}

/// The numbers of `table` a path names, with their values: the one number at a plain path,
/// every number of the table it ends in whose name a pattern's last part matches.
fn numbers_at(table: &Table, path: &str) -> Result<Vec<(String, f64)>, Problem> {
    let mut parts: Vec<&str> = path.split('.').collect();
    let last = parts.pop().filter(|p| !p.is_empty());
    let Some(last) = last else {
        return Err(Problem::Invalid("an empty key path".into()));
    };
    let mut current = table;
    for part in &parts {
        let (name, index) = match part.split_once('[') {
            Some((name, rest)) => {
                let index = rest.strip_suffix(']').and_then(|i| i.parse::<usize>().ok());
                (name, Some(index.ok_or_else(|| not_in(path, part))?))
            }
            None => (*part, None),
        };
        current = match (current.get(name), index) {
            (Some(Value::Table(t)), None) => t,
            (Some(Value::Array(entries)), Some(i)) => match entries.get(i) {
                Some(Value::Table(t)) => t,
                _ => return Err(not_in(path, part)),
            },
            _ => return Err(not_in(path, part)),
        };
    }
    let prefix = parts.join(".");
    let full = |key: &str| match prefix.is_empty() {
        true => key.to_owned(),
        false => format!("{prefix}.{key}"),
    };
    let number = |value: &Value| match value {
        Value::Float(x) => Some(*x),
        Value::Integer(i) => Some(*i as f64),
        _ => None,
    };
    if !last.contains('*') {
        return match current.get(last).map(number) {
            Some(Some(value)) => Ok(vec![(full(last), value)]),
            Some(None) => Err(Problem::Invalid(format!(
                "`{path}` is not a number in the scene"
            ))),
            None => Err(Problem::Invalid(format!(
                "the scene does not write `{path}`: write the value to vary in it"
            ))),
        };
    }
    let found: Vec<(String, f64)> = (current.iter())
        .filter(|(key, _)| glob(last, key))
        .filter_map(|(key, value)| number(value).map(|v| (full(key), v)))
        .collect();
    match found.is_empty() {
        true => Err(Problem::Invalid(format!(
            "`{path}` matches no number the scene writes"
        ))),
        false => Ok(found),
    }
}

/// Why a path's table `part` is not in the scene.
fn not_in(path: &str, part: &str) -> Problem {
    Problem::Invalid(format!(
        "`{path}`: the scene has no table `{part}` (an entry of an array by its index: \
         `manoeuvre[0].rudder_deg`)"
    ))
}

/// Whether `name` matches `pattern`, in which `*` stands for any run of characters.
fn glob(pattern: &str, name: &str) -> bool {
    match pattern.split_once('*') {
        None => pattern == name,
        Some((head, rest)) => {
            let Some(tail) = name.strip_prefix(head) else {
                return false;
            };
            (0..=tail.len())
                .filter(|&at| tail.is_char_boundary(at))
                .any(|at| glob(rest, &tail[at..]))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCENE: &str = r#"
title = "t"
[body]
mass = 2.0
[hydrodynamics.coefficients]
Yv = -0.01
Yr = 0.0
Nv = 0.5
[[manoeuvre]]
rudder_deg = 35
"#;

    fn with(vary: &str) -> Result<Uncertainty, SceneError> {
        let text =
            format!("{SCENE}\n[uncertainty]\ncases = 100\nseed = 7\n[uncertainty.vary]\n{vary}");
        Uncertainty::parse(&text, "s.toml")
    }

    #[test]
    fn a_pattern_names_every_number_of_its_table_and_a_case_sets_them() {
        let uncertainty = with(
            r#""hydrodynamics.coefficients.*" = { distribution = "normal", sigma_relative = 0.1, truncate = 3 }
"manoeuvre[0].rudder_deg" = { distribution = "uniform", low = 30, high = 40 }"#,
        )
        .unwrap();
        let keys: Vec<&str> = uncertainty.varied.iter().map(|v| v.key.as_str()).collect();
        assert_eq!(
            keys,
            [
                "hydrodynamics.coefficients.Nv",
                "hydrodynamics.coefficients.Yr",
                "hydrodynamics.coefficients.Yv",
                "manoeuvre[0].rudder_deg"
            ]
        );
        let case = uncertainty.case(3);
        let values = uncertainty.values(3);
        // A relative σ of a zero value keeps it at zero; every other value moves, within ±3σ.
        assert_eq!(values[1], 0.0);
        assert!(values[0] != 0.5 && (values[0] - 0.5).abs() <= 3.0 * 0.05);
        assert!((30.0..=40.0).contains(&values[3]));
        let coefficients = case.table["hydrodynamics"]["coefficients"]
            .as_table()
            .unwrap();
        assert_eq!(coefficients["Yv"].as_float(), Some(values[2]));
        assert_eq!(
            case.table["manoeuvre"][0]["rudder_deg"].as_float(),
            Some(values[3])
        );
        assert!(!case.table.contains_key(UNCERTAINTY_TABLE));
    }

    #[test]
    fn a_case_is_its_own_stream_whatever_was_drawn_before() {
        let uncertainty =
            with(r#""body.mass" = { distribution = "normal", sigma = 0.1 }"#).unwrap();
        let alone = uncertainty.values(41);
        let after: Vec<Vec<f64>> = (0..50).map(|k| uncertainty.values(k)).collect();
        assert_eq!(after[41], alone);
        assert_ne!(after[40], alone);
        let other_seed = Uncertainty {
            seed: 8,
            ..uncertainty.clone()
        };
        assert_ne!(other_seed.values(41), alone);
    }

    #[test]
    fn draws_follow_their_laws() {
        let uncertainty = with(
            r#""body.mass" = { distribution = "normal", sigma = 0.5, truncate = 1.0 }
"hydrodynamics.coefficients.Nv" = { distribution = "uniform", relative = 0.2 }"#,
        )
        .unwrap();
        let n = 20_000;
        let draws: Vec<Vec<f64>> = (0..n).map(|k| uncertainty.values(k)).collect();
        // In the order of their paths: body.mass, then the coefficient.
        let mass: Vec<f64> = draws.iter().map(|v| v[0]).collect();
        let nv: Vec<f64> = draws.iter().map(|v| v[1]).collect();
        assert!(mass.iter().all(|m| (m - 2.0).abs() <= 0.5));
        assert!(nv.iter().all(|x| (0.4..=0.6).contains(x)));
        // Means within five standard errors (σ/√n) of the laws' own: 2 and 0.5.
        let mean = |xs: &[f64]| xs.iter().sum::<f64>() / xs.len() as f64;
        // The normal truncated at ±1σ has standard deviation 0.5·0.5377; the uniform on
        // [0.4, 0.6], 0.2/√12.
        assert!((mean(&mass) - 2.0).abs() < 5.0 * 0.5 * 0.5377 / (n as f64).sqrt());
        assert!((mean(&nv) - 0.5).abs() < 5.0 * 0.2 / 12f64.sqrt() / (n as f64).sqrt());
        // A sixth of the draws or more lie beyond each probe: 0.219 for the normal truncated
        // at 1σ (probed at σ/2), 0.25 for the uniform; the fractions' standard error over
        // 2·10⁴ draws is 0.003.
        for (number, draws) in uncertainty.varied.iter().zip([&mass, &nv]) {
            let [below, above] = number.probes();
            let beyond =
                |f: &dyn Fn(f64) -> bool| draws.iter().filter(|x| f(**x)).count() as f64 / n as f64;
            assert!(beyond(&|x| x < below) > 1.0 / 6.0, "{}", number.key);
            assert!(beyond(&|x| x > above) > 1.0 / 6.0, "{}", number.key);
        }
    }

    #[test]
    fn a_path_that_names_nothing_or_twice_is_refused_by_name() {
        let cases = [
            (
                r#""body.volume" = { distribution = "normal", sigma = 1 }"#,
                "does not write",
            ),
            (
                r#""hull.mass" = { distribution = "normal", sigma = 1 }"#,
                "no table `hull`",
            ),
            (
                r#""body.Q*" = { distribution = "normal", sigma = 1 }"#,
                "matches no number",
            ),
            (
                r#""title" = { distribution = "normal", sigma = 1 }"#,
                "not a number",
            ),
            (
                r#""hydrodynamics.coefficients.*" = { distribution = "normal", sigma = 1 }
"hydrodynamics.coefficients.Y*" = { distribution = "normal", sigma = 1 }"#,
                "varied by",
            ),
            (
                r#""body.mass" = { distribution = "normal" }"#,
                "give one of sigma",
            ),
            (
                r#""body.mass" = { distribution = "normal", sigma = -1 }"#,
                "at least 0",
            ),
            (
                r#""body.mass" = { distribution = "normal", sigma = 1, truncate = 0 }"#,
                "truncate",
            ),
            (
                r#""body.mass" = { distribution = "normal", sigma = 1, low = 0 }"#,
                "`low`",
            ),
            (
                r#""body.mass" = { distribution = "uniform", low = 3, high = 1 }"#,
                "above high",
            ),
            (
                r#""body.mass" = { distribution = "cauchy", sigma = 1 }"#,
                "normal or uniform",
            ),
            (
                r#""body.mass" = { distribution = "normal", sigma = nan }"#,
                "finite",
            ),
            (
                r#""body.mass" = { distribution = "normal", sigmaa = 1 }"#,
                "sigmaa",
            ),
        ];
        for (vary, said) in cases {
            let error = with(vary).unwrap_err().to_string();
            assert!(error.contains("uncertainty.vary"), "{vary}: {error}");
            assert!(error.contains(said), "{vary}: {error}");
        }
        let text = format!(
            "{SCENE}\n[uncertainty]\ncases = 0\nseed = 1\n[uncertainty.vary]\n\"body.mass\" = {{ distribution = \"normal\", sigma = 1 }}"
        );
        let error = Uncertainty::parse(&text, "s.toml").unwrap_err().to_string();
        assert!(error.contains("uncertainty.cases"), "{error}");
    }

    #[test]
    fn shards_partition_the_cases() {
        let uncertainty = with(r#""body.mass" = { distribution = "normal", sigma = 1 }"#).unwrap();
        let mut all: Vec<usize> = (0..3)
            .flat_map(|k| uncertainty.shard(Some((k, 3)), "s").unwrap())
            .collect();
        all.sort_unstable();
        assert_eq!(all, (0..100).collect::<Vec<_>>());
    }

    #[test]
    fn glob_matches_runs_of_characters() {
        assert!(glob("*", "Yv"));
        assert!(glob("Y*", "Yvvr"));
        assert!(glob("*r", "Yvvr"));
        assert!(glob("Y*v*", "Yvvr"));
        assert!(!glob("N*", "Yv"));
        assert!(!glob("Yv", "Yvv"));
    }
}
