//! Underwater vehicles in six degrees of freedom about their table's origin O, on their own
//! hydrodynamic tables.
//!
//! The equations are the proved ones of [`crate::derivation::vehicle`]: 4.1 and 4.2 about O
//! with G at r_G (in three dimensions what 4.45 does to 4.43), with the tensor about O given
//! or computed by Steiner (4.23) from the tensor about G. The implicit form is
//!
//! ```text
//! (M_RB + M_A) ν̇ = τ_table + τ_propeller + τ_restoring + τ_applied − C_RB(ν)ν − C_A(ν)ν
//! ```
//!
//! with ν = (u, v, w, p, q, r) in body axes at O, and
//! - M_A the symmetric added-mass matrix, −(the table's acceleration derivatives): each named
//!   entry (`Yrdot`) fills its symmetric partner (`Nvdot`), a name given for both is one
//!   parameter whose two values must agree ([`VehicleSpec::mass_matrix_values`]);
//! - C_A(ν)ν Kirchhoff's terms from T_A = ½νᵀM_Aν ([`AddedMassCoriolis::Derived`]), or none
//!   where the table's cross terms already hold them ([`AddedMassCoriolis::Folded`], checked
//!   coefficient by coefficient by [`folded_comparison`]);
//! - τ_table the table's named terms and nothing else (see [`names`] for how a name is read);
//!   a signed square x|x| reads |x| from an input `abs_x` that the caller sets to the absolute
//!   value of x (the one quantity that is not a polynomial, as the ship's speed U is in the
//!   prime system), so every proof stays exact; ∂f/∂x then holds the x in x|x| and ∂f/∂u the
//!   |x|, and the caller adds ∂f/∂abs_x · sign(x) to the column of x;
//! - τ_restoring the weight W at G and the buoyancy B at B, vertical in space axes with Z down
//!   (NED), turned into body axes by the attitude: f = (W − B)k_b, m = r_G × W k_b − r_B × B k_b
//!   with k_b = Rᵀ(0, 0, 1); for a quaternion R is its matrix, |q|² times a rotation, as for the
//!   heavy top, so the potential below is exact along q̇ = ½ q ⊗ (0, ω).
//!
//! The table is in SI ([`Units::Dimensional`]) or in the prime system ([`Units::Prime`]) of
//! the standard submarine equations, as Healey & Lienard (1993) give the NPS AUV II and
//! Fossen's MSS `npsauv.m` scales it: with ρ and the length L (parameters `rho`, `L`) and the
//! speed U = u, the surge velocity, a term of j velocity factors, a of them angular, adds
//! ½ρL^(2 + a + m)·u^(2 − j) times its prime coefficient and its product in SI, m = 1 for a
//! moment (K, M, N) and 0 for a force; that is ½ρL²U² times the coefficient and the product
//! of v/U, w/U, pL/U, qL/U, rL/U (a force) or ½ρL³U² times it (a moment), so `Yv` adds
//! ½ρL²·Y′_v·u·v, `Kp` ½ρL⁴·K′_p·u·p, `Ydr` ½ρL²·Y′_δr·u²·δ_r, `Xvv` ½ρL²·X′_vv·v². An
//! added-mass entry of a load and a velocity is ½ρL^(3 + m + a) times its prime value, a = 1
//! for an angular velocity (M_A = ½ρL³·T⁻¹M′_AT⁻¹, T⁻¹ = diag(1, 1, 1, L, L, L)). The controls
//! are angles, without units. A term of more than two velocity factors would divide by u and
//! is refused; two names that give the same product once u is written out (`Yv`, `Yuv`) are
//! one term. The body (mass, inertia, r_G, weight, buoyancy, r_B) stays in SI. The scaling is
//! part of the derived residuals, so the program's proof covers it.
//!
//! The mass matrix is constant but a general symmetric 6×6 of many parameters, whose symbolic
//! inverse is too large to be worth emitting; it is inverted numerically once per parameter
//! set, by Cholesky ([`VehicleSpec::inverse_mass_matrix`], which also refuses a matrix that is
//! not positive definite and names its entries), and its 21 entries are parameters `minv_uu`,
//! `minv_uv`, … of the system. What is proved symbolically is the implicit form and that the
//! outputs are exactly ν̇ = −M⁻¹·bias with bias the rest of the proved residuals (staged as
//! `bias_u` … `bias_r`); the inverse is checked numerically, ‖M·M⁻¹ − 𝟙‖ ≤ 1e-9.

mod folded;
mod mass;
pub mod names;
mod spec;

pub use folded::{FoldedComparison, FoldedTerm, folded_comparison, folded_terms, format_folded};
pub use names::{
    AddedMassEntry, Convention, Factor, ForceTerm, Load, NameError, parse_added_mass, parse_term,
};

use super::families::{
    euler_kinematics, euler_kinematics_expected, quaternion_kinematics, verify_outputs,
    verify_quaternion_position,
};
use super::ship::Units;
use super::system::{BuildError, Group, System};
use super::{Kinematics, Symmetry};
use crate::derivation::quaternion::quaternion_rates;
use crate::derivation::vehicle::VELOCITIES;
use crate::symbolic::{Expr, SymbolicError};
use std::collections::BTreeSet;
use std::sync::Mutex;
use thiserror::Error;

/// About which point the spec gives the inertia tensor.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum InertiaAbout {
    /// About the table's origin O: `Ixx` … `Ixz`, used as given.
    Origin,
    /// About G: `Ixx_G` … `Ixz_G`, carried to O by Steiner (4.23).
    Gravity,
}

/// Whether eom adds the added mass's Coriolis and centripetal terms.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AddedMassCoriolis {
    /// eom derives them (Kirchhoff) and adds them.
    Derived,
    /// The table's cross terms already hold them (Prestero's Xwq, Ywp, Mrp, …).
    Folded,
}

/// How the propeller's thrust X_prop and torque K_prop enter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Propeller {
    /// No propeller loads (or the table's own terms in a control, `Xn|n|`).
    None,
    /// Constant at a setting: parameters `X_prop` (N) and `K_prop` (N m).
    Constant,
    /// Inputs `X_prop` and `K_prop`, set by the caller at every step.
    Input,
}

/// What a vehicle model is made of. The numbers are given later, as parameters.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct VehicleSpec {
    /// The units of the hydrodynamic table: SI, or the prime system (see the module docs;
    /// the body stays in SI).
    pub units: Units,
    /// How the attitude is carried.
    pub kinematics: Kinematics,
    /// About which point the inertia tensor is given.
    pub inertia: InertiaAbout,
    /// Which products of the given tensor are zero.
    pub symmetry: Symmetry,
    /// How the table's names are read.
    pub convention: Convention,
    /// The controls the table's terms may hold (`dr`, `ds`), inputs of the model.
    pub controls: Vec<String>,
    /// The added-mass entries by name (`Xudot`, `Yrdot`, …).
    pub added_mass: Vec<String>,
    /// Whether eom adds Kirchhoff's terms.
    pub added_mass_coriolis: AddedMassCoriolis,
    /// The force table's terms by name (`Yvv`, `Yuudr`, `Yv|v|`).
    pub terms: Vec<String>,
    /// The propeller's thrust and torque.
    pub propeller: Propeller,
    /// Whether the weight and the buoyancy act (parameters `weight`, `buoyancy`, r_B).
    pub hydrostatics: bool,
    /// Whether six more inputs `F_x` … `M_z` carry loads about O beyond the table.
    pub applied_loads: bool,
}

/// Why a vehicle model could not be built or its numbers not used.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum VehicleError {
    /// A name of the table was not read.
    #[error(transparent)]
    Name(#[from] NameError),
    /// A name is listed twice.
    #[error("the table lists `{0}` twice")]
    ListedTwice(String),
    /// Two names of the table are read as the same term.
    #[error("`{0}` and `{1}` are the same term ({2})")]
    SameTerm(String, String, String),
    /// A control's name that could be read otherwise, or clashes.
    #[error("the control `{name}` is refused: {why}")]
    Control {
        /// The control.
        name: String,
        /// Why.
        why: String,
    },
    /// A symbol of the model would be the same identifier as another.
    #[error("`{0}` and `{1}` would be the same identifier in the generated code")]
    Clash(String, String),
    /// What the generator does not do yet.
    #[error("{0}")]
    Unsupported(String),
    /// A value the numeric step needs is missing or not finite.
    #[error("no finite value for `{0}`")]
    MissingValue(String),
    /// An added-mass entry given under both names, with two values.
    #[error(
        "the added mass is symmetric, but `{name}` = {value} and its partner `{mirror}` = {mirror_value}"
    )]
    AsymmetricAddedMass {
        /// The entry's name.
        name: String,
        /// Its value.
        value: f64,
        /// The symmetric partner's name.
        mirror: String,
        /// Its value.
        mirror_value: f64,
    },
    /// The total mass matrix is not positive definite.
    #[error(
        "the total mass matrix M_RB + M_A is not positive definite: its leading {size}×{size} \
         block fails at {axis} (pivot {pivot:e}); the entries of that row: {entries}"
    )]
    NotPositiveDefinite {
        /// The velocity whose row fails.
        axis: &'static str,
        /// The size of the leading block that is not positive definite.
        size: usize,
        /// The Cholesky pivot left (≤ 0 or not finite).
        pivot: f64,
        /// The parameters of that row up to the diagonal, with their values.
        entries: String,
    },
    /// A term that the prime system cannot scale.
    #[error("`{name}` cannot be read in the prime system: {why}")]
    Prime {
        /// The term's name.
        name: String,
        /// Why.
        why: String,
    },
    /// The model could not be built or verified.
    #[error(transparent)]
    Build(#[from] BuildError),
}

/// The prime system's scales, by their symbols: the water's density ρ and the length L,
/// parameters of a prime-system vehicle after the hydrostatics.
pub const PRIME_SCALES: [&str; 2] = [DENSITY, LENGTH];
const DENSITY: &str = "rho";
const LENGTH: &str = "L";

pub(super) fn symbolic(name: &str) -> impl Fn(SymbolicError) -> VehicleError + '_ {
    move |source| {
        VehicleError::Build(BuildError::Symbolic {
            model: name.into(),
            source,
        })
    }
}

/// The input's name as `&'static str`, which the system's inputs are: the names a table
/// brings (its controls, `abs_dr`) are interned, each leaked once however often a vehicle is
/// built, so a runtime that builds one per scene does not grow.
fn interned(name: String) -> &'static str {
    static NAMES: Mutex<BTreeSet<&'static str>> = Mutex::new(BTreeSet::new());
    let mut names = NAMES
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    if let Some(known) = names.get(name.as_str()) {
        return known;
    }
    let leaked: &'static str = Box::leak(name.into_boxed_str());
    names.insert(leaked);
    leaked
}

/// The added-mass entries, one per symmetric pair, and the pairs (parameter, partner) of
/// the names given for both of a pair's entries.
pub type AddedMassEntries = (Vec<AddedMassEntry>, Vec<(String, String)>);

/// The name of an entry of (M_RB + M_A)⁻¹, `minv_uv`, upper triangle.
pub fn inverse_entry(i: usize, j: usize) -> String {
    format!("minv_{}{}", VELOCITIES[i.min(j)], VELOCITIES[i.max(j)])
}

/// The mass matrix of the residuals and the rest: residual = M ν̇ + rest, M of parameters
/// only, symmetric, checked exactly.
fn split(name: &str, residuals: &[Expr; 6]) -> Result<([[Expr; 6]; 6], [Expr; 6]), VehicleError> {
    let rates: Vec<String> = VELOCITIES.iter().map(|v| format!("{v}_dot")).collect();
    let matrix: [[Expr; 6]; 6] =
        std::array::from_fn(|i| std::array::from_fn(|j| residuals[i].coefficient_of(&rates[j])));
    let zeros: Vec<(&str, Expr)> = rates.iter().map(|r| (r.as_str(), Expr::zero())).collect();
    let mut rest: [Expr; 6] = std::array::from_fn(|_| Expr::zero());
    let fail = |what: String, residual: &Expr| {
        VehicleError::Build(BuildError::Verification {
            model: name.into(),
            what,
            residual: residual.to_string(),
        })
    };
    for i in 0..6 {
        rest[i] = residuals[i].subs_all(&zeros).map_err(symbolic(name))?;
        let rebuilt: Expr = (0..6)
            .map(|j| &matrix[i][j] * &Expr::symbol(&rates[j]))
            .sum::<Expr>()
            + &rest[i];
        let left = &residuals[i] - &rebuilt;
        if !left.is_zero() {
            return Err(fail(
                format!(
                    "equation {} is not linear in the accelerations",
                    Load::ALL[i].letter()
                ),
                &left,
            ));
        }
        for (j, entry) in matrix[i].iter().enumerate() {
            let moving = entry
                .symbols()
                .into_iter()
                .find(|s| VELOCITIES.contains(&s.as_str()) || rates.contains(s));
            if moving.is_some() || *entry != matrix[j][i] {
                return Err(fail(
                    format!("the mass matrix entry ({i}, {j}) is not constant and symmetric"),
                    &(entry - &matrix[j][i]),
                ));
            }
        }
    }
    Ok((matrix, rest))
}

/// The vehicle model of a spec: the six equations about O with the added mass, Kirchhoff's
/// terms (where derived), the table's terms, the propeller and the restoring loads, solved
/// as ν̇ = −(M_RB + M_A)⁻¹·bias with the inverse's entries as parameters; the position of O
/// in space axes and the attitude by the catalog's kinematics (4.57, 4.60, or the
/// quaternion's), each checked as the catalog checks them.
///
/// ```
/// use eom_codegen::model::ship::Units;
/// use eom_codegen::model::vehicle::*;
/// use eom_codegen::model::{Kinematics, Symmetry};
/// let spec = VehicleSpec {
///     units: Units::Dimensional,
///     kinematics: Kinematics::Quaternion,
///     inertia: InertiaAbout::Gravity,
///     symmetry: Symmetry::Principal,
///     convention: Convention::Fossen,
///     controls: vec!["dr".into()],
///     added_mass: vec!["Xudot".into(), "Yvdot".into(), "Nrdot".into()],
///     added_mass_coriolis: AddedMassCoriolis::Derived,
///     terms: vec!["Xu|u|".into(), "Yv|v|".into(), "Nuudr".into()],
///     propeller: Propeller::Input,
///     hydrostatics: true,
///     applied_loads: false,
/// };
/// let system = vehicle("small_auv", &spec).unwrap();
/// assert_eq!(system.inputs, ["dr", "X_prop", "K_prop", "abs_u", "abs_v"]);
/// let source = eom_codegen::emit::system_source(&system).unwrap();
/// assert!(source.contains("pub yv_abs_v: f64") && source.contains("pub minv_ur: f64"));
/// ```
pub fn vehicle(name: &str, spec: &VehicleSpec) -> Result<System, VehicleError> {
    let err = symbolic(name);
    let residuals = spec.residuals()?;
    let (_, rest) = split(name, &residuals)?;
    let bias_names: Vec<String> = VELOCITIES.iter().map(|v| format!("bias_{v}")).collect();
    let mut stages: Vec<(String, Expr)> = bias_names.iter().cloned().zip(rest.clone()).collect();
    let inverse = |i: usize, j: usize| Expr::symbol(&inverse_entry(i, j));
    let solved = |values: &dyn Fn(usize) -> Expr| -> Vec<Expr> {
        (0..6)
            .map(|i| -(0..6).map(|j| inverse(i, j) * values(j)).sum::<Expr>())
            .collect()
    };
    let mut outputs = solved(&|j| Expr::symbol(&bias_names[j]));
    let mut expected: Vec<Expr> = solved(&|j| rest[j].clone());
    let (kinematic_stages, kinematic_outputs, kinematic_equations) = match spec.kinematics {
        Kinematics::Euler => {
            let (s, o) = euler_kinematics();
            expected.extend(euler_kinematics_expected(name)?);
            (s, o, ["4.57", "4.60"])
        }
        Kinematics::Quaternion => {
            let (s, o) = quaternion_kinematics(name)?;
            (s, o, ["4.57 q", "4.60 q"])
        }
    };
    stages.extend(kinematic_stages);
    outputs.extend(kinematic_outputs);
    let parameters = spec.parameters()?;
    let inputs: Vec<&'static str> = spec.inputs()?.into_iter().map(interned).collect();
    let mut equations = vec!["4.1", "4.2", "4.5", "4.23", "4.48", "4.50"];
    equations.extend(kinematic_equations);
    let system = System {
        name: name.into(),
        title: "Underwater vehicle in six degrees of freedom about its table's origin O".into(),
        equations,
        parameters,
        reciprocals: vec![],
        state: spec.state(),
        inputs,
        stages,
        outputs,
        groups: groups(spec),
        kinetic_energy: Some(spec.kinetic_energy()?),
        energy_formula: Some(
            "T = ½M|v + ω × r_G|² + ½ωᵀ[I_G]ω + ½νᵀM_Aν, the body's and the fluid's",
        ),
        potential_energy: spec.hydrostatics.then(|| spec.potential_energy()),
        potential_formula: spec
            .hydrostatics
            .then_some("V = (B − W)z − (W r_G − B r_B)·k_b, Z down, k_b = Rᵀ(0, 0, 1)"),
        coefficient_names: vec![],
    };
    check_identifiers(&system)?;
    let mut checks: Vec<(usize, Expr)> = expected.into_iter().enumerate().collect();
    if spec.kinematics == Kinematics::Quaternion {
        let rates = quaternion_rates().map_err(&err)?;
        checks.extend((9..13).zip(rates.0));
        verify_quaternion_position(&system)?;
    }
    verify_outputs(&system, &checks)?;
    Ok(system)
}

/// No two symbols of the system may become the same identifier in the generated code.
fn check_identifiers(system: &System) -> Result<(), VehicleError> {
    let mut seen: Vec<(String, String)> = Vec::new();
    let symbols = system
        .parameters
        .iter()
        .map(|p| p.symbol.to_string())
        .chain(system.state.iter().map(|s| s.to_string()))
        .chain(system.inputs.iter().map(|s| s.to_string()))
        .chain(system.stages.iter().map(|(s, _)| s.clone()));
    for symbol in symbols {
        let identifier = crate::emit::identifier(&symbol);
        if let Some((other, _)) = seen.iter().find(|(_, id)| *id == identifier) {
            return Err(VehicleError::Clash(other.clone(), symbol));
        }
        seen.push((symbol, identifier));
    }
    Ok(())
}

fn groups(spec: &VehicleSpec) -> Vec<Group> {
    let fluid = match spec.added_mass_coriolis {
        AddedMassCoriolis::Derived => "− C_A(ν)ν (Kirchhoff) ",
        AddedMassCoriolis::Folded => "(C_A folded into the table) ",
    };
    let (position, attitude) = match spec.kinematics {
        Kinematics::Euler => (
            "4.57: the position of O in space axes, E·v one rotation at a time",
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
            comment: format!(
                "4.1, 4.2 about O (4.5, 4.23): (M_RB + M_A)ν̇ = τ − C_RB(ν)ν {fluid}+ restoring, \
                 ν̇ = −(M_RB + M_A)⁻¹ bias"
            ),
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
