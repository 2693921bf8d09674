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
