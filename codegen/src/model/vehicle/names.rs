//! The names of a vehicle table's terms, read under a declared convention.
//!
//! A name is a load letter (X, Y, Z, K, M, N) followed by the term's factors: the velocities
//! u, v, w, p, q, r (one letter each), the controls the table declares (`dr`, `ds`, `n`, …, none
//! starting with a velocity's letter), and, in Fossen's convention, `|x|` for the absolute
//! value of x. An added-mass entry is a load letter, one velocity and `dot` (`Yrdot`). A
//! constant is the load letter and `0` (`Y0`).
//!
//! - [`Convention::Fossen`]: every factor is written, so nothing is left to guess: `Yv|v|` is
//!   v|v|, `Xuu` is u·u = u², `Yuudr` is u²δ_r, `Xn|n|` is n|n|.
//! - [`Convention::Prestero`] (REMUS, Prestero 2001): a doubled letter of a drag term means
//!   the signed square x|x|, and the table says which terms are drag: those whose doubled
//!   velocity lies in the plane of the load (X: u; Y, N: v, r; Z, M: w, q; K: p), so `Xuu` is
//!   u|u|, `Yvv` v|v|, `Nrr` r|r|, `Mqq` q|q|. Xqq and Xrr are the table's added-mass cross
//!   terms, q² and r². A doubled u before controls only is the fins' u² (`Yuudr` = u²δ_r).
//!   Every other letter is a plain factor (`Yuv` = uv, `Zrp` = rp). Any other repeated factor
//!   (`Xvv`, `Kqq`, `Yvvr`, `Xdrdr`) could be either a square or a signed square, and the
//!   table does not say: such a name is refused as ambiguous, not guessed.

use std::fmt;
use thiserror::Error;

/// The convention a table's names are written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Convention {
    /// Every factor written out, `|x|` for an absolute value (Fossen's `Yv|v|`).
    Fossen,
    /// Prestero's REMUS table: a doubled letter of a drag term is x|x| (see the module docs).
    Prestero,
}

impl Convention {
    /// The name in messages and scene files: `fossen`, `prestero`.
    pub fn name(self) -> &'static str {
        match self {
            Convention::Fossen => "fossen",
            Convention::Prestero => "prestero",
        }
    }
}

/// The six loads about O, in the order of the equations.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Load {
    /// Surge force.
    X,
    /// Sway force.
    Y,
    /// Heave force.
    Z,
    /// Roll moment.
    K,
    /// Pitch moment.
    M,
    /// Yaw moment.
    N,
}

impl Load {
    /// The six, in the order of the equations.
    pub const ALL: [Load; 6] = [Load::X, Load::Y, Load::Z, Load::K, Load::M, Load::N];

    /// The letter that starts a term's name.
    pub fn letter(self) -> char {
        ['X', 'Y', 'Z', 'K', 'M', 'N'][self.index()]
    }

    /// The row of the load in τ = (X, Y, Z, K, M, N).
    pub fn index(self) -> usize {
        self as usize
    }

    /// Whether it is a moment (K, M, N), which the prime system scales by one more L.
    pub fn is_moment(self) -> bool {
        matches!(self, Load::K | Load::M | Load::N)
    }

    fn of_letter(letter: char) -> Option<Load> {
        Load::ALL.into_iter().find(|l| l.letter() == letter)
    }
}

/// The six velocities, by the letters of the names: ν = (u, v, w, p, q, r).
pub const VELOCITY_LETTERS: [char; 6] = ['u', 'v', 'w', 'p', 'q', 'r'];

/// One factor of a term: a velocity or a control, or its absolute value.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Factor {
    /// The velocity (`u` … `r`) or the control (`dr`).
    pub variable: String,
    /// |x| rather than x.
    pub absolute: bool,
}

impl fmt::Display for Factor {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.absolute {
            write!(f, "|{}|", self.variable)
        } else {
            f.write_str(&self.variable)
        }
    }
}

/// A term of the force table: the coefficient named `name` times the product of `factors`
/// in the load `load`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct ForceTerm {
    /// The name as the table writes it.
    pub name: String,
    /// The load it adds to.
    pub load: Load,
    /// The factors, in the order of the name; none for a constant.
    pub factors: Vec<Factor>,
}

impl ForceTerm {
    /// The coefficient's symbol, a Rust identifier: the name with `|x|` written `_abs_x`.
    pub fn symbol(&self) -> String {
        symbol_of(&self.name)
    }

    /// What the coefficient multiplies, `v·|v|`, `u·u·dr`, or `1`.
    pub fn meaning(&self) -> String {
        if self.factors.is_empty() {
            return "1".into();
        }
        let factors: Vec<String> = self.factors.iter().map(Factor::to_string).collect();
        factors.join("·")
    }

    /// How many of its factors are linear velocities (u, v, w) and how many angular ones
    /// (p, q, r), |x| counted as x: the powers the prime system scales by.
    pub fn velocity_powers(&self) -> (i32, i32) {
        let count = |letters: &[&str]| {
            let n = self
                .factors
                .iter()
                .filter(|f| letters.contains(&f.variable.as_str()))
                .count();
            i32::try_from(n).unwrap_or(i32::MAX)
        };
        (count(&["u", "v", "w"]), count(&["p", "q", "r"]))
    }

    /// The factors, sorted: two terms with the same product have the same key.
    pub fn product_key(&self) -> Vec<Factor> {
        let mut key = self.factors.clone();
        key.sort();
        key
    }
}

/// The Rust identifier of a table name: `|x|` becomes `_abs_x`.
pub fn symbol_of(name: &str) -> String {
    let mut symbol = String::new();
    let mut inside = false;
    for c in name.chars() {
        match (c, inside) {
            ('|', false) => {
                symbol.push_str("_abs_");
                inside = true;
            }
            ('|', true) => {
                symbol.push('_');
                inside = false;
            }
            _ => symbol.push(c),
        }
    }
    symbol.trim_end_matches('_').to_owned()
}

/// An added-mass entry: the load of `row` per acceleration of the velocity `column`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct AddedMassEntry {
    /// The name as the table writes it, `Yrdot`.
    pub name: String,
    /// The load's index in (X, Y, Z, K, M, N).
    pub row: usize,
    /// The velocity's index in (u, v, w, p, q, r).
    pub column: usize,
}

/// Why a name is not read.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum NameError {
    /// The name could mean two different terms under the convention.
    #[error("the term `{name}` is ambiguous under the {convention} convention: {why}")]
    Ambiguous {
        /// The name.
        name: String,
        /// The convention.
        convention: &'static str,
        /// The two readings.
        why: String,
    },
    /// The name is not a term of the convention.
    #[error("`{name}` is not a term name under the {convention} convention: {why}")]
    Unknown {
        /// The name.
        name: String,
        /// The convention.
        convention: &'static str,
        /// What was not understood.
        why: String,
    },
}

/// Reads an added-mass entry's name, `Xudot` … `Nrdot`.
pub fn parse_added_mass(name: &str) -> Result<AddedMassEntry, NameError> {
    let unknown = |why: &str| NameError::Unknown {
        name: name.into(),
        convention: "added-mass",
        why: why.into(),
    };
    let body = name
        .strip_suffix("dot")
        .ok_or_else(|| unknown("an added-mass entry ends in `dot`"))?;
    let mut chars = body.chars();
    let (Some(load), Some(velocity), None) = (chars.next(), chars.next(), chars.next()) else {
        return Err(unknown(
            "expected a load letter and one velocity before `dot`",
        ));
    };
    let row = Load::of_letter(load).ok_or_else(|| unknown("the load is not X, Y, Z, K, M or N"))?;
    let column = VELOCITY_LETTERS
        .iter()
        .position(|v| *v == velocity)
        .ok_or_else(|| unknown("the velocity is not u, v, w, p, q or r"))?;
    Ok(AddedMassEntry {
        name: name.into(),
        row: row.index(),
        column,
    })
}

/// Reads a force term's name under `convention`, with the table's `controls`.
pub fn parse_term(
    name: &str,
    convention: Convention,
    controls: &[String],
) -> Result<ForceTerm, NameError> {
    let unknown = |why: String| NameError::Unknown {
        name: name.into(),
        convention: convention.name(),
        why,
    };
    let mut chars = name.chars();
    let load = chars
        .next()
        .and_then(Load::of_letter)
        .ok_or_else(|| unknown("a term starts with X, Y, Z, K, M or N".into()))?;
    let body = chars.as_str();
    if body.ends_with("dot") {
        return Err(unknown(
            "an acceleration is added mass, not a force term".into(),
        ));
    }
    if body == "0" {
        return Ok(ForceTerm {
            name: name.into(),
            load,
            factors: vec![],
        });
    }
    let tokens = tokenize(body, convention, controls).map_err(unknown)?;
    if tokens.is_empty() {
        return Err(unknown("no factors: a constant is written with 0".into()));
    }
    let factors = match convention {
        Convention::Fossen => tokens,
        Convention::Prestero => prestero(name, load, tokens)?,
    };
    Ok(ForceTerm {
        name: name.into(),
        load,
        factors,
    })
}

/// Splits a name's factors: one letter per velocity, a declared control, `|x|`.
fn tokenize(
    body: &str,
    convention: Convention,
    controls: &[String],
) -> Result<Vec<Factor>, String> {
    let mut tokens = Vec::new();
    let mut rest = body;
    while !rest.is_empty() {
        if let Some(inner) = rest.strip_prefix('|') {
            if convention == Convention::Prestero {
                return Err("Prestero's names have no |x|; declare the Fossen convention".into());
            }
            let (variable, after) = inner
                .split_once('|')
                .ok_or_else(|| format!("`|` without its closing bar in `{rest}`"))?;
            let known = variable.len() == 1 && variable.starts_with(VELOCITY_LETTERS)
                || controls.iter().any(|c| c == variable);
            if !known {
                return Err(format!(
                    "|{variable}| is not a velocity or a declared control"
                ));
            }
            tokens.push(Factor {
                variable: variable.into(),
                absolute: true,
            });
            rest = after;
            continue;
        }
        let first = rest.chars().next().expect("not empty");
        if VELOCITY_LETTERS.contains(&first) {
            tokens.push(Factor {
                variable: first.to_string(),
                absolute: false,
            });
            rest = &rest[first.len_utf8()..];
            continue;
        }
        let control = controls
            .iter()
            .filter(|c| rest.starts_with(c.as_str()))
            .max_by_key(|c| c.len())
            .ok_or_else(|| format!("`{rest}` starts with no velocity and no declared control"))?;
        tokens.push(Factor {
            variable: control.clone(),
            absolute: false,
        });
        rest = &rest[control.len()..];
    }
    Ok(tokens)
}

/// The velocities a doubled letter of a drag term may be in each load (Prestero's table).
fn in_plane_of(load: Load, velocity: &str) -> bool {
    matches!(
        (load, velocity),
        (Load::X, "u")
            | (Load::Y | Load::N, "v" | "r")
            | (Load::Z | Load::M, "w" | "q")
            | (Load::K, "p")
    )
}

fn is_velocity(variable: &str) -> bool {
    variable.len() == 1 && variable.starts_with(VELOCITY_LETTERS)
}

/// Prestero's meaning of plain tokens (see the module docs).
fn prestero(name: &str, load: Load, tokens: Vec<Factor>) -> Result<Vec<Factor>, NameError> {
    let ambiguous = |why: String| NameError::Ambiguous {
        name: name.into(),
        convention: Convention::Prestero.name(),
        why,
    };
    let count = |variable: &str| tokens.iter().filter(|t| t.variable == variable).count();
    let repeated: Vec<&str> = {
        let mut seen: Vec<&str> = tokens
            .iter()
            .map(|t| t.variable.as_str())
            .filter(|v| count(v) > 1)
            .collect();
        seen.dedup();
        seen.sort();
        seen.dedup();
        seen
    };
    match repeated.as_slice() {
        [] => Ok(tokens),
        [x] if tokens.len() == 2 && is_velocity(x) => {
            if in_plane_of(load, x) {
                // The drag term x|x|.
                Ok(vec![
                    tokens[0].clone(),
                    Factor {
                        variable: (*x).into(),
                        absolute: true,
                    },
                ])
            } else if load == Load::X && matches!(*x, "q" | "r") {
                // Xqq, Xrr: the added-mass cross terms q², r².
                Ok(tokens)
            } else {
                Err(ambiguous(format!(
                    "{x}{x} in {} is neither one of Prestero's drag terms ({x}|{x}|) nor one of \
                     his added-mass squares ({x}²)",
                    load.letter()
                )))
            }
        }
        ["u"]
            if count("u") == 2
                && tokens
                    .iter()
                    .all(|t| t.variable == "u" || !is_velocity(&t.variable)) =>
        {
            // The fins' lift, u² times the fin angle (Yuudr).
            Ok(tokens)
        }
        [x, ..] => Err(ambiguous(format!(
            "the repeated {x} may be a square or a signed square ({x}|{x}|); write the name in \
             Fossen's convention"
        ))),
    }
}
