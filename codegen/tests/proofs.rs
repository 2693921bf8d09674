//! Every equation of the chapter is derived and proved equal to the book's form.

use eom_codegen::check::check_all;
use eom_codegen::check::{CheckError, Component, Equation};
use eom_codegen::derivation;
use eom_codegen::report;
use eom_codegen::symbolic::parse;

const REQUIRED: [&str; 29] = [
    "4.9",
    "4.24",
    "4.39",
    "4.57 q",
    "4.60 q",
    "4.10",
    "4.12",
    "4.13",
    "4.14",
    "4.23",
    "4.32",
    "4.34",
    "4.35",
    "4.42",
    "4.43",
    "4.44",
    "4.46",
    "4.49",
    "4.51",
    "4.52",
    "4.57",
    "4.57 EᵀE",
    "4.59",
    "4.60",
    "4.23 top",
    "4.50 top",
    "4.50 top q",
    "4.34 top",
    "4.35 top",
];

#[test]
fn every_equation_of_the_chapter_is_proved() {
    let proved = check_all().unwrap_or_else(|e| panic!("{e}"));
    for number in REQUIRED {
        assert!(
            proved.iter().any(|e| e.number == number),
            "({number}) is missing"
        );
    }
}

#[test]
fn a_wrong_reference_names_the_equation_and_prints_the_residual() {
    let equation = Equation {
        number: "4.49",
        description: "translation, with a sign error",
        components: vec![Component::new(
            "x",
            parse("M*(u_dot + w*q - v*r)").unwrap(),
            "M*(u_dot - w*q - v*r)",
            &[],
        )],
    };
    let error = equation.check().unwrap_err();
    assert_eq!(
        error,
        CheckError::Mismatch {
            number: "4.49",
            component: "x".into(),
            residual: "2*M*q*w".into(),
        }
    );
    assert!(error.to_string().contains("(4.49)"));
}

#[test]
fn a_reference_the_engine_cannot_read_is_an_error_not_a_pass() {
    let equation = Equation {
        number: "4.60",
        description: "unreadable",
        components: vec![Component::new(
            "[1,1]",
            parse("1").unwrap(),
            "1 / (a + b)",
            &[],
        )],
    };
    assert!(matches!(
        equation.check(),
        Err(CheckError::Reference { number: "4.60", .. })
    ));
}

#[test]
fn the_report_is_byte_for_byte_repeatable_and_proves_everything() {
    let equations = derivation::all().unwrap();
    let first = report::markdown(&equations);
    let second = report::markdown(&derivation::all().unwrap());
    assert_eq!(first, second);
    assert!(!first.contains("not proved"));
    let n = equations.len();
    assert!(first.contains(&format!("{n} of {n} equations proved")));
}
