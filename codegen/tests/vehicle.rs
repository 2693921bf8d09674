//! Underwater vehicles about their table's origin: the proofs of the equations about O and of
//! Kirchhoff's terms, the reduction to the catalog's spatial model at r_G = 0, the names of a
//! table, the REMUS model proved and emitted, the folded table against its added mass, and the
//! mass matrix's numeric checks.
//!
//! The REMUS numbers (`data/remus100_prestero.json`, its sources in `data/README.md`) are
//! Prestero's (2001, Appendix B) as his public transcriptions give them; the thesis itself was
//! not read.

mod mutants;

use eom_codegen::check::Equation;
use eom_codegen::derivation::spatial;
use eom_codegen::derivation::vehicle::{
    self, added_mass_coriolis, general_added_mass, rigid_body_about_origin,
};
use eom_codegen::emit::{fold, prove, system_source};
use eom_codegen::model::ship::Units;
use eom_codegen::model::vehicle::{
    AddedMassCoriolis, Convention, InertiaAbout, Load, NameError, Propeller, VehicleError,
    VehicleSpec, folded_comparison, format_folded, parse_added_mass, parse_term, vehicle,
};
use eom_codegen::model::{Kinematics, Model, Strategy, Symmetry, System};
use eom_codegen::symbolic::{Expr, parse};
use std::collections::BTreeMap;

// ---------------------------------------------------------------------------------------
// The proofs.

fn proved(number: &str) -> Equation {
    let equation = vehicle::equations()
        .unwrap()
        .into_iter()
        .find(|e| e.number == number)
        .unwrap();
    equation.check().unwrap_or_else(|e| panic!("{e}"));
    equation
}

#[test]
fn the_equations_about_o_equal_the_standard_component_form() {
    let equation = proved("4.1–4.2 O");
    assert_eq!(equation.components.len(), 6);
    assert_eq!(equation.term_count(), 78);
}

#[test]
fn the_equations_about_o_equal_m_rb_nu_dot_plus_c_rb_nu() {
    assert_eq!(proved("4.1–4.2 O M_RB").term_count(), 78);
}

#[test]
fn kirchhoffs_terms_equal_fossens_c_a_for_a_general_symmetric_added_mass() {
    assert_eq!(proved("Kirchhoff C_A").term_count(), 144);
}

#[test]
fn kirchhoffs_terms_of_a_body_of_revolution_are_prestero_s_folded_cross_terms() {
    proved("Kirchhoff REMUS");
}

/// With G at O, the six equations are 4.49 and 4.51, the catalog's, exactly.
#[test]
fn at_r_g_zero_the_equations_about_o_are_4_49_and_4_51() {
    let at_o = [
        ("x_G", Expr::zero()),
        ("y_G", Expr::zero()),
        ("z_G", Expr::zero()),
    ];
    let about_o = rigid_body_about_origin().unwrap();
    let translation = spatial::translation();
    let rotation = spatial::euler_equations().unwrap();
    let loads = ["F_x", "F_y", "F_z", "M_x", "M_y", "M_z"].map(Expr::symbol);
    for i in 0..6 {
        let catalog = if i < 3 {
            &translation.0[i] - &loads[i]
        } else {
            &rotation.0[i - 3] - &loads[i]
        };
        let difference = &about_o[i].subs_all(&at_o).unwrap() - &catalog;
        assert!(difference.is_zero(), "row {i}: {difference}");
    }
}

/// Neither the rigid body's nor the fluid's Coriolis terms do work: νᵀC(ν)ν = 0.
#[test]
fn the_coriolis_terms_of_body_and_fluid_do_no_work() {
    let nu = ["u", "v", "w", "p", "q", "r"].map(Expr::symbol);
    let at_rest: Vec<(String, Expr)> = ["u", "v", "w", "p", "q", "r"]
        .iter()
        .map(|v| (format!("{v}_dot"), Expr::zero()))
        .chain(
            ["F_x", "F_y", "F_z", "M_x", "M_y", "M_z"]
                .iter()
                .map(|l| (l.to_string(), Expr::zero())),
        )
        .collect();
    let at_rest: Vec<(&str, Expr)> = at_rest
        .iter()
        .map(|(s, e)| (s.as_str(), e.clone()))
        .collect();
    let body = rigid_body_about_origin().unwrap();
    let fluid = added_mass_coriolis(&general_added_mass()).unwrap();
    let mut power = Expr::zero();
    for i in 0..6 {
        let c = &body[i].subs_all(&at_rest).unwrap() + &fluid[i];
        assert!(!c.is_zero());
        power = &power + &(&nu[i] * &c);
    }
    assert!(power.is_zero(), "νᵀCν = {power}");
}

/// A mutant of a reference form — one sign flipped, one term dropped — is not proved.
#[test]
fn every_single_term_mutant_of_the_vehicle_proofs_is_caught() {
    let mut caught = 0;
    for equation in vehicle::equations().unwrap() {
        for component in &equation.components {
            // The reference text with one `+` turned into `-`.
            for (at, _) in component.reference_text.match_indices('+') {
                let mut mutant = component.clone();
                mutant.reference_text.replace_range(at..at + 1, "-");
                let residual = mutant.residual().unwrap();
                assert!(
                    !residual.is_zero(),
                    "{} {}: {}",
                    equation.number,
                    component.label,
                    mutant.reference_text
                );
                caught += 1;
            }
            // The derived form with one term's sign flipped.
            for (monomial, coefficient) in component.derived.terms().take(8) {
                let mut mutant = component.clone();
                let term = Expr::term(coefficient.clone(), monomial.clone());
                mutant.derived = &component.derived - &(&term * &Expr::int(2));
                assert!(!mutant.residual().unwrap().is_zero());
                caught += 1;
            }
        }
    }
    println!("{caught} mutants caught");
    assert!(caught > 150, "{caught}");
}

// ---------------------------------------------------------------------------------------
// The names of a table.

fn remus() -> serde_json::Value {
    // The crate's tests run in codegen/; the published data are in the repository's data/.
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../data/remus100_prestero.json"
    );
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str(&text).unwrap()
}

fn remus_coefficients() -> BTreeMap<String, f64> {
    remus()["coefficients"]
        .as_object()
        .unwrap()
        .iter()
        .map(|(name, value)| (name.clone(), value.as_f64().unwrap()))
        .collect()
}

fn controls() -> Vec<String> {
    vec!["dr".into(), "ds".into()]
}

#[test]
fn every_name_of_the_remus_table_reads_under_prestero_s_convention() {
    let mut terms = 0;
    for name in remus_coefficients().keys() {
        if name.ends_with("dot") {
            parse_added_mass(name).unwrap();
        } else {
            parse_term(name, Convention::Prestero, &controls()).unwrap();
            terms += 1;
        }
    }
    assert_eq!(terms, 34);
    let meaning = |name: &str| {
        parse_term(name, Convention::Prestero, &controls())
            .unwrap()
            .meaning()
    };
    assert_eq!(meaning("Xuu"), "u·|u|");
    assert_eq!(meaning("Yvv"), "v·|v|");
    assert_eq!(meaning("Yrr"), "r·|r|");
    assert_eq!(meaning("Mqq"), "q·|q|");
    assert_eq!(meaning("Kpp"), "p·|p|");
    assert_eq!(meaning("Xqq"), "q·q");
    assert_eq!(meaning("Xrr"), "r·r");
    assert_eq!(meaning("Yuudr"), "u·u·dr");
    assert_eq!(meaning("Zrp"), "r·p");
    assert_eq!(meaning("Muw"), "u·w");
    let entry = parse_added_mass("Mwdot").unwrap();
    assert_eq!((entry.row, entry.column), (Load::M.index(), 2));
}

#[test]
fn fossen_s_convention_writes_every_factor() {
    let read = |name: &str| parse_term(name, Convention::Fossen, &["n".into()]).unwrap();
    assert_eq!(read("Yv|v|").meaning(), "v·|v|");
    assert_eq!(read("Yv|v|").symbol(), "Yv_abs_v");
    assert_eq!(read("Xuu").meaning(), "u·u");
    assert_eq!(read("Xn|n|").meaning(), "n·|n|");
    assert_eq!(read("Y0").meaning(), "1");
}

#[test]
fn an_ambiguous_name_is_refused_and_named() {
    for name in ["Xvv", "Kqq", "Yvvr", "Nuuu", "Xdrdr", "Yuvv"] {
        match parse_term(name, Convention::Prestero, &controls()) {
            Err(error @ NameError::Ambiguous { .. }) => {
                assert!(error.to_string().contains(&format!("`{name}`")), "{error}");
            }
            other => panic!("{name}: {other:?}"),
        }
    }
}

#[test]
fn an_unknown_name_is_refused_and_named() {
    for (name, convention) in [
        ("Yfoo", Convention::Prestero),
        ("Qvv", Convention::Prestero),
        ("Yv|v|", Convention::Prestero),
        ("Yv|x|", Convention::Fossen),
        ("Yv|v", Convention::Fossen),
        ("Y", Convention::Fossen),
        ("Yvdot", Convention::Fossen),
    ] {
        match parse_term(name, convention, &controls()) {
            Err(error @ NameError::Unknown { .. }) => {
                assert!(error.to_string().contains(&format!("`{name}`")), "{error}");
            }
            other => panic!("{name}: {other:?}"),
        }
    }
    assert!(parse_added_mass("Xadot").is_err());
    assert!(parse_added_mass("Xuvdot").is_err());
}

// ---------------------------------------------------------------------------------------
// REMUS.

fn remus_spec(kinematics: Kinematics, coriolis: AddedMassCoriolis) -> VehicleSpec {
    let coefficients = remus_coefficients();
    VehicleSpec {
        units: Units::Dimensional,
        kinematics,
        // Prestero's moments are about O, the centre of buoyancy (data/README.md).
        inertia: InertiaAbout::Origin,
        symmetry: Symmetry::Principal,
        convention: Convention::Prestero,
        controls: controls(),
        added_mass: coefficients
            .keys()
            .filter(|n| n.ends_with("dot"))
            .cloned()
            .collect(),
        added_mass_coriolis: coriolis,
        terms: coefficients
            .keys()
            .filter(|n| !n.ends_with("dot"))
            .cloned()
            .collect(),
        propeller: Propeller::Constant,
        hydrostatics: true,
        applied_loads: false,
    }
}

fn remus_values() -> BTreeMap<String, f64> {
    let data = remus();
    let body = &data["mass_properties"];
    let mut values = remus_coefficients();
    let number = |v: &serde_json::Value| v.as_f64().unwrap();
    values.insert("M".into(), number(&body["mass_kg"]));
    for axis in ["Ixx", "Iyy", "Izz"] {
        values.insert(axis.into(), number(&body["inertia_about_O_kg_m2"][axis]));
    }
    for (i, axis) in ["x", "y", "z"].iter().enumerate() {
        values.insert(format!("{axis}_G"), number(&body["centre_of_gravity_m"][i]));
        values.insert(
            format!("{axis}_B"),
            number(&body["centre_of_buoyancy_m"][i]),
        );
    }
    values.insert("weight".into(), number(&body["weight_N"]));
    values.insert("buoyancy".into(), number(&body["buoyancy_N"]));
    values.insert(
        "X_prop".into(),
        number(&data["propeller_at_1500_rpm"]["X_prop_N"]),
    );
    values.insert(
        "K_prop".into(),
        number(&data["propeller_at_1500_rpm"]["K_prop_N_m"]),
    );
    values
}

#[test]
fn remus_builds_proves_and_emits_only_its_terms() {
    let start = std::time::Instant::now();
    let spec = remus_spec(Kinematics::Quaternion, AddedMassCoriolis::Folded);
    let system = vehicle("remus", &spec).unwrap();
    let program = prove(&system).unwrap();
    let source = system_source(&system).unwrap();
    syn::parse_file(&source).unwrap();
    for name in &spec.terms {
        assert!(
            source.contains(&format!("pub {}: f64", name.to_lowercase())),
            "{name}"
        );
    }
    assert!(source.contains("pub minv_uv: f64") && source.contains("pub minv_rr: f64"));
    // A term the table does not list is not in the code, nor an added mass it lacks.
    assert!(!source.contains("pub yvr") && !source.contains("pub xvdot"));
    // Prestero's doubled letters are signed squares: |u|, |v|, … are inputs.
    assert_eq!(
        system.inputs,
        [
            "dr", "ds", "abs_u", "abs_v", "abs_w", "abs_p", "abs_q", "abs_r"
        ]
    );
    assert!(source.contains("eom_kernel::Model<T, 13, 8> for Coefficients<T>"));
    println!(
        "REMUS: {} stages, rhs {:?}, proved and emitted in {:?}",
        system.stages.len(),
        program.operations(&program.rhs),
        start.elapsed()
    );
}

/// The fold-back proof catches a program that is not the system's: flip one output's sign.
#[test]
fn a_program_of_another_system_is_refused() {
    let spec = remus_spec(Kinematics::Euler, AddedMassCoriolis::Derived);
    let system = vehicle("remus", &spec).unwrap();
    let program = prove(&system).unwrap();
    for index in [0, 4, 8, 11] {
        let mut mutant: System = system.clone();
        mutant.outputs[index] = -&mutant.outputs[index];
        assert!(fold::verify(&mutant, &program).is_err(), "output {index}");
    }
    let mut mutant = system.clone();
    let (_, bias) = &mut mutant.stages[3];
    *bias = &*bias + &parse("Kpp*p*abs_p").unwrap();
    assert!(fold::verify(&mutant, &program).is_err());
}

#[test]
fn the_folded_table_is_shown_against_its_added_mass() {
    let spec = remus_spec(Kinematics::Quaternion, AddedMassCoriolis::Folded);
    let rows = folded_comparison(&spec, &remus_values()).unwrap();
    println!("{}", format_folded(&rows));
    let row = |name: &str| {
        rows.iter()
            .find(|r| r.name.as_deref() == Some(name))
            .unwrap()
    };
    // Xwq = Z_ẇ: printed as implied.
    assert_eq!(row("Xwq").implied, -35.5);
    assert_eq!(row("Xwq").difference, Some(0.0));
    // Mrp = K_ṗ − N_ṙ = 4.8096, printed 4.86 (the transcriptions differ on K_ṗ).
    assert!((row("Mrp").implied - 4.8096).abs() < 1e-12);
    assert!((row("Mrp").difference.unwrap() - 0.0504).abs() < 1e-12);
    // The Munk moment Muw = −(Z_ẇ − X_u̇) = 34.57; the table's 24 holds the body's lift too.
    assert!((row("Muw").implied - 34.57).abs() < 1e-12);
    assert!((row("Muw").difference.unwrap() + 10.57).abs() < 1e-12);
    // All of Prestero's folded cross terms are found by meaning, Zrp as r·p among them.
    for name in [
        "Xwq", "Xqq", "Xvr", "Xrr", "Yur", "Ywp", "Ypq", "Zuq", "Zvp", "Zrp", "Muw", "Muq", "Mvp",
        "Mrp", "Nuv", "Nur", "Nwp", "Npq",
    ] {
        row(name);
    }
    let exact = rows.iter().filter(|r| r.difference == Some(0.0)).count();
    assert_eq!(exact, 10);
    // Kirchhoff's roll terms that Prestero leaves out vanish for REMUS's axisymmetric numbers.
    for row in rows.iter().filter(|r| r.name.is_none()) {
        assert_eq!(row.load, Load::K, "{row:?}");
        assert!(row.implied.abs() < 1e-12, "{row:?}");
    }
}

#[test]
fn remus_mass_matrix_is_positive_definite_and_inverted_once() {
    let spec = remus_spec(Kinematics::Quaternion, AddedMassCoriolis::Folded);
    let values = remus_values();
    let matrix = spec.mass_matrix_values(&values).unwrap();
    // M − X_u̇ on the diagonal; the fins' Y_ṙ off it, with M x_G = 0.
    assert!((matrix[0][0] - (30.48 + 0.93)).abs() < 1e-12);
    assert!((matrix[1][5] + 1.93).abs() < 1e-12);
    let inverse: BTreeMap<String, f64> = spec
        .inverse_mass_matrix(&values)
        .unwrap()
        .into_iter()
        .collect();
    assert_eq!(inverse.len(), 21);
    let entry = |i: usize, j: usize| inverse[&eom_codegen::model::vehicle::inverse_entry(i, j)];
    for (i, row) in matrix.iter().enumerate() {
        for j in 0..6 {
            let product: f64 = row.iter().enumerate().map(|(k, m)| m * entry(k, j)).sum();
            assert!(
                (product - f64::from(u8::from(i == j))).abs() < 1e-12,
                "({i}, {j})"
            );
        }
    }
}

#[test]
fn a_mass_matrix_that_is_not_positive_definite_is_refused_naming_its_entries() {
    let spec = remus_spec(Kinematics::Quaternion, AddedMassCoriolis::Folded);
    let mut values = remus_values();
    values.insert("Kpdot".into(), 1.0);
    let error = spec.inverse_mass_matrix(&values).unwrap_err();
    let text = error.to_string();
    assert!(
        matches!(error, VehicleError::NotPositiveDefinite { axis: "p", .. }),
        "{text}"
    );
    assert!(
        text.contains("Kpdot = 1") && text.contains("Ixx = 0.177"),
        "{text}"
    );
}

#[test]
fn an_added_mass_given_twice_must_be_symmetric() {
    let spec = remus_spec(Kinematics::Quaternion, AddedMassCoriolis::Folded);
    let mut values = remus_values();
    values.insert("Nvdot".into(), 2.0);
    let error = spec.mass_matrix_values(&values).unwrap_err();
    assert!(error.to_string().contains("`Nvdot` = 2"), "{error}");
}

#[test]
fn what_is_not_supported_or_not_readable_is_refused() {
    let mut spec = remus_spec(Kinematics::Quaternion, AddedMassCoriolis::Folded);
    spec.units = Units::Prime;
    spec.terms.push("Yuvr".into());
    assert!(matches!(
        vehicle("v", &spec),
        Err(VehicleError::Prime { .. })
    ));
    let mut spec = remus_spec(Kinematics::Quaternion, AddedMassCoriolis::Folded);
    spec.controls.push("rudder".into());
    assert!(matches!(
        vehicle("v", &spec),
        Err(VehicleError::Control { .. })
    ));
    let mut spec = remus_spec(Kinematics::Quaternion, AddedMassCoriolis::Folded);
    spec.terms.push("Xvv".into());
    assert!(matches!(
        vehicle("v", &spec),
        Err(VehicleError::Name(NameError::Ambiguous { .. }))
    ));
    let mut spec = remus_spec(Kinematics::Quaternion, AddedMassCoriolis::Folded);
    spec.terms.push("Yvv".into());
    assert!(matches!(
        vehicle("v", &spec),
        Err(VehicleError::ListedTwice(_))
    ));
    let mut spec = remus_spec(Kinematics::Quaternion, AddedMassCoriolis::Folded);
    spec.convention = Convention::Fossen;
    spec.terms = vec!["Yv|v|".into(), "Yvabs".into()];
    assert!(vehicle("v", &spec).is_err());
}

// ---------------------------------------------------------------------------------------
// The built system against the catalog's and against its own energy.

fn bare_spec(kinematics: Kinematics) -> VehicleSpec {
    VehicleSpec {
        units: Units::Dimensional,
        kinematics,
        inertia: InertiaAbout::Origin,
        symmetry: Symmetry::Full,
        convention: Convention::Fossen,
        controls: vec![],
        added_mass: vec![],
        added_mass_coriolis: AddedMassCoriolis::Derived,
        terms: vec![],
        propeller: Propeller::None,
        hydrostatics: false,
        applied_loads: true,
    }
}

/// The value of every symbol at a test point: a body with all products of inertia, a state
/// away from every singularity, loads on every axis.
fn point() -> BTreeMap<String, f64> {
    let pairs = [
        ("M", 30.5),
        ("Ixx", 0.9),
        ("Iyy", 3.4),
        ("Izz", 3.6),
        ("Ixy", 0.07),
        ("Iyz", -0.11),
        ("Ixz", 0.2),
        ("x_G", 0.0),
        ("y_G", 0.0),
        ("z_G", 0.0),
        ("u", 1.4),
        ("v", -0.3),
        ("w", 0.2),
        ("p", 0.5),
        ("q", -0.7),
        ("r", 0.3),
        ("x", 3.0),
        ("y", -2.0),
        ("z", 5.0),
        ("phi", 0.3),
        ("theta", -0.4),
        ("psi", 1.1),
        ("F_x", 4.0),
        ("F_y", -1.0),
        ("F_z", 2.5),
        ("M_x", 0.3),
        ("M_y", -0.8),
        ("M_z", 0.6),
    ];
    pairs.iter().map(|(s, v)| (s.to_string(), *v)).collect()
}

fn evaluate(system: &System, index: usize, values: &BTreeMap<String, f64>) -> f64 {
    let output = system.expanded_output(index).unwrap();
    output.eval(&|s| *values.get(s).unwrap_or_else(|| panic!("no value for {s}")))
}

/// At r_G = 0 without added mass, the vehicle's system is the catalog's spatial model with
/// all products of inertia: every rate, with the inverse mass matrix computed numerically.
#[test]
fn at_r_g_zero_the_vehicle_is_the_catalogs_spatial_full_model() {
    let spec = bare_spec(Kinematics::Euler);
    let system = vehicle("bare", &spec).unwrap();
    let mut values = point();
    values.extend(spec.inverse_mass_matrix(&values).unwrap());
    let catalog = Model::Spatial {
        symmetry: Symmetry::Full,
        kinematics: Kinematics::Euler,
    }
    .system(Strategy::Expanded)
    .unwrap();
    for reciprocal in &catalog.reciprocals {
        let of = reciprocal.of.eval(&|s| values[s]);
        values.insert(reciprocal.symbol.clone(), 1.0 / of);
    }
    assert_eq!(system.state, catalog.state);
    for i in 0..system.outputs.len() {
        let (ours, theirs) = (
            evaluate(&system, i, &values),
            evaluate(&catalog, i, &values),
        );
        assert!(
            (ours - theirs).abs() <= 1e-12 * theirs.abs().max(1.0),
            "{}: {ours} against {theirs}",
            system.state[i]
        );
    }
}

/// Along the equations without the table's terms, T + V is constant: the Coriolis terms of
/// body and fluid do no work and the restoring loads are −∂V. Proved exactly with Euler
/// angles: dT/dt = νᵀM ν̇ = −νᵀ bias, with ∂T/∂ν = Mν checked first.
#[test]
fn body_fluid_and_hydrostatics_conserve_energy_along_the_equations() {
    let mut spec = remus_spec(Kinematics::Euler, AddedMassCoriolis::Derived);
    spec.terms.clear();
    spec.controls.clear();
    spec.propeller = Propeller::None;
    spec.symmetry = Symmetry::Full;
    spec.added_mass = vec![
        "Xudot", "Yvdot", "Zwdot", "Kpdot", "Mqdot", "Nrdot", "Yrdot", "Zqdot", "Xqdot", "Kvdot",
    ]
    .into_iter()
    .map(String::from)
    .collect();
    let system = vehicle("conservative", &spec).unwrap();
    let t = system.kinetic_energy.clone().unwrap();
    let v = system.potential_energy.clone().unwrap();
    let mass = spec.mass_matrix().unwrap();
    let nu = ["u", "v", "w", "p", "q", "r"];
    for i in 0..6 {
        let m_nu: Expr = (0..6).map(|j| &mass[i][j] * &Expr::symbol(nu[j])).sum();
        assert!((&t.diff(nu[i]) - &m_nu).is_zero(), "∂T/∂{}", nu[i]);
    }
    let bias: Vec<Expr> = system.stages[..6].iter().map(|(_, e)| e.clone()).collect();
    let kinetic: Expr = (0..6).map(|i| -(&Expr::symbol(nu[i]) * &bias[i])).sum();
    let mut potential = Expr::zero();
    for (i, state) in system.state.iter().enumerate().skip(6) {
        potential = potential + v.diff(state) * system.expanded_output(i).unwrap();
    }
    let power = &kinetic + &potential;
    assert!(!kinetic.is_zero());
    assert!(power.is_zero(), "d(T + V)/dt = {power}");
}

/// The restoring loads with Euler angles are −g(η) of Fossen (2011, 4.6), Z down.
#[test]
fn the_restoring_loads_are_fossens_g_of_eta_with_the_sign_on_the_right() {
    let spec = remus_spec(Kinematics::Euler, AddedMassCoriolis::Folded);
    let g_eta = [
        "(weight - buoyancy)*theta.sin()",
        "-(weight - buoyancy)*theta.cos()*phi.sin()",
        "-(weight - buoyancy)*theta.cos()*phi.cos()",
        "-(y_G*weight - y_B*buoyancy)*theta.cos()*phi.cos() + (z_G*weight - z_B*buoyancy)*theta.cos()*phi.sin()",
        "(z_G*weight - z_B*buoyancy)*theta.sin() + (x_G*weight - x_B*buoyancy)*theta.cos()*phi.cos()",
        "-(x_G*weight - x_B*buoyancy)*theta.cos()*phi.sin() - (y_G*weight - y_B*buoyancy)*theta.sin()",
    ];
    for (restoring, book) in spec.restoring().iter().zip(g_eta) {
        let sum = restoring + &parse(book).unwrap();
        assert!(sum.is_zero(), "{book}: {sum}");
    }
}

/// With a quaternion, the restoring loads at q(φ, θ, ψ) (half angles, |q| = 1 identically)
/// are those of the Euler angles.
#[test]
fn the_quaternions_restoring_loads_are_the_euler_angles_ones() {
    use eom_codegen::derivation::quaternion::{
        body_to_space_half_angles, quaternion_of_euler_angles,
    };
    let spec = remus_spec(Kinematics::Quaternion, AddedMassCoriolis::Folded);
    let q = quaternion_of_euler_angles();
    let at_euler: Vec<(&str, Expr)> = ["q0", "q1", "q2", "q3"].into_iter().zip(q.0).collect();
    let down = body_to_space_half_angles()
        .transpose()
        .mul_vec(&eom_codegen::symbolic::Vec3::new(
            Expr::zero(),
            Expr::zero(),
            Expr::int(1),
        ));
    let (weight, buoyancy) = (Expr::symbol("weight"), Expr::symbol("buoyancy"));
    let r_g = eom_codegen::symbolic::Vec3::symbols(["x_G", "y_G", "z_G"]);
    let r_b = eom_codegen::symbolic::Vec3::symbols(["x_B", "y_B", "z_B"]);
    let moment = r_g
        .cross(&down.scale(&weight))
        .sub(&r_b.cross(&down.scale(&buoyancy)));
    let force = down.scale(&(&weight - &buoyancy));
    let expected: Vec<Expr> = force.0.into_iter().chain(moment.0).collect();
    for (restoring, expected) in spec.restoring().iter().zip(expected) {
        let difference = &restoring.subs_all(&at_euler).unwrap() - &expected;
        assert!(difference.is_zero(), "{difference}");
    }
}

/// The Jacobians of a vehicle's program, proved when the scene is read, cannot be fooled
/// either: REMUS in quaternions (the model that runs) and in Euler angles (the twin that is
/// linearised), every mutant of every node their Jacobians read.
#[test]
fn single_operation_mutants_of_remus_s_jacobians_fail_their_check() {
    for kinematics in [Kinematics::Quaternion, Kinematics::Euler] {
        let spec = remus_spec(kinematics, AddedMassCoriolis::Folded);
        let system = vehicle("remus", &spec).unwrap();
        let caught = mutants::jacobian_mutants(&system, 1);
        println!(
            "REMUS ({kinematics:?}): {} Jacobian mutants caught of {}, over {} proved entries; ∂f/∂x {:?}, ∂f/∂u {:?}",
            caught.tried, caught.tried, caught.entries, caught.operations[0], caught.operations[1]
        );
        assert!(caught.tried > 100, "only {}", caught.tried);
    }
}

// ---------------------------------------------------------------------------------------
// The prime system: the NPS AUV II of Healey & Lienard (1993), as Fossen's MSS `npsauv.m`
// scales it (U = u, ½ρL^(2 + a + m) u^(2 − j) per term).

/// A table of `scenes/nps_auv2.toml`, `added_mass` or `coefficients`, read line by line
/// (`Name = number`, comments after `#`), as the scene writes it.
fn nps_table(table: &str) -> BTreeMap<String, f64> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/nps_auv2.toml");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let header = format!("[hydrodynamics.{table}]");
    let mut lines = text.lines().skip_while(|l| l.trim() != header).skip(1);
    let mut values = BTreeMap::new();
    for line in lines.by_ref() {
        let line = line.split('#').next().unwrap().trim();
        if line.starts_with('[') {
            break;
        }
        if let Some((name, value)) = line.split_once('=') {
            values.insert(name.trim().to_owned(), value.trim().parse::<f64>().unwrap());
        }
    }
    assert!(!values.is_empty(), "no {header}");
    values
}

/// The NPS AUV II as its scene makes it: its tensor about O with all three products, the
/// propeller law's ε as a control `n` beside the fins, the cross-flow drag as applied loads.
fn nps_spec(kinematics: Kinematics) -> VehicleSpec {
    let mut controls = controls();
    controls.push("n".to_owned());
    VehicleSpec {
        units: Units::Prime,
        kinematics,
        inertia: InertiaAbout::Origin,
        symmetry: Symmetry::Full,
        convention: Convention::Fossen,
        controls,
        added_mass: nps_table("added_mass").into_keys().collect(),
        added_mass_coriolis: AddedMassCoriolis::Folded,
        terms: nps_table("coefficients").into_keys().collect(),
        propeller: Propeller::Constant,
        hydrostatics: true,
        applied_loads: true,
    }
}

/// A spec of a few terms and entries only, in `units`.
fn small_spec(units: Units, terms: &[&str], added_mass: &[&str]) -> VehicleSpec {
    VehicleSpec {
        units,
        terms: terms.iter().map(|t| t.to_string()).collect(),
        added_mass: added_mass.iter().map(|t| t.to_string()).collect(),
        inertia: InertiaAbout::Gravity,
        symmetry: Symmetry::Principal,
        controls: controls(),
        propeller: Propeller::None,
        hydrostatics: false,
        applied_loads: false,
        ..nps_spec(Kinematics::Euler)
    }
}

/// Each term's prime form against its SI form: in the prime system a term of j velocity
/// factors, a of them angular, in a load (m = 1 for a moment) is the SI term with the
/// coefficient ½ρL^(2 + a + m) u^(2 − j) times the prime one, as npsauv.m writes each
/// (r2·Yv·u·v, r3·Kv·u·v, r4·Kp·u·p, r5·Kpq·p·q, r2·Ydr·u²·δ_r, r2·Xvv·v², r3·Xqds·u·q·δ_s).
#[test]
fn a_prime_term_is_its_si_term_scaled_by_half_rho_l_powers_and_the_surge_velocity() {
    let cases = [
        ("Yv", "Yuv", "rho/2.0*L.powi(2)"),
        ("Kv", "Kuv", "rho/2.0*L.powi(3)"),
        ("Kp", "Kup", "rho/2.0*L.powi(4)"),
        ("Kpq", "Kpq", "rho/2.0*L.powi(5)"),
        ("Ydr", "Yuudr", "rho/2.0*L.powi(2)"),
        ("Xvv", "Xvv", "rho/2.0*L.powi(2)"),
        ("Xqds", "Xuqds", "rho/2.0*L.powi(3)"),
        ("Muq", "Muq", "rho/2.0*L.powi(4)"),
        ("Xdsds", "Xuudsds", "rho/2.0*L.powi(2)"),
    ];
    for (prime, si, scale) in cases {
        let primed = small_spec(Units::Prime, &[prime], &[]).loads().unwrap();
        let dimensional = small_spec(Units::Dimensional, &[si], &[]).loads().unwrap();
        let scaled = parse(&format!("{scale}*{prime}")).unwrap();
        let load = prime[..1].chars().next().unwrap();
        let index = "XYZKMN".find(load).unwrap();
        let expected = dimensional[index].subs(si, &scaled).unwrap();
        let difference = &primed[index] - &expected;
        assert!(difference.is_zero(), "{prime}: {difference}");
        assert!(!primed[index].is_zero());
    }
}

/// The added mass in the prime system is ½ρL³·T⁻¹M′_AT⁻¹, T⁻¹ = diag(1, 1, 1, L, L, L), as
/// npsauv.m scales it: X_u̇ by ½ρL³, Y_ṙ and N_v̇ by ½ρL⁴, K_ṗ and N_ṙ by ½ρL⁵.
#[test]
fn the_prime_added_mass_is_half_rho_l_cubed_t_inverse_m_a_t_inverse() {
    let spec = small_spec(
        Units::Prime,
        &[],
        &["Xudot", "Yvdot", "Yrdot", "Kpdot", "Mwdot", "Nrdot"],
    );
    let m_a = spec.added_mass_matrix().unwrap();
    let cases = [
        (0, 0, "-rho/2.0*L.powi(3)*Xudot"),
        (1, 1, "-rho/2.0*L.powi(3)*Yvdot"),
        (1, 5, "-rho/2.0*L.powi(4)*Yrdot"),
        (5, 1, "-rho/2.0*L.powi(4)*Yrdot"),
        (3, 3, "-rho/2.0*L.powi(5)*Kpdot"),
        (4, 2, "-rho/2.0*L.powi(4)*Mwdot"),
        (2, 4, "-rho/2.0*L.powi(4)*Mwdot"),
        (5, 5, "-rho/2.0*L.powi(5)*Nrdot"),
        (0, 1, "0"),
    ];
    for (i, j, book) in cases {
        let difference = &m_a[i][j] - &parse(book).unwrap();
        assert!(difference.is_zero(), "({i}, {j}): {difference}");
    }
    // The numbers: M − M_RB at L = 5.3, ρ = 1025 is npsauv.m's r3·Tinv·MA·Tinv.
    let mut values: BTreeMap<String, f64> = [
        ("M", 0.0),
        ("Ixx_G", 0.0),
        ("Iyy_G", 0.0),
        ("Izz_G", 0.0),
        ("x_G", 0.0),
        ("y_G", 0.0),
        ("z_G", 0.0),
        ("rho", 1025.0),
        ("L", 5.3),
    ]
    .iter()
    .map(|(s, v)| (s.to_string(), *v))
    .collect();
    values.extend(nps_table("added_mass"));
    let numbers = spec.mass_matrix_values(&values).unwrap();
    let r4 = 0.5 * 1025.0 * 5.3_f64.powi(4);
    // Rounding: the product is formed in another order than here.
    assert!(
        (numbers[1][5] / (-r4 * 1.2e-3) - 1.0).abs() < 1e-15,
        "{}",
        numbers[1][5]
    );
    assert_eq!(numbers[5][1], numbers[1][5]);
}

/// With U = u, `Yv` and `Yuv` are the same term; a term of three velocities would divide by
/// u and is refused, naming it.
#[test]
fn the_prime_system_refuses_what_it_cannot_scale_naming_the_term() {
    let spec = small_spec(Units::Prime, &["Yv", "Yuv"], &[]);
    match vehicle("v", &spec) {
        Err(error @ VehicleError::SameTerm(..)) => {
            assert!(error.to_string().contains("`Yv` and `Yuv`"), "{error}");
            assert!(error.to_string().contains("u·v once U = u"), "{error}");
        }
        other => panic!("{other:?}"),
    }
    // In SI the two are different terms (v and u·v).
    assert!(
        small_spec(Units::Dimensional, &["Yv", "Yuv"], &[])
            .force_terms()
            .is_ok()
    );
    for name in ["Yuvr", "Yv|v|r", "Xuuu"] {
        let spec = small_spec(Units::Prime, &[name], &[]);
        match vehicle("v", &spec) {
            Err(error @ VehicleError::Prime { .. }) => {
                assert!(error.to_string().contains(&format!("`{name}`")), "{error}");
            }
            other => panic!("{name}: {other:?}"),
        }
    }
}

#[test]
fn the_nps_auv2_builds_and_proves_with_its_jacobians_in_the_prime_system() {
    let start = std::time::Instant::now();
    let spec = nps_spec(Kinematics::Quaternion);
    let system = vehicle("nps_auv2", &spec).unwrap();
    let program = eom_codegen::emit::prove_with_jacobians(&system).unwrap();
    let source = system_source(&system).unwrap();
    syn::parse_file(&source).unwrap();
    for name in &spec.terms {
        let field = format!("pub {}: f64", name.to_lowercase());
        assert!(source.contains(&field), "{field}");
    }
    assert!(source.contains("pub rho: f64") && source.contains("pub l: f64"));
    // No signed square in the table: the fins, ε and the cross-flow drag's loads are the
    // inputs.
    assert_eq!(
        system.inputs,
        ["dr", "ds", "n", "F_x", "F_y", "F_z", "M_x", "M_y", "M_z"]
    );
    assert_eq!(spec.terms.len(), 73);
    println!(
        "NPS AUV II (prime): {} stages, rhs {:?}, proved with its Jacobians in {:?}",
        system.stages.len(),
        program.operations(&program.rhs),
        start.elapsed()
    );
}

/// The folded table in prime units: Xwq = Z_ẇ for an added mass of these entries, and
/// npsauv.m prints −0.2 against Z′_ẇ = −0.24.
#[test]
fn the_prime_folded_table_is_shown_against_its_added_mass_in_prime_units() {
    let spec = nps_spec(Kinematics::Quaternion);
    let mut values = nps_table("coefficients");
    values.extend(nps_table("added_mass"));
    let rows = folded_comparison(&spec, &values).unwrap();
    println!("{}", format_folded(&rows));
    let row = |name: &str| {
        rows.iter()
            .find(|r| r.name.as_deref() == Some(name))
            .unwrap_or_else(|| panic!("{name}"))
    };
    assert_eq!(row("Xwq").implied, -0.24);
    assert_eq!(row("Xwq").printed, Some(-0.2));
    // A term matches by its product once U = u is written out: Yr is u·r.
    assert_eq!(row("Yr").product, "u·r");
    assert!(
        (row("Yr").implied - (-7.6e-3)).abs() < 1e-15,
        "{:?}",
        row("Yr")
    );
}

/// The Jacobians of the prime-system program cannot be fooled either.
#[test]
fn single_operation_mutants_of_the_nps_auv2_s_jacobians_fail_their_check() {
    let system = vehicle("nps_auv2", &nps_spec(Kinematics::Euler)).unwrap();
    let caught = mutants::jacobian_mutants(&system, 1);
    println!(
        "NPS AUV II (Euler): {} Jacobian mutants caught of {}, over {} proved entries",
        caught.tried, caught.tried, caught.entries
    );
    assert!(caught.tried > 100, "only {}", caught.tried);
}
