//! A ship's wind coefficients C_X, C_Y, C_N over the relative wind's angle: a table as a scene
//! gives it, or Isherwood's regression (1972) at the ship's dimensions.
//!
//! A table is over the angle γ off the bow the wind comes from, 0° (head wind) to 180°
//! (astern), the same from either side, in the published convention (Isherwood's, with the
//! signs Fossen's MSS gives it after Blendermann, 1994): C_X positive forward, C_Y and C_N
//! positive for a wind from port, which pushes the ship to starboard. [`WindCoefficients::at`]
//! turns it into the ship's axes for a wind from either side. A ship symmetric port and
//! starboard has no side force or moment in a head or a following wind, so C_Y and C_N are
//! zero at 0° and 180°: a table that says otherwise would have the loads jump as the wind
//! crosses the bow, and is refused.
//!
//! Isherwood's coefficients (`data/isherwood1972.json`, with its source) are a regression on
//! a ship's above-water geometry; [`Isherwood::coefficients`] evaluates them at each of the
//! regression's angles, 0°, 10°, …, 180°.

use std::f64::consts::PI;

/// Why a table of wind coefficients cannot be used; each names the key at fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WindTableError {
    /// A value that is not a finite number, or out of its range.
    #[error("`{key}`: {reason}")]
    Invalid {
        /// The key, as the scene writes it (`windage.C_Y`).
        key: &'static str,
        /// What is wrong.
        reason: String,
    },
}

fn invalid(key: &'static str, reason: impl Into<String>) -> WindTableError {
    WindTableError::Invalid {
        key,
        reason: reason.into(),
    }
}

/// C_X, C_Y, C_N at angles from 0 to π, linear between them.
#[derive(Debug, Clone, PartialEq)]
pub struct WindCoefficients {
    /// γ, rad, from 0 to π, increasing.
    angles: Vec<f64>,
    /// C_X, C_Y, C_N at each angle, in the published convention (module docs).
    values: [Vec<f64>; 3],
}

impl WindCoefficients {
    /// The table at `angles_deg` (0 first, 180 last, increasing), each coefficient's list as
    /// long, checked.
    pub fn new(angles_deg: &[f64], values: [Vec<f64>; 3]) -> Result<Self, WindTableError> {
        const KEYS: [&str; 3] = ["windage.C_X", "windage.C_Y", "windage.C_N"];
        let angle_key = "windage.angles_deg";
        if angles_deg.len() < 2 || angles_deg.first() != Some(&0.0) {
            return Err(invalid(angle_key, "the table starts at 0° (a head wind)"));
        }
        if angles_deg.last() != Some(&180.0) {
            return Err(invalid(
                angle_key,
                "the table ends at 180° (a wind from astern)",
            ));
        }
        // NaN is not greater: an angle that is not a number is refused here too.
        let increasing = |w: &&[f64]| w[1].partial_cmp(&w[0]) == Some(std::cmp::Ordering::Greater);
        if let Some(pair) = angles_deg.windows(2).find(|w| !increasing(w)) {
            return Err(invalid(
                angle_key,
                format!(
                    "the angles increase: {} is followed by {}",
                    pair[0], pair[1]
                ),
            ));
        }
        for (key, list) in KEYS.into_iter().zip(&values) {
            if list.len() != angles_deg.len() {
                return Err(invalid(
                    key,
                    format!(
                        "{} values for {} angles: one for each",
                        list.len(),
                        angles_deg.len()
                    ),
                ));
            }
            if let Some(bad) = list.iter().find(|c| !c.is_finite()) {
                return Err(invalid(key, format!("{bad} is not a finite number")));
            }
        }
        for (key, list) in KEYS.into_iter().zip(&values).skip(1) {
            let ends = [list[0], list[list.len() - 1]];
            if ends != [0.0, 0.0] {
                return Err(invalid(
                    key,
                    format!(
                        "{} at 0° and {} at 180°: a ship symmetric port and starboard has no side \
                         force or yaw moment in a head or a following wind (give 0 at both)",
                        ends[0], ends[1]
                    ),
                ));
            }
        }
        Ok(WindCoefficients {
            angles: angles_deg.iter().map(|a| a.to_radians()).collect(),
            values,
        })
    }

    /// The angles, degrees, and C_X, C_Y, C_N at each, in the published convention.
    pub fn table(&self) -> (Vec<f64>, &[Vec<f64>; 3]) {
        let degrees = self.angles.iter().map(|a| a.to_degrees()).collect();
        (degrees, &self.values)
    }

    /// (C, dC/dγ) of X, Y and N in the ship's axes at `angle`, the angle off the bow the wind
    /// comes from, positive from starboard (rad, −π to π): the table's at |γ|, C_Y and C_N
    /// turned for a wind from starboard (module docs). The slope at a tabulated angle is the
    /// segment's above it.
    pub fn at(&self, angle: f64) -> [(f64, f64); 3] {
        let magnitude = angle.abs().min(PI);
        let side = if angle < 0.0 { -1.0 } else { 1.0 };
        let last = self.angles.len() - 2;
        let segment = (self.angles[1..].iter())
            .position(|a| magnitude < *a)
            .unwrap_or(last);
        let (a0, a1) = (self.angles[segment], self.angles[segment + 1]);
        let fraction = (magnitude - a0) / (a1 - a0);
        let read = |list: &Vec<f64>| {
            let (c0, c1) = (list[segment], list[segment + 1]);
            (c0 + fraction * (c1 - c0), (c1 - c0) / (a1 - a0))
        };
        let [(x, dx), (y, dy), (n, dn)] = self.values.each_ref().map(read);
        // γ > 0 is a wind from starboard: the published C_Y, C_N (from port) change sign.
        [(x, side * dx), (-side * y, -dy), (-side * n, -dn)]
    }
}

/// A ship's above-water geometry, as Isherwood's regression reads it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Isherwood {
    /// L_oa, m.
    pub length_overall: f64,
    /// B, m.
    pub beam: f64,
    /// A_L, the lateral projected area, m².
    pub lateral_area: f64,
    /// A_F, the frontal projected area, m².
    pub frontal_area: f64,
    /// A_SS, the superstructure's lateral projected area, m².
    pub superstructure_area: f64,
    /// S, the lateral projection's perimeter, the waterline and slender bodies left out, m.
    pub perimeter: f64,
    /// C, the lateral area's centroid's distance from the bow, m.
    pub centroid_from_bow: f64,
    /// M, the groups of masts or king posts in lateral projection.
    pub masts: f64,
}

/// Isherwood's regression coefficients as `data/isherwood1972.json` gives them.
#[derive(serde::Deserialize)]
struct Regression {
    angles_deg: Vec<f64>,
    #[serde(rename = "A")]
    a: Vec<[f64; 7]>,
    #[serde(rename = "B")]
    b: Vec<[f64; 7]>,
    #[serde(rename = "C")]
    c: Vec<[f64; 6]>,
}

/// The published file, built in.
const ISHERWOOD_1972: &str = include_str!("../../../../data/isherwood1972.json");

impl Isherwood {
    /// C_X, C_Y, C_N at 0°, 10°, …, 180° by Isherwood's regression at this geometry (the
    /// formulas are in `data/isherwood1972.json`).
    pub fn coefficients(&self) -> Result<WindCoefficients, WindTableError> {
        let positive = [
            ("windage.length_overall_m", self.length_overall),
            ("windage.beam_m", self.beam),
            ("windage.lateral_area_m2", self.lateral_area),
            ("windage.frontal_area_m2", self.frontal_area),
            ("windage.perimeter_m", self.perimeter),
            ("windage.centroid_from_bow_m", self.centroid_from_bow),
        ];
        let at_least_zero = [
            ("windage.superstructure_area_m2", self.superstructure_area),
            ("windage.masts", self.masts),
        ];
        for (key, value) in positive {
            if !(value.is_finite() && value > 0.0) {
                return Err(invalid(key, format!("{value}: a positive length or area")));
            }
        }
        for (key, value) in at_least_zero {
            if !(value.is_finite() && value >= 0.0) {
                return Err(invalid(key, format!("{value}: zero or more")));
            }
        }
        let regression: Regression = serde_json::from_str(ISHERWOOD_1972)
            .map_err(|e| invalid("windage.coefficients", format!("the built-in table: {e}")))?;
        let (l, b) = (self.length_overall, self.beam);
        let ratios = [
            1.0,
            2.0 * self.lateral_area / (l * l),
            2.0 * self.frontal_area / (b * b),
            l / b,
            self.perimeter / l,
            self.centroid_from_bow / l,
        ];
        let sum = |row: &[f64], ratios: &[f64]| -> f64 {
            row.iter().zip(ratios).map(|(c, r)| c * r).sum()
        };
        let x_ratios = [&ratios[..], &[self.masts]].concat();
        let y_ratios = [&ratios[..], &[self.superstructure_area / self.lateral_area]].concat();
        let x = regression
            .a
            .iter()
            .map(|row| -sum(row, &x_ratios))
            .collect();
        let y = regression.b.iter().map(|row| sum(row, &y_ratios)).collect();
        let n = regression.c.iter().map(|row| sum(row, &ratios)).collect();
        WindCoefficients::new(&regression.angles_deg, [x, y, n])
    }
}
