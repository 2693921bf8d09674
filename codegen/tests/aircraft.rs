//! The aircraft about G on its coefficients: built, proved and emitted; its inertia constants
//! c₁ … c₉ derived from the tensor equal Stevens & Lewis's formulas; and the proofs cannot
//! be fooled (every single-operation mutant of its program and of its Jacobians fails the
//! fold-back check, as for every model).
//!
//! The F-16 numbers (`data/f16_stevens_lewis.json`, its sources in `data/README.md`) are the
//! book's as its public transcriptions give them; the book itself was not read.

mod mutants;

use eom_codegen::emit::fold::verify;
use eom_codegen::emit::{Program, prove_with_jacobians, system_source};
use eom_codegen::model::aircraft::{QUATERNION_STATE, STATE, aircraft, aircraft_with, inputs};
use eom_codegen::model::{Kinematics, System};
use mutants::{jacobian_mutants, mutants};
use std::collections::BTreeMap;

fn f16() -> serde_json::Value {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../data/f16_stevens_lewis.json");
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn the_aircraft_builds_proves_and_emits() {
    let system = aircraft("aircraft").unwrap();
    let program = prove_with_jacobians(&system).unwrap();
    let source = system_source(&system).unwrap();
    syn::parse_file(&source).unwrap();
    assert_eq!(system.state, STATE);
    assert_eq!(system.inputs, inputs());
    assert!(source.contains("eom_kernel::Model<T, 13, 19> for Coefficients<T>"));
    println!(
        "aircraft: {} stages, rhs {:?}",
        system.stages.len(),
        program.operations(&program.rhs)
    );
}

/// The value of the rate of `STATE[row]` at a state and inputs, the F-16's inertia and the
/// other parameters given.
fn rate(system: &System, row: usize, set: &BTreeMap<&str, f64>) -> f64 {
    let d = f16();
    let mass = &d["mass_properties"];
    let value = |k: &str| mass[k]["value"].as_f64().unwrap();
    let mut values: BTreeMap<String, f64> = BTreeMap::new();
    for (k, v) in [
        ("Ixx", value("Ixx")),
        ("Iyy", value("Iyy")),
        ("Izz", value("Izz")),
        // The book's J_xz = ∫xz dm; the chapter's tensor entry is −∫xz dm.
        ("Ixz", -value("Ixz")),
        ("M", 1.0),
        ("g", 0.0),
        ("S", 1.0),
        ("b", 1.0),
        ("cbar", 1.0),
        ("vt", 1.0),
    ] {
        values.insert(k.into(), v);
    }
    for (k, v) in set {
        values.insert((*k).into(), *v);
    }
    for r in &system.reciprocals {
        let of = r.of.eval(&|s| values.get(s).copied().unwrap_or(0.0));
        values.insert(r.symbol.clone(), 1.0 / of);
    }
    let output = system.expanded_output(row).unwrap();
    output.eval(&|s| values.get(s).copied().unwrap_or(0.0))
}

/// ṗ = (c₂p + c₁r + c₄h_E)q + c₃L + c₄N, q̇ = (c₅p − c₇h_E)r + c₆(r² − p²) + c₇M,
/// ṙ = (c₈p − c₂r + c₉h_E)q + c₄L + c₉N: each constant read off the proved rates at unit
/// rates, loads and rotor momentum (ρ = 2, V = 1, S = b = c̄ = 1: q̄Sb = 1) equals the
/// formula's exact value to 1e-9 relative (the file's `exact`, printed to 10 digits); the
/// book's code carries them rounded to 3–4 digits.
#[test]
fn the_derived_inertia_constants_are_stevens_and_lewis_c1_to_c9() {
    let system = aircraft("aircraft").unwrap();
    let at =
        |row: usize, pairs: &[(&str, f64)]| rate(&system, row, &pairs.iter().copied().collect());
    let unit_moment = |name: &'static str| [("rho", 2.0), (name, 1.0)];
    let (p_dot, q_dot, r_dot) = (6, 7, 8);
    let derived = [
        ("c1", at(p_dot, &[("q", 1.0), ("r", 1.0)])),
        ("c2", at(p_dot, &[("q", 1.0), ("p", 1.0)])),
        ("c3", at(p_dot, &unit_moment("C_l"))),
        ("c4", at(p_dot, &unit_moment("C_n"))),
        (
            "c5",
            at(q_dot, &[("p", 1.0), ("r", 1.0)])
                - at(q_dot, &[("p", 1.0)])
                - at(q_dot, &[("r", 1.0)]),
        ),
        ("c6", at(q_dot, &[("r", 1.0)])),
        ("c7", at(q_dot, &unit_moment("C_m"))),
        ("c8", at(r_dot, &[("q", 1.0), ("p", 1.0)])),
        ("c9", at(r_dot, &unit_moment("C_n"))),
    ];
    let d = f16();
    let constants = &d["mass_properties"]["inertia_constants"];
    for (name, value) in derived {
        let exact = constants[name]["exact"].as_f64().unwrap();
        println!("{name}: derived {value:.10e}, formula {exact:.10e}");
        assert!((value / exact - 1.0).abs() < 1e-9, "{name}");
    }
    // The rotor: c₄h_E q in ṗ, −c₇h_E r in q̇, c₉h_E q in ṙ, at h_E = 1.
    let c = |name: &str| constants[name]["exact"].as_f64().unwrap();
    let rotor = [
        (p_dot, "q", c("c4")),
        (q_dot, "r", -c("c7")),
        (r_dot, "q", c("c9")),
    ];
    for (row, rate_name, wanted) in rotor {
        let got = at(row, &[("h_E", 1.0), (rate_name, 1.0)]) - at(row, &[(rate_name, 1.0)]);
        assert!((got / wanted - 1.0).abs() < 1e-9, "rotor in row {row}");
    }
}

/// Every single-operation mutant of the aircraft's program fails the fold-back check, in
/// Euler angles and in a quaternion.
#[test]
fn every_single_operation_mutant_of_the_aircraft_fails_the_check() {
    for kinematics in Kinematics::ALL {
        let system = aircraft_with("aircraft", kinematics).unwrap();
        let program = Program::build(&system);
        verify(&system, &program).expect("the unmutated program verifies");
        let reached = program.reached(&program.rhs);
        let mut tried = 0;
        for index in (0..program.nodes.len()).filter(|&i| reached[i]) {
            for mutant in mutants(&program, index) {
                let mut mutated = program.clone();
                mutated.nodes[index] = mutant.clone();
                tried += 1;
                assert!(
                    verify(&system, &mutated).is_err(),
                    "{kinematics:?}: replacing node {index} ({:?}) by {mutant:?} passed the check",
                    program.nodes[index]
                );
            }
        }
        println!("aircraft ({kinematics:?}) program mutants: {tried} caught of {tried} tried");
        assert!(tried >= 250, "only {tried} mutants");
    }
}

/// And of its Jacobians ∂f/∂x and ∂f/∂(inputs), every third node they read, in both.
#[test]
fn every_single_operation_mutant_of_the_aircraft_jacobians_fails_their_check() {
    for kinematics in Kinematics::ALL {
        let system = aircraft_with("aircraft", kinematics).unwrap();
        let caught = jacobian_mutants(&system, 3);
        println!(
            "aircraft ({kinematics:?}) Jacobian mutants: {} caught of {} tried, over {} proved \
             entries",
            caught.tried, caught.tried, caught.entries
        );
        assert!(caught.tried >= 350, "only {} mutants", caught.tried);
    }
}

/// The quaternion form builds, proves and emits, with the attitude in q0 … q3.
#[test]
fn the_quaternion_aircraft_builds_proves_and_emits() {
    let system = aircraft_with("aircraft", Kinematics::Quaternion).unwrap();
    prove_with_jacobians(&system).unwrap();
    let source = system_source(&system).unwrap();
    syn::parse_file(&source).unwrap();
    assert_eq!(system.state, QUATERNION_STATE);
    assert!(source.contains("eom_kernel::Model<T, 14, 19> for Coefficients<T>"));
}
