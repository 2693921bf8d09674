//! The builders: each family's system from the proved derivations.

use super::solve::{Solution, solve_diagonal, solve_linear};
use super::system::{BuildError, CoefficientName, Group, Parameter, Stage, System};
use super::{Kinematics, Strategy, Symmetry};
use crate::derivation::energy::{pendulum_kinetic_energy_form, rigid_body_kinetic_energy};
use crate::derivation::kinematics::{
    body_to_space, euler_rate_matrix, rotation_x, rotation_y, rotation_z,
};
use crate::derivation::quaternion::{
    Quaternion, body_to_space_half_angles, quaternion_of_euler_angles, quaternion_rates,
};
use crate::derivation::{pendulum as pendulum_eq, planar, spatial as spatial_eq, top as top_eq};
use crate::symbolic::{Expr, SymbolicError, Vec3};
use std::borrow::Cow;

const MASS: Parameter = Parameter {
    symbol: Cow::Borrowed("M"),
    doc: Cow::Borrowed("mass M"),
};
const IZZ: Parameter = Parameter {
    symbol: Cow::Borrowed("Izz"),
    doc: Cow::Borrowed("moment of inertia I_zz about G (4.13)"),
};

fn symbolic(model: &str) -> impl Fn(SymbolicError) -> BuildError + '_ {
    move |source| BuildError::Symbolic {
        model: model.into(),
        source,
    }
}

fn symbols(names: &[&str]) -> Vec<Expr> {
    names.iter().map(|n| Expr::symbol(n)).collect()
}

fn solved(solution: &Solution) -> Vec<Expr> {
    solution.accelerations(&solution.rest)
}

/// Checks that the staged program composes back to the proved outputs, for the listed
/// output indices.
pub(super) fn verify_outputs(
    system: &System,
    expected: &[(usize, Expr)],
) -> Result<(), BuildError> {
    for (index, wanted) in expected {
        let computed = system
            .expanded_output(*index)
            .map_err(symbolic(&system.name))?;
        let residual = &computed - wanted;
        let state = system.state[*index];
        if !residual.is_zero() {
            return Err(BuildError::Verification {
                model: system.name.clone(),
                what: format!("the staged rate of {state} differs from the proved form"),
                residual: residual.to_string(),
            });
        }
    }
    Ok(())
}

/// Compound pendulum: 4.24 with an applied moment M_O about the pivot.
pub fn pendulum() -> Result<System, BuildError> {
    let name = "pendulum";
    let residual = pendulum_eq::residual() - Expr::symbol("M_O");
    let solution = solve_linear(name, &[residual], &["theta_ddot"], "inv_det")?;
    Ok(System {
        name: name.into(),
        title: "Compound pendulum about a fixed horizontal axis".into(),
        equations: vec!["4.24"],
        parameters: vec![
            Parameter {
                symbol: Cow::Borrowed("I0"),
                doc: Cow::Borrowed("moment of inertia I₀ about the pivot"),
            },
            MASS,
            Parameter {
                symbol: Cow::Borrowed("g"),
                doc: Cow::Borrowed("gravitational acceleration g"),
            },
            Parameter {
                symbol: Cow::Borrowed("h"),
                doc: Cow::Borrowed("distance h from the pivot to G"),
            },
        ],
        reciprocals: vec![],
        state: vec!["theta", "theta_dot"],
        inputs: vec!["M_O"],
        stages: vec![],
        outputs: vec![Expr::symbol("theta_dot"), solved(&solution)[0].clone()],
        groups: vec![Group {
            first: 0,
            comment: "4.24: I₀θ̈ = −Mgh sin θ + M_O".into(),
        }],
        kinetic_energy: Some(pendulum_kinetic_energy_form().map_err(symbolic(name))?),
        energy_formula: Some("T = ½I₀θ̇² (4.34)"),
        potential_energy: Some(pendulum_eq::potential_energy()),
        potential_formula: Some(
            "V = −Mg·r_G = −Mgh cos θ (4.35), zero with G level with the pivot; 4.34's \
             U = Mgh(1 − cos θ) is V + Mgh",
        ),
        coefficient_names: vec![],
    })
}

/// (Ẋ, Ẏ) = Rz(ψ)(u, v) (4.44).
fn track() -> [Expr; 2] {
    let velocity = Vec3::new(Expr::symbol("u"), Expr::symbol("v"), Expr::zero());
    let [x, y, _] = rotation_z("psi").mul_vec(&velocity).0;
    [x, y]
}

/// T = ½M(u_G² + v_G²) + ½I_zz r²: 4.32 in the plane, with the velocity of G given.
fn planar_kinetic_energy(name: &str, u_g: Expr, v_g: Expr, r: Expr) -> Result<Expr, BuildError> {
    let in_plane = [
        ("w", Expr::zero()),
        ("p", Expr::zero()),
        ("q", Expr::zero()),
        ("u", u_g),
        ("v", v_g),
        ("r", r),
    ];
    rigid_body_kinetic_energy()
        .and_then(|t| t.subs_all(&in_plane))
        .map_err(symbolic(name))
}

/// What differs between the two body-fixed planar models: the equation, and where G is.
struct BodyFixed<'a> {
    name: &'a str,
    title: &'a str,
    equations: Vec<&'static str>,
    parameters: Vec<Parameter>,
    dynamics: &'static str,
    kinetic_energy: Expr,
    energy_formula: &'static str,
}

fn planar_body_fixed(model: BodyFixed, residuals: &[Expr; 3]) -> Result<System, BuildError> {
    let BodyFixed {
        name,
        title,
        equations,
        parameters,
        dynamics,
        kinetic_energy,
        energy_formula,
    } = model;
    let solution = solve_linear(name, residuals, &["u_dot", "v_dot", "r_dot"], "inv_det")?;
    let mut outputs = solved(&solution);
    outputs.extend(track());
    outputs.push(Expr::symbol("r"));
    Ok(System {
        name: name.into(),
        title: title.into(),
        equations,
        parameters,
        reciprocals: solution.reciprocals.clone(),
        state: vec!["u", "v", "r", "X", "Y", "psi"],
        inputs: vec!["F_x", "F_y", "M_z"],
        stages: vec![],
        outputs,
        groups: vec![
            Group {
                first: 0,
                comment: dynamics.into(),
            },
            Group {
                first: 3,
                comment: "4.44: the track in space-fixed axes, and the heading".into(),
            },
        ],
        kinetic_energy: Some(kinetic_energy),
        energy_formula: Some(energy_formula),
        potential_energy: None,
        potential_formula: None,
        coefficient_names: inverse_names(&solution, "inv_mass_matrix", "M", &["u", "v", "r"]),
    })
}

/// Planar, body-fixed axes at G: 4.43 with the track 4.44.
pub fn planar_at_g() -> Result<System, BuildError> {
    let name = "planar_at_g";
    let residuals = planar::residuals_at_g().map_err(symbolic(name))?;
    let [u, v, r] = ["u", "v", "r"].map(Expr::symbol);
    let model = BodyFixed {
        name,
        title: "Planar motion in body axes at G",
        equations: vec!["4.43", "4.44"],
        parameters: vec![MASS, IZZ],
        dynamics: "4.43: surge, sway and yaw at G, body axes",
        kinetic_energy: planar_kinetic_energy(name, u, v, r)?,
        energy_formula: "T = ½M(u² + v²) + ½I_zz r²",
    };
    planar_body_fixed(model, &residuals)
}

/// Planar, body-fixed axes at midship with G at (x_G, 0, 0): 4.46 with 4.44.
pub fn planar_midship() -> Result<System, BuildError> {
    let name = "planar_midship";
    let at_g = planar::residuals_at_g().map_err(symbolic(name))?;
    let residuals = planar::residuals_at_midship(&at_g).map_err(symbolic(name))?;
    let x_g = Parameter {
        symbol: Cow::Borrowed("x_G"),
        doc: Cow::Borrowed("x_G, the position of G ahead of midship (4.45)"),
    };
    let [u, v, r] = ["u", "v", "r"].map(Expr::symbol);
    // 4.45: G moves with the midship velocity plus ω × r_G = (0, x_G r, 0).
    let v_g = &v + &(&Expr::symbol("x_G") * &r);
    let model = BodyFixed {
        name,
        title: "Planar motion in body axes at midship",
        equations: vec!["4.45", "4.46", "4.44"],
        parameters: vec![MASS, IZZ, x_g],
        dynamics: "4.46: surge, sway and yaw at midship, body axes",
        kinetic_energy: planar_kinetic_energy(name, u, v_g, r)?,
        energy_formula: "T = ½M(u² + (v + x_G r)²) + ½I_zz r², G moving at (u, v + x_G r)",
    };
    planar_body_fixed(model, &residuals)
}

/// Planar, space-fixed axes: 4.39.
pub fn planar_space_fixed() -> Result<System, BuildError> {
    let name = "planar_space_fixed";
    let residuals = planar::space_fixed_residuals().map_err(symbolic(name))?;
    let solution = solve_linear(name, &residuals, &["X_ddot", "Y_ddot", "r_dot"], "inv_det")?;
    let mut outputs = symbols(&["X_dot", "Y_dot", "psi_dot"]);
    outputs.extend(solved(&solution));
    Ok(System {
        name: name.into(),
        title: "Planar motion in space-fixed axes".into(),
        equations: vec!["4.39"],
        parameters: vec![MASS, IZZ],
        reciprocals: vec![],
        state: vec!["X", "Y", "psi", "X_dot", "Y_dot", "psi_dot"],
        inputs: vec!["F_X", "F_Y", "M_z"],
        stages: vec![],
        outputs,
        groups: vec![
            Group {
                first: 0,
                comment: "the position and the heading".into(),
            },
            Group {
                first: 3,
                comment: "4.39: Newton's and Euler's equations in space-fixed axes".into(),
            },
        ],
        kinetic_energy: Some(planar_kinetic_energy(
            name,
            Expr::symbol("X_dot"),
            Expr::symbol("Y_dot"),
            Expr::symbol("psi_dot"),
        )?),
        energy_formula: Some("T = ½M(Ẋ² + Ẏ²) + ½I_zz ψ̇²"),
        potential_energy: None,
        potential_formula: None,
        coefficient_names: vec![],
    })
}

fn inertia_parameters(symmetry: Symmetry) -> Vec<Parameter> {
    let mut parameters = vec![
        MASS,
        Parameter {
            symbol: Cow::Borrowed("Ixx"),
            doc: Cow::Borrowed("moment of inertia I_xx about G (4.13)"),
        },
        Parameter {
            symbol: Cow::Borrowed("Iyy"),
            doc: Cow::Borrowed("moment of inertia I_yy about G (4.13)"),
        },
        IZZ,
    ];
    let products = [
        Parameter {
            symbol: Cow::Borrowed("Ixy"),
            doc: Cow::Borrowed("product of inertia I_xy = −∫xy dm (4.14)"),
        },
        Parameter {
            symbol: Cow::Borrowed("Iyz"),
            doc: Cow::Borrowed("product of inertia I_yz = −∫yz dm (4.14)"),
        },
        Parameter {
            symbol: Cow::Borrowed("Ixz"),
            doc: Cow::Borrowed("product of inertia I_xz = −∫zx dm (4.14)"),
        },
    ];
    parameters.extend(
        products
            .into_iter()
            .filter(|p| !symmetry.pruned().contains(&&*p.symbol)),
    );
    parameters
}

/// The rotational part: stages and the three angular accelerations, by strategy.
fn rotation(
    name: &str,
    symmetry: Symmetry,
    strategy: Strategy,
) -> Result<(Vec<Stage>, Vec<Expr>, Solution), BuildError> {
    let err = symbolic(name);
    let products = symmetry.pruned();
    let lhs = spatial_eq::euler_equations().map_err(&err)?;
    let lhs = spatial_eq::without_products(&lhs, products).map_err(&err)?;
    let moments = Vec3::symbols(["M_x", "M_y", "M_z"]);
    let residuals: Vec<Expr> = (0..3).map(|i| &lhs.0[i] - &moments.0[i]).collect();
    let solution = solve_linear(name, &residuals, &["p_dot", "q_dot", "r_dot"], "inv_det")?;
    let (stages, rest) = match strategy {
        Strategy::Expanded => (vec![], solution.rest.clone()),
        Strategy::StagedBias => stage_all(&["b_x", "b_y", "b_z"], &solution.rest),
        Strategy::StagedMomentum => momentum_stages(name, products)?,
    };
    let accelerations = solution.accelerations(&rest);
    Ok((stages, accelerations, solution))
}

fn stage_all(names: &[&str], values: &[Expr]) -> (Vec<Stage>, Vec<Expr>) {
    let stages = names
        .iter()
        .zip(values)
        .map(|(n, v)| (n.to_string(), v.clone()))
        .collect();
    (stages, symbols(names))
}

/// H = [I]ω, then ω × H − M: the structure of 4.50.
fn momentum_stages(name: &str, products: &[&str]) -> Result<(Vec<Stage>, Vec<Expr>), BuildError> {
    let zeros: Vec<(&str, Expr)> = products.iter().map(|p| (*p, Expr::zero())).collect();
    let tensor = spatial_eq::inertia_tensor();
    let omega = Vec3::symbols(["p", "q", "r"]);
    let h = tensor
        .mul_vec(&omega)
        .try_map(|e| e.subs_all(&zeros))
        .map_err(symbolic(name))?;
    let (mut stages, h_symbols) = stage_all(&["H_x", "H_y", "H_z"], &h.0);
    let h_vec = Vec3(h_symbols.try_into().expect("three components"));
    let moments = Vec3::symbols(["M_x", "M_y", "M_z"]);
    let bias = omega.cross(&h_vec).sub(&moments);
    let (bias_stages, rest) = stage_all(&["b_x", "b_y", "b_z"], &bias.0);
    stages.extend(bias_stages);
    Ok((stages, rest))
}

/// Euler-angle kinematics: the track E·v (4.57), then the rates (4.60).
pub(super) fn euler_kinematics() -> (Vec<Stage>, Vec<Expr>) {
    let (mut stages, mut outputs) = euler_track();
    let (rate_stages, rates) = euler_rates();
    stages.extend(rate_stages);
    outputs.extend(rates);
    (stages, outputs)
}

/// The track E·v (4.57), turned one elementary rotation at a time, Rz(ψ)(Ry(θ)(Rx(φ) v)):
/// 12 multiplications, where forming the nine entries of E and then E·v takes 24.
fn euler_track() -> (Vec<Stage>, Vec<Expr>) {
    let mut stages: Vec<Stage> = Vec::new();
    let u = Expr::symbol("u");
    let rolled = rotation_x("phi").mul_vec(&Vec3::symbols(["u", "v", "w"]));
    stages.push(("rolled_y".into(), rolled.0[1].clone()));
    stages.push(("rolled_z".into(), rolled.0[2].clone()));
    let rolled = Vec3([u, Expr::symbol("rolled_y"), Expr::symbol("rolled_z")]);
    let pitched = rotation_y("theta").mul_vec(&rolled);
    stages.push(("pitched_x".into(), pitched.0[0].clone()));
    stages.push(("pitched_z".into(), pitched.0[2].clone()));
    let pitched = Vec3::symbols(["pitched_x", "rolled_y", "pitched_z"]);
    (stages, rotation_z("psi").mul_vec(&pitched).0.to_vec())
}

/// The Euler-angle rates (4.60), through ω in the frame before the roll, ω₃ = Rx(φ)ω:
/// θ̇ = ω₃y, ψ̇ = ω₃z sec θ and φ̇ = p + ψ̇ sin θ (= p + ω₃z tan θ, sharing the product).
fn euler_rates() -> (Vec<Stage>, Vec<Expr>) {
    let mut stages: Vec<Stage> = Vec::new();
    let mut outputs = Vec::new();
    let (q, r) = (Expr::symbol("q"), Expr::symbol("r"));
    let (s, c) = (Expr::sin("phi"), Expr::cos("phi"));
    stages.push(("omega3_y".into(), &q * &c - &r * &s));
    stages.push(("omega3_z".into(), &q * &s + &r * &c));
    stages.push((
        "heading_rate".into(),
        Expr::symbol("omega3_z") * Expr::sec("theta"),
    ));
    let heading_rate = Expr::symbol("heading_rate");
    outputs.push(Expr::symbol("p") + &heading_rate * &Expr::sin("theta"));
    outputs.push(Expr::symbol("omega3_y"));
    outputs.push(heading_rate);
    (stages, outputs)
}

pub(super) fn euler_kinematics_expected(name: &str) -> Result<Vec<Expr>, BuildError> {
    let v = Vec3::symbols(["u", "v", "w"]);
    let mut expected = body_to_space().mul_vec(&v).0.to_vec();
    expected.extend(euler_rates_expected(name)?);
    Ok(expected)
}

/// The Euler-angle rates as 4.60 gives them: the inverse of 4.59 times ω.
fn euler_rates_expected(name: &str) -> Result<Vec<Expr>, BuildError> {
    let inverse = euler_rate_matrix().inverse().map_err(symbolic(name))?;
    Ok(inverse.mul_vec(&Vec3::symbols(["p", "q", "r"])).0.to_vec())
}

/// Quaternion kinematics: v + 2(q₀t + q_v × t)/|q|² with t = q_v × v — the sandwich
/// q ⊗ (0, v) ⊗ q* / |q|², exact for a quaternion of any length, so a drifting integrator does
/// not scale the track — and q̇ = ½ q ⊗ (0, ω) with the half rates staged.
pub(super) fn quaternion_kinematics(name: &str) -> Result<(Vec<Stage>, Vec<Expr>), BuildError> {
    let q_v = Vec3::symbols(["q1", "q2", "q3"]);
    let v = Vec3::symbols(["u", "v", "w"]);
    let (mut stages, t) = stage_all(&["t_x", "t_y", "t_z"], &q_v.cross(&v).0);
    let t = Vec3(t.try_into().expect("three components"));
    let s = t.scale(&Expr::symbol("q0")).add(&q_v.cross(&t));
    let (s_stages, s) = stage_all(&["s_x", "s_y", "s_z"], &s.0);
    stages.extend(s_stages);
    let q = Quaternion::symbols();
    stages.push(("norm2".into(), q.0.iter().map(|c| c * c).sum()));
    let inverse_norm2 = Expr::symbol("norm2").pow(-1).map_err(symbolic(name))?;
    stages.push(("two_over_norm2".into(), &Expr::int(2) * &inverse_norm2));
    let scale = Expr::symbol("two_over_norm2");
    let mut outputs: Vec<Expr> = (0..3).map(|i| &v.0[i] + &(&scale * &s[i])).collect();
    let (rate_stages, rates) = quaternion_attitude_rates(name)?;
    stages.extend(rate_stages);
    outputs.extend(rates);
    Ok((stages, outputs))
}

/// q̇ = ½ q ⊗ (0, ω), with the half rates staged.
fn quaternion_attitude_rates(name: &str) -> Result<(Vec<Stage>, Vec<Expr>), BuildError> {
    let half = crate::symbolic::parse("1/2").map_err(symbolic(name))?;
    let (stages, half_rates) = stage_all(
        &["p_half", "q_half", "r_half"],
        &Vec3::symbols(["p", "q", "r"]).scale(&half).0,
    );
    let product = Quaternion::symbols().times(&Quaternion::pure(&Vec3(
        half_rates.try_into().expect("three components"),
    )));
    Ok((stages, product.0.to_vec()))
}

/// The quaternion position rate equals E·v for every unit quaternion: both sides are
/// evaluated at q(φ, θ, ψ) in half angles, where |q| = 1 holds identically.
pub(super) fn verify_quaternion_position(system: &System) -> Result<(), BuildError> {
    let err = symbolic(&system.name);
    let q = quaternion_of_euler_angles();
    let at_euler: Vec<(&str, Expr)> = ["q0", "q1", "q2", "q3"].into_iter().zip(q.0).collect();
    let expanded = system
        .substituted(&at_euler)
        .map_err(&err)?
        .expanded_outputs()
        .map_err(&err)?;
    let e_v = body_to_space_half_angles().mul_vec(&Vec3::symbols(["u", "v", "w"]));
    for i in 0..3 {
        let residual = &expanded[6 + i] - &e_v.0[i];
        if !residual.is_zero() {
            return Err(BuildError::Verification {
                model: system.name.clone(),
                what: "the quaternion position rate differs from E·v".into(),
                residual: residual.to_string(),
            });
        }
    }
    Ok(())
}

/// Spatial 6-DOF: 4.49 and 4.51 (pruned by symmetry), with Euler or quaternion kinematics.
pub fn spatial(
    symmetry: Symmetry,
    kinematics: Kinematics,
    strategy: Strategy,
) -> Result<System, BuildError> {
    let model = super::Model::Spatial {
        symmetry,
        kinematics,
    };
    let name = model.name();
    let err = symbolic(&name);
    let forces = Vec3::symbols(["F_x", "F_y", "F_z"]);
    let translation = spatial_eq::translation().sub(&forces);
    let solution = solve_linear(
        &name,
        &translation.0,
        &["u_dot", "v_dot", "w_dot"],
        "inv_mass_det",
    )?;
    let mut outputs = solved(&solution);
    let (mut stages, angular, rotation_solution) = rotation(&name, symmetry, strategy)?;
    outputs.extend(angular);
    let mut expected = solved(&solution);
    expected.extend(solved(&rotation_solution));
    let (kinematic_stages, kinematic_outputs, equations, state) = match kinematics {
        Kinematics::Euler => {
            let (s, o) = euler_kinematics();
            expected.extend(euler_kinematics_expected(&name)?);
            (
                s,
                o,
                vec!["4.49", "4.51", "4.57", "4.60"],
                vec!["phi", "theta", "psi"],
            )
        }
        Kinematics::Quaternion => {
            let (s, o) = quaternion_kinematics(&name)?;
            (
                s,
                o,
                vec!["4.49", "4.51", "4.57 q", "4.60 q"],
                vec!["q0", "q1", "q2", "q3"],
            )
        }
    };
    stages.extend(kinematic_stages);
    outputs.extend(kinematic_outputs);
    let mut all_state = vec!["u", "v", "w", "p", "q", "r", "x", "y", "z"];
    all_state.extend(state);
    let zeros: Vec<(&str, Expr)> = symmetry
        .pruned()
        .iter()
        .map(|p| (*p, Expr::zero()))
        .collect();
    let kinetic_energy = rigid_body_kinetic_energy()
        .and_then(|t| t.subs_all(&zeros))
        .map_err(&err)?;
    let system = System {
        name: name.clone(),
        title: format!("Spatial 6-DOF motion, {symmetry:?} inertia, {kinematics:?} kinematics"),
        equations,
        parameters: inertia_parameters(symmetry),
        reciprocals: rotation_solution.reciprocals.clone(),
        state: all_state,
        inputs: vec!["F_x", "F_y", "F_z", "M_x", "M_y", "M_z"],
        stages,
        outputs,
        groups: spatial_groups(symmetry, kinematics),
        kinetic_energy: Some(kinetic_energy),
        energy_formula: Some("T = ½M(u² + v² + w²) + ½ωᵀ[I]ω"),
        potential_energy: None,
        potential_formula: None,
        coefficient_names: inverse_names(&rotation_solution, "inv_inertia", "I", &["x", "y", "z"]),
    };
    let mut checks: Vec<(usize, Expr)> = expected.into_iter().enumerate().collect();
    if kinematics == Kinematics::Quaternion {
        let rates = quaternion_rates().map_err(&err)?;
        checks.extend((9..13).zip(rates.0));
        verify_quaternion_position(&system)?;
    }
    verify_outputs(&system, &checks)?;
    Ok(system)
}

/// The top's parameters: the body about G in principal axes, where G is, and gravity.
fn top_parameters() -> Vec<Parameter> {
    vec![
        MASS,
        Parameter {
            symbol: Cow::Borrowed("Ixx"),
            doc: Cow::Borrowed("principal moment of inertia I_xx about G (4.13)"),
        },
        Parameter {
            symbol: Cow::Borrowed("Iyy"),
            doc: Cow::Borrowed("principal moment of inertia I_yy about G (4.13)"),
        },
        Parameter {
            symbol: Cow::Borrowed("Izz"),
            doc: Cow::Borrowed(
                "principal moment of inertia I_zz about G, about the body z-axis through the \
                  pivot and G (4.13)",
            ),
        },
        Parameter {
            symbol: Cow::Borrowed("h"),
            doc: Cow::Borrowed("distance h from the pivot to G along the body z-axis"),
        },
        Parameter {
            symbol: Cow::Borrowed("g"),
            doc: Cow::Borrowed("gravitational acceleration g, along −Z in space axes"),
        },
    ]
}

/// The heavy top about a fixed point: 4.50 about the pivot with I_O by Steiner (4.23) under
/// the weight's moment r_G × Mg (`derivation::top`), solved for ṗ, q̇, ṙ (I_O is constant and
/// diagonal), with Euler-angle rates (4.60, staged as in [`spatial`]) or q̇ = ½ q ⊗ (0, ω).
pub fn top(kinematics: Kinematics) -> Result<System, BuildError> {
    let model = super::Model::Top { kinematics };
    let name = model.name();
    let err = symbolic(&name);
    let euler = kinematics == Kinematics::Euler;
    let rotation = top_eq::rotation(euler);
    let lhs = top_eq::euler_equations(&rotation).map_err(&err)?;
    let moments = Vec3::symbols(["M_x", "M_y", "M_z"]);
    let residuals: Vec<Expr> = (0..3).map(|i| &lhs.0[i] - &moments.0[i]).collect();
    let solution = solve_diagonal(
        &name,
        &residuals,
        &["p_dot", "q_dot", "r_dot"],
        &["inv_Ixx_O", "inv_Iyy_O", "inv_Izz_O"],
    )?;
    let mut outputs = solved(&solution);
    let mut expected = solved(&solution);
    let (stages, attitude_rates, equations, attitude, title, comment) = match kinematics {
        Kinematics::Euler => {
            let (stages, rates) = euler_rates();
            expected.extend(euler_rates_expected(&name)?);
            (
                stages,
                rates,
                vec!["4.23 top", "4.50 top", "4.60"],
                vec!["phi", "theta", "psi"],
                "Heavy top about a fixed point, Euler-angle kinematics",
                "4.60: the Euler-angle rates",
            )
        }
        Kinematics::Quaternion => {
            let (stages, rates) = quaternion_attitude_rates(&name)?;
            expected.extend(quaternion_rates().map_err(&err)?.0);
            (
                stages,
                rates,
                vec!["4.23 top", "4.50 top q", "4.60 q"],
                vec!["q0", "q1", "q2", "q3"],
                "Heavy top about a fixed point, quaternion kinematics",
                "4.60 by the quaternion: q̇ = ½ q ⊗ (0, ω)",
            )
        }
    };
    outputs.extend(attitude_rates);
    let mut state = vec!["p", "q", "r"];
    state.extend(attitude);
    let potential_formula = if euler {
        "V = −Mg·E r_G = Mgh cos φ cos θ: Mg times the height of G above the pivot"
    } else {
        "V = −Mg·R(q) r_G = Mgh(q0² − q1² − q2² + q3²): Mg times the height of G above the \
         pivot, times |q|² as the weight is"
    };
    let system = System {
        name: name.clone(),
        title: title.into(),
        equations,
        parameters: top_parameters(),
        reciprocals: solution.reciprocals.clone(),
        state,
        inputs: vec!["M_x", "M_y", "M_z"],
        stages,
        outputs,
        groups: vec![
            Group {
                first: 0,
                comment: "4.50 about the pivot, I_O by Steiner (4.23): Euler's equations under \
                          the weight's moment r_G × Mg, body axes"
                    .into(),
            },
            Group {
                first: 3,
                comment: comment.into(),
            },
        ],
        kinetic_energy: Some(top_eq::kinetic_energy().map_err(&err)?),
        energy_formula: Some(
            "T = ½M|ω × r_G|² + ½ωᵀ[I_G]ω = ½ωᵀ[I_O]ω, I_O = diag(I_xx + Mh², I_yy + Mh², I_zz)",
        ),
        potential_energy: Some(top_eq::potential_energy(&rotation)),
        potential_formula: Some(potential_formula),
        coefficient_names: inverse_names(&solution, "inv_inertia", "I_O", &["x", "y", "z"]),
    };
    let checks: Vec<(usize, Expr)> = expected.into_iter().enumerate().collect();
    verify_outputs(&system, &checks)?;
    Ok(system)
}

fn spatial_groups(symmetry: Symmetry, kinematics: Kinematics) -> Vec<Group> {
    let rotation = match symmetry.pruned() {
        [] => "4.51: Euler's equations with all products of inertia".to_owned(),
        ["Ixy", "Iyz", "Ixz"] => "4.52: Euler's equations in principal axes".to_owned(),
        pruned => format!("4.51 with {} = 0: Euler's equations", pruned.join(" = ")),
    };
    let (position, attitude) = match kinematics {
        Kinematics::Euler => (
            "4.57: the position rates in space axes, E·v one rotation at a time",
            "4.60: the Euler-angle rates",
        ),
        Kinematics::Quaternion => (
            "4.57 by the quaternion: v + 2(q₀t + q_v × t)/|q|², t = q_v × v",
            "4.60 by the quaternion: q̇ = ½ q ⊗ (0, ω)",
        ),
    };
    vec![
        Group {
            first: 0,
            comment: "4.49: translation about G, body axes".into(),
        },
        Group {
            first: 3,
            comment: rotation,
        },
        Group {
            first: 6,
            comment: position.into(),
        },
        Group {
            first: 9,
            comment: attitude.into(),
        },
    ]
}

/// The entries of a solved system's inverse matrix, named `{prefix}_{row}{column}`: each
/// non-zero entry once, an entry below the diagonal only where it differs from its mirror
/// above (a symmetric inverse names its upper triangle; a ship's, with Y_ṙ ≠ N_v̇, all four).
pub(super) fn inverse_names(
    solution: &Solution,
    prefix: &str,
    matrix: &str,
    axes: &[&str],
) -> Vec<CoefficientName> {
    let inverse = &solution.inverse;
    let mut names = Vec::new();
    for (i, row) in inverse.iter().enumerate() {
        for (j, value) in row.iter().enumerate() {
            if value.is_zero() || (j < i && *value == inverse[j][i]) {
                continue;
            }
            names.push(CoefficientName {
                value: value.clone(),
                name: format!("{prefix}_{}{}", axes[i], axes[j]),
                description: format!(
                    "The entry `([{matrix}]⁻¹)_{}{}` (up to sign)",
                    axes[i], axes[j]
                ),
            });
        }
    }
    names
}
