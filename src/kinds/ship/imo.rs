//! The IMO Standards for Ship Manoeuvrability (Resolution MSC.137(76), 2002), judged on the
//! figures of a scene's manoeuvres.
//!
//! | criterion | manoeuvre | limit |
//! |---|---|---|
//! | advance | turning circle at 35°, or at the steering gear's limit where it is smaller | ≤ 4.5 L |
//! | tactical diameter | the same turning circle | ≤ 5 L |
//! | initial turning | 10°/10° zig-zag: distance run when the heading has changed by 10° | ≤ 2.5 L |
//! | first overshoot, 10°/10° | 10°/10° zig-zag | 10° if L/V < 10 s; 20° if L/V ≥ 30 s; (5 + ½ L/V)° between |
//! | second overshoot, 10°/10° | 10°/10° zig-zag | 25° if L/V < 10 s; 40° if L/V ≥ 30 s; (17.5 + 0.75 L/V)° between |
//! | first overshoot, 20°/20° | 20°/20° zig-zag | ≤ 25° |
//! | track reach | crash stop: full astern from the test speed | ≤ 15 L |
//!
//! V is the test speed, the scene's design speed U₀. The turning criteria are judged on the
//! turning circle at the standard's angle, 35° or the steering gear's limit (`rudder.max_deg`)
//! where it is smaller, and on no other: a scene whose turning circles are all at other angles
//! has them listed as not judged, saying which angle they need. A manoeuvre run to both sides (the
//! default for a turning circle and a zig-zag: the resolution asks for the turning circle "to
//! port and starboard") is judged on each, and its verdict is the worse: the value judged is
//! the larger of the two, or the one that fails where the other side gave no figure; a side
//! without its figure and no failing one leaves the criterion not judged. A criterion whose manoeuvre the scene
//! does not run is left out, not passed; one whose manoeuvre ran but whose figure it did not
//! give (the ship went astern before its heading passed 90°, say: see the manoeuvre's notes)
//! is listed as not judged, with no verdict. The track reach is listed as not judged, with why,
//! where the scene has no propulsion model to go astern with, or runs no crash stop.

use super::manoeuvre::{Figures, Manoeuvre, ManoeuvreKind};
use super::scene::ShipScene;
use super::side::Side;
use crate::manoeuvring::steering::Rudder;

/// A manoeuvre as it ran: the manoeuvre, and the figures of each of its runs, by side (one run
/// of no side for a manoeuvre run as given).
pub type Trial<'a> = (&'a Manoeuvre, Vec<(Option<Side>, &'a Figures)>);

/// One criterion, judged.
#[derive(Debug, Clone, PartialEq)]
pub struct Criterion {
    /// Its key in the summary: `advance`, `tactical_diameter`, `initial_turning`,
    /// `first_overshoot_10_10`, `second_overshoot_10_10`, `first_overshoot_20_20`,
    /// `track_reach`.
    pub name: &'static str,
    /// The manoeuvre it is read from.
    pub manoeuvre: String,
    /// The figure; `None` where the manoeuvre ran but did not give it (its notes say why),
    /// so that the criterion is not judged.
    pub value: Option<f64>,
    /// The largest value allowed.
    pub limit: f64,
    /// `"m"` or `"deg"`.
    pub unit: &'static str,
    /// Each side's figure, for a manoeuvre run to both (empty otherwise).
    pub sides: Vec<(Side, Option<f64>)>,
    /// The side `value` is of, for a manoeuvre run to both or to one.
    pub side: Option<Side>,
    /// Why it is not judged, where that is not a missing figure of a manoeuvre that ran.
    pub not_judged_because: Option<String>,
}

impl Criterion {
    /// Whether the ship meets it; `None` when it is not judged.
    pub fn pass(&self) -> Option<bool> {
        self.value.map(|value| value <= self.limit)
    }
}

/// The 10°/10° first-overshoot limit for L/V in seconds.
pub fn first_overshoot_limit(l_over_v: f64) -> f64 {
    if l_over_v < 10.0 {
        10.0
    } else if l_over_v < 30.0 {
        5.0 + 0.5 * l_over_v
    } else {
        20.0
    }
}

/// The 10°/10° second-overshoot limit for L/V in seconds.
pub fn second_overshoot_limit(l_over_v: f64) -> f64 {
    if l_over_v < 10.0 {
        25.0
    } else if l_over_v < 30.0 {
        17.5 + 0.75 * l_over_v
    } else {
        40.0
    }
}

/// A zig-zag of `degrees`/`degrees`, to 1e-9 of a degree.
fn is_zigzag(kind: &ManoeuvreKind, degrees: f64) -> bool {
    let close = |angle: f64| (angle.to_degrees() - degrees).abs() < 1e-9;
    matches!(kind, ManoeuvreKind::ZigZag { rudder, heading } if close(rudder.abs()) && close(*heading))
}

/// The value judged of a figure over the sides it was read on, and its side: the larger, or
/// one over `limit` where another side gave none; `None` where a side gave none and none
/// fails.
fn judged_value(values: &[(Option<Side>, Option<f64>)], limit: f64) -> (Option<f64>, Option<Side>) {
    let present = values.iter().filter_map(|(side, v)| v.map(|v| (*side, v)));
    let largest = present.max_by(|a, b| a.1.total_cmp(&b.1));
    match largest {
        Some((side, value)) if value > limit || values.iter().all(|(_, v)| v.is_some()) => {
            (Some(value), side)
        }
        _ => (
            None,
            values
                .iter()
                .find(|(_, v)| v.is_none())
                .and_then(|(s, _)| *s),
        ),
    }
}

/// The rudder angle the turning criteria are judged at, rad: 35°, or the steering gear's
/// limit where it is smaller.
pub fn turning_angle(rudder: &Rudder) -> f64 {
    let standard = 35f64.to_radians();
    rudder.max_angle.map_or(standard, |max| max.min(standard))
}

/// Whether `kind` is a turning circle at `angle` (rad) to either side, to 1e-9 of a degree.
fn is_turn_at(kind: &ManoeuvreKind, angle: f64) -> bool {
    matches!(kind, ManoeuvreKind::TurningCircle { rudder }
        if (rudder.abs().to_degrees() - angle.to_degrees()).abs() < 1e-9)
}

/// A criterion listed as not judged, with why, resting on `manoeuvre`.
fn not_judged(
    name: &'static str,
    manoeuvre: String,
    (limit, unit): (f64, &'static str),
    why: String,
) -> Criterion {
    Criterion {
        name,
        manoeuvre,
        value: None,
        limit,
        unit,
        sides: Vec::new(),
        side: None,
        not_judged_because: Some(why),
    }
}

/// The turning criteria, judged on the turning circle at 35° or the gear's limit.
pub const TURNING: [&str; 2] = ["advance", "tactical_diameter"];
/// The zig-zag criteria, judged on the 10°/10° and the 20°/20° zig-zags.
pub const ZIGZAG: [&str; 4] = [
    "initial_turning",
    "first_overshoot_10_10",
    "second_overshoot_10_10",
    "first_overshoot_20_20",
];
/// The stopping criterion, listed whether or not it can be judged.
pub const STOPPING: &str = "track_reach";

/// The criteria the kinds of `scene`'s manoeuvres may give, whatever their angles, in the
/// order [`criteria`] lists them, each with whether a manoeuvre it may rest on runs to both
/// sides: what a sweep's table has a column for, the same in every case.
pub fn possible(scene: &ShipScene) -> Vec<(&'static str, bool)> {
    let of_kind = |turning: bool| {
        let mut runs = (scene.manoeuvres.iter()).filter(|m| match m.kind {
            ManoeuvreKind::TurningCircle { .. } => turning,
            ManoeuvreKind::ZigZag { .. } => !turning,
            _ => false,
        });
        let any = runs.clone().next().is_some();
        (any, runs.any(|m| m.sides.len() > 1))
    };
    let mut names = Vec::new();
    for (turning, group) in [(true, &TURNING[..]), (false, &ZIGZAG[..])] {
        if let (true, sided) = of_kind(turning) {
            names.extend(group.iter().map(|name| (*name, sided)));
        }
    }
    names.push((STOPPING, false));
    names
}

/// The criteria the runs of `scene` allow judging: its length, design speed, steering gear
/// and propulsion model (or none) decide the limits and what can be judged.
pub fn criteria(scene: &ShipScene, runs: &[Trial]) -> Vec<Criterion> {
    let (length, speed) = (scene.length, scene.table.design_speed);
    let propulsion = scene.table.propulsion.is_some();
    let l_over_v = length / speed;
    let mut judged = Vec::new();
    let judge = |name, run: &Trial, key: &str, limit: f64, unit| {
        let values: Vec<(Option<Side>, Option<f64>)> =
            run.1.iter().map(|(side, f)| (*side, f.get(key))).collect();
        let (value, side) = judged_value(&values, limit);
        let sides = match values.as_slice() {
            [_, _, ..] => values
                .iter()
                .filter_map(|(s, v)| s.map(|s| (s, *v)))
                .collect(),
            _ => Vec::new(),
        };
        Criterion {
            name,
            manoeuvre: run.0.name.clone(),
            value,
            limit,
            unit,
            sides,
            side,
            not_judged_because: None,
        }
    };
    let angle = turning_angle(&scene.rudder);
    let turns: Vec<&Trial> = (runs.iter())
        .filter(|run| matches!(run.0.kind, ManoeuvreKind::TurningCircle { .. }))
        .collect();
    let turning = [
        ("advance", "advance_90_m", 4.5 * length),
        ("tactical_diameter", "tactical_diameter_m", 5.0 * length),
    ];
    match turns.iter().find(|run| is_turn_at(&run.0.kind, angle)) {
        Some(run) => {
            for (name, key, limit) in turning {
                judged.push(judge(name, run, key, limit, "m"));
            }
        }
        None if !turns.is_empty() => {
            let why = wrong_turns(&turns, angle, scene.rudder.max_angle);
            let wanted = format!("turning_circle_{}", crate::Short(angle.to_degrees()));
            for (name, _, limit) in turning {
                judged.push(not_judged(name, wanted.clone(), (limit, "m"), why.clone()));
            }
        }
        None => {}
    }
    if let Some(run) = runs.iter().find(|run| is_zigzag(&run.0.kind, 10.0)) {
        judged.push(judge(
            "initial_turning",
            run,
            "initial_turning_distance_m",
            2.5 * length,
            "m",
        ));
        let first = first_overshoot_limit(l_over_v);
        judged.push(judge(
            "first_overshoot_10_10",
            run,
            "first_overshoot_deg",
            first,
            "deg",
        ));
        let second = second_overshoot_limit(l_over_v);
        judged.push(judge(
            "second_overshoot_10_10",
            run,
            "second_overshoot_deg",
            second,
            "deg",
        ));
    }
    if let Some(run) = runs.iter().find(|run| is_zigzag(&run.0.kind, 20.0)) {
        judged.push(judge(
            "first_overshoot_20_20",
            run,
            "first_overshoot_deg",
            25.0,
            "deg",
        ));
    }
    // The stopping ability: the track reach of a full astern stop from the test speed. A ship
    // table without a propulsion model cannot go astern, so the criterion is listed as not
    // judged rather than left out; so is it for a scene that runs no crash stop.
    let crash_stop = runs
        .iter()
        .find(|run| matches!(run.0.kind, ManoeuvreKind::CrashStop { .. }));
    match crash_stop {
        Some(run) if propulsion => {
            judged.push(judge(
                "track_reach",
                run,
                "track_reach_m",
                15.0 * length,
                "m",
            ));
        }
        _ => judged.push(not_judged(
            "track_reach",
            "crash_stop".to_owned(),
            (15.0 * length, "m"),
            (match (propulsion, scene.table.mmg.is_some()) {
                (true, _) => NO_CRASH_STOP,
                (false, true) => MMG_AHEAD_ONLY,
                (false, false) => NO_PROPULSION,
            })
            .to_owned(),
        )),
    }
    let in_current = scene.table.current.is_some_and(|c| c.speed > 0.0);
    let in_wind = scene.table.wind.as_ref().is_some_and(|w| w.speed > 0.0);
    let not_calm = match (in_current, in_wind) {
        (true, _) => Some(IN_CURRENT),
        (false, true) => Some(IN_WIND),
        (false, false) => None,
    };
    if let Some(why) = not_calm {
        // Each side's figure stays, for the record; no verdict rests on it.
        for criterion in judged.iter_mut().filter(|c| c.not_judged_because.is_none()) {
            criterion.value = None;
            criterion.side = None;
            criterion.not_judged_because = Some(why.to_owned());
        }
    }
    judged
}

/// Why no criterion is judged in a current.
pub const IN_CURRENT: &str = "the scene has a current: IMO MSC.137(76) judges trials in calm \
                              water, and the track's figures here are over ground";

/// Why no criterion is judged in a wind.
pub const IN_WIND: &str = "the scene has a wind: IMO MSC.137(76) judges trials in calm \
                           weather, and the track's figures here are over ground";

/// Why the turning criteria are not judged on a scene whose turning circles are all at
/// other angles than `angle` (rad): which angle they need, and the angles the scene ran.
fn wrong_turns(turns: &[&Trial], angle: f64, gear: Option<f64>) -> String {
    let ran: Vec<String> = (turns.iter())
        .filter_map(|run| match run.0.kind {
            ManoeuvreKind::TurningCircle { rudder } => Some(format!(
                "{} at {}°",
                run.0.name,
                crate::Short(rudder.abs().to_degrees())
            )),
            _ => None,
        })
        .collect();
    let standard = match gear {
        Some(max) if max < 35f64.to_radians() => "the steering gear's limit, rudder.max_deg",
        _ => "the standard's angle",
    };
    format!(
        "the turning criteria rest on a turning circle at {}° ({standard}), and the scene \
         runs only {}",
        crate::Short(angle.to_degrees()),
        ran.join(", ")
    )
}

/// Why the stopping criterion is not judged, without a propulsion model.
pub const NO_PROPULSION: &str = "the scene gives no propulsion model, so no crash stop can be run";

/// Why the stopping criterion is not judged for an MMG ship.
pub const MMG_AHEAD_ONLY: &str = "the MMG standard method's propeller and rudder are for a \
                                  ship moving ahead with its propeller turning ahead, so no \
                                  crash stop can be run";

/// Why the stopping criterion is not judged, with one.
pub const NO_CRASH_STOP: &str = "the scene runs no crash_stop manoeuvre";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_verdict_of_two_sides_is_the_worse() {
        let (port, starboard) = (Some(Side::Port), Some(Side::Starboard));
        let both = |p, s| judged_value(&[(port, p), (starboard, s)], 10.0);
        assert_eq!(both(Some(3.0), Some(5.0)), (Some(5.0), starboard));
        assert_eq!(both(Some(12.0), Some(5.0)), (Some(12.0), port));
        // A side without its figure: not judged, unless the other fails anyway.
        assert_eq!(both(Some(3.0), None), (None, starboard));
        assert_eq!(both(None, Some(11.0)), (Some(11.0), starboard));
        assert_eq!(judged_value(&[(None, Some(4.0))], 10.0), (Some(4.0), None));
    }

    #[test]
    fn overshoot_limits_follow_the_resolution() {
        assert_eq!(first_overshoot_limit(5.0), 10.0);
        assert_eq!(first_overshoot_limit(20.0), 15.0);
        assert_eq!(first_overshoot_limit(30.0), 20.0);
        assert_eq!(second_overshoot_limit(9.9), 25.0);
        assert_eq!(second_overshoot_limit(20.0), 32.5);
        assert_eq!(second_overshoot_limit(31.0), 40.0);
    }
}
