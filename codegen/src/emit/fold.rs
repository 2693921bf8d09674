//! The proof carried to the emitted code: a program, folded back into the canonical form, must
//! equal the system it was built from, exactly.
//!
//! Every node is folded once, in id order (operands first), into an [`Expr`]: a variable is its
//! symbol, a hoisted coefficient its parameter expression, sin and cos their atoms, a
//! reciprocal of a monomial its inverse (sec θ = cos⁻¹θ). The one reciprocal that is not a
//! monomial, 1/|q|² of the quaternion track, is folded as the reciprocal of the stage's symbol:
//! the stage itself is checked like every other value, and the outputs are compared with the
//! system's outputs with every other stage substituted back. Each stage and each output must
//! then equal the system's, term by term; the kinetic and potential energies likewise.
//!
//! The Jacobians, where the program has them, are compared in the same way with the exact
//! derivative of the system ([`Jacobian::of`]), entry by entry and with the same pattern.
//!
//! Because the comparison is exact, any change to one operation — a swapped operand, a flipped
//! sign, a dropped term, a wrong coefficient — leaves a residual and stops the build with the
//! model's name and the output that differs (`tests/program_check.rs` tries every such mutant).

use std::collections::HashMap;
use std::ops::Index;

use super::program::{Function, Id, Node, Program};
use crate::model::jacobian::expand;
use crate::model::{BuildError, Jacobian, System};
use crate::symbolic::{Expr, SymbolicError};

/// Checks that `program` computes exactly the stages, outputs and energies of `system`.
pub fn verify(system: &System, program: &Program) -> Result<(), BuildError> {
    let fail = |what: String, residual: &Expr| BuildError::Verification {
        model: system.name.clone(),
        what,
        residual: residual.to_string(),
    };
    let symbolic = |source: SymbolicError| BuildError::Symbolic {
        model: system.name.clone(),
        source,
    };
    let opaque = opaque_stages(system, program);
    let folded = fold(system, program, &opaque).map_err(symbolic)?;
    for ((name, definition), named) in system.stages.iter().zip(&program.rhs.stages) {
        let wanted = expand(system, definition, &opaque).map_err(symbolic)?;
        let residual = &folded[named.id.index()] - &wanted;
        if !residual.is_zero() {
            return Err(fail(format!("the emitted stage {name} differs"), &residual));
        }
    }
    check_count(
        system,
        &program.rhs,
        system.stages.len(),
        system.outputs.len(),
    )?;
    for ((state, output), named) in system
        .state
        .iter()
        .zip(&system.outputs)
        .zip(&program.rhs.outputs)
    {
        let wanted = expand(system, output, &opaque).map_err(symbolic)?;
        let residual = &folded[named.id.index()] - &wanted;
        if !residual.is_zero() {
            return Err(fail(
                format!("the emitted rate of {state} differs from the proved form"),
                &residual,
            ));
        }
    }
    let energies = [
        (
            "kinetic energy",
            "4.32",
            &system.kinetic_energy,
            &program.kinetic_energy,
        ),
        (
            "potential energy",
            "the proved form",
            &system.potential_energy,
            &program.potential_energy,
        ),
    ];
    for (what, source, wanted, function) in energies {
        match (wanted, function) {
            (None, None) => {}
            (Some(wanted), Some(function)) => {
                let residual = &folded[function.outputs[0].id.index()] - wanted;
                if !residual.is_zero() {
                    return Err(fail(
                        format!("the emitted {what} differs from {source}"),
                        &residual,
                    ));
                }
            }
            _ => {
                return Err(fail(
                    format!("the program and the system disagree on having a {what}"),
                    &Expr::zero(),
                ));
            }
        }
    }
    if program.jacobians.is_some() {
        check_jacobian(system, program, &Jacobian::of(system)?, &folded)?;
    }
    Ok(())
}

/// Checks that the Jacobians of `program` compute exactly the entries of `jacobian`, the
/// derivative of `system`, with the same pattern.
pub fn verify_jacobian(
    system: &System,
    program: &Program,
    jacobian: &Jacobian,
) -> Result<(), BuildError> {
    let opaque = opaque_stages(system, program);
    let folded = fold(system, program, &opaque).map_err(|source| BuildError::Symbolic {
        model: system.name.clone(),
        source,
    })?;
    check_jacobian(system, program, jacobian, &folded)
}

fn check_jacobian(
    system: &System,
    program: &Program,
    jacobian: &Jacobian,
    folded: &impl Index<usize, Output = Expr>,
) -> Result<(), BuildError> {
    let fail = |what: String, residual: &Expr| BuildError::Verification {
        model: system.name.clone(),
        what,
        residual: residual.to_string(),
    };
    let Some(jacobians) = &program.jacobians else {
        return Err(fail("the program has no Jacobians".into(), &Expr::zero()));
    };
    check_opaque_stages(system, program, jacobians, folded)?;
    let parts = [
        (
            "∂f/∂x",
            &jacobian.state,
            &jacobians.state,
            &jacobians.state_pattern,
            &system.state,
        ),
        (
            "∂f/∂u",
            &jacobian.input,
            &jacobians.input,
            &jacobians.input_pattern,
            &system.inputs,
        ),
    ];
    for (what, entries, function, pattern, variables) in parts {
        let wanted: Vec<(usize, usize)> = entries.iter().map(|e| (e.row, e.column)).collect();
        if *pattern != wanted || function.outputs.len() != entries.len() {
            return Err(fail(
                format!("the emitted {what} has another pattern than the derivative"),
                &Expr::zero(),
            ));
        }
        for (entry, named) in entries.iter().zip(&function.outputs) {
            let residual = &folded[named.id.index()] - &entry.value;
            if !residual.is_zero() {
                let (state, variable) = (system.state[entry.row], variables[entry.column]);
                return Err(fail(
                    format!(
                        "the emitted {what} entry ∂(d{state}/dt)/∂{variable} differs from the \
                         derivative of the proved form"
                    ),
                    &residual,
                ));
            }
        }
    }
    Ok(())
}

/// The stages the Jacobians read as symbols, each equal to its definition: so that the check
/// of the Jacobians stands on its own, without the check of `rhs`.
fn check_opaque_stages(
    system: &System,
    program: &Program,
    jacobians: &super::program::Jacobians,
    folded: &impl Index<usize, Output = Expr>,
) -> Result<(), BuildError> {
    let opaque = opaque_stages(system, program);
    for named in jacobians.state.stages.iter().chain(&jacobians.input.stages) {
        let definition = system
            .stages
            .iter()
            .find(|(name, _)| super::program::identifier(name) == named.name)
            .map(|(_, definition)| definition);
        let wanted = match definition {
            Some(definition) => {
                expand(system, definition, &opaque).map_err(|source| BuildError::Symbolic {
                    model: system.name.clone(),
                    source,
                })?
            }
            None => Expr::zero(),
        };
        let residual = &folded[named.id.index()] - &wanted;
        if definition.is_none() || !residual.is_zero() {
            return Err(BuildError::Verification {
                model: system.name.clone(),
                what: format!("the stage {} the Jacobians read differs", named.name),
                residual: residual.to_string(),
            });
        }
    }
    Ok(())
}

fn check_count(
    system: &System,
    function: &Function,
    stages: usize,
    outputs: usize,
) -> Result<(), BuildError> {
    if function.stages.len() == stages && function.outputs.len() == outputs {
        return Ok(());
    }
    Err(BuildError::Verification {
        model: system.name.clone(),
        what: format!(
            "the program has {} stages and {} outputs, the system {stages} and {outputs}",
            function.stages.len(),
            function.outputs.len()
        ),
        residual: String::new(),
    })
}

/// The stages whose reciprocal the program takes although they are not monomials: they stay
/// symbols in the folded form.
fn opaque_stages(system: &System, program: &Program) -> Vec<String> {
    let mut opaque = Vec::new();
    for node in &program.nodes {
        if let Node::Recip(of) = node
            && let Some((name, _)) = system
                .stages
                .iter()
                .zip(&program.rhs.stages)
                .find(|(_, named)| named.id == *of)
                .map(|((name, value), _)| (name, value))
            && !opaque.contains(name)
        {
            opaque.push(name.clone());
        }
    }
    opaque
}

/// Every node of the program as an expression, by id.
pub fn fold(
    system: &System,
    program: &Program,
    opaque: &[String],
) -> Result<Vec<Expr>, SymbolicError> {
    let mut folded: Vec<Expr> = Vec::with_capacity(program.nodes.len());
    for node in &program.nodes {
        let value = fold_node(system, program, node, &folded, opaque)?;
        folded.push(value);
    }
    Ok(folded)
}

/// One node as an expression, its operands' expressions taken from `folded`.
fn fold_node(
    system: &System,
    program: &Program,
    node: &Node,
    folded: &impl Index<usize, Output = Expr>,
    opaque: &[String],
) -> Result<Expr, SymbolicError> {
    Ok(match node {
        Node::Variable(symbol) => Expr::symbol(symbol),
        Node::Coefficient(index) => program.coefficients[*index].value.clone(),
        Node::Constant(c) => Expr::constant(c.clone()),
        Node::Sin(angle) => Expr::sin(&angle_name(program, *angle)),
        Node::Cos(angle) => Expr::cos(&angle_name(program, *angle)),
        Node::Recip(of) => reciprocal(system, program, folded, *of, opaque)?,
        Node::Neg(a) => -&folded[a.index()],
        Node::Add(a, b) => &folded[a.index()] + &folded[b.index()],
        Node::Sub(a, b) => &folded[a.index()] - &folded[b.index()],
        Node::Mul(a, b) => &folded[a.index()] * &folded[b.index()],
    })
}

/// The operands a node reads.
fn operands(node: &Node) -> Vec<Id> {
    match node {
        Node::Variable(_) | Node::Coefficient(_) | Node::Constant(_) => vec![],
        Node::Sin(a) | Node::Cos(a) | Node::Recip(a) | Node::Neg(a) => vec![*a],
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) => vec![*a, *b],
    }
}

/// A program's fold (every node as an expression, and the stages kept as symbols), kept to
/// check programs that differ from it in one node: a mutation test checks hundreds of them,
/// and folding each whole would fold again every node the change does not reach.
pub struct Folded {
    opaque: Vec<String>,
    nodes: Vec<Expr>,
}

impl Folded {
    /// The fold of `program`, built from `system`.
    pub fn of(system: &System, program: &Program) -> Result<Folded, BuildError> {
        let opaque = opaque_stages(system, program);
        let nodes = fold(system, program, &opaque).map_err(|source| BuildError::Symbolic {
            model: system.name.clone(),
            source,
        })?;
        Ok(Folded { opaque, nodes })
    }
}

/// A fold read through changes: the nodes refolded after a change, the others as they were.
struct Changed<'a> {
    base: &'a [Expr],
    changed: HashMap<usize, Expr>,
}

impl Index<usize> for Changed<'_> {
    type Output = Expr;

    fn index(&self, index: usize) -> &Expr {
        self.changed.get(&index).unwrap_or(&self.base[index])
    }
}

/// [`verify_jacobian`] of `program`, which differs from the program `base` was folded from
/// only in node `changed`: that node and every node that reads it, directly or through
/// others, are folded again, the rest taken from `base`. The same verdict as
/// [`verify_jacobian`] (a changed reciprocal that changes the stages kept as symbols falls
/// back to it).
pub fn verify_jacobian_changed(
    system: &System,
    program: &Program,
    jacobian: &Jacobian,
    base: &Folded,
    changed: usize,
) -> Result<(), BuildError> {
    if opaque_stages(system, program) != base.opaque {
        return verify_jacobian(system, program, jacobian);
    }
    let mut folded = Changed {
        base: &base.nodes,
        changed: HashMap::new(),
    };
    for (index, node) in program.nodes.iter().enumerate().skip(changed) {
        let reads_a_change = operands(node)
            .iter()
            .any(|id| folded.changed.contains_key(&id.index()));
        if index == changed || reads_a_change {
            let value =
                fold_node(system, program, node, &folded, &base.opaque).map_err(|source| {
                    BuildError::Symbolic {
                        model: system.name.clone(),
                        source,
                    }
                })?;
            folded.changed.insert(index, value);
        }
    }
    check_jacobian(system, program, jacobian, &folded)
}

fn angle_name(program: &Program, angle: super::program::Id) -> String {
    match program.node(angle) {
        Node::Variable(symbol) => symbol.clone(),
        other => format!("<not an angle: {other:?}>"),
    }
}

/// 1/x: the inverse of a monomial, or the reciprocal symbol of an opaque stage.
fn reciprocal(
    system: &System,
    program: &Program,
    folded: &impl Index<usize, Output = Expr>,
    of: super::program::Id,
    opaque: &[String],
) -> Result<Expr, SymbolicError> {
    let stage = system
        .stages
        .iter()
        .zip(&program.rhs.stages)
        .find(|(_, named)| named.id == of)
        .map(|((name, _), _)| name);
    match stage {
        Some(name) if opaque.contains(name) => Expr::symbol(name).pow(-1),
        _ => folded[of.index()].reciprocal(),
    }
}
