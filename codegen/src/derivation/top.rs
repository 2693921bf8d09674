//! Beyond the chapter: the heavy top, a rigid body turning about a fixed pivot O under gravity
//! (the compound pendulum of 4.24 in three dimensions).
//!
//! Nothing new is assumed; the equations are put together from the chapter's own pieces:
//! - the tensor about the pivot, I_O, by Steiner (4.23, computed from the integrals about O
//!   and the tensor about G, not copied) from the principal moments about G (`Ixx`, `Iyy`,
//!   `Izz`, the model's parameters) with G on the body z-axis at r_G = (0, 0, h);
//! - H_O = \[I_O\]ω, and dH_O/dt = \[dH_O/dt\] + ω × H_O (4.4), which equals the moment about O
//!   because O is fixed (4.50 taken about the pivot instead of G);
//! - the weight's moment r_G × Mg, as 4.24 takes it, with gravity g_space = (0, 0, −g) in space
//!   axes (Z up) turned into body axes by Rᵀ: R is E of 4.57 for Euler angles and the rotation
//!   matrix of q (column j is q ⊗ e_j ⊗ q*) for a quaternion.
//!
//! The quaternion's matrix is |q|² times a rotation, so for a quaternion off the unit sphere
//! the weight is |q|² times too; q̇ = ½ q ⊗ (0, ω) keeps |q|, and the energy below, written with
//! the same matrix, is then conserved for any |q|.
//!
//! Besides the equations, the energies and the three classical integrals are derived and
//! proved: T = ½ωᵀ\[I_O\]ω from 4.32 with v_G = ω × r_G, V = −M g·(R r_G), and along the
//! equations d(T + V)/dt = ω·M, dH_Z/dt = K·M (the vertical component of H_O in space) and
//! d(I_zz r)/dt = (I_xx − I_yy) p q + M_z, zero for a symmetric top without an applied moment.
//! "Along the equations" is shown by subtracting the residual of 4.50 (which vanishes on every
//! motion) with the multiplier that the classical proof uses: ω, the vertical, or the body
//! z-axis.

use super::energy::rigid_body_kinetic_energy;
use super::kinematics::{body_to_space, euler_rate_matrix};
use super::quaternion::{
    Quaternion, body_to_space_half_angles, quaternion_of_euler_angles, quaternion_rates,
    rotation_matrix,
};
use super::steiner::tensor_about_origin;
use super::{omega, rates_of};
use crate::check::{Component, Equation};
use crate::symbolic::{Expr, Mat3, SymbolicError, Vec3};

/// The pivot-to-G vector in body axes, r_G = (0, 0, h).
pub fn centre_of_gravity() -> Vec3 {
    Vec3::new(Expr::zero(), Expr::zero(), Expr::symbol("h"))
}

/// Gravity in space axes, (0, 0, −g): Z points up.
fn gravity_in_space() -> Vec3 {
    Vec3::new(Expr::zero(), Expr::zero(), -Expr::symbol("g"))
}

/// The upward vertical K in space axes.
fn vertical() -> Vec3 {
    Vec3::new(Expr::zero(), Expr::zero(), Expr::int(1))
}

/// I_O by Steiner (4.23): the tensor about the pivot of a body with principal moments `Ixx`,
/// `Iyy`, `Izz` about G and G at (0, 0, h).
pub fn inertia_about_pivot() -> Result<Mat3, SymbolicError> {
    let at_the_top = [
        ("x_G", Expr::zero()),
        ("y_G", Expr::zero()),
        ("z_G", Expr::symbol("h")),
        ("Ixy_G", Expr::zero()),
        ("Iyz_G", Expr::zero()),
        ("Izx_G", Expr::zero()),
        ("Ixx_G", Expr::symbol("Ixx")),
        ("Iyy_G", Expr::symbol("Iyy")),
        ("Izz_G", Expr::symbol("Izz")),
    ];
    let tensor = tensor_about_origin()?;
    let mut entries = Mat3::identity();
    for r in 0..3 {
        for c in 0..3 {
            entries.0[r][c] = tensor.0[r][c].subs_all(&at_the_top)?;
        }
    }
    Ok(entries)
}

/// The space vertical K in body axes, Rᵀ K, for the body-to-space matrix `rotation`.
pub fn vertical_in_body(rotation: &Mat3) -> Vec3 {
    rotation.transpose().mul_vec(&vertical())
}

/// The weight's moment about the pivot in body axes, r_G × M Rᵀ g_space (4.24's moment).
pub fn gravity_moment(rotation: &Mat3) -> Vec3 {
    let weight = rotation
        .transpose()
        .mul_vec(&gravity_in_space())
        .scale(&Expr::symbol("M"));
    centre_of_gravity().cross(&weight)
}

/// \[I_O\]\[dω/dt\] + ω × (\[I_O\]ω) − r_G × M g: the left side of 4.50 about the pivot, weight
/// included, for the body-to-space matrix `rotation`; the applied moment is what it equals.
pub fn euler_equations(rotation: &Mat3) -> Result<Vec3, SymbolicError> {
    let tensor = inertia_about_pivot()?;
    let momentum = tensor.mul_vec(&omega());
    Ok(tensor
        .mul_vec(&rates_of(["p", "q", "r"]))
        .add(&omega().cross(&momentum))
        .sub(&gravity_moment(rotation)))
}

/// T = ½M v_G·v_G + ½ωᵀ\[I_G\]ω (4.32 in the symbols of the models) with v_G = ω × r_G, the
/// pivot being at rest, and the products of inertia zero: the form the top models emit,
/// proved equal to ½ωᵀ\[I_O\]ω below.
pub fn kinetic_energy() -> Result<Expr, SymbolicError> {
    let [u, v, w] = omega().cross(&centre_of_gravity()).0;
    let substitutions = [
        ("u", u),
        ("v", v),
        ("w", w),
        ("Ixy", Expr::zero()),
        ("Iyz", Expr::zero()),
        ("Ixz", Expr::zero()),
    ];
    rigid_body_kinetic_energy()?.subs_all(&substitutions)
}

/// V = −M g_space·(R r_G): the weight's potential, zero with G level with the pivot, for the
/// body-to-space matrix `rotation`.
pub fn potential_energy(rotation: &Mat3) -> Expr {
    let centre = rotation.mul_vec(&centre_of_gravity());
    -(gravity_in_space().dot(&centre) * Expr::symbol("M"))
}

/// The rates of the attitude: 4.60 for the Euler angles, ½ q ⊗ (0, ω) for q.
fn attitude_rates(euler: bool) -> Result<Vec<(&'static str, Expr)>, SymbolicError> {
    if euler {
        let rates = euler_rate_matrix().inverse()?.mul_vec(&omega());
        let [phi, theta, psi] = rates.0;
        return Ok(vec![("phi", phi), ("theta", theta), ("psi", psi)]);
    }
    let [q0, q1, q2, q3] = quaternion_rates()?.0;
    Ok(vec![("q0", q0), ("q1", q1), ("q2", q2), ("q3", q3)])
}

/// The body-to-space matrix of the Euler angles (E, 4.57) or of the quaternion q.
pub fn rotation(euler: bool) -> Mat3 {
    if euler {
        body_to_space()
    } else {
        rotation_matrix(&Quaternion::symbols())
    }
}

const MOMENTS: [&str; 3] = ["M_x", "M_y", "M_z"];

pub(super) fn equations() -> Result<Vec<Equation>, SymbolicError> {
    Ok(vec![
        steiner()?,
        motion("4.50 top", EULER_BOOK, true)?,
        quaternion_motion()?,
        energies()?,
        integrals()?,
    ])
}

fn steiner() -> Result<Equation, SymbolicError> {
    let tensor = inertia_about_pivot()?;
    let entries = [
        ("I_O,xx", (0, 0), "Ixx + M*h.powi(2)"),
        ("I_O,yy", (1, 1), "Iyy + M*h.powi(2)"),
        ("I_O,zz", (2, 2), "Izz"),
        ("I_O,xy", (0, 1), "0"),
        ("I_O,yz", (1, 2), "0"),
        ("I_O,zx", (2, 0), "0"),
    ];
    Ok(Equation {
        number: "4.23 top",
        description: "beyond the chapter: the top's tensor about the pivot, G at (0, 0, h) on \
                      principal axes at G, by Steiner",
        components: entries
            .iter()
            .map(|(label, (r, c), book)| {
                Component::new(*label, tensor.0[*r][*c].clone(), *book, &[])
            })
            .collect(),
    })
}

/// The book's notation, written out: I_O by 4.23 inline, the weight's moment through the last
/// row of E (4.57).
const EULER_BOOK: [&str; 3] = [
    "(Ixx + M*h.powi(2))*p_dot + (Izz - Iyy - M*h.powi(2))*q*r \
     - M*g*h*phi.sin()*theta.cos() - M_x",
    "(Iyy + M*h.powi(2))*q_dot + (Ixx + M*h.powi(2) - Izz)*r*p - M*g*h*theta.sin() - M_y",
    "Izz*r_dot + (Iyy - Ixx)*p*q - M_z",
];

/// The same with the last row of the quaternion's matrix.
const QUATERNION_BOOK: [&str; 3] = [
    "(Ixx + M*h.powi(2))*p_dot + (Izz - Iyy - M*h.powi(2))*q*r \
     - 2*M*g*h*(q2*q3 + q0*q1) - M_x",
    "(Iyy + M*h.powi(2))*q_dot + (Ixx + M*h.powi(2) - Izz)*r*p \
     - 2*M*g*h*(q0*q2 - q1*q3) - M_y",
    "Izz*r_dot + (Iyy - Ixx)*p*q - M_z",
];

fn motion(number: &'static str, book: [&str; 3], euler: bool) -> Result<Equation, SymbolicError> {
    let lhs = euler_equations(&rotation(euler))?;
    let description = if euler {
        "beyond the chapter: the heavy top, [I_O]ω̇ + ω × [I_O]ω = r_G × Mg + M about the pivot \
         (4.23, 4.4, 4.50, 4.24's moment), gravity turned by E"
    } else {
        "beyond the chapter: the heavy top with gravity turned by the quaternion's matrix"
    };
    Ok(Equation {
        number,
        description,
        components: (0..3)
            .map(|i| {
                let residual = &lhs.0[i] - &Expr::symbol(MOMENTS[i]);
                Component::new(super::AXES[i], residual, book[i], &[])
            })
            .collect(),
    })
}

/// 4.50 top with a quaternion, and the weight's moment by q(φ, θ, ψ) equal to the moment by E
/// (both in half angles): the two models are one top.
fn quaternion_motion() -> Result<Equation, SymbolicError> {
    let mut equation = motion("4.50 top q", QUATERNION_BOOK, false)?;
    let by_q = gravity_moment(&rotation_matrix(&quaternion_of_euler_angles()));
    let by_e = gravity_moment(&body_to_space_half_angles());
    for i in 0..3 {
        let label = format!("r_G × Mg, q(φ, θ, ψ) against E, {}", super::AXES[i]);
        equation
            .components
            .push(Component::new(label, &by_q.0[i] - &by_e.0[i], "0", &[]));
    }
    Ok(equation)
}

fn energies() -> Result<Equation, SymbolicError> {
    Ok(Equation {
        number: "4.34 top",
        description: "beyond the chapter: the top's energies, T = ½Mv_G² + ½ωᵀ[I_G]ω = \
                      ½ωᵀ[I_O]ω (v_G = ω × r_G) and V = −Mg·R r_G",
        components: vec![
            Component::new(
                "T",
                kinetic_energy()?,
                "((Ixx + M*h.powi(2))*p.powi(2) + (Iyy + M*h.powi(2))*q.powi(2) \
                 + Izz*r.powi(2))/2",
                &[],
            ),
            Component::new(
                "V, Euler angles",
                potential_energy(&rotation(true)),
                "M*g*h*phi.cos()*theta.cos()",
                &[],
            ),
            Component::new(
                "V, quaternion",
                potential_energy(&rotation(false)),
                "M*g*h*(q0.powi(2) - q1.powi(2) - q2.powi(2) + q3.powi(2))",
                &[],
            ),
        ],
    })
}

/// The three integrals, for either attitude: the time derivative by the chain rule (rates of
/// ω left as the symbols ṗ, q̇, ṙ; rates of the attitude from its kinematics), minus the
/// residual of 4.50 top times the classical multiplier.
fn integrals() -> Result<Equation, SymbolicError> {
    let mut components = Vec::new();
    for (euler, kind) in [(true, "Euler angles"), (false, "quaternion")] {
        let rotation = rotation(euler);
        let mut rates = attitude_rates(euler)?;
        rates.extend(["p", "q", "r"].map(|w| (w, Expr::symbol(&format!("{w}_dot")))));
        let moments = Vec3::symbols(MOMENTS);
        let residual = euler_equations(&rotation)?.sub(&moments);
        let momentum = inertia_about_pivot()?.mul_vec(&omega());
        let up = vertical_in_body(&rotation);

        let energy = kinetic_energy()? + potential_energy(&rotation);
        let power = energy.time_derivative(&rates) - omega().dot(&residual);
        components.push(Component::new(
            format!("d(T + V)/dt − ω·(4.50 top), {kind}"),
            power,
            "p*M_x + q*M_y + r*M_z",
            &[],
        ));

        let vertical_momentum = up.dot(&momentum);
        let change = vertical_momentum.time_derivative(&rates) - up.dot(&residual);
        let book = if euler {
            "-M_x*theta.sin() + M_y*phi.sin()*theta.cos() + M_z*phi.cos()*theta.cos()"
        } else {
            "2*M_x*(q1*q3 - q0*q2) + 2*M_y*(q2*q3 + q0*q1) \
             + M_z*(q0.powi(2) - q1.powi(2) - q2.powi(2) + q3.powi(2))"
        };
        components.push(Component::new(
            format!("dH_Z/dt − K·(4.50 top), {kind}"),
            change,
            book,
            &[],
        ));
    }
    let residual = euler_equations(&rotation(true))?.sub(&Vec3::symbols(MOMENTS));
    let spin = inertia_about_pivot()?.mul_vec(&omega()).0[2].clone();
    let rates = ["p", "q", "r"].map(|w| (w, Expr::symbol(&format!("{w}_dot"))));
    components.push(Component::new(
        "dH_z/dt − k·(4.50 top)",
        spin.time_derivative(&rates) - residual.0[2].clone(),
        "(Ixx - Iyy)*p*q + M_z",
        &[],
    ));
    Ok(Equation {
        number: "4.35 top",
        description: "beyond the chapter: along the top's equations d(T + V)/dt = ω·M, \
                      dH_Z/dt = K·M, dH_z/dt = (I_xx − I_yy)pq + M_z",
        components,
    })
}
