//! The water and the air around a ship, as a run reports them: the current, the wind and its
//! gusts, the ship's windage, and what that makes of the figures, over ground or through the
//! water (`summary.json`'s `model.environment`, and a line of the text report).

use super::summary::as_given;
use super::table::ShipTable;
use super::wind::Gust;
use super::wind::gust::{HIGHEST_FREQUENCY, Spectrum};
use serde::Serialize;

/// What the figures are measured against where the ship drifts.
pub const FIGURES_OVER: &str = "over ground: the advance, the transfer, the tactical diameter \
     and the drift (from the track X, Y); through the water: the speeds, the steady turning \
     radius and trajectory.csv's u, v";

/// The current, the wind and the windage of a scene that has any.
#[derive(Debug, Clone, Serialize)]
pub struct EnvironmentSummary {
    /// The current, where the scene gives one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub current: Option<CurrentSummary>,
    /// The wind, where the scene gives one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wind: Option<WindSummary>,
    /// The ship's windage, where the scene gives one (in still air it is the ship's own air
    /// resistance).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub windage: Option<WindageSummary>,
    /// What the figures are measured against ([`FIGURES_OVER`]).
    pub figures: &'static str,
}

/// A uniform current.
#[derive(Debug, Clone, Serialize)]
pub struct CurrentSummary {
    /// Its speed, m/s.
    pub speed_m_s: f64,
    /// The direction it flows toward, degrees clockwise from north.
    pub toward_deg: f64,
}

/// A wind.
#[derive(Debug, Clone, Serialize)]
pub struct WindSummary {
    /// Its mean speed, m/s.
    pub speed_m_s: f64,
    /// The direction it blows from, degrees clockwise from north.
    pub from_deg: f64,
    /// Its gusts, where it gusts.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gust: Option<GustSummary>,
}

/// A wind's gusts: the spectrum, the seed, and the variance the series holds.
#[derive(Debug, Clone, Serialize)]
pub struct GustSummary {
    /// `norsok`.
    pub spectrum: &'static str,
    /// The seed drawn with.
    pub seed: u64,
    /// The height above the sea, m.
    pub height_m: f64,
    /// The series' standard deviation, m/s.
    pub sigma_m_s: f64,
    /// The whole spectrum's, m/s.
    pub spectrum_sigma_m_s: f64,
    /// The highest frequency the series holds, Hz.
    pub highest_frequency_hz: f64,
}

/// The ship above water.
#[derive(Debug, Clone, Serialize)]
pub struct WindageSummary {
    /// `isherwood` (Isherwood's regression at the ship's geometry, 1972) or `table` (the
    /// scene's own).
    pub coefficients: &'static str,
    /// A_F, m².
    pub frontal_area_m2: f64,
    /// A_L, m².
    pub lateral_area_m2: f64,
    /// L_oa, m.
    pub length_overall_m: f64,
    /// ρ_a, kg/m³.
    pub air_density_kg_m3: f64,
}

impl EnvironmentSummary {
    /// The environment of `table`; `None` for a ship in still water and no air.
    pub fn of(table: &ShipTable) -> Option<Self> {
        if table.current.is_none() && table.windage.is_none() {
            return None;
        }
        Some(EnvironmentSummary {
            current: table.current.map(|c| CurrentSummary {
                speed_m_s: c.speed,
                toward_deg: as_given(c.toward),
            }),
            wind: table.wind.as_ref().map(|w| WindSummary {
                speed_m_s: w.speed,
                from_deg: as_given(w.from),
                gust: w.gust.as_ref().map(GustSummary::of),
            }),
            windage: table.windage.as_ref().map(|w| WindageSummary {
                coefficients: match w.isherwood {
                    Some(_) => "isherwood",
                    None => "table",
                },
                frontal_area_m2: w.frontal_area,
                lateral_area_m2: w.lateral_area,
                length_overall_m: w.length_overall,
                air_density_kg_m3: w.air_density,
            }),
            figures: FIGURES_OVER,
        })
    }

    /// One line for the text report: what the ship moves in, and what the figures are over.
    pub fn line(&self) -> String {
        let mut parts = Vec::new();
        if let Some(c) = &self.current {
            parts.push(format!(
                "a current of {} m/s toward {}°",
                c.speed_m_s,
                crate::Short(c.toward_deg)
            ));
        }
        match &self.wind {
            Some(w) => parts.push(format!(
                "a wind of {} m/s from {}°{}",
                w.speed_m_s,
                crate::Short(w.from_deg),
                w.gust.as_ref().map_or(String::new(), |g| format!(
                    ", gusting (NORSOK, seed {}, σ = {:.2} m/s)",
                    g.seed, g.sigma_m_s
                ))
            )),
            None if self.windage.is_some() => parts.push("still air".into()),
            None => {}
        }
        format!(
            "  in {}: the figures are {FIGURES_OVER}",
            parts.join(" and ")
        )
    }
}

impl GustSummary {
    fn of(gust: &Gust) -> Self {
        let Spectrum::Norsok { height, .. } = gust.spectrum;
        GustSummary {
            spectrum: "norsok",
            seed: gust.seed,
            height_m: height,
            sigma_m_s: gust.variance().sqrt(),
            spectrum_sigma_m_s: gust.spectrum.variance().sqrt(),
            highest_frequency_hz: HIGHEST_FREQUENCY,
        }
    }
}
