//! Expressions in canonical form: the heart of the proofs.
//!
//! An [`Expr`] is a sum of monomials with exact rational coefficients, kept canonical at every
//! step: no zero coefficients, like monomials merged, and no sine raised above the first power
//! (sin² is rewritten as 1 − cos²). In the ring of polynomials in symbols, cos and cos⁻¹ of each
//! angle and sin of each angle, modulo sin² + cos² = 1, every element has exactly one such
//! representation, so two expressions are equal exactly when their difference is the empty sum.

use super::atom::Atom;
use super::monomial::Monomial;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::collections::BTreeMap;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use thiserror::Error;

/// What the symbolic engine cannot do, said plainly.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum SymbolicError {
    /// Division by a sum, or by a sine: the result is not a polynomial in the atoms.
    #[error("cannot divide by `{0}`: only monomials without a sine can be inverted")]
    NotInvertible(String),
    /// Substituting a compound expression for an angle inside sin or cos.
    #[error("cannot substitute `{replacement}` for the angle `{angle}` inside sin/cos")]
    AngleSubstitution {
        /// The angle symbol.
        angle: String,
        /// What was to replace it.
        replacement: String,
    },
    /// A body integral met a term of a degree it has no moment for.
    #[error("cannot integrate `{0}` over the body: only degrees 0, 1 and 2 in the coordinates")]
    UnsupportedMoment(String),
    /// Reference text that is not a supported Rust expression.
    #[error("cannot read `{text}` as an expression: {reason}")]
    Parse {
        /// The text (or the fragment) that failed.
        text: String,
        /// Why.
        reason: String,
    },
}

/// An exact rational coefficient.
pub type Rational = BigRational;

/// A polynomial in atoms with rational coefficients, always in canonical form.
#[derive(Debug, Clone, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Expr {
    terms: BTreeMap<Monomial, Rational>,
}

impl Expr {
    /// The empty sum, 0.
    pub fn zero() -> Self {
        Self::default()
    }

    /// An integer constant.
    pub fn int(value: i64) -> Self {
        Self::constant(Rational::from_integer(BigInt::from(value)))
    }

    /// A rational constant.
    pub fn constant(value: Rational) -> Self {
        Self::term(value, Monomial::one())
    }

    /// A symbol.
    pub fn symbol(name: &str) -> Self {
        Self::term(
            Rational::one(),
            Monomial::atom(Atom::Symbol(name.into()), 1),
        )
    }

    /// sin of an angle symbol.
    pub fn sin(angle: &str) -> Self {
        Self::term(Rational::one(), Monomial::atom(Atom::Sin(angle.into()), 1))
    }

    /// cos of an angle symbol.
    pub fn cos(angle: &str) -> Self {
        Self::term(Rational::one(), Monomial::atom(Atom::Cos(angle.into()), 1))
    }

    /// sec θ = cos⁻¹θ.
    pub fn sec(angle: &str) -> Self {
        Self::term(Rational::one(), Monomial::atom(Atom::Cos(angle.into()), -1))
    }

    /// tan θ = sin θ · cos⁻¹θ.
    pub fn tan(angle: &str) -> Self {
        Self::sin(angle) * Self::sec(angle)
    }

    /// One term `coefficient × monomial`, reduced to canonical form.
    pub fn term(coefficient: Rational, monomial: Monomial) -> Self {
        let mut e = Self::zero();
        e.add_term(coefficient, monomial);
        e
    }

    /// The terms in canonical order.
    pub fn terms(&self) -> impl Iterator<Item = (&Monomial, &Rational)> {
        self.terms.iter()
    }

    /// The number of terms.
    pub fn term_count(&self) -> usize {
        self.terms.len()
    }

    /// True for the empty sum.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The value, if the expression is a constant.
    pub fn as_constant(&self) -> Option<Rational> {
        match self.terms.len() {
            0 => Some(Rational::zero()),
            1 => self
                .terms
                .iter()
                .find(|(m, _)| m.is_one())
                .map(|(_, c)| c.clone()),
            _ => None,
        }
    }

    /// Every symbol the expression depends on, angles included, in order.
    pub fn symbols(&self) -> std::collections::BTreeSet<String> {
        self.terms
            .keys()
            .flat_map(|m| m.factors().map(|(a, _)| a.symbol().to_owned()))
            .collect()
    }

    /// Adds `coefficient × monomial`, applying sin² = 1 − cos² as it goes.
    fn add_term(&mut self, coefficient: Rational, monomial: Monomial) {
        if coefficient.is_zero() {
            return;
        }
        if let Some((angle, power)) = first_reducible_sine(&monomial) {
            // sin^n = sin^(n−2) · (1 − cos²): two terms, each with a lower sine power.
            let (rest, _) = monomial.without(&Atom::Sin(angle.clone()));
            let lower = rest.times(&Monomial::atom(Atom::Sin(angle.clone()), power - 2));
            let with_cos = lower.times(&Monomial::atom(Atom::Cos(angle), 2));
            self.add_term(coefficient.clone(), lower);
            self.add_term(-coefficient, with_cos);
            return;
        }
        let entry = self.terms.entry(monomial).or_insert_with(Rational::zero);
        *entry += coefficient;
        if entry.is_zero() {
            self.terms.retain(|_, c| !c.is_zero());
        }
    }

    /// The expression to an integer power; negative powers need a monomial without a sine.
    pub fn pow(&self, exponent: i32) -> Result<Expr, SymbolicError> {
        if exponent < 0 {
            return Ok(self.reciprocal()?.pow_unsigned(exponent.unsigned_abs()));
        }
        Ok(self.pow_unsigned(exponent.unsigned_abs()))
    }

    fn pow_unsigned(&self, exponent: u32) -> Expr {
        (0..exponent).fold(Expr::int(1), |acc, _| &acc * self)
    }

    /// 1 / self, for a non-zero monomial without a sine.
    pub fn reciprocal(&self) -> Result<Expr, SymbolicError> {
        let not_invertible = || SymbolicError::NotInvertible(self.to_string());
        let mut terms = self.terms.iter();
        match (terms.next(), terms.next()) {
            (Some((monomial, coefficient)), None) => {
                let inverse = monomial.reciprocal().ok_or_else(not_invertible)?;
                Ok(Expr::term(coefficient.recip(), inverse))
            }
            _ => Err(not_invertible()),
        }
    }

    /// self / divisor, for a divisor that is a monomial without a sine.
    pub fn div(&self, divisor: &Expr) -> Result<Expr, SymbolicError> {
        Ok(self * &divisor.reciprocal()?)
    }

    /// Multiplies by a rational constant.
    pub fn scale(&self, factor: &Rational) -> Expr {
        let mut e = Expr::zero();
        for (m, c) in self.terms() {
            e.add_term(c * factor, m.clone());
        }
        e
    }

    /// The partial derivative with respect to a symbol (angles included: d sin θ/dθ = cos θ).
    pub fn diff(&self, symbol: &str) -> Expr {
        let mut result = Expr::zero();
        for (monomial, coefficient) in self.terms() {
            for (atom, power) in monomial.factors() {
                if atom.symbol() != symbol {
                    continue;
                }
                let (rest, _) = monomial.without(atom);
                let lowered = rest.times(&Monomial::atom(atom.clone(), power - 1));
                let inner = match atom {
                    Atom::Symbol(_) => Expr::int(1),
                    Atom::Sin(angle) => Expr::cos(angle),
                    Atom::Cos(angle) => -Expr::sin(angle),
                };
                let factor = Rational::from_integer(BigInt::from(power)) * coefficient;
                result = result + Expr::term(factor, lowered) * inner;
            }
        }
        result
    }

    /// The total time derivative, given the rate of each time-dependent symbol (chain rule).
    /// Symbols without a rate are constants.
    pub fn time_derivative(&self, rates: &[(&str, Expr)]) -> Expr {
        rates.iter().fold(Expr::zero(), |acc, (symbol, rate)| {
            acc + self.diff(symbol) * rate.clone()
        })
    }

    /// Replaces every occurrence of `symbol` by `replacement`.
    ///
    /// Inside sin and cos only a rename (replacement by another symbol) is possible; a negative
    /// power of the symbol needs a replacement that can be inverted.
    pub fn subs(&self, symbol: &str, replacement: &Expr) -> Result<Expr, SymbolicError> {
        let mut result = Expr::zero();
        for (monomial, coefficient) in self.terms() {
            let mut term = Expr::term(coefficient.clone(), Monomial::one());
            for (atom, power) in monomial.factors() {
                let factor = if atom.symbol() != symbol {
                    Expr::term(Rational::one(), Monomial::atom(atom.clone(), power))
                } else {
                    substitute_atom(atom, power, symbol, replacement)?
                };
                term = term * factor;
            }
            result = result + term;
        }
        Ok(result)
    }

    /// Applies several substitutions one after another.
    pub fn subs_all(&self, substitutions: &[(&str, Expr)]) -> Result<Expr, SymbolicError> {
        substitutions
            .iter()
            .try_fold(self.clone(), |e, (symbol, replacement)| {
                e.subs(symbol, replacement)
            })
    }

    /// The coefficient of `symbol¹`: the terms in which the symbol appears to exactly the first
    /// power, with the symbol removed.
    pub fn coefficient_of(&self, symbol: &str) -> Expr {
        self.coefficient_of_power(symbol, 1)
    }

    /// The terms in which `symbol` appears to exactly `power` (0: not at all), with the symbol
    /// removed. Sin and cos of the symbol count as other atoms.
    pub fn coefficient_of_power(&self, symbol: &str, power: i32) -> Expr {
        let atom = Atom::Symbol(symbol.to_owned());
        let mut result = Expr::zero();
        for (monomial, coefficient) in self.terms() {
            let (rest, p) = monomial.without(&atom);
            if p == power {
                result.add_term(coefficient.clone(), rest);
            }
        }
        result
    }

    /// Evaluates at a point, for numeric cross-checks; `value` gives each symbol's value.
    pub fn eval(&self, value: &dyn Fn(&str) -> f64) -> f64 {
        self.terms()
            .map(|(m, c)| {
                let c = rational_to_f64(c);
                m.factors().fold(c, |acc, (atom, power)| {
                    let base = match atom {
                        Atom::Symbol(s) => value(s),
                        Atom::Sin(s) => value(s).sin(),
                        Atom::Cos(s) => value(s).cos(),
                    };
                    acc * base.powi(power)
                })
            })
            .sum()
    }
}

/// The exact rational as the nearest-ish f64 (numerator and denominator are small here).
fn rational_to_f64(r: &Rational) -> f64 {
    use num_traits::ToPrimitive;
    r.to_f64().unwrap_or(f64::NAN)
}

fn first_reducible_sine(monomial: &Monomial) -> Option<(String, i32)> {
    monomial.factors().find_map(|(atom, power)| match atom {
        Atom::Sin(angle) if power >= 2 => Some((angle.clone(), power)),
        _ => None,
    })
}

fn substitute_atom(
    atom: &Atom,
    power: i32,
    symbol: &str,
    replacement: &Expr,
) -> Result<Expr, SymbolicError> {
    match atom {
        Atom::Symbol(_) => replacement.pow(power),
        Atom::Sin(_) | Atom::Cos(_) => {
            let renamed =
                single_symbol(replacement).ok_or_else(|| SymbolicError::AngleSubstitution {
                    angle: symbol.to_owned(),
                    replacement: replacement.to_string(),
                })?;
            Ok(Expr::term(
                Rational::one(),
                Monomial::atom(atom.renamed(&renamed), power),
            ))
        }
    }
}

/// The name, if the expression is exactly one symbol with coefficient 1.
fn single_symbol(e: &Expr) -> Option<String> {
    let mut terms = e.terms();
    let (monomial, coefficient) = terms.next()?;
    if terms.next().is_some() || !coefficient.is_one() {
        return None;
    }
    let mut factors = monomial.factors();
    match (factors.next(), factors.next()) {
        (Some((Atom::Symbol(name), 1)), None) => Some(name.clone()),
        _ => None,
    }
}

impl Add<&Expr> for &Expr {
    type Output = Expr;
    fn add(self, rhs: &Expr) -> Expr {
        let mut sum = self.clone();
        for (m, c) in rhs.terms() {
            sum.add_term(c.clone(), m.clone());
        }
        sum
    }
}

impl Neg for &Expr {
    type Output = Expr;
    fn neg(self) -> Expr {
        self.scale(&-Rational::one())
    }
}

impl Sub<&Expr> for &Expr {
    type Output = Expr;
    fn sub(self, rhs: &Expr) -> Expr {
        self + &(-rhs)
    }
}

impl Mul<&Expr> for &Expr {
    type Output = Expr;
    fn mul(self, rhs: &Expr) -> Expr {
        let mut product = Expr::zero();
        for (m1, c1) in self.terms() {
            for (m2, c2) in rhs.terms() {
                product.add_term(c1 * c2, m1.times(m2));
            }
        }
        product
    }
}

/// Owned forms of the operators, delegating to the borrowed ones.
macro_rules! owned_binary_ops {
    ($($trait:ident $method:ident),*) => {$(
        impl $trait<Expr> for Expr {
            type Output = Expr;
            fn $method(self, rhs: Expr) -> Expr { (&self).$method(&rhs) }
        }
        impl $trait<&Expr> for Expr {
            type Output = Expr;
            fn $method(self, rhs: &Expr) -> Expr { (&self).$method(rhs) }
        }
        impl $trait<Expr> for &Expr {
            type Output = Expr;
            fn $method(self, rhs: Expr) -> Expr { self.$method(&rhs) }
        }
    )*};
}
owned_binary_ops!(Add add, Sub sub, Mul mul);

impl Neg for Expr {
    type Output = Expr;
    fn neg(self) -> Expr {
        -&self
    }
}

impl std::iter::Sum for Expr {
    fn sum<I: Iterator<Item = Expr>>(iter: I) -> Expr {
        iter.fold(Expr::zero(), |acc, e| acc + e)
    }
}

impl fmt::Display for Expr {
    /// Rust-like text: `2*Ixx*p - q*r*cos(theta)^-1`; `0` for the empty sum.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_zero() {
            return write!(f, "0");
        }
        for (i, (monomial, coefficient)) in self.terms().enumerate() {
            let magnitude = coefficient.abs();
            let sign = match (i, coefficient.is_negative()) {
                (0, true) => "-",
                (0, false) => "",
                (_, true) => " - ",
                (_, false) => " + ",
            };
            write!(f, "{sign}")?;
            match (magnitude.is_one(), monomial.is_one()) {
                (true, _) => write!(f, "{monomial}")?,
                (false, true) => write!(f, "{magnitude}")?,
                (false, false) => write!(f, "{magnitude}*{monomial}")?,
            }
        }
        Ok(())
    }
}
