//! Single-operation mutants of a program, shared by the tests that show the fold-back check
//! cannot be fooled: the catalog's programs (`program_check.rs`) and the scene-defined ones,
//! a ship's table (`ship.rs`) and a vehicle's (`vehicle.rs`).
//!
//! Mutations, applied to one node at a time: a sum becomes a difference and a difference a
//! sum (a flipped sign); the operands of a difference are swapped; a sum, a difference, a
//! negation or a reciprocal is replaced by its first operand (a dropped term or operation);
//! one operand of a product is replaced by another variable; a coefficient by another
//! coefficient; a constant by its double; a sine by the cosine of the same angle and back.

#![allow(dead_code)]

use eom_codegen::emit::Program;
use eom_codegen::emit::fold::{Folded, verify_jacobian, verify_jacobian_changed};
use eom_codegen::emit::program::{Id, Node};
use eom_codegen::model::{Jacobian, System};
use num_rational::BigRational;

/// Every mutant of node `index`.
pub fn mutants(program: &Program, index: usize) -> Vec<Node> {
    let node = &program.nodes[index];
    let variables: Vec<Id> = (0..index)
        .filter(|&i| matches!(program.nodes[i], Node::Variable(_)))
        .map(|i| Id(i as u32))
        .collect();
    let other_variable = |not: Id| variables.iter().copied().find(|&v| v != not);
    let copy_of = |id: Id| program.nodes[id.index()].clone();
    match node {
        Node::Add(a, b) => vec![Node::Sub(*a, *b), copy_of(*a)],
        Node::Sub(a, b) => {
            let mut m = vec![Node::Add(*a, *b), copy_of(*a)];
            if a != b {
                m.push(Node::Sub(*b, *a));
            }
            m
        }
        Node::Mul(a, b) => other_variable(*b)
            .map(|c| Node::Mul(*a, c))
            .into_iter()
            .collect(),
        Node::Neg(a) | Node::Recip(a) => vec![copy_of(*a)],
        Node::Sin(a) => vec![Node::Cos(*a)],
        Node::Cos(a) => vec![Node::Sin(*a)],
        Node::Coefficient(k) if program.coefficients.len() > 1 => {
            vec![Node::Coefficient((k + 1) % program.coefficients.len())]
        }
        Node::Constant(c) => vec![Node::Constant(c * BigRational::from_integer(2.into()))],
        Node::Coefficient(_) | Node::Variable(_) => vec![],
    }
}

/// What [`jacobian_mutants`] found: every mutant tried was caught (it panics otherwise).
pub struct Caught {
    /// The mutants tried, each caught.
    pub tried: usize,
    /// The Jacobian entries proved.
    pub entries: usize,
    /// What ∂f/∂x and ∂f/∂u cost per call, as the emitter counts it.
    pub operations: [eom_codegen::emit::Operations; 2],
}

/// Every mutant of every `stride`-th node the Jacobians ∂f/∂x and ∂f/∂u read, each checked
/// against the exact derivative of `system`; panics on the first that passes.
pub fn jacobian_mutants(system: &System, stride: usize) -> Caught {
    let jacobian = Jacobian::of(system).unwrap();
    let program = Program::build_with_jacobian(system, &jacobian);
    verify_jacobian(system, &program, &jacobian).expect("the unmutated Jacobians verify");
    let jacobians = program.jacobians.as_ref().unwrap();
    let mut reached = program.reached(&jacobians.state);
    for (r, e) in reached.iter_mut().zip(program.reached(&jacobians.input)) {
        *r |= e;
    }
    // Each mutant is checked against the unmutated fold, refolding only what the mutated
    // node reaches (`verify_jacobian_changed`, the same verdict as `verify_jacobian`).
    let folded = Folded::of(system, &program).unwrap();
    let mut mutated = program.clone();
    let mut tried = 0;
    let nodes = (0..program.nodes.len()).filter(|&i| reached[i]);
    for index in nodes.step_by(stride) {
        for mutant in mutants(&program, index) {
            mutated.nodes[index] = mutant.clone();
            tried += 1;
            assert!(
                verify_jacobian_changed(system, &mutated, &jacobian, &folded, index).is_err(),
                "{}: replacing node {index} ({:?}) by {mutant:?} passed the Jacobian check",
                system.name,
                program.nodes[index]
            );
        }
        mutated.nodes[index] = program.nodes[index].clone();
        // The refolding check passes the unmutated program, read as changed at this node: it
        // does not fail every program it is given.
        assert!(
            verify_jacobian_changed(system, &mutated, &jacobian, &folded, index).is_ok(),
            "{}: the unmutated program fails the refolding check at node {index}",
            system.name
        );
    }
    Caught {
        tried,
        entries: jacobian.state.len() + jacobian.input.len(),
        operations: [
            program.operations(&jacobians.state),
            program.operations(&jacobians.input),
        ],
    }
}
