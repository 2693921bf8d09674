//! Model selection: "model only what a scene requires".
//!
//! A spatial scene says its kinematics; its symmetry class is what the scene says, or with
//! `symmetry = "auto"` the most pruned class the tensor allows: every product the class
//! prunes must be zero to [`PRODUCT_TOLERANCE`] of the largest moment (1e-12: round-off of a
//! computed tensor, far below any product that changes the motion). The other families have
//! one model each.

use crate::InertiaTensor;
use crate::models::{CATALOG, Kinematics, ModelInfo, PRODUCT_TOLERANCE, Symmetry};

/// The model a scene runs, and why.
#[derive(Debug, Clone)]
pub struct Selection {
    /// The catalog entry.
    pub info: &'static ModelInfo,
    /// Why this variant, in one sentence for the run's summary.
    pub reason: String,
}

impl Selection {
    /// The one model of a family that has one.
    pub(crate) fn only(info: &'static ModelInfo) -> Self {
        Self {
            info,
            reason: format!("the {} family has one model", info.family.name()),
        }
    }
}

/// The value of a product of inertia named as the chapter names it.
fn product(inertia: &InertiaTensor, name: &str) -> f64 {
    match name {
        "Ixy" => inertia.ixy(),
        "Iyz" => inertia.iyz(),
        _ => inertia.izx(),
    }
}

/// Whether every product `symmetry` prunes is zero to the tolerance.
fn allows(inertia: &InertiaTensor, symmetry: Symmetry) -> bool {
    let scale = inertia.ixx().max(inertia.iyy()).max(inertia.izz());
    symmetry
        .pruned()
        .iter()
        .all(|p| product(inertia, p).abs() <= PRODUCT_TOLERANCE * scale)
}

/// The spatial variant for a body: of the class given, or with `None` ("auto") the most
/// pruned class the tensor allows.
pub fn select_spatial(
    inertia: &InertiaTensor,
    symmetry: Option<Symmetry>,
    kinematics: Kinematics,
) -> Result<Selection, String> {
    let (symmetry, reason) = match symmetry {
        Some(s) if allows(inertia, s) => {
            (s, format!("symmetry = \"{}\" as the scene says", s.name()))
        }
        Some(s) => {
            let offending: Vec<String> = s
                .pruned()
                .iter()
                .filter(|p| !allows_one(inertia, p))
                .map(|p| format!("{p} = {}", product(inertia, p)))
                .collect();
            return Err(format!(
                "the {} class needs {} = 0, but the tensor has {}; use \"auto\" or \"full\"",
                s.name(),
                s.pruned().join(" = "),
                offending.join(", ")
            ));
        }
        None => auto(inertia),
    };
    let info = ModelInfo::spatial(symmetry, kinematics).ok_or_else(|| {
        format!(
            "the catalog has no {} {} variant",
            symmetry.name(),
            kinematics.name()
        )
    })?;
    Ok(Selection { info, reason })
}

fn allows_one(inertia: &InertiaTensor, name: &str) -> bool {
    let scale = inertia.ixx().max(inertia.iyy()).max(inertia.izz());
    product(inertia, name).abs() <= PRODUCT_TOLERANCE * scale
}

/// The class with the most pruned products that the tensor allows.
fn auto(inertia: &InertiaTensor) -> (Symmetry, String) {
    let best = Symmetry::ALL
        .into_iter()
        .filter(|s| allows(inertia, *s))
        .max_by_key(|s| s.pruned().len())
        .unwrap_or(Symmetry::Full);
    let zero = best.pruned();
    let kept: Vec<String> = ["Ixy", "Iyz", "Ixz"]
        .into_iter()
        .filter(|p| !zero.contains(p))
        .map(|p| format!("{p} = {}", product(inertia, p)))
        .collect();
    let mut reason = format!("symmetry = \"auto\": {}", best.name());
    if !zero.is_empty() {
        reason += &format!(
            ", since {} = 0 (to {PRODUCT_TOLERANCE:e} of the largest moment)",
            zero.join(" = ")
        );
    }
    if !kept.is_empty() {
        reason += &format!(
            "{} {}",
            if zero.is_empty() { ", since" } else { " and" },
            kept.join(", ")
        );
        reason += " must be kept";
    }
    debug_assert!(CATALOG.iter().any(|i| i.symmetry == Some(best)));
    (best, reason)
}
