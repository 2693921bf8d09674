//! What a vehicle scene's run reports, as data: the model that ran, the method, the folded
//! table against its added mass, the cruise, and each manoeuvre's figures, converged.

use super::FoldedComparison;
use super::VehicleScene;
use super::autopilot::wrapped;
use super::manoeuvre::{Tracked, VehicleManoeuvre, VehicleRun, euler_angles};
use super::trial::{Ended, TrialFigures};
use serde::Serialize;
use std::collections::BTreeMap;

/// What a vehicle's summary adds to the keys every scene's shares.
#[derive(Debug, Clone, Serialize)]
pub struct VehicleSection {
    /// The model.
    pub model: ModelSummary,
    /// Per cross term of the added mass's Coriolis and centripetal terms: the table's value,
    /// what M_A implies, the difference (a folded table; empty for a derived one).
    pub kirchhoff: Vec<KirchhoffRow>,
    /// The cruise every manoeuvre starts from.
    pub cruise: CruiseSummary,
    /// Each manoeuvre by name.
    pub manoeuvre: BTreeMap<String, ManoeuvreSummary>,
    /// `integrator.stop_when` as the scene wrote it, where it has one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stop_when: Option<String>,
}

/// The model: the six equations about O with the table's terms.
#[derive(Debug, Clone, Serialize)]
pub struct ModelSummary {
    /// `vehicle`.
    pub family: &'static str,
    /// What it integrates.
    pub equations: &'static str,
    /// `prestero` or `fossen`.
    pub convention: &'static str,
    /// `folded` or `derived`.
    pub added_mass_coriolis: &'static str,
    /// The named force terms the model carries.
    pub terms: usize,
    /// What one right-hand side costs.
    pub operations: eom_kernel::Operations,
}

/// One cross term of Kirchhoff's terms.
#[derive(Debug, Clone, Serialize)]
pub struct KirchhoffRow {
    /// The load: X, Y, Z, K, M, N.
    pub load: String,
    /// The product of velocities.
    pub product: String,
    /// The table's coefficient of it, if it has one.
    pub coefficient: Option<String>,
    /// Its value in the table.
    pub printed: Option<f64>,
    /// What M_A implies for it.
    pub implied: f64,
    /// printed − implied.
    pub difference: Option<f64>,
}

impl KirchhoffRow {
    /// A row of the generator's comparison, the implied value and the difference to twelve
    /// significant digits.
    pub fn new(row: &FoldedComparison) -> Self {
        KirchhoffRow {
            load: row.load.letter().to_string(),
            product: row.product.clone(),
            coefficient: row.name.clone(),
            printed: row.printed,
            implied: twelve_digits(row.implied),
            difference: row.difference.map(twelve_digits),
        }
    }
}

/// `x` to twelve significant digits: a sum of a table's entries, each given to a few digits,
/// whose digits beyond are the rounding of the sum (4.86 − 4.8096 is 0.050400000000000666 in
/// binary, 0.0504 in the table's digits).
fn twelve_digits(x: f64) -> f64 {
    format!("{x:.11e}").parse::<f64>().unwrap_or(x) + 0.0
}

/// The trim every manoeuvre starts from ([`super::trim`]): surge and roll trimmed on the
/// model, against their closed forms, or the whole state but the position and the heading.
#[derive(Debug, Clone, Serialize)]
pub struct CruiseSummary {
    /// u of the trim, m/s.
    pub speed_m_s: f64,
    /// √(X_prop / −X_u|u|) where the table has a u|u| term and a propeller, on the straight
    /// level course (not given for a trim of the whole state, where it does not hold), m/s.
    pub speed_closed_form_m_s: Option<f64>,
    /// φ of the trim, degrees.
    pub roll_deg: f64,
    /// asin(K_prop / (z_G W − z_B B)), degrees: the propeller's torque against the righting
    /// moment, where the table has no other roll term on the straight level course (not given
    /// for a trim of the whole state).
    pub roll_closed_form_deg: Option<f64>,
    /// The states solved for: `["u", "phi"]` on the straight level course, else the whole
    /// state but the position and the heading.
    pub trimmed: Vec<&'static str>,
    /// Newton's steps on the whole state, where it was trimmed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub newton_steps: Option<usize>,
    /// θ of the trim, degrees.
    pub pitch_deg: f64,
    /// v of the trim, m/s.
    pub sway_m_s: f64,
    /// w of the trim, m/s.
    pub heave_m_s: f64,
    /// ψ̇ of the trim (a steady helix where it is not zero), degrees per second.
    pub heading_rate_deg_s: f64,
    /// ż of the trim (down positive), m/s.
    pub depth_rate_m_s: f64,
}

/// The figures of one step of the commands, read where it ends.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct StepFigures {
    /// When the step's commands began, s.
    pub from_s: f64,
    /// When they ended, s.
    pub to_s: f64,
    /// The rudder's angle commanded (saturated), degrees.
    pub rudder_deg: f64,
    /// The stern planes', degrees.
    pub stern_planes_deg: f64,
    /// r at the end, degrees per second.
    pub yaw_rate_deg_s: f64,
    /// √(u² + v² + w²) at the end, m/s.
    pub speed_m_s: f64,
    /// φ at the end, degrees.
    pub roll_deg: f64,
    /// θ at the end, degrees.
    pub pitch_deg: f64,
    /// ψ at the end, degrees.
    pub heading_deg: f64,
    /// z at the end (down positive), m.
    pub depth_m: f64,
}

/// How an autopilot answered one change of what it holds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SetpointFigures {
    /// `heading` (degrees) or `depth` (m).
    pub what: &'static str,
    /// When the setpoint changed, s.
    pub at_s: f64,
    /// The setpoint before, degrees or m.
    pub from: f64,
    /// The setpoint after.
    pub to: f64,
    /// How far past the new setpoint the motion went, in the direction of the change (zero
    /// if it never passed it), at the autopilot's samples.
    pub overshoot: f64,
    /// From the change until the error stays within [`SETTLING_BAND`] of the change for the
    /// rest of the step, s; `None` if it is outside at the step's end.
    pub settling_time_s: Option<f64>,
    /// The error (setpoint − value) at the step's end.
    pub steady_error: f64,
    /// When the step ended (the next change, or the run's end), s.
    pub until_s: f64,
}

/// The settling band, as a fraction of the change: 2 %, the control engineer's settling time.
pub const SETTLING_BAND: f64 = 0.02;

/// A time read at the autopilots' samples, to the nanosecond: an instant k·T_s carries the
/// rounding of the product (212 × 0.1 is 21.200000000000003), which a figure read there,
/// known to a sampling period, does not.
fn sampled(t: f64) -> f64 {
    (t * 1e9).round() / 1e9
}

impl SetpointFigures {
    /// The answer to every change of a setpoint in a run under the autopilots; in a run the
    /// stop condition ended, not the answer to a change whose step it cut short (its
    /// settling and steady error are read at the step's end).
    pub fn of(run: &VehicleRun) -> Vec<Self> {
        (Self::answers(run).into_iter())
            .filter_map(|(figures, cut)| (!cut).then_some(figures))
            .collect()
    }

    /// The changes (what, when) whose step the stop condition cut short, so that their
    /// answers are not given ([`SetpointFigures::of`]).
    pub fn cut_short(run: &VehicleRun) -> Vec<(&'static str, f64)> {
        (Self::answers(run).into_iter())
            .filter_map(|(figures, cut)| cut.then_some((figures.what, figures.at_s)))
            .collect()
    }

    /// Every change's answer as its samples give it, each with whether the stop condition cut
    /// its step short (its last, in a run it ended).
    fn answers(run: &VehicleRun) -> Vec<(Self, bool)> {
        let mut figures = Vec::new();
        for what in ["heading", "depth"] {
            let pick = |tracked: &Tracked| match what {
                "heading" => (tracked.setpoint.0, tracked.value.0),
                _ => (tracked.setpoint.1, tracked.value.1),
            };
            let error = |setpoint: f64, value: f64| match what {
                "heading" => wrapped(setpoint - value, 360.0),
                _ => setpoint - value,
            };
            let tracked = &run.tracked;
            let mut start = 0;
            for i in 1..=tracked.len() {
                let changes = i == tracked.len() || pick(&tracked[i]).0 != pick(&tracked[i - 1]).0;
                if !changes {
                    continue;
                }
                // The step tracked[start..i] holds one setpoint; it is a change if the one
                // before it differs.
                let (Some(to), _) = pick(&tracked[start]) else {
                    start = i;
                    continue;
                };
                let from = match start {
                    0 => None,
                    _ => pick(&tracked[start - 1]).0,
                };
                let cut = i == tracked.len() && run.stopped_at.is_some();
                if let Some(from) = from.filter(|&f| f != to) {
                    let change = error(to, from);
                    let errors: Vec<(f64, f64)> = (tracked[start..i].iter())
                        .map(|t| (t.t, error(to, pick(t).1)))
                        .collect();
                    let band = SETTLING_BAND * change.abs();
                    let settled_from = errors
                        .iter()
                        .rposition(|(_, e)| e.abs() > band)
                        .map_or(Some(0), |k| (k + 1 < errors.len()).then_some(k + 1));
                    let end = i.min(tracked.len() - 1);
                    let answer = SetpointFigures {
                        what,
                        at_s: sampled(tracked[start].t),
                        from,
                        to,
                        overshoot: errors
                            .iter()
                            .map(|(_, e)| -e * change.signum())
                            .fold(0.0, f64::max),
                        settling_time_s: settled_from
                            .map(|k| sampled(errors[k].0 - tracked[start].t)),
                        steady_error: errors.last().map_or(0.0, |(_, e)| *e),
                        until_s: sampled(tracked[end].t),
                    };
                    figures.push((answer, cut));
                }
                start = i;
            }
        }
        figures
    }

    fn values(&self) -> [f64; 3] {
        [
            self.overshoot,
            self.settling_time_s.unwrap_or(f64::INFINITY),
            self.steady_error,
        ]
    }
}

/// `radians` in degrees as a scene writes them: where a double within two units in the last
/// place of `radians.to_degrees()` converts back to `radians` exactly and has at most 15
/// significant digits (so that, written so, it reads back as itself), the one of the fewest;
/// else `radians.to_degrees()`. A negative zero is zero. A 7.5° command, converted to radians
/// to run, is reported as 7.5 and not as 7.499999999999999, the rounding of the two
/// conversions; a value computed in radians keeps every digit of its conversion.
pub fn degrees(radians: f64) -> f64 {
    let direct = radians.to_degrees();
    let digits = |x: f64| {
        let text = format!("{x:e}");
        let mantissa = text.split('e').next().unwrap_or("");
        mantissa.chars().filter(char::is_ascii_digit).count()
    };
    let (mut below, mut above) = (direct, direct);
    let mut best = (direct, digits(direct).min(16));
    for _ in 0..2 {
        (below, above) = (below.next_down(), above.next_up());
        for x in [below, above] {
            if x.to_radians() == radians && digits(x) < best.1 {
                best = (x, digits(x));
            }
        }
    }
    best.0 + 0.0
}

/// A trial's figures from its run, if the manoeuvre is a trial: none read at the end of a run
/// the stop condition ended.
pub fn trial_figures(run: &VehicleRun, manoeuvre: &VehicleManoeuvre) -> Option<TrialFigures> {
    let progress = run.trial.as_ref()?;
    let rudder = manoeuvre.steps.angles(progress.execute_time())[0];
    let end = match run.stopped_at {
        Some(t) => Ended::AtStopCondition(t),
        None => Ended::AtEnd(&run.ends.last()?.state),
    };
    Some(TrialFigures::of(progress, (rudder, end)))
}

/// The largest difference between two runs' autopilot figures (infinite where they differ in
/// number, or one settles and the other does not).
pub fn largest_setpoint_difference(a: &[SetpointFigures], b: &[SetpointFigures]) -> f64 {
    if a.len() != b.len() {
        return f64::INFINITY;
    }
    (a.iter().zip(b))
        .flat_map(|(x, y)| x.values().into_iter().zip(y.values()))
        .map(|(x, y)| if x == y { 0.0 } else { (x - y).abs() })
        .fold(0.0, f64::max)
}

/// A manoeuvre's figures and how far they move when the run is refined.
#[derive(Debug, Clone, Serialize)]
pub struct ManoeuvreSummary {
    /// Each step of the commands, the first being the cruise before the first change.
    pub steps: Vec<StepFigures>,
    /// Under the autopilots, how they answered each change of what they hold.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub autopilot: Vec<SetpointFigures>,
    /// A standard trial's figures (a turning circle's, a zig-zag's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trial: Option<TrialFigures>,
    /// The largest |figure − figure of the refined run| over every step's figures (degrees,
    /// degrees per second, m/s and m alike); `null` where the run was not refined (a Monte
    /// Carlo's case).
    pub refined_difference: Option<f64>,
    /// How the refined run was refined: `half the step` or `tolerances / 100`.
    pub refinement: &'static str,
    /// Steps taken.
    pub steps_taken: u64,
    /// With `integrator.stop_when`: where it ended the run, s, every digit (`null` where it
    /// never held); absent without one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stopped_at: Option<Option<f64>>,
    /// What the run could not measure, and why (a run the stop condition ended).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
}

impl StepFigures {
    /// The figures of each step of a run.
    pub fn of(run: &VehicleRun) -> Vec<Self> {
        let mut from = 0.0;
        run.ends
            .iter()
            .map(|end| {
                let [phi, theta, psi] = euler_angles(&end.state);
                let s = end.state;
                let figures = StepFigures {
                    from_s: from,
                    to_s: end.t,
                    rudder_deg: degrees(end.commands[0]),
                    stern_planes_deg: degrees(end.commands[1]),
                    yaw_rate_deg_s: s[5].to_degrees(),
                    speed_m_s: (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt(),
                    roll_deg: phi.to_degrees(),
                    pitch_deg: theta.to_degrees(),
                    heading_deg: psi.to_degrees(),
                    depth_m: s[8],
                };
                from = end.t;
                figures
            })
            .collect()
    }

    fn values(&self) -> [f64; 6] {
        [
            self.yaw_rate_deg_s,
            self.speed_m_s,
            self.roll_deg,
            self.pitch_deg,
            self.heading_deg,
            self.depth_m,
        ]
    }
}

/// The largest difference between two runs' figures, step by step (infinite where they do
/// not have the same steps).
pub fn largest_difference(a: &[StepFigures], b: &[StepFigures]) -> f64 {
    if a.len() != b.len() {
        return f64::INFINITY;
    }
    (a.iter().zip(b))
        .flat_map(|(x, y)| x.values().into_iter().zip(y.values()))
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

impl CruiseSummary {
    /// The trim of `scene`'s model, against the closed forms where they hold.
    pub fn new(scene: &VehicleScene) -> Self {
        let trim = &scene.trim;
        let start = &trim.state;
        let level = trim.whole_state_steps.is_none();
        let (closed_speed, closed_roll) = match level {
            true => closed_forms(&scene.table),
            false => (None, None),
        };
        let [phi, theta, _] = euler_angles(start);
        let (heading_rate, _) = super::trial::heading_and_pitch_rates(start);
        CruiseSummary {
            speed_m_s: start[0],
            speed_closed_form_m_s: closed_speed,
            roll_deg: phi.to_degrees(),
            roll_closed_form_deg: closed_roll,
            trimmed: trim.trimmed(),
            newton_steps: trim.whole_state_steps,
            pitch_deg: theta.to_degrees(),
            sway_m_s: start[1],
            heave_m_s: start[2],
            heading_rate_deg_s: heading_rate.to_degrees(),
            depth_rate_m_s: trim.depth_rate(),
        }
    }
}

/// The straight level cruise's speed and roll in closed form (see [`CruiseSummary`]).
fn closed_forms(table: &super::VehicleTable) -> (Option<f64>, Option<f64>) {
    // The names of X's u|u| under the table's convention (Fossen's u², the same ahead),
    // and the prime system's ½ρL² of a force of two linear velocities.
    let names: &[&str] = match table.convention {
        super::Convention::Prestero => &["Xuu"],
        super::Convention::Fossen => &["Xu|u|", "Xuu"],
    };
    let drag = names.iter().find_map(|n| table.coefficients.get(*n));
    let scale = table
        .prime
        .map_or(1.0, |p| 0.5 * p.density * p.length.powi(2));
    let closed_speed = match (table.propeller, drag) {
        (Some(p), Some(&x)) if x < 0.0 && p.thrust >= 0.0 => Some((p.thrust / (-x * scale)).sqrt()),
        _ => None,
    };
    let righting =
        table.centre_of_gravity[2] * table.weight - table.centre_of_buoyancy[2] * table.buoyancy;
    let closed_roll = table
        .propeller
        .filter(|p| righting > 0.0 && (p.torque / righting).abs() <= 1.0)
        .map(|p| (p.torque / righting).asin().to_degrees());
    (closed_speed, closed_roll)
}

impl ModelSummary {
    /// The model of `scene`.
    pub fn new(scene: &VehicleScene) -> Self {
        ModelSummary {
            family: "vehicle",
            equations: "4.1 and 4.2 about the table's origin O with G at r_G (4.5, 4.23), the \
                        added mass on the left, Kirchhoff's terms (4.48, 4.50) folded or \
                        derived, the table's terms, the propeller, weight and buoyancy; the \
                        quaternion's kinematics",
            convention: scene.table.convention.name(),
            added_mass_coriolis: match scene.table.added_mass_coriolis {
                super::AddedMassCoriolis::Folded => "folded",
                super::AddedMassCoriolis::Derived => "derived",
            },
            terms: scene.model.terms(),
            operations: scene.model.operations(),
        }
    }
}
