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
use crate::models::Model;
use eom_codegen::emit::program::{Node, Program};
use eom_codegen::emit::{Operations, prove};
use eom_codegen::model::System;
use eom_codegen::model::ship::{ADDED_MASS, PRIME_SCALES, ShipSpec, Units, YawInertia, ship};
use eom_codegen::symbolic::Expr;
use simba::simd::SimdRealField;
use std::collections::BTreeMap;

/// The state: u, v, r (m/s, m/s, rad/s, body axes at midship), X, Y (m, midship in space
/// axes), ψ (rad), δ (rad, the rudder angle).
pub const STATE: [&str; 7] = ["u", "v", "r", "X", "Y", "psi", "delta"];

/// The input: the rudder's rate δ̇ (rad/s), which the steering gear sets
/// ([`super::rudder`]).
pub const INPUTS: [&str; 1] = ["delta_rate"];

/// Where the rates can depend on the state, for any table: u̇, v̇, ṙ on u, v, r and δ (the
/// terms in U of a prime table are in u and v); Ẋ, Ẏ on u, v, ψ (4.44); ψ̇ on r; δ̇ on none.
/// A table without a term in some entry makes that entry's derivative zero at every state.
#[rustfmt::skip]
const STATE_JACOBIAN: [(usize, usize); 19] = [
    (0, 0), (0, 1), (0, 2), (0, 6),
    (1, 0), (1, 1), (1, 2), (1, 6),
    (2, 0), (2, 1), (2, 2), (2, 6),
    (3, 0), (3, 1), (3, 5),
    (4, 0), (4, 1), (4, 5),
    (5, 2),
];

/// δ̇ is the rudder's rate itself.
const INPUT_JACOBIAN: [(usize, usize); 1] = [(6, 0)];

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
    rigid_body: RigidBody,
}

/// The rigid body in SI about midship, for the kinetic energy.
#[derive(Debug, Clone, Copy, PartialEq)]
struct RigidBody {
    /// M, kg.
    mass: f64,
    /// I_z about midship, kg m².
    yaw_inertia_midship: f64,
    /// G ahead of midship, m.
    x_g: f64,
}

impl RigidBody {
    /// The table's body in SI: a prime table's m′, I′_z and x′_G scaled by ½ρL³, ½ρL⁵ and L;
    /// I_z taken to midship by the parallel-axis theorem (4.23) where it is given about G.
    fn of(table: &ShipTable) -> Self {
        let body = &table.body;
        let (mass_scale, inertia_scale, length) = match table.units {
            Units::Dimensional => (1.0, 1.0, 1.0),
            Units::Prime => {
                let length = table.length.unwrap_or(f64::NAN);
                let half_rho = 0.5 * table.density.unwrap_or(f64::NAN);
                (half_rho * length.powi(3), half_rho * length.powi(5), length)
            }
        };
        let mass = body.mass * mass_scale;
        let x_g = body.x_g * length;
        let given = body.yaw_inertia * inertia_scale;
        let yaw_inertia_midship = match body.yaw_inertia_about {
            YawInertia::AboutMidship => given,
            YawInertia::AboutG => given + mass * x_g * x_g,
        };
        RigidBody {
            mass,
            yaw_inertia_midship,
            x_g,
        }
    }
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
            rigid_body: RigidBody::of(table),
        })
    }

    /// Every node of the program at `state` with the rudder moving at `delta_rate`.
    fn values<T: SimdRealField + Copy>(&self, state: &[T; 7], delta_rate: T) -> Vec<T> {
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
        values
    }

    /// The derivatives of the rates by the seven state entries and the input (column 7), by
    /// the chain rule through the program node by node (forward mode): exact, as the program
    /// is, and generic over the scalar as `rhs` is.
    fn jacobian<T: SimdRealField + Copy>(&self, state: &[T; 7], delta_rate: T) -> [[T; 8]; 7] {
        let values = self.values(state, delta_rate);
        let zero = [T::zero(); 8];
        let unit = |j: usize| {
            let mut d = zero;
            d[j] = T::one();
            d
        };
        let scaled = |d: &[T; 8], by: T| d.map(|x| x * by);
        let mut tangents: Vec<[T; 8]> = Vec::with_capacity(self.ops.len());
        for op in &self.ops {
            let d = match *op {
                Op::State(i) => unit(i),
                Op::DeltaRate => unit(7),
                Op::Speed => {
                    // U = √(u² + v²): ∂U/∂u = u/U, ∂U/∂v = v/U.
                    let speed = (state[0] * state[0] + state[1] * state[1]).simd_sqrt();
                    let mut d = zero;
                    d[0] = state[0] / speed;
                    d[1] = state[1] / speed;
                    d
                }
                Op::Value(_) => zero,
                Op::Sin(a) => scaled(&tangents[a], eom_kernel::sin_cos([values[a]])[0].1),
                Op::Cos(a) => scaled(&tangents[a], -eom_kernel::sin_cos([values[a]])[0].0),
                Op::Recip(a) => {
                    let inverse = T::one() / values[a];
                    scaled(&tangents[a], -(inverse * inverse))
                }
                Op::Neg(a) => tangents[a].map(|x| -x),
                Op::Add(a, b) => std::array::from_fn(|j| tangents[a][j] + tangents[b][j]),
                Op::Sub(a, b) => std::array::from_fn(|j| tangents[a][j] - tangents[b][j]),
                Op::Mul(a, b) => {
                    std::array::from_fn(|j| values[a] * tangents[b][j] + values[b] * tangents[a][j])
                }
            };
            tangents.push(d);
        }
        self.outputs.map(|i| tangents[i])
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

/// The ship as a model like the catalog's: its state and input, the proved program as `rhs`,
/// its exact Jacobians, and the rigid body's kinetic energy.
impl<T: SimdRealField + Copy> Model<T, 7, 1> for ShipModel {
    const NAME: &'static str = "ship";
    const STATE: [&'static str; 7] = STATE;
    const INPUTS: [&'static str; 1] = INPUTS;
    const STATE_JACOBIAN: &'static [(usize, usize)] = &STATE_JACOBIAN;
    const INPUT_JACOBIAN: &'static [(usize, usize)] = &INPUT_JACOBIAN;

    /// The rates of the state with the rudder moving at `input[0]`: the proved program,
    /// evaluated node by node.
    fn rhs(&self, state: &[T; 7], input: &[T; 1]) -> [T; 7] {
        let values = self.values(state, input[0]);
        self.outputs.map(|i| values[i])
    }

    /// The rigid body's kinetic energy ½νᵀM_RBν about midship, ν = (u, v, r) (4.46's mass
    /// matrix without the added mass): ½M(u² + v²) + M x_G v r + ½I_z r², with I_z about
    /// midship; in J. The fluid's share (the added mass) is not in it.
    fn kinetic_energy(&self, state: &[T; 7]) -> T {
        let body = &self.rigid_body;
        let [mass, inertia, x_g] =
            [body.mass, body.yaw_inertia_midship, body.x_g].map(|x| T::from_subset(&x));
        let (u, v, r) = (state[0], state[1], state[2]);
        let half = T::from_subset(&0.5);
        half * mass * (u * u + v * v) + mass * x_g * v * r + half * inertia * r * r
    }

    fn state_jacobian(&self, state: &[T; 7], input: &[T; 1]) -> [[T; 7]; 7] {
        self.jacobian(state, input[0])
            .map(|row| std::array::from_fn(|j| row[j]))
    }

    fn input_jacobian(&self, state: &[T; 7], input: &[T; 1]) -> [[T; 1]; 7] {
        self.jacobian(state, input[0]).map(|row| [row[7]])
    }
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
