//! Section 4.6 continued: Euler angles, 4.53–4.61.
//!
//! E is the product of the three elementary rotations (4.53–4.55), not the printed matrix; ω is
//! assembled from the three elementary rates, each carried into body axes by the rotations
//! that follow it; 4.60 is obtained as the symbolic inverse of 4.59 (adjugate over the
//! determinant, which reduces to cos θ) and also checked by multiplying the two.

use crate::check::{Component, Equation};
use crate::symbolic::{Expr, Mat3, SymbolicError, Vec3, parse};

/// Rz(ψ), 4.53: components in the rotated frame to components in the frame before it.
pub fn rotation_z(angle: &str) -> Mat3 {
    rotation_z_cs(Expr::cos(angle), Expr::sin(angle))
}

/// Ry(θ), 4.54.
pub fn rotation_y(angle: &str) -> Mat3 {
    rotation_y_cs(Expr::cos(angle), Expr::sin(angle))
}

/// Rx(φ), 4.55.
pub fn rotation_x(angle: &str) -> Mat3 {
    rotation_x_cs(Expr::cos(angle), Expr::sin(angle))
}

/// Rz from the cosine and sine of its angle, given as any expressions (e.g. half-angle forms).
pub fn rotation_z_cs(c: Expr, s: Expr) -> Mat3 {
    Mat3([
        [c.clone(), -&s, Expr::zero()],
        [s, c, Expr::zero()],
        [Expr::zero(), Expr::zero(), Expr::int(1)],
    ])
}

/// Ry from the cosine and sine of its angle.
pub fn rotation_y_cs(c: Expr, s: Expr) -> Mat3 {
    Mat3([
        [c.clone(), Expr::zero(), s.clone()],
        [Expr::zero(), Expr::int(1), Expr::zero()],
        [-s, Expr::zero(), c],
    ])
}

/// Rx from the cosine and sine of its angle.
pub fn rotation_x_cs(c: Expr, s: Expr) -> Mat3 {
    Mat3([
        [Expr::int(1), Expr::zero(), Expr::zero()],
        [Expr::zero(), c.clone(), -&s],
        [Expr::zero(), s, c],
    ])
}

/// E = Rz(ψ) Ry(θ) Rx(φ) (4.56–4.57).
pub fn body_to_space() -> Mat3 {
    rotation_z("psi")
        .mul_mat(&rotation_y("theta"))
        .mul_mat(&rotation_x("phi"))
}

/// ω in body axes from (φ̇, θ̇, ψ̇) (4.59): ψ̇ about z₁ = z₂, θ̇ about y₂ = y₃, φ̇ about x₃ = x.
pub fn body_rates_from_euler_rates() -> Vec3 {
    let yaw = Vec3::new(Expr::zero(), Expr::zero(), Expr::symbol("psi_dot"));
    let pitch = Vec3::new(Expr::zero(), Expr::symbol("theta_dot"), Expr::zero());
    let roll = Vec3::new(Expr::symbol("phi_dot"), Expr::zero(), Expr::zero());
    let in_frame_3 = rotation_y("theta")
        .transpose()
        .mul_vec(&yaw)
        .add(&pitch)
        .add(&roll);
    rotation_x("phi").transpose().mul_vec(&in_frame_3)
}

const EULER_RATES: [&str; 3] = ["phi_dot", "theta_dot", "psi_dot"];

/// The matrix of 4.59: ∂(p, q, r)/∂(φ̇, θ̇, ψ̇).
pub fn euler_rate_matrix() -> Mat3 {
    let omega = body_rates_from_euler_rates();
    Mat3::from_fn(|r, c| omega.0[r].coefficient_of(EULER_RATES[c]))
}

const BOOK_E: [[&str; 3]; 3] = [
    [
        "theta.cos()*psi.cos()",
        "phi.sin()*theta.sin()*psi.cos() - phi.cos()*psi.sin()",
        "phi.cos()*theta.sin()*psi.cos() + phi.sin()*psi.sin()",
    ],
    [
        "theta.cos()*psi.sin()",
        "phi.sin()*theta.sin()*psi.sin() + phi.cos()*psi.cos()",
        "phi.cos()*theta.sin()*psi.sin() - phi.sin()*psi.cos()",
    ],
    [
        "-theta.sin()",
        "phi.sin()*theta.cos()",
        "phi.cos()*theta.cos()",
    ],
];

const BOOK_INVERSE: [[&str; 3]; 3] = [
    ["1", "phi.sin()*theta.tan()", "phi.cos()*theta.tan()"],
    ["0", "phi.cos()", "-phi.sin()"],
    ["0", "phi.sin()*theta.sec()", "phi.cos()*theta.sec()"],
];

const IDENTITY: [[&str; 3]; 3] = [["1", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]];

pub(super) fn equations() -> Result<Vec<Equation>, SymbolicError> {
    Ok(vec![
        matrix_equation(
            "4.57",
            "E = Rz(ψ)Ry(θ)Rx(φ) written out",
            &body_to_space(),
            BOOK_E,
        ),
        orthogonality(),
        euler_rates(),
        inverse_euler_rates()?,
    ])
}

fn matrix_equation(
    number: &'static str,
    description: &'static str,
    m: &Mat3,
    book: [[&str; 3]; 3],
) -> Equation {
    let components = (0..3)
        .flat_map(|r| (0..3).map(move |c| (r, c)))
        .map(|(r, c)| {
            Component::new(
                format!("[{},{}]", r + 1, c + 1),
                m.0[r][c].clone(),
                book[r][c],
                &[],
            )
        })
        .collect();
    Equation {
        number,
        description,
        components,
    }
}

fn orthogonality() -> Equation {
    let e = body_to_space();
    let product = e.transpose().mul_mat(&e);
    matrix_equation(
        "4.57 EᵀE",
        "E is a rotation: EᵀE = 𝟙 (needs sin² + cos² = 1)",
        &product,
        IDENTITY,
    )
}

fn euler_rates() -> Equation {
    let omega = body_rates_from_euler_rates();
    let book = [
        "phi_dot - psi_dot*theta.sin()",
        "theta_dot*phi.cos() + psi_dot*theta.cos()*phi.sin()",
        "-theta_dot*phi.sin() + psi_dot*theta.cos()*phi.cos()",
    ];
    let labels = ["p", "q", "r"];
    Equation {
        number: "4.59",
        description: "body rates (p, q, r) assembled from the three elementary Euler rates",
        components: (0..3)
            .map(|i| Component::new(labels[i], omega.0[i].clone(), book[i], &[]))
            .collect(),
    }
}

fn inverse_euler_rates() -> Result<Equation, SymbolicError> {
    let forward = euler_rate_matrix();
    let mut equation = matrix_equation(
        "4.60",
        "Euler rates from body rates: the inverse of 4.59, and (4.60)(4.59) = 𝟙",
        &forward.inverse()?,
        BOOK_INVERSE,
    );
    let book = parse_matrix(BOOK_INVERSE)?;
    let product = matrix_equation("", "", &book.mul_mat(&forward), IDENTITY);
    for mut component in product.components {
        component.label = format!("(4.60)(4.59){}", component.label);
        equation.components.push(component);
    }
    Ok(equation)
}

fn parse_matrix(texts: [[&str; 3]; 3]) -> Result<Mat3, SymbolicError> {
    let rows = texts.map(|row| row.map(parse));
    let mut m = Mat3::identity();
    for (r, row) in rows.into_iter().enumerate() {
        for (c, entry) in row.into_iter().enumerate() {
            m.0[r][c] = entry?;
        }
    }
    Ok(m)
}
