//! The straight-line program: what the generated function computes, in order.
//!
//! Each stage and output is a sum of `coefficient × runtime monomial`. Coefficients depend on
//! parameters only and are hoisted into a struct computed once; runtime monomials are built as
//! products of leaves (state, inputs, stages, sin, cos, sec of angles) with every prefix product
//! shared, so `q*r` is computed once however many equations use it. One `sin_cos` per angle,
//! sec θ as the reciprocal of that same cosine, and each other reciprocal once.

use crate::model::System;
use crate::symbolic::{Atom, Expr, Monomial, Rational};
use num_traits::{One, Signed};
use std::collections::BTreeMap;

/// Counts of the operations one call performs (`sin_cos` counts as one trigonometric call).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Operations {
    /// Additions, subtractions and negations.
    pub add: u32,
    /// Multiplications.
    pub mul: u32,
    /// Divisions and reciprocals.
    pub div: u32,
    /// Square roots.
    pub sqrt: u32,
    /// Trigonometric calls.
    pub trig: u32,
}

impl Operations {
    /// A cost for choosing between strategies: trigonometric calls first, then divisions,
    /// then arithmetic.
    pub fn cost(&self) -> (u32, u32, u32) {
        (self.trig, self.div + self.sqrt, self.add + self.mul)
    }
}

/// One term of a sum: ± coefficient × factor (either may be absent, not both).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Term {
    /// Subtract rather than add.
    pub negative: bool,
    /// Index into the hoisted coefficients.
    pub coefficient: Option<usize>,
    /// A runtime variable.
    pub factor: Option<String>,
}

/// One `let` of the generated function.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Step {
    /// The sine and cosine of an angle: with the emitted kernel, one `sin_cos([…])` call for
    /// all of a program's angles; with [`Trig::Std`](super::Trig::Std),
    /// `let (s_a, c_a) = a.simd_sin_cos();`.
    SinCos {
        /// The angle's variable.
        angle: String,
    },
    /// `let name = of.simd_recip();` (sec θ from cos θ, 1/|q|² from |q|²)
    Reciprocal {
        /// The new variable.
        name: String,
        /// The variable inverted.
        of: String,
    },
    /// `let name = left * right;`
    Product {
        /// The new variable.
        name: String,
        /// Left factor.
        left: String,
        /// Right factor.
        right: String,
    },
    /// `let name = Σ terms;`
    Sum {
        /// The new variable.
        name: String,
        /// The terms, in canonical order.
        terms: Vec<Term>,
    },
}

/// A hoisted coefficient: a parameter expression computed once.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Coefficient {
    /// The field name, `k0`, `k1`, …
    pub name: String,
    /// The value in parameters.
    pub value: Expr,
}

/// The straight-line program of one system.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Program {
    /// Hoisted coefficients in order of first use.
    pub coefficients: Vec<Coefficient>,
    /// The computation, in order.
    pub steps: Vec<Step>,
    /// The variable holding each output.
    pub outputs: Vec<String>,
    /// What a call costs.
    pub operations: Operations,
}

/// The Rust identifier of a symbol in generated code.
pub fn identifier(symbol: &str) -> String {
    match symbol {
        "M" => "mass".into(),
        _ => symbol.to_lowercase(),
    }
}

struct Builder<'a> {
    system: &'a System,
    program: Program,
    coefficient_index: BTreeMap<Expr, usize>,
    products: BTreeMap<Vec<String>, String>,
    angles_with_sin_cos: Vec<String>,
    reciprocals: Vec<String>,
}

impl Program {
    /// Builds the program of a system.
    pub fn build(system: &System) -> Program {
        let mut b = Builder {
            system,
            program: Program {
                coefficients: vec![],
                steps: vec![],
                outputs: vec![],
                operations: Operations::default(),
            },
            coefficient_index: BTreeMap::new(),
            products: BTreeMap::new(),
            angles_with_sin_cos: vec![],
            reciprocals: vec![],
        };
        for (name, value) in &system.stages {
            b.sum_into(identifier(name), value);
        }
        for (state, value) in system.state.iter().zip(&system.outputs) {
            let output = b.output(state, value);
            b.program.outputs.push(output);
        }
        b.program
    }
}

impl Builder<'_> {
    fn is_runtime(&self, atom: &Atom) -> bool {
        match atom {
            Atom::Symbol(s) => !self.system.is_parameter(s),
            Atom::Sin(_) | Atom::Cos(_) => true,
        }
    }

    /// An output that is a single runtime variable needs no `let`.
    fn output(&mut self, state: &str, value: &Expr) -> String {
        let mut terms = value.terms();
        if let (Some((monomial, c)), None) = (terms.next(), terms.next())
            && c.is_one()
            && let Some(var) = self.single_leaf(monomial)
        {
            return var;
        }
        let name = format!("{}_rate", identifier(state));
        self.sum_into(name.clone(), value);
        name
    }

    /// The variable of a monomial that is one runtime atom to the first power, if it is one.
    fn single_leaf(&mut self, monomial: &Monomial) -> Option<String> {
        let mut factors = monomial.factors();
        match (factors.next(), factors.next()) {
            (Some((atom, 1)), None) if self.is_runtime(atom) => self.leaves(monomial).pop(),
            _ => None,
        }
    }

    fn sum_into(&mut self, name: String, value: &Expr) {
        let mut groups: BTreeMap<Monomial, Expr> = BTreeMap::new();
        for (monomial, coefficient) in value.terms() {
            let (runtime, parameter) = self.split(monomial);
            let entry = groups.entry(runtime).or_default();
            *entry = &*entry + &Expr::term(coefficient.clone(), parameter);
        }
        let mut terms: Vec<Term> = groups
            .iter()
            .filter(|(_, c)| !c.is_zero())
            .map(|(runtime, coefficient)| self.term(runtime, coefficient))
            .collect();
        if terms.is_empty() {
            let zero = self.hoist(Expr::zero());
            terms.push(Term {
                negative: false,
                coefficient: Some(zero),
                factor: None,
            });
        }
        self.count_sum(&terms);
        self.program.steps.push(Step::Sum { name, terms });
    }

    fn split(&self, monomial: &Monomial) -> (Monomial, Monomial) {
        let (mut runtime, mut parameter) = (Monomial::one(), Monomial::one());
        for (atom, power) in monomial.factors() {
            let part = if self.is_runtime(atom) {
                &mut runtime
            } else {
                &mut parameter
            };
            part.multiply_atom(atom.clone(), power);
        }
        (runtime, parameter)
    }

    fn term(&mut self, runtime: &Monomial, coefficient: &Expr) -> Term {
        let negative = coefficient
            .terms()
            .next()
            .is_some_and(|(_, c)| c.is_negative());
        let magnitude = if negative {
            -coefficient
        } else {
            coefficient.clone()
        };
        let factor = (!runtime.is_one()).then(|| self.product(runtime));
        let unit = magnitude
            .as_constant()
            .is_some_and(|c: Rational| c.is_one());
        let coefficient = (!unit || factor.is_none()).then(|| self.hoist(magnitude));
        if coefficient.is_some() && factor.is_some() {
            self.program.operations.mul += 1;
        }
        Term {
            negative,
            coefficient,
            factor,
        }
    }

    fn hoist(&mut self, value: Expr) -> usize {
        if let Some(&index) = self.coefficient_index.get(&value) {
            return index;
        }
        let index = self.program.coefficients.len();
        let name = format!("k{index}");
        self.program.coefficients.push(Coefficient {
            name,
            value: value.clone(),
        });
        self.coefficient_index.insert(value, index);
        index
    }

    fn leaves(&mut self, monomial: &Monomial) -> Vec<String> {
        let mut leaves = Vec::new();
        for (atom, power) in monomial.factors() {
            let leaf = match atom {
                Atom::Symbol(s) if power > 0 => identifier(s),
                Atom::Symbol(s) => {
                    self.reciprocal(&format!("inv_{}", identifier(s)), &identifier(s))
                }
                Atom::Sin(a) => format!("s_{}", self.sin_cos(a)),
                Atom::Cos(a) if power > 0 => format!("c_{}", self.sin_cos(a)),
                Atom::Cos(a) => {
                    let angle = self.sin_cos(a);
                    self.reciprocal(&format!("sec_{angle}"), &format!("c_{angle}"))
                }
            };
            leaves.extend(std::iter::repeat_n(leaf, power.unsigned_abs() as usize));
        }
        leaves
    }

    fn sin_cos(&mut self, angle: &str) -> String {
        let var = identifier(angle);
        if !self.angles_with_sin_cos.contains(&var) {
            self.angles_with_sin_cos.push(var.clone());
            self.program.operations.trig += 1;
            self.program.steps.push(Step::SinCos { angle: var.clone() });
        }
        var
    }

    /// `1/of`, computed once.
    fn reciprocal(&mut self, name: &str, of: &str) -> String {
        if !self.reciprocals.iter().any(|r| r == name) {
            self.reciprocals.push(name.to_owned());
            self.program.operations.div += 1;
            self.program.steps.push(Step::Reciprocal {
                name: name.to_owned(),
                of: of.to_owned(),
            });
        }
        name.to_owned()
    }

    /// The product of a monomial's leaves, sharing every prefix already computed.
    fn product(&mut self, monomial: &Monomial) -> String {
        let leaves = self.leaves(monomial);
        let mut current = leaves[0].clone();
        for end in 2..=leaves.len() {
            let prefix = leaves[..end].to_vec();
            if let Some(existing) = self.products.get(&prefix) {
                current = existing.clone();
                continue;
            }
            let name = prefix.join("_");
            self.program.operations.mul += 1;
            self.program.steps.push(Step::Product {
                name: name.clone(),
                left: current,
                right: leaves[end - 1].clone(),
            });
            self.products.insert(prefix, name.clone());
            current = name;
        }
        current
    }

    fn count_sum(&mut self, terms: &[Term]) {
        let n = terms.len() as u32;
        self.program.operations.add += n.saturating_sub(1);
        if terms.first().is_some_and(|t| t.negative) {
            self.program.operations.add += 1;
        }
    }
}
