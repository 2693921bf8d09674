//! Atoms: the indivisible factors of a monomial.
//!
//! Every expression of the chapter is a polynomial in symbols and in the sine and cosine of
//! angle symbols. Tangent and secant are not atoms of their own: they are written through
//! sin and cos (tan θ = sin θ · cos⁻¹θ, sec θ = cos⁻¹θ), which is what lets the canonical form
//! see every trigonometric identity the chapter needs.

use std::fmt;

/// An indivisible factor: a symbol, or the sine or cosine of an angle symbol.
///
/// The derived order (symbols first, then sines, then cosines, each by name) is the order in
/// which factors are printed and emitted, so it must never depend on anything but the names.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Atom {
    /// A named quantity: a coordinate, a rate, a parameter.
    Symbol(String),
    /// `sin(angle)`.
    Sin(String),
    /// `cos(angle)`.
    Cos(String),
}

impl Atom {
    /// The symbol the atom depends on: its own name, or the angle inside sin/cos.
    pub fn symbol(&self) -> &str {
        match self {
            Atom::Symbol(name) | Atom::Sin(name) | Atom::Cos(name) => name,
        }
    }

    /// The same atom with its symbol renamed.
    pub fn renamed(&self, name: &str) -> Atom {
        match self {
            Atom::Symbol(_) => Atom::Symbol(name.to_owned()),
            Atom::Sin(_) => Atom::Sin(name.to_owned()),
            Atom::Cos(_) => Atom::Cos(name.to_owned()),
        }
    }
}

impl fmt::Display for Atom {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Atom::Symbol(name) => write!(f, "{name}"),
            Atom::Sin(angle) => write!(f, "sin({angle})"),
            Atom::Cos(angle) => write!(f, "cos({angle})"),
        }
    }
}
