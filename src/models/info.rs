//! What the catalog says about each generated model: its name, family, layouts and cost.

use super::{CATALOG, Family, Kinematics, Symmetry};
use eom_kernel::Operations;

/// One generated variant, as the catalog lists it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ModelInfo {
    /// The generated module's name: `spatial_xz_quaternion`.
    pub name: &'static str,
    /// The typed model's name in [`crate::models`]: `SpatialXzQuaternion`.
    pub type_name: &'static str,
    /// One line on what it is and which equations it implements.
    pub title: &'static str,
    /// Its family.
    pub family: Family,
    /// A spatial model's symmetry class.
    pub symmetry: Option<Symmetry>,
    /// A spatial model's or a top's attitude kinematics.
    pub kinematics: Option<Kinematics>,
    /// The state layout, as the model names its entries.
    pub state: &'static [&'static str],
    /// The input layout.
    pub inputs: &'static [&'static str],
    /// What one call costs.
    pub operations: Operations,
    /// Whether the model has a potential energy of its own (the pendulum's and the top's
    /// weight): [`Model::potential_energy`](super::Model::potential_energy) gives it.
    pub potential_energy: bool,
}

impl ModelInfo {
    /// The variant with this module name.
    ///
    /// ```
    /// use eom::models::ModelInfo;
    /// let info = ModelInfo::find("pendulum").unwrap();
    /// assert_eq!(info.state, ["theta", "theta_dot"]);
    /// ```
    pub fn find(name: &str) -> Option<&'static ModelInfo> {
        CATALOG.iter().find(|info| info.name == name)
    }

    /// Every variant of a family, in catalog order.
    pub fn of_family(family: Family) -> impl Iterator<Item = &'static ModelInfo> {
        CATALOG.iter().filter(move |info| info.family == family)
    }

    /// The spatial variant of a symmetry class and kinematics (the catalog has every pair).
    pub fn spatial(symmetry: Symmetry, kinematics: Kinematics) -> Option<&'static ModelInfo> {
        CATALOG
            .iter()
            .find(|info| info.symmetry == Some(symmetry) && info.kinematics == Some(kinematics))
    }

    /// The unpruned variant this one is measured against: for a spatial model, the full
    /// tensor with the same kinematics; any other model is its own.
    pub fn full_variant(&self) -> &'static ModelInfo {
        match (self.symmetry, self.kinematics) {
            (Some(_), Some(kinematics)) => Self::spatial(Symmetry::Full, kinematics),
            _ => Self::find(self.name),
        }
        .expect("the catalog lists the full variant of every kinematics")
    }
}
