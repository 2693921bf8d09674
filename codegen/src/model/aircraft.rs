//! Aircraft in six degrees of freedom about their centre of gravity, on coefficients that a
//! table (or a stability-derivative polynomial) gives beside the proved program.
//!
//! The chapter writes its six equations "for aircraft and underwater robots"; an aircraft's
//! loads are not a polynomial of its velocities but coefficients looked up in the angle of
//! attack, the sideslip and the controls, multiplied by the dynamic pressure. What is
//! derived and proved here is everything but the lookups:
//!
//! - the rigid body about G (4.49 and 4.51 with the product I_xz of a body symmetric about
//!   its xz-plane), with a rotor's angular momentum h_E along body x: 4.50 with
//!   H = \[I\]ω + h_E e_x, so that \[I\]ω̇ + ω × (\[I\]ω + h_E e_x) = M. The tensor is inverted
//!   symbolically, its determinant's reciprocal computed once per parameter set: the
//!   constants c₁ … c₉ of flight-dynamics texts are these entries, derived rather than typed in;
//! - the loads: the weight M g along k_b = Rᵀ(0, 0, 1) (Z down), the thrust T along body x
//!   through G, and the aerodynamic build-up q̄S·C_X, q̄S·C_Y, q̄S·C_Z, q̄Sb·C_l, q̄Sc̄·C_m,
//!   q̄Sb·C_n with q̄ = ½ρV², where each coefficient is its static value (an input) plus the
//!   damping terms through the non-dimensional rates pb/2V, qc̄/2V, rb/2V (their derivatives
//!   inputs too), and the moment carried from the aerodynamic reference point r_ref (from G,
//!   body axes) to G: M_G = M_ref + r_ref × F_aero, derived by the cross product;
//! - the wind-axis state (V, α, β) of u = V cos α cos β, v = V sin β, w = V sin α cos β: the
//!   rates are V̇ = e_V·ν̇, α̇ = (cos α ẇ − sin α u̇)/(V cos β) and
//!   β̇ = (cos β v̇ − sin β (cos α u̇ + sin α ẇ))/V, and the proof is the chain rule: the time
//!   derivative of (u, v, w) through (V, α, β) at these rates equals the solved 4.49, exactly;
//! - flat-Earth navigation (4.57: north, east, and altitude = −z) and the attitude's rates,
//!   as the catalog derives them: the Euler angles' (4.60), singular at θ = ±90°, or a unit
//!   quaternion's, q̇ = ½ q ⊗ (0, ω) ([`aircraft_with`]), for a loop or a vertical climb;
//! - the engine's power as a first-order lag, ṗ = k (p_c − p), its target p_c and gain k
//!   inputs (a source's piecewise law computes them beside the program).
//!
//! Inputs: the six static coefficients, the nine damping derivatives, ρ, T, p_c and k. Their
//! derivatives in the state and the controls are the caller's (a table's segment slope), so
//! the model's Jacobians are the proved ∂f/∂x and ∂f/∂(input) composed by the chain rule.

use super::Kinematics;
use super::families::{
    euler_kinematics, euler_kinematics_expected, quaternion_kinematics, verify_outputs,
};
use super::solve::{Solution, solve_linear};
use super::system::{BuildError, CoefficientName, Group, Parameter, Stage, System};
use crate::derivation::kinematics::body_to_space;
use crate::derivation::quaternion::{
    Quaternion, body_to_space_half_angles, quaternion_of_euler_angles, quaternion_rates,
    rotation_matrix,
};
use crate::derivation::spatial::{euler_equations, translation, without_products};
use crate::symbolic::{Expr, SymbolicError, Vec3, parse};
use std::borrow::Cow;

/// The state: airspeed V (`vt`), angle of attack, sideslip, the Euler angles, the body rates,
/// north, east, altitude and the engine's power.
pub const STATE: [&str; 13] = [
    "vt", "alpha", "beta", "phi", "theta", "psi", "p", "q", "r", "north", "east", "altitude",
    "power",
];

/// The state of [`Kinematics::Quaternion`]: the attitude a unit quaternion (scalar first) in
/// the Euler angles' place.
pub const QUATERNION_STATE: [&str; 14] = [
    "vt", "alpha", "beta", "q0", "q1", "q2", "q3", "p", "q", "r", "north", "east", "altitude",
    "power",
];

/// The static coefficients, each the source's value at the state and controls (no rates).
pub const COEFFICIENTS: [&str; 6] = ["C_X", "C_Y", "C_Z", "C_l", "C_m", "C_n"];

/// The damping derivatives, per radian of non-dimensional rate (q c̄/2V for `C_Xq`, `C_Zq`,
/// `C_mq`; p b/2V and r b/2V for the others).
pub const DAMPING: [&str; 9] = [
    "C_Xq", "C_Yr", "C_Yp", "C_Zq", "C_lr", "C_lp", "C_mq", "C_nr", "C_np",
];

/// The air's density, the thrust, and the power lag's target and gain.
pub const ENGINE_AND_AIR: [&str; 4] = ["rho", "thrust", "power_command", "power_gain"];

/// Every input of the program, in order: the coefficients, the damping derivatives, then
/// [`ENGINE_AND_AIR`].
pub fn inputs() -> Vec<&'static str> {
    COEFFICIENTS
        .iter()
        .chain(&DAMPING)
        .chain(&ENGINE_AND_AIR)
        .copied()
        .collect()
}

/// The parameters in order, with what each is.
pub const PARAMETERS: [(&str, &str); 13] = [
    ("M", "mass M"),
    ("Ixx", "moment of inertia I_xx about G (4.13)"),
    ("Iyy", "moment of inertia I_yy about G (4.13)"),
    ("Izz", "moment of inertia I_zz about G (4.13)"),
    ("Ixz", "product of inertia I_xz = −∫zx dm about G (4.14)"),
    (
        "g",
        "gravitational acceleration g, along +Z (down) in space axes",
    ),
    ("S", "wing reference area S"),
    ("b", "wing span b"),
    ("cbar", "mean aerodynamic chord c̄"),
    (
        "x_ref",
        "x of the aerodynamic reference point from G, body axes",
    ),
    (
        "y_ref",
        "y of the aerodynamic reference point from G, body axes",
    ),
    (
        "z_ref",
        "z of the aerodynamic reference point from G, body axes",
    ),
    ("h_E", "the engine rotor's angular momentum along body x"),
];

fn symbolic(model: &str) -> impl Fn(SymbolicError) -> BuildError + '_ {
    move |source| BuildError::Symbolic {
        model: model.into(),
        source,
    }
}

fn sym(name: &str) -> Expr {
    Expr::symbol(name)
}

/// The body velocity of the wind-axis state: (V cos α cos β, V sin β, V sin α cos β).
pub fn body_velocity() -> Vec3 {
    let (vt, ca, sa) = (sym("vt"), Expr::cos("alpha"), Expr::sin("alpha"));
    let (cb, sb) = (Expr::cos("beta"), Expr::sin("beta"));
    Vec3([&(&vt * &ca) * &cb, &vt * &sb, &(&vt * &sa) * &cb])
}

/// k_b = Rᵀ(0, 0, 1): the space-fixed downward unit vector in body axes (4.57's R, of the
/// Euler angles or of the quaternion, q ⊗ v ⊗ q*).
fn down_in_body(kinematics: Kinematics) -> Vec3 {
    let down = Vec3([Expr::zero(), Expr::zero(), Expr::int(1)]);
    let rotation = match kinematics {
        Kinematics::Euler => body_to_space(),
        Kinematics::Quaternion => rotation_matrix(&Quaternion::symbols()),
    };
    rotation.transpose().mul_vec(&down)
}

/// The aerodynamic build-up: the stages of q̄S, the rate factors and the six total
/// coefficients, and the aerodynamic force and moment about G in their stage symbols.
fn aerodynamics(name: &str) -> Result<(Vec<Stage>, Vec3, Vec3), BuildError> {
    let err = symbolic(name);
    let half = parse("1/2").map_err(&err)?;
    let inverse_speed = sym("vt").pow(-1).map_err(&err)?;
    let mut stages: Vec<Stage> = vec![
        (
            "qbar_s".into(),
            &(&(&half * &sym("rho")) * &(&sym("vt") * &sym("vt"))) * &sym("S"),
        ),
        ("c_2v".into(), &(&half * &sym("cbar")) * &inverse_speed),
        ("b_2v".into(), &(&half * &sym("b")) * &inverse_speed),
    ];
    let (p, q, r) = (sym("p"), sym("q"), sym("r"));
    let (c_2v, b_2v) = (sym("c_2v"), sym("b_2v"));
    let lateral =
        |rate_r: &str, rate_p: &str| &b_2v * &(&(&sym(rate_r) * &r) + &(&sym(rate_p) * &p));
    let totals = [
        ("cx_total", &sym("C_X") + &(&(&c_2v * &q) * &sym("C_Xq"))),
        ("cy_total", &sym("C_Y") + &lateral("C_Yr", "C_Yp")),
        ("cz_total", &sym("C_Z") + &(&(&c_2v * &q) * &sym("C_Zq"))),
        ("cl_total", &sym("C_l") + &lateral("C_lr", "C_lp")),
        ("cm_total", &sym("C_m") + &(&(&c_2v * &q) * &sym("C_mq"))),
        ("cn_total", &sym("C_n") + &lateral("C_nr", "C_np")),
    ];
    stages.extend(totals.iter().map(|(n, e)| (n.to_string(), e.clone())));
    let qbar_s = sym("qbar_s");
    let force = Vec3::symbols(["cx_total", "cy_total", "cz_total"]).scale(&qbar_s);
    let (force_stages, force_symbols) = staged(&["aero_x", "aero_y", "aero_z"], &force);
    stages.extend(force_stages);
    let about_reference = Vec3([
        &qbar_s * &(&sym("b") * &sym("cl_total")),
        &qbar_s * &(&sym("cbar") * &sym("cm_total")),
        &qbar_s * &(&sym("b") * &sym("cn_total")),
    ]);
    let reference = Vec3::symbols(["x_ref", "y_ref", "z_ref"]);
    let moment = about_reference.add(&reference.cross(&force_symbols));
    Ok((stages, force_symbols, moment))
}

fn staged(names: &[&str; 3], values: &Vec3) -> (Vec<Stage>, Vec3) {
    let stages = names
        .iter()
        .zip(&values.0)
        .map(|(n, v)| (n.to_string(), v.clone()))
        .collect();
    (stages, Vec3::symbols(*names))
}

/// The aircraft's system in Euler angles (see the module docs), proved: the rotation against
/// 4.51 solved, the wind-axis rates by the chain rule against 4.49 solved, the navigation and
/// the Euler angles against 4.57 and 4.60.
///
/// ```
/// let system = eom_codegen::model::aircraft::aircraft("f16").unwrap();
/// assert_eq!(system.state.len(), 13);
/// assert_eq!(system.inputs.len(), 19);
/// ```
pub fn aircraft(name: &str) -> Result<System, BuildError> {
    aircraft_with(name, Kinematics::Euler)
}

/// The aircraft's system with its attitude in `kinematics`: in Euler angles as [`aircraft`],
/// or a quaternion ([`QUATERNION_STATE`]), whose rates are proved against q̇ = ½ q ⊗ (0, ω),
/// and whose track and weight equal 4.57's at every unit quaternion (checked at q(φ, θ, ψ)).
///
/// ```
/// use eom_codegen::model::{Kinematics, aircraft::aircraft_with};
/// let system = aircraft_with("f16", Kinematics::Quaternion).unwrap();
/// assert_eq!(system.state.len(), 14);
/// ```
pub fn aircraft_with(name: &str, kinematics: Kinematics) -> Result<System, BuildError> {
    let err = symbolic(name);
    let (mut stages, aero_force, aero_moment) = aerodynamics(name)?;
    let weight = down_in_body(kinematics).scale(&(&sym("M") * &sym("g")));
    let thrust = Vec3([sym("thrust"), Expr::zero(), Expr::zero()]);
    let force = aero_force.add(&thrust).add(&weight);
    let (force_stages, force) = staged(&["f_x", "f_y", "f_z"], &force);
    stages.extend(force_stages);
    let (moment_stages, moment) = staged(&["m_x", "m_y", "m_z"], &aero_moment);
    stages.extend(moment_stages);
    let velocity = body_velocity();
    stages.extend(
        ["u", "v", "w"]
            .iter()
            .zip(&velocity.0)
            .map(|(n, e)| (n.to_string(), e.clone())),
    );

    let translation_solution = translation_solved(name, &force)?;
    let body_rates = translation_solution.accelerations(&translation_solution.rest);
    stages.extend(
        ["u_dot", "v_dot", "w_dot"]
            .iter()
            .zip(&body_rates)
            .map(|(n, e)| (n.to_string(), e.clone())),
    );
    let (wind_stages, mut outputs) = wind_axis_rates(name)?;
    stages.extend(wind_stages);

    let (kinematic_stages, kinematic_outputs) = match kinematics {
        Kinematics::Euler => euler_kinematics(),
        Kinematics::Quaternion => quaternion_kinematics(name)?,
    };
    stages.extend(kinematic_stages);
    outputs.extend(kinematic_outputs[3..].iter().cloned());

    let rotation_solution = rotation_solved(name, &moment)?;
    let (bias_stages, bias) = staged(
        &["bias_p", "bias_q", "bias_r"],
        &Vec3(rotation_solution.rest.clone().try_into().expect("three")),
    );
    stages.extend(bias_stages);
    outputs.extend(rotation_solution.accelerations(&bias.0));

    outputs.push(kinematic_outputs[0].clone());
    outputs.push(kinematic_outputs[1].clone());
    outputs.push(-&kinematic_outputs[2]);
    outputs.push(&sym("power_gain") * &(&sym("power_command") - &sym("power")));

    let half = parse("1/2").map_err(&err)?;
    let omega = Vec3::symbols(["p", "q", "r"]);
    let tensor = without_products_tensor();
    let kinetic_energy = &(&half * &(&sym("M") * &(&sym("vt") * &sym("vt"))))
        + &(&half * &omega.dot(&tensor.mul_vec(&omega)));
    let (state, kinematic_equations): (Vec<&'static str>, [&'static str; 2]) = match kinematics {
        Kinematics::Euler => (STATE.to_vec(), ["4.57", "4.60"]),
        Kinematics::Quaternion => (QUATERNION_STATE.to_vec(), ["4.57 q", "4.60 q"]),
    };
    let mut equations = vec!["4.49", "4.50", "4.51"];
    equations.extend(kinematic_equations);
    let system = System {
        name: name.into(),
        title: "Aircraft in six degrees of freedom about G on its aerodynamic coefficients".into(),
        equations,
        parameters: PARAMETERS
            .iter()
            .map(|(symbol, doc)| Parameter {
                symbol: Cow::Borrowed(symbol),
                doc: Cow::Borrowed(doc),
            })
            .collect(),
        reciprocals: rotation_solution.reciprocals.clone(),
        state,
        inputs: inputs(),
        stages,
        outputs,
        groups: groups(kinematics),
        kinetic_energy: Some(kinetic_energy),
        energy_formula: Some("T = ½MV² + ½ωᵀ[I]ω"),
        potential_energy: Some(&(&sym("M") * &sym("g")) * &sym("altitude")),
        potential_formula: Some("V = M g h, h the altitude"),
        coefficient_names: inverse_names(&rotation_solution),
    };
    verify(&system, &translation_solution, &rotation_solution)?;
    if kinematics == Kinematics::Quaternion {
        verify_quaternion_attitude(&system)?;
    }
    Ok(system)
}

fn without_products_tensor() -> crate::symbolic::Mat3 {
    let zeros = [("Ixy", Expr::zero()), ("Iyz", Expr::zero())];
    let tensor = crate::derivation::spatial::inertia_tensor();
    crate::symbolic::Mat3::from_fn(|r, c| {
        tensor.0[r][c]
            .subs_all(&zeros)
            .expect("a product of inertia is a symbol")
    })
}

/// 4.49 in the body velocity's symbols, solved for u̇, v̇, ẇ under `force`.
fn translation_solved(name: &str, force: &Vec3) -> Result<Solution, BuildError> {
    let residuals = translation().sub(force);
    solve_linear(name, &residuals.0, &["u_dot", "v_dot", "w_dot"], "inv_mass")
}

/// 4.51 for a body symmetric about its xz-plane, with the rotor's h_E: \[I\]ω̇ + ω × (\[I\]ω +
/// h_E e_x) − M, solved for ṗ, q̇, ṙ.
fn rotation_solved(name: &str, moment: &Vec3) -> Result<Solution, BuildError> {
    let err = symbolic(name);
    let lhs = without_products(&euler_equations().map_err(&err)?, &["Ixy", "Iyz"]).map_err(&err)?;
    let omega = Vec3::symbols(["p", "q", "r"]);
    let rotor = Vec3([sym("h_E"), Expr::zero(), Expr::zero()]);
    let residuals = lhs.add(&omega.cross(&rotor)).sub(moment);
    solve_linear(name, &residuals.0, &["p_dot", "q_dot", "r_dot"], "inv_det")
}

/// V̇, α̇, β̇ from u̇, v̇, ẇ (stage symbols): the inverse of the parametrisation's Jacobian,
/// whose columns are orthogonal with lengths 1, V cos β and V.
fn wind_axis_rates(name: &str) -> Result<(Vec<Stage>, Vec<Expr>), BuildError> {
    let err = symbolic(name);
    let (ca, sa) = (Expr::cos("alpha"), Expr::sin("alpha"));
    let (cb, sb) = (Expr::cos("beta"), Expr::sin("beta"));
    let (u_dot, v_dot, w_dot) = (sym("u_dot"), sym("v_dot"), sym("w_dot"));
    let inverse_speed = sym("vt").pow(-1).map_err(&err)?;
    let stages = vec![
        ("inv_vt".to_string(), inverse_speed),
        ("in_plane".to_string(), &(&ca * &u_dot) + &(&sa * &w_dot)),
    ];
    let in_plane = sym("in_plane");
    let vt_dot = &(&cb * &in_plane) + &(&sb * &v_dot);
    let alpha_dot = &(&(&(&ca * &w_dot) - &(&sa * &u_dot)) * &sym("inv_vt")) * &Expr::sec("beta");
    let beta_dot = &(&(&cb * &v_dot) - &(&sb * &in_plane)) * &sym("inv_vt");
    Ok((stages, vec![vt_dot, alpha_dot, beta_dot]))
}

/// The proofs: the rotation equals 4.51 solved; the chain rule of (u, v, w) through (V, α, β)
/// at the program's rates equals 4.49 solved; the attitude and the track equal 4.60 and
/// 4.57; the power lag its law.
fn verify(system: &System, translation: &Solution, rotation: &Solution) -> Result<(), BuildError> {
    let name = system.name.as_str();
    let err = symbolic(name);
    // The wind-axis rates only: a quaternion form's track divides by |q|², which the proof
    // of its own takes at unit quaternions.
    let expanded: Vec<Expr> = (0..3)
        .map(|i| system.expanded_output(i))
        .collect::<Result<_, _>>()
        .map_err(&err)?;
    let stage = |symbol: &str| {
        system
            .stages
            .iter()
            .find(|(s, _)| s == symbol)
            .map(|(_, e)| e.clone())
            .expect("a stage of the system")
    };
    let expand = |e: &Expr| -> Result<Expr, BuildError> {
        system
            .stages
            .iter()
            .rev()
            .try_fold(e.clone(), |e, (s, d)| e.subs(s, d))
            .map_err(&err)
    };
    // 4.49 solved with the loads and (u, v, w) of the wind-axis state.
    let solved = translation.accelerations(&translation.rest);
    let rates: Vec<(&str, Expr)> = ["vt", "alpha", "beta"]
        .into_iter()
        .zip(expanded[..3].iter().cloned())
        .collect();
    for (i, axis) in ["u", "v", "w"].iter().enumerate() {
        let chain = stage(axis).time_derivative(&rates);
        let wanted = expand(&solved[i])?;
        let residual = &chain - &wanted;
        if !residual.is_zero() {
            return Err(BuildError::Verification {
                model: name.into(),
                what: format!(
                    "the chain rule of {axis} through (V, α, β) at the program's rates differs \
                     from 4.49 solved"
                ),
                residual: residual.to_string(),
            });
        }
    }
    let rotated: Vec<Expr> = rotation
        .accelerations(&rotation.rest)
        .iter()
        .map(expand)
        .collect::<Result<_, _>>()?;
    // The attitude's rates from 3 on, then the body rates, the track and the power.
    let quaternion = system.state.len() == QUATERNION_STATE.len();
    let mut checks: Vec<(usize, Expr)> = Vec::new();
    let attitude: Vec<Expr> = if quaternion {
        quaternion_rates().map_err(&err)?.0.to_vec()
    } else {
        euler_kinematics_expected(name)?[3..].to_vec()
    };
    let rates_at = 3 + attitude.len();
    checks.extend((3..).zip(attitude));
    checks.extend((rates_at..).zip(rotated));
    if !quaternion {
        let kinematics = euler_kinematics_expected(name)?;
        let track: Vec<Expr> = kinematics[..3]
            .iter()
            .map(|e| e.subs_all(&[("u", stage("u")), ("v", stage("v")), ("w", stage("w"))]))
            .collect::<Result<_, _>>()
            .map_err(&err)?;
        checks.push((9, track[0].clone()));
        checks.push((10, track[1].clone()));
        checks.push((11, -&track[2]));
    }
    checks.push((
        rates_at + 6,
        &sym("power_gain") * &(&sym("power_command") - &sym("power")),
    ));
    verify_outputs(system, &checks)
}

/// The quaternion form's track and weight equal 4.57's at every unit quaternion: at
/// q(φ, θ, ψ) in half angles, where |q| = 1 holds identically, north, east and −altitude are
/// E·(u, v, w) and the weight's direction is Eᵀ(0, 0, 1).
fn verify_quaternion_attitude(system: &System) -> Result<(), BuildError> {
    let err = symbolic(&system.name);
    let at_euler: Vec<(&str, Expr)> = ["q0", "q1", "q2", "q3"]
        .into_iter()
        .zip(quaternion_of_euler_angles().0)
        .collect();
    let expanded = system
        .substituted(&at_euler)
        .map_err(&err)?
        .expanded_outputs()
        .map_err(&err)?;
    let velocity = body_velocity();
    let e = body_to_space_half_angles();
    let track = e.mul_vec(&velocity);
    let navigation = [
        (10, track.0[0].clone()),
        (11, track.0[1].clone()),
        (12, -&track.0[2]),
    ];
    for (index, wanted) in navigation {
        let residual = &expanded[index] - &wanted;
        if !residual.is_zero() {
            return Err(BuildError::Verification {
                model: system.name.clone(),
                what: format!(
                    "the quaternion form's {} differs from 4.57's",
                    system.state[index]
                ),
                residual: residual.to_string(),
            });
        }
    }
    check_weight(&system.name, &down_in_body(Kinematics::Quaternion))
}

/// `k_b`, a quaternion form's downward vertical in body axes, equals Eᵀ(0, 0, 1) at
/// q(φ, θ, ψ).
fn check_weight(name: &str, k_b: &Vec3) -> Result<(), BuildError> {
    let err = symbolic(name);
    let at_euler: Vec<(&str, Expr)> = ["q0", "q1", "q2", "q3"]
        .into_iter()
        .zip(quaternion_of_euler_angles().0)
        .collect();
    let down = Vec3([Expr::zero(), Expr::zero(), Expr::int(1)]);
    let wanted = body_to_space_half_angles().transpose().mul_vec(&down);
    for (k, (got, want)) in k_b.0.iter().zip(&wanted.0).enumerate() {
        let residual = &got.subs_all(&at_euler).map_err(&err)? - want;
        if !residual.is_zero() {
            return Err(BuildError::Verification {
                model: name.into(),
                what: format!("the quaternion form's weight differs from 4.57's in axis {k}"),
                residual: residual.to_string(),
            });
        }
    }
    Ok(())
}

fn inverse_names(solution: &Solution) -> Vec<CoefficientName> {
    super::families::inverse_names(solution, "inv_inertia", "I", &["x", "y", "z"])
}

fn groups(kinematics: Kinematics) -> Vec<Group> {
    let (attitude, after) = match kinematics {
        Kinematics::Euler => ("4.60: the Euler-angle rates", 6),
        Kinematics::Quaternion => ("4.60 q: the attitude quaternion's rates, ½ q ⊗ (0, ω)", 7),
    };
    vec![
        Group {
            first: 0,
            comment: "4.49 in wind axes: V̇ = e_V·ν̇, α̇ and β̇ by the parametrisation's inverse \
                      Jacobian, the loads q̄S·C + T e_x + M g k_b"
                .into(),
        },
        Group {
            first: 3,
            comment: attitude.into(),
        },
        Group {
            first: after,
            comment: "4.51 with I_xz and the rotor: [I]ω̇ = M − ω × ([I]ω + h_E e_x), M the \
                      aerodynamic moment carried to G"
                .into(),
        },
        Group {
            first: after + 3,
            comment: "4.57: north, east and altitude (−z), flat Earth".into(),
        },
        Group {
            first: after + 6,
            comment: "the engine's power, a first-order lag toward its command".into(),
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_aircraft_is_proved_and_its_program_folds_back() {
        let system = aircraft("aircraft").unwrap();
        let program = crate::emit::prove_with_jacobians(&system).unwrap();
        assert_eq!(program.rhs.outputs.len(), 13);
    }

    #[test]
    fn the_quaternion_aircraft_is_proved_and_its_program_folds_back() {
        let system = aircraft_with("aircraft", Kinematics::Quaternion).unwrap();
        let program = crate::emit::prove_with_jacobians(&system).unwrap();
        assert_eq!(program.rhs.outputs.len(), 14);
    }

    /// A weight turned the wrong way (R(q)·e_z for R(q)ᵀ·e_z) is caught by the check at
    /// q(φ, θ, ψ).
    #[test]
    fn a_wrong_quaternion_weight_is_refused() {
        let wrong = rotation_matrix(&Quaternion::symbols()).mul_vec(&Vec3([
            Expr::zero(),
            Expr::zero(),
            Expr::int(1),
        ]));
        let refused = check_weight("aircraft", &wrong).unwrap_err();
        assert!(refused.to_string().contains("weight"), "{refused}");
        check_weight("aircraft", &down_in_body(Kinematics::Quaternion)).unwrap();
    }

    /// A wrong wind-axis rate (α̇ without its 1/cos β) is caught by the chain-rule proof.
    #[test]
    fn a_wrong_wind_axis_rate_is_refused() {
        let mut system = aircraft("aircraft").unwrap();
        system.outputs[1] = &system.outputs[1] * &Expr::cos("beta");
        let translation =
            translation_solved("aircraft", &Vec3::symbols(["f_x", "f_y", "f_z"])).unwrap();
        let moment = Vec3::symbols(["m_x", "m_y", "m_z"]);
        let rotation = rotation_solved("aircraft", &moment).unwrap();
        let refused = verify(&system, &translation, &rotation).unwrap_err();
        assert!(refused.to_string().contains("chain rule"), "{refused}");
    }
}
