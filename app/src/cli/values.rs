//! Command-line values for the catalog's enums: their names come from the catalog itself
//! (`Symmetry::name`, …), so the flags accept exactly what scene files accept.

use clap::builder::{PossibleValuesParser, TypedValueParser};
use eom::models::{Family, Kinematics, Symmetry};

/// A parser for one of a catalog enum's values, by name, with each value's doc as its help.
macro_rules! catalog_parser {
    ($name:ident, $type:ty) => {
        #[doc = concat!(" Parses a [`", stringify!($type), "`] by its catalog name.")]
        pub fn $name() -> impl TypedValueParser<Value = $type> {
            let values = <$type>::ALL
                .map(|value| clap::builder::PossibleValue::new(value.name()).help(value.doc()));
            PossibleValuesParser::new(values).map(|name| {
                <$type>::ALL
                    .into_iter()
                    .find(|value| value.name() == name)
                    .expect("clap accepts only the possible values")
            })
        }
    };
}

catalog_parser!(symmetry, Symmetry);
catalog_parser!(kinematics, Kinematics);
catalog_parser!(family, Family);

/// A quantity that must be positive and finite (a period, a length, a mass, gravity): clap
/// refuses anything else with the flag's name, exit 2, before the command starts.
pub fn positive(text: &str) -> Result<f64, String> {
    let value: f64 = text.trim().parse().map_err(|e| format!("{e}"))?;
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(format!("must be positive and finite, not {value}"))
    }
}

/// An amplitude in degrees: finite, at least 0° and below 180° (at 180° the body would go over
/// the top).
pub fn amplitude_deg(text: &str) -> Result<f64, String> {
    let value: f64 = text.trim().parse().map_err(|e| format!("{e}"))?;
    if value.is_finite() && (0.0..180.0).contains(&value) {
        Ok(value)
    } else {
        Err(format!("must be at least 0° and below 180°, not {value}"))
    }
}
