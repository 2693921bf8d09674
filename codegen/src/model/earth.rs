//! A point mass over a turning Earth: the translational equations in the Earth-centred
//! Earth-fixed frame, with J2 gravitation.
//!
//! The state is the position r = (x, y, z) in ECEF axes and the velocity relative to the Earth
//! v = ṙ, in the same axes. The frame turns at Ω = (0, 0, ω) about the polar axis, so the
//! inertial acceleration of the point is (the chapter's ω × r, r × (ω × r) of 4.x with the
//! Earth's rate, Ω constant)
//!
//! ```text
//! a_inertial = r̈ + 2 Ω × ṙ + Ω × (Ω × r),
//! ```
//!
//! and Newton's law a_inertial = g(r) + f, with f the applied force per unit mass (an input, in
//! ECEF axes), gives
//!
//! ```text
//! v̇ = g(r) + f − 2 Ω × v − Ω × (Ω × r):   the Coriolis and the centripetal terms.
//! ```
//!
//! The gravitation is the gradient of the J2 potential U = (GM/r)(1 + (J2/2)(a/r)²(1 − 3Z²/r²)),
//! differentiated here, the chain rule through 1/r written out: the engine's expressions are
//! polynomials in the state and the inputs, so 1/r is an input the caller computes (as a
//! ship's speed U is), `inv_r`, and the Jacobians add ∂(1/r)/∂r = −r/r³. J2 = 0 is a point
//! mass, the spherical Earth.

use super::system::{BuildError, Group, Parameter, System};
use crate::symbolic::{Expr, Rational, SymbolicError, Vec3};
use std::borrow::Cow;

/// The state: position (m) and velocity relative to the Earth (m/s), ECEF axes.
pub const STATE: [&str; 6] = ["x", "y", "z", "v_x", "v_y", "v_z"];

/// The inputs: 1/r (1/m, which the caller computes from the position) and the applied force
/// per unit mass (m/s², ECEF axes).
pub const INPUTS: [&str; 4] = ["inv_r", "f_x", "f_y", "f_z"];

/// The parameters, by their symbols.
pub const PARAMETERS: [(&str, &str); 4] = [
    ("GM", "GM, the Earth's gravitational parameter, m³/s²"),
    ("J2", "J2, the oblateness term of the potential"),
    ("a_e", "a, the equatorial radius J2 is referred to, m"),
    (
        "omega_e",
        "ω, the Earth's rotation rate about its polar axis, rad/s",
    ),
];

fn sym(name: &str) -> Expr {
    Expr::symbol(name)
}

/// U = GM·(1/r)·(1 + (J2/2)·a²·(1/r)²·(1 − 3 z²·(1/r)²)), in the state and `inv_r`.
fn potential() -> Result<Expr, SymbolicError> {
    let inv_r = sym("inv_r");
    let inv_r2 = inv_r.pow(2)?;
    let half = Expr::constant(Rational::new(1.into(), 2.into()));
    let latitude = &Expr::int(1) - &(&Expr::int(3) * &(&sym("z").pow(2)? * &inv_r2));
    let oblate = &(&(&half * &sym("J2")) * &(&sym("a_e").pow(2)? * &inv_r2)) * &latitude;
    Ok(&(&sym("GM") * &inv_r) * &(&Expr::int(1) + &oblate))
}

/// g = ∇U: each partial derivative, and the one through 1/r, ∂(1/r)/∂x = −x/r³.
pub fn gravitation() -> Result<Vec3, SymbolicError> {
    let u = potential()?;
    let by_inv_r = u.diff("inv_r");
    let inv_r3 = sym("inv_r").pow(3)?;
    let component = |axis: &str| -> Expr {
        let through = &by_inv_r * &(&sym(axis) * &inv_r3);
        &u.diff(axis) - &through
    };
    Ok(Vec3::new(component("x"), component("y"), component("z")))
}

fn symbolic(name: &str) -> impl Fn(SymbolicError) -> BuildError + '_ {
    move |source| BuildError::Symbolic {
        model: name.into(),
        source,
    }
}

/// The point mass's system (module docs).
///
/// ```
/// let system = eom_codegen::model::earth::point_mass("dropped").unwrap();
/// assert_eq!(system.state.len(), 6);
/// eom_codegen::emit::prove_with_jacobians(&system).unwrap();
/// ```
pub fn point_mass(name: &str) -> Result<System, BuildError> {
    let err = symbolic(name);
    let r = Vec3::symbols(["x", "y", "z"]);
    let v = Vec3::symbols(["v_x", "v_y", "v_z"]);
    let f = Vec3::symbols(["f_x", "f_y", "f_z"]);
    let omega = Vec3::new(Expr::zero(), Expr::zero(), sym("omega_e"));
    let coriolis = omega.cross(&v).scale(&Expr::int(2));
    let centripetal = omega.cross(&omega.cross(&r));
    let acceleration = gravitation()
        .map_err(&err)?
        .add(&f)
        .sub(&coriolis)
        .sub(&centripetal);
    let mut outputs = v.0.to_vec();
    outputs.extend(acceleration.0);
    Ok(System {
        name: name.into(),
        title: "A point mass over a turning Earth: ECEF position and Earth-relative velocity, \
                J2 gravitation"
            .into(),
        equations: vec!["4.x: ω × r, r × (ω × r) with the Earth's rate"],
        parameters: PARAMETERS
            .iter()
            .map(|(symbol, doc)| Parameter {
                symbol: Cow::Borrowed(symbol),
                doc: Cow::Borrowed(doc),
            })
            .collect(),
        reciprocals: vec![],
        state: STATE.to_vec(),
        inputs: INPUTS.to_vec(),
        stages: vec![],
        outputs,
        groups: vec![
            Group {
                first: 0,
                comment: "the position moves at the velocity relative to the Earth".into(),
            },
            Group {
                first: 3,
                comment: "gravitation, the applied force, the Coriolis and the centripetal terms"
                    .into(),
            },
        ],
        kinetic_energy: Some(&Expr::constant(Rational::new(1.into(), 2.into())) * &v.dot(&v)),
        energy_formula: Some("T/M = ½|v|², per unit mass, relative to the Earth"),
        potential_energy: None,
        potential_formula: None,
        coefficient_names: vec![],
    })
}
