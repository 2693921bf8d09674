//! The straight-line program: what a generated function computes, as an arena of hash-consed
//! nodes.
//!
//! Every value is a [`Node`] stored once and addressed by its [`Id`]; a node's operands always
//! have smaller ids than the node itself (children before parents, the shape of egg's
//! `RecExpr`), so a program is evaluated, folded back or emitted in one pass over the ids.
//! Structural sharing is automatic: asking for a node that exists returns its id, so a product
//! or a term that two equations use is computed once whatever its name would be.
//!
//! The builder (`build.rs` beside this file) turns a system into a program: it hoists,
//! factors and shares.
//!
//! Nothing here is trusted: [`super::fold`] folds the finished program back into the canonical
//! form and proves it equal to the system before any code is written.

use crate::model::{Jacobian, System};
use crate::symbolic::{Expr, Rational};

/// The index of a node in its program's arena.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Id(pub u32);

impl Id {
    /// The position in the arena.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// One value of the program.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Node {
    /// A state or input entry, by its symbol.
    Variable(String),
    /// A hoisted parameter-only coefficient, by its index in [`Program::coefficients`].
    Coefficient(usize),
    /// An exact constant, written inline.
    Constant(Rational),
    /// The sine of an angle (a [`Node::Variable`]).
    Sin(Id),
    /// The cosine of an angle (a [`Node::Variable`]).
    Cos(Id),
    /// `1 / x`.
    Recip(Id),
    /// `−x`.
    Neg(Id),
    /// `a + b`.
    Add(Id, Id),
    /// `a − b`.
    Sub(Id, Id),
    /// `a · b`.
    Mul(Id, Id),
}

impl Node {
    /// The operands, in order.
    pub fn children(&self) -> Vec<Id> {
        match *self {
            Node::Variable(_) | Node::Coefficient(_) | Node::Constant(_) => vec![],
            Node::Sin(a) | Node::Cos(a) | Node::Recip(a) | Node::Neg(a) => vec![a],
            Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) => vec![a, b],
        }
    }
}

/// What a call costs: the one type the emitter, the generated files and `eom` share.
pub use eom_kernel::Operations;

/// A hoisted coefficient: a parameter expression computed once per parameter set.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Coefficient {
    /// The field name, after what the coefficient multiplies where it is first used
    /// (`p_dot_q_r`: the coefficient of q·r in ṗ), or after the parameter it inverts
    /// (`inv_mass`).
    pub name: String,
    /// Where it is first used, for the doc comment: `q·r in ṗ`.
    pub role: String,
    /// The value in parameters.
    pub value: Expr,
}

/// A value with a name of its own in the generated code: a stage of the system, or a state's
/// time derivative.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Named {
    /// The Rust identifier.
    pub name: String,
    /// The node.
    pub id: Id,
}

/// One generated function: its named stages and its outputs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Function {
    /// The staged intermediates, in the system's order.
    pub stages: Vec<Named>,
    /// One node per output.
    pub outputs: Vec<Named>,
}

/// The arena and the functions computed from it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Program {
    /// The nodes; every operand precedes its user.
    pub nodes: Vec<Node>,
    /// Hoisted coefficients in order of first use.
    pub coefficients: Vec<Coefficient>,
    /// The right-hand side.
    pub rhs: Function,
    /// The kinetic energy, where the system has one.
    pub kinetic_energy: Option<Function>,
    /// The potential energy, where the system has one.
    pub potential_energy: Option<Function>,
    /// ∂f/∂x and ∂f/∂u, where the program was built with them.
    pub jacobians: Option<Jacobians>,
}

/// The Jacobians of the right-hand side as two functions, one output per entry that does not
/// vanish identically, and where each entry sits in the matrix.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Jacobians {
    /// ∂f/∂x, its entries row-major.
    pub state: Function,
    /// ∂f/∂u, its entries row-major.
    pub input: Function,
    /// (row, column) of each output of [`Jacobians::state`].
    pub state_pattern: Vec<(usize, usize)>,
    /// (row, column) of each output of [`Jacobians::input`].
    pub input_pattern: Vec<(usize, usize)>,
}

/// The Rust identifier of a symbol in generated code.
pub fn identifier(symbol: &str) -> String {
    match symbol {
        "M" => "mass".into(),
        _ => symbol.to_lowercase(),
    }
}

/// The name of a state's time derivative in generated code.
pub fn rate_name(state: &str) -> String {
    format!("{}_rate", identifier(state))
}

impl Program {
    /// Builds the program of a system: its right-hand side and, where it has them, its
    /// kinetic and potential energies (the builder is in `build.rs` beside this file).
    pub fn build(system: &System) -> Program {
        super::build::program(system, None)
    }

    /// Builds the program of a system with its Jacobians as two more functions, sharing the
    /// arena and the hoisted coefficients of the right-hand side.
    pub fn build_with_jacobian(system: &System, jacobian: &Jacobian) -> Program {
        super::build::program(system, Some(jacobian))
    }

    /// The node with this id.
    pub fn node(&self, id: Id) -> &Node {
        &self.nodes[id.index()]
    }

    /// How many times each node is an operand within the part of the arena that `function`
    /// reaches (named values count once more, as the generated code reads them by name).
    pub fn uses(&self, function: &Function) -> Vec<u32> {
        let reached = self.reached(function);
        let mut uses = vec![0; self.nodes.len()];
        for (index, node) in self.nodes.iter().enumerate() {
            if reached[index] {
                for child in node.children() {
                    uses[child.index()] += 1;
                }
            }
        }
        for named in function.stages.iter().chain(&function.outputs) {
            uses[named.id.index()] += 1;
        }
        uses
    }

    /// Which nodes `function` needs.
    pub fn reached(&self, function: &Function) -> Vec<bool> {
        let mut reached = vec![false; self.nodes.len()];
        for named in &function.outputs {
            reached[named.id.index()] = true;
        }
        for index in (0..self.nodes.len()).rev() {
            if reached[index] {
                for child in self.nodes[index].children() {
                    reached[child.index()] = true;
                }
            }
        }
        reached
    }

    /// What one call of `function` costs.
    pub fn operations(&self, function: &Function) -> Operations {
        let reached = self.reached(function);
        let mut operations = Operations::default();
        for (node, _) in self.nodes.iter().zip(&reached).filter(|(_, r)| **r) {
            match node {
                Node::Add(..) | Node::Sub(..) | Node::Neg(_) => operations.add += 1,
                Node::Mul(..) => operations.mul += 1,
                Node::Recip(_) => operations.div += 1,
                Node::Sin(_) | Node::Cos(_) => {}
                Node::Variable(_) | Node::Coefficient(_) | Node::Constant(_) => {}
            }
        }
        operations.trig = self.angles(function).len() as u32;
        operations
    }

    /// The angles whose sine or cosine `function` reads, in order of their ids.
    pub fn angles(&self, function: &Function) -> Vec<Id> {
        let reached = self.reached(function);
        let mut angles: Vec<Id> = Vec::new();
        for (node, _) in self.nodes.iter().zip(&reached).filter(|(_, r)| **r) {
            if let Node::Sin(a) | Node::Cos(a) = node
                && !angles.contains(a)
            {
                angles.push(*a);
            }
        }
        angles.sort();
        angles
    }
}

/// `name`, or `name_2`, `name_3`, … if it is taken.
pub(super) fn unique<'a>(name: &str, taken: impl Iterator<Item = &'a str> + Clone) -> String {
    let free = |candidate: &str| taken.clone().all(|t| t != candidate);
    if free(name) {
        return name.to_owned();
    }
    (2..)
        .map(|n| format!("{name}_{n}"))
        .find(|candidate| free(candidate))
        .expect("some suffix is free")
}
