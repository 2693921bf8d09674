//! A point mass over a turning Earth: the derived equations against the textbook's written
//! by hand (J2 gravitation with its Z term's 3, the Coriolis and centripetal terms), proved with
//! their Jacobians, every single-operation mutant of the Jacobians caught.

mod mutants;

use eom_codegen::emit::prove_with_jacobians;
use eom_codegen::model::earth::point_mass;
use eom_codegen::symbolic::parse;

/// v̇ as the module docs write it, by hand: g_X = −GM x/r³ [1 + (3/2) J2 (a/r)² (1 − 5z²/r²)],
/// g_Z with (3 − 5z²/r²); −2Ω×v = (2ω v_y, −2ω v_x, 0); −Ω×(Ω×r) = (ω² x, ω² y, 0).
#[test]
fn the_equations_are_the_textbooks() {
    let system = point_mass("dropped").unwrap();
    let oblate = "3/2*J2*a_e.powi(2)*inv_r.powi(2)";
    let book = [
        "v_x".to_owned(),
        "v_y".to_owned(),
        "v_z".to_owned(),
        format!(
            "-GM*x*inv_r.powi(3)*(1 + {oblate}*(1 - 5*z.powi(2)*inv_r.powi(2))) + f_x + 2*omega_e*v_y + omega_e.powi(2)*x"
        ),
        format!(
            "-GM*y*inv_r.powi(3)*(1 + {oblate}*(1 - 5*z.powi(2)*inv_r.powi(2))) + f_y - 2*omega_e*v_x + omega_e.powi(2)*y"
        ),
        format!("-GM*z*inv_r.powi(3)*(1 + {oblate}*(3 - 5*z.powi(2)*inv_r.powi(2))) + f_z"),
    ];
    for (derived, written) in system.outputs.iter().zip(&book) {
        let difference = derived - &parse(written).unwrap();
        assert!(difference.is_zero(), "{written}: left over {difference}");
    }
}

/// The program and its Jacobians prove, and a mutant of any one operation of the Jacobians'
/// is caught by the check.
#[test]
fn the_program_proves_and_its_mutants_fail() {
    let system = point_mass("dropped").unwrap();
    prove_with_jacobians(&system).unwrap();
    let caught = mutants::jacobian_mutants(&system, 1);
    println!(
        "point mass over the Earth: {} Jacobian mutants caught, over {} proved entries",
        caught.tried, caught.entries
    );
    assert!(caught.tried > 20, "only {}", caught.tried);
}
