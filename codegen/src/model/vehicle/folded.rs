//! A folded table against its own added mass.
//!
//! A table that folds Kirchhoff's terms into its cross terms (Prestero's Xwq, Ywp, Mrp, …)
//! states, in effect, that each such coefficient is a combination of its added-mass entries.
//! Here the derived terms C_A(ν)ν ([`crate::derivation::vehicle::added_mass_coriolis`]) are
//! split into monomials of ν, each is matched by meaning with the table's term of that product
//! in that load, and its coefficient, moved to the right side, is what M_A implies for it.
//! The split is proved exact: the implied coefficients times their monomials give back the
//! derived terms. With the table's numbers, each coefficient's printed value, implied value
//! and difference are reported; a table that disagrees with its own added mass is shown.
//! A table in the prime system is compared in its own units: the implied coefficient of a
//! product of two velocities, a of them angular, in a load (m = 1 for a moment) is the SI one
//! over ½ρL^(2 + a + m), and a term matches by its product once U = u is written out (`Yr` is
//! u·r there).

use super::{DENSITY, ForceTerm, LENGTH, Load, Units, VehicleError, VehicleSpec, symbolic};
use crate::derivation::vehicle::{VELOCITIES, added_mass_coriolis};
use crate::model::BuildError;
use crate::symbolic::{Atom, Expr, Monomial, Rational};
use std::collections::BTreeMap;
use std::fmt::Write;

/// One monomial of Kirchhoff's terms in one load, with the table term that folds it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FoldedTerm {
    /// The load.
    pub load: Load,
    /// The product of velocities, `w·q`.
    pub product: String,
    /// The table's term of that product in that load, if it has one.
    pub name: Option<String>,
    /// The coefficient M_A implies for it, on the right side, in the added-mass entries and in
    /// the table's units.
    pub implied: Expr,
}

/// Kirchhoff's terms of the spec's added mass, monomial by monomial, each with the table's
/// term that folds it (by meaning: a plain product of the same velocities in the same load).
pub fn folded_terms(spec: &VehicleSpec) -> Result<Vec<FoldedTerm>, VehicleError> {
    let err = symbolic("vehicle");
    let terms = spec.force_terms()?;
    let coriolis = added_mass_coriolis(&spec.added_mass_matrix()?).map_err(&err)?;
    let mut folded = Vec::new();
    for (load, row) in Load::ALL.into_iter().zip(&coriolis) {
        let mut rebuilt = Expr::zero();
        for (velocities, coefficient) in by_velocity_monomial(row) {
            // The table's forces are on the right: the implied coefficient is the negated one.
            let implied = -&coefficient;
            let product = product_text(&velocities);
            rebuilt = &rebuilt
                + &(&implied
                    * &Expr::term(
                        crate::symbolic::Rational::from_integer(1.into()),
                        velocities.clone(),
                    ));
            folded.push(FoldedTerm {
                load,
                name: matching_term(spec, &terms, load, &velocities).map(|t| t.name.clone()),
                product,
                implied: in_table_units(spec, load, &velocities, &implied)?,
            });
        }
        let left = &rebuilt + row;
        if !left.is_zero() {
            return Err(VehicleError::Build(BuildError::Verification {
                model: "vehicle".into(),
                what: format!(
                    "the folded terms of {} do not rebuild C_A(ν)ν",
                    load.letter()
                ),
                residual: left.to_string(),
            }));
        }
    }
    Ok(folded)
}

/// An implied coefficient in SI, in the table's units: over ½ρL^(2 + a + m) in the prime
/// system (see the module docs), where the scales must cancel.
fn in_table_units(
    spec: &VehicleSpec,
    load: Load,
    velocities: &Monomial,
    implied: &Expr,
) -> Result<Expr, VehicleError> {
    if spec.units == Units::Dimensional {
        return Ok(implied.clone());
    }
    let err = symbolic("vehicle");
    let angular = velocity_list(velocities)
        .iter()
        .filter(|v| ["p", "q", "r"].contains(&v.as_str()))
        .count();
    let power = 2 + i32::try_from(angular).unwrap_or(0) + i32::from(load.is_moment());
    let over = &(&Expr::constant(Rational::from_integer(2.into()))
        * &Expr::symbol(DENSITY).pow(-1).map_err(&err)?)
        * &Expr::symbol(LENGTH).pow(-power).map_err(&err)?;
    let prime = implied * &over;
    if let Some(scale) = prime
        .symbols()
        .into_iter()
        .find(|s| s == DENSITY || s == LENGTH)
    {
        return Err(VehicleError::Build(BuildError::Verification {
            model: "vehicle".into(),
            what: format!("the implied coefficient in {} keeps {scale}", load.letter()),
            residual: prime.to_string(),
        }));
    }
    Ok(prime)
}

/// The terms of `row` grouped by their monomial in the velocities.
fn by_velocity_monomial(row: &Expr) -> BTreeMap<Monomial, Expr> {
    let mut groups: BTreeMap<Monomial, Expr> = BTreeMap::new();
    for (monomial, coefficient) in row.terms() {
        let (mut velocities, mut rest) = (Monomial::one(), Monomial::one());
        for (atom, power) in monomial.factors() {
            let moving = matches!(atom, Atom::Symbol(s) if VELOCITIES.contains(&s.as_str()));
            let part = if moving { &mut velocities } else { &mut rest };
            part.multiply_atom(atom.clone(), power);
        }
        let entry = groups.entry(velocities).or_default();
        *entry = &*entry + &Expr::term(coefficient.clone(), rest);
    }
    groups.retain(|_, e| !e.is_zero());
    groups
}

/// The velocities of a monomial, each as often as its power, in the order u … r.
fn velocity_list(monomial: &Monomial) -> Vec<String> {
    let mut list = Vec::new();
    for v in VELOCITIES {
        let power = monomial.power(&Atom::Symbol(v.into()));
        list.extend(std::iter::repeat_n(v.to_string(), power.max(0) as usize));
    }
    list
}

fn product_text(monomial: &Monomial) -> String {
    velocity_list(monomial).join("·")
}

fn matching_term<'a>(
    spec: &VehicleSpec,
    terms: &'a [ForceTerm],
    load: Load,
    monomial: &Monomial,
) -> Option<&'a ForceTerm> {
    let wanted = velocity_list(monomial);
    terms.iter().find(|t| {
        let Ok(key) = spec.dimensional_key(t) else {
            return false;
        };
        let mut plain: Vec<String> = key.iter().map(|f| f.variable.clone()).collect();
        plain.sort_by_key(|v| VELOCITIES.iter().position(|x| x == v));
        t.load == load && key.iter().all(|f| !f.absolute) && plain == wanted
    })
}

/// One line of the comparison of a folded table with its added mass.
#[derive(Debug, Clone, PartialEq)]
pub struct FoldedComparison {
    /// The load.
    pub load: Load,
    /// The product of velocities.
    pub product: String,
    /// The table's term, if it has one.
    pub name: Option<String>,
    /// The table's value of it.
    pub printed: Option<f64>,
    /// What M_A implies for it.
    pub implied: f64,
    /// printed − implied.
    pub difference: Option<f64>,
}

/// The folded terms with the table's numbers (by name: the added mass and the terms).
pub fn folded_comparison(
    spec: &VehicleSpec,
    values: &BTreeMap<String, f64>,
) -> Result<Vec<FoldedComparison>, VehicleError> {
    let mut rows = Vec::new();
    for term in folded_terms(spec)? {
        for symbol in term.implied.symbols() {
            if !values.get(&symbol).is_some_and(|v| v.is_finite()) {
                return Err(VehicleError::MissingValue(symbol));
            }
        }
        let implied = term.implied.eval(&|s| values[s]);
        let printed = term.name.as_ref().and_then(|n| values.get(n).copied());
        rows.push(FoldedComparison {
            load: term.load,
            product: term.product,
            name: term.name,
            printed,
            implied,
            difference: printed.map(|p| p - implied),
        });
    }
    Ok(rows)
}

/// The comparison as a Markdown table, one line per folded term.
pub fn format_folded(rows: &[FoldedComparison]) -> String {
    let mut text = String::from(
        "| load | term | coefficient | printed | implied by M_A | difference |\n|---|---|---|---|---|---|\n",
    );
    let number = |x: Option<f64>| x.map_or("—".to_owned(), |x| format!("{x:.4}"));
    for row in rows {
        let _ = writeln!(
            text,
            "| {} | {} | {} | {} | {:.4} | {} |",
            row.load.letter(),
            row.product,
            row.name.as_deref().unwrap_or("(not in the table)"),
            number(row.printed),
            row.implied,
            number(row.difference)
        );
    }
    text
}
