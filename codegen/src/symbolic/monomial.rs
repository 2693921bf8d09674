//! Monomials: products of atoms with integer exponents.

use super::atom::Atom;
use std::collections::BTreeMap;
use std::fmt;

/// A product of atoms, each raised to a non-zero integer power.
///
/// Negative powers appear only where the chapter divides by a monomial: cos⁻¹θ (sec, tan),
/// 1/I₀ when 4.24 is solved for θ̈. Sines never carry a power above one in canonical form
/// (see [`crate::symbolic::Expr`]), and never a negative one.
#[derive(Debug, Clone, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Monomial {
    powers: BTreeMap<Atom, i32>,
}

impl Monomial {
    /// The empty product, 1.
    pub fn one() -> Self {
        Self::default()
    }

    /// A single atom to a power (the empty product if the power is zero).
    pub fn atom(atom: Atom, power: i32) -> Self {
        let mut m = Self::one();
        m.multiply_atom(atom, power);
        m
    }

    /// The factors in canonical order.
    pub fn factors(&self) -> impl Iterator<Item = (&Atom, i32)> {
        self.powers.iter().map(|(a, &e)| (a, e))
    }

    /// The power of `atom` (zero if absent).
    pub fn power(&self, atom: &Atom) -> i32 {
        self.powers.get(atom).copied().unwrap_or(0)
    }

    /// True for the empty product.
    pub fn is_one(&self) -> bool {
        self.powers.is_empty()
    }

    /// Multiplies in one atom to a power, dropping it if the power cancels.
    pub fn multiply_atom(&mut self, atom: Atom, power: i32) {
        let entry = self.powers.entry(atom).or_insert(0);
        *entry += power;
        if *entry == 0 {
            self.powers.retain(|_, e| *e != 0);
        }
    }

    /// The product of two monomials (not yet reduced by sin² = 1 − cos²).
    pub fn times(&self, other: &Monomial) -> Monomial {
        let mut product = self.clone();
        for (atom, power) in other.factors() {
            product.multiply_atom(atom.clone(), power);
        }
        product
    }

    /// The monomial with `atom` removed, and the power it had.
    pub fn without(&self, atom: &Atom) -> (Monomial, i32) {
        let mut rest = self.clone();
        let power = rest.powers.remove(atom).unwrap_or(0);
        (rest, power)
    }

    /// The reciprocal, if it exists as a monomial (it does not when a sine is a factor).
    pub fn reciprocal(&self) -> Option<Monomial> {
        if self.powers.keys().any(|a| matches!(a, Atom::Sin(_))) {
            return None;
        }
        let powers = self.powers.iter().map(|(a, e)| (a.clone(), -e)).collect();
        Some(Monomial { powers })
    }
}

impl fmt::Display for Monomial {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for (atom, power) in self.factors() {
            if !first {
                write!(f, "*")?;
            }
            first = false;
            match power {
                1 => write!(f, "{atom}")?,
                _ => write!(f, "{atom}^{power}")?,
            }
        }
        if first {
            write!(f, "1")?;
        }
        Ok(())
    }
}
