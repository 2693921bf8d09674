//! A ship scene's wind checked, methods of the checker every scene's tables are checked by
//! ([`Checker`]): `[windage]` (the areas, and the coefficients as a table or by Isherwood's
//! regression, never both) and the wind's keys of `[environment]`.

use super::coefficients::{Isherwood, WindCoefficients, WindTableError};
use super::gust::{Gust, GustError, Spectrum};
use super::{Wind, Windage};
use crate::kinds::ship::file::{EnvironmentTable, WindageTable};
use crate::scene::check::Checker;
use crate::scene::{Problem, SceneError};

/// ρ_a where the scene gives none, kg/m³: the standard atmosphere's at sea level (15 °C).
pub const AIR_DENSITY: f64 = 1.225;

/// The wind's height above the sea where the scene gives none, m: the reference height of
/// wind speeds and of NORSOK's spectrum.
pub const WIND_HEIGHT_M: f64 = 10.0;

impl Checker<'_> {
    /// `[windage]`: the areas, the length overall, the air, and the coefficients.
    pub(in crate::kinds::ship) fn windage(
        &self,
        table: &WindageTable,
    ) -> Result<Windage, SceneError> {
        let key = |k: &str| format!("windage.{k}");
        let positive = |k: &str, value: Option<f64>| match value {
            Some(v) => self.positive(&key(k), v),
            None => Err(self.error(&key(k), Problem::Missing(key(k)))),
        };
        let length_overall = positive("length_overall_m", table.length_overall_m)?;
        let frontal_area = positive("frontal_area_m2", table.frontal_area_m2)?;
        let lateral_area = positive("lateral_area_m2", table.lateral_area_m2)?;
        let air_density = match table.air_density_kg_m3 {
            Some(v) => self.positive(&key("air_density_kg_m3"), v)?,
            None => AIR_DENSITY,
        };
        let (coefficients, isherwood) =
            self.wind_coefficients(table, [length_overall, frontal_area, lateral_area])?;
        Ok(Windage {
            coefficients,
            isherwood,
            frontal_area,
            lateral_area,
            length_overall,
            air_density,
        })
    }

    /// The coefficients: Isherwood's at the geometry (`coefficients = "isherwood"`), or the
    /// table's.
    fn wind_coefficients(
        &self,
        table: &WindageTable,
        [length_overall, frontal_area, lateral_area]: [f64; 3],
    ) -> Result<(WindCoefficients, Option<Isherwood>), SceneError> {
        let isherwood_keys = [
            ("beam_m", table.beam_m),
            ("superstructure_area_m2", table.superstructure_area_m2),
            ("perimeter_m", table.perimeter_m),
            ("centroid_from_bow_m", table.centroid_from_bow_m),
            ("masts", table.masts),
        ];
        let table_keys = [
            ("angles_deg", &table.angles_deg),
            ("C_X", &table.c_x),
            ("C_Y", &table.c_y),
            ("C_N", &table.c_n),
        ];
        let by_table = |e: WindTableError| match e {
            WindTableError::Invalid { key, reason } => self.invalid(key, reason),
        };
        match table.coefficients.as_deref() {
            Some("isherwood") => {
                if let Some((k, _)) = table_keys.iter().find(|(_, v)| v.is_some()) {
                    return Err(self.invalid(
                        &format!("windage.{k}"),
                        "the coefficients are Isherwood's (coefficients = \"isherwood\"): \
                         leave the table out, or leave out `coefficients` to give your own",
                    ));
                }
                let [
                    beam,
                    superstructure_area,
                    perimeter,
                    centroid_from_bow,
                    masts,
                ] = isherwood_keys.map(|(k, v)| {
                    v.ok_or_else(|| {
                        let path = format!("windage.{k}");
                        self.error(&path, Problem::Missing(format!("{path} (Isherwood's)")))
                    })
                });
                let masts = masts?;
                if masts.fract() != 0.0 {
                    return Err(self.invalid(
                        "windage.masts",
                        format!("{masts}: a count of groups of masts, a whole number"),
                    ));
                }
                let geometry = Isherwood {
                    length_overall,
                    beam: beam?,
                    lateral_area,
                    frontal_area,
                    superstructure_area: superstructure_area?,
                    perimeter: perimeter?,
                    centroid_from_bow: centroid_from_bow?,
                    masts,
                };
                let coefficients = geometry.coefficients().map_err(by_table)?;
                Ok((coefficients, Some(geometry)))
            }
            Some(other) => Err(self.invalid(
                "windage.coefficients",
                format!(
                    "`{other}`: the regression known is \"isherwood\"; for a table of your own \
                     leave `coefficients` out and give angles_deg, C_X, C_Y, C_N"
                ),
            )),
            None => {
                if let Some((k, _)) = isherwood_keys.iter().find(|(_, v)| v.is_some()) {
                    return Err(self.invalid(
                        &format!("windage.{k}"),
                        "read by Isherwood's regression alone (coefficients = \"isherwood\")",
                    ));
                }
                let [angles, x, y, n] = table_keys.map(|(k, v)| {
                    v.clone().ok_or_else(|| {
                        let path = format!("windage.{k}");
                        let what = format!(
                            "{path} (a table of coefficients, or coefficients = \"isherwood\")"
                        );
                        self.error(&path, Problem::Missing(what))
                    })
                });
                let coefficients = WindCoefficients::new(&angles?, [x?, y?, n?]);
                Ok((coefficients.map_err(by_table)?, None))
            }
        }
    }

    /// The wind of `[environment]`: a speed (≥ 0) from a direction, both given, on a ship with
    /// a windage; gusting from a named spectrum with a seed, or steady.
    pub(in crate::kinds::ship) fn wind(
        &self,
        table: &EnvironmentTable,
        has_windage: bool,
    ) -> Result<Option<Wind>, SceneError> {
        let key = |k: &str| format!("environment.{k}");
        let gust_keys = [
            ("wind_spectrum", table.wind_spectrum.is_some()),
            ("wind_seed", table.wind_seed.is_some()),
            ("wind_height_m", table.wind_height_m.is_some()),
        ];
        let given = self.speed_and_direction(
            (&key("wind_m_s"), table.wind_m_s),
            (&key("wind_from_deg"), table.wind_from_deg),
            [
                "the wind's speed",
                "the direction the wind blows from",
                "it blows from",
            ],
        )?;
        let Some((speed, from)) = given else {
            return match gust_keys.iter().find(|(_, given)| *given) {
                Some((k, _)) => Err(self.error(
                    &key("wind_m_s"),
                    Problem::Missing(format!("the mean wind that {} is of", key(k))),
                )),
                None => Ok(None),
            };
        };
        if !has_windage {
            return Err(self.invalid(
                &key("wind_m_s"),
                "the wind acts on the ship through its coefficients and areas: give [windage]",
            ));
        }
        let from = self.finite(&key("wind_from_deg"), from)?.to_radians();
        let gust = self.gust(table, speed)?;
        Ok(Some(Wind { speed, from, gust }))
    }

    /// The gusts: none without a spectrum; with one, its seed is required.
    fn gust(&self, table: &EnvironmentTable, speed: f64) -> Result<Option<Gust>, SceneError> {
        let key = |k: &str| format!("environment.{k}");
        let Some(name) = &table.wind_spectrum else {
            return match (table.wind_seed, table.wind_height_m) {
                (None, None) => Ok(None),
                (Some(_), _) => Err(self.invalid(
                    &key("wind_seed"),
                    "the seed draws gusts from a spectrum: give wind_spectrum, or leave the \
                     seed out for a steady wind",
                )),
                (None, Some(_)) => Err(self.invalid(
                    &key("wind_height_m"),
                    "the height is the gust spectrum's: give wind_spectrum, or leave it out",
                )),
            };
        };
        let seed = table.wind_seed.ok_or_else(|| {
            self.error(
                &key("wind_seed"),
                Problem::Missing("the seed the gusts are drawn with".into()),
            )
        })?;
        let height = table.wind_height_m.unwrap_or(WIND_HEIGHT_M);
        let spectrum = Spectrum::named(name, speed, height).map_err(|e| match e {
            GustError::Invalid { key, reason } => self.invalid(key, reason),
        })?;
        Ok(Some(Gust::new(spectrum, seed)))
    }
}
