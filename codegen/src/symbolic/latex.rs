//! LaTeX for the derivation report: symbols as the chapter writes them.
//!
//! Names in the engine are ASCII (`psi_dot`, `Ixy`, `x_G`, `Sxy`); the report shows them as
//! the book does (ψ̇, I_xy, x_G, ∫xy dm). Reference forms are printed from their `syn` tree so
//! that their grouping stays the book's; derived forms are printed expanded, as computed.

use super::atom::Atom;
use super::expr::{Expr, Rational};
use num_traits::{One, Signed};
use syn::{BinOp, Expr as Syn, UnOp};

const GREEK: [&str; 8] = [
    "phi", "theta", "psi", "omega", "kappa", "rho", "alpha", "beta",
];

/// LaTeX for one symbol name.
///
/// ```
/// use eom_codegen::symbolic::latex::symbol;
/// assert_eq!(symbol("psi_dot"), r"\dot{\psi}");
/// assert_eq!(symbol("Ixy"), "I_{xy}");
/// assert_eq!(symbol("Sxy"), r"{\textstyle\int} x y\,dm");
/// assert_eq!(symbol("Sxx_G"), r"{\textstyle\int} x'^2\,dm");
/// assert_eq!(symbol("I0"), "I_{0}");
/// ```
pub fn symbol(name: &str) -> String {
    if let Some(base) = name.strip_suffix("_ddot") {
        return format!(r"\ddot{{{}}}", symbol(base));
    }
    if let Some(base) = name.strip_suffix("_dot") {
        return format!(r"\dot{{{}}}", symbol(base));
    }
    if GREEK.contains(&name) {
        return format!(r"\{name}");
    }
    if let Some(axes) = moment_axes(name, 'I') {
        return match name.strip_suffix("_G") {
            Some(_) => format!("I^G_{{{}}}", &axes[..2]),
            None => format!("I_{{{axes}}}"),
        };
    }
    if let Some(axes) = moment_axes(name, 'S') {
        let primed = name.ends_with("_G");
        let prime = if primed { "'" } else { "" };
        let (a, b) = (&axes[..1], &axes[1..2]);
        let integrand = if a == b {
            format!("{a}{prime}^2")
        } else {
            format!("{a}{prime} {b}{prime}")
        };
        return format!(r"{{\textstyle\int}} {integrand}\,dm");
    }
    if let Some(coordinate) = name
        .strip_suffix('p')
        .filter(|c| ["x", "y", "z"].contains(c))
    {
        return format!("{coordinate}'");
    }
    if let Some(base) = name.strip_suffix(|c: char| c.is_ascii_digit()) {
        return format!("{}_{{{}}}", symbol(base), &name[base.len()..]);
    }
    match name.split_once('_') {
        Some((base, sub)) => format!("{}_{{{sub}}}", symbol(base)),
        None => name.to_owned(),
    }
}

/// `Ixy` → `Some("xy")`, `Ixy_G` → `Some("xy_G")` for the given leading letter.
fn moment_axes(name: &str, letter: char) -> Option<&str> {
    let rest = name.strip_prefix(letter)?;
    let axes = rest.strip_suffix("_G").unwrap_or(rest);
    let is_axes = axes.len() == 2 && axes.chars().all(|c| "xyz".contains(c));
    is_axes.then_some(rest)
}

/// LaTeX for a canonical expression, expanded.
pub fn expr(e: &Expr) -> String {
    if e.is_zero() {
        return "0".into();
    }
    let mut out = String::new();
    for (i, (monomial, coefficient)) in e.terms().enumerate() {
        out.push_str(match (i, coefficient.is_negative()) {
            (0, true) => "-",
            (0, false) => "",
            (_, true) => " - ",
            (_, false) => " + ",
        });
        let factors: Vec<String> = monomial.factors().map(|(a, p)| atom(a, p)).collect();
        let magnitude = coefficient.abs();
        let number = rational(&magnitude);
        let body = match (magnitude.is_one(), factors.is_empty()) {
            (true, true) => "1".to_owned(),
            (true, false) => factors.join(r"\,"),
            (false, true) => number,
            (false, false) => format!(r"{number}\,{}", factors.join(r"\,")),
        };
        out.push_str(&body);
    }
    out
}

fn rational(r: &Rational) -> String {
    if r.is_integer() {
        r.numer().to_string()
    } else {
        format!(r"\tfrac{{{}}}{{{}}}", r.numer(), r.denom())
    }
}

fn atom(a: &Atom, power: i32) -> String {
    let (name, power) = match a {
        Atom::Symbol(s) => (symbol(s), power),
        Atom::Sin(s) => (format!(r"\sin {}", symbol(s)), power),
        Atom::Cos(s) if power < 0 => (format!(r"\sec {}", symbol(s)), -power),
        Atom::Cos(s) => (format!(r"\cos {}", symbol(s)), power),
    };
    match (power, a) {
        (1, _) => name,
        (_, Atom::Symbol(_)) => format!("{{{name}}}^{{{power}}}"),
        (_, _) => {
            let (function, argument) = name.split_once(' ').unwrap_or((&name, ""));
            format!("{function}^{{{power}}} {argument}")
        }
    }
}

/// LaTeX for a reference form, keeping the book's grouping.
pub fn reference(tree: &Syn) -> String {
    match tree {
        Syn::Binary(b) => {
            let (l, r) = (reference(&b.left), reference(&b.right));
            match b.op {
                BinOp::Add(_) => format!("{l} + {r}"),
                BinOp::Sub(_) => format!("{l} - {r}"),
                BinOp::Div(_) => format!(r"\frac{{{l}}}{{{r}}}"),
                _ => format!(r"{l}\,{r}"),
            }
        }
        Syn::Unary(u) if matches!(u.op, UnOp::Neg(_)) => format!("-{}", reference(&u.expr)),
        Syn::Paren(p) => format!(r"\left({}\right)", reference(&p.expr)),
        Syn::Group(g) => reference(&g.expr),
        Syn::MethodCall(call) => {
            method(&call.method.to_string(), &call.receiver, call.args.first())
        }
        Syn::Call(call) => {
            let name = super::parse::symbol_name(&call.func).unwrap_or_default();
            match call.args.first() {
                Some(arg) => method(&name, arg, None),
                None => name,
            }
        }
        Syn::Path(_) => symbol(&super::parse::symbol_name(tree).unwrap_or_default()),
        Syn::Lit(lit) => quote::ToTokens::to_token_stream(&lit.lit).to_string(),
        other => quote::ToTokens::to_token_stream(other).to_string(),
    }
}

fn method(name: &str, receiver: &Syn, arg: Option<&Syn>) -> String {
    let base = reference(receiver);
    match (name, arg) {
        ("powi", Some(exponent)) => format!("{{{base}}}^{{{}}}", reference(exponent)),
        _ => format!(r"\{name} {base}"),
    }
}
