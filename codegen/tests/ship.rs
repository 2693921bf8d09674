//! The ship model: 4.46 with the added mass and the hydrodynamic polynomial of a table.

mod mutants;

use eom_codegen::emit::{prove, system_source};
use eom_codegen::model::ship::{Force, ShipForm, ShipSpec, Term, Units, YawInertia, ship};
use eom_codegen::symbolic::{Expr, parse};

fn term(force: Force, [a, b, c, d]: [u8; 4]) -> Term {
    Term {
        force,
        powers: [a, b, c, d, 0],
    }
}

/// The Mariner's terms (Chislett & Strøm-Tejsen), each load's polynomial as published.
fn mariner_terms() -> Vec<Term> {
    use Force::{N, X, Y};
    let mut terms = vec![
        term(X, [1, 0, 0, 0]),
        term(X, [2, 0, 0, 0]),
        term(X, [3, 0, 0, 0]),
        term(X, [0, 2, 0, 0]),
        term(X, [0, 0, 2, 0]),
        term(X, [0, 0, 0, 2]),
        term(X, [1, 0, 0, 2]),
        term(X, [0, 1, 1, 0]),
        term(X, [0, 1, 0, 1]),
        term(X, [1, 1, 0, 1]),
    ];
    for force in [Y, N] {
        for powers in [
            [0, 1, 0, 0],
            [0, 0, 1, 0],
            [0, 3, 0, 0],
            [0, 2, 1, 0],
            [1, 1, 0, 0],
            [1, 0, 1, 0],
            [0, 0, 0, 1],
            [0, 0, 0, 3],
            [1, 0, 0, 1],
            [2, 0, 0, 1],
            [0, 1, 0, 2],
            [0, 2, 0, 1],
            [0, 0, 0, 0],
            [1, 0, 0, 0],
            [2, 0, 0, 0],
        ] {
            terms.push(term(force, powers));
        }
    }
    terms
}

#[test]
fn a_term_is_named_by_its_load_and_its_variables() {
    assert_eq!(term(Force::Y, [0, 2, 1, 0]).symbol(), "Y_vvr");
    assert_eq!(term(Force::X, [1, 0, 0, 2]).symbol(), "X_udd");
    assert_eq!(term(Force::N, [0, 0, 0, 0]).symbol(), "N_0");
}

/// The residuals are the issue's mass-matrix form, exactly: the added mass on the left, the
/// rigid-body terms of 4.46 written out, the polynomial on the right.
#[test]
fn residuals_are_the_mass_matrix_form_with_the_polynomial() {
    let spec = ShipSpec {
        units: Units::Dimensional,
        yaw_inertia: YawInertia::AboutG,
        terms: vec![
            term(Force::X, [2, 0, 0, 0]),
            term(Force::Y, [0, 1, 0, 0]),
            term(Force::Y, [0, 0, 0, 1]),
            term(Force::N, [0, 2, 1, 0]),
        ],
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    };
    let book = [
        "(M - X_udot)*u_dot - M*v*r - M*x_G*r.powi(2) - X_uu*u.powi(2)",
        "(M - Y_vdot)*v_dot + (M*x_G - Y_rdot)*r_dot + M*u*r - Y_v*v - Y_d*delta",
        "(M*x_G - N_vdot)*v_dot + (Izz + M*x_G.powi(2) - N_rdot)*r_dot + M*x_G*u*r - N_vvr*v.powi(2)*r",
    ];
    let residuals = spec.residuals().unwrap();
    for (derived, book) in residuals.iter().zip(book) {
        let difference = derived - &parse(book).unwrap();
        assert!(difference.is_zero(), "{book}: left over {difference}");
    }
}

/// With the yaw inertia about midship, I_zz + M x_G² is the given I_O itself.
#[test]
fn inertia_about_midship_enters_the_mass_matrix_as_given() {
    let spec = ShipSpec {
        units: Units::Dimensional,
        yaw_inertia: YawInertia::AboutMidship,
        terms: vec![],
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    };
    let yaw = &spec.residuals().unwrap()[2];
    let book = parse("(M*x_G - N_vdot)*v_dot + (Izz_midship - N_rdot)*r_dot + M*x_G*u*r").unwrap();
    assert!((yaw - &book).is_zero(), "left over {}", yaw - &book);
}

/// The prime system: a term Y′_vvr contributes ½ρL²U² Y′_vvr (v/U)²(rL/U), the surge
/// variable is (u − U₀)/U, and a moment carries one more L.
#[test]
fn prime_terms_scale_by_the_instantaneous_speed() {
    let spec = ShipSpec {
        units: Units::Prime,
        yaw_inertia: YawInertia::AboutMidship,
        terms: vec![term(Force::Y, [0, 2, 1, 0]), term(Force::N, [1, 0, 0, 1])],
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    };
    let y = spec.force(Force::Y).unwrap();
    let expected = parse("rho/2.0*L.powi(3)*Y_vvr*v.powi(2)*r/U").unwrap();
    assert!((&y - &expected).is_zero(), "Y: {}", &y - &expected);
    let n = spec.force(Force::N).unwrap();
    let expected = parse("rho/2.0*L.powi(3)*N_ud*(u - U0)*U*delta").unwrap();
    assert!((&n - &expected).is_zero(), "N: {}", &n - &expected);
}

#[test]
fn the_mariner_builds_proves_and_emits_only_its_terms_and_the_model_contract() {
    for units in [Units::Dimensional, Units::Prime] {
        for yaw_inertia in [YawInertia::AboutG, YawInertia::AboutMidship] {
            let spec = ShipSpec {
                units,
                yaw_inertia,
                terms: mariner_terms(),
                propulsion: false,
                form: ShipForm::Polynomial,
                current: false,
                applied: false,
            };
            let system = ship("mariner", &spec).unwrap();
            prove(&system).unwrap();
            let source = system_source(&system).unwrap();
            for t in &spec.terms {
                let field = format!("pub {}: f64", t.symbol().to_lowercase());
                assert!(source.contains(&field), "{units:?}: {field} missing");
            }
            // A term the table does not list is not in the code.
            assert!(!source.contains("y_vrr"), "{units:?}");
            // The proved Jacobians and the contract over them: the prime system's speed U is
            // an input beside the rudder rate.
            let inputs = system.inputs.len();
            let contract = format!(
                "impl<T: SimdRealField + Copy> eom_kernel::Model<T, 7, {inputs}> for Coefficients<T>"
            );
            assert!(source.contains(&contract), "{units:?}: {contract} missing");
            assert!(source.contains("pub fn state_jacobian<T"), "{units:?}");
        }
    }
}

#[test]
fn a_term_listed_twice_is_refused() {
    let spec = ShipSpec {
        units: Units::Dimensional,
        yaw_inertia: YawInertia::AboutG,
        terms: vec![term(Force::Y, [0, 1, 0, 0]), term(Force::Y, [0, 1, 0, 0])],
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    };
    let error = ship("twice", &spec).unwrap_err();
    assert!(error.to_string().contains("Y_v is listed twice"), "{error}");
}

#[test]
fn the_rudder_angle_moves_at_its_input() {
    let spec = ShipSpec {
        units: Units::Dimensional,
        yaw_inertia: YawInertia::AboutG,
        terms: vec![],
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    };
    let system = ship("bare", &spec).unwrap();
    assert_eq!(system.state[6], "delta");
    assert_eq!(system.outputs[6], Expr::symbol("delta_rate"));
}

/// The Jacobians of a ship's program, proved when the scene is read, cannot be fooled: every
/// single-operation mutant (`mutants/mod.rs`) of every node the Mariner's Jacobians read, in
/// the prime system, fails their check against the exact derivative.
#[test]
fn single_operation_mutants_of_the_mariner_s_jacobians_fail_their_check() {
    let spec = ShipSpec {
        units: Units::Prime,
        yaw_inertia: YawInertia::AboutMidship,
        terms: mariner_terms(),
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    };
    let system = ship("mariner", &spec).unwrap();
    let caught = mutants::jacobian_mutants(&system, 1);
    println!(
        "Mariner: {} Jacobian mutants caught of {}, over {} proved entries; ∂f/∂x {:?}, ∂f/∂u {:?}",
        caught.tried, caught.tried, caught.entries, caught.operations[0], caught.operations[1]
    );
    assert!(caught.tried > 100, "only {}", caught.tried);
}

fn rudder_term(force: Force, e: u8) -> Term {
    Term {
        force,
        powers: [0, 0, 0, 0, e],
    }
}

/// Abkowitz's forms, written by hand: the rudder on its inflow speed c with e = δ − (v +
/// x_R r)/c, the change of the rudder's share of Y_v and Y_r with c from c₀, the propeller's
/// bias on (u_A/2)², and the thrust law less the resistance in X.
#[test]
fn propulsion_puts_the_rudder_on_its_inflow_and_the_thrust_law_in_surge() {
    let spec = ShipSpec {
        units: Units::Prime,
        yaw_inertia: YawInertia::AboutMidship,
        terms: vec![
            rudder_term(Force::X, 2),
            term(Force::Y, [0, 0, 0, 1]),
            rudder_term(Force::Y, 3),
            term(Force::N, [0, 0, 0, 0]),
        ],
        propulsion: true,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    };
    let e = "(delta - (v + L*x_R*r)/c)";
    let x = spec.force(Force::X).unwrap();
    let expected = parse(&format!(
        "rho/2.0*L.powi(2)*(X_ee*c.powi(2)*{e}.powi(2) + (T_uu - R_uu)*u.powi(2) \
         + T_un*L*n*u + T_nn*L.powi(2)*n*n_abs)"
    ))
    .unwrap();
    assert!((&x - &expected).is_zero(), "X: {}", &x - &expected);
    let y = spec.force(Force::Y).unwrap();
    let expected = parse(&format!(
        "rho/2.0*L.powi(2)*(Y_d*(c.powi(2)*delta - (c - c0)*(v + L*x_R*r)) \
         + Y_eee*c.powi(2)*{e}.powi(3))"
    ))
    .unwrap();
    assert!((&y - &expected).is_zero(), "Y: {}", &y - &expected);
    let n = spec.force(Force::N).unwrap();
    let expected = parse("rho/2.0*L.powi(3)*N_0*(u_A/2.0).powi(2)").unwrap();
    assert!((&n - &expected).is_zero(), "N: {}", &n - &expected);
    let system = ship("abkowitz", &spec).unwrap();
    assert_eq!(
        system.inputs,
        ["delta_rate", "U", "n", "n_abs", "u_A", "c"],
        "the computed inputs beside U"
    );
    prove(&system).unwrap();
    let source = system_source(&system).unwrap();
    assert!(source.contains("pub y_eee: f64") && source.contains("pub t_nn: f64"));
}

#[test]
fn a_term_in_the_effective_rudder_angle_needs_propulsion() {
    let spec = ShipSpec {
        units: Units::Prime,
        yaw_inertia: YawInertia::AboutG,
        terms: vec![rudder_term(Force::Y, 3)],
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    };
    let error = ship("no_propeller", &spec).unwrap_err();
    assert!(
        error.to_string().contains("needs a propulsion model"),
        "{error}"
    );
    let mixed = ShipSpec {
        terms: vec![term(Force::Y, [0, 1, 0, 1])],
        propulsion: true,
        ..spec
    };
    let error = ship("mixed", &mixed).unwrap_err();
    assert!(
        error.to_string().contains("Y_vd mixes the rudder"),
        "{error}"
    );
}

/// The MMG hull's terms (Yasukawa & Yoshimura 2015): R′₀ as the bias in X, X′_vv, X′_vr,
/// X′_rr, X′_vvvv, and Y′, N′ in v, r, vvv, vvr, vrr, rrr.
fn mmg_terms() -> Vec<Term> {
    use Force::{N, X, Y};
    let mut terms = vec![
        term(X, [0, 0, 0, 0]),
        term(X, [0, 2, 0, 0]),
        term(X, [0, 1, 1, 0]),
        term(X, [0, 0, 2, 0]),
        term(X, [0, 4, 0, 0]),
    ];
    for force in [Y, N] {
        for powers in [
            [0, 1, 0, 0],
            [0, 0, 1, 0],
            [0, 3, 0, 0],
            [0, 2, 1, 0],
            [0, 1, 2, 0],
            [0, 0, 3, 0],
        ] {
            terms.push(term(force, powers));
        }
    }
    terms
}

fn mmg_spec() -> ShipSpec {
    ShipSpec {
        units: Units::Dimensional,
        yaw_inertia: YawInertia::AboutG,
        terms: mmg_terms(),
        propulsion: false,
        form: ShipForm::Mmg,
        current: false,
        applied: false,
    }
}

/// The MMG form's residuals are the paper's equations of motion at midship, written here
/// by hand: the added masses m_x, m_y, J_z on the left with their Coriolis terms, the hull's
/// polynomial in v′ = v/U and r′ = rL/U on ½ρLdU² (½ρL²dU² for N), and the applied loads.
#[test]
fn the_mmg_form_is_the_papers_equations_of_motion() {
    let spec = mmg_spec();
    let m_x = "(rho/2.0*L.powi(2)*draft*m_x)";
    let m_y = "(rho/2.0*L.powi(2)*draft*m_y)";
    let j_z = "(rho/2.0*L.powi(4)*draft*J_z)";
    let q = "(rho/2.0*L*draft*U.powi(2))";
    let (v, r) = ("(v/U)", "(r*L/U)");
    let lateral = |f: &str| {
        format!(
            "{f}_v*{v} + {f}_r*{r} + {f}_vvv*{v}.powi(3) + {f}_vvr*{v}.powi(2)*{r} \
             + {f}_vrr*{v}*{r}.powi(2) + {f}_rrr*{r}.powi(3)"
        )
    };
    let book = [
        format!(
            "(M + {m_x})*u_dot - (M + {m_y})*v*r - M*x_G*r.powi(2) - {q}*(X_0 + X_vv*{v}.powi(2) \
             + X_vr*{v}*{r} + X_rr*{r}.powi(2) + X_vvvv*{v}.powi(4)) - X_applied"
        ),
        format!(
            "(M + {m_y})*v_dot + (M + {m_x})*u*r + M*x_G*r_dot - {q}*({}) - Y_applied",
            lateral("Y")
        ),
        format!(
            "(Izz + M*x_G.powi(2) + {j_z})*r_dot + M*x_G*(v_dot + u*r) - {q}*L*({}) - N_applied",
            lateral("N")
        ),
    ];
    let residuals = spec.residuals().unwrap();
    for (derived, book) in residuals.iter().zip(&book) {
        let difference = derived - &parse(book).unwrap();
        assert!(difference.is_zero(), "{book}: left over {difference}");
    }
    reads_the_applied_loads_and_proves(&ship("kvlcc2", &spec).unwrap());
}

/// A system whose inputs are δ̇, U and the applied loads X, Y, N, and which proves.
fn reads_the_applied_loads_and_proves(system: &eom_codegen::model::System) {
    assert_eq!(
        system.inputs,
        ["delta_rate", "U", "X_applied", "Y_applied", "N_applied"]
    );
    prove(system).unwrap();
}

/// An MMG spec reads the hull's terms alone: a term in u, δ or e, a propulsion model or
/// prime units are refused with the reason.
#[test]
fn an_mmg_spec_refuses_what_is_not_the_hulls() {
    for (what, spec) in [
        (
            "in u",
            ShipSpec {
                terms: vec![term(Force::Y, [1, 1, 0, 0])],
                ..mmg_spec()
            },
        ),
        (
            "in δ",
            ShipSpec {
                terms: vec![term(Force::Y, [0, 0, 0, 1])],
                ..mmg_spec()
            },
        ),
    ] {
        let error = ship("mmg", &spec).unwrap_err().to_string();
        assert!(
            error.contains("not one of the MMG hull's"),
            "{what}: {error}"
        );
    }
    for spec in [
        ShipSpec {
            propulsion: true,
            ..mmg_spec()
        },
        ShipSpec {
            units: Units::Prime,
            ..mmg_spec()
        },
    ] {
        let error = ship("mmg", &spec).unwrap_err().to_string();
        assert!(error.contains("an MMG spec has its body in SI"), "{error}");
    }
}

/// The MMG form's Jacobians are proved like the polynomial ships': every single-operation
/// mutant of the nodes they read fails the check.
#[test]
fn single_operation_mutants_of_the_mmg_jacobians_fail_their_check() {
    let system = ship("kvlcc2", &mmg_spec()).unwrap();
    let caught = mutants::jacobian_mutants(&system, 1);
    println!(
        "KVLCC2 (MMG): {} Jacobian mutants caught, over {} proved entries; ∂f/∂x {:?}, ∂f/∂u {:?}",
        caught.tried, caught.entries, caught.operations[0], caught.operations[1]
    );
    assert!(caught.tried > 100, "only {}", caught.tried);
}

/// A current carries the track: 4.44's rows gain its north and east components, and nothing
/// else of the system changes.
#[test]
fn a_current_carries_the_track_and_nothing_else() {
    let still = ShipSpec {
        units: Units::Prime,
        yaw_inertia: YawInertia::AboutMidship,
        terms: mariner_terms(),
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    };
    let carried = ShipSpec {
        current: true,
        ..still.clone()
    };
    let (still, carried) = (
        ship("still", &still).unwrap(),
        ship("carried", &carried).unwrap(),
    );
    assert_eq!(
        carried.inputs,
        ["delta_rate", "U", "current_north", "current_east"]
    );
    for (k, (a, b)) in still.outputs.iter().zip(&carried.outputs).enumerate() {
        let difference = b - a;
        let expected = match k {
            3 => Expr::symbol("current_north"),
            4 => Expr::symbol("current_east"),
            _ => Expr::zero(),
        };
        assert!(
            (&difference - &expected).is_zero(),
            "output {k}: {difference}"
        );
    }
    prove(&carried).unwrap();
}

/// Applied loads (the wind's) enter a polynomial ship's right side as they enter an MMG
/// ship's: each of 4.46's residuals loses exactly its load, the inputs gain X, Y, N after U,
/// and the system with them proves.
#[test]
fn applied_loads_enter_a_polynomial_ship_as_its_loads() {
    let calm = ShipSpec {
        units: Units::Prime,
        yaw_inertia: YawInertia::AboutMidship,
        terms: mariner_terms(),
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    };
    let windy = ShipSpec {
        applied: true,
        ..calm.clone()
    };
    let (before, after) = (calm.residuals().unwrap(), windy.residuals().unwrap());
    for ((a, b), load) in before
        .iter()
        .zip(&after)
        .zip(["X_applied", "Y_applied", "N_applied"])
    {
        let difference = &(b - a) + &Expr::symbol(load);
        assert!(difference.is_zero(), "{load}: {difference}");
    }
    reads_the_applied_loads_and_proves(&ship("windy", &windy).unwrap());
}
