//! The IMO Standards for Ship Manoeuvrability (Resolution MSC.137(76), 2002), judged on the
//! figures of a scene's manoeuvres.
//!
//! | criterion | manoeuvre | limit |
//! |---|---|---|
//! | advance | turning circle, the largest rudder of the scene's (35° in the standard) | ≤ 4.5 L |
//! | tactical diameter | the same turning circle | ≤ 5 L |
//! | initial turning | 10°/10° zig-zag: distance run when the heading has changed by 10° | ≤ 2.5 L |
//! | first overshoot, 10°/10° | 10°/10° zig-zag | 10° if L/V < 10 s; 20° if L/V ≥ 30 s; (5 + ½ L/V)° between |
//! | second overshoot, 10°/10° | 10°/10° zig-zag | 25° if L/V < 10 s; 40° if L/V ≥ 30 s; (17.5 + 0.75 L/V)° between |
//! | first overshoot, 20°/20° | 20°/20° zig-zag | ≤ 25° |
//!
//! V is the test speed, the scene's design speed U₀. A criterion whose manoeuvre the scene
//! does not run is left out, not passed; one whose manoeuvre ran but whose figure it did not
//! give (the ship went astern before its heading passed 90°, say: see the manoeuvre's notes)
//! is listed as not judged, with no verdict.

use super::manoeuvre::{Figures, Manoeuvre, ManoeuvreKind};

/// One criterion, judged.
#[derive(Debug, Clone, PartialEq)]
pub struct Criterion {
    /// Its key in the summary: `advance`, `tactical_diameter`, `initial_turning`,
    /// `first_overshoot_10_10`, `second_overshoot_10_10`, `first_overshoot_20_20`.
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

/// The criteria the runs allow judging, for a ship of length `length` (m) at `speed` (m/s).
pub fn criteria(length: f64, speed: f64, runs: &[(&Manoeuvre, &Figures)]) -> Vec<Criterion> {
    let l_over_v = length / speed;
    let mut judged = Vec::new();
    let mut judge = |name, run: &(&Manoeuvre, &Figures), key: &str, limit: f64, unit| {
        judged.push(Criterion {
            name,
            manoeuvre: run.0.name.clone(),
            value: run.1.get(key),
            limit,
            unit,
        });
    };
    let turn = runs
        .iter()
        .filter_map(|run| match run.0.kind {
            ManoeuvreKind::TurningCircle { rudder } => Some((rudder.abs(), run)),
            _ => None,
        })
        .max_by(|a, b| a.0.total_cmp(&b.0));
    if let Some((_, run)) = turn {
        judge("advance", run, "advance_90_m", 4.5 * length, "m");
        judge(
            "tactical_diameter",
            run,
            "tactical_diameter_m",
            5.0 * length,
            "m",
        );
    }
    if let Some(run) = runs.iter().find(|run| is_zigzag(&run.0.kind, 10.0)) {
        judge(
            "initial_turning",
            run,
            "initial_turning_distance_m",
            2.5 * length,
            "m",
        );
        let first = first_overshoot_limit(l_over_v);
        judge(
            "first_overshoot_10_10",
            run,
            "first_overshoot_deg",
            first,
            "deg",
        );
        let second = second_overshoot_limit(l_over_v);
        judge(
            "second_overshoot_10_10",
            run,
            "second_overshoot_deg",
            second,
            "deg",
        );
    }
    if let Some(run) = runs.iter().find(|run| is_zigzag(&run.0.kind, 20.0)) {
        judge(
            "first_overshoot_20_20",
            run,
            "first_overshoot_deg",
            25.0,
            "deg",
        );
    }
    judged
}

#[cfg(test)]
mod tests {
    use super::*;

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
