//! What the catalog says about each generated model: its name, family, layouts and cost.

use super::{CATALOG, Family, Kinematics, Symmetry};

/// Operations one call of a generated right-hand side performs (`sin_cos` of one angle counts
/// as one trigonometric call).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Operations {
    /// Additions, subtractions and negations.
    pub add: u32,
    /// Multiplications.
    pub mul: u32,
    /// Divisions and reciprocals.
    pub div: u32,
    /// Square roots.
    pub sqrt: u32,
    /// Trigonometric calls.
    pub trig: u32,
}

impl Operations {
    /// From a generated module's `OPERATIONS` table (add, mul, div, sqrt, trig, in that order).
    pub const fn from_table(table: [(&str, u32); 5]) -> Self {
        Self {
            add: table[0].1,
            mul: table[1].1,
            div: table[2].1,
            sqrt: table[3].1,
            trig: table[4].1,
        }
    }

    /// Additions, multiplications and divisions together.
    pub const fn arithmetic(&self) -> u32 {
        self.add + self.mul + self.div
    }
}

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
