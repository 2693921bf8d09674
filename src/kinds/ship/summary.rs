//! What a ship scene's run reports, as data: the model that ran, the method, the linear model
//! about the straight course, each manoeuvre's figures with how far each moved when the run
//! was refined, and the IMO criteria.
//!
//! These are the types `summary.json` is written from (serde), so its keys are these fields'
//! names; the application writes them with the keys of every object sorted, as a ship's
//! summary has always been written. A library user gets the same numbers without parsing JSON.

use super::environment::EnvironmentSummary;
use super::imo::Criterion;
use super::linear::{LinearModel, Nomoto, linearise};
use super::manoeuvre::{Figures, Manoeuvre, ManoeuvreKind};
use super::mmg::Edge;
use super::side::Side;
use super::spiral::{Branch, SpiralCurve, Verdict};
use super::steady::{SteadyTurn, SteadyTurns};
use super::table::RigidBodyTerms;
use super::{ShipModel, ShipScene};
use super::{Units, YawInertia};

use crate::integrate::Stepper;
use crate::models::Operations;
use crate::output::summary::{self, Figure, RunFigures};
use serde::Serialize;
use std::collections::BTreeMap;

/// What a ship's summary adds to the keys every scene's shares.
#[derive(Debug, Clone, Serialize)]
pub struct ShipSection {
    /// The model that ran.
    pub model: ModelSummary,
    /// The linear model about the straight course.
    pub linear: LinearSummary,
    /// Each manoeuvre's figures by its name, and the IMO criteria under `imo`.
    pub manoeuvre: Manoeuvres,
    /// `integrator.stop_when` as the scene wrote it, where it has one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stop_when: Option<String>,
}

/// The model: 4.46 with the table's terms.
#[derive(Debug, Clone, Serialize)]
pub struct ModelSummary {
    /// `planar-midship`.
    pub family: &'static str,
    /// What it integrates.
    pub equations: &'static str,
    /// `prime`, `dimensional`, or `mmg` (the MMG standard method's: the body in SI, the
    /// coefficients on ½ρLdU², ½ρL²dU², ½ρL²d, ½ρL⁴d).
    pub units: &'static str,
    /// `about G` or `about midship`.
    pub yaw_inertia: &'static str,
    /// `folded` or `separate`: how the table gave the rigid-body terms.
    pub rigid_body_terms: &'static str,
    /// What was converted to take folded rigid-body terms out of the table.
    pub conversion: Vec<String>,
    /// The terms of the polynomial the model carries.
    pub terms: usize,
    /// What one right-hand side costs.
    pub operations: Operations,
    /// The propeller at the approach, for a ship with a propulsion model.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub propulsion: Option<PropulsionSummary>,
    /// The MMG standard method's propeller at the approach, for an MMG ship.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mmg: Option<MmgSummary>,
    /// The current, the wind and the windage, for a ship in any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub environment: Option<EnvironmentSummary>,
}

/// An MMG ship's propeller at the approach, and the convention of its linear model.
#[derive(Debug, Clone, Serialize)]
pub struct MmgSummary {
    /// The rate the propeller is held at in every run, rev/s: the balancing rate unless the
    /// scene gives another.
    pub approach_rate_rps: f64,
    /// n₀, rev/s: X = 0 on the straight course at U₀, rudder amidships.
    pub balancing_rate_rps: f64,
    /// X at the approach at the held rate, N: zero to rounding at n₀.
    pub approach_surge_n: f64,
    /// J at the approach, U₀(1 − w_P0)/(n D_P) at the held rate.
    pub approach_advance_ratio: f64,
    /// Which one-sided derivatives the linear model takes where the model is not smooth.
    pub linear_model: &'static str,
}

/// What [`MmgSummary::linear_model`] says.
pub const MMG_LINEAR_CONVENTION: &str = "one-sided at the straight course: the derivatives \
    toward β_R > 0 and β_P > 0 (γ_R⁺, C₂⁺), which a small turn to starboard sees; a turn to \
    port sees γ_R⁻ and C₂⁻ (linear.toward_port); the straight course is stable only where \
    both sides are";

/// What the propulsion model gives at the approach, and the engine's limit.
#[derive(Debug, Clone, Serialize)]
pub struct PropulsionSummary {
    /// n₀, rev/s: thrust and resistance balance at U₀.
    pub approach_rate_rps: f64,
    /// c₀, m/s: the rudder's inflow speed at U₀ and n₀.
    pub approach_inflow_m_s: f64,
    /// The engine's rate limit, rev/s².
    pub max_rate_rps_s: f64,
}

/// Nomoto's second-order model and the course stability about the straight course.
#[derive(Debug, Clone, Serialize)]
pub struct LinearSummary {
    /// U₀, m/s.
    pub speed_m_s: f64,
    /// L, m.
    pub length_m: f64,
    /// Nomoto's constants in closed form from the table; `null` where T₁, T₂ are not real.
    pub nomoto: Option<NomotoSummary>,
    /// The same from the exact derivative of the running model.
    pub nomoto_of_linearised_model: Option<NomotoSummary>,
    /// The largest relative difference between the two among K, T₁, T₂, T₃.
    pub largest_relative_difference: Option<f64>,
    /// det N in SI: the straight course is stable where it is positive.
    pub det_n_si: f64,
    /// C′ of a prime table.
    pub stability_index: Option<f64>,
    /// Whether the straight course is stable (an MMG ship's: on both sides).
    pub course_stable: bool,
    /// The pivot point of the steady turn, m ahead of midship.
    pub pivot_point_m: f64,
    /// The same over L.
    pub pivot_point_over_length: f64,
    /// An MMG ship's other one-sided linear model at the straight course, toward β_R < 0 and
    /// β_P < 0 (a small turn to port); the fields above are toward starboard.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub toward_port: Option<OneSidedSummary>,
}

/// One side's linear model where the model is not smooth at the straight course.
#[derive(Debug, Clone, Serialize)]
pub struct OneSidedSummary {
    /// Nomoto's constants; `null` where T₁, T₂ are not real.
    pub nomoto: Option<NomotoSummary>,
    /// det N in SI.
    pub det_n_si: f64,
    /// C′ = det N over (½ρ)²L⁶U₀².
    pub stability_index: Option<f64>,
    /// Whether this side's linear model is stable.
    pub course_stable: bool,
}

/// Nomoto's constants, dimensional and in the prime system.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct NomotoSummary {
    /// K, 1/s.
    pub k_per_s: f64,
    /// T₁, s.
    pub t1_s: f64,
    /// T₂, s.
    pub t2_s: f64,
    /// T₃, s.
    pub t3_s: f64,
    /// T = T₁ + T₂ − T₃, s.
    pub t_s: f64,
    /// K′ = K L/U.
    pub k_prime: f64,
    /// T′ = T U/L.
    pub t_prime: f64,
}

/// Each manoeuvre by its name, and the IMO criteria.
#[derive(Debug, Clone, Serialize)]
pub struct Manoeuvres {
    /// The manoeuvres, by name.
    #[serde(flatten)]
    pub runs: BTreeMap<String, ManoeuvreSummary>,
    /// The IMO MSC.137(76) criteria judged on them.
    pub imo: Vec<CriterionSummary>,
}

/// One manoeuvre: what it did, its figures, and how far each moved when the run was refined.
///
/// A manoeuvre run to both sides gives here the run of the worse side (by its tactical
/// diameter, or first overshoot: [`super::side::deciding_figure`]), named by `side`, and
/// each side's under `sides` (`"port"`, `"starboard"`).
#[derive(Debug, Clone, Serialize)]
pub struct ManoeuvreSummary {
    /// The kind and its angles.
    #[serde(flatten)]
    pub kind: KindSummary,
    /// When the rudder was put over, s.
    pub execute_s: f64,
    /// The end of the run, s.
    pub duration_s: f64,
    /// Each figure by its key; `null` where the run did not give it (see `notes`).
    #[serde(flatten)]
    pub figures: BTreeMap<&'static str, Option<f64>>,
    /// `port` or `starboard`: the side of a turn, or of a zig-zag's first turn.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub side: Option<&'static str>,
    /// Each side's run, by side, for a manoeuvre run to both.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sides: Option<BTreeMap<&'static str, ManoeuvreSummary>>,
    /// A spiral's r–δ curve and its loop.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spiral: Option<SpiralSummary>,
    /// |figure − figure at half the step| (fixed-step methods).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub half_step_difference: Option<BTreeMap<&'static str, Option<f64>>>,
    /// |figure − figure with rtol and atol a hundred times tighter| (adaptive methods).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tolerance_difference: Option<BTreeMap<&'static str, Option<f64>>>,
    /// Steps the run took.
    pub steps: u64,
    /// What the run could not measure, and why.
    pub notes: Vec<String>,
    /// With `integrator.stop_when`: where it ended the run, s, every digit (`null` where it
    /// never held); absent without one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stopped_at: Option<Option<f64>>,
}

/// A spiral's curve as measured, what it says, and the steady turns it measures.
#[derive(Debug, Clone, Serialize)]
pub struct SpiralSummary {
    /// The points in the order measured.
    pub points: Vec<SpiralPointSummary>,
    /// Whether the curve has no loop (one steady turn at each rudder angle); `null` where the
    /// points cannot tell (`undetermined_because` says why).
    pub course_stable_by_spiral: Option<bool>,
    /// `no loop`, `loop` or `undetermined`.
    pub verdict: &'static str,
    /// Why the points cannot tell, and the settling that would.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub undetermined_because: Option<String>,
    /// The loop the settled points show.
    #[serde(rename = "loop", skip_serializing_if = "Option::is_none")]
    pub found: Option<LoopSummary>,
    /// The settling criterion the points were measured by.
    pub settle: SettleSummary,
    /// The steady turns over the points' range of rudder angles, traced by continuation;
    /// `null` where they could not be (the manoeuvre's notes say why).
    pub steady_turns: Option<SteadyTurnsSummary>,
}

/// The loop as the settled points show it, in degrees.
#[derive(Debug, Clone, Serialize)]
pub struct LoopSummary {
    /// Its ends, to the middle of the gaps between the split and the agreed angles.
    pub ends_deg: [f64; 2],
    /// The width between them.
    pub width_deg: f64,
    /// The least width the points allow.
    pub least_width_deg: f64,
    /// The most, where agreed angles bound it on both sides.
    pub most_width_deg: Option<f64>,
    /// The direct spiral's spacing of angles at the loop's ends.
    pub rudder_step_deg: Option<f64>,
}

/// One steady turn, in degrees.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct SteadyTurnSummary {
    /// δ.
    pub rudder_deg: f64,
    /// r, degrees per second.
    pub yaw_rate_deg_s: f64,
    /// u, m/s.
    pub u_m_s: f64,
    /// v, m/s.
    pub v_m_s: f64,
    /// Whether it is stable with the rudder held.
    pub stable: bool,
}

/// The steady turns of a spiral's range, their folds, and the loop between them.
#[derive(Debug, Clone, Serialize)]
pub struct SteadyTurnsSummary {
    /// The turns in order along the curve.
    pub turns: Vec<SteadyTurnSummary>,
    /// Where the curve turns back in δ: the loop's ends.
    pub folds: Vec<SteadyTurnSummary>,
    /// The δ between the outermost folds (zero without folds); `null` for a single fold.
    pub loop_width_deg: Option<f64>,
    /// Why each end of the curve is where it is.
    pub ends: [String; 2],
    /// The Newton steps taken.
    pub newton_steps: usize,
}

/// One point of a spiral's curve.
#[derive(Debug, Clone, Serialize)]
pub struct SpiralPointSummary {
    /// δ, degrees.
    pub rudder_deg: f64,
    /// The steady r, degrees per second.
    pub yaw_rate_deg_s: f64,
    /// The commanded r of a reverse spiral, degrees per second.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub commanded_yaw_rate_deg_s: Option<f64>,
    /// `first`, `back` (direct spiral) or `reverse`.
    pub branch: &'static str,
    /// Whether r settled by the criterion.
    pub settled: bool,
    /// How long the setpoint was held, s.
    pub held_s: f64,
}

/// The settling criterion of a spiral.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct SettleSummary {
    /// The window r is checked over, s.
    pub window_s: f64,
    /// The largest variation of r over the window, degrees per second.
    pub tolerance_deg_s: f64,
    /// The longest hold, s.
    pub max_hold_s: f64,
    /// The reverse spiral's largest change of the mean rudder from window to window, degrees.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rudder_tolerance_deg: Option<f64>,
    /// The largest variation of the speed over the window, m/s.
    pub speed_tolerance_m_s: f64,
    /// T, s: the ship's slowest sway–yaw time constant the resolution is taken at.
    pub time_constant_s: f64,
    /// ε, degrees per second: the largest distance of a settled r from the steady one.
    pub resolution_deg_s: f64,
}

impl SteadyTurnSummary {
    fn new(turn: &SteadyTurn) -> Self {
        SteadyTurnSummary {
            rudder_deg: turn.rudder.to_degrees(),
            yaw_rate_deg_s: turn.r.to_degrees(),
            u_m_s: turn.u,
            v_m_s: turn.v,
            stable: turn.stable,
        }
    }
}

impl SteadyTurnsSummary {
    /// The summary of a traced curve.
    pub fn new(steady: &SteadyTurns) -> Self {
        SteadyTurnsSummary {
            turns: steady.turns.iter().map(SteadyTurnSummary::new).collect(),
            folds: steady.folds.iter().map(SteadyTurnSummary::new).collect(),
            loop_width_deg: steady.loop_width().map(f64::to_degrees),
            ends: steady.ends.clone(),
            newton_steps: steady.newton_steps,
        }
    }
}

impl SpiralSummary {
    /// The summary of a measured curve.
    pub fn new(curve: &SpiralCurve) -> Self {
        let verdict = curve.verdict();
        let reverse = curve.points.iter().any(|p| p.branch == Branch::Reverse);
        let settle = curve.settle;
        SpiralSummary {
            points: (curve.points.iter())
                .map(|p| SpiralPointSummary {
                    // A direct spiral's δ is the scene's; a reverse spiral's, a mean.
                    rudder_deg: match p.branch {
                        Branch::Reverse => p.rudder.to_degrees(),
                        _ => as_given(p.rudder),
                    },
                    yaw_rate_deg_s: p.yaw_rate.to_degrees(),
                    commanded_yaw_rate_deg_s: p.target.map(as_given),
                    branch: p.branch.name(),
                    settled: p.settled,
                    held_s: p.held,
                })
                .collect(),
            course_stable_by_spiral: verdict.course_stable(),
            verdict: verdict.name(),
            undetermined_because: match &verdict {
                Verdict::Undetermined(why) => Some(why.clone()),
                _ => None,
            },
            found: match &verdict {
                Verdict::Loop(found) => Some(LoopSummary {
                    ends_deg: [found.ends.0.to_degrees(), found.ends.1.to_degrees()],
                    width_deg: found.width.to_degrees(),
                    least_width_deg: found.least_width().to_degrees(),
                    most_width_deg: found.most_width.map(f64::to_degrees),
                    rudder_step_deg: found.step.map(f64::to_degrees),
                }),
                _ => None,
            },
            settle: SettleSummary {
                window_s: settle.window,
                tolerance_deg_s: as_given(settle.tolerance),
                max_hold_s: settle.max_hold,
                rudder_tolerance_deg: reverse.then(|| as_given(settle.rudder_tolerance)),
                speed_tolerance_m_s: settle.speed_tolerance,
                time_constant_s: settle.time_constant,
                resolution_deg_s: settle.resolution().to_degrees(),
            },
            steady_turns: curve.steady.as_ref().ok().map(SteadyTurnsSummary::new),
        }
    }
}

/// A manoeuvre's kind and the angles it was run with, in degrees.
#[derive(Debug, Clone, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum KindSummary {
    /// A turning circle.
    TurningCircle {
        /// δ.
        rudder_deg: f64,
    },
    /// A zig-zag.
    Zigzag {
        /// δ_a.
        rudder_deg: f64,
        /// ψ_a.
        heading_deg: f64,
    },
    /// A pull-out.
    PullOut {
        /// δ.
        rudder_deg: f64,
        /// When the rudder returned to zero, s.
        release_s: f64,
    },
    /// A series of the scene's.
    RudderSeries,
    /// A direct spiral.
    Spiral {
        /// The first pass's angles.
        rudders_deg: Vec<f64>,
    },
    /// A reverse spiral.
    ReverseSpiral {
        /// The commanded yaw rates, degrees per second.
        yaw_rates_deg_s: Vec<f64>,
        /// g, degrees of rudder per degree per second of yaw rate.
        controller_gain_s: f64,
    },
    /// A crash stop.
    CrashStop {
        /// The full-astern propeller rate commanded, rev/s.
        astern_rps: f64,
    },
}

/// One IMO criterion, judged or not.
#[derive(Debug, Clone, Serialize)]
pub struct CriterionSummary {
    /// Its name.
    pub criterion: &'static str,
    /// The manoeuvre it is read from.
    pub manoeuvre: String,
    /// The figure, `null` where the manoeuvre did not give it.
    pub value: Option<f64>,
    /// The largest value allowed.
    pub limit: f64,
    /// `m` or `deg`.
    pub unit: &'static str,
    /// Whether the ship meets it; `null` when not judged.
    pub pass: Option<bool>,
    /// Whether there was a figure to judge.
    pub judged: bool,
    /// The side `value` is of, for a manoeuvre run to a side.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub side: Option<&'static str>,
    /// Each side's figure, for a manoeuvre run to both; `value` is the worse.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sides: Option<BTreeMap<&'static str, Option<f64>>>,
    /// Why it is not judged, where no manoeuvre of the scene could give its figure.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub not_judged_because: Option<String>,
}

impl ModelSummary {
    /// The model of `scene` as built.
    pub fn new(scene: &ShipScene, model: &ShipModel) -> Self {
        let table = &scene.table;
        let operations = model.operations();
        ModelSummary {
            family: "planar-midship",
            equations: match &table.mmg {
                None => "4.46 with the added mass and the hydrodynamic polynomial; 4.44",
                Some(_) => {
                    "4.46 with the added masses m_x, m_y, J_z (the MMG standard method's), the \
                     hull's polynomial and the propeller's and rudder's loads; 4.44"
                }
            },
            units: match (table.units, &table.mmg) {
                (_, Some(_)) => "mmg",
                (Units::Prime, None) => "prime",
                (Units::Dimensional, None) => "dimensional",
            },
            yaw_inertia: match table.body.yaw_inertia_about {
                YawInertia::AboutG => "about G",
                YawInertia::AboutMidship => "about midship",
            },
            rigid_body_terms: match table.given_as {
                RigidBodyTerms::Folded => "folded",
                RigidBodyTerms::Separate => "separate",
            },
            conversion: table.conversions.clone(),
            terms: model.terms(),
            operations,
            propulsion: table.propulsion.map(|p| PropulsionSummary {
                approach_rate_rps: p.approach_rate,
                approach_inflow_m_s: p.approach_inflow,
                max_rate_rps_s: p.max_rate,
            }),
            mmg: table.mmg.map(|mmg| {
                let p = &mmg.parameters;
                MmgSummary {
                    approach_rate_rps: mmg.approach_rate,
                    balancing_rate_rps: mmg.balancing_rate,
                    approach_surge_n: mmg.approach_surge(),
                    approach_advance_ratio: mmg.approach_speed * (1.0 - p.propeller.straight_wake)
                        / (mmg.approach_rate * p.particulars.propeller_diameter),
                    linear_model: MMG_LINEAR_CONVENTION,
                }
            }),
            environment: EnvironmentSummary::of(table),
        }
    }
}

impl NomotoSummary {
    fn new(nomoto: Option<Nomoto>, speed: f64, length: f64) -> Option<Self> {
        nomoto.map(|n| NomotoSummary {
            k_per_s: n.k,
            t1_s: n.t1,
            t2_s: n.t2,
            t3_s: n.t3,
            t_s: n.t,
            k_prime: n.k * length / speed,
            t_prime: n.t * speed / length,
        })
    }
}

/// An angle (or a rate) the scene gave in degrees, back from radians as it was written: the
/// conversion there and back is off by an ulp (7.5° came back as 7.499999999999999°), and
/// fifteen significant digits, well above that and below anything a scene writes, undo it.
pub(super) fn as_given(radians: f64) -> f64 {
    let degrees = radians.to_degrees();
    format!("{degrees:.14e}").parse().unwrap_or(degrees)
}

/// The largest relative difference between two Nomoto models' K, T₁, T₂, T₃.
pub fn nomoto_difference(a: Option<Nomoto>, b: Option<Nomoto>) -> Option<f64> {
    let (a, b) = (a?, b?);
    let pairs = [(a.k, b.k), (a.t1, b.t1), (a.t2, b.t2), (a.t3, b.t3)];
    Some(
        pairs
            .iter()
            .map(|(x, y)| (x - y).abs() / x.abs().max(y.abs()))
            .fold(0.0, f64::max),
    )
}

impl LinearSummary {
    /// The linear model of `scene` in closed form beside the running model's derivative.
    pub fn new(scene: &ShipScene, model: &ShipModel, linear: &LinearModel) -> Self {
        let speed = scene.table.design_speed;
        let closed = linear.nomoto();
        // The ship's own: in calm air (the wind's loads turn with the heading).
        let (a, b) = linearise(&model.calm(), speed);
        let linearised = Nomoto::from_state_space(a, b);
        let toward_port = scene.table.mmg.map(|mmg| {
            let port = LinearModel::mmg(&scene.table, &mmg, Edge::TowardNegative);
            OneSidedSummary {
                nomoto: NomotoSummary::new(port.nomoto(), speed, scene.length),
                det_n_si: port.det_damping(),
                stability_index: port.stability_index(),
                course_stable: port.course_stable(),
            }
        });
        // Stable only where every side's linear model is.
        let both_stable = toward_port.as_ref().is_none_or(|port| port.course_stable);
        LinearSummary {
            speed_m_s: speed,
            length_m: scene.length,
            nomoto: NomotoSummary::new(closed, speed, scene.length),
            nomoto_of_linearised_model: NomotoSummary::new(linearised, speed, scene.length),
            largest_relative_difference: nomoto_difference(closed, linearised),
            det_n_si: linear.det_damping(),
            stability_index: linear.stability_index(),
            course_stable: linear.course_stable() && both_stable,
            pivot_point_m: linear.pivot_point(),
            pivot_point_over_length: linear.pivot_point() / scene.length,
            toward_port,
        }
    }
}

impl KindSummary {
    /// The kind of `kind`, its angles in degrees.
    pub fn new(kind: &ManoeuvreKind) -> Self {
        match *kind {
            ManoeuvreKind::TurningCircle { rudder } => KindSummary::TurningCircle {
                rudder_deg: as_given(rudder),
            },
            ManoeuvreKind::ZigZag { rudder, heading } => KindSummary::Zigzag {
                rudder_deg: as_given(rudder),
                heading_deg: as_given(heading),
            },
            ManoeuvreKind::PullOut { rudder, release } => KindSummary::PullOut {
                rudder_deg: as_given(rudder),
                release_s: release,
            },
            ManoeuvreKind::Series(_) => KindSummary::RudderSeries,
            ManoeuvreKind::Spiral(ref spiral) => KindSummary::Spiral {
                rudders_deg: spiral.rudders.iter().map(|d| as_given(*d)).collect(),
            },
            ManoeuvreKind::ReverseSpiral(ref reverse) => KindSummary::ReverseSpiral {
                yaw_rates_deg_s: reverse.yaw_rates.iter().map(|r| as_given(*r)).collect(),
                controller_gain_s: reverse.gain,
            },
            ManoeuvreKind::CrashStop { astern } => KindSummary::CrashStop { astern_rps: astern },
        }
    }
}

impl ManoeuvreSummary {
    /// A manoeuvre's figures (`figures`), those of the same run refined by `stepper`'s
    /// [`Stepper::refined`] (`refined`), and the steps it took.
    pub fn new(
        manoeuvre: &Manoeuvre,
        stepper: &Stepper,
        (figures, refined): (&Figures, &Figures),
        steps: u64,
    ) -> Self {
        let differences: BTreeMap<&'static str, Option<f64>> = differences(figures, refined)
            .map(|(key, _, difference)| (key, difference))
            .collect();
        let adaptive = stepper.method.is_adaptive();
        ManoeuvreSummary {
            kind: KindSummary::new(&manoeuvre.kind),
            execute_s: manoeuvre.execute,
            duration_s: manoeuvre.duration,
            figures: figures.values.iter().copied().collect(),
            side: figures.side,
            sides: None,
            spiral: figures.spiral.as_ref().map(SpiralSummary::new),
            half_step_difference: (!adaptive).then(|| differences.clone()),
            tolerance_difference: adaptive.then_some(differences),
            steps,
            notes: figures.notes.clone(),
            stopped_at: None,
        }
    }
}

impl ManoeuvreSummary {
    /// A manoeuvre run to both sides: the `worse` side's summary, with each side's under
    /// `sides`.
    pub fn both(port: ManoeuvreSummary, starboard: ManoeuvreSummary, worse: Side) -> Self {
        let mut summary = match worse {
            Side::Port => port.clone(),
            Side::Starboard => starboard.clone(),
        };
        summary.side = Some(worse.name());
        let sides = [(Side::Port, port), (Side::Starboard, starboard)];
        summary.sides = Some(sides.into_iter().map(|(s, m)| (s.name(), m)).collect());
        summary
    }
}

impl CriterionSummary {
    /// A criterion as judged.
    pub fn new(criterion: &Criterion) -> Self {
        CriterionSummary {
            criterion: criterion.name,
            manoeuvre: criterion.manoeuvre.clone(),
            value: criterion.value,
            limit: criterion.limit,
            unit: criterion.unit,
            pass: criterion.pass(),
            judged: criterion.value.is_some(),
            side: criterion.side.map(Side::name),
            sides: (!criterion.sides.is_empty()).then(|| {
                (criterion.sides.iter())
                    .map(|(side, value)| (side.name(), *value))
                    .collect()
            }),
            not_judged_because: criterion.not_judged_because.clone(),
        }
    }
}

/// Each figure of a run by its key, with its value and |value − the refined run's| (`None`
/// where either run did not give it): what summary.json's `half_step_difference` and
/// [`RunFigures`] both say.
fn differences<'a>(
    figures: &'a Figures,
    refined: &'a Figures,
) -> impl Iterator<Item = (&'static str, Option<f64>, Option<f64>)> + 'a {
    (figures.values.iter()).map(|&(key, value)| {
        let difference = value.zip(refined.get(key)).map(|(a, b)| (a - b).abs());
        (key, value, difference)
    })
}

/// A manoeuvre's run (`path`: `turning_circle_35/port`) as every kind gives its figures:
/// each with how far it moved in the run refined by `stepper`'s [`Stepper::refined`].
pub fn run_figures(
    path: &str,
    stepper: &Stepper,
    (figures, refined): (&Figures, &Figures),
) -> RunFigures {
    let figures_out = differences(figures, refined)
        .map(|(key, value, difference)| Figure {
            key: key.to_owned(),
            value,
            difference,
        })
        .collect();
    RunFigures {
        run: path.to_owned(),
        figures: figures_out,
        refinement: Some(stepper.method.refinement()),
        largest_difference: None,
        notes: figures.notes.clone(),
    }
}

/// An IMO criterion as every kind gives a verdict: judged on its manoeuvre's worse side.
pub fn verdict(criterion: &Criterion) -> summary::Verdict {
    let side = criterion.side.filter(|_| !criterion.sides.is_empty());
    let run = match side {
        Some(side) => format!("{}/{}", criterion.manoeuvre, side.name()),
        None => criterion.manoeuvre.clone(),
    };
    summary::Verdict {
        name: criterion.name.to_owned(),
        run,
        pass: criterion.pass(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Angles a scene writes come back as written, where the round trip through radians
    /// alone is off by an ulp.
    #[test]
    fn an_angle_comes_back_as_the_scene_wrote_it() {
        for written in [7.5, -0.75, -1.5, -3.0, 35.0, 0.1, -0.025, 0.0] {
            assert_eq!(as_given(f64::to_radians(written)), written);
        }
        assert_ne!(7.5f64.to_radians().to_degrees(), 7.5);
    }
}
