//! Building a program from a system: hoist, factor, share, add up.
//!
//! Each stage and output of a [`System`] is a sum of `coefficient × runtime monomial`. In
//! four moves it becomes nodes of the arena ([`super::program`]):
//! 1. parameter-only coefficients are hoisted into a struct computed once per parameter set
//!    (exact constants such as ½ stay inline), named for what they are;
//! 2. terms of one sum that share a coefficient (up to sign) are factored, `k·a − k·b = k·(a − b)`;
//! 3. products are shared over the whole function, not along one monomial order: the pair of
//!    factors that occurs in the most monomials becomes a node of its own, again and again
//!    (so `q·r` and `p·q·r` share `q·r` whichever order the monomials list their atoms in);
//! 4. each sum starts with a positive term where it has one, so a negation is paid only by a
//!    sum whose terms are all negative.

use super::program::{
    Coefficient, Function, Id, Jacobians, Named, Node, Program, identifier, rate_name, unique,
};
use crate::model::{Entry, Jacobian, System};
use crate::symbolic::{Atom, Expr, Monomial, Rational};
use num_traits::{One, Signed};
use std::collections::{BTreeMap, HashMap};

/// Builds the program of a system: its right-hand side and, where it has them, its kinetic
/// and potential energies, and the Jacobians when they are given.
pub(super) fn program(system: &System, jacobian: Option<&Jacobian>) -> Program {
    let mut builder = Builder::new(system);
    let rhs = builder.function(&system.stages, &rhs_outputs(system));
    let mut energy = |value: &Option<Expr>, function: &str, name: &str, display: &str| {
        value.as_ref().map(|value| {
            let target = Target {
                name: name.into(),
                display: display.into(),
            };
            builder.function(&[], &[(function.into(), target, value.clone())])
        })
    };
    let kinetic_energy = energy(
        &system.kinetic_energy,
        "kinetic_energy",
        "t",
        "the kinetic energy T",
    );
    let potential_energy = energy(
        &system.potential_energy,
        "potential_energy",
        "v",
        "the potential energy V",
    );
    let jacobians = jacobian.map(|jacobian| {
        // The opaque stages are the right-hand side's own nodes again (hash-consed), named
        // in the Jacobians as they are in `rhs`.
        let opaque: Vec<(String, Expr)> = system
            .stages
            .iter()
            .filter(|(name, _)| jacobian.opaque.contains(name))
            .cloned()
            .collect();
        let state = jacobian_outputs(system, &jacobian.state, &system.state);
        let input = jacobian_outputs(system, &jacobian.input, &system.inputs);
        Jacobians {
            state: builder.function(&opaque, &state),
            input: builder.function(&opaque, &input),
            state_pattern: pattern(&jacobian.state),
            input_pattern: pattern(&jacobian.input),
        }
    });
    Program {
        nodes: builder.nodes,
        coefficients: builder.coefficients,
        rhs,
        kinetic_energy,
        potential_energy,
        jacobians,
    }
}

/// Where each entry sits: (row, column).
fn pattern(entries: &[Entry]) -> Vec<(usize, usize)> {
    entries.iter().map(|e| (e.row, e.column)).collect()
}

/// A Jacobian's entries as (name, target, value): `d_theta_dot_d_theta`, the derivative of
/// θ̇'s rate by θ. Opaque stages in the values are read as the right-hand side's stages.
fn jacobian_outputs(
    system: &System,
    entries: &[Entry],
    variables: &[&str],
) -> Vec<(String, Target, Expr)> {
    entries
        .iter()
        .map(|entry| {
            let (state, variable) = (system.state[entry.row], variables[entry.column]);
            let name = format!("d_{}_d_{}", rate_name(state), identifier(variable));
            let target = Target {
                name: name.clone(),
                display: format!("∂(d{state}/dt)/∂{variable}"),
            };
            (name, target, entry.value.clone())
        })
        .collect()
}

/// What a sum computes, for naming the coefficients it hoists: `p_dot` and `dp/dt`.
struct Target {
    name: String,
    display: String,
}

/// The system's outputs as (name, target, value): `u_rate`, `u_dot`, …
fn rhs_outputs(system: &System) -> Vec<(String, Target, Expr)> {
    system
        .state
        .iter()
        .zip(&system.outputs)
        .map(|(state, value)| {
            let target = Target {
                name: format!("{}_dot", identifier(state)),
                display: format!("d{state}/dt"),
            };
            (rate_name(state), target, value.clone())
        })
        .collect()
}

/// One term of a sum on its way into the arena: ± coefficient × monomial of runtime leaves.
struct Term {
    negative: bool,
    coefficient: Option<Id>,
    leaves: Vec<Id>,
}

struct Builder<'a> {
    system: &'a System,
    nodes: Vec<Node>,
    index: HashMap<Node, Id>,
    coefficients: Vec<Coefficient>,
    coefficient_index: BTreeMap<Expr, usize>,
    stage_ids: BTreeMap<String, Id>,
}

impl<'a> Builder<'a> {
    fn new(system: &'a System) -> Self {
        Builder {
            system,
            nodes: Vec::new(),
            index: HashMap::new(),
            coefficients: Vec::new(),
            coefficient_index: BTreeMap::new(),
            stage_ids: BTreeMap::new(),
        }
    }

    /// The id of `node`, adding it if it is new. Products are stored with their operands in
    /// id order, so `a·b` and `b·a` are one node.
    fn add(&mut self, node: Node) -> Id {
        let node = match node {
            Node::Mul(a, b) if b < a => Node::Mul(b, a),
            other => other,
        };
        if let Some(&id) = self.index.get(&node) {
            return id;
        }
        let id = Id(self.nodes.len() as u32);
        self.nodes.push(node.clone());
        self.index.insert(node, id);
        id
    }

    /// Builds the stages and the outputs of one function. Products are shared across all of
    /// its sums, so they are collected first and multiplied out together.
    fn function(
        &mut self,
        stages: &[(String, Expr)],
        outputs: &[(String, Target, Expr)],
    ) -> Function {
        let mut function = Function {
            stages: vec![],
            outputs: vec![],
        };
        // Stages are built one after another: a later stage reads an earlier one as a leaf.
        for (name, value) in stages {
            let target = Target {
                name: identifier(name),
                display: format!("the stage {}", identifier(name)),
            };
            let sums = [self.terms(&target, value)];
            let id = self.sums(sums)[0];
            self.stage_ids.insert(name.clone(), id);
            function.stages.push(Named {
                name: identifier(name),
                id,
            });
        }
        let sums: Vec<Vec<Term>> = outputs
            .iter()
            .map(|(_, target, value)| self.terms(target, value))
            .collect();
        let ids = self.sums(sums);
        for ((name, _, _), id) in outputs.iter().zip(ids) {
            function.outputs.push(Named {
                name: name.clone(),
                id,
            });
        }
        function
    }

    /// The terms of one sum: grouped by runtime monomial, coefficients hoisted.
    fn terms(&mut self, target: &Target, value: &Expr) -> Vec<Term> {
        let mut groups: BTreeMap<Monomial, Expr> = BTreeMap::new();
        for (monomial, coefficient) in value.terms() {
            let (runtime, parameter) = self.split(monomial);
            let entry = groups.entry(runtime).or_default();
            *entry = &*entry + &Expr::term(coefficient.clone(), parameter);
        }
        groups
            .into_iter()
            .filter(|(_, coefficient)| !coefficient.is_zero())
            .map(|(runtime, coefficient)| self.term(target, &runtime, &coefficient))
            .collect()
    }

    fn is_runtime(&self, atom: &Atom) -> bool {
        match atom {
            Atom::Symbol(s) => !self.system.is_parameter(s),
            Atom::Sin(_) | Atom::Cos(_) => true,
        }
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

    fn term(&mut self, target: &Target, runtime: &Monomial, coefficient: &Expr) -> Term {
        let negative = coefficient
            .terms()
            .next()
            .is_some_and(|(_, c)| c.is_negative());
        let magnitude = if negative {
            -coefficient
        } else {
            coefficient.clone()
        };
        let leaves = self.leaves(runtime);
        let coefficient = match magnitude.as_constant() {
            Some(c) if c.is_one() && !leaves.is_empty() => None,
            Some(c) => Some(self.add(Node::Constant(c))),
            None => Some(self.hoist(magnitude, target, runtime)),
        };
        Term {
            negative,
            coefficient,
            leaves,
        }
    }

    fn hoist(&mut self, value: Expr, target: &Target, runtime: &Monomial) -> Id {
        if let Some(&index) = self.coefficient_index.get(&value) {
            return self.add(Node::Coefficient(index));
        }
        let index = self.coefficients.len();
        let (name, role) = self.describe(&value, target, runtime);
        let name = unique(&name, self.coefficients.iter().map(|c| c.name.as_str()));
        self.coefficients.push(Coefficient {
            name,
            role,
            value: value.clone(),
        });
        self.coefficient_index.insert(value, index);
        self.add(Node::Coefficient(index))
    }

    /// A coefficient's field name and what it is: a parameter's own name where it is one
    /// (`mass`, `inv_mass`, `half_ixx`), the chapter's name where the system gives one
    /// (`inv_inertia_xy`), else what it multiplies where it is first used (`p_dot_q_r`).
    fn describe(&self, value: &Expr, target: &Target, runtime: &Monomial) -> (String, String) {
        let role = if runtime.is_one() {
            format!("The constant term of {}", target.display)
        } else {
            format!("The coefficient of {runtime} in {}", target.display)
        };
        let reciprocal = self
            .system
            .reciprocals
            .iter()
            .find(|r| *value == Expr::symbol(&r.symbol));
        if let Some(reciprocal) = reciprocal {
            let role = format!("The reciprocal `1/({})`, computed once", reciprocal.of);
            return (identifier(&reciprocal.symbol), role);
        }
        if let Some(name) = parameter_name(value) {
            return (name, "A parameter, or its reciprocal or half".into());
        }
        let negated = -value;
        let named = self
            .system
            .coefficient_names
            .iter()
            .find(|n| n.value == *value || n.value == negated);
        if let Some(named) = named {
            return (named.name.clone(), named.description.clone());
        }
        let what = runtime_name(runtime);
        let name = if what.is_empty() {
            format!("{}_constant", target.name)
        } else {
            format!("{}_{what}", target.name)
        };
        (name, role)
    }

    /// The runtime leaves of a monomial, one per unit of power.
    fn leaves(&mut self, monomial: &Monomial) -> Vec<Id> {
        let mut leaves = Vec::new();
        for (atom, power) in monomial.factors() {
            let base = match atom {
                Atom::Symbol(s) => self.symbol(s),
                Atom::Sin(a) => {
                    let angle = self.symbol(a);
                    self.add(Node::Sin(angle))
                }
                Atom::Cos(a) => {
                    let angle = self.symbol(a);
                    self.add(Node::Cos(angle))
                }
            };
            let leaf = if power > 0 {
                base
            } else {
                self.add(Node::Recip(base))
            };
            leaves.extend(std::iter::repeat_n(leaf, power.unsigned_abs() as usize));
        }
        leaves.sort();
        leaves
    }

    /// A stage by its node, anything else as a variable.
    fn symbol(&mut self, symbol: &str) -> Id {
        match self.stage_ids.get(symbol) {
            Some(&id) => id,
            None => self.add(Node::Variable(symbol.to_owned())),
        }
    }

    /// Builds a batch of sums whose products are shared: factor coefficients, share pairs,
    /// multiply out, add up.
    fn sums(&mut self, sums: impl IntoIterator<Item = Vec<Term>>) -> Vec<Id> {
        let factored: Vec<Vec<Factored>> = sums.into_iter().map(factor).collect();
        let mut monomials: Vec<Vec<Id>> = factored
            .iter()
            .flatten()
            .flat_map(|f| f.parts.iter().map(|(_, leaves)| leaves.clone()))
            .filter(|leaves| leaves.len() >= 2)
            .collect();
        monomials.sort();
        monomials.dedup();
        let shared = self.share_pairs(monomials);
        factored
            .iter()
            .map(|sum| {
                let terms: Vec<(bool, Id)> =
                    sum.iter().map(|f| self.factored_term(f, &shared)).collect();
                self.signed_sum(&terms)
            })
            .collect()
    }

    /// Greedy pair sharing: while some pair of factors occurs in two or more of the distinct
    /// monomials, the most frequent pair (ties to the smallest ids, so the result depends on
    /// nothing but the input) becomes a product node and replaces the pair wherever it occurs.
    /// Returns each original monomial's final list of factors.
    fn share_pairs(&mut self, monomials: Vec<Vec<Id>>) -> BTreeMap<Vec<Id>, Vec<Id>> {
        let mut current = monomials.clone();
        loop {
            let mut counts: BTreeMap<(Id, Id), u32> = BTreeMap::new();
            for leaves in &current {
                let mut pairs: Vec<(Id, Id)> = Vec::new();
                for i in 0..leaves.len() {
                    for j in i + 1..leaves.len() {
                        pairs.push((leaves[i], leaves[j]));
                    }
                }
                pairs.sort();
                pairs.dedup();
                for pair in pairs {
                    *counts.entry(pair).or_default() += 1;
                }
            }
            let best = counts
                .iter()
                .filter(|(_, n)| **n >= 2)
                .max_by(|(p, n), (q, m)| n.cmp(m).then(q.cmp(p)));
            let Some((&(a, b), _)) = best else { break };
            let product = self.add(Node::Mul(a, b));
            for leaves in current.iter_mut() {
                if let Some(replaced) = replace_pair(leaves, a, b, product) {
                    *leaves = replaced;
                }
            }
        }
        monomials.into_iter().zip(current).collect()
    }

    /// The product of a monomial's leaves, after pair sharing.
    fn product(&mut self, leaves: &[Id], shared: &BTreeMap<Vec<Id>, Vec<Id>>) -> Option<Id> {
        let factors = shared.get(leaves).map_or(leaves, Vec::as_slice);
        let (&first, rest) = factors.split_first()?;
        Some(
            rest.iter()
                .fold(first, |acc, &leaf| self.add(Node::Mul(acc, leaf))),
        )
    }

    /// One factored term: coefficient × (± monomial ± monomial …), with its sign.
    fn factored_term(
        &mut self,
        term: &Factored,
        shared: &BTreeMap<Vec<Id>, Vec<Id>>,
    ) -> (bool, Id) {
        let parts: Vec<(bool, Option<Id>)> = term
            .parts
            .iter()
            .map(|(negative, leaves)| (*negative, self.product(leaves, shared)))
            .collect();
        let (negative, value) = self.unsigned_term(term.coefficient, &parts);
        (negative != term.negative, value)
    }

    /// coefficient × (± monomial ± …), as (sign, magnitude).
    fn unsigned_term(
        &mut self,
        coefficient: Option<Id>,
        parts: &[(bool, Option<Id>)],
    ) -> (bool, Id) {
        match (coefficient, parts) {
            (None, [(negative, Some(product))]) => (*negative, *product),
            (Some(k), [(negative, None)]) => (*negative, k),
            (Some(k), [(negative, Some(product))]) => (*negative, self.add(Node::Mul(k, *product))),
            (Some(k), _) => {
                let inner: Vec<(bool, Id)> = parts
                    .iter()
                    .map(|&(negative, product)| {
                        (negative, product.expect("factored terms have a monomial"))
                    })
                    .collect();
                let (negative, sum) = self.sum_keeping_sign(&inner);
                (negative, self.add(Node::Mul(k, sum)))
            }
            (None, _) => unreachable!("a term has a coefficient or a monomial"),
        }
    }

    /// Σ ±terms, starting with a positive term where there is one.
    fn signed_sum(&mut self, terms: &[(bool, Id)]) -> Id {
        if terms.is_empty() {
            return self.add(Node::Constant(num_traits::Zero::zero()));
        }
        let (negative, sum) = self.sum_keeping_sign(terms);
        if negative {
            self.add(Node::Neg(sum))
        } else {
            sum
        }
    }

    /// Σ ±terms as (sign, magnitude): with every term negative, −(a + b + …) is returned as
    /// `(true, a + b + …)` so a caller that multiplies can carry the sign on instead.
    fn sum_keeping_sign(&mut self, terms: &[(bool, Id)]) -> (bool, Id) {
        let start = terms.iter().position(|(negative, _)| !negative);
        let all_negative = start.is_none();
        let start = start.unwrap_or(0);
        let mut sum = terms[start].1;
        for (i, &(negative, term)) in terms.iter().enumerate() {
            if i == start {
                continue;
            }
            let subtract = negative != all_negative;
            sum = self.add(if subtract {
                Node::Sub(sum, term)
            } else {
                Node::Add(sum, term)
            });
        }
        (all_negative, sum)
    }
}

/// A term after factoring: ± coefficient × Σ ± monomials (one part when nothing was shared).
struct Factored {
    negative: bool,
    coefficient: Option<Id>,
    parts: Vec<(bool, Vec<Id>)>,
}

/// Terms of one sum that share a coefficient (up to sign) become one term, `k·(a − b)`; the
/// first term of each group keeps its place, and `k·(−a − b)` is written `−k·(a + b)`.
fn factor(terms: Vec<Term>) -> Vec<Factored> {
    let mut factored: Vec<Factored> = Vec::new();
    for term in terms {
        let group = match term.coefficient {
            Some(k) if !term.leaves.is_empty() => factored
                .iter_mut()
                .find(|f| f.coefficient == Some(k) && f.parts.iter().all(|(_, l)| !l.is_empty())),
            _ => None,
        };
        match group {
            Some(group) => group.parts.push((term.negative, term.leaves)),
            None => factored.push(Factored {
                negative: false,
                coefficient: term.coefficient,
                parts: vec![(term.negative, term.leaves)],
            }),
        }
    }
    for group in &mut factored {
        if group.parts.iter().all(|(negative, _)| *negative) {
            group.negative = true;
            for part in &mut group.parts {
                part.0 = false;
            }
        }
    }
    factored
}

/// `leaves` with one `a` and one `b` replaced by `product`, if it holds both.
fn replace_pair(leaves: &[Id], a: Id, b: Id, product: Id) -> Option<Vec<Id>> {
    let mut rest = leaves.to_vec();
    let i = rest.iter().position(|&x| x == a)?;
    rest.remove(i);
    let j = rest.iter().position(|&x| x == b)?;
    rest.remove(j);
    rest.push(product);
    rest.sort();
    Some(rest)
}

/// A monomial of runtime atoms as an identifier fragment: `q_r`, `sin_theta`, `sec_theta`.
fn runtime_name(monomial: &Monomial) -> String {
    let mut parts = Vec::new();
    for (atom, power) in monomial.factors() {
        let base = match atom {
            Atom::Symbol(s) => identifier(s),
            Atom::Sin(a) => format!("sin_{}", identifier(a)),
            Atom::Cos(a) if power < 0 => format!("sec_{}", identifier(a)),
            Atom::Cos(a) => format!("cos_{}", identifier(a)),
        };
        let base = match (atom, power < 0) {
            (Atom::Symbol(_), true) => format!("inv_{base}"),
            _ => base,
        };
        parts.extend(std::iter::repeat_n(base, power.unsigned_abs() as usize));
    }
    parts.join("_")
}

/// The name of a coefficient that is one parameter, its reciprocal or its half: `mass`,
/// `inv_mass`, `half_mass`.
fn parameter_name(value: &Expr) -> Option<String> {
    let mut terms = value.terms();
    let (Some((monomial, c)), None) = (terms.next(), terms.next()) else {
        return None;
    };
    let mut factors = monomial.factors();
    let (Some((Atom::Symbol(s), power)), None) = (factors.next(), factors.next()) else {
        return None;
    };
    let half = Rational::new(1.into(), 2.into());
    match (power, c) {
        (1, c) if c.is_one() => Some(identifier(s)),
        (-1, c) if c.is_one() => Some(format!("inv_{}", identifier(s))),
        (1, c) if *c == half => Some(format!("half_{}", identifier(s))),
        _ => None,
    }
}
