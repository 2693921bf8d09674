//! An MMG scene's own checks, methods of the checker every scene's tables are checked by
//! ([`Checker`]): the body in SI, the method's coefficients and particulars by the names of
//! `data/kvlcc2_mmg.json`, the keys a polynomial table has and an MMG table has not, and the
//! propeller rate that balances the approach.

use std::collections::BTreeMap;

use super::parameters::{MMG_COEFFICIENTS, MMG_PARTICULARS, MmgParameters};
use crate::kinds::ship::file::ShipSceneFile;
use crate::kinds::ship::table::ShipTable;
use crate::kinds::ship::{ShipError, Units};
use crate::scene::check::Checker;
use crate::scene::{Problem, SceneError};

impl Checker<'_> {
    /// An MMG table (`model = "mmg"`): the body in SI, ρ, the approach speed, the method's
    /// coefficients by the names of `data/kvlcc2_mmg.json` and the particulars B, d, D_P,
    /// H_R, A_R (L and x_G are the body's); the propeller rate that balances the approach is
    /// solved here.
    pub(in crate::kinds::ship) fn mmg_table(
        &self,
        file: &ShipSceneFile,
    ) -> Result<(ShipTable, f64), SceneError> {
        let hydro = &file.hydrodynamics;
        self.none_of(
            [
                ("units", hydro.units.is_some()),
                ("rigid_body_terms", hydro.rigid_body_terms.is_some()),
            ],
            "an MMG table's units are the method's own (the body in SI, the coefficients on \
             ½ρLdU², ½ρL²dU², ½ρL²d, ½ρL⁴d): leave it out",
        )?;
        if file.propulsion.is_some() {
            return Err(self.invalid(
                "propulsion",
                "an MMG ship's propeller is in its coefficients (t_P, w_P0, k_0 …) and \
                 particulars (D_P): leave [propulsion] out",
            ));
        }
        let density = hydro.density.ok_or_else(|| {
            self.error(
                "hydrodynamics.density",
                Problem::Missing("an MMG table needs ρ".into()),
            )
        })?;
        let density = self.positive("hydrodynamics.density", density)?;
        let speed = self.positive("hydrodynamics.design_speed", hydro.design_speed)?;
        let (body, length) = self.ship_body(&file.body, Units::Dimensional)?;
        let mut particulars = hydro.particulars.clone().unwrap_or_default();
        self.known_names(
            "hydrodynamics.coefficients",
            &hydro.coefficients,
            &MMG_COEFFICIENTS,
        )?;
        self.known_names("hydrodynamics.particulars", &particulars, &MMG_PARTICULARS)?;
        particulars.insert("L".into(), length);
        particulars.insert("x_G".into(), body.x_g);
        let parameters = MmgParameters::from_values(&hydro.coefficients, &particulars, density)
            .map_err(|e| self.invalid(&format!("hydrodynamics.{}", e.key()), e.to_string()))?;
        let held = (hydro.propeller_rate_rps)
            .map(|rate| self.positive("hydrodynamics.propeller_rate_rps", rate))
            .transpose()?;
        let table = ShipTable::mmg(body, parameters, (speed, held)).map_err(|e| match e {
            ShipError::Invalid { key, reason } => self.invalid(&key, reason),
            other => self.invalid("hydrodynamics", other.to_string()),
        })?;
        Ok((table, length))
    }

    /// Refuses the first of the `[hydrodynamics]` keys `given` that the table's form does not
    /// read, saying `why`.
    pub(in crate::kinds::ship) fn none_of(
        &self,
        given: [(&str, bool); 2],
        why: &str,
    ) -> Result<(), SceneError> {
        match given.iter().find(|(_, present)| *present) {
            Some((key, _)) => Err(self.invalid(&format!("hydrodynamics.{key}"), why)),
            None => Ok(()),
        }
    }

    /// Refuses a name of `given` that is not one of `known`, listing them.
    fn known_names(
        &self,
        key: &str,
        given: &BTreeMap<String, f64>,
        known: &[&str],
    ) -> Result<(), SceneError> {
        match given.keys().find(|name| !known.contains(&name.as_str())) {
            Some(name) => Err(self.invalid(
                &format!("{key}.{name}"),
                format!(
                    "not a name of an MMG table here; the names are {}",
                    known.join(", ")
                ),
            )),
            None => Ok(()),
        }
    }
}
