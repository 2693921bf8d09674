//! The symbolic core: atoms, monomials, canonical expressions, vectors and matrices of them,
//! the reader for reference forms and the LaTeX printer.

mod atom;
mod expr;
pub mod latex;
mod linalg;
mod monomial;
mod parse;

pub use atom::Atom;
pub use expr::{Expr, Rational, SymbolicError};
pub use linalg::{Mat3, Vec3, adjugate, determinant};
pub use monomial::Monomial;
pub use parse::{parse, parse_tree, symbol_name, to_expr};
