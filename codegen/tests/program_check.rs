//! The check that a program folds back to its system cannot be fooled: every single-operation
//! mutant (`mutants/mod.rs` lists them) of every shipped model's program fails it. The same mutants of every node the Jacobians ∂f/∂x and ∂f/∂u read fail the check of the
//! Jacobians alone, against the exact derivative of the system.
//! `cargo test -p eom-codegen --test program_check -- --nocapture` prints the counts.

mod mutants;

use eom_codegen::emit::Program;
use eom_codegen::emit::fold::verify;
use eom_codegen::model::Model;
use mutants::{jacobian_mutants, mutants};

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
    let (mut tried, mut entries) = (0, 0);
    for model in Model::all() {
        let strategy = eom_codegen::emit::generate(model).unwrap().strategy;
        let system = model.system(strategy).unwrap();
        let found = jacobian_mutants(&system, 1);
        tried += found.tried;
        entries += found.entries;
    }
    println!("Jacobian mutants: {tried} caught of {tried} tried, over {entries} proved entries");
    assert!(tried > 500, "only {tried} mutants");
}
