//! What a spiral's points say: a loop, none, or undetermined, read only from the points that
//! settled and only where they differ by more than the settling criterion can tell apart.
//!
//! **Direct spiral.** A settled r is within ε ([`Settle::resolution`]) of its steady value, so
//! the two passes at one angle are two steady turns only where they differ by more than 2ε.
//! Each angle is
//! - *split* where both passes settled, turn the ship opposite ways and differ by more than
//!   2ε: the ship keeps turning the way it came, a loop;
//! - *within the resolution* where they turn it opposite ways by no more than 2ε: a
//!   course-stable ship's passes do so about its straight course, each still approaching the
//!   one steady turn from its own side;
//! - *unsettled* where a pass did not settle: nothing rests on it;
//! - *agreed* otherwise.
//!
//! One split angle shows a loop. Its ends lie between the outermost split angles and the
//! nearest agreed angle beyond each (unsettled and unresolved angles are skipped): the width is
//! taken to the middle of each gap, and is known to lie between the split angles' span (the
//! least) and the agreed angles' span (the most). Without a split angle the verdict is
//! undetermined where an angle is within the resolution (saying the settling that would tell
//! that difference apart) or unsettled (saying so), and otherwise no loop.
//!
//! **Reverse spiral.** δ against r from the settled points: a loop where δ(r) turns back
//! against the curve's trend by more than twice the rudder's settling tolerance; the width is
//! the δ between the extremes of the stretch turned back (the folds lie at or beyond them);
//! undetermined where it turns back by less, or where a point did not settle and none turns
//! back.
//!
//! The steady-turn curve ([`super::super::steady`]) gives the loop's true ends without any
//! procedure: the summary shows it beside the verdict.

use super::{Branch, Settle, SpiralCurve, SpiralPoint};
use crate::Short;

/// What a spiral's points say.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// One steady turn at each angle measured: a course-stable ship's curve.
    NoLoop,
    /// Two steady turns at some angle: a course-unstable ship's loop.
    Loop(Loop),
    /// Neither can be read from the points, and why (with the settling that would tell).
    Undetermined(String),
}

impl Loop {
    /// The least width the points allow, rad: the span of [`Loop::inner`].
    pub fn least_width(&self) -> f64 {
        self.inner.1 - self.inner.0
    }
}

impl Verdict {
    /// Whether the spiral shows the ship course-stable: `Some(true)` without a loop,
    /// `Some(false)` with one, `None` when undetermined.
    pub fn course_stable(&self) -> Option<bool> {
        match self {
            Verdict::NoLoop => Some(true),
            Verdict::Loop(_) => Some(false),
            Verdict::Undetermined(_) => None,
        }
    }

    /// `no loop`, `loop` or `undetermined`.
    pub fn name(&self) -> &'static str {
        match self {
            Verdict::NoLoop => "no loop",
            Verdict::Loop(_) => "loop",
            Verdict::Undetermined(_) => "undetermined",
        }
    }
}

/// The loop of an r–δ curve, as the settled points show it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Loop {
    /// The range of δ where two steady turns exist, rad, to the middle of the gaps at its
    /// ends.
    pub width: f64,
    /// The jump in r across the loop at δ = 0 (or the split angle nearest it), rad/s; `None`
    /// where the loop does not reach δ = 0.
    pub height: Option<f64>,
    /// Its ends, rad, as `width` takes them.
    pub ends: (f64, f64),
    /// The δ the points show two steady turns between, rad: the outermost split angles
    /// (direct), the extremes of the stretch turned back (reverse); its span is the least
    /// width the points allow.
    pub inner: (f64, f64),
    /// The most, rad: the span of the agreed angles beyond the ends (direct); `None` where the
    /// loop runs past the angles measured, or for a reverse spiral.
    pub most_width: Option<f64>,
    /// The direct spiral's spacing of angles at the loop's ends (the larger), rad.
    pub step: Option<f64>,
}

/// The verdict of a spiral's curve.
pub(super) fn of(curve: &SpiralCurve) -> Verdict {
    if let Some(why) = &curve.incomplete {
        return Verdict::Undetermined(why.clone());
    }
    if curve.points.iter().any(|p| p.branch == Branch::Reverse) {
        reverse(&curve.points, &curve.settle)
    } else {
        direct(&curve.points, &curve.settle)
    }
}

/// What one angle of a direct spiral shows.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Angle {
    Agreed,
    /// The passes differ in sign by more than 2ε.
    Split(f64),
    /// They differ in sign by no more than 2ε.
    Within(f64),
    Unsettled,
}

fn classify(first: Option<&SpiralPoint>, back: Option<&SpiralPoint>, epsilon: f64) -> Angle {
    if [first, back].into_iter().flatten().any(|p| !p.settled) {
        return Angle::Unsettled;
    }
    match (first, back) {
        (Some(f), Some(b)) if f.yaw_rate * b.yaw_rate < 0.0 => {
            let apart = (f.yaw_rate - b.yaw_rate).abs();
            if apart > 2.0 * epsilon {
                Angle::Split(apart)
            } else {
                Angle::Within(apart)
            }
        }
        _ => Angle::Agreed,
    }
}

fn direct(points: &[SpiralPoint], settle: &Settle) -> Verdict {
    let epsilon = settle.resolution();
    let mut angles: Vec<f64> = points.iter().map(|p| p.rudder).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    let on = |branch: Branch, rudder: f64| {
        (points.iter()).find(|p| p.branch == branch && p.rudder == rudder)
    };
    let classes: Vec<(f64, Angle)> = (angles.iter())
        .map(|&d| {
            (
                d,
                classify(on(Branch::First, d), on(Branch::Back, d), epsilon),
            )
        })
        .collect();
    let split: Vec<usize> = (0..classes.len())
        .filter(|&i| matches!(classes[i].1, Angle::Split(_)))
        .collect();
    if let (Some(&low), Some(&high)) = (split.first(), split.last()) {
        return Verdict::Loop(direct_loop(&classes, low, high));
    }
    let within = (classes.iter())
        .filter_map(|(d, class)| match class {
            Angle::Within(apart) => Some((*d, *apart)),
            _ => None,
        })
        .max_by(|a, b| a.1.total_cmp(&b.1));
    if let Some((rudder, apart)) = within {
        return Verdict::Undetermined(unresolved(rudder, apart, settle));
    }
    let unsettled: Vec<f64> = (classes.iter())
        .filter(|(_, class)| *class == Angle::Unsettled)
        .map(|(d, _)| *d)
        .collect();
    if !unsettled.is_empty() {
        return Verdict::Undetermined(not_settled(&unsettled, settle));
    }
    Verdict::NoLoop
}

/// The loop between the split angles `low` and `high` (indices into `classes`, sorted by δ).
fn direct_loop(classes: &[(f64, Angle)], low: usize, high: usize) -> Loop {
    let agreed = |i: &usize| classes[*i].1 == Angle::Agreed;
    let below = (0..low).rev().find(agreed).map(|i| classes[i].0);
    let above = (high + 1..classes.len()).find(agreed).map(|i| classes[i].0);
    let (from, to) = (classes[low].0, classes[high].0);
    let ends = (
        below.map_or(from, |b| 0.5 * (from + b)),
        above.map_or(to, |a| 0.5 * (to + a)),
    );
    let before = low.checked_sub(1).map(|i| from - classes[i].0);
    let after = classes.get(high + 1).map(|(d, _)| d - to);
    let step = match (before, after) {
        (Some(a), Some(b)) => Some(a.max(b)),
        (one, other) => one.or(other),
    };
    let height = (classes.iter())
        .filter_map(|(d, class)| match class {
            Angle::Split(apart) => Some((*d, *apart)),
            _ => None,
        })
        .min_by(|a, b| a.0.abs().total_cmp(&b.0.abs()))
        .map(|(_, apart)| apart);
    Loop {
        width: ends.1 - ends.0,
        height,
        ends,
        inner: (from, to),
        most_width: below.zip(above).map(|(b, a)| a - b),
        step,
    }
}

/// Why passes that differ in sign by `apart` (rad/s) at `rudder` are not a loop, and the
/// settling that would tell a difference that size apart: ε a quarter of it.
fn unresolved(rudder: f64, apart: f64, settle: &Settle) -> String {
    let epsilon = settle.resolution();
    let time = settle.time_constant;
    let wanted = apart / 4.0;
    let window = (time * (settle.tolerance / wanted).ln_1p() / 10.0).ceil() * 10.0;
    let tolerance = wanted * (settle.window / time).exp_m1();
    format!(
        "the passes turn the ship opposite ways at δ = {}° but differ by {}°/s, within what the \
         settling tells apart: a settled r is within ε = {}°/s of the steady one \
         (tolerance/(e^(W/T₁) − 1), T₁ = {} s from the linear model), so two closer than 2ε \
         may be one steady turn; to tell a difference this size apart, settle_window_s = {} \
         (at this tolerance) or settle_tolerance_deg_s = {} (at this window); the steady-turn \
         curve shows the loop, if any, without a procedure",
        Short(rudder.to_degrees()),
        Short(apart.to_degrees()),
        Short(epsilon.to_degrees()),
        Short(time),
        Short(window),
        Short(tolerance.to_degrees())
    )
}

/// Why angles that did not settle leave the verdict open.
fn not_settled(rudders: &[f64], settle: &Settle) -> String {
    let listed: Vec<String> = (rudders.iter())
        .map(|d| format!("{}°", Short(d.to_degrees())))
        .collect();
    format!(
        "δ = {} did not settle within max_hold_s = {} s and no verdict rests on them; hold \
         longer (the ship's slowest sway–yaw time constant is {} s)",
        listed.join(", "),
        Short(settle.max_hold),
        Short(settle.time_constant)
    )
}

fn reverse(points: &[SpiralPoint], settle: &Settle) -> Verdict {
    let mut curve: Vec<(f64, f64)> = (points.iter())
        .filter(|p| p.settled)
        .map(|p| (p.yaw_rate, p.rudder))
        .collect();
    curve.sort_by(|a, b| a.0.total_cmp(&b.0));
    let unsettled: Vec<f64> = (points.iter())
        .filter(|p| !p.settled)
        .map(|p| p.rudder)
        .collect();
    let (Some(first), Some(last)) = (curve.first(), curve.last()) else {
        return Verdict::Undetermined(not_settled(&unsettled, settle));
    };
    let trend = (last.1 - first.1).signum();
    // The points at either end of a stretch where δ(r) goes against the curve's trend.
    let folded: Vec<f64> = (curve.windows(2))
        .filter(|w| (w[1].1 - w[0].1) * trend < 0.0)
        .flat_map(|w| [w[0].1, w[1].1])
        .collect();
    if folded.is_empty() {
        return match unsettled.is_empty() {
            true => Verdict::NoLoop,
            false => Verdict::Undetermined(not_settled(&unsettled, settle)),
        };
    }
    let low = folded.iter().copied().fold(f64::INFINITY, f64::min);
    let high = folded.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if high - low <= 2.0 * settle.rudder_tolerance {
        return Verdict::Undetermined(format!(
            "δ(r) turns back by {}°, no more than twice the rudder's settling tolerance ({}°): \
             settle_rudder_deg = {} would tell it apart",
            Short((high - low).to_degrees()),
            Short(settle.rudder_tolerance.to_degrees()),
            Short((high - low).to_degrees() / 4.0)
        ));
    }
    Verdict::Loop(Loop {
        width: high - low,
        height: reverse_height(&curve, 0.5 * (low + high)),
        ends: (low, high),
        inner: (low, high),
        most_width: None,
        step: None,
    })
}

/// The r between the outer crossings of δ(r) with the loop's middle angle `middle`, halfway
/// between its folds (δ = 0 for a ship without bias).
fn reverse_height(curve: &[(f64, f64)], middle: f64) -> Option<f64> {
    let crossings: Vec<f64> = (curve.windows(2))
        .map(|w| (w[0].0, w[0].1 - middle, w[1].0, w[1].1 - middle))
        .filter(|(_, d0, _, d1)| d0 * d1 < 0.0 || *d1 == 0.0)
        .map(|(r0, d0, r1, d1)| r0 - d0 * (r1 - r0) / (d1 - d0))
        .collect();
    (crossings.len() >= 3).then(|| crossings[crossings.len() - 1] - crossings[0])
}

#[cfg(test)]
mod tests {
    use super::super::Settle;
    use super::*;

    fn point(rudder_deg: f64, r: f64, branch: Branch) -> SpiralPoint {
        SpiralPoint {
            rudder: rudder_deg.to_radians(),
            yaw_rate: r,
            target: None,
            branch,
            settled: true,
            held: 100.0,
            at: 0.0,
        }
    }

    /// W = 100 s, tolerance 1e-3 rad/s, T = 100/ln 2 s: ε = 1e-3 rad/s.
    fn settle() -> Settle {
        Settle {
            window: 100.0,
            tolerance: 1e-3,
            max_hold: 1000.0,
            rudder_tolerance: 1e-3,
            speed_tolerance: 1e-3,
            time_constant: 100.0 / std::f64::consts::LN_2,
        }
    }

    /// A direct spiral through ±6° every 2°, each pass's r at the angles from 6° down.
    fn direct_curve(first: [f64; 7], back: [f64; 7]) -> SpiralCurve {
        let angles = [6.0, 4.0, 2.0, 0.0, -2.0, -4.0, -6.0];
        let mut points: Vec<SpiralPoint> = (angles.iter().zip(first))
            .map(|(&d, r)| point(d, r, Branch::First))
            .collect();
        points.extend(
            (angles.iter().zip(back).rev().skip(1)).map(|(&d, r)| point(d, r, Branch::Back)),
        );
        SpiralCurve {
            points,
            settle: settle(),
            incomplete: None,
            steady: Err("not traced".into()),
        }
    }

    /// An unstable ship's direct spiral: between −2° and 2° the passes disagree.
    #[test]
    fn a_direct_loop_is_where_the_passes_disagree() {
        let first = [-0.3, -0.25, -0.2, -0.15, -0.1, 0.25, 0.3];
        let back = [-0.3, -0.25, 0.1, 0.15, 0.2, 0.25, 0.3];
        let curve = direct_curve(first, back);
        let found = curve.find_loop().unwrap();
        // From halfway between −4° and −2° to halfway between 2° and 4°, the split angles'
        // span the least, the agreed angles' the most, at a step of 2°.
        let degrees = |x: f64| x.to_degrees();
        assert!((degrees(found.width) - 6.0).abs() < 1e-12, "{found:?}");
        assert!((degrees(found.least_width()) - 4.0).abs() < 1e-12);
        assert!((degrees(found.most_width.unwrap()) - 8.0).abs() < 1e-12);
        assert!((degrees(found.step.unwrap()) - 2.0).abs() < 1e-12);
        assert!((found.height.unwrap() - 0.3).abs() < 1e-12);
        // The same passes agreeing: no loop.
        let mut stable = curve.clone();
        for p in &mut stable.points {
            p.yaw_rate = -0.05 * p.rudder.to_degrees();
        }
        assert_eq!(stable.verdict(), Verdict::NoLoop);
    }

    /// No figure rests on an unsettled point: the loop's end moves out to the next settled
    /// angle that agrees, and an unsettled split is no split.
    #[test]
    fn an_unsettled_point_bears_no_figure() {
        let first = [-0.3, -0.25, -0.2, -0.15, -0.1, 0.25, 0.3];
        let back = [-0.3, -0.25, 0.1, 0.15, 0.2, 0.25, 0.3];
        let mut curve = direct_curve(first, back);
        // The first pass at −2° (a split) and the back pass at −4° (agreed) not settled.
        for p in &mut curve.points {
            let degrees = p.rudder.to_degrees();
            let first_at_minus_2 = p.branch == Branch::First && (degrees + 2.0).abs() < 1e-9;
            let back_at_minus_4 = p.branch == Branch::Back && (degrees + 4.0).abs() < 1e-9;
            if first_at_minus_2 || back_at_minus_4 {
                p.settled = false;
            }
        }
        let found = curve.find_loop().unwrap();
        // Split only at 0° and 2°; below, −2° and −4° are unsettled, −6° agrees.
        assert!(
            (found.least_width().to_degrees() - 2.0).abs() < 1e-12,
            "{found:?}"
        );
        assert!((found.ends.0.to_degrees() + 3.0).abs() < 1e-12, "{found:?}");
        assert!((found.ends.1.to_degrees() - 3.0).abs() < 1e-12, "{found:?}");
    }

    /// A course-stable ship's passes straddle its straight course by no more than 2ε: the
    /// spiral cannot tell that from a loop, says so, and names the settling that would.
    #[test]
    fn passes_within_the_resolution_are_undetermined() {
        let first = [-0.3, -0.2, -0.1, -0.0009, 0.1, 0.2, 0.3];
        let back = [-0.3, -0.2, -0.1, 0.0009, 0.1, 0.2, 0.3];
        let curve = direct_curve(first, back);
        let Verdict::Undetermined(why) = curve.verdict() else {
            panic!("{:?}", curve.verdict());
        };
        assert!(why.contains("settle_window_s = "), "{why}");
        assert_eq!(curve.verdict().course_stable(), None);
        // The same disagreement beyond 2ε (ε = 1e-3 rad/s): a loop.
        let first = [-0.3, -0.2, -0.1, -0.0011, 0.1, 0.2, 0.3];
        let back = [-0.3, -0.2, -0.1, 0.0011, 0.1, 0.2, 0.3];
        assert!(direct_curve(first, back).find_loop().is_some());
    }

    #[test]
    fn a_reverse_loop_is_where_the_rudder_turns_back() {
        // δ(r) = r³ − r, a loop between the folds at r = ±1/√3, crossing zero at r = 0, ±1.
        let points: Vec<SpiralPoint> = (-12..=12)
            .map(|k| {
                let r = f64::from(k) / 10.0;
                SpiralPoint {
                    rudder: r * r * r - r,
                    branch: Branch::Reverse,
                    ..point(0.0, r, Branch::Reverse)
                }
            })
            .collect();
        let curve = SpiralCurve {
            points,
            settle: settle(),
            incomplete: None,
            steady: Err("not traced".into()),
        };
        let found = curve.find_loop().unwrap();
        // The grid's extremes of δ: ±(0.6 − 0.216) = ±0.384 (the folds are ±0.3849).
        assert!((found.width - 0.768).abs() < 1e-12, "{found:?}");
        assert!((found.height.unwrap() - 2.0).abs() < 1e-12);
        // Turned back by less than twice the rudder's tolerance: undetermined.
        let mut small = curve.clone();
        small.settle.rudder_tolerance = 0.5;
        assert!(matches!(small.verdict(), Verdict::Undetermined(_)));
        // A spiral cut short says nothing.
        let mut cut = curve;
        cut.incomplete = Some("the run ended".into());
        assert_eq!(cut.verdict(), Verdict::Undetermined("the run ended".into()));
    }
}
