//! One ship's MMG parameters, typed, and read from a table of named numbers.
//!
//! The names are the keys of `data/kvlcc2_mmg.json` (the public transcriptions' names): the
//! non-dimensional coefficients under `coefficients` (`X_vv_p` is X′_vv), the particulars of
//! one scale under `particulars.<scale>` in metres. Every value read must be finite and the
//! lengths, the rudder's area and the density positive; an error names the key it is about,
//! by its path in the table (`coefficients.k_2`, `particulars.L7.L`).

use serde_json::{Map, Value};
use std::collections::BTreeMap;

use crate::Short;

/// Why a table of MMG parameters cannot be used; each names the key by its path in the table.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MmgParameterError {
    /// A key the model needs is not in the table.
    #[error("`{key}` is missing")]
    Missing {
        /// The key's path, `coefficients.k_2`.
        key: String,
    },
    /// A key's value is not a number (a string, an object, null).
    #[error("`{key}` is not a number")]
    NotANumber {
        /// The key's path.
        key: String,
    },
    /// A group of numbers (`coefficients`, `particulars.L7`) that is not a JSON object.
    #[error("`{key}` is not a table of named numbers")]
    NotAGroup {
        /// The group's path.
        key: String,
    },
    /// A value that is NaN or infinite.
    #[error("`{key}` = {} is not finite", Short(*value))]
    NotFinite {
        /// The key's path.
        key: String,
        /// The value.
        value: f64,
    },
    /// A length, an area or the density that is zero or negative.
    #[error("`{key}` = {} must be positive", Short(*value))]
    NotPositive {
        /// The key's path.
        key: String,
        /// The value.
        value: f64,
    },
}

impl MmgParameterError {
    /// The key it is about, by its path in the table (`coefficients.k_2`).
    pub fn key(&self) -> &str {
        match self {
            MmgParameterError::Missing { key }
            | MmgParameterError::NotANumber { key }
            | MmgParameterError::NotAGroup { key }
            | MmgParameterError::NotFinite { key, .. }
            | MmgParameterError::NotPositive { key, .. } => key,
        }
    }
}

/// The ship's principal particulars and the water's density, in SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Particulars {
    /// L, the length between perpendiculars, m.
    pub length: f64,
    /// B, the breadth, m.
    pub breadth: f64,
    /// d, the draft, m.
    pub draft: f64,
    /// x_G, the centre of gravity ahead of midship, m (the equations of motion's, not the forces').
    pub centre_of_gravity: f64,
    /// D_P, the propeller's diameter, m.
    pub propeller_diameter: f64,
    /// H_R, the rudder's span, m.
    pub rudder_span: f64,
    /// A_R, the rudder's profile area, m².
    pub rudder_area: f64,
    /// ρ, the water's density, kg/m³.
    pub density: f64,
}

/// The hull's non-dimensional derivatives: forces on ½ρLdU², the moment on ½ρL²dU², in
/// v′ = v_m/U and r′ = rL/U.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HullDerivatives {
    /// R′₀, the resistance on a straight course (X′_H = −R′₀ there).
    pub resistance: f64,
    /// X′_vv.
    pub x_vv: f64,
    /// X′_vr.
    pub x_vr: f64,
    /// X′_rr.
    pub x_rr: f64,
    /// X′_vvvv.
    pub x_vvvv: f64,
    /// Y′_v.
    pub y_v: f64,
    /// Y′_r.
    pub y_r: f64,
    /// Y′_vvv.
    pub y_vvv: f64,
    /// Y′_vvr.
    pub y_vvr: f64,
    /// Y′_vrr.
    pub y_vrr: f64,
    /// Y′_rrr.
    pub y_rrr: f64,
    /// N′_v.
    pub n_v: f64,
    /// N′_r.
    pub n_r: f64,
    /// N′_vvv.
    pub n_vvv: f64,
    /// N′_vvr.
    pub n_vvr: f64,
    /// N′_vrr.
    pub n_vrr: f64,
    /// N′_rrr.
    pub n_rrr: f64,
}

/// The added masses, non-dimensional: m′_x, m′_y on ½ρL²d, J′_z on ½ρL⁴d. Not used by the
/// forces; the equations of motion of a later step read them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AddedMasses {
    /// m′_x.
    pub surge: f64,
    /// m′_y.
    pub sway: f64,
    /// J′_z.
    pub yaw: f64,
}

/// The propeller's open-water curve, its wake and thrust deduction, and its position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PropellerCoefficients {
    /// t_P, the thrust deduction factor.
    pub thrust_deduction: f64,
    /// w_P0, the wake fraction on a straight course.
    pub straight_wake: f64,
    /// x′_P = x_P/L, the propeller's position ahead of midship (negative aft).
    pub position: f64,
    /// C₁, how fast the wake changes with the inflow angle β_P.
    pub wake_rate: f64,
    /// C₂⁺, the wake law's C₂ for β_P ≥ 0.
    pub wake_gain_positive: f64,
    /// C₂⁻, the wake law's C₂ for β_P < 0.
    pub wake_gain_negative: f64,
    /// k₀, k₁, k₂ of K_T = k₀ + k₁J + k₂J².
    pub thrust_curve: [f64; 3],
}

/// The rudder's lift gradient and its interaction with the hull and the propeller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RudderCoefficients {
    /// t_R, the steering resistance deduction factor.
    pub drag_deduction: f64,
    /// a_H, the rudder force increase factor (the hull's share of the rudder's lateral force).
    pub hull_force_share: f64,
    /// x′_H = x_H/L, where the hull's share acts, ahead of midship.
    pub hull_force_position: f64,
    /// x′_R = x_R/L, the rudder's position ahead of midship (−0.5: the aft perpendicular).
    pub position: f64,
    /// γ_R⁺, the flow-straightening coefficient for β_R ≥ 0.
    pub straightening_positive: f64,
    /// γ_R⁻, the flow-straightening coefficient for β_R < 0.
    pub straightening_negative: f64,
    /// l′_R = l_R/L, the effective position of the rudder in β_R = β − l′_R r′.
    pub effective_position: f64,
    /// ε, the ratio of the wake at the rudder to the wake at the propeller, (1 − w_R)/(1 − w_P).
    pub wake_ratio: f64,
    /// κ, the share of the propeller's race that reaches the rudder.
    pub race_share: f64,
    /// f_α, the rudder's lift gradient, per rad.
    pub lift_gradient: f64,
    /// η = D_P/H_R, the share of the rudder's span in the propeller's race.
    pub span_in_race: f64,
}

/// One ship's MMG parameters: what [`MmgParameters::forces`] needs, and the added masses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MmgParameters {
    /// L, B, d, x_G, D_P, H_R, A_R, ρ.
    pub particulars: Particulars,
    /// R′₀ and the hull's derivatives.
    pub hull: HullDerivatives,
    /// m′_x, m′_y, J′_z.
    pub added_mass: AddedMasses,
    /// t_P, w_P0, x′_P, C₁, C₂±, k₀…k₂.
    pub propeller: PropellerCoefficients,
    /// t_R, a_H, x′_H, x′_R, γ_R±, l′_R, ε, κ, f_α, η.
    pub rudder: RudderCoefficients,
}

/// The names of a table's `coefficients` ([`MmgParameters::from_values`]); `f_alpha` may be
/// left out (Fujii's formula then gives it).
pub const MMG_COEFFICIENTS: [&str; 39] = [
    "m_x_p",
    "m_y_p",
    "J_z_p",
    "R_0_p",
    "X_vv_p",
    "X_vr_p",
    "X_rr_p",
    "X_vvvv_p",
    "Y_v_p",
    "Y_r_p",
    "Y_vvv_p",
    "Y_vvr_p",
    "Y_vrr_p",
    "Y_rrr_p",
    "N_v_p",
    "N_r_p",
    "N_vvv_p",
    "N_vvr_p",
    "N_vrr_p",
    "N_rrr_p",
    "t_P",
    "w_P0",
    "x_P_p",
    "k_0",
    "k_1",
    "k_2",
    "C_1",
    "C_2_plus",
    "C_2_minus",
    "t_R",
    "a_H",
    "x_H_p",
    "x_R_p",
    "gamma_R_plus",
    "gamma_R_minus",
    "l_R_p",
    "epsilon",
    "kappa",
    "f_alpha",
];

/// The names of a scene's `particulars` the forces read beside the body's L and x_G: B, d
/// (m), D_P, H_R (m), A_R (m²).
pub const MMG_PARTICULARS: [&str; 5] = ["B", "d", "D_P", "H_R", "A_R"];

/// Fujii's rudder lift gradient, f_α = 6.13Λ/(Λ + 2.25), at the aspect ratio Λ.
pub fn fujii_lift_gradient(aspect_ratio: f64) -> f64 {
    6.13 * aspect_ratio / (aspect_ratio + 2.25)
}

impl MmgParameters {
    /// The parameters of `document` (the layout of `data/kvlcc2_mmg.json`): its `coefficients`
    /// and the particulars `particulars.<scale>`, at the water's `density` (kg/m³).
    pub fn from_json(
        document: &Value,
        scale: &str,
        density: f64,
    ) -> Result<Self, MmgParameterError> {
        let coefficients = Group::json(document, "coefficients")?;
        let particulars = Group::json(document, "particulars")?;
        let scale = particulars.group(scale)?;
        Self::read(&coefficients, &scale, density)
    }

    /// The parameters of two maps with the keys of `data/kvlcc2_mmg.json`'s `coefficients`
    /// and of one of its `particulars` (errors name them `coefficients.…`, `particulars.…`).
    pub fn from_values(
        coefficients: &BTreeMap<String, f64>,
        particulars: &BTreeMap<String, f64>,
        density: f64,
    ) -> Result<Self, MmgParameterError> {
        let coefficients = Group::values("coefficients", coefficients);
        let particulars = Group::values("particulars", particulars);
        Self::read(&coefficients, &particulars, density)
    }

    fn read(
        coefficients: &Group<'_>,
        particulars: &Group<'_>,
        density: f64,
    ) -> Result<Self, MmgParameterError> {
        let particulars = read_particulars(particulars, density)?;
        Ok(MmgParameters {
            particulars,
            hull: read_hull(coefficients)?,
            added_mass: AddedMasses {
                surge: coefficients.finite("m_x_p")?,
                sway: coefficients.finite("m_y_p")?,
                yaw: coefficients.finite("J_z_p")?,
            },
            propeller: read_propeller(coefficients)?,
            rudder: read_rudder(coefficients, &particulars)?,
        })
    }
}

fn read_particulars(table: &Group<'_>, density: f64) -> Result<Particulars, MmgParameterError> {
    Ok(Particulars {
        length: table.positive("L")?,
        breadth: table.positive("B")?,
        draft: table.positive("d")?,
        centre_of_gravity: table.finite("x_G")?,
        propeller_diameter: table.positive("D_P")?,
        rudder_span: table.positive("H_R")?,
        rudder_area: table.positive("A_R")?,
        density: positive("density".to_owned(), density)?,
    })
}

fn read_hull(table: &Group<'_>) -> Result<HullDerivatives, MmgParameterError> {
    Ok(HullDerivatives {
        resistance: table.finite("R_0_p")?,
        x_vv: table.finite("X_vv_p")?,
        x_vr: table.finite("X_vr_p")?,
        x_rr: table.finite("X_rr_p")?,
        x_vvvv: table.finite("X_vvvv_p")?,
        y_v: table.finite("Y_v_p")?,
        y_r: table.finite("Y_r_p")?,
        y_vvv: table.finite("Y_vvv_p")?,
        y_vvr: table.finite("Y_vvr_p")?,
        y_vrr: table.finite("Y_vrr_p")?,
        y_rrr: table.finite("Y_rrr_p")?,
        n_v: table.finite("N_v_p")?,
        n_r: table.finite("N_r_p")?,
        n_vvv: table.finite("N_vvv_p")?,
        n_vvr: table.finite("N_vvr_p")?,
        n_vrr: table.finite("N_vrr_p")?,
        n_rrr: table.finite("N_rrr_p")?,
    })
}

fn read_propeller(table: &Group<'_>) -> Result<PropellerCoefficients, MmgParameterError> {
    Ok(PropellerCoefficients {
        thrust_deduction: table.finite("t_P")?,
        straight_wake: table.finite("w_P0")?,
        position: table.finite("x_P_p")?,
        wake_rate: table.finite("C_1")?,
        wake_gain_positive: table.finite("C_2_plus")?,
        wake_gain_negative: table.finite("C_2_minus")?,
        thrust_curve: [
            table.finite("k_0")?,
            table.finite("k_1")?,
            table.finite("k_2")?,
        ],
    })
}

/// The rudder's coefficients; f_α by Fujii's formula at Λ = H_R²/A_R when the table has none,
/// η = D_P/H_R always.
fn read_rudder(
    table: &Group<'_>,
    ship: &Particulars,
) -> Result<RudderCoefficients, MmgParameterError> {
    let lift_gradient = match table.optional_finite("f_alpha")? {
        Some(given) => given,
        None => fujii_lift_gradient(ship.rudder_span.powi(2) / ship.rudder_area),
    };
    Ok(RudderCoefficients {
        drag_deduction: table.finite("t_R")?,
        hull_force_share: table.finite("a_H")?,
        hull_force_position: table.finite("x_H_p")?,
        position: table.finite("x_R_p")?,
        straightening_positive: table.finite("gamma_R_plus")?,
        straightening_negative: table.finite("gamma_R_minus")?,
        effective_position: table.finite("l_R_p")?,
        wake_ratio: table.finite("epsilon")?,
        race_share: table.finite("kappa")?,
        lift_gradient,
        span_in_race: ship.propeller_diameter / ship.rudder_span,
    })
}

/// A group of named numbers and its path in the table, for the errors.
struct Group<'a> {
    path: String,
    entries: Entries<'a>,
}

enum Entries<'a> {
    Json(&'a Map<String, Value>),
    Values(&'a BTreeMap<String, f64>),
}

impl<'a> Group<'a> {
    /// The object `key` at the top of `document`.
    fn json(document: &'a Value, key: &str) -> Result<Self, MmgParameterError> {
        Self::object(document.get(key), key.to_owned())
    }

    /// The object `key` inside this group (`particulars.L7`).
    fn group(&self, key: &str) -> Result<Self, MmgParameterError> {
        let value = match &self.entries {
            Entries::Json(object) => object.get(key),
            Entries::Values(_) => None,
        };
        Self::object(value, self.key(key))
    }

    fn object(value: Option<&'a Value>, path: String) -> Result<Self, MmgParameterError> {
        match value {
            None => Err(MmgParameterError::Missing { key: path }),
            Some(Value::Object(entries)) => Ok(Group {
                path,
                entries: Entries::Json(entries),
            }),
            Some(_) => Err(MmgParameterError::NotAGroup { key: path }),
        }
    }

    fn values(path: &str, values: &'a BTreeMap<String, f64>) -> Self {
        Group {
            path: path.to_owned(),
            entries: Entries::Values(values),
        }
    }

    fn key(&self, name: &str) -> String {
        format!("{}.{name}", self.path)
    }

    /// The number `name`, if the group has it.
    fn number(&self, name: &str) -> Result<Option<f64>, MmgParameterError> {
        match &self.entries {
            Entries::Values(values) => Ok(values.get(name).copied()),
            Entries::Json(object) => match object.get(name) {
                None => Ok(None),
                Some(value) => {
                    value
                        .as_f64()
                        .map(Some)
                        .ok_or_else(|| MmgParameterError::NotANumber {
                            key: self.key(name),
                        })
                }
            },
        }
    }

    fn optional_finite(&self, name: &str) -> Result<Option<f64>, MmgParameterError> {
        self.number(name)?
            .map(|value| finite(self.key(name), value))
            .transpose()
    }

    fn finite(&self, name: &str) -> Result<f64, MmgParameterError> {
        self.optional_finite(name)?
            .ok_or_else(|| MmgParameterError::Missing {
                key: self.key(name),
            })
    }

    fn positive(&self, name: &str) -> Result<f64, MmgParameterError> {
        positive(self.key(name), self.finite(name)?)
    }
}

fn finite(key: String, value: f64) -> Result<f64, MmgParameterError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(MmgParameterError::NotFinite { key, value })
    }
}

fn positive(key: String, value: f64) -> Result<f64, MmgParameterError> {
    let value = finite(key.clone(), value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(MmgParameterError::NotPositive { key, value })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const KVLCC2: &str = include_str!("../../../../data/kvlcc2_mmg.json");

    fn kvlcc2() -> Value {
        serde_json::from_str(KVLCC2).expect("data/kvlcc2_mmg.json is JSON")
    }

    fn kvlcc2_values() -> (BTreeMap<String, f64>, BTreeMap<String, f64>) {
        let document = kvlcc2();
        let numbers = |value: &Value| -> BTreeMap<String, f64> {
            let object = value.as_object().expect("an object");
            (object.iter())
                .map(|(key, value)| (key.clone(), value.as_f64().expect("a number")))
                .collect()
        };
        (
            numbers(&document["coefficients"]),
            numbers(&document["particulars"]["L7"]),
        )
    }

    /// A coefficient is read as written: every decimal of 17 significant digits to its nearest
    /// double, as Rust's own parser reads it (serde_json's default reader puts a fifth to a
    /// third of such decimals an ulp off; the library's `float_roundtrip` reads them exactly).
    #[test]
    fn a_coefficient_is_read_to_its_nearest_double() {
        let mut bits: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut wrong = Vec::new();
        for _ in 0..2000 {
            // A double in [0.1, 1): a coefficient's range, every bit of its mantissa random.
            bits = bits.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
            let x = 0.1 + 0.9 * (bits >> 11) as f64 / (1u64 << 53) as f64;
            let text = format!("{x:.16e}");
            let document: Value = serde_json::from_str(&format!("{{\"t_P\": {text}}}")).unwrap();
            let read = document["t_P"].as_f64().unwrap();
            if read.to_bits() != text.parse::<f64>().unwrap().to_bits() {
                wrong.push(text);
            }
        }
        assert!(
            wrong.is_empty(),
            "{} of 2000 read wrong: {:?}",
            wrong.len(),
            &wrong[..wrong.len().min(5)]
        );
    }

    #[test]
    fn the_published_table_reads_at_both_scales() {
        let document = kvlcc2();
        let model = MmgParameters::from_json(&document, "L7", 1025.0).unwrap();
        assert_eq!(model.particulars.length, 7.0);
        assert_eq!(model.hull.n_vvr, -0.294);
        assert_eq!(model.propeller.thrust_curve, [0.2931, -0.2753, -0.1385]);
        assert_eq!(model.rudder.lift_gradient, 2.747);
        assert_eq!(model.rudder.span_in_race, 0.216 / 0.345);
        let ship = MmgParameters::from_json(&document, "full", 1025.0).unwrap();
        assert_eq!(ship.particulars.rudder_area, 112.5);
        assert_eq!(ship.hull, model.hull);
    }

    #[test]
    fn without_f_alpha_fujiis_formula_at_h_r_squared_over_a_r_is_taken() {
        let (mut coefficients, particulars) = kvlcc2_values();
        coefficients.remove("f_alpha");
        let model = MmgParameters::from_values(&coefficients, &particulars, 1025.0).unwrap();
        let aspect_ratio = 0.345_f64.powi(2) / 0.0539;
        assert_eq!(
            model.rudder.lift_gradient,
            6.13 * aspect_ratio / (aspect_ratio + 2.25)
        );
        // The published 2.747 is Fujii's formula at an aspect ratio of 1.827, not at H_R²/A_R.
        assert!((fujii_lift_gradient(1.827) - 2.747).abs() < 1e-4);
    }

    #[test]
    fn a_missing_key_is_named_by_its_path() {
        let mut document = kvlcc2();
        document["coefficients"]
            .as_object_mut()
            .unwrap()
            .remove("k_2");
        let error = MmgParameters::from_json(&document, "L7", 1025.0).unwrap_err();
        assert_eq!(
            error,
            MmgParameterError::Missing {
                key: "coefficients.k_2".into()
            }
        );
        assert_eq!(error.to_string(), "`coefficients.k_2` is missing");
    }

    #[test]
    fn a_missing_scale_is_named() {
        let error = MmgParameters::from_json(&kvlcc2(), "L3", 1025.0).unwrap_err();
        assert_eq!(
            error,
            MmgParameterError::Missing {
                key: "particulars.L3".into()
            }
        );
    }

    #[test]
    fn a_negative_length_is_named_by_its_path() {
        let mut document = kvlcc2();
        document["particulars"]["L7"]["L"] = (-7.0).into();
        let error = MmgParameters::from_json(&document, "L7", 1025.0).unwrap_err();
        assert_eq!(
            error,
            MmgParameterError::NotPositive {
                key: "particulars.L7.L".into(),
                value: -7.0
            }
        );
        assert_eq!(
            error.to_string(),
            "`particulars.L7.L` = -7 must be positive"
        );
    }

    #[test]
    fn nan_in_a_coefficient_is_named() {
        let (mut coefficients, particulars) = kvlcc2_values();
        coefficients.insert("a_H".into(), f64::NAN);
        let error = MmgParameters::from_values(&coefficients, &particulars, 1025.0).unwrap_err();
        assert!(
            matches!(&error, MmgParameterError::NotFinite { key, value }
                if key == "coefficients.a_H" && value.is_nan()),
            "{error:?}"
        );
        assert_eq!(error.to_string(), "`coefficients.a_H` = NaN is not finite");
    }

    #[test]
    fn an_infinite_particular_and_a_zero_density_are_named() {
        let (coefficients, mut particulars) = kvlcc2_values();
        particulars.insert("D_P".into(), f64::INFINITY);
        let error = MmgParameters::from_values(&coefficients, &particulars, 1025.0).unwrap_err();
        assert!(
            matches!(&error, MmgParameterError::NotFinite { key, .. } if key == "particulars.D_P")
        );
        let (coefficients, particulars) = kvlcc2_values();
        let error = MmgParameters::from_values(&coefficients, &particulars, 0.0).unwrap_err();
        assert_eq!(
            error,
            MmgParameterError::NotPositive {
                key: "density".into(),
                value: 0.0
            }
        );
    }

    #[test]
    fn a_value_that_is_not_a_number_is_named() {
        let mut document = kvlcc2();
        document["coefficients"]["kappa"] = "0.5".into();
        let error = MmgParameters::from_json(&document, "L7", 1025.0).unwrap_err();
        assert_eq!(
            error,
            MmgParameterError::NotANumber {
                key: "coefficients.kappa".into()
            }
        );
    }
}
