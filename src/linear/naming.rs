//! The names of modes: by what moves in each, read in comparable units.
//!
//! Every rule here reads a mode's shares ([`Mode::shares`]: each entry of its eigenvector
//! read as an angle, a rate by the mode's own time, a velocity over the speed, a length over a
//! length scale; see [`modes`](mod@super::modes)), never the order of the modes' frequencies
//! alone. Two groups of states are told apart the way a state is called dominant: a group
//! whose largest share is at least twice the other's names the mode ([`DISTINCT`]); where
//! neither is, the mode moves both, and is called coupled, with both named, rather than given
//! the name of one.
//!
//! - Flight (`name_flight_modes`): lateral (β, φ, p, r) against longitudinal (speed, α,
//!   θ, q, altitude). Longitudinal: α (the short period's) against speed and altitude (the
//!   phugoid's; θ and q move in both and decide nothing). Of a real root trading speed and
//!   height, altitude at twice the speed's share is the height mode (at the same share the
//!   speed and the height are traded, g Δh = −V ΔV: the phugoid become real). Lateral: an
//!   oscillation is the Dutch roll; a real root the roll subsidence where the roll rate's share
//!   is twice the yaw rate's, the spiral where the yaw rate's is twice the roll rate's (r/|λ|
//!   is the heading's swing: the spiral turns the heading, the roll subsidence banks).
//! - Planes (`name_planes`): surge (u), sway and yaw (v, r, ψ), heave and pitch (w, q, θ,
//!   z), roll (p, φ), each plane's share its largest state's.
//! - A catalog family (`name_modes`): the family's own names, as before.

use super::modes::Mode;
use crate::models::Family;

/// A group of states names a mode where its share is at least this many times the other's:
/// the factor that makes a state dominant (half the largest share), so that a mode is named
/// by one group exactly when no state of the other is among its dominant states.
pub const DISTINCT: f64 = 2.0;

/// Which of two shares a mode is named by.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Side {
    /// The first, at least [`DISTINCT`] times the second.
    First,
    /// The second, at least [`DISTINCT`] times the first.
    Second,
    /// Neither: the mode moves both.
    Both,
}

fn side(first: f64, second: f64) -> Side {
    if first >= DISTINCT * second {
        Side::First
    } else if second >= DISTINCT * first {
        Side::Second
    } else {
        Side::Both
    }
}

/// A mode's largest share among `states`, by name (zero for a state not in `names`).
fn share(mode: &Mode, names: &[String], states: &[&str]) -> f64 {
    (names.iter().zip(&mode.shares))
        .filter(|(name, _)| states.contains(&name.as_str()))
        .fold(0.0f64, |m, (_, share)| m.max(*share))
}

/// A mode of the engine's power below this share does not move it (the power's rate reads
/// nothing but the power and the throttle, so every other mode's power entry is zero to
/// rounding, 10⁻¹⁶ of the largest).
const POWER: f64 = 1e-6;

/// The modes of a state in wind axes, as flight-dynamics texts name them, each by what moves in
/// it (see the module docs): the power lag; the Dutch roll, the roll subsidence, the spiral;
/// the short period (an oscillation, or split into two real roots behind the neutral point),
/// the phugoid (an oscillation, or real), the height mode; and coupled modes, named by both
/// groups they move.
pub(super) fn name_flight_modes(modes: &mut [Mode], names: &[String]) {
    for mode in modes.iter_mut() {
        let of = |states: &[&str]| share(mode, names, states);
        let oscillates = mode.eigenvalue.im > 0.0;
        let lateral = of(&["beta", "phi", "p", "r"]);
        let longitudinal = of(&["vt", "alpha", "theta", "q", "altitude"]);
        mode.name = Some(if of(&["power"]) > POWER {
            "power lag"
        } else {
            match side(lateral, longitudinal) {
                Side::Both => "coupled: longitudinal + lateral",
                Side::First if oscillates => "Dutch roll",
                Side::First => lateral_real(of(&["p"]), of(&["r"])),
                Side::Second => {
                    longitudinal_name(oscillates, of(&["alpha"]), (of(&["vt"]), of(&["altitude"])))
                }
            }
        });
    }
}

/// A real lateral root by its roll rate's share against its yaw rate's.
fn lateral_real(roll: f64, yaw: f64) -> &'static str {
    match side(roll, yaw) {
        Side::First => "roll subsidence",
        Side::Second => "spiral",
        Side::Both => "coupled: roll subsidence + spiral",
    }
}

/// A longitudinal mode by α's share against the speed's and the altitude's.
fn longitudinal_name(oscillates: bool, alpha: f64, (speed, altitude): (f64, f64)) -> &'static str {
    match (side(alpha, speed.max(altitude)), oscillates) {
        (Side::First, true) => "short period",
        (Side::First, false) => "short period, aperiodic",
        (Side::Second, true) => "phugoid",
        (Side::Second, false) if altitude >= DISTINCT * speed => "height",
        (Side::Second, false) => "phugoid, aperiodic",
        (Side::Both, _) => "coupled: short period + phugoid",
    }
}

/// The planes of motion of a body in six degrees of freedom (a vehicle's; a ship's three of
/// them), with the states that move in each.
const PLANES: [(&str, &[&str]); 4] = [
    ("surge", &["u"]),
    ("sway and yaw", &["v", "r", "psi"]),
    ("heave and pitch", &["w", "q", "theta", "z"]),
    ("roll", &["p", "phi"]),
];

/// Two planes that share a mode, by their places in [`PLANES`] (the first before the second).
fn coupled_planes(first: usize, second: usize) -> &'static str {
    match (first.min(second), first.max(second)) {
        (0, 1) => "coupled: surge + sway and yaw",
        (0, 2) => "coupled: surge + heave and pitch",
        (0, 3) => "coupled: surge + roll",
        (1, 2) => "coupled: sway and yaw + heave and pitch",
        (1, 3) => "coupled: sway and yaw + roll",
        _ => "coupled: heave and pitch + roll",
    }
}

/// Each mode by the plane of motion its largest shares lie in (see the module docs): the
/// plane of the largest share, where the next plane's is less than half of it; else the two
/// planes, coupled. A mode that moves none of the planes' states is left unnamed.
pub(super) fn name_planes(modes: &mut [Mode], names: &[String]) {
    for mode in modes.iter_mut() {
        let mut planes: Vec<(usize, f64)> = (PLANES.iter().enumerate())
            .map(|(i, (_, states))| (i, share(mode, names, states)))
            .collect();
        planes.sort_by(|x, y| y.1.total_cmp(&x.1));
        let ((first, largest), (second, next)) = (planes[0], planes[1]);
        mode.name = match side(largest, next) {
            _ if largest == 0.0 => None,
            Side::First => Some(PLANES[first].0),
            _ => Some(coupled_planes(first, second)),
        };
    }
}

/// Names the modes where the family knows them.
pub(super) fn name_modes(modes: &mut [Mode], family: Family) {
    let is =
        |mode: &Mode, names: &[&str]| mode.dominant.iter().all(|d| names.contains(&d.as_str()));
    let mut top_oscillations: Vec<usize> = Vec::new();
    for (index, mode) in modes.iter_mut().enumerate() {
        let oscillates = mode.eigenvalue.im > 0.0;
        let moving = mode.damping_ratio.is_some();
        mode.name = match family {
            Family::Pendulum if moving => Some("the pendulum's swing"),
            Family::Spatial
                if oscillates
                    && is(mode, &["p", "phi"])
                    && mode.dominant.iter().any(|d| d == "p") =>
            {
                Some("roll")
            }
            Family::Spatial if is(mode, &["p", "q", "r"]) && moving => Some(if oscillates {
                "nutation"
            } else {
                "the spin's instability"
            }),
            Family::Top if oscillates => {
                top_oscillations.push(index);
                None
            }
            Family::Top if moving => Some("the top's fall"),
            // Surge among the dominant entries: where u̇ depends on u alone (a straight course),
            // the sway–yaw modes have no u at all, and the surge mode drags some sway along.
            Family::PlanarAtG | Family::PlanarMidship
                if moving && mode.dominant.iter().any(|d| d == "u") =>
            {
                Some("surge")
            }
            Family::PlanarAtG | Family::PlanarMidship if moving => Some("sway and yaw"),
            _ => None,
        };
    }
    // A sleeping top's two oscillations: the faster in space is its nutation, the slower its
    // precession.
    let in_space = |mode: &Mode| mode.frequency_in_space.unwrap_or(mode.eigenvalue.im).abs();
    top_oscillations.sort_by(|&i, &j| in_space(&modes[j]).total_cmp(&in_space(&modes[i])));
    for (rank, index) in top_oscillations.into_iter().enumerate() {
        modes[index].name = Some(if rank == 0 { "nutation" } else { "precession" });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Complex;

    /// A mode at `eigenvalue` whose shares are `shares`, by name (the rest zero).
    fn mode(eigenvalue: Complex<f64>, shares: &[(&str, f64)], names: &[String]) -> Mode {
        let share = |name: &String| {
            (shares.iter())
                .find(|(n, _)| n == name)
                .map_or(0.0, |(_, s)| *s)
        };
        Mode {
            eigenvalue,
            period_s: None,
            period_in_turning_axes_s: None,
            damping_ratio: Some(1.0),
            time_to_double_s: None,
            time_to_half_s: None,
            shares: names.iter().map(share).collect(),
            dominant: Vec::new(),
            name: None,
            frequency_in_space: None,
        }
    }

    fn flight(eigenvalue: Complex<f64>, shares: &[(&str, f64)]) -> &'static str {
        let names: Vec<String> = [
            "vt", "alpha", "beta", "phi", "theta", "p", "q", "r", "altitude", "power",
        ]
        .map(String::from)
        .to_vec();
        let mut modes = [mode(eigenvalue, shares, &names)];
        name_flight_modes(&mut modes, &names);
        modes[0].name.unwrap()
    }

    /// Each name by what moves: α against speed and altitude, altitude against speed in a
    /// real root, roll rate against yaw rate, the groups against each other; a share at less
    /// than twice the other's is coupled.
    #[test]
    fn a_flight_mode_is_named_by_what_moves() {
        let pair = Complex::new(-1.0, 1.0);
        let real = Complex::new(-1.0, 0.0);
        let (theta, q) = (("theta", 1.0), ("q", 1.0));
        let named = |l, s: &[(&str, f64)]| flight(l, s);
        assert_eq!(
            named(pair, &[("alpha", 0.9), theta, q, ("vt", 0.4)]),
            "short period"
        );
        assert_eq!(
            named(real, &[("alpha", 0.9), ("vt", 0.4)]),
            "short period, aperiodic"
        );
        assert_eq!(
            named(pair, &[("vt", 0.7), theta, ("altitude", 0.7)]),
            "phugoid"
        );
        assert_eq!(
            named(real, &[("vt", 0.7), ("altitude", 0.8)]),
            "phugoid, aperiodic"
        );
        assert_eq!(named(real, &[("vt", 0.1), ("altitude", 1.0)]), "height");
        assert_eq!(
            named(pair, &[("alpha", 0.4), theta, ("vt", 0.3)]),
            "coupled: short period + phugoid"
        );
        assert_eq!(
            named(pair, &[("beta", 0.6), ("phi", 1.0), ("p", 1.0)]),
            "Dutch roll"
        );
        assert_eq!(
            named(real, &[("phi", 1.0), ("p", 1.0), ("r", 0.1)]),
            "roll subsidence"
        );
        assert_eq!(
            named(real, &[("phi", 0.2), ("p", 0.2), ("r", 1.0)]),
            "spiral"
        );
        assert_eq!(
            named(pair, &[("beta", 1.0), ("alpha", 0.7)]),
            "coupled: longitudinal + lateral"
        );
        assert_eq!(named(real, &[("power", 1.0)]), "power lag");
    }

    /// A plane names a mode where the next plane's share is less than half its own; else the
    /// two are named, coupled, whichever is the larger.
    #[test]
    fn a_vehicle_mode_is_named_by_its_plane_or_planes() {
        let names: Vec<String> = ["u", "v", "w", "p", "q", "r", "phi", "theta"]
            .map(String::from)
            .to_vec();
        let named = |shares: &[(&str, f64)]| {
            let mut modes = [mode(Complex::new(-1.0, 1.0), shares, &names)];
            name_planes(&mut modes, &names);
            modes[0].name
        };
        assert_eq!(
            named(&[("v", 1.0), ("r", 0.8), ("phi", 0.4)]),
            Some("sway and yaw")
        );
        assert_eq!(
            named(&[("v", 1.0), ("phi", 0.6)]),
            Some("coupled: sway and yaw + roll")
        );
        assert_eq!(
            named(&[("p", 1.0), ("r", 0.6)]),
            Some("coupled: sway and yaw + roll")
        );
        assert_eq!(named(&[("u", 1.0)]), Some("surge"));
        assert_eq!(named(&[]), None);
    }
}
