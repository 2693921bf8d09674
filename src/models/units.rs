//! The unit of a state entry or an input, by its name.
//!
//! The layouts themselves are the catalog's ([`ModelInfo::state`](super::ModelInfo)) and the
//! ship model's (`ship::model::STATE`, with the feature `ship`); this module knows only what each name
//! measures, so that every file that labels a state column (the trajectory header, the scene
//! reference) reads the unit from one place. The names follow the chapter: u, v, w body
//! velocities (m/s), p, q, r body rates (rad/s), x, y, z positions (m), φ, θ, ψ and the
//! rudder's δ angles (rad), q0…q3 the unit quaternion's parts (dimensionless), and a name
//! ending in `_dot` the rate of what it ends with. Outputs are in radians: the degrees of a
//! scene file are converted when it is read.
//!
//! Output columns carry their unit in brackets, `u[m/s]`, `psi[rad]`, `q0[-]`, `t[s]`,
//! `kinetic_energy[J]` ([`with_unit`]), so that a file read alone says what it holds.

/// The unit of time, the column `t`.
pub const TIME_UNIT: &str = "s";
/// The unit of the energy columns.
pub const ENERGY_UNIT: &str = "J";

/// A column's label as output files write it: the name, then its unit in brackets,
/// `u[m/s]` (`-` for a dimensionless quantity).
pub fn with_unit(name: &str, unit: &str) -> String {
    format!("{name}[{unit}]")
}

/// A state entry's column label, its unit from [`state_unit`]: `theta_dot[rad/s]`. A name
/// with no known unit (none of the catalog's or the ship's; the tests hold them to it) is
/// written bare rather than with a wrong one.
pub fn state_with_unit(name: &str) -> String {
    match state_unit(name) {
        Some(unit) => with_unit(name, unit),
        None => name.to_owned(),
    }
}

/// The unit of the state entry `name` (any case: the catalog writes `X`, the trajectory `x`),
/// in the form trajectory headers write it: `m/s`, `rad`, `-` for a dimensionless entry.
/// `None` for a name no model uses.
///
/// ```
/// use eom::models::state_unit;
/// assert_eq!(state_unit("u"), Some("m/s"));
/// assert_eq!(state_unit("X_dot"), Some("m/s"));
/// assert_eq!(state_unit("theta_dot"), Some("rad/s"));
/// assert_eq!(state_unit("q0"), Some("-"));
/// assert_eq!(state_unit("speed"), None);
/// ```
pub fn state_unit(name: &str) -> Option<&'static str> {
    let name = name.to_ascii_lowercase();
    match name.strip_suffix("_dot") {
        Some(base) => rate_of(base_unit(base)?),
        None => base_unit(&name),
    }
}

/// The unit of the input `name`: a force `F_…` in N, a moment `M_…` in N m, a rudder's or a
/// fin's angle as [`state_unit`] gives it. `None` for a name no model uses.
///
/// ```
/// use eom::models::input_unit;
/// assert_eq!(input_unit("F_x"), Some("N"));
/// assert_eq!(input_unit("M_O"), Some("N m"));
/// assert_eq!(input_unit("delta"), Some("rad"));
/// assert_eq!(input_unit("thrust"), None);
/// ```
pub fn input_unit(name: &str) -> Option<&'static str> {
    if name.starts_with("F_") {
        Some("N")
    } else if name.starts_with("M_") {
        Some("N m")
    } else {
        state_unit(name)
    }
}

/// The unit of a name that is not a rate of another.
fn base_unit(name: &str) -> Option<&'static str> {
    match name {
        "u" | "v" | "w" => Some("m/s"),
        "p" | "q" | "r" => Some("rad/s"),
        "x" | "y" | "z" => Some("m"),
        // delta: a rudder's angle; command: the angle it is commanded to.
        "phi" | "theta" | "psi" | "delta" | "command" => Some("rad"),
        // A vehicle's rudder and stern planes, and their commands.
        "dr" | "ds" | "dr_command" | "ds_command" => Some("rad"),
        // distance: the distance run along the track.
        "distance" => Some("m"),
        "q0" | "q1" | "q2" | "q3" => Some("-"),
        _ => None,
    }
}

/// The unit of the time derivative of a quantity in `unit`.
fn rate_of(unit: &str) -> Option<&'static str> {
    match unit {
        "m" => Some("m/s"),
        "rad" => Some("rad/s"),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::CATALOG;

    #[test]
    fn every_catalog_state_entry_has_a_unit() {
        for info in CATALOG {
            for name in info.state {
                assert!(state_unit(name).is_some(), "{}: {name}", info.name);
            }
        }
    }

    #[test]
    fn every_catalog_input_has_a_unit() {
        for info in CATALOG {
            for name in info.inputs {
                assert!(input_unit(name).is_some(), "{}: {name}", info.name);
            }
        }
    }

    #[test]
    fn a_rate_is_its_quantity_per_second() {
        assert_eq!(state_unit("x_dot"), Some("m/s"));
        assert_eq!(state_unit("psi_dot"), Some("rad/s"));
        // No model carries the rate of a velocity or of a quaternion part.
        assert_eq!(state_unit("u_dot"), None);
        assert_eq!(state_unit("q0_dot"), None);
    }
}
