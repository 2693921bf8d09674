//! The ship model: 4.46 with a table's terms, built and proved by `eom-codegen` when the
//! scene is read, and evaluated here.
//!
//! What runs is the proved straight-line program itself ([`eom_codegen::emit::Program`]):
//! the same arena of shared nodes the emitter writes as Rust for a catalog model, each node
//! evaluated once per call in order, its hoisted coefficients computed once per table. It is
//! generic over simba's `SimdRealField`, so it runs on f64 and on dual numbers (the linear
//! model is its exact derivative, [`super::linear`]).

use super::ShipError;
use super::table::ShipTable;
use eom_codegen::emit::program::{Node, Program};
use eom_codegen::emit::{Operations, prove};
use eom_codegen::model::System;
use eom_codegen::model::ship::{ADDED_MASS, PRIME_SCALES, ShipSpec, Units, ship};
use eom_codegen::symbolic::Expr;
use simba::simd::SimdRealField;
use std::collections::BTreeMap;

/// The state: u, v, r (m/s, m/s, rad/s, body axes at midship), X, Y (m, midship in space
/// axes), ψ (rad), δ (rad, the rudder angle).
pub const STATE: [&str; 7] = ["u", "v", "r", "X", "Y", "psi", "delta"];

/// One node of the program, with its operands resolved to positions.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Op {
    State(usize),
    DeltaRate,
    Speed,
    Value(f64),
    Sin(usize),
    Cos(usize),
    Recip(usize),
    Neg(usize),
    Add(usize, usize),
    Sub(usize, usize),
    Mul(usize, usize),
}

/// A ship's proved right-hand side, ready to evaluate.
#[derive(Debug, Clone)]
pub struct ShipModel {
    ops: Vec<Op>,
    outputs: [usize; 7],
    operations: Operations,
    terms: usize,
}

impl ShipModel {
    /// Derives, solves and proves 4.46 with the table's terms, then resolves the program.
    pub fn new(table: &ShipTable) -> Result<Self, ShipError> {
        let spec = ShipSpec {
            units: table.units,
            yaw_inertia: table.body.yaw_inertia_about,
            terms: table.terms.keys().copied().collect(),
        };
        let system = ship("ship", &spec)
            .map_err(|e| ShipError::Build(eom_codegen::emit::EmitError::Model(e)))?;
        let program = prove(&system)?;
        let values = parameter_values(&spec, table);
        let coefficients = coefficient_values(&system, &program, &values);
        let mut ops = Vec::with_capacity(program.nodes.len());
        for node in &program.nodes {
            ops.push(resolve(node, &coefficients)?);
        }
        let outputs = std::array::from_fn(|i| program.rhs.outputs[i].id.index());
        Ok(ShipModel {
            ops,
            outputs,
            operations: program.operations(&program.rhs),
            terms: spec.terms.len(),
        })
    }

    /// The time derivative of the state with the rudder moving at `delta_rate`.
    pub fn rhs<T: SimdRealField + Copy>(&self, state: &[T; 7], delta_rate: T) -> [T; 7] {
        let speed = (state[0] * state[0] + state[1] * state[1]).simd_sqrt();
        let mut values: Vec<T> = Vec::with_capacity(self.ops.len());
        for op in &self.ops {
            let value = match *op {
                Op::State(i) => state[i],
                Op::DeltaRate => delta_rate,
                Op::Speed => speed,
                Op::Value(x) => T::from_subset(&x),
                Op::Sin(a) => eom_kernel::sin_cos([values[a]])[0].0,
                Op::Cos(a) => eom_kernel::sin_cos([values[a]])[0].1,
                Op::Recip(a) => T::one() / values[a],
                Op::Neg(a) => -values[a],
                Op::Add(a, b) => values[a] + values[b],
                Op::Sub(a, b) => values[a] - values[b],
                Op::Mul(a, b) => values[a] * values[b],
            };
            values.push(value);
        }
        self.outputs.map(|i| values[i])
    }

    /// What one call costs, as the emitter counts it.
    pub fn operations(&self) -> Operations {
        self.operations
    }

    /// How many terms of the polynomial the model carries.
    pub fn terms(&self) -> usize {
        self.terms
    }
}

/// Every parameter's value by its symbol, as the table gives it; the symbols are the spec's.
fn parameter_values(spec: &ShipSpec, table: &ShipTable) -> BTreeMap<String, f64> {
    let body = [table.body.mass, table.body.yaw_inertia, table.body.x_g];
    let mut values: BTreeMap<String, f64> = spec
        .body_symbols()
        .into_iter()
        .zip(body)
        .chain(ADDED_MASS.into_iter().zip(table.added_mass))
        .map(|(symbol, value)| (symbol.to_owned(), value))
        .collect();
    if table.units == Units::Prime {
        let scales = [
            table.density.unwrap_or(f64::NAN),
            table.length.unwrap_or(f64::NAN),
            table.design_speed,
        ];
        for (symbol, value) in PRIME_SCALES.into_iter().zip(scales) {
            values.insert(symbol.to_owned(), value);
        }
    }
    for (term, value) in &table.terms {
        values.insert(term.symbol(), *value);
    }
    values
}

/// The hoisted coefficients, each computed once from the parameters (and the reciprocals of
/// parameter polynomials, computed first).
fn coefficient_values(
    system: &System,
    program: &Program,
    parameters: &BTreeMap<String, f64>,
) -> Vec<f64> {
    let mut known = parameters.clone();
    for reciprocal in &system.reciprocals {
        let of = reciprocal
            .of
            .eval(&|s| known.get(s).copied().unwrap_or(f64::NAN));
        known.insert(reciprocal.symbol.clone(), 1.0 / of);
    }
    let lookup = |s: &str| known.get(s).copied().unwrap_or(f64::NAN);
    program
        .coefficients
        .iter()
        .map(|c| c.value.eval(&lookup))
        .collect()
}

fn resolve(node: &Node, coefficients: &[f64]) -> Result<Op, ShipError> {
    Ok(match node {
        Node::Variable(name) => match name.as_str() {
            "delta_rate" => Op::DeltaRate,
            "U" => Op::Speed,
            _ => Op::State(STATE.iter().position(|s| s == name).ok_or_else(|| {
                ShipError::invalid("hydrodynamics", format!("the program reads `{name}`"))
            })?),
        },
        Node::Coefficient(i) => Op::Value(coefficients[*i]),
        Node::Constant(c) => Op::Value(Expr::constant(c.clone()).eval(&|_| f64::NAN)),
        Node::Sin(a) => Op::Sin(a.index()),
        Node::Cos(a) => Op::Cos(a.index()),
        Node::Recip(a) => Op::Recip(a.index()),
        Node::Neg(a) => Op::Neg(a.index()),
        Node::Add(a, b) => Op::Add(a.index(), b.index()),
        Node::Sub(a, b) => Op::Sub(a.index(), b.index()),
        Node::Mul(a, b) => Op::Mul(a.index(), b.index()),
    })
}
