//! A vehicle's table as the scene gives it: the body, the hydrostatics, the added mass, the
//! named force terms under a declared convention and in their units (SI or the prime system),
//! and the propeller at its setting.

use super::cross_flow::CrossFlow;
use super::propeller::PropellerLaw;
use super::{AddedMassCoriolis, Convention, InertiaAbout};
use crate::defined::engine::Symmetry;
use std::collections::BTreeMap;

/// The controls a vehicle's terms may hold: the rudder δ_r and the stern planes δ_s (rad),
/// each a fin the scene's steering gear moves ([`super::fins`]).
pub const CONTROLS: [&str; 2] = ["dr", "ds"];

/// The factor of a term in the propeller law's ε ([`super::propeller`]), a control of the
/// table when the scene names the law: `n`, as the source's names write it (`Zqn`).
pub const EPSILON: &str = "n";

/// The propeller at its setting: constant thrust and torque on the body, and the law they
/// come from, if the scene names one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PropellerSetting {
    /// X_prop, N, along body x.
    pub thrust: f64,
    /// K_prop, N m, about body x (the propeller's reaction on the hull).
    pub torque: f64,
    /// The law in the propeller's rate, whose ε the table's terms in `n` multiply.
    pub law: Option<PropellerLaw>,
}

/// The scales of a table in the prime system: ½ρL^(2 + a + m)·u^(2 − j) per term of j
/// velocity factors, a of them angular, m = 1 for a moment; ½ρL^(3 + m + a) per added-mass
/// entry (`eom_codegen::model::vehicle`, the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrimeScales {
    /// ρ, kg/m³.
    pub density: f64,
    /// L, m.
    pub length: f64,
}

/// The numbers of a vehicle, checked by the scene ([`super::scene`]): the body in SI, the
/// hydrodynamic table in SI or in the prime system.
#[derive(Debug, Clone, PartialEq)]
pub struct VehicleTable {
    /// M, kg.
    pub mass: f64,
    /// W, N.
    pub weight: f64,
    /// B, N.
    pub buoyancy: f64,
    /// r_G from the table's origin O, m, body axes.
    pub centre_of_gravity: [f64; 3],
    /// r_B from O, m, body axes.
    pub centre_of_buoyancy: [f64; 3],
    /// The inertia tensor `[[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]]`, kg m², about
    /// the point `inertia_about` says, body axes; its products with the chapter's sign,
    /// Ixy = −∫xy dm (4.14), so H = \[I\]ω.
    pub inertia: [[f64; 3]; 3],
    /// The point the tensor is about: G (the default) or the table's origin O.
    pub inertia_about: InertiaAbout,
    /// How the table's names are read.
    pub convention: Convention,
    /// Whether the table's cross terms hold Kirchhoff's terms or eom adds them.
    pub added_mass_coriolis: AddedMassCoriolis,
    /// The added-mass entries by name (`Xudot`, `Yrdot`, …).
    pub added_mass: BTreeMap<String, f64>,
    /// The force terms by name (`Yvv`, `Yuudr`, …).
    pub coefficients: BTreeMap<String, f64>,
    /// The propeller, if it acts.
    pub propeller: Option<PropellerSetting>,
    /// The prime system's scales, if the added mass and the terms are given in it.
    pub prime: Option<PrimeScales>,
    /// The cross-flow drag in strips, if the scene gives it.
    pub cross_flow: Option<CrossFlow>,
}

impl VehicleTable {
    /// The propeller's law, if the scene names one.
    pub fn propeller_law(&self) -> Option<PropellerLaw> {
        self.propeller.and_then(|p| p.law)
    }

    /// The products of inertia the tensor sets to zero, as the smallest symmetry class that
    /// holds them: every product zero is principal axes, Ixy = Iyz = 0 the x–z plane of
    /// symmetry; the model is built with the class's products pruned.
    pub(crate) fn symmetry(&self) -> Symmetry {
        let [[_, xy, xz], [_, _, yz], _] = self.inertia;
        match (xy == 0.0 && yz == 0.0, xz == 0.0) {
            (true, true) => Symmetry::Principal,
            (true, false) => Symmetry::Xz,
            (false, _) => Symmetry::Full,
        }
    }

    /// The same vehicle with its products Ixy and Iyz taken off (Ixz kept): a body with the
    /// x–z plane as a plane of symmetry, whose port and starboard turns can mirror each other.
    pub fn without_lateral_products(&self) -> Self {
        let mut table = self.clone();
        for (r, c) in [(0, 1), (1, 0), (1, 2), (2, 1)] {
            table.inertia[r][c] = 0.0;
        }
        table
    }

    /// The same vehicle with its propeller torque taken off (thrust kept): the vehicle whose
    /// port and starboard turns mirror each other.
    pub fn without_propeller_torque(&self) -> Self {
        let mut table = self.clone();
        if let Some(propeller) = table.propeller.as_mut() {
            propeller.torque = 0.0;
        }
        table
    }
}
