//! The checker cannot be fooled: every single-term mutation of every reference form is caught.
//!
//! Mutations, applied one at a time anywhere in a reference form's syntax tree:
//! drop one term of a sum, flip one sign (`+` ↔ `−`, or remove a unary minus), swap two
//! symbols everywhere, change one coefficient (a literal n → n + 1, or an implicit 1 → 2).
//! Whether a mutant really differs is judged independently of the engine, by evaluating both
//! texts numerically at random points; mutants that agree there (e.g. swapping `Ixy` and `Iyx`,
//! which 4.14 makes equal) are equivalent, and the engine must call those equal too.

use eom_codegen::check::{Component, Definition};
use eom_codegen::derivation;
use eom_codegen::symbolic::{parse_tree, symbol_name};
use quote::ToTokens;
use std::collections::BTreeSet;
use syn::{BinOp, Expr as Syn, UnOp, parse_quote};

#[derive(Default, Debug)]
struct Tally {
    generated: usize,
    equivalent: usize,
    caught: usize,
    missed: Vec<String>,
    disagreements: Vec<String>,
}

#[test]
fn every_single_term_mutation_of_every_reference_form_is_caught() {
    let mut tally = Tally::default();
    for equation in derivation::all().unwrap() {
        for component in &equation.components {
            let tag = format!("({}) {}", equation.number, component.label);
            judge_component(component, &tag, &mut tally);
        }
    }
    println!(
        "mutants: {} generated, {} equivalent (numerically), {} caught of {}",
        tally.generated,
        tally.equivalent,
        tally.caught,
        tally.generated - tally.equivalent
    );
    assert!(tally.missed.is_empty(), "missed: {:#?}", tally.missed);
    assert!(
        tally.disagreements.is_empty(),
        "engine called a numerically equal mutant different: {:#?}",
        tally.disagreements
    );
    assert!(
        tally.generated > 1000,
        "too few mutants to mean anything: {}",
        tally.generated
    );
}

fn judge_component(component: &Component, tag: &str, tally: &mut Tally) {
    let original = parse_tree(&component.reference_text).unwrap();
    for mutant in mutants(&original) {
        let text = mutant.to_token_stream().to_string();
        let candidate = Component {
            reference_text: text.clone(),
            ..component.clone()
        };
        let engine_equal = candidate.residual().map(|r| r.is_zero()).unwrap_or(false);
        tally.generated += 1;
        if numerically_equal(&original, &mutant, &component.definitions) {
            tally.equivalent += 1;
            println!("equivalent mutant {tag}: {text}");
            if !engine_equal {
                tally.disagreements.push(format!("{tag}: {text}"));
            }
        } else if engine_equal {
            tally.missed.push(format!("{tag}: {text}"));
        } else {
            tally.caught += 1;
        }
    }
}

/// Every single mutation of the tree.
fn mutants(tree: &Syn) -> Vec<Syn> {
    let mut all = local_mutants(tree);
    if !matches!(tree, Syn::Binary(b) if is_sum(&b.op)) {
        all.push(parse_quote!(2 * (#tree)));
    }
    all.extend(symbol_swaps(tree));
    all
}

fn is_sum(op: &BinOp) -> bool {
    matches!(op, BinOp::Add(_) | BinOp::Sub(_))
}

/// Mutations at this node and, recursively, at every node below it.
fn local_mutants(tree: &Syn) -> Vec<Syn> {
    let mut out = Vec::new();
    match tree {
        Syn::Binary(b) => {
            if is_sum(&b.op) {
                let (left, right) = (&*b.left, &*b.right);
                out.push(left.clone());
                out.push(match b.op {
                    BinOp::Sub(_) => parse_quote!(-#right),
                    _ => right.clone(),
                });
                let mut flipped = b.clone();
                flipped.op = match b.op {
                    BinOp::Add(_) => parse_quote!(-),
                    _ => parse_quote!(+),
                };
                out.push(Syn::Binary(flipped));
                for (i, operand) in [left, right].into_iter().enumerate() {
                    if !matches!(operand, Syn::Binary(inner) if is_sum(&inner.op)) {
                        let mut doubled = b.clone();
                        let twice: Syn = parse_quote!(2 * (#operand));
                        let slot = if i == 0 {
                            &mut doubled.left
                        } else {
                            &mut doubled.right
                        };
                        **slot = twice;
                        out.push(Syn::Binary(doubled));
                    }
                }
            }
            for m in local_mutants(&b.left) {
                let mut c = b.clone();
                c.left = Box::new(m);
                out.push(Syn::Binary(c));
            }
            for m in local_mutants(&b.right) {
                let mut c = b.clone();
                c.right = Box::new(m);
                out.push(Syn::Binary(c));
            }
        }
        Syn::Unary(u) if matches!(u.op, UnOp::Neg(_)) => {
            out.push((*u.expr).clone());
            for m in local_mutants(&u.expr) {
                let mut c = u.clone();
                c.expr = Box::new(m);
                out.push(Syn::Unary(c));
            }
        }
        Syn::Paren(p) => {
            for m in local_mutants(&p.expr) {
                let mut c = p.clone();
                c.expr = Box::new(m);
                out.push(Syn::Paren(c));
            }
        }
        Syn::MethodCall(call) => {
            for (i, arg) in call.args.iter().enumerate() {
                for m in local_mutants(arg) {
                    let mut c = call.clone();
                    *c.args.iter_mut().nth(i).unwrap() = m;
                    out.push(Syn::MethodCall(c));
                }
            }
        }
        Syn::Lit(lit) => {
            let value: f64 = lit.to_token_stream().to_string().parse().unwrap();
            let bumped = syn::LitInt::new(
                &format!("{}", value as i64 + 1),
                proc_macro2::Span::call_site(),
            );
            out.push(parse_quote!(#bumped));
        }
        _ => {}
    }
    out
}

fn symbols(tree: &Syn, found: &mut BTreeSet<String>) {
    match tree {
        Syn::Path(_) => {
            found.insert(symbol_name(tree).unwrap());
        }
        Syn::Binary(b) => {
            symbols(&b.left, found);
            symbols(&b.right, found);
        }
        Syn::Unary(u) => symbols(&u.expr, found),
        Syn::Paren(p) => symbols(&p.expr, found),
        Syn::MethodCall(call) => {
            symbols(&call.receiver, found);
            call.args.iter().for_each(|a| symbols(a, found));
        }
        _ => {}
    }
}

fn symbol_swaps(tree: &Syn) -> Vec<Syn> {
    let mut found = BTreeSet::new();
    symbols(tree, &mut found);
    let names: Vec<String> = found.into_iter().collect();
    let mut out = Vec::new();
    for (i, a) in names.iter().enumerate() {
        for b in &names[i + 1..] {
            let mut swapped = tree.clone();
            rename(&mut swapped, a, b);
            out.push(swapped);
        }
    }
    out
}

fn rename(tree: &mut Syn, a: &str, b: &str) {
    match tree {
        Syn::Path(_) => {
            let name = symbol_name(tree).unwrap();
            let new = if name == a {
                b
            } else if name == b {
                a
            } else {
                return;
            };
            let ident = syn::Ident::new(new, proc_macro2::Span::call_site());
            *tree = parse_quote!(#ident);
        }
        Syn::Binary(x) => {
            rename(&mut x.left, a, b);
            rename(&mut x.right, a, b);
        }
        Syn::Unary(x) => rename(&mut x.expr, a, b),
        Syn::Paren(x) => rename(&mut x.expr, a, b),
        Syn::MethodCall(x) => {
            rename(&mut x.receiver, a, b);
            x.args.iter_mut().for_each(|arg| rename(arg, a, b));
        }
        _ => {}
    }
}

/// Evaluates a reference tree numerically, without the canonical form.
fn evaluate(tree: &Syn, value: &dyn Fn(&str) -> f64) -> f64 {
    match tree {
        Syn::Binary(b) => {
            let (l, r) = (evaluate(&b.left, value), evaluate(&b.right, value));
            match b.op {
                BinOp::Add(_) => l + r,
                BinOp::Sub(_) => l - r,
                BinOp::Mul(_) => l * r,
                BinOp::Div(_) => l / r,
                _ => panic!("unexpected operator"),
            }
        }
        Syn::Unary(u) => -evaluate(&u.expr, value),
        Syn::Paren(p) => evaluate(&p.expr, value),
        Syn::Lit(lit) => lit.to_token_stream().to_string().parse().unwrap(),
        Syn::Path(_) => value(&symbol_name(tree).unwrap()),
        Syn::MethodCall(call) => {
            let x = evaluate(&call.receiver, value);
            match call.method.to_string().as_str() {
                "sin" => x.sin(),
                "cos" => x.cos(),
                "tan" => x.tan(),
                "sec" => 1.0 / x.cos(),
                "powi" => x.powi(evaluate(&call.args[0], value) as i32),
                other => panic!("unexpected method {other}"),
            }
        }
        other => panic!("unexpected node {}", other.to_token_stream()),
    }
}

/// A repeatable value in [0.3, 1.7) for each (symbol, point): away from the zeros of cos.
fn pseudo_random(name: &str, point: u64) -> f64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325 ^ point.wrapping_mul(0x9e37_79b9_7f4a_7c15);
    for byte in name.bytes() {
        h = (h ^ u64::from(byte)).wrapping_mul(0x100_0000_01b3);
    }
    // The splitmix64 finaliser, so that names differing in one byte get unrelated values.
    h = (h ^ (h >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h = (h ^ (h >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^= h >> 31;
    0.3 + 1.4 * ((h >> 11) as f64 / (1u64 << 53) as f64)
}

/// Equal at five random points to a relative 1e-9: far above the round-off of evaluating a
/// few dozen terms of size ~1, far below the smallest change a mutation makes.
fn numerically_equal(a: &Syn, b: &Syn, definitions: &[Definition]) -> bool {
    (0..5).all(|point| {
        let base = |name: &str| pseudo_random(name, point);
        let value = |name: &str| match definitions.iter().find(|(s, _)| s == name) {
            Some((_, def)) => def.eval(&base),
            None => base(name),
        };
        let (x, y) = (evaluate(a, &value), evaluate(b, &value));
        (x - y).abs() <= 1e-9 * (1.0 + x.abs().max(y.abs()))
    })
}
