//! The check that a program folds back to its system cannot be fooled: every single-operation
//! mutant of every shipped model's program fails it.
//!
//! Mutations, applied to one node at a time: a sum becomes a difference and a difference a
//! sum (a flipped sign); the operands of a difference are swapped; a sum, a difference, a
//! negation or a reciprocal is replaced by its first operand (a dropped term or operation);
//! one operand of a product is replaced by another variable; a coefficient by another
//! coefficient; a constant by its double; a sine by the cosine of the same angle and back.
//! The same mutants of every node the Jacobians ∂f/∂x and ∂f/∂u read fail the check of the
//! Jacobians alone, against the exact derivative of the system.
//! `cargo test -p eom-codegen --test program_check -- --nocapture` prints the counts.

use eom_codegen::emit::Program;
use eom_codegen::emit::fold::{verify, verify_jacobian};
use eom_codegen::emit::program::{Id, Node};
use eom_codegen::model::{Jacobian, Model};
use num_rational::BigRational;

/// Every mutant of node `index`.
fn mutants(program: &Program, index: usize) -> Vec<Node> {
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

#[test]
fn every_single_operation_mutant_fails_the_check() {
    let (mut tried, mut caught) = (0, 0);
    for model in Model::all() {
        let strategy = eom_codegen::emit::generate(model).unwrap().strategy;
        let system = model.system(strategy).unwrap();
        let program = Program::build(&system);
        verify(&system, &program).expect("the unmutated program verifies");
        let mut reached = program.reached(&program.rhs);
        for energy in [&program.kinetic_energy, &program.potential_energy]
            .into_iter()
            .flatten()
        {
            for (r, e) in reached.iter_mut().zip(program.reached(energy)) {
                *r |= e;
            }
        }
        for index in (0..program.nodes.len()).filter(|&i| reached[i]) {
            for mutant in mutants(&program, index) {
                let mut mutated = program.clone();
                mutated.nodes[index] = mutant.clone();
                tried += 1;
                if verify(&system, &mutated).is_err() {
                    caught += 1;
                } else {
                    panic!(
                        "{}: replacing node {index} ({:?}) by {mutant:?} passed the check",
                        system.name, program.nodes[index]
                    );
                }
            }
        }
    }
    println!("program mutants: {caught} caught of {tried} tried");
    assert!(tried > 500, "only {tried} mutants");
}

#[test]
fn every_single_operation_mutant_of_the_jacobians_fails_their_check() {
    let (mut tried, mut caught, mut entries) = (0, 0, 0);
    for model in Model::all() {
        let strategy = eom_codegen::emit::generate(model).unwrap().strategy;
        let system = model.system(strategy).unwrap();
        let jacobian = Jacobian::of(&system).unwrap();
        let program = Program::build_with_jacobian(&system, &jacobian);
        verify_jacobian(&system, &program, &jacobian).expect("the unmutated Jacobians verify");
        let jacobians = program.jacobians.as_ref().unwrap();
        entries += jacobian.state.len() + jacobian.input.len();
        let mut reached = program.reached(&jacobians.state);
        for (r, e) in reached.iter_mut().zip(program.reached(&jacobians.input)) {
            *r |= e;
        }
        for index in (0..program.nodes.len()).filter(|&i| reached[i]) {
            for mutant in mutants(&program, index) {
                let mut mutated = program.clone();
                mutated.nodes[index] = mutant.clone();
                tried += 1;
                if verify_jacobian(&system, &mutated, &jacobian).is_err() {
                    caught += 1;
                } else {
                    panic!(
                        "{}: replacing node {index} ({:?}) by {mutant:?} passed the Jacobian check",
                        system.name, program.nodes[index]
                    );
                }
            }
        }
    }
    println!("Jacobian mutants: {caught} caught of {tried} tried, over {entries} proved entries");
    assert!(tried > 500, "only {tried} mutants");
}
