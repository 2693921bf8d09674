//! Reference forms: the book's equations transcribed as Rust expression text, read with `syn`.
//!
//! Writing each reference as `Ixx*p_dot + (Izz - Iyy)*q*r + …` keeps the transcription close
//! enough to the printed page to check by eye, while `syn` does the tokenising and precedence.
//! Supported: `+ - * /`, unary minus, parentheses, integer and decimal literals (read exactly),
//! symbols, `x.powi(n)`, and `sin cos tan sec` written as `theta.sin()` or `sin(theta)`.

use super::expr::{Expr, Rational, SymbolicError};
use num_bigint::BigInt;
use num_traits::{One, Zero};
use quote::ToTokens;
use syn::{BinOp, Expr as Syn, Lit, UnOp};

/// Parses reference text into a canonical expression.
///
/// ```
/// use eom_codegen::symbolic::{parse, Expr};
/// let e = parse("theta.sin()*theta.sin() + theta.cos().powi(2)").unwrap();
/// assert_eq!(e, Expr::int(1));
/// ```
pub fn parse(text: &str) -> Result<Expr, SymbolicError> {
    let tree = parse_tree(text)?;
    to_expr(&tree)
}

/// Parses reference text into a `syn` tree (kept for printing and for mutation tests).
pub fn parse_tree(text: &str) -> Result<Syn, SymbolicError> {
    syn::parse_str::<Syn>(text).map_err(|e| SymbolicError::Parse {
        text: text.to_owned(),
        reason: e.to_string(),
    })
}

/// Converts a `syn` expression tree into a canonical expression.
pub fn to_expr(tree: &Syn) -> Result<Expr, SymbolicError> {
    match tree {
        Syn::Binary(b) => binary(&b.op, to_expr(&b.left)?, to_expr(&b.right)?, tree),
        Syn::Unary(u) if matches!(u.op, UnOp::Neg(_)) => Ok(-to_expr(&u.expr)?),
        Syn::Paren(p) => to_expr(&p.expr),
        Syn::Group(g) => to_expr(&g.expr),
        Syn::Lit(lit) => literal(&lit.lit),
        Syn::Path(_) => Ok(Expr::symbol(&symbol_name(tree)?)),
        Syn::MethodCall(call) => {
            let args: Vec<&Syn> = call.args.iter().collect();
            function(&call.method.to_string(), &call.receiver, &args, tree)
        }
        Syn::Call(call) => {
            let name = symbol_name(&call.func)?;
            let args: Vec<&Syn> = call.args.iter().collect();
            match args.split_first() {
                Some((first, rest)) => function(&name, first, rest, tree),
                None => Err(unsupported(tree, "a call needs an argument")),
            }
        }
        _ => Err(unsupported(tree, "not an arithmetic expression")),
    }
}

fn binary(op: &BinOp, left: Expr, right: Expr, tree: &Syn) -> Result<Expr, SymbolicError> {
    match op {
        BinOp::Add(_) => Ok(left + right),
        BinOp::Sub(_) => Ok(left - right),
        BinOp::Mul(_) => Ok(left * right),
        BinOp::Div(_) => left.div(&right),
        _ => Err(unsupported(tree, "only + - * / are supported")),
    }
}

fn function(name: &str, receiver: &Syn, args: &[&Syn], tree: &Syn) -> Result<Expr, SymbolicError> {
    match (name, args) {
        ("sin", []) => Ok(Expr::sin(&symbol_name(receiver)?)),
        ("cos", []) => Ok(Expr::cos(&symbol_name(receiver)?)),
        ("tan", []) => Ok(Expr::tan(&symbol_name(receiver)?)),
        ("sec", []) => Ok(Expr::sec(&symbol_name(receiver)?)),
        ("powi", [exponent]) => to_expr(receiver)?.pow(integer_exponent(exponent)?),
        _ => Err(unsupported(tree, "unknown function")),
    }
}

fn integer_exponent(tree: &Syn) -> Result<i32, SymbolicError> {
    let value = to_expr(tree)?
        .as_constant()
        .filter(|c| c.is_integer())
        .ok_or_else(|| unsupported(tree, "powi needs an integer constant"))?;
    i32::try_from(value.to_integer()).map_err(|_| unsupported(tree, "exponent too large"))
}

/// The name of a plain identifier; trigonometric functions take only these as arguments.
pub fn symbol_name(tree: &Syn) -> Result<String, SymbolicError> {
    match tree {
        Syn::Path(p) if p.qself.is_none() => p
            .path
            .get_ident()
            .map(|ident| ident.to_string())
            .ok_or_else(|| unsupported(tree, "expected a plain symbol")),
        Syn::Paren(p) => symbol_name(&p.expr),
        Syn::Group(g) => symbol_name(&g.expr),
        _ => Err(unsupported(tree, "expected a plain symbol")),
    }
}

fn literal(lit: &Lit) -> Result<Expr, SymbolicError> {
    let digits = match lit {
        Lit::Int(i) => i.base10_digits().to_owned(),
        Lit::Float(f) => f.base10_digits().to_owned(),
        _ => {
            return Err(unsupported_text(
                &lit.to_token_stream().to_string(),
                "not a number",
            ));
        }
    };
    decimal(&digits).map(Expr::constant)
}

/// Reads a decimal literal (`12`, `0.5`, `2.5e-3`) as an exact rational.
fn decimal(digits: &str) -> Result<Rational, SymbolicError> {
    let bad = || unsupported_text(digits, "not a decimal number");
    let (mantissa, exponent) = match digits.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i32>().map_err(|_| bad())?),
        None => (digits, 0),
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let all: BigInt = format!("{whole}{fraction}").parse().map_err(|_| bad())?;
    let shift = exponent - i32::try_from(fraction.len()).map_err(|_| bad())?;
    let ten = Rational::from_integer(BigInt::from(10));
    let scale = if shift >= 0 {
        (0..shift).fold(Rational::one(), |acc, _| acc * &ten)
    } else {
        (0..-shift).fold(Rational::one(), |acc, _| acc / &ten)
    };
    let value = Rational::from_integer(all) * scale;
    if value.is_zero() && !digits.chars().any(|c| c.is_ascii_digit()) {
        return Err(bad());
    }
    Ok(value)
}

fn unsupported(tree: &Syn, reason: &str) -> SymbolicError {
    unsupported_text(&tree.to_token_stream().to_string(), reason)
}

fn unsupported_text(text: &str, reason: &str) -> SymbolicError {
    SymbolicError::Parse {
        text: text.to_owned(),
        reason: reason.to_owned(),
    }
}
