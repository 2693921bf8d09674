//! Beyond the chapter: an underwater vehicle in six degrees of freedom about its table's
//! origin O, with the fluid's added mass.
//!
//! Hydrodynamic tables of vehicles are written about a body origin O (REMUS: the centre of
//! buoyancy), with G at r_G = (x_G, y_G, z_G) from it. The six equations about O are put
//! together from the chapter's pieces, as 4.46 comes from 4.43 by 4.45:
//! - the velocity of G is v_G = v + ω × r_G (4.5 with r = r_G + r′), and 4.1 with 4.48 gives
//!   F = M([dv_G/dt] + ω × v_G);
//! - 4.2 with 4.50 gives the moment about G, \[I_G\]ω̇ + ω × \[I_G\]ω, and the moment about O is
//!   that plus r_G × F (the change of origin of 4.45, in three dimensions);
//! - the tensor about G is traded for the tensor about O by Steiner (4.23, computed).
//!
//! The result is proved equal to two reference forms: the component form of the standard
//! rigid-body equations about O (Fossen's, with the chapter's sign of the products of inertia,
//! so that the rotational part is 4.51 with \[I_O\]), and the matrix form
//! M_RB ν̇ + C_RB(ν)ν = τ with M_RB = [[M𝟙, −M S(r_G)], [M S(r_G), I_O]] and
//! C_RB = [[M S(ω), −M S(ω)S(r_G)], [M S(r_G)S(ω), −S(I_O ω)]], built from its blocks. At
//! r_G = 0 it is 4.49 + 4.51 (see `tests/vehicle.rs`).
//!
//! The fluid's share follows Kirchhoff: with T_A = ½νᵀM_Aν, its momentum is P = ∂T_A/∂v and
//! its angular momentum about O is H = ∂T_A/∂ω, and 4.48 and 4.50 about a moving origin give
//! [dP/dt] + ω × P and [dH/dt] + ω × H + v × P. This is proved equal to Fossen's
//! M_Aν̇ + C_A(ν)ν with C_A = [[0, −S(A₁₁v + A₁₂ω)], [−S(A₁₁v + A₁₂ω), −S(A₂₁v + A₂₂ω)]] for a
//! general symmetric M_A, and, for the entries of a body of revolution's table, equal to the
//! cross terms Prestero's REMUS table folds (Xwq = Z_ẇ, Mrp = K_ṗ − N_ṙ, the Munk moment
//! Muw = −(Z_ẇ − X_u̇), …).

use super::steiner::tensor_about_origin;
use super::{omega, rates_of};
use crate::check::{Component, Equation, definitions};
use crate::symbolic::{Expr, Mat3, SymbolicError, Vec3, parse};

/// The six velocities ν = (u, v, w, p, q, r).
pub const VELOCITIES: [&str; 6] = ["u", "v", "w", "p", "q", "r"];

/// The six loads about O, τ = (F_x, F_y, F_z, M_x, M_y, M_z).
pub const LOADS: [&str; 6] = ["F_x", "F_y", "F_z", "M_x", "M_y", "M_z"];

/// The tensor about O, in the chapter's convention (products with the minus sign inside).
const TENSOR_ABOUT_O: [[&str; 3]; 3] = [
    ["Ixx", "Ixy", "Ixz"],
    ["Ixy", "Iyy", "Iyz"],
    ["Ixz", "Iyz", "Izz"],
];

/// The tensor about G, in the symbols of Steiner's derivation (4.23).
const TENSOR_ABOUT_G: [[&str; 3]; 3] = [
    ["Ixx_G", "Ixy_G", "Izx_G"],
    ["Ixy_G", "Iyy_G", "Iyz_G"],
    ["Izx_G", "Iyz_G", "Izz_G"],
];

/// r_G = (x_G, y_G, z_G), G from O in body axes.
pub fn centre_of_gravity() -> Vec3 {
    Vec3::symbols(["x_G", "y_G", "z_G"])
}

fn velocity() -> Vec3 {
    Vec3::symbols(["u", "v", "w"])
}

/// The rates of ν as the chain rule needs them: u → u_dot, …, r → r_dot.
pub fn velocity_rates() -> Vec<(&'static str, Expr)> {
    VELOCITIES
        .iter()
        .map(|v| (*v, Expr::symbol(&format!("{v}_dot"))))
        .collect()
}

fn loads() -> [Expr; 6] {
    LOADS.map(Expr::symbol)
}

/// I_G = I_O − (Steiner's correction): each entry of the tensor about G in the tensor about O,
/// the correction being 4.23's, computed ([`tensor_about_origin`] less the tensor about G).
fn tensor_about_g_from_o() -> Result<Vec<(&'static str, Expr)>, SymbolicError> {
    let about_o = tensor_about_origin()?;
    let mut pairs = Vec::new();
    for (r, c) in [(0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (0, 2)] {
        let g = Expr::symbol(TENSOR_ABOUT_G[r][c]);
        let correction = &about_o.0[r][c] - &g;
        pairs.push((
            TENSOR_ABOUT_G[r][c],
            Expr::symbol(TENSOR_ABOUT_O[r][c]) - correction,
        ));
    }
    Ok(pairs)
}

/// The left sides of the six equations about O less the loads, in the tensor about O:
/// M([dv_G/dt] + ω × v_G) − F and \[I_G\]ω̇ + ω × \[I_G\]ω + r_G × M a_G − M_O, with
/// v_G = v + ω × r_G and I_G = I_O less Steiner's correction (4.23).
pub fn rigid_body_about_origin() -> Result<[Expr; 6], SymbolicError> {
    let r_g = centre_of_gravity();
    let v_g = velocity().add(&omega().cross(&r_g));
    let rates = velocity_rates();
    let v_g_rate = v_g.try_map(|e| Ok(e.time_derivative(&rates)))?;
    let a_g = v_g_rate.add(&omega().cross(&v_g));
    let force = a_g.scale(&Expr::symbol("M"));
    let tensor = Mat3::from_fn(|r, c| Expr::symbol(TENSOR_ABOUT_G[r][c]));
    let h_g = tensor.mul_vec(&omega());
    let moment_about_g = tensor
        .mul_vec(&rates_of(["p", "q", "r"]))
        .add(&omega().cross(&h_g));
    let moment_about_o = moment_about_g.add(&r_g.cross(&force));
    let about_o = tensor_about_g_from_o()?;
    let loads = loads();
    let mut residuals: [Expr; 6] = std::array::from_fn(|_| Expr::zero());
    for i in 0..3 {
        residuals[i] = &force.0[i] - &loads[i];
        residuals[i + 3] = &moment_about_o.0[i].subs_all(&about_o)? - &loads[i + 3];
    }
    Ok(residuals)
}

/// The skew matrix S(a) with S(a)b = a × b.
pub fn skew(a: &Vec3) -> Mat3 {
    let [x, y, z] = a.0.clone();
    Mat3([
        [Expr::zero(), -&z, y.clone()],
        [z, Expr::zero(), -&x],
        [-y, x, Expr::zero()],
    ])
}

fn scaled(m: &Mat3, factor: &Expr) -> Mat3 {
    Mat3::from_fn(|r, c| &m.0[r][c] * factor)
}

fn negated(m: &Mat3) -> Mat3 {
    Mat3::from_fn(|r, c| -&m.0[r][c])
}

/// A 6×6 matrix of 3×3 blocks times (a; b).
fn block_times(blocks: [[&Mat3; 2]; 2], a: &Vec3, b: &Vec3) -> [Expr; 6] {
    let top = blocks[0][0].mul_vec(a).add(&blocks[0][1].mul_vec(b));
    let bottom = blocks[1][0].mul_vec(a).add(&blocks[1][1].mul_vec(b));
    let [x, y, z] = top.0;
    let [k, m, n] = bottom.0;
    [x, y, z, k, m, n]
}

/// M_RB ν̇ + C_RB(ν)ν − τ about O, built from the blocks of the standard matrix form.
pub fn rigid_body_matrix_form() -> [Expr; 6] {
    let m = Expr::symbol("M");
    let s_rg = skew(&centre_of_gravity());
    let s_omega = skew(&omega());
    let tensor = Mat3::from_fn(|r, c| Expr::symbol(TENSOR_ABOUT_O[r][c]));
    let identity = scaled(&Mat3::identity(), &m);
    let (upper, lower) = (scaled(&negated(&s_rg), &m), scaled(&s_rg, &m));
    let mass = block_times(
        [[&identity, &upper], [&lower, &tensor]],
        &rates_of(["u", "v", "w"]),
        &rates_of(["p", "q", "r"]),
    );
    let c11 = scaled(&s_omega, &m);
    let c12 = scaled(&negated(&s_omega.mul_mat(&s_rg)), &m);
    let c21 = scaled(&s_rg.mul_mat(&s_omega), &m);
    let c22 = negated(&skew(&tensor.mul_vec(&omega())));
    let coriolis = block_times([[&c11, &c12], [&c21, &c22]], &velocity(), &omega());
    let loads = loads();
    std::array::from_fn(|i| &(&mass[i] + &coriolis[i]) - &loads[i])
}

/// A symmetric 6×6 added-mass matrix M_A of symbols, entry (i, j) named by `name(i, j)` for
/// i ≤ j (the lower triangle mirrors the upper); an empty name is a zero entry.
pub fn symmetric_matrix(name: impl Fn(usize, usize) -> String) -> [[Expr; 6]; 6] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let symbol = name(i.min(j), i.max(j));
            if symbol.is_empty() {
                Expr::zero()
            } else {
                Expr::symbol(&symbol)
            }
        })
    })
}

fn nu() -> [Expr; 6] {
    VELOCITIES.map(Expr::symbol)
}

fn nu_rates() -> [Expr; 6] {
    VELOCITIES.map(|v| Expr::symbol(&format!("{v}_dot")))
}

fn times(matrix: &[[Expr; 6]; 6], vector: &[Expr; 6]) -> [Expr; 6] {
    std::array::from_fn(|i| (0..6).map(|j| &matrix[i][j] * &vector[j]).sum())
}

/// T_A = ½νᵀM_Aν: the fluid's kinetic energy.
pub fn fluid_kinetic_energy(added_mass: &[[Expr; 6]; 6]) -> Result<Expr, SymbolicError> {
    let nu = nu();
    let twice: Expr = (0..6)
        .map(|i| &nu[i] * &times(added_mass, &nu)[i])
        .sum::<Expr>();
    Ok(&twice * &parse("1/2")?)
}

/// Kirchhoff's equations for the fluid's share, left sides: P = ∂T_A/∂v, H = ∂T_A/∂ω, and
/// ([dP/dt] + ω × P, [dH/dt] + ω × H + v × P) by 4.48 and 4.50 about the moving origin O.
pub fn kirchhoff(added_mass: &[[Expr; 6]; 6]) -> Result<[Expr; 6], SymbolicError> {
    let energy = fluid_kinetic_energy(added_mass)?;
    let gradient = |names: [&str; 3]| Vec3(names.map(|n| energy.diff(n)));
    let momentum = gradient(["u", "v", "w"]);
    let angular = gradient(["p", "q", "r"]);
    let rates = velocity_rates();
    let rate_of = |v: &Vec3| v.try_map(|e| Ok(e.time_derivative(&rates)));
    let force = rate_of(&momentum)?.add(&omega().cross(&momentum));
    let moment = rate_of(&angular)?
        .add(&omega().cross(&angular))
        .add(&velocity().cross(&momentum));
    let [x, y, z] = force.0;
    let [k, m, n] = moment.0;
    Ok([x, y, z, k, m, n])
}

/// Kirchhoff's terms without the accelerations: C_A(ν)ν, the fluid's Coriolis and
/// centripetal terms (the Munk moment among them), on the left.
pub fn added_mass_coriolis(added_mass: &[[Expr; 6]; 6]) -> Result<[Expr; 6], SymbolicError> {
    let rate_symbols: Vec<String> = VELOCITIES.iter().map(|v| format!("{v}_dot")).collect();
    let zeros: Vec<(&str, Expr)> = rate_symbols
        .iter()
        .map(|s| (s.as_str(), Expr::zero()))
        .collect();
    let full = kirchhoff(added_mass)?;
    let mut terms: [Expr; 6] = std::array::from_fn(|_| Expr::zero());
    for (term, row) in terms.iter_mut().zip(full) {
        *term = row.subs_all(&zeros)?;
    }
    Ok(terms)
}

/// Fossen's form of the fluid's share: M_Aν̇ + C_A(ν)ν with
/// C_A = [[0, −S(A₁₁v + A₁₂ω)], [−S(A₁₁v + A₁₂ω), −S(A₂₁v + A₂₂ω)]].
pub fn added_mass_matrix_form(added_mass: &[[Expr; 6]; 6]) -> [Expr; 6] {
    let nu = nu();
    let product = times(added_mass, &nu);
    let a = Vec3::new(product[0].clone(), product[1].clone(), product[2].clone());
    let b = Vec3::new(product[3].clone(), product[4].clone(), product[5].clone());
    let zero = Mat3::from_fn(|_, _| Expr::zero());
    let (s_a, s_b) = (negated(&skew(&a)), negated(&skew(&b)));
    let coriolis = block_times([[&zero, &s_a], [&s_a, &s_b]], &velocity(), &omega());
    let inertia = times(added_mass, &nu_rates());
    std::array::from_fn(|i| &inertia[i] + &coriolis[i])
}

/// The added-mass matrix of a body of revolution's table (REMUS): M_A = −[X_u̇, Y_v̇, Z_ẇ,
/// K_ṗ, M_q̇, N_ṙ] on the diagonal, −Y_ṙ = −N_v̇ and −Z_q̇ = −M_ẇ off it.
pub fn body_of_revolution_added_mass() -> [[Expr; 6]; 6] {
    let names = |i: usize, j: usize| -> String {
        let name = match (i, j) {
            (0, 0) => "Xudot",
            (1, 1) => "Yvdot",
            (2, 2) => "Zwdot",
            (3, 3) => "Kpdot",
            (4, 4) => "Mqdot",
            (5, 5) => "Nrdot",
            (1, 5) => "Yrdot",
            (2, 4) => "Zqdot",
            _ => "",
        };
        name.to_owned()
    };
    let table = symmetric_matrix(names);
    std::array::from_fn(|i| std::array::from_fn(|j| -&table[i][j]))
}

/// Every equation of this module, derived and beside its reference form, for the tests and
/// the vehicle's report (they are not part of the catalog's build-time proof, which they
/// would only slow down).
pub fn equations() -> Result<Vec<Equation>, SymbolicError> {
    Ok(vec![
        about_origin()?,
        about_origin_matrix_form()?,
        kirchhoff_matrix_form()?,
        kirchhoff_folded()?,
    ])
}

/// The standard equations about O in components (Fossen 1994, 2.96–2.101), with the products
/// of inertia in the chapter's convention: the rotational part is 4.51 with \[I_O\].
const ABOUT_ORIGIN: [&str; 6] = [
    "M*(u_dot - v*r + w*q - x_G*(q.powi(2) + r.powi(2)) + y_G*(p*q - r_dot) + z_G*(p*r + q_dot)) - F_x",
    "M*(v_dot - w*p + u*r - y_G*(r.powi(2) + p.powi(2)) + z_G*(q*r - p_dot) + x_G*(q*p + r_dot)) - F_y",
    "M*(w_dot - u*q + v*p - z_G*(p.powi(2) + q.powi(2)) + x_G*(r*p - q_dot) + y_G*(r*q + p_dot)) - F_z",
    "Ixx*p_dot + (Izz - Iyy)*q*r + Ixy*(q_dot - r*p) + Ixz*(r_dot + p*q) + Iyz*(q.powi(2) - r.powi(2)) \
     + M*(y_G*(w_dot - u*q + v*p) - z_G*(v_dot - w*p + u*r)) - M_x",
    "Iyy*q_dot + (Ixx - Izz)*r*p + Iyz*(r_dot - p*q) + Ixy*(p_dot + q*r) + Ixz*(r.powi(2) - p.powi(2)) \
     + M*(z_G*(u_dot - v*r + w*q) - x_G*(w_dot - u*q + v*p)) - M_y",
    "Izz*r_dot + (Iyy - Ixx)*p*q + Ixz*(p_dot - q*r) + Iyz*(q_dot + r*p) + Ixy*(p.powi(2) - q.powi(2)) \
     + M*(x_G*(v_dot - w*p + u*r) - y_G*(u_dot - v*r + w*q)) - M_z",
];

const ROWS: [&str; 6] = ["X", "Y", "Z", "K", "M", "N"];

fn about_origin() -> Result<Equation, SymbolicError> {
    let derived = rigid_body_about_origin()?;
    Ok(Equation {
        number: "4.1–4.2 O",
        description: "beyond the chapter: the six equations about O with G at r_G, from 4.1 and \
                      4.2 with r = r_G + r′ (4.5, 4.48, 4.50, Steiner 4.23)",
        components: (0..6)
            .map(|i| Component::new(ROWS[i], derived[i].clone(), ABOUT_ORIGIN[i], &[]))
            .collect(),
    })
}

fn about_origin_matrix_form() -> Result<Equation, SymbolicError> {
    let derived = rigid_body_about_origin()?;
    let matrix = rigid_body_matrix_form();
    Ok(Equation {
        number: "4.1–4.2 O M_RB",
        description: "beyond the chapter: the equations about O equal M_RB ν̇ + C_RB(ν)ν − τ, \
                      built from the blocks S(r_G), S(ω), S(I_O ω)",
        components: (0..6)
            .map(|i| built(ROWS[i], &derived[i], "M_RB_nu_dot_plus_C_RB_nu", &matrix[i]))
            .collect(),
    })
}

/// A component whose reference is built from matrix blocks rather than typed: the reference
/// text is one symbol, defined as the built form.
fn built(label: &str, derived: &Expr, symbol: &str, reference: &Expr) -> Component {
    let definition = (symbol.to_owned(), reference.clone());
    Component::new(label, derived.clone(), symbol, &[definition])
}

/// The upper triangle of a general symmetric M_A, `A11 … A66`.
pub fn general_added_mass() -> [[Expr; 6]; 6] {
    symmetric_matrix(|i, j| format!("A{}{}", i + 1, j + 1))
}

fn kirchhoff_matrix_form() -> Result<Equation, SymbolicError> {
    let added_mass = general_added_mass();
    let derived = kirchhoff(&added_mass)?;
    let standard = added_mass_matrix_form(&added_mass);
    Ok(Equation {
        number: "Kirchhoff C_A",
        description: "beyond the chapter: ([dP/dt] + ω×P, [dH/dt] + ω×H + v×P) with \
                      P = ∂T_A/∂v, H = ∂T_A/∂ω equals M_Aν̇ + C_A(ν)ν, M_A general symmetric",
        components: (0..6)
            .map(|i| built(ROWS[i], &derived[i], "M_A_nu_dot_plus_C_A_nu", &standard[i]))
            .collect(),
    })
}

/// Prestero's REMUS forces of the added mass (thesis, 2001, §3.4), the cross terms named as
/// his table folds them: the right sides, with the accelerations' own terms.
const PRESTERO_FOLDED: [&str; 6] = [
    "Xudot*u_dot + Xwq*w*q + Xqq*q.powi(2) + Xvr*v*r + Xrr*r.powi(2)",
    "Yvdot*v_dot + Yrdot*r_dot + Yur*u*r + Ywp*w*p + Ypq*p*q",
    "Zwdot*w_dot + Zqdot*q_dot + Zuq*u*q + Zvp*v*p + Zrp*r*p",
    "Kpdot*p_dot",
    "Mwdot*w_dot + Mqdot*q_dot + Muw*u*w + Muq*u*q + Mvp*v*p + Mrp*r*p",
    "Nvdot*v_dot + Nrdot*r_dot + Nuv*u*v + Nur*u*r + Nwp*w*p + Npq*p*q",
];

/// The added-mass cross terms as Prestero's thesis expresses them in the added mass (the
/// accelerations' symmetric partners Nv̇ = Yṙ and Mẇ = Zq̇ included).
const PRESTERO_IDENTITIES: [(&str, &str); 20] = [
    ("Nvdot", "Yrdot"),
    ("Mwdot", "Zqdot"),
    ("Xwq", "Zwdot"),
    ("Xqq", "Zqdot"),
    ("Xvr", "-Yvdot"),
    ("Xrr", "-Yrdot"),
    ("Yur", "Xudot"),
    ("Ywp", "-Zwdot"),
    ("Ypq", "-Zqdot"),
    ("Zuq", "-Xudot"),
    ("Zvp", "Yvdot"),
    ("Zrp", "Yrdot"),
    ("Muw", "-(Zwdot - Xudot)"),
    ("Muq", "-Zqdot"),
    ("Mvp", "-Yrdot"),
    ("Mrp", "Kpdot - Nrdot"),
    ("Nuv", "-(Xudot - Yvdot)"),
    ("Nur", "Yrdot"),
    ("Nwp", "Zqdot"),
    ("Npq", "-(Kpdot - Mqdot)"),
];

fn kirchhoff_folded() -> Result<Equation, SymbolicError> {
    let derived = kirchhoff(&body_of_revolution_added_mass())?;
    let identities = definitions(&PRESTERO_IDENTITIES)?;
    let axisymmetric = definitions(&AXISYMMETRIC)?;
    let axisymmetric: Vec<(&str, Expr)> = axisymmetric
        .iter()
        .map(|(symbol, value)| (symbol.as_str(), value.clone()))
        .collect();
    Ok(Equation {
        number: "Kirchhoff REMUS",
        description: "beyond the chapter: Kirchhoff's terms of a body of revolution's added \
                      mass are Prestero's folded cross terms (Xwq = Z_ẇ, the Munk moment \
                      Muw = −(Z_ẇ − X_u̇), Mrp = K_ṗ − N_ṙ, …)",
        components: (0..6)
            .map(|i| {
                // The table's forces are on the right: the negated left side. Prestero's roll
                // equation keeps K_ṗ ṗ alone; the rest of Kirchhoff's K vanishes only for an
                // axisymmetric added mass, so that row is proved for one.
                let (label, derived) = if i == 3 {
                    (
                        "K (axisymmetric)".to_owned(),
                        derived[i].subs_all(&axisymmetric)?,
                    )
                } else {
                    (ROWS[i].to_owned(), derived[i].clone())
                };
                Ok(Component::new(
                    label,
                    -derived,
                    PRESTERO_FOLDED[i],
                    &identities,
                ))
            })
            .collect::<Result<_, SymbolicError>>()?,
    })
}

/// A body of revolution about x: the added mass in z is that in y, turned (Z_ẇ = Y_v̇,
/// M_q̇ = N_ṙ, Z_q̇ = −Y_ṙ).
const AXISYMMETRIC: [(&str, &str); 3] =
    [("Zwdot", "Yvdot"), ("Mqdot", "Nrdot"), ("Zqdot", "-Yrdot")];
