//! The two sides of a trial: IMO MSC.137(76) asks for the turning circle "to port and
//! starboard", and a ship whose table has bias terms (a single screw's asymmetry: the
//! Mariner's `Y0`, `N0`) turns differently to each. A turning circle or a zig-zag runs to
//! both sides unless its scene names one; each side is a manoeuvre run of its own, and a
//! figure judged is the worse of the two.
//!
//! Which sign of δ turns the ship to port is the table's: the tables here put positive δ to
//! port (positive Y, negative N), but a table may not. The side is read from the linear model
//! about the straight course: the yaw acceleration a rudder angle gives at once, ṙ = b_r δ
//! (B of [`LinearModel::state_space`]), turns the ship to starboard (ψ growing, r > 0) where
//! b_r δ > 0. The initial response is used, not Nomoto's K: for a course-unstable ship K's
//! sign is that of the unstable steady state, the wrong side.

use super::linear::LinearModel;

/// A side a ship turns to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Side {
    /// To port: the heading decreasing, r < 0.
    Port,
    /// To starboard: the heading increasing, r > 0.
    Starboard,
}

impl Side {
    /// Both, in the order they are run and written.
    pub const BOTH: [Side; 2] = [Side::Port, Side::Starboard];

    /// `port` or `starboard`: the key in the summary and the output folder's name.
    pub fn name(self) -> &'static str {
        match self {
            Side::Port => "port",
            Side::Starboard => "starboard",
        }
    }

    /// The side of `name`, `port` or `starboard`.
    pub fn from_name(name: &str) -> Option<Side> {
        match name {
            "port" => Some(Side::Port),
            "starboard" => Some(Side::Starboard),
            _ => None,
        }
    }

    /// The sign of r (and of the heading change) of a turn to this side.
    pub fn yaw_sign(self) -> f64 {
        match self {
            Side::Port => -1.0,
            Side::Starboard => 1.0,
        }
    }

    /// The sign of δ that turns the ship described by `linear` to this side, by the yaw
    /// acceleration a rudder angle gives at once (see the module's documentation).
    pub fn rudder_sign(self, linear: &LinearModel) -> f64 {
        let (_, b) = linear.state_space();
        let starboard = if b[1] < 0.0 { -1.0 } else { 1.0 };
        starboard * self.yaw_sign()
    }
}

/// Which of two values of a figure is the worse, for the figures IMO judges (the larger
/// advance, tactical diameter, initial turning distance or overshoot is the worse) and for
/// the choice of the side a both-sided manoeuvre's summary shows first: the larger. A
/// missing value is worse than any (the run did not give it: its notes say why), so that a
/// verdict is never read from the side that gave a figure when the other could not.
pub fn worse(port: Option<f64>, starboard: Option<f64>) -> Side {
    match (port, starboard) {
        (Some(p), Some(s)) if s > p => Side::Starboard,
        (Some(_), None) => Side::Starboard,
        _ => Side::Port,
    }
}

/// The figure that decides which side of a manoeuvre is the worse, by its kind's key: the
/// tactical diameter of a turning circle, the first overshoot of a zig-zag.
pub fn deciding_figure(turning: bool) -> &'static str {
    if turning {
        "tactical_diameter_m"
    } else {
        "first_overshoot_deg"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_worse_is_the_larger_and_a_missing_figure_is_worst() {
        assert_eq!(worse(Some(1.0), Some(2.0)), Side::Starboard);
        assert_eq!(worse(Some(2.0), Some(1.0)), Side::Port);
        assert_eq!(worse(Some(2.0), Some(2.0)), Side::Port);
        assert_eq!(worse(None, Some(2.0)), Side::Port);
        assert_eq!(worse(Some(2.0), None), Side::Starboard);
        assert_eq!(Side::from_name("port"), Some(Side::Port));
        assert_eq!(Side::from_name("Port"), None);
    }
}
